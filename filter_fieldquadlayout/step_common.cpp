#include "step_common.h"

#include <algorithm>
#include <cstdio>

namespace fcql_meshlab {

std::string formatSeconds(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f s", seconds);
  return buffer;
}

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

}  // namespace fcql_meshlab
