// A field-aligned map of a patch onto its integer rectangle (issue #21).
//
// Given where the boundary of a disk patch goes on [0, W] × [0, H] (mean-value coordinates
// would fill the inside ignoring the cross field), find (u, v) per wedge whose gradients
// follow the field: per triangle, with d1, d2 the cross directions matched to the patch's u and v axes,
// minimise (by sparse least squares, Eigen's SimplicialLDLT on the normal equations)
//   area · [ λ (∇u·d2)² + (∇u·d1 − a)² + λ (∇v·d1)² + (∇v·d2 − b)² ]
// where a and b (one each per patch) are unknown scales: u's iso-lines run along d2 and its
// spacing is as even as the boundary allows. The matching of the cross to the axes is found by
// combing the field over the patch (parallel transport across edges, no singularity inside a
// patch) and picking the rotation that agrees best with the constrained (boundary) edges' images.
//
// Each wedge is free, fixed (u and v given), or slides along one axis (only u or only v
// fixed: a point inside a side of the rectangle, which stays on its iso-line).
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace fcql {

struct FieldAlignedProblem {
  enum Constraint : std::int8_t { Free = 0, Fixed = 1, FixU = 2, FixV = 3 };
  std::vector<std::array<int, 3>> triangles;  ///< wedge ids (0..n−1), counter-clockwise
  std::vector<std::array<Vec3, 3>> corners;   ///< per triangle, its corners' positions
  std::vector<Vec3> direction;                ///< per triangle, one direction of the cross (any of the four)
  std::vector<std::array<int, 3>> neighbours; ///< per triangle and edge (i → i+1): triangle across inside the patch, or −1
  std::vector<Vec2> start;                    ///< per wedge: constrained ones their image (counter-clockwise), free ones anything
  std::vector<std::int8_t> constraint;        ///< per wedge; fixed coordinates are taken from start
  double alignWeight = 10;                    ///< λ above
};

struct FieldAlignedResult {
  std::vector<Vec2> uv;  ///< per wedge
  bool solved = false;   ///< false: the system could not be factored (uv = start)
};

FieldAlignedResult solveFieldAlignedMap(const FieldAlignedProblem& problem);

/// The least-squares rows of the problem before any wedge is fixed, per axis (0: u, 1: v):
/// each row is Σ_i coefficient[i] · (that axis's coordinate of wedge[i]) + scale · (the axis's
/// unknown scale a or b), to be made as small as possible (squared, summed). For solving
/// several patches together (their sides shared).
struct FieldAlignedRows {
  struct Row {
    std::array<int, 3> wedge;
    std::array<double, 3> coefficient;
    double scale = 0;
  };
  std::array<std::vector<Row>, 2> axis;
};
FieldAlignedRows fieldAlignedRows(const FieldAlignedProblem& problem);

/// Triangles whose image has a signed area ≤ `minArea` times the mean (folded or flattened).
int foldedTriangles(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec2>& uv, double minArea = 1e-9);

}  // namespace fcql
