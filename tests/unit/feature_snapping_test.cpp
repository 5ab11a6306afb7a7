#include "metrics/quad_quality.h"
#include "quadrangulation/feature_snapping.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fcql {
namespace {

/// A quad grid bent over a 90° crease along the y axis (x = z = 0): column s of the grid lies
/// at (s, y, 0) for s ≤ 0 and at (0, y, s) beyond, rows y = 0..4. The crease runs between the
/// columns at s = −0.3 and s = 0.7, as a layout side traced beside a crease leaves it.
struct BentGrid {
  std::vector<double> columns = {-2.3, -1.3, -0.3, 0.7, 1.7, 2.7};
  int rows = 5;
  QuadMesh mesh;
  std::vector<char> movable;
  std::vector<std::vector<int>> neighbours;
  int at(int column, int row) const { return row * int(columns.size()) + column; }

  BentGrid() {
    const int nc = int(columns.size());
    for (int j = 0; j < rows; ++j)
      for (double s : columns) mesh.positions.push_back(s <= 0 ? Vec3(s, j, 0) : Vec3(0, j, s));
    for (int j = 0; j + 1 < rows; ++j)
      for (int i = 0; i + 1 < nc; ++i) mesh.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    movable.assign(mesh.positions.size(), 0);
    neighbours.resize(mesh.positions.size());
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < nc; ++i) {
        movable[at(i, j)] = i > 0 && i + 1 < nc && j > 0 && j + 1 < rows;  // the border stays
        if (i > 0) neighbours[at(i, j)].push_back(at(i - 1, j));
        if (i + 1 < nc) neighbours[at(i, j)].push_back(at(i + 1, j));
        if (j > 0) neighbours[at(i, j)].push_back(at(i, j - 1));
        if (j + 1 < rows) neighbours[at(i, j)].push_back(at(i, j + 1));
      }
  }
};

double leastScaledJacobian(const QuadMesh& mesh) {
  double least = 1;
  for (int q = 0; q < mesh.numQuads(); ++q) least = std::min(least, scaledJacobian(mesh, q));
  return least;
}

TEST(FeatureSnapping, TheGridLineNearestAStraightCreaseGoesOntoIt) {
  BentGrid grid;
  const QuadMesh before = grid.mesh;
  // The crease from (0, −1, 0) to (0, 5, 0), in two segments, as degenerate triangles.
  const std::vector<Vec3> surface = {Vec3(0, -1, 0), Vec3(0, 2, 0), Vec3(0, 5, 0)};
  const std::vector<std::array<int, 3>> segments = {{0, 1, 1}, {1, 2, 2}};
  const std::vector<char> snappable = {1, 1};
  const ClosestPointIndex features(surface, segments);
  EXPECT_EQ(snapGridLinesToFeatures(grid.mesh, surface, segments, snappable, features, grid.movable, grid.neighbours), 3);
  for (int j = 1; j + 1 < grid.rows; ++j) {
    const Vec3& p = grid.mesh.positions[grid.at(2, j)];  // the column 0.3 from the crease
    EXPECT_NEAR(p.x(), 0, 1e-12);
    EXPECT_NEAR(p.z(), 0, 1e-12);
    EXPECT_NEAR(p.y(), j, 1e-12);
    // The column on the other side, 0.7 away, and every other vertex stay.
    EXPECT_EQ(grid.mesh.positions[grid.at(3, j)], before.positions[grid.at(3, j)]);
  }
  int changed = 0;
  for (std::size_t v = 0; v < before.positions.size(); ++v) changed += grid.mesh.positions[v] != before.positions[v];
  EXPECT_EQ(changed, 3);
  EXPECT_GT(leastScaledJacobian(grid.mesh), 0.1);
}

TEST(FeatureSnapping, OnlySnappableSegmentsAreSnappedTo) {
  // The same crease, its second half not snappable (a scan's ridge, say): the vertex beside the
  // first half goes onto it, the two beside the second half stay.
  BentGrid grid;
  const QuadMesh before = grid.mesh;
  const std::vector<Vec3> surface = {Vec3(0, -3, 0), Vec3(0, 1.5, 0), Vec3(0, 5, 0)};
  const std::vector<std::array<int, 3>> segments = {{0, 1, 1}, {1, 2, 2}};
  const std::vector<char> snappable = {1, 0};
  const ClosestPointIndex features(surface, segments);
  EXPECT_EQ(snapGridLinesToFeatures(grid.mesh, surface, segments, snappable, features, grid.movable, grid.neighbours), 1);
  EXPECT_NEAR(grid.mesh.positions[grid.at(2, 1)].x(), 0, 1e-12);
  for (int j : {2, 3}) EXPECT_EQ(grid.mesh.positions[grid.at(2, j)], before.positions[grid.at(2, j)]);
  EXPECT_GT(leastScaledJacobian(grid.mesh), 0.1);
}

TEST(FeatureSnapping, ACreaseShorterThanThreeQuadEdgesIsLeft) {
  // A crease two quad edges long, as a scan has a few sharp triangles: no grid line goes onto it.
  BentGrid grid;
  const QuadMesh before = grid.mesh;
  const std::vector<Vec3> surface = {Vec3(0, 1, 0), Vec3(0, 3, 0)};
  const std::vector<std::array<int, 3>> segments = {{0, 1, 1}};
  const std::vector<char> snappable = {1};
  const ClosestPointIndex features(surface, segments);
  EXPECT_EQ(snapGridLinesToFeatures(grid.mesh, surface, segments, snappable, features, grid.movable, grid.neighbours), 0);
  EXPECT_EQ(grid.mesh.positions, before.positions);
}

TEST(FeatureSnapping, AGridLineMoreThanItsReachAwayStays) {
  // Both columns beside the crease farther than 0.6 of an edge: the crease lies mid-row, and
  // no column goes onto it.
  BentGrid far;
  far.columns = {-2.8, -1.8, -0.8, 0.8, 1.8, 2.8};
  far.mesh.positions.clear();
  for (int j = 0; j < far.rows; ++j)
    for (double s : far.columns) far.mesh.positions.push_back(s <= 0 ? Vec3(s, j, 0) : Vec3(0, j, s));
  const QuadMesh before = far.mesh;
  const std::vector<Vec3> surface = {Vec3(0, -1, 0), Vec3(0, 5, 0)};
  const std::vector<std::array<int, 3>> segments = {{0, 1, 1}};
  const std::vector<char> snappable = {1};
  const ClosestPointIndex features(surface, segments);
  EXPECT_EQ(snapGridLinesToFeatures(far.mesh, surface, segments, snappable, features, far.movable, far.neighbours), 0);
  EXPECT_EQ(far.mesh.positions, before.positions);
}

}  // namespace
}  // namespace fcql
