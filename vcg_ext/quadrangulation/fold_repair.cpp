#include "quadrangulation/fold_repair.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace fcql {

namespace {

constexpr double kTarget = 0.2;   ///< ε: corners below it pay (ε − J)²
constexpr double kFloor = 0.02;   ///< a quad that was not folded may not fall below this (or its figure)
constexpr int kIterations = 100;  ///< descent steps per part

/// A connected part of the region: its vertices and the quads around them, sorted.
struct Part {
  std::vector<int> vertices;
  std::vector<int> quads;
};

/// Σ over the corners of quad q of max(0, ε − J)² + max(0, ε − α / area)², J the corner's
/// scaled Jacobian and α its area (e1 × e2)·n, both against normal[corner] (fixed, or with
/// `dynamic` the quad mesh's normals at the current positions), plus with `dynamic` the term
/// of J against the quad's own normal (as QuadJacobian measures). The area term keeps corners
/// from collapsing: J is not defined at a point and gives no gradient there.
double quadEnergy(const QuadMesh& mesh, int q, const std::vector<Vec3>& normal, double area, bool dynamic) {
  const auto& f = mesh.quads[q];
  const auto& P = mesh.positions;
  double e = 0;
  auto hinge = [](double x) { return x < kTarget ? (kTarget - x) * (kTarget - x) : 0.0; };
  Vec3 own = Vec3::Zero();
  if (dynamic) {
    own = (P[f[2]] - P[f[0]]).cross(P[f[3]] - P[f[1]]);
    if (own.norm() > 0) own.normalize();
  }
  // The four edges and their lengths once: corner i's edges are edge i and edge i + 3 reversed
  // (the same figures, to the bit, as each corner's own differences: a − b is −(b − a) exactly).
  std::array<Vec3, 4> edge;
  std::array<double, 4> length;
  for (int i = 0; i < 4; ++i) edge[i] = P[f[(i + 1) % 4]] - P[f[i]], length[i] = edge[i].norm();
  for (int i = 0; i < 4; ++i) {
    const Vec3& e1 = edge[i];
    const Vec3 e2 = -edge[(i + 3) % 4];
    const double l = length[i] * length[(i + 3) % 4];
    const Vec3 c = e1.cross(e2);
    const Vec3& n = normal[f[i]];
    const double a = c.dot(n);
    e += hinge(l > 0 ? a / l : -1) + hinge(a / area);
    if (dynamic) e += hinge(l > 0 ? c.dot(own) / l : -1);
  }
  return e;
}

/// The movable vertices within `rings` rings (along quad edges) of the corners of the quads
/// folded or at most `margin`, split into connected parts.
std::vector<Part> regionParts(const QuadMesh& mesh, const QuadJacobian& jacobian, const std::vector<char>& movable,
                              const std::vector<double>& figure, int rings, double margin) {
  const int nv = mesh.numVertices();
  auto neighbours = [&](int v, std::vector<int>& out) {
    out.clear();
    for (int q : jacobian.quadsAround(v)) {
      const auto& f = mesh.quads[q];
      const int k = int(std::find(f.begin(), f.end(), v) - f.begin());
      out.push_back(f[(k + 1) % 4]), out.push_back(f[(k + 3) % 4]);
    }
  };
  std::vector<char> inRegion(nv, 0);
  std::vector<int> frontier, grown, around;
  for (int q = 0; q < mesh.numQuads(); ++q)
    if (figure[q] <= margin)
      for (int v : mesh.quads[q])
        if (!inRegion[v]) inRegion[v] = 1, frontier.push_back(v);
  for (int ring = 0; ring < rings; ++ring) {
    grown.clear();
    for (int v : frontier) {
      neighbours(v, around);
      for (int w : around)
        if (!inRegion[w]) inRegion[w] = 1, grown.push_back(w);
    }
    frontier.swap(grown);
  }
  std::vector<Part> parts;
  std::vector<char> seen(nv, 0);
  for (int seed = 0; seed < nv; ++seed) {
    if (!inRegion[seed] || !movable[seed] || seen[seed]) continue;
    Part part;
    std::vector<int> stack{seed};
    seen[seed] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      part.vertices.push_back(v);
      neighbours(v, around);
      for (int w : around)
        if (inRegion[w] && movable[w] && !seen[w]) seen[w] = 1, stack.push_back(w);
    }
    for (int v : part.vertices)
      part.quads.insert(part.quads.end(), jacobian.quadsAround(v).begin(), jacobian.quadsAround(v).end());
    std::sort(part.quads.begin(), part.quads.end());
    part.quads.erase(std::unique(part.quads.begin(), part.quads.end()), part.quads.end());
    parts.push_back(std::move(part));
  }
  return parts;
}

/// The fixed normal at every corner of the part's quads: per quad the mean of the surface
/// normals at its corners, per vertex the mean over its quads.
void cornerNormals(const QuadMesh& mesh, const Part& part, const QuadJacobian& jacobian, const ClosestPointIndex& surface,
                   const std::vector<Vec3>& triangleNormals, std::vector<Vec3>& normal) {
  auto quadNormal = [&](int q) {
    Vec3 n = Vec3::Zero();
    for (int v : mesh.quads[q]) n += triangleNormals[surface.closest(mesh.positions[v]).triangle];
    return n;
  };
  for (int q : part.quads)
    for (int v : mesh.quads[q]) {
      Vec3 n = Vec3::Zero();
      for (int r : jacobian.quadsAround(v)) n += quadNormal(r);
      normal[v] = n.norm() > 0 ? Vec3(n.normalized()) : n;
    }
}

/// The mean length of the quad edges at vertex v.
double meanEdge(const QuadMesh& mesh, const QuadJacobian& jacobian, int v) {
  double sum = 0;
  int count = 0;
  for (int q : jacobian.quadsAround(v)) {
    const auto& f = mesh.quads[q];
    const int k = int(std::find(f.begin(), f.end(), v) - f.begin());
    sum += (mesh.positions[f[(k + 1) % 4]] - mesh.positions[v]).norm() + (mesh.positions[f[(k + 3) % 4]] - mesh.positions[v]).norm();
    count += 2;
  }
  return count > 0 ? sum / count : 0;
}

/// Gradient descent on E over the part's vertices (see the header); `place` puts a vertex back
/// on the surface or its feature line.
template <class Place>
void descend(QuadMesh& mesh, const Part& part, const QuadJacobian& jacobian, const Place& place,
             const std::vector<Vec3>& normal, bool dynamic) {
  auto& P = mesh.positions;
  const std::size_t m = part.vertices.size();
  // With dynamic normals, the mesh's own, kept by the jacobian as each vertex moves.
  if (dynamic) jacobian.track();
  const std::vector<Vec3>& cornerNormal = dynamic ? jacobian.normals() : normal;
  std::vector<int> quads = part.quads;
  if (dynamic) jacobian.dependents(part.vertices, quads);
  // Each quad's reference area: the square of the mean edge length at its corners.
  std::vector<double> area(quads.size(), 0);
  for (std::size_t k = 0; k < quads.size(); ++k) {
    for (int v : mesh.quads[quads[k]]) area[k] += meanEdge(mesh, jacobian, v) / 4;
    area[k] *= area[k];
  }
  std::vector<std::vector<std::size_t>> around(m);  // per vertex, indices into quads
  for (std::size_t i = 0; i < m; ++i) {
    std::vector<int> dependent;
    if (dynamic) jacobian.dependents(part.vertices[i], dependent);
    else dependent = jacobian.quadsAround(part.vertices[i]);
    for (int q : dependent)
      around[i].push_back(std::size_t(std::lower_bound(quads.begin(), quads.end(), q) - quads.begin()));
  }
  auto quadE = [&](std::size_t k) { return area[k] > 0 ? quadEnergy(mesh, quads[k], cornerNormal, area[k], dynamic) : 0.0; };
  std::size_t current = 0;
  auto local = [&](int) {
    double e = 0;
    for (std::size_t k : around[current]) e += quadE(k);
    return e;
  };
  auto total = [&] {
    double e = 0;
    for (std::size_t k = 0; k < quads.size(); ++k) e += quadE(k);
    return e;
  };
  std::vector<double> edge(m, 0);
  for (std::size_t i = 0; i < m; ++i) edge[i] = meanEdge(mesh, jacobian, part.vertices[i]);
  std::vector<Vec3> direction(m), start(m);
  double energy = total(), alpha = 0.25;
  // Stopped once ten steps gain less than 1% of the energy: the descent then crawls (it is
  // judged by the folds it removes, not by its energy), and a part that does not unfold is
  // tried again with more rings.
  double tenStepsAgo = energy;
  for (int it = 0; it < kIterations && energy > 1e-12 && alpha > 1e-4; ++it) {
    if (it > 0 && it % 10 == 0) {
      if (energy > 0.99 * tenStepsAgo) break;
      tenStepsAgo = energy;
    }
    double largest = 0;  // the largest move, in edge lengths, at alpha = 1
    for (std::size_t i = 0; i < m; ++i) {
      const int v = part.vertices[i];
      current = i;
      const Vec3 x = P[v], n = normal[v];
      direction[i] = Vec3::Zero();
      if (n.isZero() || !(edge[i] > 0)) continue;
      const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
      const double h = 1e-4 * edge[i];
      for (const Vec3& t : {t1, t2}) {
        P[v] = x + h * t;
        jacobian.moved(v);
        const double plus = local(v);
        P[v] = x - h * t;
        jacobian.moved(v);
        const double minus = local(v);
        direction[i] -= t * ((plus - minus) / (2 * h)) * edge[i] * edge[i];
      }
      P[v] = x;
      jacobian.moved(v);
      largest = std::max(largest, direction[i].norm() / edge[i]);
    }
    if (!(largest > 0)) break;
    const double cap = std::min(1.0, 0.5 / largest);  // no vertex moves more than half an edge
    for (std::size_t i = 0; i < m; ++i) start[i] = P[part.vertices[i]];
    for (;;) {
      for (std::size_t i = 0; i < m; ++i)
        P[part.vertices[i]] = place(part.vertices[i], start[i] + direction[i] * (alpha * cap));
      for (int v : part.vertices) jacobian.moved(v);
      const double tried = total();
      if (tried < energy) {
        energy = tried;
        alpha = std::min(1.0, 2 * alpha);
        break;
      }
      alpha /= 2;
      if (alpha <= 1e-4) {
        for (std::size_t i = 0; i < m; ++i) P[part.vertices[i]] = start[i];
        for (int v : part.vertices) jacobian.moved(v);
        break;
      }
    }
  }
  jacobian.untrack();
}

}  // namespace

int repairFolds(QuadMesh& quads, const ClosestPointIndex& surface, const ClosestPointIndex* features,
                const std::vector<Vec3>& triangleNormals, const std::vector<char>& moves, const QuadJacobian& jacobian,
                double margin) {
  margin = std::max(margin, 0.0);
  std::vector<char> movable(moves.size());
  for (std::size_t v = 0; v < moves.size(); ++v) movable[v] = moves[v] == kOnSurface || (features && moves[v] == kAlongFeature);
  std::vector<double> figure;
  jacobian.all(figure);
  // How bad: the folded quads, then those at or below the margin (folded ones included).
  const auto badness = [margin](const std::vector<double>& f) {
    return std::make_pair(int(std::count_if(f.begin(), f.end(), [](double j) { return j <= 0; })),
                          int(std::count_if(f.begin(), f.end(), [margin](double j) { return j <= margin; })));
  };
  const auto before = badness(figure);
  if (before.second == 0) return 0;
  std::vector<Vec3> normal(quads.positions.size(), Vec3::Zero());
  const auto place = [&](int v, const Vec3& p) {
    return (moves[v] == kAlongFeature ? features->closest(p) : surface.closest(p)).point;
  };
  std::vector<int> around;
  std::vector<double> was, now;
  for (int rings : {1, 2, 4, 8}) {
    for (const Part& part : regionParts(quads, jacobian, movable, figure, rings, margin)) {
      jacobian.dependents(part.vertices, around);
      jacobian.values(around, was);
      if (std::none_of(was.begin(), was.end(), [margin](double j) { return j <= margin; })) continue;
      std::vector<Vec3> kept;
      for (int v : part.vertices) kept.push_back(quads.positions[v]);
      cornerNormals(quads, part, jacobian, surface, triangleNormals, normal);
      descend(quads, part, jacobian, place, normal, false);
      descend(quads, part, jacobian, place, normal, true);
      jacobian.values(around, now);
      bool keep = badness(now) < badness(was);
      for (std::size_t i = 0; i < around.size() && keep; ++i)
        keep = was[i] <= 0 || now[i] >= std::min(was[i], kFloor);
      if (!keep)
        for (std::size_t i = 0; i < part.vertices.size(); ++i) quads.positions[part.vertices[i]] = kept[i];
    }
    jacobian.all(figure);
    if (badness(figure).second == 0) break;
  }
  const auto after = badness(figure);
  return margin > 0 ? before.second - after.second : before.first - after.first;
}

}  // namespace fcql
