// QuadMesh: the output of the pipeline, a pure quad mesh, with checks of its structure.
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fcql {

struct QuadMesh {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 4>> quads;  ///< counter-clockwise about the outward normal
  std::vector<int> quadPatch;             ///< layout patch each quad comes from
  /// Grid points that fell outside their patch's map and were put on the nearest mapped
  /// triangle (0 unless a patch map is degenerate; its quads are then distorted).
  int outsidePoints = 0;
  /// With a cross field (samplePatches' faceDirections): layout patches mapped field-aligned,
  /// blended back towards mean-value coordinates because the aligned map folded, or left to
  /// mean-value coordinates (the blend folded too, or the system failed).
  int alignedPatches = 0, blendedPatches = 0, meanValuePatches = 0;

  int numVertices() const { return int(positions.size()); }
  int numQuads() const { return int(quads.size()); }
};

struct QuadMeshReport {
  bool manifold = false;       ///< every edge in ≤ 2 quads, consistently oriented; vertex fans single
  int eulerCharacteristic = 0;
  int borderLoops = 0;
  int components = 0;          ///< connected components (quads sharing vertices)
  int genus = 0;               ///< summed over components: (2·components − χ − borderLoops) / 2
  int irregularVertices = 0;   ///< interior valence ≠ 4, border valence ∉ {2 at corners, 3}
  /// Those vertices by valence: "3", "5", ... inside, "border 4", ... on the border (sorted as text).
  std::vector<std::pair<std::string, int>> irregularByValence;
  int unusedVertices = 0;
  std::string problem;
};

QuadMeshReport checkQuadMesh(const QuadMesh& mesh);

/// Euler characteristic, border loops and components of a triangle mesh (vertices that no
/// triangle uses are ignored): what a quad mesh sampled from it must also have.
struct SurfaceTopology {
  int eulerCharacteristic = 0;
  int borderLoops = 0;
  int components = 0;
};
SurfaceTopology triangleMeshTopology(int numVertices, const std::vector<std::array<int, 3>>& triangles);

/// Marks, `rings` times over, every vertex of each quad that has a marked vertex: the vertices
/// within `rings` quads of those marked (`marked`: one flag per vertex).
void growAcrossQuads(const QuadMesh& mesh, std::vector<char>& marked, int rings);

/// One flag per vertex: 1 for a vertex on the border, an end of a directed quad edge that no
/// quad has the other way round (on a consistently oriented manifold: an edge of one quad).
std::vector<char> quadBorderVertices(const QuadMesh& mesh);

/// OBJ text with `v` and `f a b c d` lines only.
std::string quadMeshToObj(const QuadMesh& mesh);

}  // namespace fcql
