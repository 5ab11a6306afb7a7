// Tracing field-coherent geodesic paths (paper §3.3): Dijkstra searches in graph G from the
// source node of a port, stopping after k sinks are reached, with optional barriers (a set of
// separatrices that may not be crossed tangentially) and a t-junction mode that stops at the
// first orthogonal crossing of a barrier or at the border.
// Searches for sinks run on G's weights reduced by the distance to the nearest sink (A* with
// an exact heuristic, sink_distance.h): the same sinks in the same order by the same shortest
// paths as on Eq. 1's weights (ties and rounding aside), settling far fewer nodes
// (bench/RESULTS.md). T-junction searches run on Eq. 1 itself.
#pragma once

#include "tracing/geodesic_graph.h"
#include "tracing/traced_path.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace fcql {

/// Called from the calling thread as searches complete: (searches done, searches in all).
using ProgressCallback = std::function<void(int done, int total)>;

/// Separatrices that searches must respect, indexed per face for fast lookups: the chords of
/// all faces in one array, face by face (each face's in the order they were added), so that a
/// whole layout's barriers take two allocations instead of one per face, and a search's test
/// of a face holding none reads two neighbouring integers.
class BarrierSet {
public:
  explicit BarrierSet(int numFaces = 0) : start_(std::size_t(std::max(0, numFaces)) + 1, 0) {}
  /// Adds every segment of `path` as a barrier with identifier `id`. Each call rebuilds the
  /// array: many paths go in one call of the overload below (layoutBarriers).
  void add(const TracedPath& path, int id) { add({{&path, id}}); }
  /// Adds every segment of each path as a barrier with the path's identifier, in the order
  /// given (the same per-face order as adding them one by one, in one pass over the set).
  void add(const std::vector<std::pair<const TracedPath*, int>>& paths);
  bool empty() const { return count_ == 0; }
  int size() const { return count_; }

  struct Chord {
    double from, to;
    int direction;
    int id;
    Vec3 a, b;  ///< endpoints
    /// The path stops inside the triangle at a (or b), on another separatrix (a t-junction):
    /// the chord's `from` (or `to`) is then the edge point beyond, where the straight move
    /// would have ended, and only the part up to the real end is a barrier.
    bool endsInsideA = false, endsInsideB = false;
  };
  /// The chords of one face, in the order they were added.
  struct Chords {
    const Chord *first, *last;
    const Chord* begin() const { return first; }
    const Chord* end() const { return last; }
    bool empty() const { return first == last; }
    std::size_t size() const { return std::size_t(last - first); }
  };
  Chords inFace(int f) const { return {chords_.data() + start_[f], chords_.data() + start_[f + 1]}; }

private:
  std::vector<Chord> chords_;  ///< face by face
  std::vector<int> start_;     ///< face f's chords: [start_[f], start_[f + 1])
  int count_ = 0;
};

/// How a straight piece of path meets a barrier chord of the same triangle.
struct BarrierContact {
  /// Disjoint: they do not meet, or only beyond the end of a chord that stops inside its
  /// triangle (a t-junction).
  ChordRelation relation = ChordRelation::Disjoint;
  /// They meet and follow the same direction of the triangle's cross up to a half turn: a
  /// tangential crossing, never allowed (paper Fig. 5). Meeting otherwise, they cross
  /// orthogonally.
  bool tangential = false;
};

/// The tangential-crossing test of a search's move against a barrier, and of a traced path
/// against a layout's separatrices: `segment` is the piece, from `from` to `to` in its face,
/// `chord` a barrier in that face.
BarrierContact barrierContact(const PathSegment& segment, const Vec3& from, const Vec3& to,
                              const BarrierSet::Chord& chord);

struct SearchOptions {
  int maxSinks = 10;                 ///< k
  const BarrierSet* barriers = nullptr;
  /// T-junction mode: the path ends at its first orthogonal crossing with a barrier, or at
  /// the border, whichever is nearest; sinks allowed by `sinkAllowed` also end it.
  bool tJunctionMode = false;
  /// Border mode: the path ends at the border or at the first sink `sinkAllowed` allows,
  /// whichever is nearest, crossing barriers orthogonally on the way (never tangentially).
  /// One path at most; ignored in t-junction mode.
  bool borderEnds = false;
  /// Paths longer than this (γ, Eq. 1) are not sought: the search stops once every path left
  /// would be longer (infinity: no bound).
  double maxLength = std::numeric_limits<double>::infinity();
  /// Per port: 1 if its sink may end a path (empty: all). The source's own sink never does.
  std::vector<char> sinkAllowed;
};

/// All paths found by one search, in the order their ends were settled (shortest first).
std::vector<TracedPath> traceFromPort(const GeodesicGraph& graph, int port, const SearchOptions& options);

/// Searches from each port in `ports`, in parallel (graph.parameters().threads); result i
/// belongs to ports[i], identical whatever the number of threads.
std::vector<std::vector<TracedPath>> traceFromPorts(const GeodesicGraph& graph, const std::vector<int>& ports,
                                                    const SearchOptions& options,
                                                    const ProgressCallback& progress = nullptr);
/// The same with options of its own for each search: `options[i]` for ports[i].
std::vector<std::vector<TracedPath>> traceFromPorts(const GeodesicGraph& graph, const std::vector<int>& ports,
                                                    const std::vector<SearchOptions>& options);

}  // namespace fcql
