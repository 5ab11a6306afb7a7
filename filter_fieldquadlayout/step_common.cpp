#include "step_common.h"

#include <algorithm>
#include <cstdio>

namespace fcql_meshlab {

void Progress::operator()(int percent, const std::string& what) const {
  if (!cb) return;
  const int p = std::max(0, std::min(100, percent));
  cb(from + (to - from) * p / 100, ("Field-Coherent Quad Layout: " + what + "\n").c_str());
}

Progress Progress::sub(int a, int b) const {
  Progress p = *this;
  p.from = from + (to - from) * a / 100;
  p.to = from + (to - from) * b / 100;
  return p;
}

fcql::StageObserver observerOf(const Progress& progress) {
  fcql::StageObserver o;
  o.progress = [progress](int percent, const std::string& what) { progress(percent, what); };
  return o;
}

void appendLog(std::vector<std::string>& log, const std::vector<fcql::LogLine>& lines) {
  for (const fcql::LogLine& line : lines) log.push_back(fcql::formatLogLine(line));
}

}  // namespace fcql_meshlab
