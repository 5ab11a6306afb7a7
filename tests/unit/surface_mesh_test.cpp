#include "mesh/surface_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fcql;

namespace {

// A regular tetrahedron with outward CCW faces.
SurfaceMesh tetrahedron() {
  std::vector<Vec3> p = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::vector<std::array<int, 3>> f = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return SurfaceMesh(p, f);
}

// A flat n×n grid of squares split into triangles, in the z = 0 plane, normals +z.
SurfaceMesh grid(int n) {
  std::vector<Vec3> p;
  std::vector<std::array<int, 3>> f;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.emplace_back(i, j, 0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return SurfaceMesh(p, f);
}

std::string errorOf(std::vector<Vec3> p, std::vector<std::array<int, 3>> f) {
  try {
    SurfaceMesh m(p, f);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SurfaceMesh, TetrahedronTopology) {
  SurfaceMesh m = tetrahedron();
  EXPECT_EQ(m.numEdges(), 6);
  EXPECT_EQ(m.eulerCharacteristic(), 2);
  EXPECT_EQ(m.genus(), 0);
  EXPECT_EQ(m.numBorderLoops(), 0);
  EXPECT_EQ(m.numComponents(), 1);
  for (int f = 0; f < m.numFaces(); ++f) {
    EXPECT_GT(m.faceNormal(f).dot(m.faceCentroid(f)), 0) << "normal of face " << f << " points inward";
    for (int i = 0; i < 3; ++i) {
      int g = m.adjacentFace(f, i), j = m.adjacentEdge(f, i);
      ASSERT_GE(g, 0);
      EXPECT_EQ(m.adjacentFace(g, j), f);
      EXPECT_EQ(m.vertex(f, i), m.vertex(g, (j + 1) % 3));
      EXPECT_EQ(m.edgeId(f, i), m.edgeId(g, j));
    }
  }
}

TEST(SurfaceMesh, StarsAreCounterClockwiseFans) {
  SurfaceMesh m = grid(3);
  // Interior vertex (1,1) has 6 faces, angles summing to 2π; consecutive faces share an edge.
  int v = 1 * 4 + 1;
  const auto& star = m.star(v);
  ASSERT_EQ(star.size(), 6u);
  double total = 0;
  for (std::size_t k = 0; k < star.size(); ++k) {
    total += m.cornerAngle(star[k].face, star[k].corner);
    const auto& next = star[(k + 1) % star.size()];
    // The edge entering v in face k is the edge leaving v in face k+1.
    int entering = (star[k].corner + 2) % 3;
    EXPECT_EQ(m.adjacentFace(star[k].face, entering), next.face);
    EXPECT_EQ(m.vertex(star[k].face, entering), m.vertex(next.face, (next.corner + 1) % 3));
  }
  EXPECT_NEAR(total, 2 * M_PI, 1e-12);
  EXPECT_FALSE(m.isBorderVertex(v));
  // Border vertex (1,0): the fan starts and ends at border edges.
  int b = 1;
  EXPECT_TRUE(m.isBorderVertex(b));
  const auto& bs = m.star(b);
  EXPECT_TRUE(m.isBorderEdge(bs.front().face, bs.front().corner));
  EXPECT_TRUE(m.isBorderEdge(bs.back().face, (bs.back().corner + 2) % 3));
  EXPECT_EQ(m.numBorderLoops(), 1);
  EXPECT_EQ(m.eulerCharacteristic(), 1);
  EXPECT_EQ(m.genus(), 0);
}

TEST(SurfaceMesh, RejectsBadInputWithClearMessages) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  EXPECT_NE(errorOf(p, {}).find("no faces"), std::string::npos);
  EXPECT_NE(errorOf(p, {{0, 1, 7}}).find("out of range"), std::string::npos);
  EXPECT_NE(errorOf(p, {{0, 1, 1}}).find("same vertex twice"), std::string::npos);
  std::vector<Vec3> collinear = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_NE(errorOf(collinear, {{0, 1, 2}}).find("degenerate"), std::string::npos);
  std::vector<Vec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}};
  EXPECT_NE(errorOf(nan, {{0, 1, 2}}).find("non-finite"), std::string::npos);
  // Three triangles on one edge.
  EXPECT_NE(errorOf(p, {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}}).find("non-manifold edge"), std::string::npos);
  // Two triangles running their shared edge the same way.
  EXPECT_NE(errorOf(p, {{0, 1, 2}, {0, 1, 3}}).find("inconsistent orientation"), std::string::npos);
  // Two fans touching at vertex 0 only (a bow tie).
  std::vector<Vec3> q = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  EXPECT_NE(errorOf(q, {{0, 1, 2}, {0, 3, 4}}).find("non-manifold vertex"), std::string::npos);
}

TEST(SurfaceMesh, UnreferencedVerticesDoNotCount) {
  std::vector<Vec3> p = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}, {5, 5, 5}};
  std::vector<std::array<int, 3>> f = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  SurfaceMesh m(p, f);
  EXPECT_EQ(m.eulerCharacteristic(), 2);
  EXPECT_TRUE(m.star(4).empty());
}
