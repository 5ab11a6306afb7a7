// Tests of the mesh generators: topology (genus, border loops, Euler characteristic), outward
// orientation, triangle shape, smoothness of the rounded box and exactness of its geometry,
// and the error for an unknown example name.
#include "mesh/generators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

using namespace fcql;

namespace {

constexpr double kDeg = 180.0 / M_PI;

/// Volume enclosed by a closed mesh (divergence theorem); positive iff the normals point out.
double signedVolume(const SurfaceMesh& m) {
  double v = 0;
  for (int f = 0; f < m.numFaces(); ++f) {
    const auto& t = m.face(f);
    v += m.position(t[0]).dot(m.position(t[1]).cross(m.position(t[2]))) / 6.0;
  }
  return v;
}

double minAngleDeg(const SurfaceMesh& m) {
  double a = 180;
  for (int f = 0; f < m.numFaces(); ++f)
    for (int c = 0; c < 3; ++c) a = std::min(a, m.cornerAngle(f, c) * kDeg);
  return a;
}

/// Largest angle between the normals of two faces sharing an edge.
double maxDihedralDeg(const SurfaceMesh& m) {
  double a = 0;
  for (int f = 0; f < m.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int g = m.adjacentFace(f, i);
      if (g >= 0) a = std::max(a, std::acos(std::clamp(m.faceNormal(f).dot(m.faceNormal(g)), -1.0, 1.0)) * kDeg);
    }
  return a;
}

/// Closest point of the box [-inner, inner] (the core of a rounded box).
Vec3 closestOnBox(const Vec3& p, const Vec3& inner) { return p.cwiseMax(-inner).cwiseMin(inner); }

struct Expected {
  std::string name;
  int genus, borderLoops, euler;
};

const Expected kExamples[] = {{"sphere", 0, 0, 2},
                              {"torus", 1, 0, 0},
                              {"double_torus", 2, 0, -2},
                              {"rounded_box", 0, 0, 2},
                              {"open_cylinder", 0, 2, 0}};

}  // namespace

TEST(Generators, ExampleNamesAreTheDocumentedOnes) {
  std::vector<std::string> expected;
  for (const Expected& e : kExamples) expected.push_back(e.name);
  EXPECT_EQ(exampleNames(), expected);
}

TEST(Generators, ExamplesHaveTheRightTopologyOrientationAndShape) {
  for (const Expected& e : kExamples) {
    SCOPED_TRACE(e.name);
    SurfaceMesh m;
    ASSERT_NO_THROW(m = makeExample(e.name));  // the SurfaceMesh constructor validates
    EXPECT_EQ(m.numComponents(), 1);
    EXPECT_EQ(m.genus(), e.genus);
    EXPECT_EQ(m.numBorderLoops(), e.borderLoops);
    EXPECT_EQ(m.eulerCharacteristic(), e.euler);
    EXPECT_EQ(m.eulerCharacteristic(), 2 - 2 * e.genus - e.borderLoops);
    if (e.borderLoops == 0) EXPECT_GT(signedVolume(m), 0) << "normals point inwards";
    EXPECT_GT(minAngleDeg(m), 25.0) << "sliver triangles";
    // A few thousand faces: big enough to be interesting, small enough for quick tests.
    EXPECT_GE(m.numFaces(), 1000);
    EXPECT_LE(m.numFaces(), 8000);
    // Every vertex is used (welded patches leave no duplicates behind).
    std::vector<char> used(m.numVertices(), 0);
    for (const auto& t : m.faces())
      for (int v : t) used[v] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), m.numVertices());
  }
}

TEST(Generators, ExamplesAreDeterministic) {
  for (const std::string& name : exampleNames()) {
    SurfaceMesh a = makeExample(name), b = makeExample(name);
    EXPECT_EQ(a.faces(), b.faces()) << name;
    EXPECT_EQ(a.positions(), b.positions()) << name;
  }
}

TEST(Generators, SphereIsASubdividedIcosahedronOnTheUnitSphere) {
  for (int s = 0; s <= 3; ++s) {
    SurfaceMesh m = makeSphere(s);
    EXPECT_EQ(m.numFaces(), 20 << (2 * s));
    EXPECT_EQ(m.genus(), 0);
    for (const Vec3& p : m.positions()) EXPECT_NEAR(p.norm(), 1.0, 1e-12);
    // On a sphere centred at the origin, outward means along the position.
    for (int f = 0; f < m.numFaces(); ++f) EXPECT_GT(m.faceNormal(f).dot(m.faceCentroid(f)), 0);
  }
  EXPECT_THROW(makeSphere(-1), MeshError);
  EXPECT_THROW(makeSphere(8), MeshError);
}

TEST(Generators, TorusLiesOnItsSurfaceWithOutwardNormals) {
  const double R = 2.0, r = 0.5;
  SurfaceMesh m = makeTorus(R, r, 30, 12);
  EXPECT_EQ(m.numFaces(), 2 * 30 * 12);
  EXPECT_EQ(m.genus(), 1);
  EXPECT_EQ(m.numBorderLoops(), 0);
  EXPECT_GT(signedVolume(m), 0);
  for (const Vec3& p : m.positions()) EXPECT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()), r, 1e-12);
  // Outward: away from the tube's core circle.
  for (int f = 0; f < m.numFaces(); ++f) {
    Vec3 c = m.faceCentroid(f), core(c.x(), c.y(), 0);
    core = core.normalized() * R;
    EXPECT_GT(m.faceNormal(f).dot(c - core), 0);
  }
  EXPECT_THROW(makeTorus(0.3, 0.4), MeshError);
  EXPECT_THROW(makeTorus(1.0, 0.4, 2, 10), MeshError);
}

TEST(Generators, OpenCylinderHasTwoBorderLoopsAtItsEnds) {
  const double radius = 0.7, height = 1.5;
  SurfaceMesh m = makeOpenCylinder(radius, height, 20, 6);
  EXPECT_EQ(m.numFaces(), 2 * 20 * 6);
  EXPECT_EQ(m.numBorderLoops(), 2);
  EXPECT_EQ(m.genus(), 0);
  EXPECT_EQ(m.eulerCharacteristic(), 0);
  int border = 0;
  for (int v = 0; v < m.numVertices(); ++v) {
    const Vec3& p = m.position(v);
    EXPECT_NEAR(std::hypot(p.x(), p.y()), radius, 1e-12);
    if (m.isBorderVertex(v)) {
      ++border;
      EXPECT_NEAR(std::abs(p.z()), height / 2, 1e-12);
    }
  }
  EXPECT_EQ(border, 2 * 20);
  for (int f = 0; f < m.numFaces(); ++f) {
    Vec3 c = m.faceCentroid(f);
    EXPECT_GT(m.faceNormal(f).dot(Vec3(c.x(), c.y(), 0)), 0) << "normal points into the cylinder";
  }
  EXPECT_THROW(makeOpenCylinder(-1.0), MeshError);
}

TEST(Generators, DoubleTorusHasGenusTwoAtEveryResolution) {
  for (int resolution : {12, 24, 40}) {
    SCOPED_TRACE(resolution);
    SurfaceMesh m = makeDoubleTorus(resolution);
    EXPECT_EQ(m.genus(), 2);
    EXPECT_EQ(m.numBorderLoops(), 0);
    EXPECT_EQ(m.eulerCharacteristic(), -2);
    EXPECT_EQ(m.numComponents(), 1);
    EXPECT_GT(signedVolume(m), 0);
    EXPECT_GT(minAngleDeg(m), 25.0);
    // The two holes (around the vertical lines through (1.5, 1.5) and (3.5, 1.5)) stay
    // geometrically open: the smoothing does not pinch them.
    double clearance = 1e9;
    for (const Vec3& p : m.positions())
      for (double cx : {1.5, 3.5}) clearance = std::min(clearance, std::hypot(p.x() - cx, p.y() - 1.5));
    EXPECT_GT(clearance, 0.4);
  }
  EXPECT_THROW(makeDoubleTorus(3), MeshError);
}

TEST(Generators, RoundedBoxIsSmoothAndExact) {
  struct Box {
    Vec3 half;
    double radius;
    int resolution;
    double minAngle;
  };
  // The default, an elongated box, a nearly spherical one, a small radius and a coarse one (in
  // the last three the quarter circles need more segments than the resolution gives, so their
  // strips are at most 2:1 cells: a right triangle with legs 1 and 2 has a 26.6° angle).
  for (const Box& b : {Box{Vec3(1.0, 0.8, 0.6), 0.2, 16, 30}, Box{Vec3(1.0, 1.0, 1.0), 0.9, 8, 30},
                       Box{Vec3(2.0, 0.5, 0.5), 0.1, 10, 25}, Box{Vec3(1.0, 0.8, 0.6), 0.05, 16, 25},
                       Box{Vec3(1.0, 0.8, 0.6), 0.2, 4, 25}}) {
    SCOPED_TRACE(testing::Message() << "half " << b.half.transpose() << " radius " << b.radius << " resolution "
                                    << b.resolution);
    SurfaceMesh m = makeRoundedBox(b.half, b.radius, b.resolution);
    EXPECT_EQ(m.genus(), 0);
    EXPECT_EQ(m.numBorderLoops(), 0);
    EXPECT_EQ(m.eulerCharacteristic(), 2);
    EXPECT_GT(signedVolume(m), 0);
    EXPECT_LT(maxDihedralDeg(m), 30.0) << "a sharp edge";
    EXPECT_GT(minAngleDeg(m), b.minAngle);

    // Every vertex is at distance `radius` from the inner box, and the extent is `half`.
    const Vec3 inner = b.half - Vec3::Constant(b.radius);
    Vec3 lo = Vec3::Constant(1e9), hi = -lo;
    for (const Vec3& p : m.positions()) {
      EXPECT_NEAR((p - closestOnBox(p, inner)).norm(), b.radius, 1e-12);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    EXPECT_LT((hi - b.half).norm(), 1e-12);
    EXPECT_LT((lo + b.half).norm(), 1e-12);
    // Outward: away from the inner box.
    for (int f = 0; f < m.numFaces(); ++f) {
      Vec3 c = m.faceCentroid(f);
      EXPECT_GT(m.faceNormal(f).dot(c - closestOnBox(c, inner)), 0);
    }

    // Each rounded edge gets at least 4 segments across its quarter circle: look at the edge
    // along axis a between the +b and +c sides and count the distinct angles of its vertices.
    for (int a = 0; a < 3; ++a) {
      const int bAxis = (a + 1) % 3, cAxis = (a + 2) % 3;
      std::set<long> angles;
      for (const Vec3& p : m.positions()) {
        if (std::abs(p[a]) > inner[a] || p[bAxis] < inner[bAxis] - 1e-12 || p[cAxis] < inner[cAxis] - 1e-12)
          continue;
        double angle = std::atan2(p[cAxis] - inner[cAxis], p[bAxis] - inner[bAxis]);
        angles.insert(std::lround(angle * kDeg * 1e6));
      }
      EXPECT_GE(angles.size(), 5u) << "rounded edge along axis " << a;
    }
  }
}

TEST(Generators, RoundedBoxResolutionIsSegmentsPerUnitLength) {
  // Along the flat middle of the default box's longest side (length 2·(1 - 0.2) = 1.6), the
  // top face's grid has about 1.6·resolution segments: the mean edge length follows 1/resolution.
  for (int resolution : {8, 16}) {
    SurfaceMesh m = makeRoundedBox(Vec3(1.0, 0.8, 0.6), 0.2, resolution);
    std::set<long> xs;  // distinct x of the vertices on the flat top
    for (const Vec3& p : m.positions())
      if (p.z() > 0.6 - 1e-12 && std::abs(p.x()) <= 0.8 + 1e-12) xs.insert(std::lround(p.x() * 1e9));
    const double segments = double(xs.size()) - 1;
    EXPECT_GE(segments, 1.6 * resolution);
    EXPECT_LE(segments, 1.6 * resolution + 1);
  }
  EXPECT_GT(makeRoundedBox(Vec3(1, 1, 1), 0.3, 12).numFaces(), makeRoundedBox(Vec3(1, 1, 1), 0.3, 6).numFaces());
}

TEST(Generators, RoundedBoxRejectsBadParameters) {
  EXPECT_THROW(makeRoundedBox(Vec3(1, 1, 1), 2.0, 8), MeshError);   // radius larger than the box
  EXPECT_THROW(makeRoundedBox(Vec3(1, 1, 1), 1.0, 8), MeshError);   // radius equal to a half-size
  EXPECT_THROW(makeRoundedBox(Vec3(1, 1, 1), 0.0, 8), MeshError);   // no rounding
  EXPECT_THROW(makeRoundedBox(Vec3(1, 1, 1), 0.2, 1), MeshError);   // resolution too low
  EXPECT_THROW(makeRoundedBox(Vec3(1, NAN, 1), 0.2, 8), MeshError);  // not finite
}

TEST(Generators, UnknownExampleListsTheValidNames) {
  for (const std::string& bad : {std::string("teapot"), std::string(""), std::string("Sphere")}) {
    try {
      makeExample(bad);
      ADD_FAILURE() << "no error for '" << bad << "'";
    } catch (const MeshError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find("'" + bad + "'"), std::string::npos) << msg;
      for (const auto& n : exampleNames()) EXPECT_NE(msg.find(n), std::string::npos) << msg;
    }
  }
}
