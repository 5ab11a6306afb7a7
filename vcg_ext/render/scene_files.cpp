#include "render/scene_files.h"

#include "mesh/ply_reader.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fcql {
namespace render {
namespace {

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// OBJ `v` and `l` (polylines) or `f` (faces) lines; indices may be negative (relative) or
// carry /vt/vn parts.
struct ObjData {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> lines, faces;
  std::vector<std::string> lineComments;  ///< the comment just before each `l`
};

ObjData parseObj(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  auto fail = [&](long n, const std::string& why) {
    return std::runtime_error(path + ": line " + std::to_string(n) + ": " + why);
  };
  ObjData obj;
  std::string line, lastComment;
  long n = 0;
  while (std::getline(in, line)) {
    ++n;
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag)) continue;
    if (tag[0] == '#') {
      lastComment = line;
    } else if (tag == "v") {
      Vec3 p;
      if (!(words >> p.x() >> p.y() >> p.z()) || !finite(p)) throw fail(n, "bad vertex");
      obj.positions.push_back(p);
    } else if (tag == "l" || tag == "f") {
      std::vector<int> ids;
      std::string item;
      while (words >> item) {
        char* end = nullptr;
        long v = std::strtol(item.c_str(), &end, 10);
        if (end == item.c_str() || (*end && *end != '/')) throw fail(n, "bad index '" + item + "'");
        if (v < 0) v += long(obj.positions.size()) + 1;
        if (v < 1 || v > long(obj.positions.size())) throw fail(n, "index " + item + " out of range");
        ids.push_back(int(v - 1));
      }
      if (tag == "l") {
        if (ids.size() < 2) throw fail(n, "polyline with fewer than 2 points");
        obj.lines.push_back(ids);
        obj.lineComments.push_back(lastComment);
      } else {
        if (ids.size() < 3) throw fail(n, "face with fewer than 3 corners");
        obj.faces.push_back(ids);
      }
      lastComment.clear();
    }
  }
  return obj;
}

}  // namespace

// layout.ply (any PLY with a per-face scalar `patch`), through the project's strict PLY reader.
LayoutScene parseLayoutPly(const std::string& bytes, const std::string& path) {
  PlyPolygons ply;
  try {
    ply = parsePly(bytes, path, {"patch"});
  } catch (const MeshError& e) {
    throw std::runtime_error(e.what());
  }
  LayoutScene scene;
  scene.positions = std::move(ply.positions);
  for (int f = 0; f < ply.numFaces(); ++f) {
    const double patch = ply.faceValues[0][f];
    if (patch < 0 || patch > 100000000) throw std::runtime_error(path + ": face " + std::to_string(f) + " has a bad patch id");
    for (int i = ply.faceStart[f] + 1; i + 1 < ply.faceStart[f + 1]; ++i) {
      scene.triangles.push_back({ply.corners[ply.faceStart[f]], ply.corners[i], ply.corners[i + 1]});
      scene.patch.push_back(int(patch));
    }
  }
  return scene;
}

std::vector<Polyline> parseSeparatrices(const std::string& text, const std::string& path) {
  ObjData obj = parseObj(text, path);
  std::vector<Polyline> result;
  for (std::size_t i = 0; i < obj.lines.size(); ++i) {
    Polyline p;
    for (int v : obj.lines[i]) p.points.push_back(obj.positions[v]);
    const std::string& c = obj.lineComments[i];
    for (const char* kind : {"t-junction", "to border", "separatrix"})
      if (c.find(kind) != std::string::npos) {
        p.kind = kind;
        break;
      }
    result.push_back(std::move(p));
  }
  return result;
}

QuadScene parseQuads(const std::string& text, const std::string& path) {
  ObjData obj = parseObj(text, path);
  QuadScene scene;
  scene.positions = std::move(obj.positions);
  for (const auto& f : obj.faces) {
    if (f.size() == 4) scene.quads.push_back({f[0], f[1], f[2], f[3]});
    else if (f.size() == 3) scene.quads.push_back({f[0], f[1], f[2], f[2]});  // drawn as a triangle
    else throw std::runtime_error(path + ": a face with " + std::to_string(f.size()) + " corners (quads expected)");
  }
  if (scene.quads.empty()) throw std::runtime_error(path + ": no faces");
  return scene;
}

}  // namespace render
}  // namespace fcql
