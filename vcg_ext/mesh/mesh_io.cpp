#include "mesh/mesh_io.h"

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fcql {
namespace {

// A minimal double-precision vcglib mesh used only to read and write files.
class IoVertex;
class IoFace;
struct IoUsedTypes : public vcg::UsedTypes<vcg::Use<IoVertex>::AsVertexType, vcg::Use<IoFace>::AsFaceType> {};
class IoVertex : public vcg::Vertex<IoUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                    vcg::vertex::BitFlags> {};
class IoFace : public vcg::Face<IoUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class IoMesh : public vcg::tri::TriMesh<std::vector<IoVertex>, std::vector<IoFace>> {};

std::string lowerExtension(const std::string& path) {
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// ---- OBJ and OFF: our own strict readers (vcglib's OBJ importer silently drops some faces) --

struct RawMesh {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> faces;
};

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw MeshError(path + ", line " + std::to_string(line) + ": " + what);
}

double readCoordinate(std::istringstream& in, const std::string& path, int line) {
  std::string tok;
  if (!(in >> tok)) fail(path, line, "missing coordinate");
  char* end = nullptr;
  double v = std::strtod(tok.c_str(), &end);
  if (end == tok.c_str() || *end != '\0') fail(path, line, "'" + tok + "' is not a number");
  if (!std::isfinite(v)) fail(path, line, "coordinate '" + tok + "' is not finite");
  return v;
}

/// Fan-triangulates a polygon (corner indices already 0-based and checked).
void addPolygon(RawMesh& m, const std::vector<int>& corners, const std::string& path, int line) {
  if (corners.size() < 3) fail(path, line, "a face needs at least 3 vertices");
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) m.faces.push_back({corners[0], corners[i], corners[i + 1]});
}

RawMesh readObj(const std::string& path, std::istream& file) {
  RawMesh m;
  std::string raw;
  int line = 0;
  while (std::getline(file, raw)) {
    ++line;
    std::istringstream in(raw);
    std::string key;
    if (!(in >> key) || key[0] == '#') continue;
    if (key == "v") {
      double x = readCoordinate(in, path, line), y = readCoordinate(in, path, line), z = readCoordinate(in, path, line);
      m.positions.emplace_back(x, y, z);
    } else if (key == "f") {
      std::vector<int> corners;
      std::string tok;
      while (in >> tok) {
        std::string head = tok.substr(0, tok.find('/'));
        char* end = nullptr;
        long idx = std::strtol(head.c_str(), &end, 10);
        if (head.empty() || *end != '\0' || idx == 0) fail(path, line, "bad vertex reference '" + tok + "'");
        long zeroBased = idx > 0 ? idx - 1 : long(m.positions.size()) + idx;
        if (zeroBased < 0 || zeroBased >= long(m.positions.size()))
          fail(path, line, "vertex reference " + std::to_string(idx) + " is out of range");
        corners.push_back(int(zeroBased));
      }
      addPolygon(m, corners, path, line);
    }
    // Other records (vt, vn, g, o, s, usemtl, mtllib, l) do not define the surface.
  }
  return m;
}

RawMesh readOff(const std::string& path, std::istream& file) {
  // Tokens with their line numbers, comments removed.
  std::vector<std::pair<std::string, int>> tokens;
  std::string raw;
  int line = 0;
  while (std::getline(file, raw)) {
    ++line;
    auto hash = raw.find('#');
    if (hash != std::string::npos) raw.resize(hash);
    std::istringstream in(raw);
    std::string tok;
    while (in >> tok) tokens.emplace_back(tok, line);
  }
  std::size_t at = 0;
  auto next = [&](const char* what) -> const std::pair<std::string, int>& {
    if (at >= tokens.size()) throw MeshError(path + ": truncated OFF file (missing " + what + ")");
    return tokens[at++];
  };
  auto integer = [&](const char* what) {
    const auto& t = next(what);
    char* end = nullptr;
    long v = std::strtol(t.first.c_str(), &end, 10);
    if (end == t.first.c_str() || *end != '\0' || v < 0) fail(path, t.second, std::string("bad ") + what + " '" + t.first + "'");
    return v;
  };
  auto number = [&](const char* what) {
    const auto& t = next(what);
    char* end = nullptr;
    double v = std::strtod(t.first.c_str(), &end);
    if (end == t.first.c_str() || *end != '\0' || !std::isfinite(v)) fail(path, t.second, std::string("bad ") + what + " '" + t.first + "'");
    return v;
  };
  if (tokens.empty()) throw MeshError(path + ": the file is empty");
  std::string header = tokens[0].first;
  if (header.size() < 3 || header.compare(header.size() - 3, 3, "OFF") != 0)
    throw MeshError(path + ": not an OFF file (first word '" + header + "')");
  if (header != "OFF") throw MeshError(path + ": OFF variant '" + header + "' is not supported (plain OFF only)");
  at = 1;
  long nv = integer("vertex count"), nf = integer("face count");
  integer("edge count");
  RawMesh m;
  for (long i = 0; i < nv; ++i) {
    double x = number("coordinate"), y = number("coordinate"), z = number("coordinate");
    m.positions.emplace_back(x, y, z);
  }
  for (long i = 0; i < nf; ++i) {
    int faceLine = at < tokens.size() ? tokens[at].second : line;
    long n = integer("face size");
    std::vector<int> corners;
    for (long c = 0; c < n; ++c) {
      long idx = integer("vertex index");
      if (idx >= nv) fail(path, faceLine, "vertex index " + std::to_string(idx) + " is out of range");
      corners.push_back(int(idx));
    }
    addPolygon(m, corners, path, faceLine);
    // Optional per-face colour values up to the end of the line.
    while (at < tokens.size() && tokens[at].second == faceLine) ++at;
  }
  return m;
}

}  // namespace

SurfaceMesh loadMesh(const std::string& path) {
  std::string ext = lowerExtension(path);
  if (ext != "obj" && ext != "ply" && ext != "off")
    throw MeshError(path + ": unsupported mesh format '." + ext + "' (use .obj, .ply or .off)");
  {
    std::ifstream probe(path);
    if (!probe) throw MeshError(path + ": cannot open the file");
    if (probe.peek() == std::ifstream::traits_type::eof()) throw MeshError(path + ": the file is empty");
  }
  if (ext == "obj" || ext == "off") {
    std::ifstream file(path);
    RawMesh raw = ext == "obj" ? readObj(path, file) : readOff(path, file);
    if (raw.faces.empty()) throw MeshError(path + ": the file holds no faces");
    try {
      return SurfaceMesh(std::move(raw.positions), std::move(raw.faces));
    } catch (const MeshError& e) {
      throw MeshError(path + ": " + e.what());
    }
  }
  IoMesh m;
  int mask = 0;
  int err = vcg::tri::io::Importer<IoMesh>::Open(m, path.c_str(), mask);
  if (err != 0 && vcg::tri::io::Importer<IoMesh>::ErrorCritical(err))
    throw MeshError(path + ": cannot read the mesh (" +
                    vcg::tri::io::Importer<IoMesh>::ErrorMsg(err) + ")");
  std::vector<Vec3> positions;
  std::vector<int> index(m.vert.size(), -1);
  positions.reserve(m.vn);
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD()) continue;
    const auto& p = m.vert[i].cP();
    index[i] = int(positions.size());
    positions.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::array<int, 3>> faces;
  faces.reserve(m.fn);
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    std::array<int, 3> t;
    for (int c = 0; c < 3; ++c) {
      if (f.V(c) == nullptr) throw MeshError(path + ": a face refers to a missing vertex");
      t[c] = index[vcg::tri::Index(m, f.V(c))];
    }
    faces.push_back(t);
  }
  if (faces.empty()) throw MeshError(path + ": the file holds no faces");
  try {
    return SurfaceMesh(std::move(positions), std::move(faces));
  } catch (const MeshError& e) {
    throw MeshError(path + ": " + e.what());
  }
}

void saveMesh(const SurfaceMesh& mesh, const std::string& path) {
  std::string ext = lowerExtension(path);
  if (ext != "obj" && ext != "ply" && ext != "off")
    throw MeshError(path + ": unsupported mesh format '." + ext + "' (use .obj, .ply or .off)");
  IoMesh m;
  auto vi = vcg::tri::Allocator<IoMesh>::AddVertices(m, mesh.numVertices());
  for (int v = 0; v < mesh.numVertices(); ++v, ++vi) {
    const Vec3& p = mesh.position(v);
    vi->P() = vcg::Point3d(p.x(), p.y(), p.z());
  }
  vcg::tri::Allocator<IoMesh>::AddFaces(m, mesh.numFaces());
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int c = 0; c < 3; ++c) m.face[f].V(c) = &m.vert[mesh.vertex(f, c)];
  int err = vcg::tri::io::Exporter<IoMesh>::Save(m, path.c_str(), 0);
  if (err != 0) throw MeshError(path + ": cannot write the mesh (" +
                                std::string(vcg::tri::io::Exporter<IoMesh>::ErrorMsg(err)) + ")");
}

}  // namespace fcql
