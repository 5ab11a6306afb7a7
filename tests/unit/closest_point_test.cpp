#include "mesh/generators.h"
#include "mesh/closest_point_index.h"

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
