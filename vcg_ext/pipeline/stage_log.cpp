#include "stage_log.h"

#include <cstdio>

namespace fcql {

std::string formatLogLine(const LogLine& line) {
  switch (line.kind) {
    case LogLine::Warning: return "Warning: " + line.text;
    case LogLine::Note: return "Note: " + line.text;
    case LogLine::Info: break;
  }
  return line.text;
}

std::string formatSeconds(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f s", seconds);
  return buffer;
}

}  // namespace fcql
