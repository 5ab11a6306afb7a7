// Reading an input file whole, refusing anything that is not a regular file: a directory, a
// device such as /dev/zero, a FIFO or a socket would otherwise be read forever or reported as
// "empty". Used by every reader of user files (meshes, fields, a run's outputs).
#pragma once

#include <string>

namespace fcql {

/// Reads `path` into `bytes`. On failure returns false and sets `error` to one line naming the
/// path: "cannot open the file (no such file)", "is a directory, not a file", "is not a regular file (...)", or
/// "cannot be read". A file larger than `maxBytes` is refused before it is read.
bool readRegularFile(const std::string& path, std::string& bytes, std::string& error,
                     unsigned long long maxBytes = 1ull << 34);

}  // namespace fcql
