#include "output_dir.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace fcql {

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
