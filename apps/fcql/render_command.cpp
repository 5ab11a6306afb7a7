// fcql render: PNG pictures of the output directory of `fcql run`, drawn without a display by
// the project's own rasterizer (vcg_ext/render). The layout view shows the cut surface
// (layout.ply) with one colour per patch (neighbouring patches always differ), the
// separatrices (separatrices.obj) as dark lines and the singularities as dots: blue where three
// separatrices leave (index +1/4), red where five leave (−1/4), white otherwise (other
// indices, border singularities, virtual anchors). The quad view shows quad.obj with its edges
// and its irregular vertices (same colours by valence).
#include "command_line.h"
#include "commands.h"

#include "mesh/input_file.h"
#include "mesh/ply_reader.h"
#include "render/png.h"
#include "render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>

namespace fcql {

namespace {

using render::Rgb;

struct LayoutScene {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> patch;  ///< per triangle
};

struct Polyline {
  std::vector<Vec3> points;
  std::string kind;  ///< from the comment before its `l` line: "separatrix", "t-junction", "to border" or ""
};

struct QuadScene {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 4>> quads;
};

struct Dot {
  Vec3 position;
  int valence;
};

std::string readWhole(const std::string& path) {
  std::string bytes, error;
  if (!readRegularFile(path, bytes, error)) throw std::runtime_error(error);
  return bytes;
}

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// layout.ply (any PLY with a per-face scalar `patch`), through the project's strict PLY reader.
LayoutScene readLayoutPly(const std::string& path) {
  PlyPolygons ply;
  try {
    ply = parsePly(readWhole(path), path, {"patch"});
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

// OBJ `v` and `l` (polylines) or `f` (faces) lines; indices may be negative (relative) or
// carry /vt/vn parts.
struct ObjData {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> lines, faces;
  std::vector<std::string> lineComments;  ///< the comment just before each `l`
};

ObjData readObj(const std::string& path) {
  std::istringstream in(readWhole(path));
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

std::vector<Polyline> readSeparatrices(const std::string& path) {
  ObjData obj = readObj(path);
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

QuadScene readQuads(const std::string& path) {
  ObjData obj = readObj(path);
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

// Twelve clearly different colours of medium lightness (dark lines and dots stay readable on
// all of them).
const Rgb kPalette[] = {{231, 111, 98},  {92, 163, 224},  {102, 199, 120}, {245, 178, 66},  {163, 120, 201}, {70, 196, 186},
                        {240, 220, 90},  {222, 121, 176}, {150, 205, 240}, {196, 226, 120}, {214, 150, 108}, {168, 174, 236}};
const int kPaletteSize = int(sizeof kPalette / sizeof kPalette[0]);

// One palette colour per triangle, by patch, such that patches sharing an edge differ (greedy colouring,
// most-connected patches first, each taking the least used colour its neighbours leave free).
std::vector<Rgb> patchColours(const LayoutScene& s) {
  // Patch ids made dense (they need not be 0..n−1 in a hand-edited file).
  std::map<int, int> dense;
  for (int p : s.patch) dense.emplace(p, 0);
  int patches = 0;
  for (auto& [id, index] : dense) index = patches++;
  std::vector<int> patchOf(s.patch.size());
  for (std::size_t t = 0; t < s.patch.size(); ++t) patchOf[t] = dense[s.patch[t]];
  std::map<std::pair<int, int>, int> edgePatch;
  std::vector<std::set<int>> neighbours(patches);
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      int a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      auto it = edgePatch.emplace(std::minmax(a, b), patchOf[t]).first;
      if (it->second != patchOf[t]) neighbours[it->second].insert(patchOf[t]), neighbours[patchOf[t]].insert(it->second);
    }
  std::vector<int> order(patches);
  for (int p = 0; p < patches; ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return neighbours[a].size() > neighbours[b].size(); });
  std::vector<int> colour(patches, -1), uses(kPaletteSize, 0);
  for (int p : order) {
    std::vector<int> clash(kPaletteSize, 0);
    for (int q : neighbours[p])
      if (colour[q] >= 0) ++clash[colour[q]];
    int best = 0;
    for (int c = 1; c < kPaletteSize; ++c)
      if (std::make_pair(clash[c], uses[c]) < std::make_pair(clash[best], uses[best])) best = c;
    colour[p] = best;
    ++uses[best];
  }
  std::vector<Rgb> result(s.patch.size());  // per triangle
  for (std::size_t t = 0; t < s.patch.size(); ++t) result[t] = kPalette[colour[patchOf[t]]];
  return result;
}

// Singularities are where separatrices leave: the first point of every layout separatrix and
// the last one of those joining two ports (t-junction and border ends are not singular). The
// valence is the number of separatrices leaving the point.
std::vector<Dot> separatrixOrigins(const std::vector<Polyline>& lines) {
  std::map<std::array<double, 3>, int> count;
  auto add = [&](const Vec3& p) { ++count[{p.x(), p.y(), p.z()}]; };
  for (const Polyline& l : lines) {
    add(l.points.front());
    if (l.kind == "separatrix" || l.kind.empty()) add(l.points.back());
  }
  std::vector<Dot> dots;
  for (const auto& [p, n] : count) dots.push_back({Vec3(p[0], p[1], p[2]), n});
  return dots;
}

// Interior vertices of the quad mesh with other than four edges.
std::vector<Dot> irregularVertices(const QuadScene& q) {
  std::map<std::pair<int, int>, int> edgeFaces;
  for (const auto& f : q.quads)
    for (int i = 0; i < 4; ++i)
      if (f[i] != f[(i + 1) % 4]) ++edgeFaces[std::minmax(f[i], f[(i + 1) % 4])];
  std::vector<int> valence(q.positions.size(), 0);
  std::vector<char> border(q.positions.size(), 0);
  for (const auto& [e, faces] : edgeFaces) {
    ++valence[e.first], ++valence[e.second];
    if (faces == 1) border[e.first] = border[e.second] = 1;
  }
  std::vector<Dot> dots;
  for (std::size_t v = 0; v < q.positions.size(); ++v)
    if (!border[v] && valence[v] > 0 && valence[v] != 4) dots.push_back({q.positions[v], valence[v]});
  return dots;
}

// Drawing at 3× the size and averaging down smooths the edges; big pictures take less of it
// (memory: 7 bytes per drawn pixel).
int supersampling(int size) { return size <= 1200 ? 3 : (size <= 2400 ? 2 : 1); }

struct Style {
  double scale;  // output pixels per "unit": size / 800
  double separatrixWidth() const { return std::max(1.3, 2.4 * scale); }
  double quadEdgeWidth() const { return std::max(0.7, 1.0 * scale); }
  double dotRadius() const { return std::max(2.4, 4.5 * scale); }
  double ring() const { return std::max(1.0, 1.5 * scale); }
};

const Rgb kBackground{255, 255, 255}, kInk{28, 28, 36}, kOutline{60, 60, 70};

Rgb dotColour(int valence) {
  if (valence == 3) return {40, 100, 235};
  if (valence == 5) return {225, 35, 35};
  return {250, 250, 250};
}

void drawDots(render::Rasterizer& r, const std::vector<Dot>& dots, const Style& st) {
  for (const Dot& d : dots) r.dot(d.position, st.dotRadius(), dotColour(d.valence), st.ring(), kInk);
}

render::Image renderLayout(const LayoutScene& s, const std::vector<Polyline>& seps, const render::CameraSetup& cam,
                           const std::vector<Vec3>& frame, int size) {
  Style st{size / 800.0};
  render::Rasterizer r(size, size, cam, kBackground, supersampling(size));
  r.frame(frame);
  std::vector<Rgb> colours = patchColours(s);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    r.triangle(s.positions[tri[0]], s.positions[tri[1]], s.positions[tri[2]], colours[t]);
  }
  r.outline(kOutline, st.quadEdgeWidth());
  for (const Polyline& l : seps)
    for (std::size_t i = 0; i + 1 < l.points.size(); ++i) r.line(l.points[i], l.points[i + 1], st.separatrixWidth(), kInk);
  drawDots(r, separatrixOrigins(seps), st);
  return r.finish();
}

render::Image renderQuads(const QuadScene& q, const render::CameraSetup& cam, const std::vector<Vec3>& frame, int size) {
  Style st{size / 800.0};
  render::Rasterizer r(size, size, cam, kBackground, supersampling(size));
  r.frame(frame);
  const Rgb surface{214, 222, 232};
  std::set<std::pair<int, int>> edges;
  for (const auto& f : q.quads) {
    const Vec3 &a = q.positions[f[0]], &b = q.positions[f[1]], &c = q.positions[f[2]], &d = q.positions[f[3]];
    Vec3 n = (c - a).cross(d - b);  // the quad's normal, so both halves shade alike
    if (f[2] == f[3]) n = (b - a).cross(c - a);
    r.triangle(a, b, c, n, surface);
    if (f[2] != f[3]) r.triangle(a, c, d, n, surface);
    for (int i = 0; i < 4; ++i)
      if (f[i] != f[(i + 1) % 4]) edges.insert(std::minmax(f[i], f[(i + 1) % 4]));
  }
  r.outline(kOutline, st.quadEdgeWidth());
  for (const auto& [a, b] : edges) r.line(q.positions[a], q.positions[b], st.quadEdgeWidth(), {50, 56, 72}, 0.003);
  drawDots(r, irregularVertices(q), st);
  return r.finish();
}

void include(Eigen::AlignedBox3d& box, std::vector<Vec3>& frame, const std::vector<Vec3>& points) {
  for (const Vec3& p : points) box.extend(p);
  frame.insert(frame.end(), points.begin(), points.end());
}

}  // namespace

int renderCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2, {"view", "size", "azimuth", "elevation", "up", "out"}, {"quiet"});
  const auto& pos = cl.positional();
  if (pos.empty()) throw UsageError("missing input: give the output DIR of fcql run");
  if (pos.size() > 1) throw UsageError("unexpected argument '" + pos[1] + "'");
  if (!cl.has("out")) throw UsageError("missing --out FILE.png");
  std::string view = cl.value("view", "layout");
  if (view != "layout" && view != "quad" && view != "both") throw UsageError("view must be layout, quad or both");
  std::string up = cl.value("up", "y");
  if (up != "x" && up != "y" && up != "z") throw UsageError("up must be x, y or z");
  int size = cl.integer("size", 800, 32, 4096);
  render::CameraSetup cam;
  cam.azimuthDeg = cl.number("azimuth", 30, -360, 360);
  cam.elevationDeg = cl.number("elevation", 20, -90, 90);
  cam.upAxis = up[0] - 'x';
  std::string out = cl.value("out");

  const std::string dir = pos[0];
  struct stat st;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) throw std::runtime_error(dir + ": no such directory");
  bool wantLayout = view != "quad", wantQuad = view != "layout";
  LayoutScene layout;
  std::vector<Polyline> seps;
  QuadScene quads;
  Eigen::AlignedBox3d box;
  std::vector<Vec3> frame;  // the points the picture is fitted to (both panels alike)
  if (wantLayout) {
    layout = readLayoutPly(dir + "/layout.ply");
    seps = readSeparatrices(dir + "/separatrices.obj");
    include(box, frame, layout.positions);
  }
  if (wantQuad) {
    quads = readQuads(dir + "/quad.obj");
    include(box, frame, quads.positions);
  }
  cam.center = box.center();
  cam.radius = std::max(0.5 * box.diagonal().norm(), 1e-12);

  render::Image picture;
  if (view == "both") {
    render::Image left = renderLayout(layout, seps, cam, frame, size), right = renderQuads(quads, cam, frame, size);
    picture = render::Image(2 * size, size);
    for (int y = 0; y < size; ++y) {
      std::copy(left.pixel(0, y), left.pixel(0, y) + 3 * size, picture.pixel(0, y));
      std::copy(right.pixel(0, y), right.pixel(0, y) + 3 * size, picture.pixel(size, y));
    }
  } else {
    picture = wantLayout ? renderLayout(layout, seps, cam, frame, size) : renderQuads(quads, cam, frame, size);
  }
  render::savePng(picture, out);
  progress(cl.has("quiet"), "wrote " + out + " (" + std::to_string(picture.width) + "x" + std::to_string(picture.height) +
                                 ", " + view + " view)");
  return 0;
}

}  // namespace fcql
