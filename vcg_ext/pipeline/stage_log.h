// What a pipeline stage tells while it runs: log lines (information, notes, warnings) and its
// progress. The stage keeps its lines in its result and passes each to the observer as it
// comes, so fcql prints them at once and the filters log them in the same words.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace fcql {

struct LogLine {
  enum Kind { Info, Note, Warning };
  Kind kind = Info;
  std::string text;  ///< starts with a capital, no "Warning: " prefix
};

struct StageObserver {
  std::function<void(const LogLine&)> line;                       ///< may be empty
  std::function<void(int percent, const std::string& what)> progress;  ///< 0..100 of the stage; may be empty
};

/// A stage's log: kept lines, forwarded to the observer.
class StageLog {
public:
  explicit StageLog(StageObserver observer) : observer_(std::move(observer)) {}
  void info(const std::string& text) { add(LogLine::Info, text); }
  void note(const std::string& text) { add(LogLine::Note, text); }
  void warning(const std::string& text) { add(LogLine::Warning, text); }
  void progress(int percent, const std::string& what) const {
    if (observer_.progress) observer_.progress(percent, what);
  }
  std::vector<LogLine> lines;

private:
  void add(LogLine::Kind kind, const std::string& text) {
    lines.push_back(LogLine{kind, text});
    if (observer_.line) observer_.line(lines.back());
  }
  StageObserver observer_;
};

/// "Warning: text", "Note: text" or "text".
std::string formatLogLine(const LogLine& line);

/// "0.123 s".
std::string formatSeconds(double seconds);

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace fcql
