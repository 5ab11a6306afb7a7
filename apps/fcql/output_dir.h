// OutputDir: writes a command's results so that a failed run leaves no partial files behind
// looking valid. Files are written under temporary names and renamed into place by commit();
// if commit() is never reached, the temporaries are removed.
#pragma once

#include <string>
#include <vector>

namespace fcql {

class OutputDir {
public:
  /// Creates the directory (and parents) if needed; throws std::runtime_error if it cannot.
  explicit OutputDir(const std::string& dir);
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  /// The temporary path to write `name` to now; it becomes dir/name at commit().
  std::string stage(const std::string& name);
  /// Final path of `name` (for messages).
  std::string finalPath(const std::string& name) const { return dir_ + "/" + name; }
  void writeText(const std::string& name, const std::string& text);
  void commit();

private:
  std::string dir_;
  std::vector<std::string> names_;
  bool committed_ = false;
};

}  // namespace fcql
