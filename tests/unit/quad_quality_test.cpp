#include "metrics/quad_quality.h"
#include "test_support.h"

#include "util/math_constants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace fcql;

namespace {

/// The unit square in the plane z = 0 as 2·n² triangles, with the field along x.
struct FlatSquare {
  SurfaceMesh mesh;
  CrossField field;
};

FlatSquare flatSquare(int n) {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) positions.push_back(Vec3(double(i) / n, double(j) / n, 0));
  auto at = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  FlatSquare s{SurfaceMesh(positions, faces), CrossField()};
  s.field = CrossField::fromVectors(s.mesh, std::vector<Vec3>(faces.size(), Vec3(1, 0, 0)));
  return s;
}

/// An n × n grid of quads covering the unit square, its lines along (1, 0) turned by `turn`
/// and along (0, 1) turned by `turn` + `shear` (radians), mapped into the square by an affine
/// map that fixes its centre (the grid overhangs or falls short of the square at the edges,
/// which the measures below do not mind: every face's centroid still has a quad nearest).
QuadMesh grid(int n, double turn, double shear) {
  const Vec3 a(std::cos(turn), std::sin(turn), 0), b(-std::sin(turn + shear), std::cos(turn + shear), 0);
  QuadMesh q;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) q.positions.push_back(Vec3(0.5, 0.5, 0) + (double(i) / n - 0.5) * a + (double(j) / n - 0.5) * b);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      q.quads.push_back({j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i});
      q.quadPatch.push_back(0);
    }
  return q;
}

QuadQuality quality(const QuadMesh& q, const FlatSquare& s) {
  const ClosestPointIndex index(s.mesh);
  return measureQuadQuality(q, s.mesh, s.field, index);
}

}  // namespace

TEST(QuadQuality, MisalignmentOfQuadsAndOfFacesAsThePaperCountsThem) {
  const FlatSquare s = flatSquare(12);
  // On the field: nothing misaligned either way.
  QuadQuality r = quality(grid(10, 0, 0), s);
  EXPECT_EQ(r.misalignedPercent, 0);
  EXPECT_EQ(r.misalignedFacesPercent, 0);
  // Sheared by 20°, one family of lines on the field: every quad has a direction 20° off,
  // but the cross that fits both is 10° off, under π/16 = 11.25°.
  r = quality(grid(10, 0, 20 * kPi / 180), s);
  EXPECT_EQ(r.misalignedPercent, 100);
  EXPECT_EQ(r.misalignedFacesPercent, 0);
  // Sheared by 30°: the fitted cross is 15° off.
  r = quality(grid(10, 0, 30 * kPi / 180), s);
  EXPECT_EQ(r.misalignedFacesPercent, 100);
  // Square quads turned by 15°: both ways.
  r = quality(grid(10, 15 * kPi / 180, 0), s);
  EXPECT_EQ(r.misalignedPercent, 100);
  EXPECT_EQ(r.misalignedFacesPercent, 100);
  // Turned by a quarter turn plus 5°: the cross ignores quarter turns, and 5° is under π/16.
  r = quality(grid(10, (90 + 5) * kPi / 180, 0), s);
  EXPECT_EQ(r.misalignedPercent, 0);
  EXPECT_EQ(r.misalignedFacesPercent, 0);
}

TEST(QuadQuality, EachFaceIsMeasuredAgainstTheQuadOverIt) {
  // Two grids side by side: on the left half of the square 8 × 8 quads on the field, on the
  // right half 4 × 4 quads turned by 20°. About half of the faces lie under each (a few near the
  // middle under the turned grid's overhanging corners), and only those under the turned one
  // are misaligned. (The grids differ in size so that a face measured against the wrong quad
  // would show.)
  const FlatSquare s = flatSquare(12);
  QuadMesh left = grid(8, 0, 0), right = grid(4, 20 * kPi / 180, 0);
  QuadMesh both;
  for (const QuadMesh* g : {&left, &right}) {
    const int offset = both.numVertices();
    const Vec3 shift = g == &left ? Vec3(-0.25, 0, 0) : Vec3(0.25, 0, 0);
    for (const Vec3& p : g->positions) both.positions.push_back(Vec3(0.5, 0.5, 0) + 0.5 * (p - Vec3(0.5, 0.5, 0)) + shift);
    for (const auto& q : g->quads) both.quads.push_back({q[0] + offset, q[1] + offset, q[2] + offset, q[3] + offset});
    both.quadPatch.insert(both.quadPatch.end(), g->quadPatch.begin(), g->quadPatch.end());
  }
  const QuadQuality r = quality(both, s);
  EXPECT_EQ(r.misalignedPercent, 20);  // per quad: the right grid's 16 of 80
  EXPECT_GE(r.misalignedFacesPercent, 45);
  EXPECT_LE(r.misalignedFacesPercent, 60);
}

namespace {

/// An n × n grid of quads on a bumpy height field (so that the normals differ per vertex).
QuadMesh bumpyGrid(int n) {
  QuadMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      m.positions.push_back(Vec3(i, j, 0.3 * std::sin(1.3 * i) * std::cos(0.7 * j)));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.quads.push_back({j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i});
  return m;
}

}  // namespace

TEST(QuadQuality, TrackedNormalsGiveTheSameFiguresAsComputedOnes) {
  // The untangling and the fold repair move one vertex at a time and keep the normals with
  // moved(): every figure must equal, bit for bit, the one computed from scratch, also for
  // quads folded by the moves.
  QuadMesh tracked = bumpyGrid(8);
  QuadMesh fresh = tracked;
  const QuadJacobian keeping(tracked), computing(fresh);
  keeping.track();
  std::vector<int> all(tracked.quads.size());
  for (int q = 0; q < int(all.size()); ++q) all[q] = q;
  std::vector<double> a, b;
  int folded = 0;
  for (int step = 0; step < 200; ++step) {
    const int v = (step * 37) % tracked.numVertices();
    const Vec3 move(0.9 * std::sin(step), 0.9 * std::cos(2.0 * step), 0.5 * std::sin(3.0 * step));
    tracked.positions[v] += move;
    fresh.positions[v] += move;
    keeping.moved(v);
    keeping.values(all, a);
    computing.values(all, b);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "quad " << i << " after step " << step;
    for (int w = 0; w < tracked.numVertices(); ++w) {
      const Vec3 kept = keeping.normals()[w], computed = computing.vertexNormal(w);
      ASSERT_EQ(kept, computed) << "vertex " << w << " after step " << step;
    }
    folded += int(std::count_if(a.begin(), a.end(), [](double j) { return j <= 0; }));
  }
  EXPECT_GT(folded, 0);  // the moves did fold quads: the comparison covered them
  // Untracked again: values() computes the normals itself, from the positions as they are now.
  keeping.untrack();
  tracked.positions[0] += Vec3(0.5, 0.5, 0.5);
  fresh.positions[0] += Vec3(0.5, 0.5, 0.5);
  keeping.values(all, a);
  computing.values(all, b);
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "quad " << i << " untracked";
}

TEST(QuadQuality, DeviationBoundIsAnUpperBoundAndTightWhereAPassFails) {
  // A bump of height 0.1 over the unit square against a flat 4 × 4 quad grid, and a reference
  // distance from both surfaces sampled on barycentric grids 0.005 apart. Within the limit the
  // bound must prove it (bound ≤ limit); above it, the measure may stop cutting early, but its
  // bound must still be an upper bound, within 5% of the true distance's excess over the
  // limit, and found with few samples even though the resolution asked is tiny.
  const int n = 40;
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      positions.push_back(Vec3(x, y, 0.1 * std::sin(kPi * x) * std::sin(kPi * y)));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 2});
      faces.push_back({a, a + n + 2, a + n + 1});
    }
  const ClosestPointIndex surface(positions, faces);
  const QuadMesh quads = grid(4, 0, 0);
  const std::vector<std::array<int, 3>> quadTris = quadTriangles(quads);
  const ClosestPointIndex quadIndex(quads.positions, quadTris);
  const double spacing = 0.005;
  const double dense = std::max(test::sampledOneWayDistance(quads.positions, quadTris, surface, spacing),
                                test::sampledOneWayDistance(positions, faces, quadIndex, spacing));
  ASSERT_GT(dense, 0.09);
  ASSERT_LT(dense, 0.1 + 1e-9);

  const SurfaceDeviation within = measureDeviation(quads, surface, 2 * dense, 1e-3);
  EXPECT_LE(within.bound, 2 * dense);
  EXPECT_GE(within.bound, dense - 1e-12);
  EXPECT_TRUE(within.farPoints.empty());

  const double limit = dense / 3;
  const SurfaceDeviation failed = measureDeviation(quads, surface, limit, 1e-4);
  EXPECT_GT(failed.distance, limit);
  EXPECT_LE(failed.distance, failed.bound);
  EXPECT_GE(failed.bound, dense - 1e-12);
  // The true distance is within the reference's sample spacing of it.
  EXPECT_LE(failed.bound, dense + spacing + 0.05 * (dense + spacing - limit));
  EXPECT_FALSE(failed.farPoints.empty());
  // Cut to the resolution wherever the quads are over the limit, as it was, there would be
  // millions of far samples.
  EXPECT_LT(failed.farPoints.size(), 50000u);
}

TEST(QuadQuality, AMoveSpoilsAQuadItTakesToTheFloorOrFolds) {
  // Above the floor to it or below spoils; below it already, only a fold does; folded ones
  // getting worse or better do not; the figures are compared pairwise.
  EXPECT_FALSE(spoilsQuads({0.9, 0.5}, {0.8, 0.2}, 0.1));
  EXPECT_TRUE(spoilsQuads({0.9, 0.5}, {0.8, 0.1}, 0.1));
  EXPECT_FALSE(spoilsQuads({0.05}, {0.01}, 0.1));
  EXPECT_TRUE(spoilsQuads({0.05}, {0.0}, 0.1));
  EXPECT_FALSE(spoilsQuads({-0.2}, {-0.5}, 0.1));
  EXPECT_FALSE(spoilsQuads({-0.2}, {0.5}, 0.1));
  EXPECT_FALSE(spoilsQuads({}, {}, 0.1));
}
