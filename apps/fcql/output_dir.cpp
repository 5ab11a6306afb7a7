#include "output_dir.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace fs = std::filesystem;

namespace fcql {

std::string OutputDir::problem(const std::string& dir) {
  if (dir.empty()) return "--out needs a directory name";
  std::error_code ec;
  const fs::path target = fs::absolute(fs::path(dir), ec);
  if (ec) return dir + ": not a usable path (" + ec.message() + ")";
  // The nearest part of the path that exists must be a directory we may write into.
  fs::path at = target;
  while (!fs::exists(fs::symlink_status(at, ec)) && at.has_parent_path() && at != at.parent_path()) at = at.parent_path();
  if (fs::exists(at, ec) && !fs::is_directory(at, ec))
    return dir + ": " + (at == target ? std::string("is a file, not a directory") : at.string() + " is a file, not a directory");
  if (access(at.c_str(), W_OK | X_OK) != 0)
    return dir + ": cannot write into " + at.string() + " (permission denied)";
  return "";
}

OutputDir::OutputDir(const std::string& dir) : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw std::runtime_error(dir + ": cannot create the output directory");
}

OutputDir::~OutputDir() {
  if (committed_) return;
  std::error_code ec;
  for (const auto& n : names_) fs::remove(dir_ + "/." + n + ".partial", ec);
}

std::string OutputDir::stage(const std::string& name) {
  names_.push_back(name);
  return dir_ + "/." + name + ".partial";
}

std::string OutputDir::withFinalName(std::string message, const std::string& name) const {
  const std::string partial = dir_ + "/." + name + ".partial";
  for (std::size_t at = message.find(partial); at != std::string::npos; at = message.find(partial, at))
    message.replace(at, partial.size(), finalPath(name));
  return message;
}

void OutputDir::writeText(const std::string& name, const std::string& text) {
  std::string path = stage(name);
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.flush();
  if (!out) throw std::runtime_error(finalPath(name) + ": cannot write");
}

void OutputDir::commit() {
  for (const auto& n : names_) {
    std::error_code ec;
    fs::rename(dir_ + "/." + n + ".partial", dir_ + "/" + n, ec);
    if (ec) throw std::runtime_error(finalPath(n) + ": cannot write (" + ec.message() + ")");
  }
  committed_ = true;
}

}  // namespace fcql
