#include "layout/layout_completion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

namespace fcql {
namespace {

/// A set of separatrices to free, from one path between two dangling ports.
struct FreeingOption {
  std::vector<int> separatrices;  ///< indices into layout.separatrices, increasing
  double length = 0;              ///< the path's length γ
  int from = -1, to = -1;         ///< the dangling ports it joins
};

/// At most this many separatrices are freed for one path: more would rebuild a large part of
/// the layout for one pair of ports.
constexpr std::size_t kMaxFreed = 16;
/// A trial's searches stop after this many times k sinks: the few ports it frees need more
/// alternatives than the first program's searches to be matched all at once.
constexpr int kTrialSinkFactor = 1;
/// ... and seek no path longer than this many times the longest of those it replaces.
constexpr double kTrialLengthFactor = 4.0;

/// Per dangling port, its paths to the other dangling ports with no barrier in the way, and
/// what each would have to free. `reasons`, if given, gets for each dangling port why no
/// separatrix joins it yet.
/// With `reroute`, the paths may end at any port: one that ends at a port a separatrix already
/// joins frees that separatrix too, whose other port then needs a new partner (a dangling port
/// taken over, the old separatrix re-routed).
std::vector<FreeingOption> freeingOptions(const GeodesicGraph& graph, const Layout& layout,
                                          const std::vector<int>& dangling, bool reroute,
                                          std::map<int, std::string>* reasons = nullptr) {
  std::vector<char> sinks(graph.ports().size(), reroute ? 1 : 0);
  for (int p : dangling) sinks[p] = 1;
  std::vector<int> separatrixAt(graph.ports().size(), -1);
  for (int i = 0; i < int(layout.separatrices.size()); ++i)
    for (int port : {layout.separatrices[i].portA, layout.separatrices[i].portB})
      if (port >= 0) separatrixAt[port] = i;
  SearchOptions search;
  search.maxSinks = graph.parameters().k;
  search.sinkAllowed = sinks;
  const auto searches = traceFromPorts(graph, dangling, search);
  const BarrierSet barriers = layoutBarriers(graph, layout);
  std::vector<FreeingOption> options;
  for (std::size_t i = 0; i < searches.size(); ++i) {
    std::size_t fewest = std::numeric_limits<std::size_t>::max();
    int paths = 0;
    for (const TracedPath& path : searches[i]) {
      if (path.end != TracedPath::Sink || path.sinkPort == dangling[i]) continue;
      ++paths;
      std::vector<int> blockers = tangentialBlockers(path, barriers);
      if (separatrixAt[path.sinkPort] >= 0) {
        blockers.push_back(separatrixAt[path.sinkPort]);
        std::sort(blockers.begin(), blockers.end());
        blockers.erase(std::unique(blockers.begin(), blockers.end()), blockers.end());
      }
      fewest = std::min(fewest, blockers.size());
      // No blocker: the pair was reachable and the cycle chose otherwise; freeing nothing
      // changes nothing.
      if (blockers.empty() || blockers.size() > kMaxFreed) continue;
      options.push_back({std::move(blockers), path.length, dangling[i], path.sinkPort});
    }
    if (!reasons) continue;
    std::string& why = (*reasons)[dangling[i]];
    if (paths == 0)
      why = "no other dangling port can be reached from it by a field-coherent path, even across the layout";
    else if (fewest == 0)
      why = "a path to another dangling port is free, but it crosses the other new candidates tangentially";
    else if (fewest > kMaxFreed)
      why = "every path to another dangling port runs along " + std::to_string(fewest) +
            " or more separatrices (tangentially), more than are freed for one port (" + std::to_string(kMaxFreed) + ")";
    else
      why = "every path to another dangling port runs along at least " + std::to_string(fewest) +
            " separatrices (tangentially), and matching their ports again left no fewer t-junctions";
  }
  std::sort(options.begin(), options.end(), [](const FreeingOption& a, const FreeingOption& b) {
    if (a.separatrices.size() != b.separatrices.size()) return a.separatrices.size() < b.separatrices.size();
    if (a.length != b.length) return a.length < b.length;
    return a.separatrices < b.separatrices;
  });
  // The same set reached by several paths is tried once (the shortest path's place).
  std::vector<FreeingOption> distinct;
  std::set<std::vector<int>> seen;
  for (auto& o : options)
    if (seen.insert(o.separatrices).second) distinct.push_back(std::move(o));
  return distinct;
}

}  // namespace

std::vector<int> tangentialBlockers(const TracedPath& path, const BarrierSet& barriers) {
  std::vector<int> ids;
  for (std::size_t i = 0; i < path.segments.size(); ++i) {
    const PathSegment& s = path.segments[i];
    for (const auto& c : barriers.inFace(s.face))
      if (barrierContact(s, path.points[i].position, path.points[i + 1].position, c).tangential) ids.push_back(c.id);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

int propagationDefects(const GeodesicGraph& graph, const Layout& layout) {
  Layout propagated = layout;
  propagateDanglingPorts(graph, propagated);
  return propagated.tJunctions + int(propagated.unresolvedPorts.size());
}

namespace {

/// A separatrix by its two ports: what stays the same while others are freed and added.
std::pair<int, int> portsOf(const LayoutSeparatrix& s) { return {std::min(s.portA, s.portB), std::max(s.portA, s.portB)}; }

/// The indices in `layout` of the separatrices with the given ports, increasing; empty if one
/// of them is gone.
std::vector<int> findSeparatrices(const Layout& layout, const std::vector<std::pair<int, int>>& ports) {
  std::vector<int> found;
  for (const auto& wanted : ports) {
    int index = -1;
    for (int i = 0; i < int(layout.separatrices.size()) && index < 0; ++i)
      if (portsOf(layout.separatrices[i]) == wanted) index = i;
    if (index < 0) return {};
    found.push_back(index);
  }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

CompletionReport completeLayout(const GeodesicGraph& graph, Layout& layout, const LayoutParameters& params) {
  CompletionReport report;
  int current = propagationDefects(graph, layout);
  report.tJunctionsBefore = current;
  const int budget = params.completionTrials > 0
                         ? params.completionTrials + int(std::ceil(kCompletionTrialsPerDefect * current))
                         : 0;
  // Passes over the options found for the dangling ports: each option names its separatrices
  // by their ports, so that it still applies after other trials were kept. A pass that kept a
  // trial is followed by another, with the options found anew.
  // A pass that keeps nothing with paths between dangling ports is followed by one that may
  // re-route separatrices (paths to any port); one that keeps nothing either ends it.
  bool reroute = false;
  // Trials that left no fewer t-junctions, by what they freed and the pair they were for: a
  // later pass finds most of them again, and their ports' surroundings rarely changed since.
  std::set<std::pair<std::pair<int, int>, std::vector<std::pair<int, int>>>> failed;
  while (current > 0 && report.trials < budget) {
    const std::vector<int> dangling = danglingPorts(graph, layout);
    if (dangling.size() < (reroute ? 1u : 2u)) break;
    std::vector<std::pair<std::vector<std::pair<int, int>>, FreeingOption>> options;
    if (!reroute) report.reasons.clear();
    for (FreeingOption& o : freeingOptions(graph, layout, dangling, reroute, reroute ? nullptr : &report.reasons)) {
      std::vector<std::pair<int, int>> ports;
      for (int i : o.separatrices) ports.push_back(portsOf(layout.separatrices[i]));
      options.push_back({std::move(ports), std::move(o)});
    }
    bool improved = false;
    std::size_t danglingNow = dangling.size();
    for (std::size_t o = 0; o < options.size(); ++o) {
      const auto& [freedPorts, option] = options[o];
      if (current == 0) break;
      if (report.trials >= budget) {  // the ports of the options not tried could still be joined
        for (std::size_t rest = o; rest < options.size(); ++rest) report.untriedPorts.insert(options[rest].second.from);
        break;
      }
      const std::vector<char> used = usedPorts(graph, layout);
      // Its ports joined by a trial kept before: the dangling one it starts from, and the one it
      // ends at unless that is a port of a separatrix it frees (a re-route).
      const bool freesTo = std::any_of(freedPorts.begin(), freedPorts.end(), [&](const std::pair<int, int>& f) {
        return f.first == option.to || f.second == option.to;
      });
      if (used[option.from] || (used[option.to] && !freesTo)) continue;
      const std::vector<int> freed = findSeparatrices(layout, freedPorts);
      if (freed.empty()) continue;  // replaced by a trial kept before
      const auto key = std::make_pair(std::make_pair(option.from, option.to), freedPorts);
      if (failed.count(key)) continue;
      ++report.trials;
      // Only the ports this frees and the two it is for (and the dangling ports of their
      // singularities) are searched from; every free port is a sink. The other dangling ports'
      // searches would find what they found when the solving cycle settled: on the dragon,
      // searching from all ~300 of them made 90% of a trial's time and changed no trial's
      // outcome (326 -> 250 defects in 100 trials, 34 kept, either way).
      Layout trial = layout;
      // The new separatrices replace those freed and the path that showed them: none is sought
      // much longer than the longest of these (the searches would otherwise run through the
      // whole graph for sinks that barriers hide).
      double longest = option.length;
      for (int i : freed) longest = std::max(longest, layout.separatrices[i].path.length);
      const double maxLength = kTrialLengthFactor * longest;
      std::vector<char> sources(graph.ports().size(), 0);
      sources[option.from] = sources[option.to] = 1;
      for (const auto& [a, b] : freedPorts) {
        if (a >= 0) sources[a] = 1;
        if (b >= 0) sources[b] = 1;
      }
      // ... and the dangling ports of the singularities those ports belong to.
      std::vector<char> atSingularity(graph.firstPort().size(), 0);
      for (int p = 0; p < int(sources.size()); ++p)
        if (sources[p]) atSingularity[graph.ports()[p].singularity] = 1;
      for (int p : dangling)
        if (atSingularity[graph.ports()[p].singularity]) sources[p] = 1;
      for (auto it = freed.rbegin(); it != freed.rend(); ++it) trial.separatrices.erase(trial.separatrices.begin() + *it);
      runSolvingCycle(graph, trial, params, SelectionWeights::CoverageFirst, &sources,
                      kTrialSinkFactor * graph.parameters().k, maxLength);
      // A trial that leaves as many ports dangling as before never left fewer t-junctions (on
      // the dragon, 142 of 142 such trials in 200): only the others are propagated to count them.
      const std::size_t trialDangling = danglingPorts(graph, trial).size();
      const int defects = trialDangling < danglingNow ? propagationDefects(graph, trial) : current;
      if (defects < current) {
        report.freedSeparatrices += int(freed.size());
        ++report.accepted;
        // The trials' programs and searches count in the completion's time, not twice.
        trial.ilpSeconds = layout.ilpSeconds;
        trial.cycleTracingSeconds = layout.cycleTracingSeconds;
        layout = std::move(trial);
        current = defects;
        danglingNow = trialDangling;
        improved = true;
      } else {
        failed.insert(key);
      }
    }
    if (improved) {
      reroute = false;
    } else if (!reroute) {
      reroute = true;
    } else {
      break;
    }
  }
  report.tJunctionsAfter = current;
  for (auto& [port, why] : report.reasons)
    if (report.untriedPorts.count(port))
      why += " (the completion's " + std::to_string(budget) +
             " trials were used up before all its options were tried: --completion-trials)";
  return report;
}

}  // namespace fcql
