#include "tracing/separatrix_tracer.h"

#include "util/worker_threads.h"
#include "util/radix_heap.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace fcql {
namespace {

constexpr double kEps = 1e-9;

/// Local index, in face f, of the edge carrying sample q.
int localEdgeOfSample(const EdgeSampling& es, int q, int f) {
  int e = es.sampleEdge[q];
  return es.edgeFace[e][0] == f ? es.edgeLocal[e][0] : es.edgeLocal[e][1];
}

int cornerOf(const SurfaceMesh& mesh, int f, int v) {
  for (int c = 0; c < 3; ++c)
    if (mesh.vertex(f, c) == v) return c;
  return -1;
}

/// The straight piece of a path that arc u → v of G stands for: face, direction, chord.
PathSegment arcSegment(const GeodesicGraph& g, int u, int v) {
  const SurfaceMesh& mesh = g.mesh();
  const EdgeSampling& es = g.sampling();
  PathSegment seg;
  const GeodesicGraph::ArcFrame frame = g.arcFrame(u, v);
  seg.face = frame.face;
  seg.direction = frame.direction;
  if (g.isPortNode(u)) {  // source arc: from the singular vertex to the sample of v
    const int q = g.nodeSample(v);
    seg.from = cornerCoordinate(cornerOf(mesh, seg.face, g.ports()[g.portOfNode(u)].vertex));
    seg.to = edgeCoordinate(localEdgeOfSample(es, q, seg.face), es.paramInFace(q, seg.face));
    return seg;
  }
  const int qa = g.nodeSample(u);
  seg.from = edgeCoordinate(localEdgeOfSample(es, qa, seg.face), es.paramInFace(qa, seg.face));
  if (g.isPortNode(v)) {
    seg.to = cornerCoordinate(cornerOf(mesh, seg.face, g.ports()[g.portOfNode(v)].vertex));
  } else {
    const int qb = g.nodeSample(v);
    seg.to = edgeCoordinate(localEdgeOfSample(es, qb, seg.face), es.paramInFace(qb, seg.face));
  }
  return seg;
}

Vec3 nodePosition(const GeodesicGraph& g, int node) {
  if (g.isPortNode(node)) return g.mesh().position(g.ports()[g.portOfNode(node)].vertex);
  return g.sampling().samplePosition[g.nodeSample(node)];
}

PathPoint nodePoint(const GeodesicGraph& g, int node) {
  PathPoint p;
  if (g.isPortNode(node)) {
    p.kind = PathPoint::Vertex;
    p.id = g.ports()[g.portOfNode(node)].vertex;
  } else {
    p.kind = PathPoint::Sample;
    p.id = g.nodeSample(node);
  }
  p.position = nodePosition(g, node);
  return p;
}

/// Intersection of segments [a, b] and [c, d] lying in one plane (closest point on [a, b]).
Vec3 intersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Vec3 r = b - a, s = d - c;
  Vec3 n = r.cross(s);
  double nn = n.squaredNorm();
  if (nn < 1e-300) return 0.5 * (a + b);
  double t = (c - a).cross(s).dot(n) / nn;
  return a + r * std::clamp(t, 0.0, 1.0);
}

/// Whether segment [a0, a1] meets barrier chord c within the part of it the path really
/// covers: a chord that ends inside its triangle (at a t-junction) is only a barrier up to that
/// end, while its edge coordinates describe the whole straight move.
bool meetsBeforeEnd(const Vec3& a0, const Vec3& a1, const BarrierSet::Chord& c) {
  const Vec3 r = c.b - c.a, s = a1 - a0;
  const double length2 = r.squaredNorm();
  if (!(length2 > 0)) return false;  // the path ended where the chord began
  const Vec3 n = r.cross(s);
  const double nn = n.squaredNorm();
  double t;  // parameter along c.a → c.b of the meeting point
  if (nn <= 1e-24 * length2 * s.squaredNorm()) {
    // Parallel (overlapping, since the chords are related): where a0 or a1 falls on c.
    t = std::max((a0 - c.a).dot(r), (a1 - c.a).dot(r)) / length2;
    const double low = std::min((a0 - c.a).dot(r), (a1 - c.a).dot(r)) / length2;
    if (c.endsInsideA && t < 0) return false;
    if (c.endsInsideB && low > 1) return false;
    return true;
  }
  t = (a0 - c.a).cross(s).dot(n) / nn;
  const double tolerance = 1e-9;
  if (c.endsInsideA && t < -tolerance) return false;
  if (c.endsInsideB && t > 1 + tolerance) return false;
  return true;
}

}  // namespace

BarrierContact barrierContact(const PathSegment& segment, const Vec3& from, const Vec3& to,
                              const BarrierSet::Chord& chord) {
  BarrierContact contact;
  const ChordRelation r = relateChords(segment.from, segment.to, chord.from, chord.to);
  if (r == ChordRelation::Disjoint) return contact;
  if ((chord.endsInsideA || chord.endsInsideB) && !meetsBeforeEnd(from, to, chord)) return contact;
  contact.relation = r;
  contact.tangential = (segment.direction - chord.direction) % 2 == 0;
  return contact;
}

namespace {

struct Terminal {
  int pred;
  int barrier;
  Vec3 point;
  PathSegment segment;
};

class Search {
public:
  explicit Search(const GeodesicGraph& g) : g_(g), state_(g.numNodeSlots()) { heap_.resize(state_.size()); }

  std::vector<TracedPath> run(int port, const SearchOptions& opt) {
    reset();
    std::vector<TracedPath> found;
    terminals_.clear();
    RadixHeap& heap = heap_;
    heap.clear();
    const int source = g_.sourceNode(port);
    setDist(source, 0, -1);
    heap.push({0.0f, source});
    const BarrierSet* barriers = opt.barriers && !opt.barriers->empty() ? opt.barriers : nullptr;
    const double alpha = g_.parameters().alpha;
    // Searches for sinks run on the reduced weights (sink_distance.h): a path's reduced length
    // is its length minus the source's distance to the nearest sink (a sink's own is 0).
    // T-junction searches end at crossings and at the border as well, so they run on Eq. 1.
    const bool reduced = !opt.tJunctionMode && !opt.borderEnds;
    const double sourceOffset = reduced ? g_.sinkDistance(source) : 0.0;
    int sinks = 0;
    // Once every sink the search may stop at has been found, nothing more can be: stop there
    // instead of exhausting the graph (the solving cycle's searches allow only the few ports
    // still dangling, often fewer than k).
    int allowedSinks = 0;
    for (int p = 0; p < int(g_.ports().size()); ++p)
      allowedSinks += p != port && (opt.sinkAllowed.empty() || opt.sinkAllowed[p] != 0);
    const int wanted = std::min(opt.maxSinks, allowedSinks);
    if (wanted == 0 && !opt.tJunctionMode && !opt.borderEnds) return found;
    while (!heap.empty()) {
      auto [d, u] = heap.pop();
      // Keys are popped in increasing order, and a path through u is at least its key plus the
      // source's offset long (the reduced weights' potential is a lower bound).
      if (double(d) + sourceOffset > opt.maxLength) break;
      if (u < 0) {  // a t-junction terminal: the path stops on a barrier
        found.push_back(buildTerminalPath(port, terminals_[-1 - u], d));
        break;
      }
      // A node is in the heap once, with its current distance: popped, it is settled.
      if (g_.isSinkNode(u)) {
        int p = g_.portOfNode(u);
        bool allowed = p != port && (opt.sinkAllowed.empty() || opt.sinkAllowed[p] != 0);
        if (!allowed) continue;
        found.push_back(buildPath(port, u, double(d) + sourceOffset, TracedPath::Sink));
        found.back().sinkPort = p;
        if (opt.tJunctionMode || opt.borderEnds || ++sinks >= wanted) break;
        continue;
      }
      if ((opt.tJunctionMode || opt.borderEnds) && g_.isBorderTerminal(u)) {  // only these searches enter them
        found.push_back(buildPath(port, u, d, TracedPath::Border));
        break;
      }
      // The search waits on memory, not arithmetic: ask for the targets' records (and where
      // their arcs are) before the relaxations, whose branches would otherwise take the
      // cache misses one at a time.
      for (const GeodesicGraph::Arc *a = g_.arcsBegin(u), *end = g_.arcsEnd(u); a != end; ++a) {
        if (GeodesicGraph::isDeadEnd(*a) && !opt.tJunctionMode && !opt.borderEnds) continue;
        const int v = GeodesicGraph::targetNode(*a);
        __builtin_prefetch(&state_[v]);
        g_.prefetchArcRange(v);
      }
      for (const GeodesicGraph::Arc *a = g_.arcsBegin(u), *end = g_.arcsEnd(u); a != end; ++a) {
        int v = a->target;
        if (GeodesicGraph::isDeadEnd(*a)) {
          if (!opt.tJunctionMode && !opt.borderEnds) continue;  // paths reaching the border or a dead end are dropped
          v = ~v;
        }
        const float nd = d + (reduced ? a->weight : g_.arcLength(u, v));
        if (barriers) {
          // Nodes at distance <= d are settled (ties aside): nothing to test there.
          if (state_[v].dist <= d) continue;
          // The move crosses u's face (for a source: the face behind v's edge); most faces
          // hold no barrier, and then the move needs no geometry.
          const int face = g_.isPortNode(u) ? -1 : g_.nodeFace(u);
          if (face < 0 || !barriers->inFace(face).empty()) {
            PathSegment seg = arcSegment(g_, u, v);
            const auto& chords = barriers->inFace(seg.face);
            bool blocked = false;
            int crossing = -1;
            double crossingDistance = std::numeric_limits<double>::infinity();
            Vec3 crossingPoint = Vec3::Zero();
            Vec3 a0 = nodePosition(g_, u), a1 = nodePosition(g_, v);
            for (const auto& c : chords) {
              const BarrierContact contact = barrierContact(seg, a0, a1, c);
              const ChordRelation r = contact.relation;
              if (r == ChordRelation::Disjoint) continue;
              if (contact.tangential) {
                blocked = true;  // never crossed
                break;
              }
              if (!opt.tJunctionMode) continue;  // orthogonal crossings are allowed
              Vec3 x = r == ChordRelation::Crossing ? intersect(a0, a1, c.a, c.b) : (r == ChordRelation::Touching ? touchingPoint(a0, a1, c) : a0);
              double dx = (x - a0).norm();
              if (dx < crossingDistance) crossingDistance = dx, crossing = c.id, crossingPoint = x;
            }
            if (blocked) continue;
            if (crossing >= 0) {
              Vec3 dir = g_.field().direction(g_.mesh(), seg.face, seg.direction);
              double td = d + anisotropicLength(crossingPoint - a0, dir, alpha);
              terminals_.push_back({u, crossing, crossingPoint, seg});
              heap.push({float(td), -int(terminals_.size())});
              continue;
            }
          }
        }
        if (nd < state_[v].dist) {
          const float old = state_[v].dist;
          setDist(v, nd, u);
          if (std::isinf(old)) {
            heap.push({nd, v});
            __builtin_prefetch(g_.arcsBegin(v));  // long before v is popped
          } else {
            heap.decrease(old, {nd, v});
          }
        }
      }
    }
    return found;
  }

private:
  static Vec3 touchingPoint(const Vec3& a0, const Vec3& a1, const BarrierSet::Chord& c) {
    // The shared endpoint: whichever of the chord's ends coincides with one of ours.
    for (const Vec3* p : {&c.a, &c.b})
      for (const Vec3* q : {&a0, &a1})
        if ((*p - *q).norm() <= 1e-9 * (1 + p->norm())) return *p;
    return a0;
  }

  void reset() {
    for (int n : touched_) state_[n] = NodeState();
    touched_.clear();
  }

  void setDist(int n, float d, int pred) {
    if (std::isinf(state_[n].dist)) touched_.push_back(n);
    state_[n] = {d, pred};
  }

  std::vector<int> chainTo(int end) const {
    std::vector<int> nodes;
    for (int n = end; n >= 0; n = state_[n].pred) nodes.push_back(n);
    std::reverse(nodes.begin(), nodes.end());
    return nodes;
  }

  TracedPath buildPath(int port, int end, double length, TracedPath::End kind) const {
    TracedPath path;
    path.sourcePort = port;
    path.end = kind;
    path.length = length;
    std::vector<int> nodes = chainTo(end);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      path.points.push_back(nodePoint(g_, nodes[i]));
      if (i + 1 < nodes.size()) path.segments.push_back(arcSegment(g_, nodes[i], nodes[i + 1]));
    }
    return path;
  }

  TracedPath buildTerminalPath(int port, const Terminal& t, double length) const {
    TracedPath path = buildPath(port, t.pred, length, TracedPath::Barrier);
    path.barrier = t.barrier;
    PathPoint p;
    p.kind = PathPoint::Crossing;
    p.id = t.barrier;
    p.position = t.point;
    path.points.push_back(p);
    PathSegment seg = t.segment;
    path.segments.push_back(seg);  // chord end is the sample beyond; the path stops at `point`
    return path;
  }

  /// A node's tentative distance and predecessor, side by side: a relaxation reads one line.
  struct NodeState {
    float dist = std::numeric_limits<float>::infinity();
    int pred = -1;
  };

  const GeodesicGraph& g_;
  std::vector<NodeState> state_;
  std::vector<int> touched_;
  std::vector<Terminal> terminals_;
  RadixHeap heap_;
};

}  // namespace

ChordRelation relateChords(double a1, double b1, double a2, double b2) {
  // Coordinates live on the triangle's boundary, a circle of length 3 (see traced_path.h):
  // no fmod or rounding here, this runs for every pair of pieces sharing a triangle.
  auto same = [](double x, double y) {
    double d = std::abs(x - y);
    return d < kEps || std::abs(d - 3) < kEps;
  };
  auto isCorner = [](double x) {
    return std::abs(x) < kEps || std::abs(x - 1) < kEps || std::abs(x - 2) < kEps || std::abs(x - 3) < kEps;
  };
  if ((same(a1, a2) && same(b1, b2)) || (same(a1, b2) && same(b1, a2))) return ChordRelation::SameChord;
  for (double p : {a1, b1})
    for (double q : {a2, b2})
      if (same(p, q)) return isCorner(p) ? ChordRelation::Disjoint : ChordRelation::Touching;
  auto along = [a1](double x) {  // position of x after a1, going round, in [0, 3)
    double t = x - a1;
    if (t < 0) t += 3;
    if (t >= 3) t -= 3;
    return t;
  };
  double end = along(b1);
  auto inside = [&](double x) {
    double t = along(x);
    return t > 0 && t < end;
  };
  return inside(a2) != inside(b2) ? ChordRelation::Crossing : ChordRelation::Disjoint;
}

void BarrierSet::add(const std::vector<std::pair<const TracedPath*, int>>& paths) {
  const int numFaces = int(start_.size()) - 1;
  auto inRange = [&](const PathSegment& s) { return s.face >= 0 && s.face < numFaces; };
  // Each face's new size, then its chords: the old ones first, the new ones after them.
  std::vector<int> start(start_.size(), 0);
  for (int f = 0; f < numFaces; ++f) start[f + 1] = start_[f + 1] - start_[f];
  for (const auto& entry : paths)
    for (const PathSegment& s : entry.first->segments)
      if (inRange(s)) ++start[s.face + 1];
  for (int f = 0; f < numFaces; ++f) start[f + 1] += start[f];
  std::vector<Chord> chords(static_cast<std::size_t>(start[numFaces]));
  std::vector<int> next(start.begin(), start.end() - 1);  // where each face's next chord goes
  for (int f = 0; f < numFaces; ++f)
    for (int i = start_[f]; i < start_[f + 1]; ++i) chords[next[f]++] = chords_[i];
  for (const auto& [path, id] : paths) {
    for (std::size_t i = 0; i < path->segments.size(); ++i) {
      const PathSegment& s = path->segments[i];
      if (!inRange(s)) continue;
      chords[next[s.face]++] = {s.from,
                                s.to,
                                s.direction,
                                id,
                                path->points[i].position,
                                path->points[i + 1].position,
                                path->points[i].kind == PathPoint::Crossing,
                                path->points[i + 1].kind == PathPoint::Crossing};
    }
    ++count_;
  }
  chords_ = std::move(chords);
  start_ = std::move(start);
}

std::vector<TracedPath> traceFromPort(const GeodesicGraph& graph, int port, const SearchOptions& options) {
  Search search(graph);
  return search.run(port, options);
}

namespace {

/// Searches ready for reuse on one graph (GeodesicGraph::searchScratch): reset() clears only the
/// nodes a search touched, so a reused Search costs nothing up front.
struct SearchPool {
  std::mutex mutex;
  std::vector<std::unique_ptr<Search>> idle;

  std::unique_ptr<Search> take(const GeodesicGraph& graph) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!idle.empty()) {
        std::unique_ptr<Search> s = std::move(idle.back());
        idle.pop_back();
        return s;
      }
    }
    return std::make_unique<Search>(graph);
  }
  void give(std::unique_ptr<Search> s) {
    std::lock_guard<std::mutex> lock(mutex);
    idle.push_back(std::move(s));
  }
};

SearchPool& searchPool(const GeodesicGraph& graph) {
  static std::mutex creating;
  std::lock_guard<std::mutex> lock(creating);
  std::shared_ptr<void>& scratch = graph.searchScratch();
  if (!scratch) scratch = std::make_shared<SearchPool>();
  return *static_cast<SearchPool*>(scratch.get());
}

/// Search i from ports[i] with optionsOf(i), shared out among the threads port by port.
template <class OptionsOf>
std::vector<std::vector<TracedPath>> searchInParallel(const GeodesicGraph& graph, const std::vector<int>& ports,
                                                      const OptionsOf& optionsOf, const ProgressCallback& progress) {
  std::vector<std::vector<TracedPath>> results(ports.size());
  const int threads = workerThreadCount(graph.parameters().threads, int(ports.size()));
  std::atomic<std::size_t> next{0};
  std::atomic<int> done{0};
  SearchPool& pool = searchPool(graph);
  auto work = [&](int thread) {
    const bool reports = thread == 0;  // only the calling thread reports: callbacks need no locking
    std::unique_ptr<Search> search = pool.take(graph);
    for (;;) {
      std::size_t i = next.fetch_add(1);
      if (i >= ports.size()) break;
      results[i] = search->run(ports[i], optionsOf(i));
      int finished = ++done;
      if (reports && progress) progress(finished, int(ports.size()));
    }
    pool.give(std::move(search));
  };
  runOnWorkerThreads(threads, work);
  if (progress) progress(int(ports.size()), int(ports.size()));
  return results;
}

}  // namespace

std::vector<std::vector<TracedPath>> traceFromPorts(const GeodesicGraph& graph, const std::vector<int>& ports,
                                                    const SearchOptions& options, const ProgressCallback& progress) {
  return searchInParallel(graph, ports, [&](std::size_t) -> const SearchOptions& { return options; }, progress);
}

std::vector<std::vector<TracedPath>> traceFromPorts(const GeodesicGraph& graph, const std::vector<int>& ports,
                                                    const std::vector<SearchOptions>& options) {
  if (options.size() != ports.size()) throw std::invalid_argument("traceFromPorts: one set of options per port");
  return searchInParallel(graph, ports, [&](std::size_t i) -> const SearchOptions& { return options[i]; }, nullptr);
}

}  // namespace fcql
