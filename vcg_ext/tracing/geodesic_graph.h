// Graph G of the paper (§3.2): field-coherent straight moves across triangles.
//
// Nodes
//  - Edge nodes: one per auxiliary point s, incident triangle t and cross direction j of t,
//    meaning "a path standing at s that continues into t following direction j". Directions
//    whose ±45° sector is hidden behind the edge have no arcs (at most 3 per point per
//    triangle are live).
//  - Border terminals: the slots of side 1 of a sample on a border edge (that side has no
//    triangle): reaching one means the path hit the border there, following direction j of
//    the triangle on side 0.
//  - Port nodes: for port p (numbered over all singular vertices in FieldAnalysis order), one
//    source node sourceNode(p) and one sink node sinkNode(p).
// Numbering. Slots are laid out so that one search touches a compact part of memory. The
// faces are combed: a rotation r(t) per face, chosen along a spanning tree so that the
// matching across most edges becomes zero; the combed direction of direction j of t is
// j − r(t). A field-coherent path keeps its combed direction except where it crosses a
// non-tree edge, so slots are numbered combed direction first:
//    slot = (combed · numSamples + sample) · 2 + side,   side = side of t w.r.t. the edge
//    (see EdgeSampling), then the port nodes.
// Arcs (stored in one flat CSR array of {target, weight}; a target from which no sink can be
// reached, such as a border terminal or an edge node without arcs out, is stored complemented,
// ~node, so that searches that only look for sinks skip such dead ends without a lookup; the
// weights are stored reduced by the distances to the nearest sink, see sink_distance.h)
//  - From an edge node (s, t, j) to every auxiliary point s' on the two other edges of t whose
//    direction s' − s lies within 45° of direction j of t (its sector); the target is the node
//    of s' in the triangle t' across that edge, carrying the transported direction
//    j' = j + matching(t, edge). Weight = Eq. 1: |w|(1 + α·Angle(d_j, w)/(π/4)). A point s'
//    on a border edge (the border terminal: the path ends there) only if direction j meets
//    the border across it, within 45° of the edge's normal, as separatrices meet each other.
//  - From an edge node (s, t, j) to the sink of port p of the vertex v opposite s in t, when v
//    lies in the sector of (s, t, j), s lies in the sector of p in the conformally flattened
//    star of v, and j is p's direction carried to t, reversed (pointing at v).
//  - From the source of port p of v to the auxiliary points on the edges opposite v whose
//    flattened angle lies in p's sector and which lie within 45° of p's direction carried to
//    that face.
// Every directed chain of arcs is therefore field-coherent (paper §3.2).
#pragma once

#include "field/field_analysis.h"
#include "tracing/edge_sampling.h"
#include "tracing/sink_distance.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace fcql {

/// Eq. 1 of the paper: the length of a move w whose field direction is d (unit), penalised by
/// its drift angle from d: |w|·(1 + α·angle(d, w)/(π/4)).
double anisotropicLength(const Vec3& w, const Vec3& d, double alpha);

struct TracingParameters {
  double alpha = 20.0;  ///< drift penalty of Eq. 1 (α ≥ 0)
  int k = 10;           ///< sinks reached before a search stops (k ≥ 1)
  double phiDeg = 10.0; ///< angular density of auxiliary points (1° ≤ φ ≤ 45°)
  int threads = 0;      ///< 0: all hardware threads

  /// Throws std::invalid_argument with a message naming the parameter and its valid range.
  void validate() const;
};

/// A separatrix port as a node of G: the singular vertex, which port, and its sector in the
/// flattened star.
struct PortNode {
  int singularity = -1;  ///< index in FieldAnalysis::singularities
  int portIndex = -1;    ///< index in that singularity's ports
  int vertex = -1;
  double flatAngle = 0;  ///< from Port::flatAngle
  double sectorLow = 0, sectorHigh = 0;  ///< flattened sector, unwrapped around flatAngle
};

class GeodesicGraph {
public:
  /// Whether the graph computes each node's distance to the nearest sink, which guides the
  /// searches for sinks (see sink_distance.h). A graph used only by t-junction searches, which
  /// run on Eq. 1, can skip it: searches for sinks are then unguided, with the same results.
  enum class SinkDistances { Computed, Skipped };
  GeodesicGraph(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                const TracingParameters& params, SinkDistances sinkDistances = SinkDistances::Computed);

  const SurfaceMesh& mesh() const { return *mesh_; }
  const CrossField& field() const { return *field_; }
  const FieldAnalysis& analysis() const { return *analysis_; }
  const EdgeSampling& sampling() const { return sampling_; }
  const TracingParameters& parameters() const { return params_; }

  int numSamples() const { return sampling_.numSamples(); }
  /// Slot of the edge node at `sample`, on `side`, with combed direction `combed`.
  int edgeNode(int sample, int side, int combed) const { return (combed * numSamples() + sample) * 2 + side; }
  int nodeSample(int node) const { return (node >> 1) % numSamples(); }
  int nodeSide(int node) const { return node & 1; }
  /// Direction index of an edge node in the face it continues into (for a border terminal:
  /// in the face on side 0).
  int nodeDirection(int node) const {
    int e = sampling_.sampleEdge[nodeSample(node)];
    int f = sampling_.edgeFace[e][nodeSide(node)];
    if (f < 0) f = sampling_.edgeFace[e][0];
    return (node / (2 * numSamples()) + faceRotation_[f]) & 3;
  }
  /// Combing rotation r(t) of face t (see Numbering above).
  int faceRotation(int f) const { return faceRotation_[f]; }
  int sourceNode(int port) const { return portBase_ + 2 * port; }
  int sinkNode(int port) const { return portBase_ + 2 * port + 1; }
  bool isPortNode(int node) const { return node >= portBase_; }
  int portOfNode(int node) const { return (node - portBase_) / 2; }
  bool isSinkNode(int node) const { return isPortNode(node) && (node - portBase_) % 2 == 1; }
  bool isBorderTerminal(int node) const {
    return !isPortNode(node) && nodeSide(node) == 1 && sampling_.edgeFace[sampling_.sampleEdge[nodeSample(node)]][1] < 0;
  }
  /// Face an edge node continues into (−1 for a border terminal).
  int nodeFace(int node) const {
    return sampling_.edgeFace[sampling_.sampleEdge[nodeSample(node)]][nodeSide(node)];
  }

  /// An arc of G: `target` is the node reached, complemented (~node, negative) when no sink
  /// can be reached from that node (a border terminal, an edge node without arcs out, or one
  /// whose every way on ends so); `weight` is the arc's length of Eq. 1 reduced by the
  /// distances to the nearest sink, w + h(target) − h(source) ≥ 0 (see sink_distance.h; only
  /// searches for sinks use it: arcLength() gives Eq. 1 itself), or, for a complemented
  /// target, Eq. 1 unreduced.
  using Arc = WeightedArc;
  /// Whether no path through the arc's target reaches a sink: only searches that end paths
  /// at the border or at a crossing on the way need such arcs.
  static bool isDeadEnd(const Arc& a) { return a.target < 0; }
  static int targetNode(const Arc& a) { return a.target < 0 ? ~a.target : a.target; }

  int numNodeSlots() const { return int(arcBegin_.size()) - 1; }
  const std::vector<PortNode>& ports() const { return ports_; }
  /// Arcs leaving `node`: [arcsBegin(node), arcsEnd(node)).
  const Arc* arcsBegin(int node) const { return arcs_.data() + arcBegin_[node]; }
  const Arc* arcsEnd(int node) const { return arcs_.data() + arcBegin_[node + 1]; }
  /// Length of the shortest path from `node` to any sink (+infinity if there is none); with
  /// SinkDistances::Skipped, 0 wherever a path can go on.
  float sinkDistance(int node) const { return sinkDistance_[node]; }
  /// The face the move of arc `from` → `to` crosses and the direction index it follows there
  /// (for a source arc: the face behind the target's edge, the port's direction carried).
  struct ArcFrame {
    int face;
    int direction;
  };
  ArcFrame arcFrame(int from, int to) const;
  /// Eq. 1 for the move of arc `from` → `to`, the same number the graph was built with (its
  /// stored weight is reduced).
  float arcLength(int from, int to) const;
  /// Asks the cache for where the arcs of `node` are (searches prefetch ahead).
  void prefetchArcRange(int node) const { __builtin_prefetch(arcBegin_.data() + node); }

  /// |G|: nodes with at least one arc (in or out) and arcs.
  long numNodes() const { return numLiveNodes_; }
  long numArcs() const { return long(arcs_.size()); }

  /// Index of the port whose flattened sector at singular vertex `singularity` contains the
  /// flattened angle `flat`; −1 if none.
  int portAtFlatAngle(int singularity, double flat) const;
  /// First port index of each singularity (ports of singularity s are
  /// [firstPort[s], firstPort[s+1])).
  const std::vector<int>& firstPort() const { return firstPort_; }

  /// Scratch space of the searches (separatrix_tracer.cpp: per-node arrays as large as the
  /// graph), kept with the graph between calls: the completion runs hundreds of small searches,
  /// and allocating and clearing those arrays for each call cost more than the searches. The
  /// searches in it refer to this graph, so a copy or a moved-to graph starts without any.
  std::shared_ptr<void>& searchScratch() const { return searchScratch_.scratch; }

private:
  struct ScratchSlot {
    std::shared_ptr<void> scratch;
    ScratchSlot() = default;
    ScratchSlot(const ScratchSlot&) {}
    ScratchSlot(ScratchSlot&&) noexcept {}
    ScratchSlot& operator=(const ScratchSlot&) { scratch.reset(); return *this; }
    ScratchSlot& operator=(ScratchSlot&&) noexcept { scratch.reset(); return *this; }
  };
  mutable ScratchSlot searchScratch_;
  const SurfaceMesh* mesh_;
  const CrossField* field_;
  const FieldAnalysis* analysis_;
  TracingParameters params_;
  EdgeSampling sampling_;
  std::vector<PortNode> ports_;
  std::vector<int> firstPort_;
  int portBase_ = 0;
  std::vector<int> faceRotation_;
  std::vector<std::uint32_t> arcBegin_;  ///< per slot, plus one
  std::vector<Arc> arcs_;
  std::vector<float> sinkDistance_;  ///< per slot: h, the distance to the nearest sink
  long numLiveNodes_ = 0;
  friend class GeodesicGraphBuilder;
};

}  // namespace fcql
