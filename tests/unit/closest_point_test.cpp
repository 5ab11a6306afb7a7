#include "mesh/generators.h"
#include "mesh/closest_point_index.h"
#include "mesh/point_buckets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace fcql;

namespace {

double bruteForceDistance(const SurfaceMesh& mesh, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < mesh.numFaces(); ++f) {
    const Vec3 q = closestPointOnTriangle(p, mesh.position(mesh.vertex(f, 0)), mesh.position(mesh.vertex(f, 1)),
                                          mesh.position(mesh.vertex(f, 2)));
    best = std::min(best, (q - p).norm());
  }
  return best;
}

}  // namespace

TEST(ClosestPointIndex, AgreesWithBruteForceNearFarAndOutsideTheGrid) {
  // The search stops once no unvisited cell can be nearer than the best so far: points on the
  // surface, just off it, in the hole, and far outside the grid must all get the true nearest.
  const SurfaceMesh torus = makeTorus(1.0, 0.3, 40, 20);
  const ClosestPointIndex index(torus);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int checked = 0;
  for (double spread : {0.0, 0.02, 0.1, 0.3, 1.5, 6.0}) {
    for (int i = 0; i < (spread == 0.1 ? 2000 : 150); ++i) {
      const int f = int(random() % torus.numFaces());
      const Vec3 onSurface = (torus.position(torus.vertex(f, 0)) + torus.position(torus.vertex(f, 1)) +
                              torus.position(torus.vertex(f, 2))) / 3;
      const Vec3 p = onSurface + spread * Vec3(unit(random), unit(random), unit(random));
      const ClosestPoint cp = index.closest(p);
      ASSERT_GE(cp.triangle, 0);
      EXPECT_NEAR(cp.distance, bruteForceDistance(torus, p), 1e-12) << "spread " << spread << ", point " << i;
      EXPECT_NEAR((cp.point - p).norm(), cp.distance, 1e-12);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2750);
  // Points on a lattice through the whole grid and beyond it, finer than its cells: many lie
  // just beside a cell face, on every side, where a shell bound off by one cell goes wrong.
  const Vec3 lo(-1.6, -1.6, -0.6), hi(1.6, 1.6, 0.6);
  int lattice = 0;
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j)
      for (int k = 0; k <= 6; ++k) {
        const Vec3 p = lo + Vec3(i / 16.0 * (hi.x() - lo.x()), j / 16.0 * (hi.y() - lo.y()), k / 6.0 * (hi.z() - lo.z()));
        ASSERT_NEAR(index.closest(p).distance, bruteForceDistance(torus, p), 1e-12) << p.transpose();
        ++lattice;
      }
  EXPECT_EQ(lattice, 17 * 17 * 7);
}

TEST(PointBuckets, NearestWithinACellAgreesWithBruteForce) {
  // Any point within a cell of the query is found, whatever cell it fell in; farther ones may
  // be missed (infinity), never reported nearer than they are. `enough` stops at the first
  // point that close, which is then at most that far.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-2, 2);
  std::vector<Vec3> points;
  for (int i = 0; i < 400; ++i) points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  const double cell = 0.5;
  PointBuckets buckets(points, cell);
  EXPECT_EQ(buckets.nearest(Vec3(0, 0, 0)), std::numeric_limits<double>::infinity());  // nothing added yet
  buckets.addAll();
  for (int i = 0; i < 300; ++i) {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    double truth = std::numeric_limits<double>::infinity();
    for (const Vec3& q : points) truth = std::min(truth, (q - p).norm());
    const double found = buckets.nearest(p);
    if (truth <= cell) EXPECT_EQ(found, truth);
    else EXPECT_GE(found, truth);
    const double early = buckets.nearest(p, 0.3);
    if (truth <= 0.3) EXPECT_LE(early, 0.3);
    else if (truth <= cell) EXPECT_EQ(early, truth);
  }
  buckets.clear();
  EXPECT_EQ(buckets.nearest(points[0]), std::numeric_limits<double>::infinity());
  buckets.add(7);
  EXPECT_EQ(buckets.nearest(points[7]), 0.0);
}
