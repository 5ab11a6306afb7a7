#include "layout/patch_layout.h"

#include "util/union_find.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace fcql {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

struct FacePoint {
  int global;
  Vec2 xy;
};

struct Chord {
  int a, b;   ///< local point indices
  int curve;  ///< separatrix index
  double paramA, paramB;  ///< path parameter at a and b
};

/// What an edge of the arrangement lies on.
struct EdgeInfo {
  int curve;          ///< separatrix, −2 border, −1 none
  double paramLow;    ///< path parameter at the lower local point index
  double paramHigh;   ///< ... at the higher one
};

/// Builds the arrangement of one triangle and appends its triangles.
class FaceArrangement {
public:
  FaceArrangement(const SurfaceMesh& mesh, int f, std::vector<Vec3>& positions)
      : mesh_(mesh), f_(f), positions_(positions) {
    origin_ = mesh.position(mesh.vertex(f, 0));
    x_ = mesh.faceFrameX(f);
    y_ = mesh.faceFrameY(f);
    double longest = 0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, mesh.edgeVector(f, i).norm());
    eps_ = 1e-9 * longest;
    for (int c = 0; c < 3; ++c) addPoint(mesh.vertex(f, c), mesh.position(mesh.vertex(f, c)));
  }

  Vec2 to2d(const Vec3& p) const { return Vec2((p - origin_).dot(x_), (p - origin_).dot(y_)); }

  /// Adds (or finds) a point with a known global id.
  int addPoint(int global, const Vec3& p) {
    for (int i = 0; i < int(points_.size()); ++i)
      if (points_[i].global == global) return i;
    points_.push_back({global, to2d(p)});
    return int(points_.size()) - 1;
  }

  /// Adds a point without a global id yet (an interior point), snapping to an existing one.
  int addInteriorPoint(const Vec2& xy) {
    for (int i = 0; i < int(points_.size()); ++i)
      if ((points_[i].xy - xy).norm() <= 1e3 * eps_) return i;
    Vec3 p = origin_ + x_ * xy.x() + y_ * xy.y();
    positions_.push_back(p);
    points_.push_back({int(positions_.size()) - 1, xy});
    return int(points_.size()) - 1;
  }
  int addInteriorPoint3d(const Vec3& p) { return addInteriorPoint(to2d(p)); }

  void addChord(int a, int b, int curve, double paramA, double paramB) {
    if (a != b) chords_.push_back({a, b, curve, paramA, paramB});
  }

  /// Triangulates the arrangement; appends triangles with per-edge curve ids.
  void triangulate(std::vector<std::array<int, 3>>& tris, std::vector<std::array<int, 3>>& curves,
                   std::vector<std::array<std::array<double, 2>, 3>>& params, std::vector<int>& originalFace) {
    intersectChords();
    // Undirected edges with their curve: chord pieces and boundary pieces.
    std::map<std::pair<int, int>, EdgeInfo> edges;
    auto addEdge = [&](int a, int b, int curve, double pa, double pb) {
      if (a == b) return;
      EdgeInfo info{curve, a < b ? pa : pb, a < b ? pb : pa};
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = edges.find(key);
      if (it == edges.end() || it->second.curve < curve) edges[key] = info;
    };
    for (const Chord& c : chords_) {
      std::vector<double> t;
      auto on = pointsOnSegment(c.a, c.b, &t);
      for (std::size_t i = 0; i + 1 < on.size(); ++i)
        addEdge(on[i], on[i + 1], c.curve, c.paramA + t[i] * (c.paramB - c.paramA),
                c.paramA + t[i + 1] * (c.paramB - c.paramA));
    }
    for (int i = 0; i < 3; ++i) {
      int curve = mesh_.isBorderEdge(f_, i) ? -2 : -1;
      auto on = pointsOnSegment(i, (i + 1) % 3);
      for (std::size_t k = 0; k + 1 < on.size(); ++k) addEdge(on[k], on[k + 1], curve, 0, 0);
    }
    // Faces of the planar graph, traced with the face on the left.
    const int n = int(points_.size());
    std::vector<std::vector<int>> around(n);
    for (const auto& e : edges) {
      around[e.first.first].push_back(e.first.second);
      around[e.first.second].push_back(e.first.first);
    }
    for (int v = 0; v < n; ++v) {
      auto& nb = around[v];
      std::sort(nb.begin(), nb.end(), [&](int a, int b) {
        Vec2 da = points_[a].xy - points_[v].xy, db = points_[b].xy - points_[v].xy;
        return std::atan2(da.y(), da.x()) < std::atan2(db.y(), db.x());
      });
    }
    std::map<std::pair<int, int>, char> used;
    for (const auto& e : edges)
      for (int dir = 0; dir < 2; ++dir) {
        int u = dir ? e.first.second : e.first.first, v = dir ? e.first.first : e.first.second;
        if (used[{u, v}]) continue;
        std::vector<int> cycle;
        int a = u, b = v;
        for (int guard = 0; guard < 4 * n + 8; ++guard) {
          used[{a, b}] = 1;
          cycle.push_back(a);
          const auto& nb = around[b];
          int at = int(std::find(nb.begin(), nb.end(), a) - nb.begin());
          int w = nb[(at + int(nb.size()) - 1) % int(nb.size())];  // next clockwise from a
          a = b;
          b = w;
          if (a == u && b == v) break;
        }
        double area = 0;
        for (std::size_t i = 0; i < cycle.size(); ++i)
          area += cross2(points_[cycle[i]].xy, points_[cycle[(i + 1) % cycle.size()]].xy);
        if (area <= 0) continue;  // the outer face
        earClip(cycle, edges, tris, curves, params, originalFace);
      }
  }

private:
  /// Local indices of the points on segment [a, b], sorted from a to b (with their
  /// parameters along it in `params` if given).
  std::vector<int> pointsOnSegment(int a, int b, std::vector<double>* params = nullptr) const {
    const Vec2 pa = points_[a].xy, pb = points_[b].xy;
    Vec2 d = pb - pa;
    double len2 = d.squaredNorm();
    std::vector<std::pair<double, int>> on = {{0.0, a}, {1.0, b}};
    for (int i = 0; i < int(points_.size()); ++i) {
      if (i == a || i == b) continue;
      Vec2 w = points_[i].xy - pa;
      double t = w.dot(d) / len2;
      if (t <= 0 || t >= 1) continue;
      if (std::abs(cross2(d, w)) / std::sqrt(len2) > 1e3 * eps_) continue;
      on.push_back({t, i});
    }
    std::sort(on.begin(), on.end());
    std::vector<int> out;
    for (const auto& p : on) {
      out.push_back(p.second);
      if (params) params->push_back(p.first);
    }
    return out;
  }

  void intersectChords() {
    for (std::size_t i = 0; i < chords_.size(); ++i)
      for (std::size_t j = i + 1; j < chords_.size(); ++j) {
        const Chord& c = chords_[i];
        const Chord& d = chords_[j];
        if (c.a == d.a || c.a == d.b || c.b == d.a || c.b == d.b) continue;
        Vec2 p = points_[c.a].xy, r = points_[c.b].xy - p;
        Vec2 q = points_[d.a].xy, s = points_[d.b].xy - q;
        double denom = cross2(r, s);
        if (std::abs(denom) < 1e-14 * r.norm() * s.norm()) continue;  // parallel
        double t = cross2(q - p, s) / denom, u = cross2(q - p, r) / denom;
        if (t <= 0 || t >= 1 || u <= 0 || u >= 1) continue;
        addInteriorPoint(p + r * t);
      }
  }

  void earClip(std::vector<int> poly, const std::map<std::pair<int, int>, EdgeInfo>& edges,
               std::vector<std::array<int, 3>>& tris, std::vector<std::array<int, 3>>& curves,
               std::vector<std::array<std::array<double, 2>, 3>>& params, std::vector<int>& originalFace) {
    auto curveOf = [&](int a, int b) {
      auto it = edges.find({std::min(a, b), std::max(a, b)});
      return it == edges.end() ? -1 : it->second.curve;
    };
    auto paramOf = [&](int a, int b) -> std::array<double, 2> {
      auto it = edges.find({std::min(a, b), std::max(a, b)});
      if (it == edges.end()) return {0, 0};
      return a < b ? std::array<double, 2>{it->second.paramLow, it->second.paramHigh}
                   : std::array<double, 2>{it->second.paramHigh, it->second.paramLow};
    };
    double scale = 0;
    for (int i : poly) scale = std::max(scale, points_[i].xy.norm());
    double minArea = 1e-14 * (scale * scale + 1e-300);
    while (poly.size() >= 3) {
      const int m = int(poly.size());
      int best = -1;
      double bestArea = 0;
      for (int i = 0; i < m; ++i) {
        int a = poly[(i + m - 1) % m], b = poly[i], c = poly[(i + 1) % m];
        double area = cross2(points_[b].xy - points_[a].xy, points_[c].xy - points_[a].xy);
        if (area <= minArea) continue;
        bool empty = true;
        for (int k = 0; k < m && empty; ++k) {
          int p = poly[k];
          if (p == a || p == b || p == c) continue;
          const Vec2& x = points_[p].xy;
          double w0 = cross2(points_[b].xy - points_[a].xy, x - points_[a].xy);
          double w1 = cross2(points_[c].xy - points_[b].xy, x - points_[b].xy);
          double w2 = cross2(points_[a].xy - points_[c].xy, x - points_[c].xy);
          if (w0 >= -minArea && w1 >= -minArea && w2 >= -minArea) empty = false;
        }
        // Prefer the fattest ear: keeps the triangles away from slivers.
        if (empty && area > bestArea) best = i, bestArea = area;
      }
      if (best < 0) break;
      int a = poly[(best + m - 1) % m], b = poly[best], c = poly[(best + 1) % m];
      tris.push_back({points_[a].global, points_[b].global, points_[c].global});
      curves.push_back({curveOf(a, b), curveOf(b, c), -1});  // c→a is inside unless it is a polygon edge
      params.push_back({paramOf(a, b), paramOf(b, c), std::array<double, 2>{0, 0}});
      if (poly.size() == 3) curves.back()[2] = curveOf(c, a), params.back()[2] = paramOf(c, a);
      originalFace.push_back(f_);
      poly.erase(poly.begin() + best);
    }
  }

  const SurfaceMesh& mesh_;
  int f_;
  std::vector<Vec3>& positions_;
  Vec3 origin_, x_, y_;
  double eps_;
  std::vector<FacePoint> points_;
  std::vector<Chord> chords_;
};

std::uint64_t key(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

}  // namespace

int addBoundaryCorners(PatchLayout& out, int patch) {
  PatchReport& rep = out.patches[patch];
  const int m = int(rep.loop.size());
  std::map<int, int> timesOnLoop;
  for (int v : rep.loop) ++timesOnLoop[v];
  std::vector<double> at(m + 1, 0.0);  // arc length from loop[0] to loop[k]
  for (int k = 0; k < m; ++k) at[k + 1] = at[k] + (out.positions[rep.loop[(k + 1) % m]] - out.positions[rep.loop[k]]).norm();
  auto usable = [&](int k) { return !rep.loopCorner[k] && timesOnLoop[rep.loop[k]] == 1; };
  auto lengthFrom = [&](int from, int to) {  // along the loop, forwards, wrapping round
    return to > from ? at[to] - at[from] : at[m] - at[from] + at[to];
  };
  int added = 0;
  auto makeCorner = [&](int k) {
    rep.loopCorner[k] = 1;
    out.corner[rep.loop[k]] = 1;
    ++rep.corners, ++added;
  };
  while (rep.corners < 3) {
    std::vector<int> corners;
    for (int k = 0; k < m; ++k)
      if (rep.loopCorner[k]) corners.push_back(k);
    if (corners.empty()) {  // a cap: start from any usable vertex
      int first = -1;
      for (int k = 0; k < m && first < 0; ++k)
        if (usable(k)) first = k;
      if (first < 0) break;
      makeCorner(first);
      continue;
    }
    // The longest stretch from a corner a to the next corner b (with one corner: the whole
    // loop from a back to a).
    int a = -1, b = -1;
    double best = -1;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const int from = corners[i], to = corners[(i + 1) % corners.size()];
      const double length = lengthFrom(from, to);
      if (length > best) best = length, a = from, b = to;
    }
    // The usable vertex strictly inside the stretch nearest its middle.
    int split = -1;
    double bestOffset = 0;
    for (int step = 1; step < m; ++step) {
      const int k = (a + step) % m;
      if (k == b) break;
      if (!usable(k)) continue;
      const double offset = std::abs(lengthFrom(a, k) - 0.5 * best);
      if (split < 0 || offset < bestOffset) split = k, bestOffset = offset;
    }
    if (split < 0) break;
    makeCorner(split);
  }
  out.addedCorners += added;
  return added;
}

int PatchLayout::numInvalidPatches() const {
  return int(std::count_if(patches.begin(), patches.end(), [](const PatchReport& p) { return !p.valid; }));
}

std::vector<std::pair<int, int>> PatchLayout::cornerHistogram() const {
  std::map<int, int> h;
  for (const auto& p : patches)
    if (p.isDisk) ++h[p.corners];
  return {h.begin(), h.end()};
}

namespace {

using HalfEdgeIndex = std::unordered_map<std::uint64_t, int>;  // (a, b) -> t*3+i

/// Step 1: the triangles of the layout. Faces no separatrix touches are copied; the others are
/// cut along the separatrices through them (FaceArrangement), with the auxiliary points the
/// separatrices pass through as new vertices.
void arrangeFaces(const GeodesicGraph& graph, const Layout& layout, PatchLayout& out) {
  const SurfaceMesh& mesh = graph.mesh();
  const EdgeSampling& es = graph.sampling();
  // Global ids of the auxiliary points the separatrices pass through.
  std::unordered_map<int, int> sampleVertex;
  std::vector<std::vector<int>> samplesOfEdge(mesh.numEdges());
  for (const auto& s : layout.separatrices)
    for (const auto& p : s.path.points)
      if (p.kind == PathPoint::Sample && !sampleVertex.count(p.id)) {
        sampleVertex[p.id] = int(out.positions.size());
        out.positions.push_back(es.samplePosition[p.id]);
        samplesOfEdge[es.sampleEdge[p.id]].push_back(p.id);
      }
  // Chords per face.
  struct FaceChord {
    int curve;
    PathPoint a, b;
    double paramA, paramB;
  };
  std::vector<std::vector<FaceChord>> chordsOfFace(mesh.numFaces());
  for (int s = 0; s < int(layout.separatrices.size()); ++s) {
    const TracedPath& path = layout.separatrices[s].path;
    for (std::size_t i = 0; i < path.segments.size(); ++i)
      chordsOfFace[path.segments[i].face].push_back({s, path.points[i], path.points[i + 1], double(i), double(i + 1)});
  }
  for (int f = 0; f < mesh.numFaces(); ++f) {
    bool touched = !chordsOfFace[f].empty();
    for (int i = 0; i < 3 && !touched; ++i) touched = !samplesOfEdge[mesh.edgeId(f, i)].empty();
    if (!touched) {
      out.triangles.push_back(mesh.face(f));
      out.edgeCurve.push_back({mesh.isBorderEdge(f, 0) ? -2 : -1, mesh.isBorderEdge(f, 1) ? -2 : -1,
                               mesh.isBorderEdge(f, 2) ? -2 : -1});
      out.edgeParam.push_back({});
      out.originalFace.push_back(f);
      continue;
    }
    FaceArrangement arr(mesh, f, out.positions);
    for (int i = 0; i < 3; ++i)
      for (int q : samplesOfEdge[mesh.edgeId(f, i)]) arr.addPoint(sampleVertex[q], es.samplePosition[q]);
    auto local = [&](const PathPoint& p) {
      if (p.kind == PathPoint::Vertex) return arr.addPoint(p.id, mesh.position(p.id));
      if (p.kind == PathPoint::Sample) return arr.addPoint(sampleVertex[p.id], es.samplePosition[p.id]);
      return arr.addInteriorPoint3d(p.position);
    };
    for (const auto& c : chordsOfFace[f]) {
      int a = local(c.a), b = local(c.b);
      arr.addChord(a, b, c.curve, c.paramA, c.paramB);
    }
    arr.triangulate(out.triangles, out.edgeCurve, out.edgeParam, out.originalFace);
  }
}

/// Step 2: patches, the components across edges that are not on a separatrix or the border
/// (out.patch, out.patches sized). Returns the half-edges of the triangles.
HalfEdgeIndex labelPatches(PatchLayout& out) {
  const int nt = int(out.triangles.size());
  HalfEdgeIndex halfEdge;
  halfEdge.reserve(std::size_t(nt) * 3);
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) halfEdge[key(out.triangles[t][i], out.triangles[t][(i + 1) % 3])] = t * 3 + i;
  // A separatrix edge is a separatrix edge from both sides.
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      if (out.edgeCurve[t][i] < 0) continue;
      auto it = halfEdge.find(key(out.triangles[t][(i + 1) % 3], out.triangles[t][i]));
      if (it != halfEdge.end()) {
        out.edgeCurve[it->second / 3][it->second % 3] = out.edgeCurve[t][i];
        out.edgeParam[it->second / 3][it->second % 3] = {out.edgeParam[t][i][1], out.edgeParam[t][i][0]};
      }
    }
  UnionFind uf(nt);
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      if (out.edgeCurve[t][i] != -1) continue;
      auto it = halfEdge.find(key(out.triangles[t][(i + 1) % 3], out.triangles[t][i]));
      if (it != halfEdge.end()) uf.unite(t, it->second / 3);
    }
  std::unordered_map<int, int> patchOfRoot;
  out.patch.resize(nt);
  for (int t = 0; t < nt; ++t) {
    auto ins = patchOfRoot.emplace(uf.find(t), int(patchOfRoot.size()));
    out.patch[t] = ins.first->second;
  }
  out.patches.assign(patchOfRoot.size(), {});
  return halfEdge;
}

/// Which boundary vertices are corners of a patch: where its boundary changes separatrix (or
/// jumps along the same one), and at singular vertices, unless it runs straight on there.
class CornerRule {
public:
  CornerRule(const GeodesicGraph& graph, const Layout& layout)
      : graph_(graph), layout_(layout), mesh_(graph.mesh()), index_(graph.analysis().vertexIndexQuarters) {
    // A field line that closes on itself through a regular (virtual) anchor runs straight on
    // through it: its parameter wraps from the last segment back to 0 there.
    closedLoopLength_.assign(layout.separatrices.size(), -1);
    for (int i = 0; i < int(layout.separatrices.size()); ++i) {
      const auto& s = layout.separatrices[i];
      if (s.portA < 0 || s.portB < 0) continue;
      int va = graph.ports()[s.portA].vertex, vb = graph.ports()[s.portB].vertex;
      if (va == vb && index_[va] == 0) closedLoopLength_[i] = int(s.path.segments.size());
    }
  }

  /// Is b a corner where the boundary arrives along curve c1 (parameter p1 at b) and leaves
  /// along c2 (parameter p2)?
  bool isCorner(int b, int c1, double p1, int c2, double p2) const {
    // Same separatrix on both sides of b, but is it the same stretch of it?
    bool jump = c1 >= 0 && c1 == c2 && std::abs(p1 - p2) > 1e-6;
    if (jump && closedLoopLength_[c1] > 0 && std::abs(std::abs(p1 - p2) - closedLoopLength_[c1]) < 1e-6) jump = false;
    return (c1 != c2 || jump || alwaysCorner(b)) && !straightThroughSingularity(b, c1, p1, c2, p2);
  }

private:
  /// Vertices that are corners whenever a patch boundary passes through them.
  bool alwaysCorner(int v) const { return v < mesh_.numVertices() && index_[v] != 0; }

  // At an interior singular vertex the patch's wedge lies between the separatrix the boundary
  // leaves by and the one it arrives by, both ending there: it spans as many of the vertex's
  // sectors (90° each) as port steps from the first round (counter-clockwise, the patch on the
  // left) to the second. Two steps mean a port between them that no separatrix leaves (an
  // unresolved port): the boundary runs straight on through the vertex, which is no corner of
  // this patch (it is one of the patches beyond the two separatrices).
  int portEndingAt(int c, double param, int v) const {
    if (c < 0) return -1;
    const LayoutSeparatrix& s = layout_.separatrices[c];
    if (std::abs(param) < 1e-6 && s.portA >= 0 && graph_.ports()[s.portA].vertex == v) return s.portA;
    if (std::abs(param - double(s.path.segments.size())) < 1e-6 && s.portB >= 0 && graph_.ports()[s.portB].vertex == v)
      return s.portB;
    return -1;
  }
  bool straightThroughSingularity(int v, int arriving, double arrivingParam, int leaving, double leavingParam) const {
    if (v >= mesh_.numVertices() || index_[v] == 0) return false;
    const int in = portEndingAt(arriving, arrivingParam, v), out = portEndingAt(leaving, leavingParam, v);
    if (in < 0 || out < 0) return false;
    const PortNode &a = graph_.ports()[in], &b = graph_.ports()[out];
    const SingularVertex& sv = graph_.analysis().singularities[a.singularity];
    if (sv.onBorder || a.singularity != b.singularity) return false;
    const int m = int(sv.ports.size());
    return ((a.portIndex - b.portIndex) % m + m) % m == 2;
  }

  const GeodesicGraph& graph_;
  const Layout& layout_;
  const SurfaceMesh& mesh_;
  const std::vector<int>& index_;
  std::vector<int> closedLoopLength_;
};

/// Per patch, what its Euler characteristic needs besides the boundary walk.
struct PatchTally {
  std::vector<long> interiorHalfEdges;
  std::vector<std::vector<int>> vertices;
  std::vector<std::unordered_map<int, char>> onBoundary;  ///< filled by walkBoundaries
};

/// Counts each patch's triangles (in out.patches) and interior half-edges, and lists its vertices.
PatchTally tallyPatches(PatchLayout& out) {
  const int nt = int(out.triangles.size()), np = int(out.patches.size());
  PatchTally tally;
  tally.interiorHalfEdges.assign(np, 0);
  tally.vertices.resize(np);
  tally.onBoundary.resize(np);
  for (int t = 0; t < nt; ++t) {
    int p = out.patch[t];
    out.patches[p].triangles += 1;
    for (int i = 0; i < 3; ++i) {
      tally.vertices[p].push_back(out.triangles[t][i]);
      if (out.edgeCurve[t][i] == -1) tally.interiorHalfEdges[p] += 1;
    }
  }
  return tally;
}

/// Step 3: walks the boundary loops of every patch, counting loops and corners, marking the
/// corners (out.corner) and recording each patch's first loop with its corners.
void walkBoundaries(const HalfEdgeIndex& halfEdge, const CornerRule& corners, PatchLayout& out,
                    std::vector<std::unordered_map<int, char>>& onBoundary) {
  const int nt = int(out.triangles.size());
  // From boundary half-edge (a→b) in triangle t, rotate about b through the patch (across
  // edges inside it) to the next boundary half-edge leaving b.
  auto isBoundary = [&](int t, int i) { return out.edgeCurve[t][i] != -1; };
  auto nextBoundary = [&](int t, int i) {
    int b = out.triangles[t][(i + 1) % 3];
    int tt = t, j = (i + 1) % 3;  // edge b → c of t
    for (int guard = 0; guard < 4 * nt + 8; ++guard) {
      if (isBoundary(tt, j)) return tt * 3 + j;
      auto it = halfEdge.find(key(out.triangles[tt][(j + 1) % 3], b));
      if (it == halfEdge.end()) return -1;
      tt = it->second / 3;
      j = (it->second % 3 + 1) % 3;  // in tt the edge (c → b) is followed by (b → d)
    }
    return -1;
  };
  std::vector<char> visited(std::size_t(nt) * 3, 0);
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      if (!isBoundary(t, i) || visited[t * 3 + i]) continue;
      int p = out.patch[t];
      PatchReport& rep = out.patches[p];
      rep.boundaryLoops += 1;
      const bool recordLoop = rep.boundaryLoops == 1;
      std::vector<char> cornerAtEnd;
      int he = t * 3 + i;
      for (int guard = 0; guard < 3 * nt + 8 && he >= 0 && !visited[he]; ++guard) {
        visited[he] = 1;
        int tt = he / 3, ii = he % 3;
        onBoundary[p][out.triangles[tt][ii]] = 1;
        if (recordLoop) rep.loop.push_back(out.triangles[tt][ii]), rep.loopTriangle.push_back(tt);
        int next = nextBoundary(tt, ii);
        if (next < 0) {
          rep.problem = "its boundary is not a closed loop";
          break;
        }
        int b = out.triangles[tt][(ii + 1) % 3];
        int c1 = out.edgeCurve[tt][ii], c2 = out.edgeCurve[next / 3][next % 3];
        double p1 = out.edgeParam[tt][ii][1], p2 = out.edgeParam[next / 3][next % 3][0];
        bool isCorner = corners.isCorner(b, c1, p1, c2, p2);
        if (isCorner) {
          rep.corners += 1;
          out.corner[b] = 1;
        }
        if (recordLoop) cornerAtEnd.push_back(isCorner);
        he = next;
      }
      if (recordLoop) {
        const std::size_t m = cornerAtEnd.size();
        rep.loopCorner.assign(rep.loop.size(), 0);
        for (std::size_t k = 0; k < m && k < rep.loop.size(); ++k) rep.loopCorner[(k + 1) % rep.loop.size()] = cornerAtEnd[k];
      }
    }
}

/// Step 4: each patch's Euler characteristic, whether it is a valid 4-sided disk and, if not,
/// why; disks with fewer than 3 corners get corners added on their boundary.
void classifyPatches(PatchTally& tally, PatchLayout& out) {
  const int np = int(out.patches.size());
  for (int p = 0; p < np; ++p) {
    auto& vs = tally.vertices[p];
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    long interiorVertices = 0;
    for (int v : vs) interiorVertices += tally.onBoundary[p].count(v) ? 0 : 1;
    PatchReport& rep = out.patches[p];
    // χ of the patch cut open along its boundary (see the header).
    rep.eulerCharacteristic = int(interiorVertices - tally.interiorHalfEdges[p] / 2 + rep.triangles);
    rep.isDisk = rep.eulerCharacteristic == 1 && rep.boundaryLoops == 1;
    // A boundary that goes x → v → x runs along a separatrix and straight back: a separatrix
    // ends inside the patch, at v (a slit); no grid fits such a patch.
    const int m = int(rep.loop.size());
    for (int k = 0; k < m && m > 2 && rep.problem.empty(); ++k)
      if (rep.loop[(k + m - 1) % m] == rep.loop[(k + 1) % m])
        rep.problem = "a separatrix ends inside it (a slit at vertex " + std::to_string(rep.loop[k]) + ")";
    rep.valid = rep.isDisk && rep.corners == 4 && rep.problem.empty();
    if (rep.problem.empty() && !rep.isDisk)
      rep.problem = "not a disk (Euler characteristic " + std::to_string(rep.eulerCharacteristic) + ", " +
                    std::to_string(rep.boundaryLoops) + " boundary loops)";
    else if (rep.problem.empty() && rep.corners != 4)
      rep.problem = std::to_string(rep.corners) + " corners";
    if (rep.problem.empty() || !rep.isDisk || rep.corners >= 3) continue;
    const int added = addBoundaryCorners(out, p);
    rep.problem = std::to_string(rep.corners - added) + " corners (" + std::to_string(added) +
                  " added on its boundary to cut it as a " + std::to_string(rep.corners) + "-gon)";
  }
}

}  // namespace

PatchLayout buildPatchLayout(const GeodesicGraph& graph, const Layout& layout) {
  PatchLayout out;
  out.numOriginalVertices = graph.mesh().numVertices();
  out.positions = graph.mesh().positions();
  arrangeFaces(graph, layout, out);
  const HalfEdgeIndex halfEdge = labelPatches(out);
  const CornerRule corners(graph, layout);
  out.corner.assign(out.positions.size(), 0);
  PatchTally tally = tallyPatches(out);
  walkBoundaries(halfEdge, corners, out, tally.onBoundary);
  classifyPatches(tally, out);
  return out;
}

}  // namespace fcql
