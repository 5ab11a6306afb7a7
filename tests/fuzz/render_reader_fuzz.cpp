// libFuzzer target: the readers of `fcql render` (layout.ply, separatrices.obj, quad.obj) on
// untrusted bytes; the first byte picks one. Any outcome but a scene or a std::runtime_error
// (a crash, a sanitizer report, another exception, a hang) is a finding.
#include "render/scene_files.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    switch (data[0] % 3) {
      case 0: fcql::render::parseLayoutPly(bytes, "layout.ply"); break;
      case 1: fcql::render::parseSeparatrices(bytes, "separatrices.obj"); break;
      default: fcql::render::parseQuads(bytes, "quad.obj"); break;
    }
  } catch (const std::runtime_error&) {
  }
  return 0;
}
