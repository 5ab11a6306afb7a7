#include "quadrangulation/side_lengths.h"

#include <cmath>
#include <stdexcept>

namespace fcql {

int SideLengths::sideLength(const PatchGraph& g, int p, int k) const {
  int n = 0;
  for (const auto& s : g.patches[p].sides[k]) n += segments[s.segment];
  return n;
}

namespace {

SideLengths solve(const PatchGraph& graph, double targetEdgeLength, double timeLimitSeconds, bool honourForced) {
  IntegerProgram ip;
  const int ns = int(graph.segments.size());
  std::vector<int> n(ns), t(ns);
  for (int s = 0; s < ns; ++s) {
    double ideal = graph.segments[s].length / targetEdgeLength;
    n[s] = ip.addVariable(1, std::max(1.0, 4 * std::ceil(ideal) + 4), true, 0);
    t[s] = ip.addVariable(0, std::numeric_limits<double>::infinity(), false, 1.0);
    // t_s ≥ |n_s − ideal|
    ip.addConstraint({{t[s], 1}, {n[s], -1}}, IntegerProgram::Sense::GreaterEqual, -ideal);
    ip.addConstraint({{t[s], 1}, {n[s], 1}}, IntegerProgram::Sense::GreaterEqual, ideal);
  }
  const double softWeight = 10.0 * (1 + ns);  // any mismatch costs more than all rounding
  for (const PatchSides& ps : graph.patches)
    for (int k = 0; k < 2 && ps.active; ++k) {
      const auto& a = ps.sides[k];
      const auto& b = ps.sides[k + 2];
      std::vector<std::pair<int, double>> diff;
      for (const auto& s : a) diff.push_back({n[s.segment], 1.0});
      for (const auto& s : b) diff.push_back({n[s.segment], -1.0});
      if ((a.size() == 1 && b.size() == 1) || (honourForced && ps.forceEqual)) {
        if (!(a.size() == 1 && b.size() == 1 && a[0].segment == b[0].segment))
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
  IntegerProgram::Result r = ip.solve(timeLimitSeconds);
  if (!r.hasSolution()) {
    if (honourForced && r.status == IntegerProgram::Status::Infeasible) return solve(graph, targetEdgeLength, timeLimitSeconds, false);
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
