// Reading the output files `fcql render` draws (layout.ply, separatrices.obj, quad.obj) from
// their bytes, strictly: each reader throws std::runtime_error with one line naming the file
// and the line or byte, and never reads past its input, whatever the bytes (fuzzed by
// tests/fuzz/render_reader_fuzz).
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <string>
#include <vector>

namespace fcql {
namespace render {

struct LayoutScene {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> patch;  ///< per triangle
};

struct Polyline {
  std::vector<Vec3> points;
  std::string kind;  ///< from the comment before its `l` line: "separatrix", "t-junction", "to border" or ""
};

struct QuadScene {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 4>> quads;
};

/// layout.ply: any PLY (ASCII or binary) with a per-face scalar `patch` in [0, 10^8].
LayoutScene parseLayoutPly(const std::string& bytes, const std::string& name);

/// separatrices.obj: `v` and `l` lines; each polyline's kind from the comment before it.
std::vector<Polyline> parseSeparatrices(const std::string& text, const std::string& name);

/// quad.obj: `v` and `f` lines of 4 corners (3 are drawn as a triangle); at least one face.
QuadScene parseQuads(const std::string& text, const std::string& name);

}  // namespace render
}  // namespace fcql
