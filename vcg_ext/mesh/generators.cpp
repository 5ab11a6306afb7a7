#include "mesh/generators.h"

#include "util/math_constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

namespace fcql {
namespace {

/// Collects quads and triangles, welding vertices that coincide.
class MeshBuilder {
public:
  int vertex(const Vec3& x) {
    std::array<long, 3> key = {std::lround(x.x() * 1e7), std::lround(x.y() * 1e7), std::lround(x.z() * 1e7)};
    auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    positions_.push_back(x);
    return index_[key] = int(positions_.size()) - 1;
  }
  /// A planar grid origin + U·s + V·t, s,t ∈ [0,1], facing `outward`.
  void addGrid(const Vec3& origin, Vec3 u, Vec3 v, int nu, int nv, const Vec3& outward) {
    Vec3 o = origin;
    if (u.cross(v).dot(outward) < 0) {
      std::swap(u, v);
      std::swap(nu, nv);
    }
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        int a = vertex(o + u * (double(i) / nu) + v * (double(j) / nv));
        int b = vertex(o + u * (double(i + 1) / nu) + v * (double(j) / nv));
        int c = vertex(o + u * (double(i + 1) / nu) + v * (double(j + 1) / nv));
        int d = vertex(o + u * (double(i) / nu) + v * (double(j + 1) / nv));
        faces_.push_back({a, b, c});
        faces_.push_back({a, c, d});
      }
  }
  std::vector<Vec3>& positions() { return positions_; }
  const std::vector<std::array<int, 3>>& faces() const { return faces_; }

private:
  std::map<std::array<long, 3>, int> index_;
  std::vector<Vec3> positions_;
  std::vector<std::array<int, 3>> faces_;
};

/// Laplacian smoothing of all vertices (uniform weights), `iterations` half steps.
void smooth(std::vector<Vec3>& p, const std::vector<std::array<int, 3>>& faces, int iterations) {
  std::vector<std::vector<int>> nb(p.size());
  for (const auto& f : faces)
    for (int i = 0; i < 3; ++i) nb[f[i]].push_back(f[(i + 1) % 3]);
  for (int it = 0; it < iterations; ++it) {
    std::vector<Vec3> q = p;
    for (std::size_t v = 0; v < p.size(); ++v) {
      if (nb[v].empty()) continue;
      Vec3 mean = Vec3::Zero();
      for (int w : nb[v]) mean += p[w];
      q[v] = 0.5 * p[v] + 0.5 * mean / double(nb[v].size());
    }
    p.swap(q);
  }
}

}  // namespace

SurfaceMesh gridSurface(int nu, int nv, bool closedU, bool closedV, const std::function<Vec3(double, double)>& at,
                        GridDiagonal diagonal) {
  const int cu = closedU ? nu : nu + 1, cv = closedV ? nv : nv + 1;
  std::vector<Vec3> p;
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) p.push_back(at(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) { return (j % cv) * cu + (i % cu); };
  std::vector<std::array<int, 3>> f;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (diagonal == GridDiagonal::Same || (p[a] - p[c]).norm() <= (p[b] - p[d]).norm()) {
        f.push_back({a, b, c});
        f.push_back({a, c, d});
      } else {
        f.push_back({a, b, d});
        f.push_back({b, c, d});
      }
    }
  return SurfaceMesh(p, f);
}

SurfaceMesh makeSphere(int subdivisions) {
  if (subdivisions < 0 || subdivisions > 7) throw MeshError("sphere subdivisions must be between 0 and 7");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& x : p) x.normalize();
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back((p[a] + p[b]).normalized());
      return mid[key] = int(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& tri : f) {
      int ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], ab, ca});
      g.push_back({tri[1], bc, ab});
      g.push_back({tri[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  return SurfaceMesh(p, f);
}

SurfaceMesh makeTorus(double R, double r, int nu, int nv, GridDiagonal diagonal) {
  if (!(R > r && r > 0) || nu < 3 || nv < 3) throw MeshError("torus needs R > r > 0 and at least 3 segments each way");
  return gridSurface(
      nu, nv, true, true,
      [&](double s, double t) {
        double a = 2 * kPi * s, b = 2 * kPi * t;
        return Vec3((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b));
      },
      diagonal);
}

SurfaceMesh makeOpenCylinder(double radius, double height, int nu, int nv, GridDiagonal diagonal) {
  if (!(radius > 0 && height > 0) || nu < 3 || nv < 1) throw MeshError("cylinder needs positive sizes and at least 3 segments around");
  return gridSurface(
      nu, nv, true, false,
      [&](double s, double t) {
        double a = 2 * kPi * s;
        return Vec3(radius * std::cos(a), radius * std::sin(a), height * (t - 0.5));
      },
      diagonal);
}

SurfaceMesh makeRoundedBox(Vec3 half, double radius, int resolution) {
  if (!(radius > 0 && radius < half.minCoeff()) || !half.allFinite() || resolution < 2)
    throw MeshError("rounded box needs 0 < radius < the smallest half-size and resolution >= 2");
  // The surface at distance `radius` from the inner box of half-size half - radius. It is
  // meshed as the outer box, each side a grid, every grid point p pulled onto the surface as
  // core + radius * normalize(p - core), core = the closest point of the inner box. Grid points
  // on a flat part of the outer box stay where they are; those in a strip of width `radius`
  // along an outer box edge land on the quarter cylinder (and, near the corners, on the sphere
  // octant). The grid lines are placed per axis, not uniformly: the flat middle gets
  // ~resolution segments per unit length, each strip k segments, with lines at offsets
  // radius·tan(θ) that land at equal angles θ on the rounded part (the strips of the two sides
  // meeting at an edge each cover 45° of its quarter circle).
  const Vec3 inner = half - Vec3::Constant(radius);
  const double quarterArc = 0.5 * kPi * radius;
  // Segments per strip: quarter circle at the requested density, but at least 4 segments on
  // it in all (2 per strip) so that it stays smooth (≤ 22.5° between neighbouring rows).
  const int k = std::max(2, int(std::ceil(0.5 * quarterArc * resolution - 1e-9)));
  // When that minimum wins (a radius small against 1/resolution), the strips' cells are short
  // across the edge; so that they stay at most 2:1 (no slivers), the flat parts, and with them
  // the spacing along the edges, get denser than `resolution` where needed.
  const double arcSegment = quarterArc / (2 * k);
  const double density = std::max(double(resolution), 0.5 / arcSegment);
  std::array<std::vector<double>, 3> lines;  // sorted grid coordinates on [-half, half] per axis
  for (int axis = 0; axis < 3; ++axis) {
    const double flat = inner[axis];
    const int m = std::max(1, int(std::ceil(2 * flat * density - 1e-9)));
    std::vector<double> strip;  // offsets into the strip, increasing, ending exactly at radius
    for (int i = 1; i < k; ++i) strip.push_back(radius * std::tan(0.25 * kPi * i / k));
    strip.push_back(radius);
    std::vector<double>& l = lines[axis];
    for (auto it = strip.rbegin(); it != strip.rend(); ++it) l.push_back(-flat - *it);
    for (int i = 0; i <= m; ++i) l.push_back(-flat + 2 * flat * i / m);
    for (double s : strip) l.push_back(flat + s);
    l.front() = -half[axis];  // exact extent, whatever the rounding above
    l.back() = half[axis];
  }

  // Vertices are keyed by their integer grid indices on the outer box, so the sides share the
  // vertices of their common edges exactly (no tolerance involved).
  std::map<std::array<int, 3>, int> index;
  std::vector<Vec3> positions;
  auto vertexAt = [&](const std::array<int, 3>& g) {
    auto it = index.find(g);
    if (it != index.end()) return it->second;
    const Vec3 onBox(lines[0][g[0]], lines[1][g[1]], lines[2][g[2]]);
    const Vec3 core = onBox.cwiseMax(-inner).cwiseMin(inner);
    const Vec3 offset = onBox - core;  // never zero: onBox is on the outer box
    positions.push_back(core + radius * offset.normalized());
    return index[g] = int(positions.size()) - 1;
  };

  std::vector<std::array<int, 3>> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      // Tangent axes a, b with (e_a, e_b, outward normal) right-handed: (axis+1, axis+2) on
      // the positive side, swapped on the negative one.
      int a = (axis + 1) % 3, b = (axis + 2) % 3;
      if (side < 0) std::swap(a, b);
      const int na = int(lines[a].size()) - 1, nb = int(lines[b].size()) - 1;
      const int fixed = side > 0 ? int(lines[axis].size()) - 1 : 0;
      auto at = [&](int i, int j) {
        std::array<int, 3> g;
        g[axis] = fixed;
        g[a] = i;
        g[b] = j;
        return vertexAt(g);
      };
      for (int j = 0; j < nb; ++j)
        for (int i = 0; i < na; ++i) {
          const int v00 = at(i, j), v10 = at(i + 1, j), v11 = at(i + 1, j + 1), v01 = at(i, j + 1);
          // Split along the shorter diagonal (after the mapping): better angles near corners.
          if ((positions[v00] - positions[v11]).squaredNorm() <= (positions[v10] - positions[v01]).squaredNorm()) {
            faces.push_back({v00, v10, v11});
            faces.push_back({v00, v11, v01});
          } else {
            faces.push_back({v00, v10, v01});
            faces.push_back({v10, v11, v01});
          }
        }
    }
  return SurfaceMesh(std::move(positions), std::move(faces));
}

SurfaceMesh makeDoubleTorus(int resolution) {
  if (resolution < 4) throw MeshError("double torus resolution must be at least 4");
  // A slab over a 5×3 grid of unit cells with two holes, smoothed into a genus-2 surface.
  const int cellsX = 5, cellsY = 3;
  auto solid = [&](int cx, int cy) {
    if (cx < 0 || cy < 0 || cx >= cellsX || cy >= cellsY) return false;
    return !(cy == 1 && (cx == 1 || cx == 3));
  };
  const int n = std::max(2, resolution / 6);
  const double h = 0.5;
  const int m = std::max(2, int(std::lround(2 * h * n)));
  MeshBuilder b;
  for (int cy = 0; cy < cellsY; ++cy)
    for (int cx = 0; cx < cellsX; ++cx) {
      if (!solid(cx, cy)) continue;
      b.addGrid(Vec3(cx, cy, h), Vec3(1, 0, 0), Vec3(0, 1, 0), n, n, Vec3(0, 0, 1));
      b.addGrid(Vec3(cx, cy, -h), Vec3(1, 0, 0), Vec3(0, 1, 0), n, n, Vec3(0, 0, -1));
      // Walls towards empty neighbours.
      if (!solid(cx + 1, cy)) b.addGrid(Vec3(cx + 1, cy, -h), Vec3(0, 1, 0), Vec3(0, 0, 2 * h), n, m, Vec3(1, 0, 0));
      if (!solid(cx - 1, cy)) b.addGrid(Vec3(cx, cy, -h), Vec3(0, 1, 0), Vec3(0, 0, 2 * h), n, m, Vec3(-1, 0, 0));
      if (!solid(cx, cy + 1)) b.addGrid(Vec3(cx, cy + 1, -h), Vec3(1, 0, 0), Vec3(0, 0, 2 * h), n, m, Vec3(0, 1, 0));
      if (!solid(cx, cy - 1)) b.addGrid(Vec3(cx, cy, -h), Vec3(1, 0, 0), Vec3(0, 0, 2 * h), n, m, Vec3(0, -1, 0));
    }
  smooth(b.positions(), b.faces(), 4 * n);
  return SurfaceMesh(b.positions(), b.faces());
}

std::vector<std::string> exampleNames() { return {"sphere", "torus", "double_torus", "rounded_box", "open_cylinder"}; }

SurfaceMesh makeExample(const std::string& name) {
  if (name == "sphere") return makeSphere(3);
  if (name == "torus") return makeTorus();
  if (name == "double_torus") return makeDoubleTorus();
  if (name == "rounded_box") return makeRoundedBox();
  if (name == "open_cylinder") return makeOpenCylinder();
  std::string list;
  for (const auto& n : exampleNames()) list += (list.empty() ? "" : ", ") + n;
  throw MeshError("unknown example '" + name + "' (choose one of: " + list + ")");
}

}  // namespace fcql
