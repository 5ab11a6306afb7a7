// libFuzzer target: the mesh readers (PLY in its three formats, OBJ, OFF) on untrusted bytes.
// The first byte picks the format; the rest is the file. Any outcome but a SurfaceMesh or a
// MeshError (a crash, a sanitizer report, another exception, a hang) is a finding.
#include "mesh/mesh_io.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kFormats[] = {"ply", "obj", "off"};
  const std::string format = kFormats[data[0] % 3];
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    fcql::parseMesh(bytes, "fuzz." + format, format);
  } catch (const fcql::MeshError&) {
  }
  return 0;
}
