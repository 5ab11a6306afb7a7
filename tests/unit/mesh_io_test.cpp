#include "mesh/generators.h"
#include "mesh/mesh_io.h"
#include "util/number_text.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>

using namespace fcql;

namespace {

std::string writeText(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

std::string loadError(const std::string& path) {
  try {
    loadMesh(path);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshIo, RoundTripsThroughObjPlyAndOff) {
  SurfaceMesh m = makeDoubleTorus();
  for (const char* ext : {"obj", "ply", "off"}) {
    std::string path = ::testing::TempDir() + "roundtrip." + ext;
    saveMesh(m, path);
    SurfaceMesh r = loadMesh(path);
    ASSERT_EQ(r.numFaces(), m.numFaces()) << ext;
    ASSERT_EQ(r.numVertices(), m.numVertices()) << ext;
    EXPECT_EQ(r.genus(), 2) << ext;
    for (int f = 0; f < m.numFaces(); ++f) ASSERT_EQ(r.face(f), m.face(f)) << ext;
    double maxError = 0;
    for (int v = 0; v < m.numVertices(); ++v) maxError = std::max(maxError, (r.position(v) - m.position(v)).norm());
    EXPECT_LT(maxError, 1e-5) << ext;  // PLY stores floats
    std::remove(path.c_str());
  }
}

TEST(MeshIo, ReadsObjVariantsAndPolygons) {
  // Texture/normal references, negative indices and a quad (fan-triangulated).
  std::string path = writeText("variants.obj",
                               "# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                               "g part\nf 1/1/1 2/1/1 3/1/1 -1/1/1\n");
  SurfaceMesh m = loadMesh(path);
  EXPECT_EQ(m.numFaces(), 2);
  EXPECT_EQ(m.numBorderLoops(), 1);
  std::string off = writeText("quad.off", "OFF\n# a square\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  EXPECT_EQ(loadMesh(off).numFaces(), 2);
}

TEST(MeshIo, BadFilesGiveOneLineErrors) {
  EXPECT_NE(loadError(writeText("empty.obj", "")).find("empty"), std::string::npos);
  EXPECT_NE(loadError(writeText("nofaces.obj", "v 0 0 0\nv 1 0 0\n")).find("no faces"), std::string::npos);
  EXPECT_NE(loadError(writeText("badnum.obj", "v 0 x 0\n")).find("line 1: 'x' is not a number"), std::string::npos);
  EXPECT_NE(loadError(writeText("nan.obj", "v 0 nan 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).find("not finite"), std::string::npos);
  EXPECT_NE(loadError(writeText("idx.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")).find("out of range"), std::string::npos);
  EXPECT_NE(loadError(writeText("trunc.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n")).find("declares 3 vertices but the file holds at most 2"), std::string::npos);
  EXPECT_NE(loadError(writeText("notoff.off", "PLY\n")).find("not an OFF file"), std::string::npos);
  EXPECT_NE(loadError(writeText("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n")).find("no faces"),
            std::string::npos);
  EXPECT_NE(loadError(::testing::TempDir() + "missing.obj").find("cannot open"), std::string::npos);
  EXPECT_NE(loadError(writeText("mesh.stl", "solid")).find("unsupported mesh format"), std::string::npos);
  // A non-manifold file names the file and the problem.
  std::string nm = writeText("nm.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 2 3\nf 2 1 4\nf 2 1 5\n");
  std::string msg = loadError(nm);
  EXPECT_NE(msg.find("nm.obj"), std::string::npos);
  EXPECT_NE(msg.find("non-manifold edge"), std::string::npos);
}

TEST(MeshIo, NumbersAreWrittenAsPrintfWritesThem) {
  // The OBJ and field writers format coordinates with std::to_chars: the text must be the
  // "%.<digits>g" of the stream formatting it replaces, and read back within that precision.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-12, 12);
  std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 0.1, 1e-300, 123456789012.0, 0.5e-5};
  for (int i = 0; i < 2000; ++i) values.push_back(std::ldexp(mantissa(random), exponent(random)));
  for (double x : values)
    for (int digits : {9, 10}) {
      std::string text;
      appendNumber(text, x, digits);
      char expected[64];
      std::snprintf(expected, sizeof expected, "%.*g", digits, x);
      ASSERT_EQ(text, expected) << "digits " << digits;
      EXPECT_NEAR(std::stod(text), x, 1e-8 * std::abs(x) + 1e-300);
    }
  std::string n;
  appendNumber(n, -1234567890123L);
  EXPECT_EQ(n, "-1234567890123");
}
