// Helpers shared by the unit tests.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace fcql::test {

/// Absolute path of a file in ../shared/data/meshes, or "" if the shared folder is absent.
inline std::string sharedMesh(const std::string& name) {
  std::string path = std::string(FCQL_SHARED_DIR) + "/data/meshes/" + name;
  std::ifstream probe(path);
  return probe ? path : std::string();
}

}  // namespace fcql::test

/// Skips the current test with a message when a shared mesh is missing.
#define FCQL_REQUIRE_SHARED(var, name)                                                   \
  std::string var = fcql::test::sharedMesh(name);                                        \
  if (var.empty()) GTEST_SKIP() << "../shared/data/meshes/" << name << " is absent: skipped"
