// OutputDir: writes a command's results so that a failed run leaves no partial files behind
// looking valid. Files are written under temporary names and renamed into place by commit();
// if commit() is never reached, the temporaries are removed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace fcql {

class OutputDir {
public:
  /// Checks, before any work, that `dir` names a directory that exists and can be written, or
  /// that it can be created (its nearest existing ancestor is a writable directory). Returns ""
  /// if so, else one line saying why (an empty name, a file, no permission).
  static std::string problem(const std::string& dir);

  /// Creates the directory (and parents) if needed; throws std::runtime_error if it cannot.
  explicit OutputDir(const std::string& dir);
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  /// Calls write(path) with the temporary path of `name`, which becomes dir/name at commit(); an
  /// error thrown by `write` is rethrown naming dir/name instead of the temporary path.
  template <class Write>
  void write(const std::string& name, Write write) {
    const std::string path = stage(name);
    try {
      write(path);
    } catch (const std::exception& e) {
      throw std::runtime_error(withFinalName(e.what(), name));
    }
  }
  /// Final path of `name` (for messages).
  std::string finalPath(const std::string& name) const { return dir_ + "/" + name; }
  void writeText(const std::string& name, const std::string& text);
  void commit();

private:
  std::string stage(const std::string& name);
  std::string withFinalName(std::string message, const std::string& name) const;

  std::string dir_;
  std::vector<std::string> names_;
  bool committed_ = false;
};

}  // namespace fcql
