#include "metrics/base_complex.h"

#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include <gtest/gtest.h>

using namespace fcql;

namespace {

/// Quads of the unit cells of an open grid of integer points, the cells `keep` accepts.
template <typename Keep>
QuadMesh gridQuads(int nx, int ny, Keep keep) {
  QuadMesh m;
  std::map<std::pair<int, int>, int> index;
  auto vertex = [&](int x, int y) {
    auto [it, fresh] = index.emplace(std::make_pair(x, y), m.numVertices());
    if (fresh) m.positions.push_back(Vec3(x, y, 0));
    return it->second;
  };
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y)
      if (keep(x, y)) m.quads.push_back({vertex(x, y), vertex(x + 1, y), vertex(x + 1, y + 1), vertex(x, y + 1)});
  m.quadPatch.assign(m.quads.size(), 0);
  return m;
}

/// The surface of the cube [0, n]³ cut into unit quads (8 corners of valence 3).
QuadMesh cubeQuads(int n) {
  QuadMesh m;
  std::map<std::tuple<int, int, int>, int> index;
  auto vertex = [&](int x, int y, int z) {
    auto [it, fresh] = index.emplace(std::make_tuple(x, y, z), m.numVertices());
    if (fresh) m.positions.push_back(Vec3(x, y, z));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int a, int b) {
            int p[3];
            p[axis] = side;
            p[(axis + 1) % 3] = a;
            p[(axis + 2) % 3] = b;
            return vertex(p[0], p[1], p[2]);
          };
          m.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
  m.quadPatch.assign(m.quads.size(), 0);
  return m;
}

}  // namespace

TEST(BaseComplex, ARegularGridIsOnePatch) {
  const BaseComplex c = measureBaseComplex(gridQuads(5, 3, [](int, int) { return true; }));
  EXPECT_EQ(c.patches, 1);
  EXPECT_EQ(c.irregularVertices, 0);  // the four corners of valence 2 are the grid's own
  EXPECT_EQ(c.separatrices, 0);
}

TEST(BaseComplex, ACubeHasSixPatchesBoundedByItsTwelveEdges) {
  const BaseComplex c = measureBaseComplex(cubeQuads(4));
  EXPECT_EQ(c.patches, 6);
  EXPECT_EQ(c.irregularVertices, 8);
  EXPECT_EQ(c.separatrices, 12);  // each cube edge traced once, from one of its ends
  EXPECT_EQ(c.separatrixEdges, 12 * 4);
}

TEST(BaseComplex, AConcaveBorderCornerCutsAnLShapeIntoThreeRectangles) {
  // 6 × 6 cells without the upper right 3 × 3: the concave corner (3, 3) has valence 4 on the
  // border, and its two inner edges run straight to the border.
  const BaseComplex c = measureBaseComplex(gridQuads(6, 6, [](int x, int y) { return x < 3 || y < 3; }));
  EXPECT_EQ(c.irregularVertices, 1);
  EXPECT_EQ(c.separatrices, 2);
  EXPECT_EQ(c.separatrixEdges, 6);
  EXPECT_EQ(c.patches, 3);
}

TEST(BaseComplex, ATriangleCutIntoThreeGridsHasThreePatches) {
  // A triangle cut into three quads at its centre (valence 3) and its sides' midpoints, each
  // quad an n × n grid: three lines from the centre to the midpoints, three patches.
  const int n = 4;
  const Vec3 a(0, 0, 0), b(4, 0, 0), c(2, 3.5, 0);
  const Vec3 o = (a + b + c) / 3, ab = (a + b) / 2, bc = (b + c) / 2, ca = (c + a) / 2;
  QuadMesh m;
  std::map<std::tuple<long, long>, int> index;
  auto vertex = [&](const Vec3& p) {
    auto [it, fresh] = index.emplace(std::make_tuple(std::lround(p.x() * 1e6), std::lround(p.y() * 1e6)), m.numVertices());
    if (fresh) m.positions.push_back(p);
    return it->second;
  };
  for (const auto& corners : {std::array<Vec3, 4>{a, ab, o, ca}, std::array<Vec3, 4>{b, bc, o, ab},
                              std::array<Vec3, 4>{c, ca, o, bc}}) {
    auto at = [&](int i, int j) {
      const double u = double(i) / n, v = double(j) / n;
      return vertex((1 - u) * (1 - v) * corners[0] + u * (1 - v) * corners[1] + u * v * corners[2] +
                    (1 - u) * v * corners[3]);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) m.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  }
  m.quadPatch.assign(m.quads.size(), 0);
  ASSERT_EQ(m.numVertices(), 3 * (n + 1) * (n + 1) - 3 * (n + 1) + 1);
  const BaseComplex c3 = measureBaseComplex(m);
  EXPECT_EQ(c3.irregularVertices, 1);  // the centre; the triangle's corners have valence 2
  EXPECT_EQ(c3.separatrices, 3);
  EXPECT_EQ(c3.separatrixEdges, 3 * n);
  EXPECT_EQ(c3.patches, 3);
}

TEST(BaseComplex, ANonManifoldEdgeIsRejected) {
  QuadMesh m = gridQuads(1, 1, [](int, int) { return true; });
  m.positions.push_back(Vec3(0, 0, 1));
  m.positions.push_back(Vec3(1, 0, 1));
  m.positions.push_back(Vec3(0, 0, -1));
  m.positions.push_back(Vec3(1, 0, -1));
  m.quads.push_back({0, 1, 5, 4});
  m.quads.push_back({0, 1, 7, 6});
  EXPECT_THROW(measureBaseComplex(m), std::invalid_argument);
}
