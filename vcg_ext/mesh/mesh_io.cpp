#include "mesh/mesh_io.h"

#include "mesh/input_file.h"
#include "util/number_text.h"
#include "mesh/ply_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fcql {
namespace {

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
  // Each vertex takes 3 tokens and each face at least 4: check before reading any.
  const long left = long(tokens.size() - at);
  if (nv > left / 3)
    throw MeshError(path + ": declares " + std::to_string(nv) + " vertices but the file holds at most " +
                    std::to_string(left / 3));
  if (nf > (left - 3 * nv) / 4)
    throw MeshError(path + ": declares " + std::to_string(nf) + " faces but the file holds at most " +
                    std::to_string((left - 3 * nv) / 4));
  RawMesh m;
  m.positions.reserve(std::size_t(nv));
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

SurfaceMesh parseMesh(const std::string& bytes, const std::string& name, const std::string& format) {
  if (bytes.empty()) throw MeshError(name + ": the file is empty");
  RawMesh raw;
  if (format == "ply") {
    PlyPolygons ply = parsePly(bytes, name);
    raw.positions = std::move(ply.positions);
    raw.faces.reserve(ply.corners.size() - 2 * std::size_t(ply.numFaces()));
    for (int f = 0; f < ply.numFaces(); ++f) {
      const int* c = ply.corners.data() + ply.faceStart[f];
      const int n = ply.faceStart[f + 1] - ply.faceStart[f];
      for (int i = 1; i + 1 < n; ++i) raw.faces.push_back({c[0], c[i], c[i + 1]});
    }
  } else if (format == "obj" || format == "off") {
    std::istringstream file(bytes);
    raw = format == "obj" ? readObj(name, file) : readOff(name, file);
  } else {
    throw MeshError(name + ": unsupported mesh format '." + format + "' (use .obj, .ply or .off)");
  }
  if (raw.faces.empty()) throw MeshError(name + ": the file holds no faces");
  try {
    return SurfaceMesh(std::move(raw.positions), std::move(raw.faces));
  } catch (const MeshError& e) {
    throw MeshError(name + ": " + e.what());
  }
}

SurfaceMesh loadMesh(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != "obj" && ext != "ply" && ext != "off")
    throw MeshError(path + ": unsupported mesh format '." + ext + "' (use .obj, .ply or .off)");
  std::string bytes, error;
  if (!readRegularFile(path, bytes, error)) throw MeshError(error);
  return parseMesh(bytes, path, ext);
}

void saveMesh(const SurfaceMesh& mesh, const std::string& path) {
  std::string ext = lowerExtension(path);
  if (ext != "obj" && ext != "ply" && ext != "off")
    throw MeshError(path + ": unsupported mesh format '." + ext + "' (use .obj, .ply or .off)");
  std::string text;
  const long nv = mesh.numVertices(), nf = mesh.numFaces();
  if (ext == "ply") {
    text = "ply\nformat ascii 1.0\ncomment written by fcql\nelement vertex " + std::to_string(nv) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(nf) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
  } else if (ext == "off") {
    text = "OFF\n" + std::to_string(nv) + " " + std::to_string(nf) + " 0\n";
  }
  for (int v = 0; v < nv; ++v) {
    if (ext == "obj") text += "v ";
    const Vec3& p = mesh.position(v);
    for (int c = 0; c < 3; ++c) {
      if (c > 0) text += ' ';
      appendNumber(text, p[c], 17);
    }
    text += '\n';
  }
  for (int f = 0; f < nf; ++f) {
    text += ext == "obj" ? "f" : "3";
    for (int c = 0; c < 3; ++c) {
      text += ' ';
      appendNumber(text, long(mesh.vertex(f, c)) + (ext == "obj" ? 1 : 0));
    }
    text += '\n';
  }
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.flush();
  if (!out) throw MeshError(path + ": cannot write the mesh");
}

}  // namespace fcql
