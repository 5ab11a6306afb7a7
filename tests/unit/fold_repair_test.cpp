#include "metrics/quad_quality.h"
#include "quadrangulation/fold_repair.h"

#include "test_support.h"

#include <gtest/gtest.h>

namespace fcql {
namespace {

using test::planarGrid;

int folded(const QuadMesh& mesh) {
  const QuadJacobian jacobian(mesh);
  std::vector<double> j;
  jacobian.all(j);
  return int(std::count_if(j.begin(), j.end(), [](double x) { return x <= 0; }));
}

TEST(FoldRepair, AGridFoldedOverItselfIsUnfoldedOnTheSurface) {
  // A 6×6 grid whose middle 2×2 vertices are mirrored left to right: the column of quads
  // between them turns over, and the quads beside it fold. Moving one vertex at a time
  // without letting any quad get worse cannot undo it; moving them together can.
  const int n = 6;
  QuadMesh grid = planarGrid(n);
  auto at = [&](int i, int j) { return (n + 1) * j + i; };
  for (int j : {2, 3, 4}) std::swap(grid.positions[at(2, j)], grid.positions[at(4, j)]);
  const int before = folded(grid);
  ASSERT_GE(before, 4);
  const std::vector<Vec3> plane = {Vec3(-1, -1, 0), Vec3(n + 1, -1, 0), Vec3(n + 1, n + 1, 0), Vec3(-1, n + 1, 0)};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  const ClosestPointIndex surface(plane, triangles);
  const std::vector<Vec3> normals(2, Vec3(0, 0, 1));
  std::vector<char> movable(grid.positions.size(), 0);
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) movable[at(i, j)] = kOnSurface;  // the border stays
  const QuadJacobian jacobian(grid);
  EXPECT_EQ(repairFolds(grid, surface, nullptr, normals, movable, jacobian), before);
  EXPECT_EQ(folded(grid), 0);
  for (const Vec3& p : grid.positions) EXPECT_NEAR(p.z(), 0, 1e-12);
  EXPECT_EQ(grid.positions[at(0, 3)], Vec3(0, 3, 0));  // border vertices did not move
}

TEST(FoldRepair, AnUnfoldedMeshIsLeftAsItIs) {
  QuadMesh grid = planarGrid(3);
  grid.positions[5] = Vec3(1.2, 0.9, 0);
  const QuadMesh copy = grid;
  const std::vector<Vec3> plane = {Vec3(-1, -1, 0), Vec3(4, -1, 0), Vec3(4, 4, 0), Vec3(-1, 4, 0)};
  const ClosestPointIndex surface(plane, {{0, 1, 2}, {0, 2, 3}});
  const std::vector<char> movable(grid.positions.size(), kOnSurface);
  EXPECT_EQ(repairFolds(grid, surface, nullptr, {Vec3(0, 0, 1), Vec3(0, 0, 1)}, movable, QuadJacobian(grid)), 0);
  EXPECT_EQ(grid.positions, copy.positions);
}

TEST(FoldRepair, WithAMarginANearlyFlatQuadIsLiftedAboveIt) {
  // A 4×4 grid with vertex (2, 2) pulled almost onto the diagonal of the quad below and left of
  // it: that quad's corner there is nearly flat (scaled Jacobian about 0.012), none is folded.
  // Without a margin nothing is to repair; with a margin of 0.02 the quad is lifted above it,
  // no quad folds and the border stays.
  const int n = 4;
  QuadMesh grid = planarGrid(n);
  auto at = [&](int i, int j) { return (n + 1) * j + i; };
  grid.positions[at(2, 2)] = Vec3(1.503, 1.503, 0);
  auto least = [](const QuadMesh& mesh) {
    std::vector<double> j;
    QuadJacobian(mesh).all(j);
    return *std::min_element(j.begin(), j.end());
  };
  ASSERT_GT(least(grid), 0);
  ASSERT_LT(least(grid), 0.02);
  const std::vector<Vec3> plane = {Vec3(-1, -1, 0), Vec3(n + 1, -1, 0), Vec3(n + 1, n + 1, 0), Vec3(-1, n + 1, 0)};
  const ClosestPointIndex surface(plane, {{0, 1, 2}, {0, 2, 3}});
  const std::vector<Vec3> normals(2, Vec3(0, 0, 1));
  std::vector<char> movable(grid.positions.size(), 0);
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) movable[at(i, j)] = kOnSurface;
  const QuadMesh copy = grid;
  EXPECT_EQ(repairFolds(grid, surface, nullptr, normals, movable, QuadJacobian(grid)), 0);
  EXPECT_EQ(grid.positions, copy.positions);
  EXPECT_EQ(repairFolds(grid, surface, nullptr, normals, movable, QuadJacobian(grid), 0.02), 1);
  EXPECT_GT(least(grid), 0.02);
  EXPECT_EQ(folded(grid), 0);
  for (int k = 0; k <= n; ++k) EXPECT_EQ(grid.positions[at(k, 0)], copy.positions[at(k, 0)]);
}

}  // namespace
}  // namespace fcql
