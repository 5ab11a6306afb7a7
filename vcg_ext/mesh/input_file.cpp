#include "mesh/input_file.h"

#include <sys/stat.h>

#include <cstdio>
#include <memory>

namespace fcql {

bool readRegularFile(const std::string& path, std::string& bytes, std::string& error, unsigned long long maxBytes) {
  struct stat st;
  if (path.empty()) {
    error = "an empty file name";
    return false;
  }
  if (stat(path.c_str(), &st) != 0) {
    error = path + ": cannot open the file (no such file)";
    return false;
  }
  if (S_ISDIR(st.st_mode)) {
    error = path + ": is a directory, not a file";
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    error = path + ": is not a regular file (a device, FIFO or socket cannot be read as a mesh or field)";
    return false;
  }
  if (static_cast<unsigned long long>(st.st_size) > maxBytes) {
    error = path + ": the file is too large (" + std::to_string(st.st_size) + " bytes)";
    return false;
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    error = path + ": cannot be read (permission denied or an I/O error)";
    return false;
  }
  // At most the size stat reported: a file that grows meanwhile is read as it was.
  bytes.assign(std::size_t(st.st_size), '\0');
  std::size_t got = st.st_size > 0 ? std::fread(&bytes[0], 1, bytes.size(), file.get()) : 0;
  if (std::ferror(file.get())) {
    error = path + ": cannot be read (an I/O error)";
    return false;
  }
  bytes.resize(got);
  return true;
}

}  // namespace fcql
