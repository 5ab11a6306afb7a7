#include "mesh/generators.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fcql;

namespace {

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
    for (int c = 0; c < 3; ++c) a = std::min(a, m.cornerAngle(f, c) * 180 / M_PI);
  return a;
}

double maxDihedralDeg(const SurfaceMesh& m) {
  double a = 0;
  for (int f = 0; f < m.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) {
      int g = m.adjacentFace(f, i);
      if (g >= 0) a = std::max(a, std::acos(std::clamp(m.faceNormal(f).dot(m.faceNormal(g)), -1.0, 1.0)) * 180 / M_PI);
    }
  return a;
}

}  // namespace

TEST(Generators, TopologyOrientationAndShape) {
  struct Case {
    std::string name;
    int genus, borders, chi;
  };
  for (const Case& c : {Case{"sphere", 0, 0, 2}, Case{"torus", 1, 0, 0}, Case{"double_torus", 2, 0, -2},
                        Case{"rounded_box", 0, 0, 2}, Case{"open_cylinder", 0, 2, 0}}) {
    SurfaceMesh m = makeExample(c.name);
    EXPECT_EQ(m.genus(), c.genus) << c.name;
    EXPECT_EQ(m.numBorderLoops(), c.borders) << c.name;
    EXPECT_EQ(m.eulerCharacteristic(), c.chi) << c.name;
    EXPECT_EQ(m.numComponents(), 1) << c.name;
    if (c.borders == 0) EXPECT_GT(signedVolume(m), 0) << c.name << " has inward normals";
    EXPECT_GT(minAngleDeg(m), 15.0) << c.name;
    EXPECT_LT(m.numFaces(), 20000) << c.name;
  }
}

TEST(Generators, RoundedBoxIsSmooth) {
  SurfaceMesh m = makeRoundedBox();
  EXPECT_LT(maxDihedralDeg(m), 30.0);
  // Its extent is the requested half-size.
  double maxX = 0;
  for (const auto& p : m.positions()) maxX = std::max(maxX, p.x());
  EXPECT_NEAR(maxX, 1.0, 1e-9);
}

TEST(Generators, UnknownExampleListsTheValidNames) {
  try {
    makeExample("teapot");
    FAIL() << "no error";
  } catch (const MeshError& e) {
    std::string msg = e.what();
    for (const auto& n : exampleNames()) EXPECT_NE(msg.find(n), std::string::npos) << msg;
  }
  EXPECT_THROW(makeRoundedBox(Vec3(1, 1, 1), 2.0, 8), MeshError);
  EXPECT_THROW(makeTorus(0.3, 0.4), MeshError);
}
