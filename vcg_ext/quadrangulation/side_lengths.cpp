#include "quadrangulation/side_lengths.h"

#include "util/union_find.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace fcql {

int SideLengths::sideLength(const PatchGraph& g, int p, int k) const {
  int n = 0;
  for (const auto& s : g.patches[p].sides[k]) n += segments[s.segment];
  return n;
}

namespace {

constexpr double kUnderWeight = 3.0;
/// Branch and bound per part, in nodes so that the same input gives the same quads on any
/// machine however busy: a part of at most kSmallProgramVariables variables gets up to
/// kSmallProgramNodes, a larger one kLargeProgramNodes (lp_solve finds a solution quickly and
/// then spends its time on proving optimality, which the dragon's parts of thousands of
/// variables never reach). On the project's machine a small part runs about 6,700 nodes a
/// second (the dragon's part of 112 variables: 8,610 nodes, 1.3 s, optimal), and the dragon's
/// parts of 1,300–2,300 variables take 0.5–2.5 s for their 1,500 nodes. With 300 nodes those
/// parts mostly stopped without any solution, were rounded instead, and their zero chains did
/// not settle in 8 rounds. The time left of the whole limit stays as a safety stop, reported
/// when it is reached.
constexpr int kSmallProgramVariables = 1000;
constexpr long kSmallProgramNodes = 50000;
constexpr long kLargeProgramNodes = 1500;
/// Every part's branch and bound takes the lower branch of a count first (lp_solve's default
/// is the upper one) and stops once this many nodes brought no better solution. Measured on the
/// dragon: its first part of 638 variables took 11,304 nodes (13 s) with upper branches first
/// to prove within the 1% gap what lower branches first find and prove in 286 (0.3 s); its
/// parts of ~1,000 variables spent their 1,500 nodes (3–5 s each) on no better solution than
/// they held after 300. With both its counts settle in 5 rounds (59 patches split) instead of
/// 6 (64). The other shared meshes' parts are solved to optimality either way, with the same
/// counts.
constexpr long kStallNodes = 300;
constexpr double kMaxStretch = 1.5;
/// Warm rounds solve the classes of the patches a split changed and of the equalities up to
/// this many steps from them (see keptCounts). On the dragon: 1 ring let the mismatches spread
/// (87 → 17 → 21 → 11 → 23 ... patches split a round, never settling), 3 settle in four rounds
/// (87 → 9 → 6 → 3 → 0) as the whole program did (104 patches split in four rounds).
constexpr int kWarmRings = 3;

/// Whether the opposite sides k and k + 2 of ps are one segment each (a hard equality that
/// the classes below make implicit).
bool singleSegmentPair(const PatchSides& ps, int k) {
  return ps.sides[k].size() == 1 && ps.sides[k + 2].size() == 1;
}

/// Rounding cost of count n for a class whose segments have these ideal counts:
/// Σ max(n − ideal, kUnderWeight·(ideal − n)).
double roundingCost(int n, const std::vector<double>& ideals) {
  double cost = 0;
  for (double ideal : ideals) cost += std::max(n - ideal, kUnderWeight * (ideal - n));
  return cost;
}

/// The linear pieces (slope, intercept) of roundingCost as a function of a real n that hold
/// somewhere in [lower, upper]: between consecutive ideals, those below n count n − ideal and
/// the others kUnderWeight·(ideal − n). Their maximum equals the cost on [lower, upper].
std::vector<std::pair<double, double>> roundingCostPieces(std::vector<double> ideals, double lower, double upper) {
  std::sort(ideals.begin(), ideals.end());
  const int m = int(ideals.size());
  double below = 0, above = 0;  // sums of the ideals below and above n
  for (double ideal : ideals) above += ideal;
  std::vector<std::pair<double, double>> pieces;
  for (int j = 0; j <= m; ++j) {  // piece j: n between ideals[j − 1] and ideals[j]
    if (j > 0) below += ideals[j - 1], above -= ideals[j - 1];
    const double from = j > 0 ? ideals[j - 1] : -std::numeric_limits<double>::infinity();
    const double to = j < m ? ideals[j] : std::numeric_limits<double>::infinity();
    if (to < lower || from > upper) continue;
    pieces.push_back({j - kUnderWeight * (m - j), -below + kUnderWeight * above});
  }
  return pieces;
}

/// An equality between the opposite sides of a patch that do not reduce to one class each:
/// Σ (coefficient · class count) + constant = 0, exactly if `forced`, else in the L1 sense.
/// The constant gathers the classes kept at their last counts (warm rounds).
struct SideEquality {
  std::vector<std::pair<int, double>> terms;  ///< (class, coefficient)
  bool forced;
  double constant = 0;
};

struct Component {
  std::vector<int> classes;
  std::vector<int> equalities;
};

/// The program of one component: class counts, rounding terms, its equalities;
/// `variableOf` maps each class to its variable.
IntegerProgram componentProgram(const Component& c, const std::vector<SideEquality>& equalities,
                                const std::vector<std::vector<double>>& idealsOf, const std::vector<double>& lowerOf,
                                const std::vector<double>& upperOf, double softWeight, bool honourForced,
                                std::map<int, int>& variableOf) {
  IntegerProgram ip;
  variableOf.clear();
  for (int cls : c.classes) {
    const int n = ip.addVariable(lowerOf[cls], upperOf[cls], true, 0);
    variableOf[cls] = n;
    // The class's rounding cost Σ max(n − ideal, kUnderWeight·(ideal − n)) over its segments:
    // a chord crossing patches of different widths gets a count nearer to its wide patches
    // than the plain median, so no patch is sampled much more coarsely than the target (which
    // would lose the shape). The sum is convex and piecewise linear in n, so one variable
    // t ≥ each linear piece stands for it exactly; pieces that hold only outside the class's
    // bounds are left out. (One t per segment, as before, made the dragon's largest part a
    // program of 12K variables whose relaxation alone took lp_solve 20 s.)
    const int t = ip.addVariable(0, std::numeric_limits<double>::infinity(), false, 1.0);
    for (const auto& piece : roundingCostPieces(idealsOf[cls], lowerOf[cls], upperOf[cls]))
      ip.addConstraint({{t, 1}, {n, -piece.first}}, IntegerProgram::Sense::GreaterEqual, piece.second);
  }
  for (int e : c.equalities) {
    std::vector<std::pair<int, double>> diff;
    for (const auto& term : equalities[e].terms) diff.push_back({variableOf.at(term.first), term.second});
    const double constant = equalities[e].constant;
    if (honourForced && equalities[e].forced) {
      ip.addConstraint(diff, IntegerProgram::Sense::Equal, -constant);
      continue;
    }
    // d ≥ |Σa − Σb|
    const int d = ip.addVariable(0, std::numeric_limits<double>::infinity(), false, softWeight);
    auto plus = diff, minus = diff;
    plus.push_back({d, 1.0});
    for (auto& term : minus) term.second = -term.second;
    minus.push_back({d, 1.0});
    ip.addConstraint(plus, IntegerProgram::Sense::GreaterEqual, -constant);
    ip.addConstraint(minus, IntegerProgram::Sense::GreaterEqual, constant);
  }
  // A 1% gap cannot hide a mismatch (each costs softWeight, more than 1% of any objective
  // made of rounding terms alone) and spares branch and bound most of its work.
  ip.setRelativeGap(0.01);
  return ip;
}

int statusRank(IntegerProgram::Status s) { return s == IntegerProgram::Status::Optimal ? 0 : 1; }

/// One ring more of classes solved again: a class solved again changes the opposite-side
/// equalities it is in, whose other classes are solved again too, so that they can make up for it.
void growSolved(const PatchGraph& graph, const std::vector<int>& classOf, std::vector<char>& solved) {
  const std::vector<char> before = solved;
  for (const PatchSides& ps : graph.patches)
    for (int k = 0; k < 2 && ps.active; ++k) {
      bool any = false;
      for (int j : {k, k + 2})
        for (const auto& ss : ps.sides[j]) any = any || before[classOf[ss.segment]];
      if (!any) continue;
      for (int j : {k, k + 2})
        for (const auto& ss : ps.sides[j]) solved[classOf[ss.segment]] = 1;
    }
}

/// Warm rounds: the count each class keeps from `previous` (the last round's counts, indexed
/// by the segments that existed then), or −1 for a class solved again. Solved again: the
/// classes of every segment of a patch that has a segment added since (the parts of the
/// split patches and their neighbours, whose sides were halved), so that the counts across
/// such a patch may change, and those kWarmRings equalities away (growSolved). A class of old
/// segments keeps one count: classes only split when patches are split (chords break at new
/// t-junctions, new links join new segments).
std::vector<int> keptCounts(const PatchGraph& graph, const std::vector<int>& classOf, const std::vector<int>& previous) {
  const int ns = int(graph.segments.size()), old = int(previous.size());
  std::vector<int> kept(ns, -1);
  std::vector<char> solved(ns, 0);  // classes solved again
  for (int s = 0; s < ns; ++s) {
    const int c = classOf[s];
    // (Old segments of one class that had different counts cannot happen, as said above;
    // such a class would be solved again.)
    if (s >= old || previous[s] < 1 || (kept[c] >= 0 && kept[c] != previous[s])) solved[c] = 1;
    else kept[c] = previous[s];
  }
  for (const PatchSides& ps : graph.patches) {
    if (!ps.active) continue;
    bool touched = false;
    for (const auto& side : ps.sides)
      for (const auto& ss : side) touched = touched || ss.segment >= old;
    if (!touched) continue;
    for (const auto& side : ps.sides)
      for (const auto& ss : side) solved[classOf[ss.segment]] = 1;
  }
  for (int ring = 0; ring < kWarmRings; ++ring) growSolved(graph, classOf, solved);
  for (int c = 0; c < ns; ++c)
    if (solved[c]) kept[c] = -1;
  return kept;
}

SideLengths solve(const PatchGraph& graph, double targetEdgeLength, double timeLimitSeconds, bool boundStretch,
                  const std::vector<int>* previous) {
  const auto start = std::chrono::steady_clock::now();
  const int ns = int(graph.segments.size());
  // Segments that must be equal because they are the single-segment opposite sides of a
  // patch form classes (the chords of the layout): one integer count per class.
  UnionFind chords(ns);
  for (const PatchSides& ps : graph.patches)
    for (int k = 0; k < 2 && ps.active; ++k)
      if (singleSegmentPair(ps, k)) chords.unite(ps.sides[k][0].segment, ps.sides[k + 2][0].segment);
  std::vector<int> classOf(ns);
  std::vector<std::vector<double>> idealsOf(ns);
  std::vector<double> classMaxIdeal(ns, 0.0);
  for (int s = 0; s < ns; ++s) {
    classOf[s] = chords.find(s);
    const double ideal = graph.segments[s].length / targetEdgeLength;
    idealsOf[classOf[s]].push_back(ideal);
    classMaxIdeal[classOf[s]] = std::max(classMaxIdeal[classOf[s]], ideal);
  }
  std::vector<double> lowerOf(ns), upperOf(ns);
  for (int c = 0; c < ns; ++c) {
    // No segment of a class is sampled more than kMaxStretch times coarser than the target
    // (unless that bound is dropped).
    lowerOf[c] = boundStretch ? std::max(1.0, std::floor(classMaxIdeal[c] / kMaxStretch)) : 1.0;
    upperOf[c] = 4 * std::ceil(classMaxIdeal[c]) + 4;
  }
  std::vector<int> kept(ns, -1);
  if (previous) kept = keptCounts(graph, classOf, *previous);
  // The other opposite-side pairs (sides made of several segments, at t-junctions); the
  // classes that keep their counts move into the constant, and an equality of those alone
  // drops out (it held in the last round, or its patch would have been split).
  std::vector<SideEquality> equalities;
  for (const PatchSides& ps : graph.patches)
    for (int k = 0; k < 2 && ps.active; ++k) {
      if (singleSegmentPair(ps, k)) continue;
      std::map<int, double> sum;  // Σa − Σb, with the terms of one class gathered
      for (const auto& s : ps.sides[k]) sum[classOf[s.segment]] += 1.0;
      for (const auto& s : ps.sides[k + 2]) sum[classOf[s.segment]] -= 1.0;
      SideEquality eq{{}, ps.forceEqual};
      for (const auto& term : sum)
        if (term.second != 0 && kept[term.first] >= 0) eq.constant += term.second * kept[term.first];
        else if (term.second != 0) eq.terms.push_back(term);
      if (!eq.terms.empty()) equalities.push_back(std::move(eq));
    }
  // The program splits exactly into independent components: classes linked by equalities.
  // A class in no equality just takes its best rounding; each other component is a small
  // program of its own, which lp_solve settles far faster than one program of thousands of
  // classes (the dragon's layout has 20K).
  UnionFind link(ns);
  for (const SideEquality& eq : equalities)
    for (std::size_t i = 1; i < eq.terms.size(); ++i) link.unite(eq.terms[i].first, eq.terms[0].first);
  std::map<int, Component> components;
  for (int s = 0; s < ns; ++s)
    if (classOf[s] == s && kept[s] < 0) components[link.find(s)].classes.push_back(s);
  for (int e = 0; e < int(equalities.size()); ++e)
    components[link.find(equalities[e].terms[0].first)].equalities.push_back(e);

  SideLengths out;
  std::vector<int> count(ns, 0);
  for (int c = 0; c < ns; ++c)
    if (kept[c] >= 0) count[c] = kept[c];
  const double softWeight = 10.0 * kUnderWeight * (1 + ns);  // any mismatch costs more than all rounding
  int programs = 0;
  for (const auto& entry : components) {
    const Component& c = entry.second;
    if (c.equalities.empty()) {
      for (int cls : c.classes) {
        int best = int(lowerOf[cls]);
        for (int n = best + 1; n <= int(upperOf[cls]); ++n)
          if (roundingCost(n, idealsOf[cls]) < roundingCost(best, idealsOf[cls]) - 1e-12) best = n;
        count[cls] = best;
      }
      continue;
    }
    ++programs;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double limit = std::max(1.0, timeLimitSeconds - elapsed);
    std::map<int, int> variableOf;
    // Branch and bound first, with the budget above. If it stops without proving optimality
    // or finds nothing (the dragon's layout has a part of 800 classes tied by 500 equalities),
    // the LP relaxation is rounded too and the better solution kept: a stopped branch and
    // bound may hold a poor one (in the soft program, mismatches it did not need). Forced
    // equalities that cannot all hold are made soft: the patches that then disagree are split
    // once more (zero chains).
    bool rounded = false;
    auto attempt = [&](IntegerProgram ip) {
      ip.setNodeLimit(ip.numVariables() <= kSmallProgramVariables ? kSmallProgramNodes : kLargeProgramNodes);
      ip.setBranchDownFirst(true);
      ip.setStallNodes(kStallNodes);
      IntegerProgram::Result best = ip.solve(limit);
      if (best.timeLimitReached) ++out.timeLimitedParts;
      if (best.status == IntegerProgram::Status::Optimal || best.status == IntegerProgram::Status::Infeasible) return best;
      IntegerProgram::Result other = ip.solveByRounding(limit);
      if (other.timeLimitReached) ++out.timeLimitedParts;
      if (other.hasSolution() && (!best.hasSolution() || other.objective < best.objective - 1e-9)) {
        best = std::move(other);
        rounded = true;
      }
      return best;
    };
    IntegerProgram::Result r = attempt(componentProgram(c, equalities, idealsOf, lowerOf, upperOf, softWeight, true, variableOf));
    if (!r.hasSolution()) {
      r = attempt(componentProgram(c, equalities, idealsOf, lowerOf, upperOf, softWeight, false, variableOf));
    }
    if (rounded) ++out.roundedParts;
    if (r.status == IntegerProgram::Status::WorkLimit) ++out.budgetLimitedParts;
    if (!r.hasSolution()) throw std::runtime_error("side lengths: " + r.message);
    if (statusRank(r.status) > statusRank(out.status)) out.status = r.status, out.message = r.message;
    for (int cls : c.classes) count[cls] = int(std::lround(r.values[variableOf.at(cls)]));
  }
  out.parts = int(components.size());
  out.programs = programs;
  const std::string summary = std::to_string(out.parts) + " independent parts, " + std::to_string(programs) +
                              " solved by lp_solve" +
                              (out.roundedParts > 0 ? ", " + std::to_string(out.roundedParts) +
                                                          " of them by rounding the LP relaxation (branch and bound "
                                                          "found nothing better within its node budget)"
                                                    : "");
  out.message = out.message.empty() ? summary : out.message + " (" + summary + ")";
  if (out.timeLimitedParts > 0)
    out.message += "; the safety time limit cut " + std::to_string(out.timeLimitedParts) +
                   " parts short: these quads depend on the machine's speed";
  out.segments.resize(ns);
  for (int s = 0; s < ns; ++s) out.segments[s] = count[classOf[s]];
  for (int p = 0; p < int(graph.patches.size()); ++p)
    if (graph.patches[p].active &&
        (out.sideLength(graph, p, 0) != out.sideLength(graph, p, 2) || out.sideLength(graph, p, 1) != out.sideLength(graph, p, 3)))
      out.inconsistentPatches.push_back(p);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

SideLengths solveSideLengths(const PatchGraph& graph, double targetEdgeLength, double timeLimitSeconds,
                             bool boundStretch, const std::vector<int>* previous) {
  if (!(targetEdgeLength > 0)) throw std::invalid_argument("the target quad edge length must be positive");
  return solve(graph, targetEdgeLength, timeLimitSeconds, boundStretch, previous);
}

}  // namespace fcql
