// Small helpers shared by the filters' *_step.cpp files: timing, progress reporting through
// MeshLab's callback, the pipeline stages' log lines.
#pragma once

#include <cstring>  // wrap/callback.h uses strcpy without including it

#include <vcg/space/point3.h>
#include <wrap/callback.h>

#include "pipeline/stage_log.h"

#include <chrono>
#include <string>
#include <vector>

namespace fcql_meshlab {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A share [from, to] of the filter's progress bar, so a stage can report its own 0..100%
/// whether it runs alone or inside "All Steps".
struct Progress {
  vcg::CallBackPos* cb = nullptr;
  int from = 0, to = 100;

  /// Reports `percent` (0..100 of this stage) with a message; MeshLab prints the message.
  void operator()(int percent, const std::string& what) const;
  /// The sub-range [a, b] (0..100 of this stage).
  Progress sub(int a, int b) const;
};

/// What a pipeline stage reports as it runs, for the filters: its progress goes to `progress`;
/// its log lines are taken from the stage's result at the end.
fcql::StageObserver observerOf(const Progress& progress);

/// The log lines of a stage as the filters write them ("Warning: ...").
void appendLog(std::vector<std::string>& log, const std::vector<fcql::LogLine>& lines);

}  // namespace fcql_meshlab
