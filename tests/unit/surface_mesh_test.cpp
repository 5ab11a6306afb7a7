#include "mesh/surface_mesh.h"

#include "mesh/generators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

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

TEST(SurfaceMesh, BorderLoopsAreClosedWalksOfEveryBorderEdge) {
  // An open cylinder of 48 × 32 quads: two border circles of 48 edges each.
  SurfaceMesh m = makeOpenCylinder(0.5, 2.0, 48, 32);
  ASSERT_EQ(m.numBorderLoops(), 2);
  std::set<int> walked;
  for (const auto& loop : m.borderLoops()) {
    ASSERT_EQ(loop.size(), 48u);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const StarCorner& e = loop[k];
      const StarCorner& next = loop[(k + 1) % loop.size()];
      EXPECT_TRUE(m.isBorderEdge(e.face, e.corner));
      EXPECT_TRUE(walked.insert(m.edgeId(e.face, e.corner)).second) << "a border edge walked twice";
      // Each edge ends where the next one starts; the last one where the loop began.
      EXPECT_EQ(m.vertex(e.face, (e.corner + 1) % 3), m.vertex(next.face, next.corner));
    }
  }
  int borderEdges = 0;
  for (int f = 0; f < m.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) borderEdges += m.isBorderEdge(f, i);
  EXPECT_EQ(int(walked.size()), borderEdges);
  EXPECT_TRUE(makeTorus().borderLoops().empty());
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

#include "mesh/vertex_welding.h"

TEST(VertexWelding, AnUnweldedMeshGetsItsSurfaceBack) {
  // Every face with its own three vertices (a triangle soup): 1 component per face, each with
  // a border. Welding gives the rounded box back, faces in their order.
  SurfaceMesh box = makeRoundedBox();
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> faces;
  for (int f = 0; f < box.numFaces(); ++f) {
    std::array<int, 3> t;
    for (int c = 0; c < 3; ++c) t[c] = int(positions.size()), positions.push_back(box.position(box.vertex(f, c)));
    faces.push_back(t);
  }
  SurfaceMesh soup(positions, faces);
  ASSERT_EQ(soup.numBorderLoops(), box.numFaces());
  VertexWelding w = weldCoincidentVertices(soup);
  ASSERT_TRUE(w.welded) << w.problem;
  EXPECT_EQ(w.merged, 3 * box.numFaces() - box.numVertices());
  EXPECT_EQ(w.mesh.numVertices(), box.numVertices());
  EXPECT_EQ(w.mesh.numBorderLoops(), 0);
  EXPECT_EQ(w.mesh.genus(), 0);
  ASSERT_EQ(w.mesh.numFaces(), box.numFaces());
  for (int f = 0; f < box.numFaces(); ++f)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(w.mesh.position(w.mesh.vertex(f, c)), box.position(box.vertex(f, c)));
      EXPECT_EQ(w.newIndex[faces[f][c]], w.mesh.vertex(f, c));
    }
  EXPECT_NE(w.note().find("merged"), std::string::npos) << w.note();
  // Nothing to merge: nothing done, nothing to say.
  VertexWelding none = weldCoincidentVertices(box);
  EXPECT_EQ(none.merged, 0);
  EXPECT_FALSE(none.welded);
  EXPECT_TRUE(none.note().empty());
}

TEST(VertexWelding, SurfacesTouchingAtAPointStayApart) {
  // Two tetrahedra whose apexes coincide: merging them would make a non-manifold vertex.
  std::vector<Vec3> positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                                 Vec3(0, 0, 1), Vec3(1, 0, 2), Vec3(0, 1, 2), Vec3(0, 0, 2.5)};
  std::vector<std::array<int, 3>> faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3},
                                           {4, 6, 5}, {4, 5, 7}, {5, 6, 7}, {6, 4, 7}};
  SurfaceMesh two(positions, faces);
  VertexWelding w = weldCoincidentVertices(two);
  EXPECT_EQ(w.merged, 1);
  EXPECT_FALSE(w.welded);
  EXPECT_FALSE(w.problem.empty());
  EXPECT_NE(w.note().find("kept apart"), std::string::npos) << w.note();
}
