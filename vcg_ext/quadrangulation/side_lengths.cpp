#include "quadrangulation/side_lengths.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace fcql {

int SideLengths::sideLength(const PatchGraph& g, int p, int k) const {
  int n = 0;
  for (const auto& s : g.patches[p].sides[k]) n += segments[s.segment];
  return n;
}

namespace {

constexpr double kUnderWeight = 3.0;
constexpr double kMaxStretch = 1.5;

int findRoot(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

/// Whether the opposite sides k and k + 2 of ps are one segment each (a hard equality that
/// the classes below make implicit).
bool singleSegmentPair(const PatchSides& ps, int k) {
  return ps.sides[k].size() == 1 && ps.sides[k + 2].size() == 1;
}

SideLengths solve(const PatchGraph& graph, double targetEdgeLength, double timeLimitSeconds, bool honourForced) {
  const int ns = int(graph.segments.size());
  // Segments that must be equal because they are the single-segment opposite sides of a
  // patch form classes (the chords of the layout): one integer variable per class.
  std::vector<int> parent(ns);
  for (int s = 0; s < ns; ++s) parent[s] = s;
  for (const PatchSides& ps : graph.patches)
    for (int k = 0; k < 2 && ps.active; ++k)
      if (singleSegmentPair(ps, k))
        parent[findRoot(parent, ps.sides[k][0].segment)] = findRoot(parent, ps.sides[k + 2][0].segment);

  IntegerProgram ip;
  std::vector<int> classVariable(ns, -1), n(ns);
  std::vector<double> ideal(ns), classMaxIdeal(ns, 0.0);
  for (int s = 0; s < ns; ++s) {
    ideal[s] = graph.segments[s].length / targetEdgeLength;
    const int root = findRoot(parent, s);
    classMaxIdeal[root] = std::max(classMaxIdeal[root], ideal[s]);
  }
  for (int s = 0; s < ns; ++s) {
    const int root = findRoot(parent, s);
    // No segment of a class is sampled more than kMaxStretch times coarser than the target.
    const double lower = std::max(1.0, std::floor(classMaxIdeal[root] / kMaxStretch));
    if (classVariable[root] < 0)
      classVariable[root] = ip.addVariable(lower, 4 * std::ceil(classMaxIdeal[root]) + 4, true, 0);
    n[s] = classVariable[root];
    // t_s ≥ n_s − ideal_s and t_s ≥ kUnderWeight·(ideal_s − n_s): a chord crossing patches of
    // different widths gets a count nearer to its wide patches than the plain median, so no
    // patch is sampled much more coarsely than the target (which would lose the shape).
    const int t = ip.addVariable(0, std::numeric_limits<double>::infinity(), false, 1.0);
    ip.addConstraint({{t, 1}, {n[s], -1}}, IntegerProgram::Sense::GreaterEqual, -ideal[s]);
    ip.addConstraint({{t, 1}, {n[s], kUnderWeight}}, IntegerProgram::Sense::GreaterEqual, kUnderWeight * ideal[s]);
  }
  const double softWeight = 10.0 * kUnderWeight * (1 + ns);  // any mismatch costs more than all rounding
  for (const PatchSides& ps : graph.patches)
    for (int k = 0; k < 2 && ps.active; ++k) {
      if (singleSegmentPair(ps, k)) continue;
      // Σa − Σb, with the terms of one class gathered.
      std::map<int, double> sum;
      for (const auto& s : ps.sides[k]) sum[n[s.segment]] += 1.0;
      for (const auto& s : ps.sides[k + 2]) sum[n[s.segment]] -= 1.0;
      std::vector<std::pair<int, double>> diff;
      for (const auto& term : sum)
        if (term.second != 0) diff.push_back(term);
      if (diff.empty()) continue;
      if (honourForced && ps.forceEqual) {
        ip.addConstraint(diff, IntegerProgram::Sense::Equal, 0);
        continue;
      }
      // d ≥ |Σa − Σb|
      int d = ip.addVariable(0, std::numeric_limits<double>::infinity(), false, softWeight);
      auto plus = diff, minus = diff;
      plus.push_back({d, 1.0});
      for (auto& term : minus) term.second = -term.second;
      minus.push_back({d, 1.0});
      ip.addConstraint(plus, IntegerProgram::Sense::GreaterEqual, 0);
      ip.addConstraint(minus, IntegerProgram::Sense::GreaterEqual, 0);
    }
  // A 1% gap cannot hide a mismatch (each costs softWeight, more than 1% of any objective
  // made of rounding terms alone) and spares branch and bound most of its work.
  ip.setRelativeGap(0.01);
  IntegerProgram::Result r = ip.solve(timeLimitSeconds);
  if (!r.hasSolution()) {
    // Forced equalities that cannot all hold (or that lp_solve cannot settle in time): solve
    // again with them soft; the patches that then disagree are split once more.
    if (honourForced && (r.status == IntegerProgram::Status::Infeasible || r.status == IntegerProgram::Status::Failed))
      return solve(graph, targetEdgeLength, timeLimitSeconds, false);
    throw std::runtime_error("side lengths: " + r.message);
  }
  SideLengths out;
  out.status = r.status;
  out.message = r.message;
  out.seconds = r.seconds;
  out.segments.resize(ns);
  for (int s = 0; s < ns; ++s) out.segments[s] = int(std::lround(r.values[n[s]]));
  for (int p = 0; p < int(graph.patches.size()); ++p)
    if (graph.patches[p].active &&
        (out.sideLength(graph, p, 0) != out.sideLength(graph, p, 2) || out.sideLength(graph, p, 1) != out.sideLength(graph, p, 3)))
      out.inconsistentPatches.push_back(p);
  return out;
}

}  // namespace

SideLengths solveSideLengths(const PatchGraph& graph, double targetEdgeLength, double timeLimitSeconds) {
  if (!(targetEdgeLength > 0)) throw std::invalid_argument("the target quad edge length must be positive");
  return solve(graph, targetEdgeLength, timeLimitSeconds, true);
}

}  // namespace fcql
