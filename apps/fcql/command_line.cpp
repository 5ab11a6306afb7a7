#include "command_line.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fcql {

CommandLine::CommandLine(int argc, char** argv, int first, const std::set<std::string>& valueOptions,
                         const std::set<std::string>& flags) {
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      std::string name = arg.substr(2), value;
      bool inlineValue = false;
      auto eq = name.find('=');
      if (eq != std::string::npos) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
        inlineValue = true;
      }
      if (flags.count(name)) {
        if (inlineValue) throw UsageError("option --" + name + " takes no value");
        flags_.insert(name);
      } else if (valueOptions.count(name)) {
        if (!inlineValue) {
          if (i + 1 >= argc) throw UsageError("option --" + name + " needs a value");
          value = argv[++i];
        }
        values_[name] = value;
      } else {
        throw UsageError("unknown option --" + name);
      }
    } else {
      positional_.push_back(arg);
    }
  }
}

std::string CommandLine::value(const std::string& name, const std::string& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

double CommandLine::number(const std::string& name, double fallback, double min, double max) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const char* s = it->second.c_str();
  char* end = nullptr;
  double v = std::strtod(s, &end);
  if (end == s || *end != '\0' || !std::isfinite(v))
    throw UsageError("--" + name + " must be a number, got '" + it->second + "'");
  if (v < min || v > max) {
    std::ostringstream ss;
    ss << "--" << name << " must be between " << min << " and " << max << ", got " << it->second;
    throw UsageError(ss.str());
  }
  return v;
}

int CommandLine::integer(const std::string& name, int fallback, int min, int max) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const char* s = it->second.c_str();
  char* end = nullptr;
  long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0') throw UsageError("--" + name + " must be an integer, got '" + it->second + "'");
  if (v < min || v > max)
    throw UsageError("--" + name + " must be between " + std::to_string(min) + " and " + std::to_string(max) +
                     ", got " + it->second);
  return int(v);
}

}  // namespace fcql
