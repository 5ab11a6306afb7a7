// Command-line parsing for fcql: a subcommand, positional arguments, --options with a value and
// --flags. Every problem is a UsageError with a one-line message.
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fcql {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class CommandLine {
public:
  /// Parses argv[first..argc). `valueOptions` take a value (--name V or --name=V), `flags` do not.
  CommandLine(int argc, char** argv, int first, const std::set<std::string>& valueOptions,
              const std::set<std::string>& flags);

  const std::vector<std::string>& positional() const { return positional_; }
  bool has(const std::string& name) const { return values_.count(name) || flags_.count(name); }
  std::string value(const std::string& name, const std::string& fallback = "") const;
  /// A number option; throws UsageError naming the option if it does not parse or is outside
  /// [min, max].
  double number(const std::string& name, double fallback, double min, double max) const;
  int integer(const std::string& name, int fallback, int min, int max) const;

private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
};

}  // namespace fcql
