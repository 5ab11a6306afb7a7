#include "layout/coverage_repair.h"

#include "layout/separatrix_selection.h"

#include <algorithm>
#include <chrono>

namespace fcql {
namespace {

/// Steps a neighbourhood grows at most (each: the selected arcs its arcs conflict with, then
/// the arcs at their ports).
constexpr int kMaxSteps = 4;
/// Passes over the dangling ports; a pass that keeps nothing ends the repair.
constexpr int kMaxPasses = 3;
/// A port's own neighbourhood is not solved once it frees more than this many selected arcs
/// (the growth stops there): on the dragon (795 singularities) larger ones made most of the
/// repair's time (2–4 s per program of 150 freed arcs, against milliseconds below 64) for few
/// more ports covered.
constexpr std::size_t kMaxFreed = 64;
/// The neighbourhood of all dangling ports together is not solved past this many arcs (fertility
/// at k 30: 3,571 arcs in H, its two dangling ports covered only from a neighbourhood of 3,200).
constexpr std::size_t kMaxJointArcs = 6000;

class Repair {
public:
  Repair(const SeparatrixGraph& h, const std::vector<int>& selected) : h_(h), cliquesOf_(h.arcs.size()) {
    for (int c = 0; c < int(h.tangentialCliques.size()); ++c)
      for (int a : h.tangentialCliques[c]) cliquesOf_[a].push_back(c);
    isSelected_.assign(h.arcs.size(), 0);
    changedAt_.assign(h.arcs.size(), 0);
    portUsed_.assign(h.arcsAtPort.size(), 0);
    failedAt_.assign(h.arcsAtPort.size(), -1);
    for (int a : selected) setSelected(a, 1);
  }

  std::vector<int> dangling() const {
    std::vector<int> ports;
    for (int p = 0; p < int(portUsed_.size()); ++p)
      if (!portUsed_[p] && !h_.arcsAtPort[p].empty()) ports.push_back(p);
    return ports;
  }
  bool used(int port) const { return portUsed_[port] != 0; }

  std::vector<int> selection() const {
    std::vector<int> s;
    for (int a = 0; a < int(isSelected_.size()); ++a)
      if (isSelected_[a]) s.push_back(a);
    return s;
  }

  /// How far a neighbourhood grows, and whether the first one that covers more ports is kept
  /// (per port) or the best of all it grows through (all dangling ports together: a larger
  /// neighbourhood leaves less of the first program fixed, closer to solving it all anew).
  struct Growth {
    std::size_t maxFreed;
    std::size_t maxArcs;
    bool keepBest;
  };

  /// Tries the neighbourhoods of `seeds`, growing one step at a time; true if one was kept.
  bool tryPorts(const std::vector<int>& seeds, const Growth& growth, double timeLimitSeconds, long stallNodes,
                CoverageRepairReport& report, const std::chrono::steady_clock::time_point start) {
    std::vector<int> arcs, freed;  // the neighbourhood, and its selected arcs
    std::vector<char> inArcs(h_.arcs.size(), 0), inFreed(h_.arcs.size(), 0);
    auto addArcsAt = [&](int p) {
      if (p < 0) return;
      for (int a : h_.arcsAtPort[p])
        if (!inArcs[a]) inArcs[a] = 1, arcs.push_back(a);
    };
    for (int port : seeds) addArcsAt(port);
    // The best replacement found: ports gained, then the length it adds (least first).
    std::vector<int> bestFreed, bestSelected;
    int bestGain = 0;
    double bestAdded = 0;
    std::size_t grownFrom = 0;
    for (int step = 0; step < kMaxSteps; ++step) {
      std::vector<int> newlyFreed;
      for (std::size_t i = grownFrom; i < arcs.size(); ++i)
        forEachConflict(arcs[i], [&](int c) {
          if (isSelected_[c] && !inFreed[c]) inFreed[c] = 1, newlyFreed.push_back(c);
        });
      grownFrom = arcs.size();
      if (newlyFreed.empty() && step > 0) break;  // nothing more to free: the last program saw it all
      for (int c : newlyFreed) {
        freed.push_back(c);
        addArcsAt(h_.arcs[c].portA);
        addArcsAt(h_.arcs[c].portB);
      }
      if (arcs.size() > growth.maxArcs || freed.size() > growth.maxFreed) break;
      const double left =
          timeLimitSeconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (left <= 0) {  // the safety time limit: counted, as lp_solve's own stops are
        ++report.timeLimitedParts;
        break;
      }
      // The arcs that conflict with no selected arc outside the neighbourhood may be chosen.
      SelectionScope scope;
      scope.coverageFirst = true;
      scope.arcAllowed.assign(h_.arcs.size(), 0);
      int lastChange = 0;  // the latest acceptance that flipped an arc this program depends on
      for (int a : arcs) {
        bool blocked = false;
        lastChange = std::max(lastChange, changedAt_[a]);
        forEachConflict(a, [&](int c) {
          blocked = blocked || (isSelected_[c] && !inFreed[c]);
          lastChange = std::max(lastChange, changedAt_[c]);
        });
        scope.arcAllowed[a] = !blocked;
      }
      // A port that failed before, with nothing it depends on changed since: the same program,
      // the same answer.
      if (seeds.size() == 1 && failedAt_[seeds[0]] >= lastChange) continue;
      scope.portFree.assign(portUsed_.size(), 0);
      for (int p = 0; p < int(portUsed_.size()); ++p) scope.portFree[p] = !portUsed_[p];
      for (int c : freed) {
        if (h_.arcs[c].portA >= 0) scope.portFree[h_.arcs[c].portA] = 1;
        if (h_.arcs[c].portB >= 0) scope.portFree[h_.arcs[c].portB] = 1;
      }
      const SelectionResult r = selectSeparatricesIn(h_, scope, left, stallNodes);
      ++report.programs;
      report.stalledParts += r.stalledParts;
      report.timeLimitedParts += r.timeLimitedParts;
      const int gain = int(r.selected.size()) - int(freed.size());
      double added = 0;
      for (int a : r.selected) added += h_.arcs[a].length;
      for (int c : freed) added -= h_.arcs[c].length;
      if (gain > bestGain || (gain == bestGain && gain > 0 && added < bestAdded)) {
        bestGain = gain, bestAdded = added, bestFreed = freed, bestSelected = r.selected;
        if (!growth.keepBest) break;
      }
    }
    if (bestGain <= 0) {
      if (seeds.size() == 1) failedAt_[seeds[0]] = epoch_;
      return false;
    }
    ++epoch_;
    for (int c : bestFreed) setSelected(c, 0);
    for (int a : bestSelected) setSelected(a, 1);
    ++report.accepted;
    report.portsGained += 2 * bestGain;
    return true;
  }

private:
  template <class F>
  void forEachConflict(int a, F&& f) {
    for (int p : {h_.arcs[a].portA, h_.arcs[a].portB})
      if (p >= 0)
        for (int b : h_.arcsAtPort[p])
          if (b != a) f(b);
    for (int c : cliquesOf_[a])
      for (int b : h_.tangentialCliques[c])
        if (b != a) f(b);
  }

  void setSelected(int a, char on) {
    if (isSelected_[a] != on) changedAt_[a] = epoch_;
    isSelected_[a] = on;
    for (int p : {h_.arcs[a].portA, h_.arcs[a].portB})
      if (p >= 0) portUsed_[p] = on;
  }

  const SeparatrixGraph& h_;
  std::vector<std::vector<int>> cliquesOf_;
  std::vector<char> isSelected_, portUsed_;
  /// Acceptances so far; per arc, the one that last flipped it (0: none); per port, the count
  /// when its own neighbourhoods last covered nothing more (−1: never).
  int epoch_ = 0;
  std::vector<int> changedAt_, failedAt_;
};

}  // namespace

CoverageRepairReport repairCoverage(const SeparatrixGraph& h, std::vector<int>& selected, double timeLimitSeconds,
                                    long stallNodes) {
  CoverageRepairReport report;
  const auto start = std::chrono::steady_clock::now();
  Repair repair(h, selected);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    bool kept = false;
    const std::vector<int> dangling = repair.dangling();
    if (dangling.size() >= 2)
      kept = repair.tryPorts(dangling, {std::size_t(-1), kMaxJointArcs, true}, timeLimitSeconds, stallNodes, report, start);
    for (int port : repair.dangling())
      if (!repair.used(port))
        kept = repair.tryPorts({port}, {kMaxFreed, std::size_t(-1), false}, timeLimitSeconds, stallNodes, report, start) || kept;
    if (!kept) break;
  }
  selected = repair.selection();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace fcql
