#include "metrics/quad_quality.h"
#include "quadrangulation/field_relaxation.h"
#include "quadrangulation/quad_smoothing.h"
#include "util/math_constants.h"
#include "test_support.h"

#include <cmath>

#include <gtest/gtest.h>

namespace fcql {
namespace {

using test::planarGrid;

/// The plane z = 0 around the grid, as two triangles.
struct Plane {
  std::vector<Vec3> positions = {Vec3(-20, -20, 0), Vec3(30, -20, 0), Vec3(30, 30, 0), Vec3(-20, 30, 0)};
  std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  std::vector<Vec3> normals = {Vec3(0, 0, 1), Vec3(0, 0, 1)};
};

/// The worst angle (radians) between a quad's two directions (midpoints of opposite edges) and
/// the cross of direction d on the plane.
double angleOff(const QuadMesh& m, int q, const Vec3& d) {
  const auto& f = m.quads[q];
  const auto& P = m.positions;
  const Vec3 eu = (P[f[1]] + P[f[2]] - P[f[0]] - P[f[3]]) / 2, ev = (P[f[2]] + P[f[3]] - P[f[0]] - P[f[1]]) / 2;
  double worst = 0;
  for (const Vec3& e : {eu, ev}) {
    double a = std::atan2(d.cross(e).z(), d.dot(e));
    a = std::fmod(std::fmod(a, kPi / 2) + kPi / 2, kPi / 2);
    worst = std::max(worst, std::min(a, kPi / 2 - a));
  }
  return worst;
}

double meanAngleOff(const QuadMesh& m, const Vec3& d) {
  double sum = 0;
  for (int q = 0; q < m.numQuads(); ++q) sum += angleOff(m, q, d);
  return sum / m.numQuads();
}

TEST(FieldRelaxation, AGridTurnsTowardsAFieldItIsTurnedFrom) {
  // Local averages cannot turn a grid (each quad turned about its own centre gives every inner
  // vertex back); the relaxation solved for all vertices at once does.
  const Plane plane;
  const ClosestPointIndex surface(plane.positions, plane.triangles);
  const double turn = 12 * kPi / 180;
  const Vec3 d(std::cos(turn), std::sin(turn), 0);
  const std::vector<Vec3> directions(2, d);
  QuadMesh grid = planarGrid(8);
  const std::vector<char> movable(grid.numVertices(), 1);
  const double before = meanAngleOff(grid, d);
  ASSERT_NEAR(before, turn, 1e-12);
  FieldRelaxation relaxed = relaxTowardsField(grid, surface, plane.normals, directions, movable, 0.1);
  ASSERT_TRUE(relaxed.solved);
  grid.positions = relaxed.positions;
  const double once = meanAngleOff(grid, d);
  relaxed = relaxTowardsField(grid, surface, plane.normals, directions, movable, 0.1);
  grid.positions = relaxed.positions;
  const double twice = meanAngleOff(grid, d);
  std::cout << "mean angle off the field: " << before * 180 / kPi << " deg, then " << once * 180 / kPi << ", "
            << twice * 180 / kPi << "\n";
  EXPECT_LT(once, before / 2);
  EXPECT_LT(twice, once);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_LT(angleOff(grid, q, d), turn) << "quad " << q;
  for (const Vec3& p : grid.positions) EXPECT_NEAR(p.z(), 0, 1e-12) << "moved off the surface";
  const QuadJacobian jacobian(grid);
  for (int q = 0; q < grid.numQuads(); ++q) EXPECT_GT(jacobian(q), 0.9) << "quad " << q << " lost its shape";
}

TEST(FieldRelaxation, AGridAlongTheFieldAndFixedVerticesStayWhereTheyAre) {
  const Plane plane;
  const ClosestPointIndex surface(plane.positions, plane.triangles);
  QuadMesh grid = planarGrid(5);
  // Along the field: nothing to do.
  std::vector<char> movable(grid.numVertices(), 1);
  FieldRelaxation relaxed = relaxTowardsField(grid, surface, plane.normals, std::vector<Vec3>(2, Vec3(0, 1, 0)), movable, 0.1);
  ASSERT_TRUE(relaxed.solved);
  for (int v = 0; v < grid.numVertices(); ++v) EXPECT_LT((relaxed.positions[v] - grid.positions[v]).norm(), 1e-9);
  // Turned from the field, with every other vertex fixed: those stay exactly.
  const Vec3 d(std::cos(0.2), std::sin(0.2), 0);
  for (int v = 0; v < grid.numVertices(); ++v) movable[v] = v % 2;
  relaxed = relaxTowardsField(grid, surface, plane.normals, std::vector<Vec3>(2, d), movable, 0.1);
  ASSERT_TRUE(relaxed.solved);
  int moved = 0;
  for (int v = 0; v < grid.numVertices(); ++v) {
    if (!movable[v]) EXPECT_EQ(relaxed.positions[v], grid.positions[v]);
    moved += relaxed.positions[v] != grid.positions[v];
  }
  EXPECT_GT(moved, 0);
  // No field anywhere (a mean-value patch): nothing asks to move.
  relaxed = relaxTowardsField(grid, surface, plane.normals, std::vector<Vec3>(2, Vec3::Zero()), movable, 0.1);
  for (int v = 0; v < grid.numVertices(); ++v) EXPECT_LT((relaxed.positions[v] - grid.positions[v]).norm(), 1e-12);
}

TEST(FieldRelaxation, SmoothingTurnsBackAPartOfTheGridTurnedFromTheField) {
  // A 12×12 grid along the field whose middle (vertices 3..9 each way) is turned by 12° about
  // its centre, as the quads along a layout side that leaves a singularity off the field. Inside
  // that part the quads are turned rigidly, so the smoothing's local averages leave its
  // vertices where they are; the relaxation turns the part back. The border stays (fixed), and
  // no quad goes to a scaled Jacobian of 0.1 or below.
  const Plane plane;
  const int n = 12;
  QuadMesh turned = planarGrid(n);
  const double turn = 12 * kPi / 180;
  const Vec3 centre(6, 6, 0);
  for (Vec3& p : turned.positions)
    if (p.x() >= 3 && p.x() <= 9 && p.y() >= 3 && p.y() <= 9) {
      const Vec3 r = p - centre;
      p = centre + Vec3(r.x() * std::cos(turn) - r.y() * std::sin(turn), r.x() * std::sin(turn) + r.y() * std::cos(turn), 0);
    }
  const Vec3 d(1, 0, 0);
  SmoothingOptions options;
  options.iterations = 1;
  options.triangleDirections.assign(2, d);
  options.fieldRelaxationRounds = 0;
  QuadMesh without = turned;
  smoothQuadMesh(without, plane.positions, plane.triangles, options);
  QuadMesh with = turned;
  options.fieldRelaxationRounds = 2;
  const SmoothingReport report = smoothQuadMesh(with, plane.positions, plane.triangles, options);
  EXPECT_GT(report.relaxedMoves, 0);
  const double start = meanAngleOff(turned, d), a = meanAngleOff(without, d), b = meanAngleOff(with, d);
  std::cout << "mean angle off the field: " << start * 180 / kPi << " deg turned, " << a * 180 / kPi
            << " smoothed without the relaxation, " << b * 180 / kPi << " with it\n";
  EXPECT_LT(b, 0.5 * a);
  const QuadJacobian jacobian(with);
  for (int q = 0; q < with.numQuads(); ++q) EXPECT_GT(jacobian(q), 0.1) << "quad " << q;
  for (int v = 0; v < with.numVertices(); ++v) {
    const Vec3& p = turned.positions[v];
    if (p.x() == 0 || p.y() == 0 || p.x() == n || p.y() == n) EXPECT_EQ(with.positions[v], p) << "a border vertex moved";
    EXPECT_NEAR(with.positions[v].z(), 0, 1e-12);
  }
}

TEST(FieldRelaxation, BadOptionsAreRejected) {
  const Plane plane;
  QuadMesh grid = planarGrid(2);
  SmoothingOptions options;
  options.fieldRelaxationRounds = -1;
  EXPECT_THROW(smoothQuadMesh(grid, plane.positions, plane.triangles, options), std::invalid_argument);
  options.fieldRelaxationRounds = 2;
  options.fieldRelaxationAnchor = 0;
  EXPECT_THROW(smoothQuadMesh(grid, plane.positions, plane.triangles, options), std::invalid_argument);
}

}  // namespace
}  // namespace fcql
