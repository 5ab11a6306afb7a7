#include "layout/layout_solver.h"

#include "layout/layout_completion.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace fcql {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }


/// True if two paths meet anywhere inside a shared triangle (cross, touch or overlap).
bool pathsMeet(const TracedPath& p, const TracedPath& q) {
  for (const auto& s : p.segments)
    for (const auto& t : q.segments)
      if (s.face == t.face && relateChords(s.from, s.to, t.from, t.to) != ChordRelation::Disjoint) return true;
  return false;
}

void noteSelection(Layout& layout, const SelectionResult& r) {
  layout.ilpSeconds += r.seconds;
  layout.iterations += 1;
  layout.ilpStalled += r.stalledParts;
  layout.ilpTimeLimited += r.timeLimitedParts;
  if (r.timeLimitedParts > 0) layout.ilpTimeLimitHit = true;
  if (r.status == IntegerProgram::Status::TimeLimit || r.status == IntegerProgram::Status::Stalled) {
    layout.messages.push_back("0-1 program " + std::to_string(layout.iterations) + ": " + r.message);
  }
}

/// A line per port that propagation ended at a t-junction or could not resolve, with why the
/// solving cycle and the completion left it.
void nameLeftPorts(const GeodesicGraph& graph, Layout& layout) {
  auto name = [&](int port, const std::string& what) {
    std::string line = "port " + std::to_string(port) + " (singularity at vertex " +
                       std::to_string(graph.ports()[port].vertex) + ") " + what;
    auto why = layout.completion.reasons.find(port);
    if (why != layout.completion.reasons.end()) line += ": " + why->second;
    layout.leftPorts.push_back(line);
  };
  for (const auto& s : layout.separatrices)
    if (s.kind == LayoutSeparatrix::TJunction)
      name(s.portA, layout.borderOutOfReach.count(s.portA)
                        ? "ends at a t-junction (no field-coherent path from it reaches the border or a dangling port, "
                          "even crossing the layout orthogonally)"
                        : "ends at a t-junction");
  for (int p : layout.unresolvedPorts) name(p, "is left unresolved: no path from it reaches a separatrix, the border or another port");
}

}  // namespace

BarrierSet layoutBarriers(const GeodesicGraph& graph, const Layout& layout) {
  BarrierSet b(graph.mesh().numFaces());
  std::vector<std::pair<const TracedPath*, int>> paths;
  paths.reserve(layout.separatrices.size());
  for (int i = 0; i < int(layout.separatrices.size()); ++i) paths.push_back({&layout.separatrices[i].path, i});
  b.add(paths);
  return b;
}

void LayoutParameters::validate() const {
  if (!(ilpTimeLimit >= 1) || !std::isfinite(ilpTimeLimit))
    throw std::invalid_argument("ilp_time_limit must be at least 1 second");
  if (ilpStallNodes < 0) throw std::invalid_argument("ilp_stall must be 0 or more nodes");
  if (maxIterations < 1) throw std::invalid_argument("the solving cycle needs at least one iteration");
  if (completionTrials < 0) throw std::invalid_argument("completion_trials must be 0 or more");
}

std::vector<char> usedPorts(const GeodesicGraph& graph, const Layout& layout) {
  std::vector<char> used(graph.ports().size(), 0);
  for (const auto& s : layout.separatrices) {
    if (s.portA >= 0) used[s.portA] = 1;
    if (s.portB >= 0) used[s.portB] = 1;
  }
  return used;
}

std::vector<int> danglingPorts(const GeodesicGraph& graph, const Layout& layout) {
  const std::vector<char> used = usedPorts(graph, layout);
  std::vector<int> dangling;
  for (int p = 0; p < int(used.size()); ++p)
    if (!used[p]) dangling.push_back(p);
  return dangling;
}

void runSolvingCycle(const GeodesicGraph& graph, Layout& layout, const LayoutParameters& params,
                     const SelectionWeights weights, const std::vector<char>* sourcesOnly, int maxSinks,
                     double maxLength) {
  // A search that ran out of graph before finding as many sinks as it was allowed proves the
  // sinks it did not find out of reach of its port, and they stay out of reach in later
  // rounds: the barriers only grow. Later searches leave them out, so they stop once the sinks
  // still in reach are found, and a port with none left is not searched.
  const int numPorts = int(graph.ports().size());
  SinksOutOfReach outOfReach(numPorts);
  for (int round = 0; round + 1 < params.maxIterations; ++round) {
    const std::vector<int> dangling = danglingPorts(graph, layout);
    std::vector<char> free(numPorts, 0);
    for (int p : dangling) free[p] = 1;
    if (dangling.size() < 2) break;  // a separatrix needs two free ports
    auto start = Clock::now();
    BarrierSet barriers = layoutBarriers(graph, layout);
    std::vector<int> sources;
    std::vector<SearchOptions> options;
    for (int p : dangling) {
      if (sourcesOnly && !(*sourcesOnly)[p]) continue;
      SearchOptions o;
      o.maxSinks = maxSinks > 0 ? maxSinks : graph.parameters().k;
      o.maxLength = maxLength;
      o.barriers = &barriers;
      o.sinkAllowed = outOfReach.allowedFrom(p, free);
      if (std::count(o.sinkAllowed.begin(), o.sinkAllowed.end(), 1) == 0) continue;
      sources.push_back(p);
      options.push_back(std::move(o));
    }
    if (sources.empty()) break;
    auto searches = traceFromPorts(graph, sources, options);
    for (std::size_t i = 0; i < searches.size(); ++i)
      outOfReach.note(sources[i], options[i].sinkAllowed, options[i].maxSinks, searches[i]);
    SeparatrixGraph more = buildSeparatrixGraph(graph, searches);
    layout.cycleTracingSeconds += since(start);
    if (more.arcs.empty()) break;
    SelectionScope scope;
    scope.portFree = free;
    scope.coverageFirst = weights == SelectionWeights::CoverageFirst;
    SelectionResult r = selectSeparatricesIn(more, scope, params.ilpTimeLimit, params.ilpStallNodes);
    noteSelection(layout, r);
    if (r.selected.empty()) break;
    const int iteration = layout.iterations;
    for (int a : r.selected) {
      const auto& c = more.arcs[a];
      layout.separatrices.push_back({LayoutSeparatrix::Full, c.portA, c.portB, iteration, c.path});
    }
  }
}

void propagateDanglingPorts(const GeodesicGraph& graph, Layout& layout) {
  const int numPorts = int(graph.ports().size());
  std::vector<char> failed(numPorts, 0);
  for (;;) {
    std::vector<int> dangling = danglingPorts(graph, layout);
    std::vector<char> free(numPorts, 0);
    for (int p : dangling) free[p] = 1;
    // Ports that reached nothing before stay sinks, but are not searched from again.
    dangling.erase(std::remove_if(dangling.begin(), dangling.end(), [&](int p) { return failed[p] != 0; }), dangling.end());
    if (dangling.empty()) break;
    BarrierSet barriers = layoutBarriers(graph, layout);
    SearchOptions options;
    options.maxSinks = 1;
    options.barriers = &barriers;
    options.tJunctionMode = true;
    options.sinkAllowed = free;
    auto results = traceFromPorts(graph, dangling, options);
    // The own sink is excluded by sinkAllowed only if the port is not free: drop it here.
    std::vector<const TracedPath*> best(dangling.size(), nullptr);
    for (std::size_t i = 0; i < results.size(); ++i)
      for (const auto& p : results[i])
        if (p.sinkPort != dangling[i]) best[i] = &p;
    // On a surface with a border, a port whose path ends at a t-junction but can reach the
    // border (or another dangling port) across the layout, crossing separatrices orthogonally,
    // goes there instead: a conforming line, where a t-junction is not.
    std::vector<std::vector<TracedPath>> acrossResults;
    std::vector<std::size_t> atBarrier;
    if (graph.mesh().numBorderLoops() > 0)
      for (std::size_t i = 0; i < best.size(); ++i)
        if (best[i] && best[i]->end == TracedPath::Barrier) atBarrier.push_back(i);
    if (!atBarrier.empty()) {
      SearchOptions across = options;
      across.tJunctionMode = false;
      across.borderEnds = true;
      std::vector<int> ports;
      for (std::size_t i : atBarrier) ports.push_back(dangling[i]);
      acrossResults = traceFromPorts(graph, ports, across);
      for (std::size_t j = 0; j < atBarrier.size(); ++j) {
        bool reached = false;
        for (const auto& p : acrossResults[j])
          if (p.end != TracedPath::Barrier && p.sinkPort != ports[j]) best[atBarrier[j]] = &p, reached = true;
        if (reached) layout.borderOutOfReach.erase(ports[j]);
        else layout.borderOutOfReach.insert(ports[j]);
      }
    }
    std::vector<const TracedPath*> found;
    for (std::size_t i = 0; i < best.size(); ++i) {
      if (best[i]) found.push_back(best[i]);
      else failed[dangling[i]] = 1;
    }
    std::sort(found.begin(), found.end(), [](const TracedPath* a, const TracedPath* b) {
      return a->length != b->length ? a->length < b->length : a->sourcePort < b->sourcePort;
    });
    std::vector<const TracedPath*> accepted;
    std::vector<char> takenThisRound(numPorts, 0);
    for (const TracedPath* p : found) {
      if (takenThisRound[p->sourcePort]) continue;
      if (p->end == TracedPath::Sink && takenThisRound[p->sinkPort]) continue;
      bool meets = false;
      for (const TracedPath* q : accepted) meets = meets || pathsMeet(*p, *q);
      if (meets) continue;
      accepted.push_back(p);
      takenThisRound[p->sourcePort] = 1;
      LayoutSeparatrix s;
      s.portA = p->sourcePort;
      s.path = *p;
      s.iteration = 0;
      if (p->end == TracedPath::Sink) {
        s.kind = LayoutSeparatrix::Full;
        s.portB = p->sinkPort;
        takenThisRound[p->sinkPort] = 1;
      } else if (p->end == TracedPath::Barrier) {
        s.kind = LayoutSeparatrix::TJunction;
        ++layout.tJunctions;
      } else {
        s.kind = LayoutSeparatrix::Border;
        ++layout.borderConnections;
      }
      layout.separatrices.push_back(std::move(s));
    }
    if (accepted.empty()) break;
  }
  for (int p = 0; p < numPorts; ++p)
    if (failed[p]) layout.unresolvedPorts.push_back(p);
}

Layout solveLayout(const GeodesicGraph& graph, const SeparatrixGraph& candidates, const LayoutParameters& params) {
  params.validate();
  Layout layout;

  // 1. The first 0-1 program on all candidates.
  SelectionResult first = selectSeparatrices(candidates, {}, params.ilpTimeLimit, params.ilpStallNodes);
  noteSelection(layout, first);
  // 1b. More ports covered: the neighbourhoods of the dangling ports selected again, coverage first.
  if (params.coverageRepair) {
    layout.coverageRepair = repairCoverage(candidates, first.selected, params.ilpTimeLimit, params.ilpStallNodes);
    layout.ilpSeconds += layout.coverageRepair.seconds;
    layout.ilpStalled += layout.coverageRepair.stalledParts;
    layout.ilpTimeLimited += layout.coverageRepair.timeLimitedParts;
    if (layout.coverageRepair.timeLimitedParts > 0) layout.ilpTimeLimitHit = true;
  }
  for (int a : first.selected) {
    const auto& c = candidates.arcs[a];
    layout.separatrices.push_back({LayoutSeparatrix::Full, c.portA, c.portB, 1, c.path});
  }
  layout.selectedFromCandidates = int(first.selected.size());

  // 2. The solving cycle.
  runSolvingCycle(graph, layout, params, SelectionWeights::Length);
  // 2b. Completion: the separatrices that keep dangling ports apart are freed and the ports
  // around them matched again, where that leaves fewer t-junctions.
  if (params.completionTrials > 0) {
    const auto start = Clock::now();
    layout.completion = completeLayout(graph, layout, params);
    layout.completionSeconds = since(start);
  }
  layout.danglingAfterCycle = int(danglingPorts(graph, layout).size());
  if (!params.propagate) return layout;

  // 3. Propagation from the ports still dangling.
  auto start = Clock::now();
  propagateDanglingPorts(graph, layout);
  nameLeftPorts(graph, layout);
  layout.deadEndsRemoved = removeDeadEnds(graph, layout);
  if (layout.deadEndsRemoved > 0)
    layout.messages.push_back(std::to_string(layout.deadEndsRemoved) +
                              " separatrices removed: they ended at a singularity no other separatrix reaches "
                              "(its other ports unresolved, or a singularity of index 3/4 with a single port), "
                              "which would leave a slit inside a patch");
  layout.propagationSeconds = since(start);
  return layout;
}

std::vector<char> SinksOutOfReach::allowedFrom(int port, const std::vector<char>& free) const {
  std::vector<char> allowed(free.begin(), free.end());
  allowed.at(port) = 0;  // a port's own sink is never a target
  if (!far_.at(port).empty())
    for (std::size_t q = 0; q < allowed.size(); ++q)
      if (far_[port][q]) allowed[q] = 0;
  return allowed;
}

void SinksOutOfReach::note(int port, const std::vector<char>& allowed, int maxSinks, const std::vector<TracedPath>& found) {
  // Stopped at its k-th sink: nothing shown out of reach. (Fewer than k found, all it was
  // allowed among them, also shows nothing: every one found is cleared below.)
  if (int(found.size()) >= maxSinks) return;
  std::vector<char>& far = far_.at(port);
  if (far.empty()) far.assign(allowed.size(), 0);
  for (std::size_t q = 0; q < allowed.size(); ++q)
    if (allowed[q]) far[q] = 1;
  for (const TracedPath& path : found)
    if (path.end == TracedPath::Sink) far.at(path.sinkPort) = 0;
}

int removeDeadEnds(const GeodesicGraph& graph, Layout& layout) {
  const auto& ports = graph.ports();
  const SurfaceMesh& mesh = graph.mesh();
  const int n = int(layout.separatrices.size());
  std::vector<char> removed(n, 0);
  // Separatrices ending at each interior singular vertex (both ends of a loop count).
  std::map<int, std::vector<int>> endsAt;
  // The interior singular vertices at the two ends of separatrix i (−1 for none).
  auto interiorEnds = [&](int i) {
    std::array<int, 2> ends{};
    const LayoutSeparatrix& s = layout.separatrices[i];
    const int endPorts[2] = {s.portA, s.portB};
    for (int e = 0; e < 2; ++e) {
      const int p = endPorts[e];
      const int v = p >= 0 && p < int(ports.size()) ? ports[p].vertex : -1;
      ends[e] = v >= 0 && !mesh.isBorderVertex(v) ? v : -1;
    }
    return ends;
  };
  for (int i = 0; i < n; ++i)
    for (int v : interiorEnds(i))
      if (v >= 0) endsAt[v].push_back(i);
  // T-junction paths that end on each separatrix: they would dangle without it.
  std::vector<std::vector<int>> endingOn(n);
  for (int i = 0; i < n; ++i) {
    const auto& s = layout.separatrices[i];
    if (s.kind == LayoutSeparatrix::TJunction && s.path.barrier >= 0 && s.path.barrier < n)
      endingOn[s.path.barrier].push_back(i);
  }
  auto liveEnds = [&](int v) {
    int count = 0;
    for (int i : endsAt[v]) count += removed[i] ? 0 : 1;
    return count;
  };
  std::vector<int> stack;
  for (const auto& [v, list] : endsAt)
    if (list.size() == 1) stack.push_back(list[0]);
  int count = 0;
  while (!stack.empty()) {
    int i = stack.back();
    stack.pop_back();
    if (removed[i]) continue;
    removed[i] = 1;
    ++count;
    for (int v : interiorEnds(i))
      if (v >= 0 && liveEnds(v) == 1)
        for (int j : endsAt[v])
          if (!removed[j]) stack.push_back(j);
    for (int j : endingOn[i]) stack.push_back(j);
  }
  if (count == 0) return 0;
  // Compact, renumbering the separatrices that t-junction ends name.
  std::vector<int> removedPorts;
  for (int i = 0; i < n; ++i)
    if (removed[i])
      for (int p : {layout.separatrices[i].portA, layout.separatrices[i].portB})
        if (p >= 0) removedPorts.push_back(p);
  std::vector<int> newIndex(n, -1);
  std::vector<LayoutSeparatrix> kept;
  for (int i = 0; i < n; ++i)
    if (!removed[i]) newIndex[i] = int(kept.size()), kept.push_back(std::move(layout.separatrices[i]));
  // The ports of removed separatrices are dangling again.
  layout.unresolvedPorts.insert(layout.unresolvedPorts.end(), removedPorts.begin(), removedPorts.end());
  std::sort(layout.unresolvedPorts.begin(), layout.unresolvedPorts.end());
  layout.unresolvedPorts.erase(std::unique(layout.unresolvedPorts.begin(), layout.unresolvedPorts.end()),
                               layout.unresolvedPorts.end());
  for (auto& s : kept) {
    if (s.path.barrier < 0 || s.path.barrier >= n) continue;
    s.path.barrier = newIndex[s.path.barrier];
    if (!s.path.points.empty() && s.path.points.back().kind == PathPoint::Crossing) s.path.points.back().id = s.path.barrier;
  }
  layout.separatrices = std::move(kept);
  layout.tJunctions = 0;
  layout.borderConnections = 0;
  for (const auto& s : layout.separatrices) {
    layout.tJunctions += s.kind == LayoutSeparatrix::TJunction;
    layout.borderConnections += s.kind == LayoutSeparatrix::Border;
  }
  return count;
}

}  // namespace fcql
