// Small helpers shared by the filters' *_step.cpp files: timing, progress reporting through
// MeshLab's callback, number formatting for the log.
#pragma once

#include <cstring>  // wrap/callback.h uses strcpy without including it

#include <vcg/space/point3.h>
#include <wrap/callback.h>

#include <chrono>
#include <string>

namespace fcql_meshlab {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// "0.123 s".
std::string formatSeconds(double seconds);

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

}  // namespace fcql_meshlab
