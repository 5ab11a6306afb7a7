#include "field/field_analysis.h"
#include "field/field_generation.h"
#include "mesh/border_tangents.h"
#include "mesh/generators.h"
#include "mesh/surface_mesh.h"
#include "util/math_constants.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fcql;

namespace {

constexpr double kRowHeight = 0.8660254037844386;  // √3/2

/// A flat sheet of equilateral triangles of edge 1, `columns` wide and `rows` rows high: its
/// bottom and top sides are straight, its left and right sides zigzag (each row is shifted by
/// half an edge against the next), turning by ±60° at every vertex, as the border of a hole cut
/// into a scan does.
SurfaceMesh zigzagSheet(int columns, int rows) {
  std::vector<Vec3> P;
  std::vector<std::array<int, 3>> T;
  const auto id = [columns](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) P.emplace_back(i + 0.5 * (j % 2), j * kRowHeight, 0);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      if (j % 2 == 0) {  // the row above is shifted right
        T.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        T.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {           // the row above is shifted left
        T.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        T.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      }
    }
  return SurfaceMesh(std::move(P), std::move(T));
}

}  // namespace

TEST(BorderTangents, AZigzagSideGetsItsMeanDirectionAndStraightSidesKeepTheirOwn) {
  const int columns = 100, rows = 116;
  const SurfaceMesh m = zigzagSheet(columns, rows);
  ASSERT_EQ(m.numBorderLoops(), 1);
  const double reach = kBorderTangentReach * m.boundingBoxDiagonal();
  ASSERT_LT(1.0, reach / 2) << "the sheet's edges must be shorter than half a quad";
  const auto tangents = zigzagBorderTangents(m, reach);
  const double top = rows * kRowHeight;
  int sideEdges = 0;
  for (int f = 0; f < m.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      if (!m.isBorderEdge(f, i)) continue;
      const Vec3 mid = m.position(m.vertex(f, i)) + m.edgeVector(f, i) / 2;
      const auto it = tangents.find(m.edgeId(f, i));
      const bool side = mid.y() > 0.1 && mid.y() < top - 0.1;
      // Beside the corners the window shrinks, and where a zigzag meets a straight side the
      // corner may be either of two vertices: those edges are not checked.
      const bool nearCorner = (mid.x() < 5 || mid.x() > columns - 4.5) && (mid.y() < 5 || mid.y() > top - 5);
      if (nearCorner) continue;
      if (!side) {
        EXPECT_EQ(it, tangents.end()) << "a straight edge at " << mid.transpose();
        EXPECT_NEAR(std::abs(m.borderTangent(f, i).x()), 1.0, 1e-12);
        continue;
      }
      ++sideEdges;
      ASSERT_NE(it, tangents.end()) << "a zigzag edge at " << mid.transpose();
      EXPECT_GT(std::abs(it->second.y()), std::cos(3 * kPi / 180)) << "at " << mid.transpose();
      EXPECT_GT(it->second.dot(m.edgeVector(f, i)), 0) << "it points the way the edge runs";
      EXPECT_EQ(m.borderTangent(f, i), it->second);
    }
  EXPECT_GT(sideEdges, 2 * rows - 30);
}

TEST(BorderTangents, SmoothBordersKeepTheirEdgesDirections) {
  // Two circles of 48 edges, turning by 7.5° at each vertex the same way.
  const SurfaceMesh cylinder = makeOpenCylinder(0.5, 2.0, 48, 32, GridDiagonal::Same);
  EXPECT_TRUE(zigzagBorderTangents(cylinder, kBorderTangentReach * cylinder.boundingBoxDiagonal()).empty());
  // A reach of 0 lists nothing, even where the border zigzags.
  EXPECT_TRUE(zigzagBorderTangents(zigzagSheet(100, 116), 0).empty());
}

TEST(BorderTangents, AComputedFieldAlongAZigzagBorderHasOnlyTheCornersAsBorderSingularities) {
  // Constrained to each edge, the field turned by 60° at every vertex of the two zigzag sides
  // and the analysis found border singularities along them; a flat sheet needs only its four
  // corners.
  const SurfaceMesh m = zigzagSheet(100, 116);
  const CrossField field = generateCrossField(m);
  const FieldAnalysis a = analyzeField(m, field);
  EXPECT_EQ(a.indexSumQuarters(), 4 * m.eulerCharacteristic());
  EXPECT_EQ(a.numBorderSingularities(), 4);
  EXPECT_EQ(a.singularities.size(), 4u) << "no interior singularity on a flat sheet";
}

TEST(BorderTangents, TheQuartersOfAZigzagHoleLandOnVerticesOfTheirKind) {
  // A hole cut into the sheet (the faces within 3 edges of its centre): its border zigzags,
  // convex and reflex vertices in turn. A border quarter of index +1/4 is served by one quad,
  // which a reflex vertex (more than 180° of surface around it) folds; one of −1/4 by three
  // quads, which a sharp convex vertex crushes.
  const SurfaceMesh sheet = zigzagSheet(100, 116);
  const Vec3 centre(50, 58 * kRowHeight, 0);
  std::vector<std::array<int, 3>> kept;
  for (int f = 0; f < sheet.numFaces(); ++f)
    if ((sheet.faceCentroid(f) - centre).norm() > 3) kept.push_back(sheet.face(f));
  const SurfaceMesh m(sheet.positions(), kept);
  ASSERT_EQ(m.numBorderLoops(), 2);
  const FieldAnalysis a = analyzeField(m, generateCrossField(m));
  EXPECT_EQ(a.indexSumQuarters(), 4 * m.eulerCharacteristic());
  int onHole = 0;
  for (const SingularVertex& s : a.singularities) {
    if (!s.onBorder) continue;
    const double theta = a.starAngle[s.vertex] * 180 / kPi;
    if ((m.position(s.vertex) - centre).norm() < 6) ++onHole;
    if (s.indexQuarters > 0) EXPECT_LT(theta, 210) << "a convex quarter on a reflex vertex " << s.vertex;
    if (s.indexQuarters < 0) EXPECT_GT(theta, 150) << "a concave quarter on a convex vertex " << s.vertex;
  }
  // The hole takes 1 from the Euler characteristic: four concave quarters on its border, as on
  // a square hole (a larger hole's field turns with it and its quarters go inside).
  EXPECT_EQ(onHole, 4);
}
