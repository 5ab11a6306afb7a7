#include "field/field_io.h"
#include "mesh/mesh_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace fcql;

namespace {

// Two triangles forming a unit square in the z = 0 plane.
SurfaceMesh square() {
  return SurfaceMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{{0, 1, 2}}, {{0, 2, 3}}});
}

std::string parseError(const std::string& text, bool rosy) {
  SurfaceMesh m = square();
  try {
    if (rosy) parseRosy(m, text, "f.rosy");
    else parseFField(m, text, "f.ffield");
  } catch (const FieldError& e) {
    return e.what();
  }
  return "";
}

const char* kGoodFField =
    "# frame generated with VCG\ntarget frame\n2\nk1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z\n"
    "1 1 1 0 0 0 1 0\n1 1 0 2 0.5 -1 0 0\n";

}  // namespace

TEST(FieldIo, ParsesFFieldAndProjectsToFaces) {
  SurfaceMesh m = square();
  CrossField f = parseFField(m, kGoodFField, "good.ffield");
  ASSERT_EQ(f.numFaces(), 2);
  EXPECT_NEAR((f.u[0] - Vec3(1, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((f.u[1] - Vec3(0, 1, 0)).norm(), 0, 1e-12);  // z component projected away, normalised
}

TEST(FieldIo, ParsesRosy) {
  SurfaceMesh m = square();
  CrossField f = parseRosy(m, "2\n4\n0 3 0\n1 1 0\n", "r.rosy");
  EXPECT_NEAR((f.u[0] - Vec3(0, 1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((f.u[1] - Vec3(1, 1, 0).normalized()).norm(), 0, 1e-12);
}

TEST(FieldIo, BadFilesGiveClearErrors) {
  EXPECT_NE(parseError("", false).find("empty"), std::string::npos);
  EXPECT_NE(parseError("target frame\n3\n1 1 1 0 0 0 1 0\n", false).find("3 faces but the mesh has 2"), std::string::npos);
  EXPECT_NE(parseError("target frame\n2\n1 1 1 0 0 0 1 0\n", false).find("truncated"), std::string::npos);
  EXPECT_NE(parseError("target frame\n2\n1 1 1 0 0 0 1 0\n1 1 nan 0 0 0 1 0\n", false).find("not a finite number"),
            std::string::npos);
  EXPECT_NE(parseError("target frame\n2\n1 1 1 0 0 0 1 0\n1 1 x 0 0 0 1 0\n", false).find("not a number"),
            std::string::npos);
  EXPECT_NE(parseError("target frame\n2\n1 1 1 0 0 0 1 0\n1 1 0 0 0 0 0 0\n", false).find("is zero"), std::string::npos);
  EXPECT_NE(parseError("target frame\n2\n1 1 1 0 0 0 1 0\n1 1 0 0 1 0 0 0\n", false).find("more than 60 degrees out of the face's plane"),
            std::string::npos);
  EXPECT_NE(parseError("target frame\n2\n1 1 1 0 0\n", false).find("expected 8 numbers"), std::string::npos);
  EXPECT_NE(parseError("2\n4\n1 0 0\n1 0 0\n1 0 0\n", true).find("more faces than the mesh"), std::string::npos);
  EXPECT_NE(parseError("2\n6\n1 0 0\n1 0 0\n", true).find("not a cross field"), std::string::npos);
  EXPECT_NE(parseError("2\n4\n1 0 0\n", true).find("truncated"), std::string::npos);
  EXPECT_NE(parseError("2\n4\n1 0 0\n0 0 0\n", true).find("line 4"), std::string::npos);
}

TEST(FieldIo, WriteReadRoundTrip) {
  SurfaceMesh m = square();
  CrossField f = parseRosy(m, "2\n4\n0.6 0.8 0\n-1 0.2 0\n", "r.rosy");
  std::string path = ::testing::TempDir() + "roundtrip.ffield";
  saveFField(m, f, path);
  CrossField g = loadField(m, path);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR((f.u[i] - g.u[i]).norm(), 0, 1e-7);
  std::string rosy = ::testing::TempDir() + "roundtrip.rosy";
  saveRosy(m, f, rosy);
  CrossField h = loadField(m, rosy);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR((f.u[i] - h.u[i]).norm(), 0, 1e-7);
  std::remove(path.c_str());
  std::remove(rosy.c_str());
  EXPECT_THROW(loadField(m, ::testing::TempDir() + "missing.ffield"), FieldError);
  EXPECT_THROW(loadField(m, ::testing::TempDir() + "x.txt"), FieldError);
}

TEST(FieldIo, ReadsSharedEightField) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  EXPECT_EQ(f.numFaces(), 11092);
}
