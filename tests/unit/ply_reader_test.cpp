// The strict PLY reader: the three formats, skipping what is not the mesh, and every malformed
// input of the adversarial campaign (each crashed or corrupted the stack of the vcglib/plylib
// reader used before), crafted here from its description.
#include "mesh/mesh_io.h"
#include "mesh/ply_reader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace fcql;

namespace {

/// Appends binary values in the chosen byte order.
struct Bytes {
  bool bigEndian = false;
  std::string data;

  template <class T>
  Bytes& put(T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) data.push_back(char(raw[bigEndian ? sizeof(T) - 1 - i : i]));
    return *this;
  }
};

std::string parseError(const std::string& bytes, const std::vector<std::string>& faceProperties = {}) {
  try {
    parsePly(bytes, "t.ply", faceProperties);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

// A unit square as two triangles plus a quad, with distractions: a per-vertex normal (float),
// colour (uchar), a per-vertex list of doubles, an `edge` element before the faces, and per-face
// an int `patch` and a list of floats after the index list.
const char* kHeaderTail =
    "element vertex 5\n"
    "property float x\nproperty float y\nproperty double z\nproperty float nx\n"
    "property uchar red\nproperty list uchar double extra\n"
    "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
    "element face 3\n"
    "property list uchar int vertex_indices\nproperty int patch\nproperty list ushort float texcoord\n"
    "end_header\n";

std::string binarySquare(bool bigEndian) {
  Bytes b;
  b.bigEndian = bigEndian;
  const float xy[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0.5f}};
  for (int v = 0; v < 5; ++v) {
    b.put(xy[v][0]).put(xy[v][1]).put(double(v) * 0.25).put(0.0f).put(std::uint8_t(200));
    b.put(std::uint8_t(v % 3));
    for (int i = 0; i < v % 3; ++i) b.put(double(i));
  }
  b.put(std::int32_t(0)).put(std::int32_t(1));
  const std::vector<std::vector<int>> faces = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2, 2}};
  for (std::size_t f = 0; f < faces.size(); ++f) {
    b.put(std::uint8_t(faces[f].size()));
    for (int i : faces[f]) b.put(std::int32_t(i));
    b.put(std::int32_t(10 + f));
    b.put(std::uint16_t(2)).put(0.5f).put(0.25f);
  }
  return std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\ncomment made by the test\n" + kHeaderTail + b.data;
}

std::string asciiSquare() {
  return std::string("ply\nformat ascii 1.0\n") + kHeaderTail +
         "0 0 0 0 200 0\n1 0 0.25 0 200 1 0\n1 1 0.5 0 200 2 0 1\n0 1 0.75 0 200 0\n2 0.5 1 0 200 1 0\n"
         "0 1\n"
         "3 0 1 2 10 2 0.5 0.25\n3 0 2 3 11 2 0.5 0.25\n4 1 4 2 2 12 2 0.5 0.25\n";
}

}  // namespace

TEST(PlyReader, ReadsAsciiAndBothBinaryByteOrdersAlike) {
  for (const std::string& bytes : {asciiSquare(), binarySquare(false), binarySquare(true)}) {
    PlyPolygons p = parsePly(bytes, "square.ply", {"patch"});
    ASSERT_EQ(p.positions.size(), 5u);
    EXPECT_EQ(p.positions[2], Vec3(1, 1, 0.5));
    EXPECT_EQ(p.positions[4], Vec3(2, 0.5, 1));
    ASSERT_EQ(p.numFaces(), 3);
    EXPECT_EQ(p.faceStart, (std::vector<int>{0, 3, 6, 10}));
    EXPECT_EQ(p.corners, (std::vector<int>{0, 1, 2, 0, 2, 3, 1, 4, 2, 2}));
    EXPECT_EQ(p.faceValues[0], (std::vector<double>{10, 11, 12}));
  }
}

TEST(PlyReader, CountsAreCheckedAgainstTheFileBeforeAnythingIsAllocated) {
  // 2·10^9 vertices declared in a few hundred bytes: refused at once, naming both numbers.
  std::string huge = "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
                     "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n" + std::string(120, 'A');
  std::string e = parseError(huge);
  EXPECT_NE(e.find("line 3: declares 2000000000 vertices but the file holds at most 10"), std::string::npos) << e;
  std::string ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 100\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  e = parseError(ascii);
  EXPECT_NE(e.find("declares 100 faces but the file holds at most"), std::string::npos) << e;
  // A negative or missing count is a header error, not an allocation.
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nelement vertex -5\nend_header\n").find("line 3"), std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nelement vertex -5\nend_header\n").find("non-negative integer"), std::string::npos);
}

TEST(PlyReader, TheCampaignsCrashingInputsGiveClearErrorsOrParse) {
  const std::string vertices3 = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  // 1. A polygon whose 5th index is out of range (plylib read past its corner array).
  {
    Bytes b;
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b.put(v);
    b.put(std::uint8_t(5));
    for (int i : {0, 1, 2, 1, 70000}) b.put(std::int32_t(i));
    std::string e = parseError("ply\nformat binary_little_endian 1.0\n" + vertices3 +
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n" + b.data);
    EXPECT_NE(e.find("face 0 refers to vertex 70000, out of range (the file declares 3 vertices)"), std::string::npos) << e;
    EXPECT_NE(e.find("byte "), std::string::npos) << e;
  }
  // 2. `element vertex` with no count (plylib called atoi(NULL)).
  {
    std::string e = parseError("ply\nformat ascii 1.0\nelement vertex\nproperty float x\nend_header\n");
    EXPECT_NE(e.find("t.ply, line 3: an element line must be 'element NAME COUNT'"), std::string::npos) << e;
  }
  const std::string faces1 = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  // 3. A blank line after a comment in the header (plylib called strcmp(NULL)): it carries nothing.
  EXPECT_EQ(parsePly("ply\nformat ascii 1.0\ncomment hi\n\n" + vertices3 + faces1 + "end_header\n" + body, "t.ply").numFaces(), 1);
  // 4. An unknown binary list property with 255 int items (plylib overflowed a 512-byte stack
  //    buffer with the file's bytes): skipped by its declared type.
  {
    Bytes b;
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b.put(v);
    b.put(std::uint8_t(3)).put(std::int32_t(0)).put(std::int32_t(1)).put(std::int32_t(2));
    b.put(std::uint8_t(255));
    for (int i = 0; i < 255; ++i) b.put(std::int32_t(0x41414141));
    std::string header = "ply\nformat binary_little_endian 1.0\n" + vertices3 + faces1 + "property list uchar int junk\nend_header\n";
    PlyPolygons p = parsePly(header + b.data, "t.ply");
    EXPECT_EQ(p.corners, (std::vector<int>{0, 1, 2}));
    // The same list cut short ends with an error naming the offset, not a read past the end.
    std::string e = parseError(header + b.data.substr(0, b.data.size() - 100));
    EXPECT_NE(e.find("byte 248: the file ends inside a list"), std::string::npos) << e;
  }
  // 5. `comment TextureFile` and 480 characters (plylib overflowed a 255-byte stack buffer).
  EXPECT_EQ(parsePly("ply\nformat ascii 1.0\ncomment TextureFile " + std::string(480, 'T') + "\n" + vertices3 + faces1 +
                         "end_header\n" + body, "t.ply").numFaces(), 1);
  // 6. Two `element vertex` blocks (plylib freed and reused its vertex array).
  {
    std::string e = parseError("ply\nformat ascii 1.0\n" + vertices3 + vertices3 + faces1 + "end_header\n" + body + body);
    EXPECT_NE(e.find("line 7: element 'vertex' is declared twice"), std::string::npos) << e;
  }
}

TEST(PlyReader, MalformedRecordsNameTheirLineOrByte) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
  // A face with 0 or 2 corners (vcglib silently reused the previous face's indices).
  EXPECT_NE(parseError(head + verts + "2 0 1\n").find("line 13: face 0 has 2 corners (a face needs at least 3)"), std::string::npos);
  EXPECT_NE(parseError(head + verts + "0\n").find("face 0 has 0 corners"), std::string::npos);
  EXPECT_NE(parseError(head + verts + "3 0 1 -1\n").find("refers to vertex -1, out of range"), std::string::npos);
  EXPECT_NE(parseError(head + verts + "3 0 1 2.5\n").find("'2.5' in the face records is not an integer"), std::string::npos);
  EXPECT_NE(parseError(head + verts + "300 0 1 2\n").find("'300' in a list's count is out of range"), std::string::npos);
  EXPECT_NE(parseError(head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n").find("line 11: vertex 1 has a coordinate that is not finite"),
            std::string::npos);
  EXPECT_NE(parseError(head + verts + "3 0 1 2\n3 0 1 2\n").find("line 14: unexpected data after the last element"),
            std::string::npos);
  EXPECT_NE(parseError(head + "0 0 0\n1 0 0\n0 1\n").find("declares 3 vertices but the file holds at most 2"), std::string::npos);
  EXPECT_NE(parseError(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n").find("the file ends inside the face records"), std::string::npos);
  // Header problems.
  EXPECT_NE(parseError("PLY\n").find("not a PLY file"), std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\n").find("no end_header"), std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 2.0\nend_header\n").find("line 2: PLY version '2.0'"), std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nproperty float x\nend_header\n").find("property before any element"), std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n").find("unknown PLY type 'quad'"),
            std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n").find("count type"),
            std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                       "property list uchar float vertex_indices\nend_header\n3 0 1 2\n")
                .find("integer list property vertex_indices"), std::string::npos);
  EXPECT_NE(parseError(head + verts + "3 0 1 2\n", {"patch"}).find("no scalar property 'patch'"), std::string::npos);
  EXPECT_NE(parseError("ply\nformat ascii 1.0\nelement vertex 0\nend_header\n").find("no faces"), std::string::npos);
  EXPECT_NE(parseError("ply\nelement vertex 0\nend_header\n").find("line 3: the header has no format line"), std::string::npos);
}

TEST(PlyReader, LoadMeshReadsOnlyRegularFiles) {
  auto loadError = [](const std::string& path) -> std::string {
    try {
      loadMesh(path);
    } catch (const MeshError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(loadError("/dev/zero.ply").find("no such file"), std::string::npos);
  // A device under a mesh's name is refused at once instead of being read forever.
  std::string device = ::testing::TempDir() + "zero.obj";
  std::remove(device.c_str());
  ASSERT_EQ(symlink("/dev/zero", device.c_str()), 0);
  EXPECT_NE(loadError(device).find("is not a regular file"), std::string::npos) << loadError(device);
  std::remove(device.c_str());
  std::string dir = ::testing::TempDir() + "dir.ply";
  mkdir(dir.c_str(), 0755);
  EXPECT_NE(loadError(dir).find("is a directory, not a file"), std::string::npos) << loadError(dir);
  // A big-endian binary PLY of one quad loads as two triangles.
  Bytes b;
  b.bigEndian = true;
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) b.put(v);
  b.put(std::uint8_t(4)).put(std::uint32_t(0)).put(std::uint32_t(1)).put(std::uint32_t(2)).put(std::uint32_t(3));
  std::string path = ::testing::TempDir() + "square.ply";
  std::ofstream(path, std::ios::binary) << "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\n"
                                           "property float y\nproperty float z\nelement face 1\n"
                                           "property list uchar uint vertex_indices\nend_header\n" << b.data;
  SurfaceMesh m = loadMesh(path);
  EXPECT_EQ(m.numFaces(), 2);
  EXPECT_EQ(m.numBorderLoops(), 1);
  EXPECT_EQ(m.position(2), Vec3(1, 1, 0));
}
