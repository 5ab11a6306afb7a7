// ClosestPointIndex: nearest point on a set of triangles, for reprojection and distances.
//
// A uniform grid over the triangles' bounding box (about two cells per triangle); each
// triangle is listed in every cell its bounding box overlaps. A query visits the cells in
// growing cubic shells around the query point, skipping those farther than the best so far,
// and stops as soon as no unvisited shell can hold a closer point, so the answer is exact (up
// to rounding), not an approximation.
#pragma once

#include "mesh/surface_mesh.h"

#include <array>
#include <vector>

namespace fcql {

struct ClosestPoint {
  int triangle = -1;    ///< index into the triangles given to the index
  Vec3 point{0, 0, 0};  ///< the nearest point on that triangle
  double distance = 0;
};

/// Nearest point to p on the triangle (a, b, c) (Ericson, Real-Time Collision Detection §5.1.5).
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class ClosestPointIndex {
public:
  /// Throws std::invalid_argument if there are no triangles or an index is out of range.
  ClosestPointIndex(std::vector<Vec3> positions, std::vector<std::array<int, 3>> triangles);
  explicit ClosestPointIndex(const SurfaceMesh& mesh);

  ClosestPoint closest(const Vec3& p) const;
  int numTriangles() const { return int(triangles_.size()); }
  const std::array<int, 3>& triangle(int t) const { return triangles_[t]; }
  const Vec3& position(int v) const { return positions_[v]; }

private:
  int cellIndex(int x, int y, int z) const { return (z * dims_[1] + y) * dims_[0] + x; }
  std::array<int, 3> cellOf(const Vec3& p) const;

  std::vector<Vec3> positions_;
  std::vector<std::array<int, 3>> triangles_;
  Vec3 origin_{0, 0, 0};
  double cell_ = 1;
  std::array<int, 3> dims_{{1, 1, 1}};
  std::vector<int> cellStart_;  ///< CSR: triangles of cell c are cellTriangles_[cellStart_[c] .. cellStart_[c+1])
  std::vector<int> cellTriangles_;
  std::vector<Vec3> boxLow_, boxHigh_;  ///< per triangle: its bounding box
};

}  // namespace fcql
