// libFuzzer target: the .ffield and .rosy readers against a fixed small mesh (the icosahedron,
// 20 faces). The first byte picks the format. Any outcome but a field or a FieldError is a finding.
#include "field/field_io.h"
#include "mesh/generators.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const fcql::SurfaceMesh mesh = fcql::makeSphere(0);
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    if (data[0] % 2 == 0)
      fcql::parseFField(mesh, text, "fuzz.ffield");
    else
      fcql::parseRosy(mesh, text, "fuzz.rosy");
  } catch (const fcql::FieldError&) {
  }
  return 0;
}
