#include "field/field_analysis.h"
#include "field/field_io.h"
#include "field/field_generation.h"
#include "mesh/generators.h"
#include "mesh/mesh_io.h"
#include "tracing/edge_sampling.h"
#include "test_support.h"
#include "tracing/separatrix_graph.h"
#include "util/math_constants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <limits>
#include <numeric>
#include <queue>
#include <set>

using namespace fcql;

namespace {

struct Traced {
  SurfaceMesh mesh;
  CrossField field;
  FieldAnalysis analysis;
  std::unique_ptr<GeodesicGraph> graph;
  SeparatrixGraph h;
};

std::unique_ptr<Traced> trace(SurfaceMesh mesh, CrossField field, TracingParameters params) {
  auto t = std::make_unique<Traced>();
  t->mesh = std::move(mesh);
  t->field = std::move(field);
  t->analysis = analyzeField(t->mesh, t->field);
  t->graph = std::make_unique<GeodesicGraph>(t->mesh, t->field, t->analysis, params);
  t->h = traceCandidateSeparatrices(*t->graph);
  return t;
}

/// Checks that a path is field-coherent: every segment lies in its triangle, within 45° of
/// the direction it claims, and that direction is the one transported from the previous
/// triangle. Returns the mean drift angle of its segments.
double checkCoherent(const Traced& t, const TracedPath& p) {
  EXPECT_EQ(p.points.size(), p.segments.size() + 1);
  double drift = 0, total = 0;
  for (std::size_t i = 0; i < p.segments.size(); ++i) {
    const PathSegment& s = p.segments[i];
    Vec3 w = p.points[i + 1].position - p.points[i].position;
    Vec3 d = t.field.direction(t.mesh, s.face, s.direction);
    EXPECT_LT(std::abs(t.mesh.faceNormal(s.face).dot(w)), 1e-9 * (1 + w.norm())) << "segment leaves its face";
    double angle = std::acos(std::clamp(d.dot(w) / w.norm(), -1.0, 1.0));
    EXPECT_LE(angle, kPi / 4 + 1e-9) << "segment " << i << " drifts more than 45 degrees";
    drift += angle * w.norm();
    total += w.norm();
    if (i + 1 < p.segments.size()) {
      const PathSegment& n = p.segments[i + 1];
      int shared = -1;
      for (int e = 0; e < 3; ++e)
        if (t.mesh.adjacentFace(s.face, e) == n.face) shared = e;
      EXPECT_GE(shared, 0) << "consecutive segments are not in adjacent faces";
      if (shared < 0) return 0;
      EXPECT_EQ(n.direction, (s.direction + t.analysis.matching[s.face][shared]) % 4) << "direction not transported";
    }
  }
  return total > 0 ? drift / total : 0;
}

}  // namespace

TEST(Tracing, ParametersAreValidated) {
  TracingParameters p;
  p.alpha = -1;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = {};
  p.k = 0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = {};
  p.phiDeg = 0.5;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.phiDeg = 46;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

TEST(Tracing, ChordRelations) {
  EXPECT_EQ(relateChords(0.5, 1.5, 1.2, 2.5), ChordRelation::Crossing);
  EXPECT_EQ(relateChords(0.5, 1.5, 1.7, 2.5), ChordRelation::Disjoint);
  EXPECT_EQ(relateChords(0.5, 1.5, 0.5, 2.5), ChordRelation::Touching);
  EXPECT_EQ(relateChords(0.0, 1.5, 0.0, 2.5), ChordRelation::Disjoint);  // meet at a corner
  EXPECT_EQ(relateChords(0.5, 1.5, 1.5, 0.5), ChordRelation::SameChord);
  EXPECT_EQ(relateChords(2.5, 0.5, 0.2, 1.5), ChordRelation::Crossing);
}

TEST(Tracing, PathsMeetingThemselvesTangentiallyAreFound) {
  // Face 0 is entered twice. Directions 0 and 2 are one class up to a half turn (tangential),
  // 0 and 1 are orthogonal.
  auto path = [](std::vector<PathSegment> segments) {
    TracedPath p;
    p.segments = std::move(segments);
    return p;
  };
  EXPECT_TRUE(meetsItself(path({{0, 0, 0.5, 1.5}, {1, 1, 0.2, 2.2}, {0, 2, 1.2, 2.5}})));   // crossing
  EXPECT_TRUE(meetsItself(path({{0, 0, 0.5, 1.5}, {1, 1, 0.2, 2.2}, {0, 2, 0.5, 2.5}})));   // one auxiliary point twice
  EXPECT_TRUE(meetsItself(path({{0, 0, 0.5, 1.5}, {1, 1, 0.2, 2.2}, {0, 0, 1.5, 0.5}})));   // back along itself
  EXPECT_FALSE(meetsItself(path({{0, 0, 0.5, 1.5}, {1, 1, 0.2, 2.2}, {0, 1, 1.2, 2.5}})));  // orthogonal crossing
  EXPECT_FALSE(meetsItself(path({{0, 0, 0.5, 1.5}, {1, 1, 0.2, 2.2}, {0, 2, 1.7, 2.5}})));  // apart in face 0
  EXPECT_FALSE(meetsItself(path({{0, 0, 0.5, 1.5}, {1, 0, 0.5, 1.5}, {2, 0, 0.5, 1.5}})));  // no face twice
}

TEST(Tracing, GraphHLeavesOutPathsThatMeetThemselvesTangentially) {
  // The dragon's noisy field (795 singularities) has searches whose paths loop round and cross
  // their own start in the same direction class: such a separatrix cut a 3-corner and a
  // 5-corner patch pair on each side of its loop. H keeps none of them.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "dragon");
  TracingParameters params;
  params.alpha = 15;
  params.k = 10;
  auto t = trace(m, f, params);
  std::vector<int> ports(t->graph->ports().size());
  std::iota(ports.begin(), ports.end(), 0);
  SearchOptions options;
  options.maxSinks = params.k;
  int looping = 0;
  for (const auto& search : traceFromPorts(*t->graph, ports, options))
    for (const auto& p : search) looping += p.end == TracedPath::Sink && meetsItself(p);
  EXPECT_GT(looping, 0) << "the dragon's searches no longer find looping paths: the test checks nothing";
  ASSERT_GT(t->h.arcs.size(), 20000u);
  for (std::size_t a = 0; a < t->h.arcs.size(); ++a) ASSERT_FALSE(meetsItself(t->h.arcs[a].path)) << "arc " << a;
}

TEST(Tracing, CubeCandidatesIncludeTheTwelveEdges) {
  TracingParameters params;
  params.k = 6;
  auto t = trace(test::sharpCube(6), test::axisField(test::sharpCube(6)), params);
  ASSERT_EQ(t->graph->ports().size(), 24u);
  EXPECT_GT(t->graph->numNodes(), 0);
  std::set<std::pair<int, int>> connected;
  for (const auto& c : t->h.arcs) {
    int va = t->graph->ports()[c.portA].vertex, vb = t->graph->ports()[c.portB].vertex;
    connected.insert({std::min(va, vb), std::max(va, vb)});
    EXPECT_EQ(c.path.points.front().kind, PathPoint::Vertex);
    EXPECT_EQ(c.path.points.back().kind, PathPoint::Vertex);
    checkCoherent(*t, c.path);
  }
  // Every pair of corners joined by a cube edge is connected by a candidate.
  int edges = 0;
  for (const auto& a : t->analysis.singularities)
    for (const auto& b : t->analysis.singularities) {
      if (a.vertex >= b.vertex) continue;
      Vec3 d = t->mesh.position(a.vertex) - t->mesh.position(b.vertex);
      if (std::abs(d.norm() - 2.0) > 1e-9) continue;  // not adjacent corners
      ++edges;
      EXPECT_TRUE(connected.count({a.vertex, b.vertex})) << "corners " << a.vertex << " and " << b.vertex;
    }
  EXPECT_EQ(edges, 12);
}

/// Checks the φ rule of §3.2 on every edge: at least one auxiliary point, parameters strictly
/// increasing in (0, 1), positions on the edge, no two points (edge ends included) closer than a
/// tenth of the mean spacing (near-coincident points make degenerate pieces when the surface is
/// cut), and every pair of consecutive points subtends less than φ at the vertex opposite the
/// edge in each incident triangle. Returns the number of points.
int checkAuxiliaryPoints(const SurfaceMesh& m, double phiDeg) {
  const double phi = phiDeg * kPi / 180;
  EdgeSampling es = sampleEdges(m, phi);
  // Sampled on two threads: the same points, numbered the same way.
  const EdgeSampling two = sampleEdges(m, phi, 48, 2);
  EXPECT_EQ(two.sampleEdge, es.sampleEdge);
  EXPECT_EQ(two.sampleParam, es.sampleParam);
  EXPECT_EQ(two.firstSample, es.firstSample);
  auto angleAt = [](const Vec3& apex, const Vec3& a, const Vec3& b) {
    Vec3 u = a - apex, v = b - apex;
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  int violations = 0;
  for (int e = 0; e < m.numEdges(); ++e) {
    EXPECT_GE(es.sampleCount[e], 1) << "edge " << e << " has no auxiliary point";
    int f = es.edgeFace[e][0], i = es.edgeLocal[e][0];
    Vec3 a = m.position(m.vertex(f, i)), b = m.position(m.vertex(f, (i + 1) % 3));
    std::vector<Vec3> points{a};
    double previous = 0;
    for (int q = es.firstSample[e]; q < es.firstSample[e] + es.sampleCount[e]; ++q) {
      EXPECT_EQ(es.sampleEdge[q], e);
      EXPECT_GE(es.sampleParam[q] - previous, 0.1 / (es.sampleCount[e] + 1)) << "edge " << e;
      previous = es.sampleParam[q];
      EXPECT_LT((es.samplePosition[q] - (a + (b - a) * previous)).norm(), 1e-12 * (1 + a.norm()));
      points.push_back(es.samplePosition[q]);
    }
    EXPECT_GE(1.0 - previous, 0.1 / (es.sampleCount[e] + 1)) << "edge " << e;
    points.push_back(b);
    for (int side = 0; side < 2; ++side) {
      int g = es.edgeFace[e][side];
      if (g < 0) continue;
      Vec3 apex = m.position(m.vertex(g, (es.edgeLocal[e][side] + 2) % 3));
      for (std::size_t k = 0; k + 1 < points.size(); ++k)
        if (angleAt(apex, points[k], points[k + 1]) >= phi) ++violations;
    }
  }
  EXPECT_EQ(violations, 0) << "segments subtending phi or more at an opposite vertex";
  return es.numSamples();
}

TEST(Tracing, AuxiliaryPointsFollowThePhiRule) {
  // Right triangles (the cube), near-equilateral ones (the sphere), a border (the cylinder).
  for (double phi : {5.0, 10.0, 20.0}) {
    checkAuxiliaryPoints(test::sharpCube(3), phi);
    checkAuxiliaryPoints(makeSphere(3), phi);
    checkAuxiliaryPoints(makeOpenCylinder(), phi);
  }
  std::string bunny = test::sharedMesh("bunny.obj");
  if (bunny.empty()) GTEST_SKIP() << "../shared/data/meshes/bunny.obj is absent";
  SurfaceMesh m = loadMesh(bunny);
  // The greedy walk needs fewer points than equal steps would (327K for the same rule).
  EXPECT_LT(checkAuxiliaryPoints(m, 10), 300000);
}

TEST(Tracing, SmallerPhiGivesMoreNodes) {
  SurfaceMesh m = test::sharpCube(3);
  CrossField f = test::axisField(m);
  FieldAnalysis a = analyzeField(m, f);
  TracingParameters coarse, fine;
  coarse.phiDeg = 20;
  fine.phiDeg = 5;
  GeodesicGraph gc(m, f, a, coarse), gf(m, f, a, fine);
  EXPECT_GT(gf.numNodes(), gc.numNodes());
  EXPECT_GT(gf.numArcs(), gc.numArcs());
}

TEST(Tracing, ArcsIntoDeadEndsAreMarkedAndNoOthers) {
  // Searches for sinks skip the marked arcs without looking at their targets: an arc is
  // marked exactly when no sink can be reached from its target, which holds for every border
  // terminal and edge node without arcs out. The lilium (open, with its own field) has both
  // kinds, and nodes whose every way on ends so.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "lilium");
  FieldAnalysis a = analyzeField(m, f);
  GeodesicGraph g(m, f, a, TracingParameters());
  long border = 0, stuck = 0, leadingNowhere = 0;
  for (int n = 0; n < g.numNodeSlots(); ++n)
    for (const GeodesicGraph::Arc* arc = g.arcsBegin(n); arc != g.arcsEnd(n); ++arc) {
      const int v = GeodesicGraph::targetNode(*arc);
      const bool terminal = g.isBorderTerminal(v);
      const bool noWayOn = !g.isPortNode(v) && g.arcsBegin(v) == g.arcsEnd(v);
      ASSERT_EQ(GeodesicGraph::isDeadEnd(*arc), std::isinf(g.sinkDistance(v))) << "arc " << n << " -> " << v;
      if (terminal || noWayOn) ASSERT_TRUE(GeodesicGraph::isDeadEnd(*arc)) << "arc " << n << " -> " << v;
      border += terminal;
      stuck += noWayOn && !terminal;
      leadingNowhere += GeodesicGraph::isDeadEnd(*arc) && !terminal && !noWayOn;
    }
  EXPECT_GT(border, 0);
  EXPECT_GT(stuck, 0);
  EXPECT_GT(leadingNowhere, 0);
  // Independently of h: the nodes from which some sink can be reached, found backwards from
  // the sinks along every arc, marked or not, are exactly those with a finite h.
  std::vector<std::vector<int>> into(g.numNodeSlots());
  for (int n = 0; n < g.numNodeSlots(); ++n)
    for (const GeodesicGraph::Arc* arc = g.arcsBegin(n); arc != g.arcsEnd(n); ++arc)
      into[GeodesicGraph::targetNode(*arc)].push_back(n);
  std::vector<char> reaches(g.numNodeSlots(), 0);
  std::vector<int> queue;
  for (int p = 0; p < int(g.ports().size()); ++p) reaches[g.sinkNode(p)] = 1, queue.push_back(g.sinkNode(p));
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (int u : into[queue[i]])
      if (!reaches[u]) reaches[u] = 1, queue.push_back(u);
  for (int n = 0; n < g.numNodeSlots(); ++n)
    ASSERT_EQ(bool(reaches[n]), std::isfinite(g.sinkDistance(n))) << "node " << n;
  // A marked arc keeps Eq. 1 itself (t-junction searches follow it).
  for (int n = 0; n < g.numNodeSlots(); ++n)
    for (const GeodesicGraph::Arc* arc = g.arcsBegin(n); arc != g.arcsEnd(n); ++arc)
      if (GeodesicGraph::isDeadEnd(*arc)) ASSERT_EQ(arc->weight, g.arcLength(n, GeodesicGraph::targetNode(*arc)));
}

TEST(Tracing, SinkDistancesAreShortestPathLengthsAndReduceTheWeights) {
  // h(n), the length of the shortest path from n to a sink, satisfies Bellman's equation
  // h(u) = min over arcs (Eq. 1 + h(v)), with h = 0 at the sinks; each stored weight is Eq. 1
  // reduced by it, w + h(v) − h(u), hence never negative.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  FieldAnalysis a = analyzeField(m, f);
  GeodesicGraph g(m, f, a, TracingParameters());
  for (int p = 0; p < int(g.ports().size()); ++p) ASSERT_EQ(g.sinkDistance(g.sinkNode(p)), 0.0f);
  long finite = 0, reduced = 0;
  for (int u = 0; u < g.numNodeSlots(); ++u) {
    const double hu = g.sinkDistance(u);
    if (g.isSinkNode(u) || std::isinf(hu)) continue;
    ++finite;
    double best = std::numeric_limits<double>::infinity();
    for (const GeodesicGraph::Arc* arc = g.arcsBegin(u); arc != g.arcsEnd(u); ++arc) {
      if (GeodesicGraph::isDeadEnd(*arc)) continue;
      const int v = GeodesicGraph::targetNode(*arc);
      const double length = g.arcLength(u, v), hv = g.sinkDistance(v);
      const double tolerance = 1e-5 * (hu + length);
      ASSERT_GE(arc->weight, 0.0f) << "arc " << u << " -> " << v;
      ASSERT_NEAR(arc->weight, length + hv - hu, tolerance) << "arc " << u << " -> " << v;
      ASSERT_GE(length + hv, hu - tolerance) << "h(" << u << ") is longer than a way through " << v;
      best = std::min(best, length + hv);
      reduced += arc->weight < 0.999f * length;
    }
    ASSERT_NEAR(best, hu, 1e-5 * hu) << "h(" << u << ") is not the length of any way on";
  }
  EXPECT_GT(finite, g.numNodes() / 2);
  EXPECT_GT(reduced, 0);
}

namespace {

/// Searches run on the reduced weights; plain Dijkstra on Eq. 1 (the paper's search) must
/// find the same k nearest allowed sinks at the same distances, from every port. Returns the
/// number of sinks compared.
long compareWithPlainDijkstra(const GeodesicGraph& g, const SearchOptions& options) {
  long compared = 0;
  for (int port = 0; port < int(g.ports().size()); ++port) {
    std::vector<double> dist(g.numNodeSlots(), std::numeric_limits<double>::infinity());
    std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> queue;
    dist[g.sourceNode(port)] = 0;
    queue.push({0.0, g.sourceNode(port)});
    std::vector<std::pair<double, int>> plain;  // (length, sink port), nearest first
    while (!queue.empty() && int(plain.size()) < options.maxSinks) {
      const auto [d, u] = queue.top();
      queue.pop();
      if (d > dist[u]) continue;
      if (g.isSinkNode(u)) {
        const int p = g.portOfNode(u);
        if (p != port && (options.sinkAllowed.empty() || options.sinkAllowed[p])) plain.push_back({d, p});
        continue;
      }
      for (const GeodesicGraph::Arc* arc = g.arcsBegin(u); arc != g.arcsEnd(u); ++arc) {
        const int v = GeodesicGraph::targetNode(*arc);
        if (g.isBorderTerminal(v)) continue;
        const double nd = d + g.arcLength(u, v);
        if (nd < dist[v]) dist[v] = nd, queue.push({nd, v});
      }
    }
    const std::vector<TracedPath> found = traceFromPort(g, port, options);
    EXPECT_EQ(found.size(), plain.size()) << "port " << port;
    if (found.size() != plain.size()) continue;
    for (std::size_t i = 0; i < found.size(); ++i) {
      EXPECT_NEAR(found[i].length, plain[i].first, 1e-4 * plain[i].first) << "port " << port << ", sink " << i;
      const bool tie = (i > 0 && plain[i].first - plain[i - 1].first < 1e-4 * plain[i].first) ||
                       (i + 1 < plain.size() && plain[i + 1].first - plain[i].first < 1e-4 * plain[i].first);
      if (!tie) EXPECT_EQ(found[i].sinkPort, plain[i].second) << "port " << port << ", sink " << i;
      ++compared;
    }
  }
  return compared;
}

/// The same on a graph of m and f, searching for k sinks, every `allowEvery`-th port's sink
/// allowed; also returns the number of ports.
long compareWithPlainDijkstra(const SurfaceMesh& m, const CrossField& f, int k, int allowEvery, long* ports) {
  FieldAnalysis a = analyzeField(m, f);
  TracingParameters params;
  params.k = k;
  GeodesicGraph g(m, f, a, params);
  SearchOptions options;
  options.maxSinks = k;
  options.sinkAllowed.assign(g.ports().size(), 0);
  for (std::size_t p = 0; p < g.ports().size(); p += allowEvery) options.sinkAllowed[p] = 1;
  *ports = long(g.ports().size());
  return compareWithPlainDijkstra(g, options);
}

}  // namespace

TEST(Tracing, SearchesFindTheSinksPlainDijkstraFinds) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  long ports = 0;
  EXPECT_GT(compareWithPlainDijkstra(m, f, 6, 1, &ports), 5 * ports);
}

TEST(Tracing, SearchesFindTheAllowedSinksPlainDijkstraFindsOnAnOpenSurface) {
  // The lilium has a border (paths may not end on it in a search for sinks) and the
  // solving cycle's searches allow only some sinks: h, taken over all sinks, still guides.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "lilium");
  long ports = 0;
  EXPECT_GT(compareWithPlainDijkstra(m, f, 4, 3, &ports), ports);
}

TEST(Tracing, GraphWithoutSinkDistancesKeepsEquationOneAndFindsTheSameSinks) {
  // For graphs only t-junction searches use (the patch closing's), the distances are skipped:
  // every stored weight is then Eq. 1 itself, and searches for sinks, unguided, find what
  // guided ones find.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  FieldAnalysis a = analyzeField(m, f);
  TracingParameters params;
  params.k = 5;
  GeodesicGraph guided(m, f, a, params), plain(m, f, a, params, GeodesicGraph::SinkDistances::Skipped);
  ASSERT_EQ(guided.numArcs(), plain.numArcs());
  long reducedDiffer = 0;
  for (int n = 0; n < plain.numNodeSlots(); ++n)
    for (const GeodesicGraph::Arc *arc = plain.arcsBegin(n), *other = guided.arcsBegin(n); arc != plain.arcsEnd(n); ++arc, ++other) {
      const int v = GeodesicGraph::targetNode(*arc);
      ASSERT_EQ(v, GeodesicGraph::targetNode(*other));
      ASSERT_EQ(arc->weight, plain.arcLength(n, v)) << "arc " << n << " -> " << v;
      reducedDiffer += arc->weight != other->weight;
    }
  EXPECT_GT(reducedDiffer, 0);
  SearchOptions options;
  options.maxSinks = params.k;
  for (int port = 0; port < int(plain.ports().size()); ++port) {
    const auto a1 = traceFromPort(plain, port, options), a2 = traceFromPort(guided, port, options);
    ASSERT_EQ(a1.size(), a2.size()) << "port " << port;
    for (std::size_t i = 0; i < a1.size(); ++i) EXPECT_NEAR(a1[i].length, a2[i].length, 1e-4 * a1[i].length);
  }
}

TEST(Tracing, PathsEndOnTheBorderOnlyAcrossIt) {
  // A path may end on a border edge only if its field direction lies within 45° of the
  // edge's normal: one running along the border would meet it at a grazing angle and cut
  // off a sliver patch (on the lilium at alpha 5, k 3 a 6-triangle 3-corner patch, beside a
  // 5-corner one). Both kinds of direction must occur, or the check proves nothing.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "lilium");
  FieldAnalysis a = analyzeField(m, f);
  GeodesicGraph g(m, f, a, TracingParameters());
  const EdgeSampling& es = g.sampling();
  // Whether direction j of the face beside border edge e grazes the edge.
  auto grazes = [&](int e, int j) {
    const int face = es.edgeFace[e][0];
    for (int i = 0; i < 3; ++i)
      if (m.edgeId(face, i) == e) {
        const Vec3 edge = (m.position(m.vertex(face, (i + 1) % 3)) - m.position(m.vertex(face, i))).normalized();
        return std::abs(edge.dot(f.direction(m, face, j).normalized())) > std::cos(kPi / 4);
      }
    ADD_FAILURE() << "edge " << e << " is not an edge of its face";
    return false;
  };
  long across = 0, grazingDirections = 0;
  std::set<std::pair<int, int>> seen;
  for (int n = 0; n < g.numNodeSlots(); ++n)
    for (const GeodesicGraph::Arc* arc = g.arcsBegin(n); arc != g.arcsEnd(n); ++arc) {
      const int v = GeodesicGraph::targetNode(*arc);
      if (!g.isBorderTerminal(v)) continue;
      const int e = es.sampleEdge[g.nodeSample(v)];
      ASSERT_FALSE(grazes(e, g.nodeDirection(v))) << "arc " << n << " ends on border edge " << e << " along it";
      ++across;
      if (seen.insert({e, 0}).second)
        for (int j = 0; j < 4; ++j) grazingDirections += grazes(e, j);
    }
  EXPECT_GT(across, 0);
  EXPECT_GT(grazingDirections, 0);
}

TEST(Tracing, EightPathsAreCoherentAndDeterministic) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  TracingParameters one, two;
  one.threads = 1;
  two.threads = 2;
  one.k = two.k = 5;
  auto a = trace(m, f, one);
  auto b = trace(m, f, two);
  ASSERT_EQ(a->h.arcs.size(), b->h.arcs.size());
  ASSERT_GT(a->h.arcs.size(), 20u);
  for (std::size_t i = 0; i < a->h.arcs.size(); ++i) {
    EXPECT_EQ(a->h.arcs[i].portA, b->h.arcs[i].portA);
    EXPECT_EQ(a->h.arcs[i].portB, b->h.arcs[i].portB);
    EXPECT_EQ(a->h.arcs[i].length, b->h.arcs[i].length);
    checkCoherent(*a, a->h.arcs[i].path);
  }
  EXPECT_EQ(a->h.tangentialPairs, b->h.tangentialPairs);
  EXPECT_EQ(a->h.tangentialCliques, b->h.tangentialCliques);
}

TEST(Tracing, SearchesReusingTheGraphsScratchFindWhatFreshSearchesFind) {
  // traceFromPorts keeps its per-node arrays with the graph between calls (the completion runs
  // hundreds of small searches); a search after others, with other sinks, limits and modes,
  // must find exactly what a search with fresh arrays (traceFromPort) finds.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  TracingParameters params;
  params.k = 4;
  params.threads = 2;
  auto t = trace(m, f, params);
  const GeodesicGraph& g = *t->graph;
  const int numPorts = int(g.ports().size());
  ASSERT_GT(numPorts, 8);
  std::vector<int> ports;
  for (int p = 0; p < numPorts; ++p) ports.push_back(p);
  std::vector<SearchOptions> variants(3);
  variants[1].maxSinks = 2;
  variants[1].sinkAllowed.assign(numPorts, 0);
  for (int p = 0; p < numPorts; p += 2) variants[1].sinkAllowed[p] = 1;
  variants[2].tJunctionMode = true;
  variants[2].maxSinks = 1;
  int compared = 0;
  for (int round = 0; round < 2; ++round)
    for (const SearchOptions& o : variants) {
      const auto pooled = traceFromPorts(g, ports, o);
      ASSERT_EQ(pooled.size(), ports.size());
      for (int p = 0; p < numPorts; p += 3) {
        const auto fresh = traceFromPort(g, p, o);
        ASSERT_EQ(pooled[p].size(), fresh.size()) << "port " << p;
        for (std::size_t i = 0; i < fresh.size(); ++i) {
          EXPECT_EQ(pooled[p][i].sinkPort, fresh[i].sinkPort);
          EXPECT_EQ(pooled[p][i].length, fresh[i].length);
          EXPECT_EQ(pooled[p][i].points.size(), fresh[i].points.size());
          ++compared;
        }
      }
    }
  EXPECT_GT(compared, 20);
}

TEST(Tracing, TangentialCliquesHoldExactlyTheArcsThatCrossTangentially) {
  // Graph H's tangential crossings come from cliques of chords per triangle. Checked against
  // every pair of pieces in every triangle: the pairs are exactly those that cross in a
  // parallel direction class, and every clique holds only such pairs.
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  TracingParameters params;
  params.k = 5;
  auto t = trace(m, f, params);
  const auto& arcs = t->h.arcs;
  ASSERT_GT(arcs.size(), 20u);
  std::map<int, std::vector<std::pair<int, const PathSegment*>>> perFace;
  for (int a = 0; a < int(arcs.size()); ++a)
    for (const auto& s : arcs[a].path.segments)
      if (s.face >= 0) perFace[s.face].push_back({a, &s});
  std::set<std::pair<int, int>> expected;
  for (const auto& face : perFace)
    for (const auto& p : face.second)
      for (const auto& q : face.second) {
        const PathSegment &s = *p.second, &u = *q.second;
        if (p.first < q.first && (s.direction - u.direction) % 2 == 0 &&
            relateChords(s.from, s.to, u.from, u.to) != ChordRelation::Disjoint)
          expected.insert({p.first, q.first});
      }
  ASSERT_GT(expected.size(), 50u);
  // No candidate crosses itself tangentially either (Eq. 3 holds within a separatrix too).
  for (const auto& face : perFace)
    for (const auto& p : face.second)
      for (const auto& q : face.second) {
        const PathSegment &s = *p.second, &u = *q.second;
        if (p.first == q.first && &s < &u && (s.direction - u.direction) % 2 == 0)
          EXPECT_EQ(relateChords(s.from, s.to, u.from, u.to), ChordRelation::Disjoint)
              << "candidate " << p.first << " meets itself tangentially in face " << face.first;
      }
  const std::vector<std::pair<int, int>> pairs(expected.begin(), expected.end());
  EXPECT_EQ(t->h.tangentialPairs, pairs);
  std::set<std::vector<int>> distinct;
  for (const auto& clique : t->h.tangentialCliques) {
    ASSERT_GE(clique.size(), 2u);
    EXPECT_TRUE(std::is_sorted(clique.begin(), clique.end()));
    EXPECT_TRUE(distinct.insert(clique).second) << "a clique is listed twice";
    for (std::size_t i = 0; i < clique.size(); ++i)
      for (std::size_t j = i + 1; j < clique.size(); ++j)
        EXPECT_TRUE(expected.count({clique[i], clique[j]})) << clique[i] << " and " << clique[j] << " do not cross tangentially";
  }
}

namespace {

/// True if any segment of `p` crosses or touches a segment of `q` in a shared face while
/// following a parallel direction class.
bool crossesTangentially(const TracedPath& p, const TracedPath& q) {
  for (const auto& s : p.segments)
    for (const auto& t : q.segments)
      if (s.face == t.face && relateChords(s.from, s.to, t.from, t.to) != ChordRelation::Disjoint &&
          (s.direction - t.direction) % 2 == 0)
        return true;
  return false;
}

double meanDrift(const Traced& t) {
  double sum = 0;
  for (const auto& c : t.h.arcs) sum += checkCoherent(t, c.path);
  return t.h.arcs.empty() ? 0 : sum / t.h.arcs.size();
}

}  // namespace

TEST(Tracing, LargerAlphaKeepsPathsCloserToTheField) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  TracingParameters loose, strict;
  loose.alpha = 0;
  strict.alpha = 30;
  loose.k = strict.k = 4;
  auto a = trace(m, f, loose);
  auto b = trace(m, f, strict);
  double driftLoose = meanDrift(*a), driftStrict = meanDrift(*b);
  EXPECT_LT(driftStrict, driftLoose) << "alpha 30 drift " << driftStrict << " vs alpha 0 drift " << driftLoose;
}

TEST(Tracing, BarriersAreNeverCrossedTangentially) {
  FCQL_REQUIRE_SHARED_WITH_FIELD(m, f, "eight");
  TracingParameters params;
  params.k = 4;
  auto t = trace(m, f, params);
  ASSERT_FALSE(t->h.arcs.empty());
  // The longest candidate makes the best obstacle.
  std::size_t longest = 0;
  for (std::size_t i = 0; i < t->h.arcs.size(); ++i)
    if (t->h.arcs[i].path.segments.size() > t->h.arcs[longest].path.segments.size()) longest = i;
  const TracedPath& barrier = t->h.arcs[longest].path;
  // Without the barrier some candidate crosses it tangentially (else the test proves nothing).
  int crossingBefore = 0;
  for (const auto& c : t->h.arcs) crossingBefore += crossesTangentially(c.path, barrier) ? 1 : 0;
  BarrierSet barriers(m.numFaces());
  barriers.add(barrier, 0);
  SearchOptions options;
  options.maxSinks = params.k;
  options.barriers = &barriers;
  std::vector<int> ports(t->graph->ports().size());
  std::iota(ports.begin(), ports.end(), 0);
  auto results = traceFromPorts(*t->graph, ports, options);
  int paths = 0;
  for (const auto& r : results)
    for (const auto& p : r) {
      ++paths;
      EXPECT_FALSE(crossesTangentially(p, barrier)) << "path from port " << p.sourcePort << " crosses the barrier";
    }
  EXPECT_GT(paths, 0);
  EXPECT_GT(crossingBefore, 0) << "no candidate crossed the chosen barrier tangentially to begin with";

  // T-junction mode: every search ends at the first orthogonal crossing, a sink or the border.
  options.tJunctionMode = true;
  auto stops = traceFromPorts(*t->graph, ports, options);
  int onBarrier = 0;
  for (const auto& r : stops) {
    ASSERT_LE(r.size(), 1u);
    for (const auto& p : r) {
      EXPECT_FALSE(crossesTangentially(p, barrier));
      if (p.end == TracedPath::Barrier) {
        ++onBarrier;
        EXPECT_EQ(p.barrier, 0);
        EXPECT_EQ(p.points.back().kind, PathPoint::Crossing);
      }
    }
  }
  EXPECT_GT(onBarrier, 0);
}

TEST(Tracing, SinksOutOfReachStayOutOfReachBehindMoreBarriers) {
  // The solving cycle leaves out the sinks an earlier search of the same port ran out of graph
  // without reaching: barriers only grow, so they stay out of reach. Checked here on the
  // rounded box: searches that may stop at every port, behind a tenth of the candidates and
  // then behind a fifth, find behind the fifth only sinks they found behind the tenth, and
  // leaving out the others changes nothing.
  SurfaceMesh m = makeRoundedBox();
  CrossField f = generateCrossField(m);
  auto t = trace(m, f, TracingParameters{});
  const auto& arcs = t->h.arcs;
  ASSERT_GE(arcs.size(), 12u);
  BarrierSet fewer(m.numFaces()), more(m.numFaces());
  for (int i = 0; i < int(arcs.size()); ++i) {
    if (i % 10 == 0) fewer.add(arcs[i].path, i);  // every tenth candidate
    if (i % 5 == 0) more.add(arcs[i].path, i);    // and as many again
  }
  const int numPorts = int(t->graph->ports().size());
  std::vector<int> ports(numPorts);
  std::iota(ports.begin(), ports.end(), 0);
  SearchOptions options;
  options.maxSinks = numPorts;  // every search runs out of graph
  options.barriers = &fewer;
  const auto behindFewer = traceFromPorts(*t->graph, ports, options);
  options.barriers = &more;
  const auto behindMore = traceFromPorts(*t->graph, ports, options);
  std::vector<SearchOptions> perPort(numPorts, options);
  int outOfReach = 0, lost = 0;
  for (int p = 0; p < numPorts; ++p) {
    std::vector<char> reached(numPorts, 0);
    for (const auto& path : behindFewer[p]) reached[path.sinkPort] = 1;
    for (const auto& path : behindMore[p]) EXPECT_TRUE(reached[path.sinkPort]) << "port " << p << " reaches " << path.sinkPort;
    perPort[p].sinkAllowed = reached;
    outOfReach += numPorts - 1 - int(behindFewer[p].size());
    lost += int(behindFewer[p].size() - behindMore[p].size());
  }
  EXPECT_GT(outOfReach, 0) << "no sink was out of reach: the test would prove little";
  EXPECT_GT(lost, 0) << "the extra barriers should cut some paths";
  const auto narrowed = traceFromPorts(*t->graph, ports, perPort);
  ASSERT_EQ(narrowed.size(), behindMore.size());
  for (int p = 0; p < numPorts; ++p) {
    ASSERT_EQ(narrowed[p].size(), behindMore[p].size()) << "port " << p;
    for (std::size_t i = 0; i < narrowed[p].size(); ++i) {
      EXPECT_EQ(narrowed[p][i].sinkPort, behindMore[p][i].sinkPort);
      EXPECT_EQ(narrowed[p][i].length, behindMore[p][i].length);
    }
  }
  // Each search takes its own options: allowed only the farthest sink it reached, it finds it.
  std::vector<int> withPaths;
  std::vector<SearchOptions> farthestOnly;
  for (int p = 0; p < numPorts; ++p) {
    if (behindMore[p].empty()) continue;
    withPaths.push_back(p);
    farthestOnly.push_back(options);
    farthestOnly.back().sinkAllowed.assign(numPorts, 0);
    farthestOnly.back().sinkAllowed[behindMore[p].back().sinkPort] = 1;
  }
  ASSERT_GE(withPaths.size(), 2u);
  const auto farthest = traceFromPorts(*t->graph, withPaths, farthestOnly);
  for (std::size_t i = 0; i < withPaths.size(); ++i) {
    ASSERT_EQ(farthest[i].size(), 1u) << "port " << withPaths[i];
    EXPECT_EQ(farthest[i][0].sinkPort, behindMore[withPaths[i]].back().sinkPort);
  }
}

#include "field/field_generation.h"
#include "mesh/generators.h"

TEST(Tracing, RoundedBoxCandidatesIncludeTheTwelveBoxEdges) {
  SurfaceMesh m = makeRoundedBox();
  CrossField f = generateCrossField(m);
  auto t = trace(m, f, TracingParameters{});
  ASSERT_EQ(t->analysis.numInteriorSingularities(), 8);
  // Each corner singularity sits in one octant; box edges join corners differing in one sign.
  auto octant = [&](int v) {
    const Vec3& p = t->mesh.position(v);
    return (p.x() > 0 ? 1 : 0) | (p.y() > 0 ? 2 : 0) | (p.z() > 0 ? 4 : 0);
  };
  std::set<std::pair<int, int>> joined;
  for (const auto& c : t->h.arcs) {
    int a = octant(t->graph->ports()[c.portA].vertex), b = octant(t->graph->ports()[c.portB].vertex);
    joined.insert({std::min(a, b), std::max(a, b)});
    checkCoherent(*t, c.path);
  }
  int edges = 0;
  for (int a = 0; a < 8; ++a)
    for (int bit : {1, 2, 4})
      if (!(a & bit)) {
        ++edges;
        EXPECT_TRUE(joined.count({a, a | bit})) << "no candidate between octants " << a << " and " << (a | bit);
      }
  EXPECT_EQ(edges, 12);
}

TEST(Tracing, TorusWithSymmetricFieldHasNoPaths) {
  SurfaceMesh m = makeTorus();
  // The field along the rings of the torus: rotationally symmetric, no singularities.
  std::vector<Vec3> u(m.numFaces());
  for (int f = 0; f < m.numFaces(); ++f) {
    Vec3 c = m.faceCentroid(f);
    u[f] = Vec3(-c.y(), c.x(), 0);
  }
  auto t = trace(m, CrossField::fromVectors(m, u), TracingParameters{});
  EXPECT_EQ(t->analysis.singularities.size(), 0u);
  EXPECT_EQ(t->graph->ports().size(), 0u);
  EXPECT_TRUE(t->h.arcs.empty());
  EXPECT_GT(t->graph->numNodes(), 0);
}
