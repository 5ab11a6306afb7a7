#include "tracing/geodesic_graph.h"

#include "util/math_constants.h"
#include "util/worker_threads.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace fcql {
namespace {

const double kCos45 = std::cos(kPi / 4) - 1e-12;

bool withinSector(const Vec3& w, const Vec3& d) {
  double len = w.norm();
  return len > 0 && d.dot(w) >= kCos45 * len;
}

int mod4(int x) { return ((x % 4) + 4) % 4; }

/// What the builder needs to know about one singular vertex.
struct SingularStar {
  StarChart chart;
  std::unordered_map<int, int> starIndexOfFace;
  int seamShift = 0;  ///< direction index shift when the chart crosses its seam forward
};

}  // namespace

double anisotropicLength(const Vec3& w, const Vec3& d, double alpha) {
  double len = w.norm();
  if (len <= 0) return 0;
  double c = std::clamp(d.dot(w) / len, -1.0, 1.0);
  return len * (1.0 + alpha * std::acos(c) / (kPi / 4));
}

void TracingParameters::validate() const {
  if (!(alpha >= 0) || !std::isfinite(alpha))
    throw std::invalid_argument("alpha must be a finite number >= 0");
  if (k < 1) throw std::invalid_argument("k must be at least 1");
  if (!(phiDeg >= 1 && phiDeg <= 45)) throw std::invalid_argument("phi must be between 1 and 45 degrees");
  if (threads < 0) throw std::invalid_argument("threads must be >= 0");
}

class GeodesicGraphBuilder {
public:
  GeodesicGraphBuilder(GeodesicGraph& g, GeodesicGraph::SinkDistances sinkDistances)
      : g_(g), mesh_(*g.mesh_), field_(*g.field_), analysis_(*g.analysis_), sinkDistances_(sinkDistances) {}

  void build() {
    combFaces();
    buildPorts();
    const long long slots = 8LL * g_.sampling_.numSamples() + 2LL * g_.ports_.size();
    if (slots >= (1LL << 30))
      throw std::runtime_error("graph G would have " + std::to_string(slots) +
                               " node slots, more than it can hold (2^30): use a larger phi");
    const int numSlots = int(slots);
    const int threads = workerThreadCount(g_.params_.threads, mesh_.numFaces());
    // Every edge node's arcs come from the one face it continues into (a source node's from
    // its port), so the faces can be shared out among the threads, no node shared: a first
    // pass counts each node's arcs, a second computes their weights and writes them in place.
    auto forEachFace = [&](auto&& emit) {
      std::atomic<int> nextChunk{0};
      const int chunk = 256;
      runOnWorkerThreads(threads, [&](int) {
        for (int first; (first = nextChunk.fetch_add(chunk)) < mesh_.numFaces();)
          for (int f = first, end = std::min(mesh_.numFaces(), first + chunk); f < end; ++f) faceArcs(f, emit);
      });
      for (int p = 0; p < int(g_.ports_.size()); ++p) sourceArcs(p, emit);
    };
    std::vector<std::uint32_t>& begin = g_.arcBegin_;
    begin.assign(numSlots + 1, 0);
    forEachFace([&](int from, int, const auto&) { ++begin[from + 1]; });
    long long total = 0;
    for (int i = 0; i < numSlots; ++i) total += begin[i + 1];
    if (total >= (1LL << 32))
      throw std::runtime_error("graph G would have " + std::to_string(total) +
                               " arcs, more than it can hold (2^32): use a larger phi");
    for (int i = 0; i < numSlots; ++i) begin[i + 1] += begin[i];
    g_.arcs_.resize(begin[numSlots]);
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    std::vector<unsigned char> live(numSlots, 0);
    forEachFace([&](int from, int target, const auto& weight) {
      g_.arcs_[fill[from]++] = {target, weight()};
      __atomic_store_n(&live[from], 1, __ATOMIC_RELAXED);
      __atomic_store_n(&live[target < 0 ? ~target : target], 1, __ATOMIC_RELAXED);
    });
    // Within a node, arcs keep a deterministic order (by target), whatever the threads.
    const int block = 1 << 14;
    std::atomic<int> nextBlock{0};
    runOnWorkerThreads(threads, [&](int) {
      for (int first; (first = nextBlock.fetch_add(block)) < numSlots;)
        for (int n = first; n < std::min(numSlots, first + block); ++n)
          std::sort(g_.arcs_.begin() + begin[n], g_.arcs_.begin() + begin[n + 1],
                    [](const GeodesicGraph::Arc& a, const GeodesicGraph::Arc& b) {
                      return a.target != b.target ? a.target < b.target : a.weight < b.weight;
                    });
    });
    g_.numLiveNodes_ = std::count(live.begin(), live.end(), 1);
    // Searches for sinks run on weights reduced by the distance to the nearest sink (see
    // sink_distance.h); arcs into nodes from which no sink can be reached (border terminals,
    // edge nodes whose direction, carried into the next triangle, points back across the edge,
    // and whatever leads only there) are complemented instead, after the sort, so that the
    // order of the arcs does not change. Without the distances (SinkDistances::Skipped), h is
    // 0 wherever a path can go on (a potential too, if a weak one): the weights stay Eq. 1 and
    // only the arcs into border terminals and nodes without arcs out are complemented.
    std::vector<float>& h = g_.sinkDistance_;
    if (sinkDistances_ == GeodesicGraph::SinkDistances::Computed) {
      std::vector<int> sinks;
      for (int p = 0; p < int(g_.ports_.size()); ++p) sinks.push_back(g_.sinkNode(p));
      h = distancesToNearestTarget(begin, g_.arcs_, sinks, std::min(threads, 4));
    } else {
      h.assign(numSlots, 0.0f);
      for (int n = 0; n < numSlots; ++n)
        if (!g_.isPortNode(n) && begin[n] == begin[n + 1]) h[n] = std::numeric_limits<float>::infinity();
    }
    const int nodeRange = std::max(1, (numSlots + threads - 1) / threads);
    runOnWorkerThreads(threads, [&](int t) {
      const int from = std::min(numSlots, t * nodeRange), to = std::min(numSlots, from + nodeRange);
      for (int u = from; u < to; ++u)
        for (auto a = g_.arcs_.begin() + begin[u], end = g_.arcs_.begin() + begin[u + 1]; a != end; ++a) {
          const int v = GeodesicGraph::targetNode(*a);
          const double reduced = double(a->weight) + double(h[v]) - double(h[u]);
          if (std::isinf(h[v]) || std::isnan(reduced)) a->target = ~v;  // NaN: a broken move, never taken
          else a->weight = float(std::max(0.0, reduced));
        }
    });
  }

private:
  /// Rotations r(t) along a breadth-first spanning tree of each connected component, so that
  /// the matching across tree edges, m(t, i) + r(t) − r(t'), is zero.
  void combFaces() {
    const int nf = mesh_.numFaces();
    std::vector<int>& r = g_.faceRotation_;
    r.assign(nf, -1);
    std::vector<int> queue;
    queue.reserve(nf);
    for (int root = 0; root < nf; ++root) {
      if (r[root] >= 0) continue;
      r[root] = 0;
      queue.assign(1, root);
      for (std::size_t h = 0; h < queue.size(); ++h) {
        int f = queue[h];
        for (int i = 0; i < 3; ++i) {
          int g = mesh_.adjacentFace(f, i);
          if (g < 0 || r[g] >= 0) continue;
          r[g] = mod4(r[f] + analysis_.matching[f][i]);
          queue.push_back(g);
        }
      }
    }
  }

  int combed(int f, int dirInF) const { return mod4(dirInF - g_.faceRotation_[f]); }

  void buildPorts() {
    const auto& sings = analysis_.singularities;
    g_.firstPort_.assign(sings.size() + 1, 0);
    stars_.resize(sings.size());
    for (int s = 0; s < int(sings.size()); ++s) {
      const SingularVertex& sv = sings[s];
      g_.firstPort_[s] = int(g_.ports_.size());
      singularityOfVertex_[sv.vertex] = s;
      SingularStar& star = stars_[s];
      star.chart = computeStarChart(mesh_, field_, sv.vertex);
      const auto& corners = mesh_.star(sv.vertex);
      for (int k = 0; k < int(corners.size()); ++k) star.starIndexOfFace[corners[k].face] = k;
      if (star.chart.loop) {
        const int n = int(corners.size());
        double psiN = star.chart.psi[n - 1] + star.chart.delta[n - 1];
        star.seamShift = mod4(int(std::lround((psiN - star.chart.theta - star.chart.psi[0]) / (kPi / 2))));
      }
      const int m = int(sv.ports.size());
      const double full = star.chart.loop ? 2 * kPi : kPi;
      for (int i = 0; i < m; ++i) {
        PortNode pn;
        pn.singularity = s;
        pn.portIndex = i;
        pn.vertex = sv.vertex;
        pn.flatAngle = sv.ports[i].flatAngle;
        if (star.chart.loop) {
          // Neighbouring ports around the circle (the port itself, a full turn away, if alone).
          double prev = i > 0 ? sv.ports[i - 1].flatAngle : sv.ports[m - 1].flatAngle - 2 * kPi;
          double next = i + 1 < m ? sv.ports[i + 1].flatAngle : sv.ports[0].flatAngle + 2 * kPi;
          pn.sectorLow = 0.5 * (prev + pn.flatAngle);
          pn.sectorHigh = 0.5 * (pn.flatAngle + next);
        } else {
          pn.sectorLow = i == 0 ? 0.0 : 0.5 * (sv.ports[i - 1].flatAngle + pn.flatAngle);
          pn.sectorHigh = i == m - 1 ? full : 0.5 * (pn.flatAngle + sv.ports[i + 1].flatAngle);
        }
        g_.ports_.push_back(pn);
      }
    }
    g_.firstPort_[sings.size()] = int(g_.ports_.size());
    g_.portBase_ = g_.sampling_.numSamples() * 8;
  }

  /// Flattened angle of point q around singular vertex of star s, seen in star face k,
  /// unwrapped to lie nearest the angle `near`.
  double flatAngle(int s, int k, const Vec3& q, double near) const {
    const SingularStar& star = stars_[s];
    double x = star.chart.chartAngleOf(mesh_, k, q - mesh_.position(analysis_.singularities[s].vertex)) *
               star.chart.flatScale;
    if (star.chart.loop) x += 2 * kPi * std::round((near - x) / (2 * kPi));
    return x;
  }

  /// Direction index, in star face k, of port p's direction carried there inside p's sector;
  /// `unwrapped` is the flattened angle of the destination (unwrapped around the port).
  int carriedPortDirection(int p, int k, double unwrapped) const {
    const PortNode& pn = g_.ports_[p];
    const SingularStar& star = stars_[pn.singularity];
    const Port& port = analysis_.singularities[pn.singularity].ports[pn.portIndex];
    int kp = star.starIndexOfFace.at(port.face);
    int relative = port.fieldDirection - star.chart.carried[kp];
    int dir = star.chart.carried[k] + relative;
    if (star.chart.loop) {
      if (unwrapped >= 2 * kPi) dir += star.seamShift;
      else if (unwrapped < 0) dir -= star.seamShift;
    }
    return mod4(dir);
  }

  /// The port of singularity s whose sector holds point q of star face k; −1 if none. Also
  /// returns the unwrapped flattened angle.
  int portAt(int s, int k, const Vec3& q, double* unwrapped) const {
    for (int p = g_.firstPort_[s]; p < g_.firstPort_[s + 1]; ++p) {
      const PortNode& pn = g_.ports_[p];
      double x = flatAngle(s, k, q, pn.flatAngle);
      if (x >= pn.sectorLow && x < pn.sectorHigh) {
        *unwrapped = x;
        return p;
      }
    }
    return -1;
  }

  /// The node at sample q entering the face across local edge `i` of face f, direction dirInF
  /// of f carried across, as stored in an arc: the border terminal (complemented) if there is
  /// no face.
  int nodeAcross(int f, int i, int q, int dirInF) const {
    int g = mesh_.adjacentFace(f, i);
    if (g < 0) return ~g_.edgeNode(q, 1, combed(f, dirInF));
    int e = mesh_.edgeId(f, i);
    int dir = mod4(dirInF + analysis_.matching[f][i]);
    return g_.edgeNode(q, g_.sampling_.sideOf(e, g), combed(g, dir));
  }

  /// A path in direction `dir` of face f may end on the border edge `i` of f only if it meets
  /// the border transversally, as separatrices meet each other: the direction lies closer to
  /// the edge's normal than to the edge (within 45° of the normal). A direction closer to the
  /// edge runs along the border, which is itself a field line there, and reaching the border
  /// at a grazing angle would cut off a sliver patch with a spurious corner.
  bool meetsBorderTangentially(int f, int i, const Vec3& dir) const {
    const Vec3 edge = mesh_.position(mesh_.vertex(f, (i + 1) % 3)) - mesh_.position(mesh_.vertex(f, i));
    const double len = edge.norm() * dir.norm();
    return !(len > 0) || std::abs(edge.dot(dir)) > kCos45 * len;
  }

  /// Calls emit(from, target, weight) for each arc out of the nodes continuing into face f,
  /// `weight` a function computing its Eq. 1 (a first pass only counts).
  template <class Emit>
  void faceArcs(int f, Emit& emit) const {
    const EdgeSampling& es = g_.sampling_;
    const double alpha = g_.params_.alpha;
    Vec3 dirs[4];
    for (int j = 0; j < 4; ++j) dirs[j] = field_.direction(mesh_, f, j);
    // Per local edge: bit j set if direction j may not end on it (a border edge it grazes).
    int grazing[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
      if (mesh_.adjacentFace(f, i) < 0)
        for (int j = 0; j < 4; ++j)
          if (meetsBorderTangentially(f, i, dirs[j])) grazing[i] |= 1 << j;
    for (int a = 0; a < 3; ++a) {
      int ea = mesh_.edgeId(f, a);
      int sideA = es.sideOf(ea, f);
      int opposite = mesh_.vertex(f, (a + 2) % 3);
      auto sing = singularityOfVertex_.find(opposite);
      for (int qa = es.firstSample[ea]; qa < es.firstSample[ea] + es.sampleCount[ea]; ++qa) {
        const Vec3& from = es.samplePosition[qa];
        // Moves to the samples of the two other edges: directions j and j + 2 are opposite,
        // so one dot product per axis tells which sector (if any) holds the move.
        for (int b = 0; b < 3; ++b) {
          if (b == a) continue;
          int eb = mesh_.edgeId(f, b);
          for (int qb = es.firstSample[eb]; qb < es.firstSample[eb] + es.sampleCount[eb]; ++qb) {
            const Vec3 w = es.samplePosition[qb] - from;
            const double len = w.norm();
            if (!(len > 0)) continue;
            const double along[2] = {dirs[0].dot(w), dirs[1].dot(w)};
            for (int j = 0; j < 4; ++j) {
              const double dot = j < 2 ? along[j] : -along[j - 2];
              if (dot < kCos45 * len || (grazing[b] >> j & 1)) continue;
              emit(g_.edgeNode(qa, sideA, combed(f, j)), nodeAcross(f, b, qb, j),
                   [&] { return float(anisotropicLength(w, dirs[j], alpha)); });
            }
          }
        }
        // Sinks of the ports of the singular vertex opposite this edge.
        if (sing == singularityOfVertex_.end()) continue;
        const Vec3 w = mesh_.position(opposite) - from;
        for (int j = 0; j < 4; ++j) {
          if (!withinSector(w, dirs[j])) continue;
          int s = sing->second;
          int k = stars_[s].starIndexOfFace.at(f);
          double unwrapped = 0;
          int p = portAt(s, k, from, &unwrapped);
          if (p < 0 || mod4(carriedPortDirection(p, k, unwrapped) + 2) != j) continue;
          emit(g_.edgeNode(qa, sideA, combed(f, j)), g_.sinkNode(p), [&] { return float(anisotropicLength(w, dirs[j], alpha)); });
        }
      }
    }
  }

  /// The same for the arcs out of port p's source node.
  template <class Emit>
  void sourceArcs(int p, Emit& emit) const {
    const PortNode& pn = g_.ports_[p];
    const int s = pn.singularity;
    const Vec3& apex = mesh_.position(pn.vertex);
    const auto& corners = mesh_.star(pn.vertex);
    const EdgeSampling& es = g_.sampling_;
    for (int k = 0; k < int(corners.size()); ++k) {
      int f = corners[k].face;
      int i = (corners[k].corner + 1) % 3;  // the edge opposite the vertex
      int e = mesh_.edgeId(f, i);
      for (int q = es.firstSample[e]; q < es.firstSample[e] + es.sampleCount[e]; ++q) {
        const Vec3& to = es.samplePosition[q];
        double x = flatAngle(s, k, to, pn.flatAngle);
        if (!(x >= pn.sectorLow && x < pn.sectorHigh)) continue;
        int dir = carriedPortDirection(p, k, x);
        Vec3 d = field_.direction(mesh_, f, dir);
        Vec3 w = to - apex;
        if (!withinSector(w, d)) continue;
        if (mesh_.adjacentFace(f, i) < 0 && meetsBorderTangentially(f, i, d)) continue;
        emit(g_.sourceNode(p), nodeAcross(f, i, q, dir), [&] { return float(anisotropicLength(w, d, g_.params_.alpha)); });
      }
    }
  }

  GeodesicGraph& g_;
  const SurfaceMesh& mesh_;
  const CrossField& field_;
  const FieldAnalysis& analysis_;
  std::vector<SingularStar> stars_;
  std::unordered_map<int, int> singularityOfVertex_;
  GeodesicGraph::SinkDistances sinkDistances_;
};

GeodesicGraph::GeodesicGraph(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                             const TracingParameters& params, SinkDistances sinkDistances)
    : mesh_(&mesh), field_(&field), analysis_(&analysis), params_(params) {
  params_.validate();
  if (field.numFaces() != mesh.numFaces() || int(analysis.matching.size()) != mesh.numFaces())
    throw std::invalid_argument("the field or its analysis does not belong to this mesh");
  sampling_ = sampleEdges(mesh, params_.phiDeg * kPi / 180.0, 48, params_.threads);
  GeodesicGraphBuilder(*this, sinkDistances).build();
}

GeodesicGraph::ArcFrame GeodesicGraph::arcFrame(int from, int to) const {
  if (!isPortNode(from)) return {nodeFace(from), nodeDirection(from)};
  const int e = sampling_.sampleEdge[nodeSample(to)];
  if (isBorderTerminal(to)) return {sampling_.edgeFace[e][0], nodeDirection(to)};
  // The target continues into the face across its edge, its direction carried there.
  const int side = 1 - nodeSide(to);
  const int face = sampling_.edgeFace[e][side];
  return {face, mod4(nodeDirection(to) - analysis_->matching[face][sampling_.edgeLocal[e][side]])};
}

float GeodesicGraph::arcLength(int from, int to) const {
  auto position = [&](int node) -> const Vec3& {
    return isPortNode(node) ? mesh_->position(ports_[portOfNode(node)].vertex) : sampling_.samplePosition[nodeSample(node)];
  };
  const ArcFrame frame = arcFrame(from, to);
  return float(anisotropicLength(position(to) - position(from), field_->direction(*mesh_, frame.face, frame.direction), params_.alpha));
}

int GeodesicGraph::portAtFlatAngle(int singularity, double flat) const {
  for (int p = firstPort_[singularity]; p < firstPort_[singularity + 1]; ++p) {
    const PortNode& pn = ports_[p];
    double x = flat;
    if (mesh_->star(pn.vertex).empty() || !mesh_->isBorderVertex(pn.vertex))
      x += 2 * kPi * std::round((pn.flatAngle - x) / (2 * kPi));
    if (x >= pn.sectorLow && x < pn.sectorHigh) return p;
  }
  return -1;
}

}  // namespace fcql
