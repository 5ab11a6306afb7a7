#include "field/field_analysis.h"

#include "util/math_constants.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace fcql {
namespace {

constexpr double kQuarter = kPi / 2;

/// x minus the nearest multiple of π/2: the smallest turn between two directions of crosses.
double wrapQuarter(double x) { return x - std::round(x / kQuarter) * kQuarter; }

double signedAngle(const Vec3& from, const Vec3& to, const Vec3& normal) {
  return std::atan2(normal.dot(from.cross(to)), from.dot(to));
}

/// Chart angle of the field's u in a star face whose outgoing edge is at chart angle `start`.
double chartAngleOfU(const SurfaceMesh& mesh, const CrossField& field, const StarCorner& sc, double start) {
  Vec3 outgoing = mesh.edgeVector(sc.face, sc.corner);
  return start + signedAngle(outgoing, field.u[sc.face], mesh.faceNormal(sc.face));
}

/// A border edge: corner i of face f (from vertex i to vertex i + 1).
struct BorderEdge {
  int face, corner;
};

/// Border vertex v's outgoing border edge (to the next vertex along the border: its star's
/// first face) or its incoming one (from the previous vertex: its star's last face).
BorderEdge borderEdgeAt(const SurfaceMesh& mesh, int v, bool outgoing) {
  const auto& star = mesh.star(v);
  return outgoing ? BorderEdge{star.front().face, star.front().corner}
                  : BorderEdge{star.back().face, (star.back().corner + 2) % 3};
}

/// The angle, in the edge's face, from a border edge to the border's direction there
/// (SurfaceMesh::borderTangent), or nothing where the edge is that direction (no zigzag).
std::optional<double> zigzagTurn(const SurfaceMesh& mesh, BorderEdge b) {
  const Vec3 e = mesh.edgeVector(b.face, b.corner), t = mesh.borderTangent(b.face, b.corner);
  if (!(e.norm() > 0) || t == e) return std::nullopt;
  return signedAngle(e, t, mesh.faceNormal(b.face));
}

/// The angle, in the face's plane, from border edge b to the direction a border vertex's index
/// is counted against there: the border's direction where it differs from the edge's (a zigzag
/// border) and the field follows it more closely than the edge, else 0 (the edge's own
/// direction). A computed field follows the border's direction; a field read from a file may
/// follow the edges.
double borderReference(const SurfaceMesh& mesh, const CrossField& field, BorderEdge b) {
  const std::optional<double> turn = zigzagTurn(mesh, b);
  if (!turn) return 0;
  const Vec3& n = mesh.faceNormal(b.face);
  const double offEdge = std::abs(wrapQuarter(signedAngle(mesh.edgeVector(b.face, b.corner), field.u[b.face], n)));
  const double offBorder = std::abs(wrapQuarter(signedAngle(mesh.borderTangent(b.face, b.corner), field.u[b.face], n)));
  return offBorder < offEdge ? *turn : 0.0;
}

}  // namespace

StarChart computeStarChart(const SurfaceMesh& mesh, const CrossField& field, int v) {
  const auto& star = mesh.star(v);
  const int n = int(star.size());
  StarChart w;
  w.vertex = v;
  w.loop = !mesh.isBorderVertex(v);
  w.start.resize(n + 1);
  w.start[0] = 0;
  for (int k = 0; k < n; ++k) w.start[k + 1] = w.start[k] + mesh.cornerAngle(star[k].face, star[k].corner);
  w.theta = w.start[n];
  w.psi.resize(n);
  w.psi[0] = chartAngleOfU(mesh, field, star[0], 0);
  w.carried.assign(n, 0);
  for (int k = 0; k + 1 < n; ++k) {
    double phi = chartAngleOfU(mesh, field, star[k + 1], w.start[k + 1]);
    double d = wrapQuarter(phi - w.psi[k]);
    if (std::abs(d) < 1e-12) d = 0;  // numerically parallel crosses do not turn
    w.delta.push_back(d);
    w.psi[k + 1] = w.psi[k] + d;
    w.carried[k + 1] = ((int(std::lround((w.psi[k + 1] - phi) / kQuarter)) % 4) + 4) % 4;
  }
  w.flatScale = (w.loop ? 2 * kPi : kPi) / w.theta;
  if (!w.loop) {
    w.borderStart = borderReference(mesh, field, borderEdgeAt(mesh, v, true));
    w.borderEnd = borderReference(mesh, field, borderEdgeAt(mesh, v, false));
  }
  if (w.loop) {
    // Back to face 0, seen across the seam of the chart: its angles are shifted by Θ.
    double phi = w.psi[0] + w.theta;
    double d = wrapQuarter(phi - w.psi[n - 1]);
    w.delta.push_back(std::abs(d) < 1e-12 ? 0 : d);
  }
  return w;
}

double StarChart::chartAngleOf(const SurfaceMesh& mesh, int k, const Vec3& direction) const {
  const auto& sc = mesh.star(vertex)[k];
  return start[k] + signedAngle(mesh.edgeVector(sc.face, sc.corner), direction, mesh.faceNormal(sc.face));
}

namespace {

struct PortEvent {
  double t;
  int sign;   ///< +1: the field becomes radial going counter-clockwise; −1: a spurious touch
  int face;   ///< star index of the face holding the tangent
};

/// Levels L = m·π/2 with lo < L <= hi.
std::vector<double> levelsIn(double lo, double hi) {
  std::vector<double> out;
  for (double m = std::floor(lo / kQuarter); m * kQuarter <= hi; m += 1)
    if (m * kQuarter > lo) out.push_back(m * kQuarter);
  return out;
}

/// g(t) = ψ(t) − t is the angle between the field and the radial direction at chart angle t.
/// Ports are where g crosses a multiple of π/2 downward (see the header for the count). The
/// values of g at the ends of consecutive faces are chained (start of k+1 = end of k + δ_k) so
/// that a crossing exactly on an edge is counted once.
/// x moved exactly onto the nearest multiple of π/2 if it is within rounding noise of it, so
/// that a direction exactly along an edge (fields aligned to sharp edges and borders) is
/// counted once, on the same side of the comparison everywhere.
double snapToLevel(double x) {
  double level = std::round(x / kQuarter) * kQuarter;
  return std::abs(x - level) < 1e-9 ? level : x;
}

std::vector<PortEvent> portEvents(const StarChart& w) {
  const int n = int(w.psi.size());
  std::vector<PortEvent> events;
  double gStart = snapToLevel(w.psi[0] - w.start[0]);
  for (int k = 0; k < n; ++k) {
    double span = w.start[k + 1] - w.start[k];
    double gEnd = snapToLevel(gStart - span);
    for (double L : levelsIn(gEnd, gStart)) events.push_back({std::min(w.start[k] + (gStart - L), w.start[k + 1]), +1, k});
    bool hasJump = k + 1 < n || w.loop;
    if (!hasJump) {
      // Border vertex: a direction exactly along the last (border) edge is kept here and
      // removed later with the other border-aligned directions.
      if (std::fmod(gEnd, kQuarter) == 0) events.push_back({w.start[k + 1], +1, k});
      break;
    }
    const double gNext = snapToLevel(gEnd + w.delta[k]);
    int nextFace = (k + 1) % n;
    if (gNext > gEnd) {
      for (std::size_t c = levelsIn(gEnd, gNext).size(); c > 0; --c) events.push_back({w.start[k + 1], -1, nextFace});
    } else if (gNext < gEnd) {
      for (std::size_t c = levelsIn(gNext, gEnd).size(); c > 0; --c) events.push_back({w.start[k + 1], +1, nextFace});
    }
    gStart = gNext;
  }
  // A port found at the very end of a loop (chart angle Θ) is the same as one at angle 0.
  for (auto& e : events)
    if (w.loop && e.t >= w.theta) e.t -= w.theta, e.face = 0;
  return events;
}

/// Cancels each −1 event against the nearest +1 event (cyclically for a loop).
std::vector<PortEvent> cancelSpurious(std::vector<PortEvent> events, double theta, bool loop) {
  for (;;) {
    auto neg = std::find_if(events.begin(), events.end(), [](const PortEvent& e) { return e.sign < 0; });
    if (neg == events.end()) break;
    double best = 1e300;
    std::size_t bestIndex = events.size();
    for (std::size_t i = 0; i < events.size(); ++i) {
      if (events[i].sign < 0) continue;
      double d = std::abs(events[i].t - neg->t);
      if (loop) d = std::min(d, theta - d);
      if (d < best) best = d, bestIndex = i;
    }
    std::size_t negIndex = std::size_t(neg - events.begin());
    if (bestIndex == events.size()) {
      events.erase(events.begin() + negIndex);
      continue;
    }
    std::size_t a = std::max(bestIndex, negIndex), b = std::min(bestIndex, negIndex);
    events.erase(events.begin() + a);
    events.erase(events.begin() + b);
  }
  return events;
}

Port makePort(const SurfaceMesh& mesh, const CrossField& field, int v, const StarChart& w,
              const PortEvent& e) {
  const auto& sc = mesh.star(v)[e.face];
  Port p;
  p.vertex = v;
  p.face = sc.face;
  p.chartAngle = e.t;
  p.flatAngle = e.t * w.flatScale;
  Vec3 outgoing = mesh.edgeVector(sc.face, sc.corner).normalized();
  double within = std::clamp(e.t - w.start[e.face], 0.0, w.start[e.face + 1] - w.start[e.face]);
  p.tangent = rotateInPlane(outgoing, mesh.faceNormal(sc.face), within).normalized();
  double a = signedAngle(field.u[sc.face], p.tangent, mesh.faceNormal(sc.face));
  p.fieldDirection = ((int(std::lround(a / kQuarter)) % 4) + 4) % 4;
  return p;
}

int quartersFromTurn(double quarters) { return int(std::lround(quarters)); }

}  // namespace

std::vector<std::string> fieldWarnings(const SurfaceMesh& mesh, const FieldAnalysis& analysis) {
  std::vector<std::string> warnings;
  std::string named;
  int count = 0;
  for (const SingularVertex& s : analysis.singularities) {
    if (s.onBorder || s.indexQuarters < 3) continue;
    if (++count <= 3)
      named += std::string(named.empty() ? "" : ", ") + "vertex " + std::to_string(s.vertex) + " (index " +
               formatQuarterIndex(s.indexQuarters) + ", " + std::to_string(mesh.star(s.vertex).size()) + " triangles around it)";
  }
  if (count == 0) return warnings;
  warnings.push_back(std::to_string(count) + " singularit" + (count == 1 ? "y" : "ies") +
                     " of index 3/4 or more: " + named + (count > 3 ? ", ..." : "") +
                     ". Such a vertex leaves at most one separatrix, so the patch around it gets too few corners and "
                     "poor quads; refine the mesh around it (e.g. midpoint subdivision) so that the field can split it "
                     "into singularities of index 1/4");
  return warnings;
}

std::string formatQuarterIndex(int quarters) {
  if (quarters == 0) return "0";
  int num = quarters, den = 4;
  int g = std::gcd(std::abs(num), den);
  num /= g;
  den /= g;
  return den == 1 ? std::to_string(num) : std::to_string(num) + "/" + std::to_string(den);
}

Vec3 unfoldIntoFace(const SurfaceMesh& mesh, int f, int i, const Vec3& vectorInG) {
  int g = mesh.adjacentFace(f, i);
  if (g < 0) return vectorInG;
  Vec3 e = mesh.edgeVector(f, i).normalized();
  Vec3 perpF = mesh.faceNormal(f).cross(e);
  Vec3 perpG = mesh.faceNormal(g).cross(e);
  return e * vectorInG.dot(e) + perpF * vectorInG.dot(perpG);
}

double transportAngle(const SurfaceMesh& mesh, int f, int i, const Vec3& d, const Vec3& e) {
  return signedAngle(d, unfoldIntoFace(mesh, f, i, e), mesh.faceNormal(f));
}

int computeMatching(const SurfaceMesh& mesh, const CrossField& field, int f, int i) {
  if (mesh.adjacentFace(f, i) < 0) return 0;
  double a = transportAngle(mesh, f, i, field.u[f], field.u[mesh.adjacentFace(f, i)]);
  // Direction k of f is closest to direction 0 of g, so direction j of f goes to j − k.
  int k = int(std::lround(a / kQuarter));
  return ((-k) % 4 + 4) % 4;
}

namespace {

/// Border index ×4 of the vertex whose star chart is w: (π − Θ + Σδ − m_e + m_s)/(2π), m_s and
/// m_e the field's misalignment at the two border edges, each measured (to the nearest quarter)
/// against the border's direction there and then taken back to the edge's, so that a field
/// following a zigzag border's direction gives its zigzag vertices index 0.
int borderIndexQuarters(const StarChart& w) {
  const double sumDelta = std::accumulate(w.delta.begin(), w.delta.end(), 0.0);
  const double ms = wrapQuarter(w.psi.front() - w.borderStart) + w.borderStart;
  const double me = wrapQuarter(w.psi.back() - w.theta - w.borderEnd) + w.borderEnd;
  return quartersFromTurn(4 * (kPi - w.theta + sumDelta - me + ms) / (2 * kPi));
}

/// The ports of the vertex whose star chart is w (see computePorts).
std::vector<Port> portsOf(const SurfaceMesh& mesh, const CrossField& field, const StarChart& w) {
  std::vector<PortEvent> events = cancelSpurious(portEvents(w), w.theta, w.loop);
  std::sort(events.begin(), events.end(), [](const PortEvent& a, const PortEvent& b) { return a.t < b.t; });
  if (!w.loop) {
    // Keep only directions pointing into the surface: drop the ones along the border edges,
    // nearest to the two ends first, until the expected count 1 − 4·I_b remains.
    const int indexQuarters = borderIndexQuarters(w);
    int expected = std::max(0, 1 - indexQuarters);
    while (int(events.size()) > expected) {
      if (events.front().t <= w.theta - events.back().t) events.erase(events.begin());
      else events.pop_back();
    }
  }
  std::vector<Port> ports;
  for (const auto& e : events) ports.push_back(makePort(mesh, field, w.vertex, w, e));
  return ports;
}

}  // namespace

std::vector<Port> computePorts(const SurfaceMesh& mesh, const CrossField& field, int v) {
  if (mesh.star(v).empty()) return {};
  return portsOf(mesh, field, computeStarChart(mesh, field, v));
}

namespace {

/// Index ×4 of the vertex whose star chart is w.
int indexQuartersOf(const StarChart& w) {
  if (!w.loop) return borderIndexQuarters(w);
  double sumDelta = std::accumulate(w.delta.begin(), w.delta.end(), 0.0);
  return quartersFromTurn(4 * (1 + (sumDelta - w.theta) / (2 * kPi)));
}

void checkFieldMatchesMesh(const SurfaceMesh& mesh, const CrossField& field) {
  if (field.numFaces() != mesh.numFaces())
    throw FieldError("the field has " + std::to_string(field.numFaces()) + " faces but the mesh has " +
                     std::to_string(mesh.numFaces()));
}

}  // namespace

Vec3 rotateInPlane(const Vec3& v, const Vec3& axis, double angle) {
  return v * std::cos(angle) + axis.cross(v) * std::sin(angle);
}

int vertexIndexQuarters(const SurfaceMesh& mesh, const CrossField& field, int v) {
  return indexQuartersOf(computeStarChart(mesh, field, v));
}

std::vector<int> computeVertexIndices(const SurfaceMesh& mesh, const CrossField& field) {
  checkFieldMatchesMesh(mesh, field);
  std::vector<int> quarters(mesh.numVertices(), 0);
  for (int v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.star(v).empty()) quarters[v] = indexQuartersOf(computeStarChart(mesh, field, v));
  return quarters;
}

namespace {

constexpr double kMisplacedSlackDeg = 30;  ///< a border quarter is misplaced this far past a straight border

/// A border index of this sign does not fit a vertex with this much surface around it: a
/// convex quarter (served by one quad) on a reflex vertex, or a concave one on a convex vertex.
bool misplacedOnBorder(int quarters, double theta) {
  const double slack = kMisplacedSlackDeg * kPi / 180;
  return (quarters > 0 && theta > kPi + slack) || (quarters < 0 && theta < kPi - slack);
}

/// Where the border zigzags, the quarter of a border index falls on the convex or the reflex
/// vertex of a tooth, as the rounding goes. A misplaced one is moved to the neighbour across
/// its outgoing, else its incoming border edge, by counting that edge's index against its other
/// direction (the edge's own instead of the border's, or the reverse): the two vertices' sum,
/// and so every loop's, stays as it was. Kept only if neither vertex is then misplaced and
/// they hold no more quarters than before.
void placeBorderQuarters(const SurfaceMesh& mesh, std::unordered_map<int, StarChart>& charts, std::vector<int>& quarters) {
  std::vector<int> order;
  for (const auto& c : charts) order.push_back(c.first);
  std::sort(order.begin(), order.end());
  for (int v : order) {
    StarChart& cv = charts.at(v);
    if (!misplacedOnBorder(quarters[v], cv.theta)) continue;
    for (bool out : {true, false}) {
      const BorderEdge b = borderEdgeAt(mesh, v, out);
      const int w = out ? mesh.vertex(b.face, (b.corner + 1) % 3) : mesh.vertex(b.face, b.corner);
      const auto it = charts.find(w);
      if (it == charts.end() || w == v) continue;
      const std::optional<double> turn = zigzagTurn(mesh, b);
      if (!turn) continue;  // the edge is the border's direction
      StarChart& cw = it->second;
      double& atV = out ? cv.borderStart : cv.borderEnd;
      double& atW = out ? cw.borderEnd : cw.borderStart;
      const double was = atV, other = was != 0 ? 0.0 : *turn;
      atV = atW = other;
      const int qv = borderIndexQuarters(cv), qw = borderIndexQuarters(cw);
      if (!misplacedOnBorder(qv, cv.theta) && !misplacedOnBorder(qw, cw.theta) &&
          std::abs(qv) + std::abs(qw) <= std::abs(quarters[v]) + std::abs(quarters[w])) {
        quarters[v] = qv, quarters[w] = qw;
        break;
      }
      atV = atW = was;
    }
  }
}

}  // namespace

FieldAnalysis analyzeField(const SurfaceMesh& mesh, const CrossField& field) {
  checkFieldMatchesMesh(mesh, field);
  FieldAnalysis out;
  out.matching.assign(mesh.numFaces(), {0, 0, 0});
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i) out.matching[f][i] = computeMatching(mesh, field, f, i);
  out.vertexIndexQuarters.assign(mesh.numVertices(), 0);
  out.starAngle.assign(mesh.numVertices(), 0);
  std::unordered_map<int, StarChart> borderCharts;
  for (int v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.star(v).empty()) continue;
    StarChart w = computeStarChart(mesh, field, v);
    out.starAngle[v] = w.theta;
    out.vertexIndexQuarters[v] = indexQuartersOf(w);
    if (!w.loop) borderCharts.emplace(v, std::move(w));
  }
  placeBorderQuarters(mesh, borderCharts, out.vertexIndexQuarters);
  for (int v = 0; v < mesh.numVertices(); ++v) {
    if (out.vertexIndexQuarters[v] == 0) continue;
    SingularVertex s;
    s.vertex = v;
    s.indexQuarters = out.vertexIndexQuarters[v];
    const auto it = borderCharts.find(v);
    s.onBorder = it != borderCharts.end();
    s.ports = s.onBorder ? portsOf(mesh, field, it->second) : computePorts(mesh, field, v);
    out.singularities.push_back(std::move(s));
  }
  return out;
}

int FieldAnalysis::numInteriorSingularities() const {
  return int(std::count_if(singularities.begin(), singularities.end(),
                           [](const SingularVertex& s) { return !s.onBorder && s.indexQuarters != 0; }));
}
int FieldAnalysis::numBorderSingularities() const {
  return int(std::count_if(singularities.begin(), singularities.end(),
                           [](const SingularVertex& s) { return s.onBorder && s.indexQuarters != 0; }));
}
int FieldAnalysis::numPorts() const {
  int n = 0;
  for (const auto& s : singularities)
    if (s.indexQuarters != 0) n += int(s.ports.size());
  return n;
}
int FieldAnalysis::indexSumQuarters() const {
  return std::accumulate(vertexIndexQuarters.begin(), vertexIndexQuarters.end(), 0);
}
std::vector<std::pair<std::string, int>> FieldAnalysis::interiorHistogram() const {
  std::vector<std::pair<int, int>> counts;
  for (const auto& s : singularities) {
    if (s.onBorder || s.indexQuarters == 0) continue;
    auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == s.indexQuarters; });
    if (it == counts.end()) counts.push_back({s.indexQuarters, 1});
    else ++it->second;
  }
  std::sort(counts.begin(), counts.end());
  std::vector<std::pair<std::string, int>> out;
  for (const auto& c : counts) out.push_back({formatQuarterIndex(c.first), c.second});
  return out;
}

}  // namespace fcql
