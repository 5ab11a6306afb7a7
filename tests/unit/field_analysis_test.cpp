#include "field/field_analysis.h"
#include "field/field_io.h"
#include "mesh/mesh_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

using namespace fcql;
using fcql::test::axisField;
using fcql::test::sharpCube;

namespace {

SurfaceMesh flatGrid(int n) {
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

}  // namespace

TEST(FieldAnalysis, MatchingsAreInverseAcrossEachEdge) {
  SurfaceMesh m = sharpCube(3);
  std::vector<Vec3> u(m.numFaces());
  for (int f = 0; f < m.numFaces(); ++f) {  // an arbitrary, non-smooth field
    Vec3 t = m.faceFrameX(f) * std::cos(0.7 * f) + m.faceFrameY(f) * std::sin(0.7 * f);
    u[f] = t;
  }
  CrossField field = CrossField::fromVectors(m, u);
  FieldAnalysis a = analyzeField(m, field);
  for (int f = 0; f < m.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int g = m.adjacentFace(f, i), j = m.adjacentEdge(f, i);
      EXPECT_EQ((a.matching[f][i] + a.matching[g][j]) % 4, 0);
      // Direction 0 of f carried across the edge lands within 45° of direction matching of g.
      Vec3 carried = field.direction(m, f, 0);
      Vec3 target = unfoldIntoFace(m, f, i, field.direction(m, g, a.matching[f][i]));
      EXPECT_GT(carried.dot(target), std::cos(M_PI / 4) - 1e-9);
    }
  // Whatever the field, interior indices of a closed surface sum to χ = 2.
  EXPECT_EQ(a.indexSumQuarters(), 4 * 2);
}

TEST(FieldAnalysis, CubeCornersAreThreePortSingularitiesAlongTheEdges) {
  SurfaceMesh m = sharpCube(4);
  CrossField field = axisField(m);
  FieldAnalysis a = analyzeField(m, field);
  ASSERT_EQ(a.numInteriorSingularities(), 8);
  EXPECT_EQ(a.indexSumQuarters(), 8);
  EXPECT_EQ(a.numPorts(), 24);
  for (const auto& s : a.singularities) {
    EXPECT_EQ(s.indexQuarters, 1);
    const Vec3& corner = m.position(s.vertex);
    EXPECT_NEAR(corner.cwiseAbs().minCoeff(), 1.0, 1e-12) << "singularity not at a cube corner";
    ASSERT_EQ(s.ports.size(), 3u);
    // Each port runs along one of the three cube edges leaving the corner, all distinct.
    std::set<int> axes;
    for (const auto& port : s.ports) {
      int axis;
      double along = port.tangent.cwiseAbs().maxCoeff(&axis);
      EXPECT_NEAR(along, 1.0, 1e-9);
      EXPECT_LT(port.tangent[axis] * corner[axis], 0) << "port points away from the cube";
      axes.insert(axis);
      // The port follows the field direction it names, inside the face it names.
      EXPECT_NEAR(field.direction(m, port.face, port.fieldDirection).dot(port.tangent), 1.0, 1e-9);
      EXPECT_NEAR(m.faceNormal(port.face).dot(port.tangent), 0.0, 1e-9);
    }
    EXPECT_EQ(axes.size(), 3u);
  }
}

TEST(FieldAnalysis, FlatSquareWithConstantFieldHasFourBorderCorners) {
  SurfaceMesh m = flatGrid(5);
  std::vector<Vec3> u(m.numFaces(), Vec3(1, 0, 0));
  CrossField field = CrossField::fromVectors(m, u);
  FieldAnalysis a = analyzeField(m, field);
  EXPECT_EQ(a.numInteriorSingularities(), 0);
  EXPECT_EQ(a.numBorderSingularities(), 4);
  EXPECT_EQ(a.indexSumQuarters(), 4 * m.eulerCharacteristic());
  for (const auto& s : a.singularities) {
    EXPECT_TRUE(s.onBorder);
    EXPECT_EQ(s.indexQuarters, 1);
    EXPECT_TRUE(s.ports.empty()) << "a convex 90-degree corner has no port into the surface";
  }
  // A straight border vertex has exactly one port, orthogonal to the border, pointing inside.
  int v = 2;  // (2, 0) on the bottom side
  auto ports = computePorts(m, field, v);
  ASSERT_EQ(ports.size(), 1u);
  EXPECT_NEAR(ports[0].tangent.y(), 1.0, 1e-9);
  // An interior regular vertex has four ports along ±x and ±y.
  auto interior = computePorts(m, field, 2 * 6 + 2);
  ASSERT_EQ(interior.size(), 4u);
  for (const auto& p : interior) EXPECT_NEAR(p.tangent.cwiseAbs().maxCoeff(), 1.0, 1e-9);
  EXPECT_NEAR(interior[1].flatAngle - interior[0].flatAngle, M_PI / 2, 1e-9);
}

TEST(FieldAnalysis, FormatsQuarterIndices) {
  EXPECT_EQ(formatQuarterIndex(-1), "-1/4");
  EXPECT_EQ(formatQuarterIndex(1), "1/4");
  EXPECT_EQ(formatQuarterIndex(2), "1/2");
  EXPECT_EQ(formatQuarterIndex(-3), "-3/4");
  EXPECT_EQ(formatQuarterIndex(4), "1");
  EXPECT_EQ(formatQuarterIndex(0), "0");
}

TEST(FieldAnalysis, EightWithItsFieldHas24Singularities) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, field, "eight");
  FieldAnalysis a = analyzeField(m, field);
  EXPECT_EQ(a.numInteriorSingularities(), 24);
  auto histogram = a.interiorHistogram();
  std::map<std::string, int> hist(histogram.begin(), histogram.end());
  EXPECT_EQ(hist["-1/4"], 16);
  EXPECT_EQ(hist["1/4"], 8);
  EXPECT_EQ(a.indexSumQuarters(), 4 * m.eulerCharacteristic());
  EXPECT_EQ(m.eulerCharacteristic(), -2);
  // 5 ports at index -1/4, 3 at +1/4, all with distinct flattened angles around the vertex.
  for (const auto& s : a.singularities) {
    ASSERT_EQ(int(s.ports.size()), 4 - s.indexQuarters) << "vertex " << s.vertex;
    for (std::size_t i = 1; i < s.ports.size(); ++i)
      EXPECT_GT(s.ports[i].flatAngle, s.ports[i - 1].flatAngle);
  }
  EXPECT_EQ(a.numPorts(), 16 * 5 + 8 * 3);
}

TEST(FieldAnalysis, SharedFieldsSumToEulerCharacteristic) {
  for (const char* name : {"dragon", "lilium"}) {
    std::string obj = fcql::test::sharedMesh(std::string(name) + ".obj");
    if (obj.empty()) GTEST_SKIP() << "../shared is absent: skipped";
    SurfaceMesh m = loadMesh(obj);
    FieldAnalysis a = analyzeField(m, loadField(m, fcql::test::sharedMesh(std::string(name) + ".ffield")));
    if (m.numBorderLoops() == 0) {
      EXPECT_EQ(a.indexSumQuarters(), 4 * m.eulerCharacteristic()) << name;
    }
    if (std::string(name) == "dragon") {
      EXPECT_EQ(a.numInteriorSingularities(), 795);  // SOURCES.md: a noisy field
    } else {
      EXPECT_EQ(a.numInteriorSingularities(), 15);  // SOURCES.md: {-1/4: 6, 1/4: 8, 1/2: 1}
    }
  }
}

TEST(FieldAnalysis, StarChartCarriesOneDirectionAroundTheVertex) {
  SurfaceMesh m = sharpCube(3);
  CrossField field = axisField(m);
  for (int v : {0, 5, 17}) {
    StarChart c = computeStarChart(m, field, v);
    ASSERT_EQ(c.psi.size(), m.star(v).size());
    for (std::size_t k = 0; k < c.psi.size(); ++k) {
      int f = m.star(v)[k].face;
      double angle = c.chartAngleOf(m, int(k), field.direction(m, f, c.carried[k]));
      EXPECT_NEAR(std::remainder(angle - c.psi[k], 2 * M_PI), 0, 1e-9) << "vertex " << v << " face " << k;
    }
    EXPECT_NEAR(c.theta * c.flatScale, 2 * M_PI, 1e-12);
  }
}

#include "field/field_generation.h"

TEST(FieldAnalysis, PortCountsMatchIndicesOnSharpAndNoisyMeshes) {
  // Fields aligned to sharp edges put cross directions exactly along mesh edges; the port
  // count must still be 4 − 4·index (interior) and 1 − 4·index (border) at every singularity.
  for (const char* name : {"deckel", "fandisk", "dragon", "camelhead"}) {
    std::string obj = test::sharedMesh(std::string(name) + ".obj");
    if (obj.empty()) GTEST_SKIP() << "../shared is absent: skipped";
    SurfaceMesh m = loadMesh(obj);
    std::string ffield = test::sharedMesh(std::string(name) + ".ffield");
    CrossField f = ffield.empty() ? generateCrossField(m) : loadField(m, ffield);
    FieldAnalysis a = analyzeField(m, f);
    for (const auto& s : a.singularities) {
      int expected = s.onBorder ? std::max(0, 1 - s.indexQuarters) : 4 - s.indexQuarters;
      EXPECT_EQ(int(s.ports.size()), expected) << name << " vertex " << s.vertex << " index/4 " << s.indexQuarters;
    }
  }
}

#include "mesh/generators.h"

TEST(FieldAnalysis, WarnsAboutCentresThatLeaveNoSeparatrix) {
  // A closed cylinder whose caps are triangle fans, as CAD exports often are: each cap has a
  // single inner vertex, which takes the cap's whole index +1 (its field runs round the rim)
  // and leaves no separatrix. The log must say so, name it and say what helps.
  const int k = 24;
  std::vector<Vec3> positions;
  for (double z : {0.0, 3.0})
    for (int i = 0; i < k; ++i) positions.push_back(Vec3(std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k), z));
  positions.push_back(Vec3(0, 0, 0));
  positions.push_back(Vec3(0, 0, 3));
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < k; ++i) {
    const int a = i, b = (i + 1) % k;
    faces.push_back({a, b, k + b});
    faces.push_back({a, k + b, k + a});
    faces.push_back({2 * k, b, a});
    faces.push_back({2 * k + 1, k + a, k + b});
  }
  SurfaceMesh capped(positions, faces);
  FieldAnalysis a = analyzeField(capped, generateCrossField(capped));
  const std::vector<std::string> warnings = fieldWarnings(capped, a);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("2 singularities of index 3/4 or more"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("vertex 48 (index 1, 24 triangles around it)"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("refine the mesh"), std::string::npos) << warnings[0];
  // A rounded box's field has eight +1/4 corners: nothing to warn about.
  SurfaceMesh box = makeRoundedBox();
  EXPECT_TRUE(fieldWarnings(box, analyzeField(box, generateCrossField(box))).empty());
}
