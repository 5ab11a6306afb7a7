#include "quadrangulation/quadrangulation.h"

#include "mesh/closest_point_index.h"
#include "metrics/quad_quality.h"
#include "quadrangulation/far_point_snapping.h"
#include "util/worker_threads.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <future>
#include <limits>
#include <map>
#include <tuple>
#include <optional>
#include <stdexcept>

namespace fcql {

int dissolveTwoValentVertices(QuadMesh& mesh) {
  int dissolved = 0;
  for (bool again = true; again;) {
    again = false;
    std::vector<std::vector<int>> quadsOf(mesh.positions.size());
    for (int q = 0; q < mesh.numQuads(); ++q)
      for (int v : mesh.quads[q]) quadsOf[v].push_back(q);
    std::vector<char> goneQuad(mesh.quads.size(), 0), goneVertex(mesh.positions.size(), 0), touched(mesh.quads.size(), 0);
    for (int v = 0; v < mesh.numVertices(); ++v) {
      if (quadsOf[v].size() != 2) continue;
      const int qa = quadsOf[v][0], qb = quadsOf[v][1];
      if (touched[qa] || touched[qb]) continue;
      auto rotated = [&](int q) {
        std::array<int, 4> f = mesh.quads[q];
        while (f[0] != v) std::rotate(f.begin(), f.begin() + 1, f.end());
        return f;
      };
      const std::array<int, 4> A = rotated(qa), B = rotated(qb);  // (v, a, x, b), (v, b, y, a)
      if (B[1] != A[3] || B[3] != A[1] || A[2] == B[2]) continue;
      mesh.quads[qa] = {A[1], A[2], A[3], B[2]};
      goneQuad[qb] = 1;
      goneVertex[v] = 1;
      touched[qa] = touched[qb] = 1;
      ++dissolved;
      again = true;
    }
    if (!again) break;
    std::vector<int> index(mesh.positions.size(), -1);
    std::vector<Vec3> positions;
    for (int v = 0; v < mesh.numVertices(); ++v)
      if (!goneVertex[v]) index[v] = int(positions.size()), positions.push_back(mesh.positions[v]);
    std::vector<std::array<int, 4>> quads;
    std::vector<int> patches;
    for (int q = 0; q < mesh.numQuads(); ++q) {
      if (goneQuad[q]) continue;
      std::array<int, 4> f = mesh.quads[q];
      for (int& v : f) v = index[v];
      quads.push_back(f);
      if (q < int(mesh.quadPatch.size())) patches.push_back(mesh.quadPatch[q]);
    }
    mesh.positions = std::move(positions);
    mesh.quads = std::move(quads);
    mesh.quadPatch = std::move(patches);
  }
  return dissolved;
}

namespace {

/// The scaled Jacobian below which a quad of a field-aligned grid is smoothed (with the
/// vertices two rings around it) when the stage keeps that grid elsewhere (keepFieldGrid).
constexpr double kKeepFieldGridAbove = 0.5;

/// The smoothing options of a pass: with a field, towards it (per layout triangle, the field
/// of the input face it lies in).
/// Not in the layout patches marked in `meanValuePatches` (if given), which are smoothed plainly.
SmoothingOptions smoothingFor(const PatchLayout& layout, const QuadrangulationOptions& options,
                              const std::vector<char>* meanValuePatches = nullptr) {
  SmoothingOptions smoothing = options.smoothing;
  if (!options.fieldDirections.empty() && smoothing.triangleDirections.empty()) {
    smoothing.triangleDirections.assign(layout.triangles.size(), Vec3::Zero());
    for (std::size_t t = 0; t < layout.triangles.size(); ++t) {
      const int f = layout.originalFace[t], p = t < layout.patch.size() ? layout.patch[t] : -1;
      if (meanValuePatches && p >= 0 && p < int(meanValuePatches->size()) && (*meanValuePatches)[p] == kMeanValuePatch)
        continue;
      if (f >= 0 && f < int(options.fieldDirections.size())) smoothing.triangleDirections[t] = options.fieldDirections[f];
    }
  }
  if (!options.fieldDirections.empty() && options.keepFieldGrid) smoothing.keepGridAbove = kKeepFieldGridAbove;
  return smoothing;
}

/// How far a patch mark (patch_sampling.h) departs from the field-aligned map: arc-length
/// sides, then mean-value interiors as well (the marks' own values are not in that order). A
/// fallback raises a patch's mark, never lowers it.
int departure(char mark) { return mark == kMeanValuePatch ? 2 : mark == kArcLengthSides ? 1 : 0; }

/// The largest share of the layout's patches a patch-wise fallback for the distance bound may
/// touch (arc-length sides, or mean-value interiors as well) and still be kept over the
/// refinements: beyond it the fallback shears too much of the mesh. At a half, camelhead at
/// --scale 0.01 kept 53 of 115 patches with arc-length sides (14.7% of its quads more than π/16
/// off the field) and fandisk rotated and scaled 1 × 1.7 × 0.6 kept 29 of 59 (41.4%); refined
/// instead, 7.5% and 9.8%, with 1.4 and 5.4 times the quads. The dragon's fallback touches 94
/// of its 5,852 patches and stays.
constexpr double kLocalFallbackShare = 0.25;

/// Rounds of snapping quad vertices onto the surface's points the quads miss, and the scaled
/// Jacobian no quad may fall to for it (far_point_snapping.h).
constexpr int kSnapRounds = 3;
constexpr double kSnapFloor = 0.1;
/// Rings of quads around a vertex pulled onto a spike that are smoothed to follow it.
constexpr int kPullRings = 3;

/// Further rounds of reduceFolds' second way (sampling the patches around the folds again).
constexpr int kResampleRounds = 3;

/// Quads folded (scaled Jacobian <= 0), listed in `which` if given.
int foldedQuads(const QuadMesh& m, std::vector<int>* which = nullptr) {
  std::vector<double> j;
  QuadJacobian(m).all(j);
  int n = 0;
  for (int q = 0; q < int(j.size()); ++q)
    if (!(j[q] > 0)) {
      ++n;
      if (which) which->push_back(q);
    }
  return n;
}

/// How many rings (along quad edges) the region a pass smooths again grows around the
/// vertices that changed (smoothOnlyAround).
constexpr int kRefoldRings = 3;

/// The vertices of the quads of the layout patches whose marks (patch_sampling.h) differ
/// between `now` and `was` (either may be shorter: kFieldPatch beyond), added to `region`.
void markChangedPatches(const QuadMesh& m, const std::vector<char>& now, const std::vector<char>& was,
                        std::vector<char>& region) {
  auto mark = [](const std::vector<char>& marks, int p) { return p < int(marks.size()) ? marks[p] : kFieldPatch; };
  for (int q = 0; q < m.numQuads() && q < int(m.quadPatch.size()); ++q) {
    const int p = m.quadPatch[q];
    if (p >= 0 && mark(now, p) != mark(was, p))
      for (int v : m.quads[q]) region[v] = 1;
  }
}

/// Prepares `c`, just sampled (its positions its samples), to be smoothed again only around
/// `region` (per vertex): the vertices within kRefoldRings rings of it keep their samples, the
/// others take their positions in `from` (a pass smoothed before with the same quads) and are
/// frozen in `smoothing`. So a pass that changes a few patches, or the mesh around a few folds,
/// costs in proportion to them. Returns false, changing nothing, where the quads differ from
/// `from`'s or the region grows over the whole mesh.
bool smoothOnlyAround(QuadrangulationResult& c, const QuadrangulationResult& from, std::vector<char> region,
                      SmoothingOptions& smoothing) {
  if (c.mesh.quads != from.mesh.quads || c.mesh.quadPatch != from.mesh.quadPatch ||
      c.mesh.positions.size() != from.mesh.positions.size() || region.size() != c.mesh.positions.size())
    return false;
  growAcrossQuads(c.mesh, region, kRefoldRings);
  if (std::find(region.begin(), region.end(), 0) == region.end()) return false;
  smoothing.frozen.assign(region.size(), 0);
  for (std::size_t v = 0; v < region.size(); ++v)
    if (!region[v]) c.mesh.positions[v] = from.mesh.positions[v], smoothing.frozen[v] = 1;
  return true;
}

/// With a field, a pass left with folded quads: other ways to sample and smooth the same side
/// lengths. Smoothing towards the field can leave a fold the neighbours' average would have
/// undone: (0) the plain smoothing, on the same samples; (1) the patches the folds and the
/// quads around them lie in sampled again with mean-value coordinates inside and arc length on
/// their sides (the neighbours keep the field inside); (3) those patches with arc length on
/// their sides alone, the field kept inside; (2) the whole pass without the field (mean-value
/// maps, arc-length sides, plain smoothing). A candidate counts if it folds fewer than `r` and
/// `accept` takes it (given the result, which it may change, e.g. measure). Each round tries
/// (0) and (1) from `r` and keeps the one folding fewest ((0) on a tie); if neither counts in
/// the first round, (3), then (2) if (3) does not count either; up to 1 + kResampleRounds
/// rounds, while one counts (the patches sampled again can leave folds in their neighbours).
/// Returns whether one was taken. Run once, on the pass the refinements keep. (3) comes before
/// the whole pass without the field: the bunny at --scale 0.01 had one fold (scaled Jacobian
/// −0.07, on an ear) that (0) kept and (1) turned into 18; without the field, 32.8% of its quads
/// were more than π/16 off the field, with (3) 6.3% and no fold.
/// (0), (1) and (3) change the mesh only near the folds: they start from the samples within
/// kRefoldRings rings of the folds' corners (and of the patches sampled again), keep r's
/// smoothed positions elsewhere and smooth only there (SmoothingOptions::frozen), so a try
/// costs in proportion to the folds (the dragon: 0.3–0.9 s instead of 2–2.5 s for the whole
/// mesh). Where sampling again changed the mesh's connectivity (it should not: the counts are
/// the same), the whole mesh is smoothed. With two threads or more (SmoothingOptions::threads),
/// (0) and (1) run side by side, (1) then also when (0) leaves no fold (its result, or its
/// error, then dropped); the result is the same (the dragon's four rounds: 10.6 s → 7.4 s).
/// `accept` must then be safe to call from two threads.
template <class Accept>
bool reduceFolds(QuadrangulationResult& r, const PatchLayout& layout, const QuadrangulationOptions& options,
                 SampledGrids& grids, Accept&& accept) {
  std::vector<int> folded;
  int before = foldedQuads(r.mesh, &folded);
  if (options.fieldDirections.empty() || before == 0) return false;
  SmoothingOptions laplacian = options.smoothing;
  laplacian.triangleDirections.clear();
  // Candidate k: its mesh sampled and smoothed into a copy of r, with its folds; none if it
  // folds no fewer than r or is not accepted.
  // `dropped`, if given, is set once the candidate's result is no longer wanted: it then
  // stops between its sampling, its smoothing and its measuring.
  auto attempt = [&](int k,
                     const std::atomic<bool>* dropped = nullptr) -> std::optional<std::pair<QuadrangulationResult, int>> {
    auto droppedNow = [&] { return dropped && dropped->load(); };
    QuadrangulationResult c = r;
    c.restoredVertices = 0;
    c.snappedVertices = 0;
    const bool resample = k == 1 || k == 3;  // the patches around the folds sampled again
    // The vertices to smooth again (all but k = 2): around the folds' corners, and the patches
    // sampled again.
    std::vector<char> region(r.mesh.numVertices(), 0);
    for (int q : folded)
      for (int v : r.mesh.quads[q]) region[v] = 1;
    if (k > 0) {
      std::vector<char> meanValue = r.meanValuePatches;
      meanValue.resize(layout.patches.size(), 0);
      // The patches of the folded quads and of the quads around them: a fold at a patch's
      // side takes the patch across it too, the side then sampled by arc length.
      for (int q = 0; q < r.mesh.numQuads() && q < int(r.mesh.quadPatch.size()); ++q) {
        const auto& quad = r.mesh.quads[q];
        if (r.mesh.quadPatch[q] >= 0 && std::any_of(quad.begin(), quad.end(), [&](int v) { return region[v] != 0; }))
          if (const char mark = k == 3 ? kArcLengthSides : kMeanValuePatch;
              departure(meanValue[r.mesh.quadPatch[q]]) < departure(mark))
            meanValue[r.mesh.quadPatch[q]] = mark;
      }
      c.mesh = resample ? samplePatches(layout, r.graph, r.lengths, &options.fieldDirections, &meanValue, &grids)
                        : samplePatches(layout, r.graph, r.lengths, nullptr, nullptr, &grids);
      c.meanValuePatches = resample ? meanValue : std::vector<char>();
      c.boundMeanValuePatches = resample ? r.boundMeanValuePatches : 0;
      c.boundArcLengthPatches = resample ? r.boundArcLengthPatches : 0;
      c.dissolvedVertices = dissolveTwoValentVertices(c.mesh);
      c.sampledPositions = c.mesh.positions;
      if (resample && region.size() == c.mesh.positions.size())
        markChangedPatches(c.mesh, meanValue, r.meanValuePatches, region);
    }
    c.mesh.positions = c.sampledPositions;
    if (droppedNow()) return std::nullopt;
    SmoothingOptions smoothing = resample ? smoothingFor(layout, options, &c.meanValuePatches) : laplacian;
    const bool local = k != 2 && smoothOnlyAround(c, r, region, smoothing);
    c.smoothing = smoothQuadMesh(c.mesh, layout.positions, layout.triangles, smoothing);
    const int folds = foldedQuads(c.mesh);
    if (!(folds < before) || droppedNow()) return std::nullopt;
    c.report = checkQuadMesh(c.mesh);
    if (!c.report.manifold || !accept(c)) return std::nullopt;
    c.foldsResmoothed = c.foldsResmoothed || k == 0;
    c.foldsResampled = c.foldsResampled || resample;
    c.foldsSidesByArcLength = c.foldsSidesByArcLength || k == 3;
    c.foldsWithoutField = k == 2;
    // The plain smoothing of the whole mesh moves every vertex; of a region, only those.
    c.fieldGridKept = c.fieldGridKept && (resample || (k == 0 && local));
    if (local) c.smoothing.fixedVertices = r.smoothing.fixedVertices;  // the region's alone otherwise
    return std::make_pair(std::move(c), folds);
  };
  // Each round tries the first two ways from r and takes the one that folds fewest (the
  // first on a tie; the second is not tried when the first leaves no fold), the third only if
  // neither helps in the first round; the rounds go on while one helps.
  bool taken = false;
  const bool together = workerThreadCount(options.smoothing.threads, 2) >= 2;
  for (int round = 0; round <= kResampleRounds; ++round) {
    if (round > 0) {
      folded.clear();
      before = foldedQuads(r.mesh, &folded);
      if (before == 0) break;
    }
    std::optional<std::pair<QuadrangulationResult, int>> best, resampled;
    if (together) {
      // The second way on a thread of its own beside the first: both are mostly sequential
      // (untangling, fold repair, sampling), and neither reads what the other writes.
      std::atomic<bool> secondDropped{false};
      auto second = std::async(std::launch::async, [&] { return attempt(1, &secondDropped); });
      best = attempt(0);
      // (1) counts only where (0) leaves folds, as when they run one after the other: only
      // then does its result, or its error, come out. Else it is told to stop at its next
      // step (its sampling, smoothing or measuring: the dragon's last round waited 0.5 s for
      // a smoothing whose result it dropped) and waited for.
      if (!best || best->second > 0) {
        resampled = second.get();
      } else {
        secondDropped = true;
        second.wait();
      }
    } else {
      best = attempt(0);
      if (!best || best->second > 0) resampled = attempt(1);  // none can fold fewer than none
    }
    if (resampled && (!best || resampled->second < best->second)) best = std::move(resampled);
    if (!best && round == 0) best = attempt(3);
    if (!best && round == 0) best = attempt(2);
    if (!best) break;
    r = std::move(best->first);
    taken = true;
  }
  return taken;
}

/// The patch graph and its integer side lengths at one target edge length, after the
/// zero-chain splits: what a pass samples. They do not depend on the field (only the maps
/// and the smoothing do), so the passes with and without it at one size share them.
QuadrangulationResult solveCounts(const PatchLayout& layout, const QuadrangulationOptions& options) {
  QuadrangulationResult r;
  // The lower bound on the counts (no segment sampled more than 1.5 times coarser than the
  // target) can itself contradict the equalities at t-junctions, and no split then helps:
  // the counts disagree again on the parts and the splits spread. When the rounds run out,
  // the counts are solved once more without that bound before giving up.
  // Warm rounds: once a solve leaves a part at its node budget (a large program, solved again
  // whole in every round: the dragon's part of ~900 classes took 1.5–4 s a round), the later
  // rounds solve only the classes around the patches the splits changed (solveSideLengths'
  // `previous`) and keep the rest. Where every part is solved to optimality, the rounds
  // solve the whole program, as that costs little.
  bool warm = false;
  auto solveLengths = [&](const PatchGraph& graph, const std::vector<int>* previous = nullptr) {
    SideLengths lengths = solveSideLengths(graph, options.targetEdgeLength, options.ilpTimeLimit, !r.stretchBoundDropped,
                                           warm ? previous : nullptr);
    r.timeLimitedParts += lengths.timeLimitedParts;
    warm = warm || lengths.budgetLimitedParts > 0;
    return lengths;
  };
  r.graph = buildPatchGraph(layout);
  r.polygonPatches = splitPolygonPatches(r.graph, layout);
  r.lengths = solveLengths(r.graph);
  while (!r.lengths.inconsistentPatches.empty()) {
    if (r.splitRounds >= options.maxSplitRounds && !r.stretchBoundDropped) {
      r.stretchBoundDropped = true;
      r.lengths = solveLengths(r.graph);
      continue;
    }
    if (r.splitRounds >= options.maxSplitRounds && !r.splitEverything) {
      // The last resort, §4.4's worst case: every patch split once more. Each part is then a
      // quad whose four sides are single segments (two halves of the patch's segments, two
      // spokes to its centre), so no equality spans several segments and the counts always
      // agree. A patch without t-junctions becomes four quads around a regular vertex; one with
      // t-junctions gets an irregular centre, as in the rounds. It also coarsens the grid where
      // the rounds had refined it, hence only when they fail.
      std::vector<int> all;
      for (int p = 0; p < int(r.graph.patches.size()); ++p)
        if (r.graph.patches[p].active) all.push_back(p);
      r.splitPatches += int(all.size());
      r.splitEverything = true;
      splitPatches(r.graph, layout, all);
      r.lengths = solveLengths(r.graph);
      continue;
    }
    if (r.splitRounds >= options.maxSplitRounds)
      throw std::runtime_error(std::to_string(r.lengths.inconsistentPatches.size()) +
                               " patches still have unequal opposite sides after " +
                               std::to_string(options.maxSplitRounds) +
                               " rounds of zero-chain splits, the side lengths solved once more without the bound "
                               "on stretching, and every patch split once more");
    r.splitPatches += int(r.lengths.inconsistentPatches.size());
    splitPatches(r.graph, layout, r.lengths.inconsistentPatches);
    ++r.splitRounds;
    r.lengths = solveLengths(r.graph, &r.lengths.segments);
  }
  return r;
}

/// Per target edge length, the counts of a pass (or the error they failed with),
/// kept for the other passes of the stage at the same size; and the measured passes at the
/// asked size, with and without the field.
struct PassCache {
  std::map<double, QuadrangulationResult> counts;
  std::map<double, std::string> failures;
  std::map<std::tuple<double, bool, bool>, QuadrangulationResult> measured;
  /// Per target edge length and with or without the field: the patches sampled (their
  /// two-valent vertices dissolved) with no patch marked, and how many were dissolved. The
  /// passes smoothed only around the poor quads and everywhere sample the same.
  std::map<std::pair<double, bool>, std::pair<QuadMesh, int>> sampled;
  /// The patches' grids mapped so far, by all passes.
  SampledGrids grids;

  QuadrangulationResult get(const PatchLayout& layout, const QuadrangulationOptions& options) {
    const double size = options.targetEdgeLength;
    if (auto f = failures.find(size); f != failures.end()) throw std::runtime_error(f->second);
    auto it = counts.find(size);
    if (it == counts.end()) {
      try {
        it = counts.emplace(size, solveCounts(layout, options)).first;
      } catch (const std::runtime_error& e) {
        failures.emplace(size, e.what());
        throw;
      }
    }
    return it->second;
  }
};

/// One pass of the stage at one target edge length; `surface` is the topology of the layout's
/// triangles, which the quad mesh must have. Given a `previous` pass with the same counts
/// (the pass whose patches `meanValuePatches` marks again), only the patches whose marks
/// changed are smoothed again, with the vertices around them (smoothOnlyAround).
QuadrangulationResult quadrangulateOnce(const PatchLayout& layout, const QuadrangulationOptions& options,
                                        const SurfaceTopology& surface, PassCache& cache,
                                        const std::vector<char>* meanValuePatches = nullptr,
                                        const QuadrangulationResult* previous = nullptr) {
  QuadrangulationResult r = cache.get(layout, options);
  const bool field = !options.fieldDirections.empty();
  const bool marked = field && meanValuePatches;  // some patches sampled otherwise: not shared
  const std::pair<double, bool> sampledKey{options.targetEdgeLength, field};
  if (auto it = cache.sampled.find(sampledKey); it != cache.sampled.end() && !marked) {
    r.mesh = it->second.first;
    r.dissolvedVertices = it->second.second;
  } else {
    r.mesh = samplePatches(layout, r.graph, r.lengths, field ? &options.fieldDirections : nullptr,
                           marked ? meanValuePatches : nullptr, &cache.grids);
    r.dissolvedVertices = dissolveTwoValentVertices(r.mesh);
    if (!marked) cache.sampled.emplace(sampledKey, std::make_pair(r.mesh, r.dissolvedVertices));
  }
  if (marked) {
    r.meanValuePatches = *meanValuePatches;
    r.boundMeanValuePatches = int(std::count(meanValuePatches->begin(), meanValuePatches->end(), kMeanValuePatch));
    r.boundArcLengthPatches = int(std::count(meanValuePatches->begin(), meanValuePatches->end(), kArcLengthSides));
  }
  r.sampledPositions = r.mesh.positions;
  r.fieldGridKept = field && options.keepFieldGrid;
  SmoothingOptions smoothing = smoothingFor(layout, options, marked ? meanValuePatches : nullptr);
  bool local = false;
  if (previous && marked) {
    std::vector<char> region(r.mesh.numVertices(), 0);
    markChangedPatches(r.mesh, *meanValuePatches, previous->meanValuePatches, region);
    local = smoothOnlyAround(r, *previous, region, smoothing);
  }
  r.smoothing = smoothQuadMesh(r.mesh, layout.positions, layout.triangles, smoothing);
  if (local) {
    r.smoothing.fixedVertices = previous->smoothing.fixedVertices;  // the region's alone otherwise
    r.restoredVertices = previous->restoredVertices;                // kept outside the region
    r.snappedVertices = previous->snappedVertices;
  }
  r.report = checkQuadMesh(r.mesh);
  if (!r.report.manifold)
    throw std::runtime_error("the quad mesh came out non-manifold (" + r.report.problem +
                             "): the layout has a patch the sampling cannot handle");
  // The quads must cover the surface as it is: a crack (a side sampled twice) or a missing
  // patch shows as border loops or an Euler characteristic the surface does not have.
  if (r.report.borderLoops != surface.borderLoops || r.report.eulerCharacteristic != surface.eulerCharacteristic ||
      r.report.components != surface.components)
    throw std::runtime_error("the quad mesh does not have the surface's topology (" + std::to_string(r.report.borderLoops) +
                             " border loops, Euler characteristic " + std::to_string(r.report.eulerCharacteristic) + ", " +
                             std::to_string(r.report.components) + " components, where the surface has " +
                             std::to_string(surface.borderLoops) + ", " + std::to_string(surface.eulerCharacteristic) +
                             ", " + std::to_string(surface.components) + "): the layout has a patch the sampling cannot handle");
  r.targetEdgeLength = options.targetEdgeLength;
  return r;
}

/// The stage, with the counts of each size computed once for all its passes.
QuadrangulationResult quadrangulateWith(const PatchLayout& layout, const QuadrangulationOptions& asked,
                                        PassCache& cache) {
  QuadrangulationOptions options = asked;
  if (!(options.targetEdgeLength > 0)) throw std::invalid_argument("the target quad edge length must be positive");
  if (options.maxSplitRounds < 0) throw std::invalid_argument("the number of zero-chain split rounds must be >= 0");
  if (!(options.ilpTimeLimit >= 1)) throw std::invalid_argument("the side-length time limit must be at least 1 s");
  if (!(options.maxDeviation >= 0) || !std::isfinite(options.maxDeviation))
    throw std::invalid_argument("the maximum deviation must be a finite number >= 0");
  if (options.maxRefinements < 0) throw std::invalid_argument("the number of refinements must be >= 0");
  const SurfaceTopology topology = triangleMeshTopology(int(layout.positions.size()), layout.triangles);
  if (options.maxDeviation <= 0) {
    QuadrangulationResult r = quadrangulateOnce(layout, options, topology, cache);
    reduceFolds(r, layout, options, cache.grids, [](QuadrangulationResult&) { return true; });
    return r;
  }
  // The distance to the surface, measured on the layout's triangles (the input, cut), both
  // ways and densely (measureDeviation: an upper bound on the true distance decides): where it
  // may exceed the bound, sample again more finely. A chord of a curve deviates from it by
  // about h²/(8R) for edges of length h, hence the square root in the step.
  std::vector<char> used(layout.positions.size(), 0);
  for (const auto& t : layout.triangles)
    for (int v : t) used[v] = 1;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  bool any = false;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) lo = lo.cwiseMin(layout.positions[v]), hi = hi.cwiseMax(layout.positions[v]), any = true;
  if (!any) return quadrangulateOnce(layout, options, topology, cache);  // nothing to measure
  const double limit = options.maxDeviation * (hi - lo).norm();
  // Triangles are cut down to 2% of the limit, but no finer than 2e-4 of the diagonal (a
  // tiny limit would cut without end; what stays undecided then counts as too far).
  const double resolution = std::max(0.02 * limit, 2e-4 * (hi - lo).norm());
  const ClosestPointIndex surface(layout.positions, layout.triangles);
  // Smoothing may have slid vertices off a sharp tip, which the sampled mesh covered: where
  // the quads stray too far, undo it around those points (a few rounds, while it helps)
  // before sampling finer.
  // Each measurement also gives the far points the next round starts from.
  auto measure = [&](QuadrangulationResult& q, std::vector<Vec3>* farPoints = nullptr) {
    SurfaceDeviation d = measureDeviation(q.mesh, surface, limit, resolution);
    q.deviation = d.distance;
    q.deviationBound = d.bound;
    // Rounds of `move` (which moves vertices of q.mesh, given the points too far, and returns
    // how many it moved), each kept only if the measured bound drops; `count` adds them up.
    auto whileCloser = [&](int rounds, const auto& move, int& count) {
      for (int round = 0; round < rounds && q.deviationBound > limit; ++round) {
        const std::vector<Vec3> before = q.mesh.positions;
        const int moved = move(d.farPoints);
        if (moved == 0) break;
        SurfaceDeviation after = measureDeviation(q.mesh, surface, limit, resolution);
        if (!(after.bound < q.deviationBound)) {
          q.mesh.positions = before;
          break;
        }
        count += moved;
        q.deviation = after.distance;
        q.deviationBound = after.bound;
        d = std::move(after);
      }
    };
    whileCloser(
        3,
        [&](const std::vector<Vec3>& far) {
          return restoreSampledPositions(q.mesh, q.sampledPositions, far, 2 * q.targetEdgeLength);
        },
        q.restoredVertices);
    // Still too far: the spots the quads miss get a vertex each (far_point_snapping.h), a few
    // rounds while the bound drops. The refinements size their steps by the bound before.
    q.boundBeforeSnapping = q.deviationBound;
    whileCloser(
        kSnapRounds,
        [&](const std::vector<Vec3>& far) { return snapVerticesToFarPoints(q.mesh, surface, far, limit, kSnapFloor); },
        q.snappedVertices);
    // Then the spots whose vertex would spoil its quads (a spike longer than they are wide):
    // the vertex goes onto it all the same, held there while the quads within kPullRings rings
    // of it are smoothed (plainly, and untangled) to follow; each part of them is undone where
    // it folds a quad (far_point_snapping.h). The dragon with fcql's own field:
    // 20K quads 2.96 times the bound away, 1.11 times after the pulls, where snapping alone
    // left 1.82 and the stage refined three times to 192K quads.
    whileCloser(
        kSnapRounds,
        [&](const std::vector<Vec3>& far) {
          SmoothingOptions plain = options.smoothing;
          plain.triangleDirections.clear();
          return pullVerticesToFarPoints(q.mesh, layout.positions, layout.triangles, surface, far, limit, kSnapFloor,
                                         plain, kPullRings);
        },
        q.snappedVertices);
    if (farPoints) *farPoints = std::move(d.farPoints);
  };
  // A pass at the asked size, measured (and restored): cached, as the stage without the field
  // makes it both as the alternative below and as the first pass of its own stage.
  auto measuredPass = [&](const QuadrangulationOptions& o, std::vector<Vec3>* farPoints = nullptr) {
    const std::tuple<double, bool, bool> key{o.targetEdgeLength, o.fieldDirections.empty(), o.keepFieldGrid};
    if (auto it = cache.measured.find(key); it != cache.measured.end()) {
      if (farPoints && it->second.mesh.numQuads() > 0)
        *farPoints = measureDeviation(it->second.mesh, surface, limit, resolution).farPoints;
      return it->second;
    }
    QuadrangulationResult q = quadrangulateOnce(layout, o, topology, cache);
    if (q.mesh.numQuads() > 0) measure(q, farPoints);
    cache.measured.emplace(key, q);
    return q;
  };
  // The points too far are wanted only with a field (for the patch-wise fallback below): the
  // stage without it may find its pass measured already, and need not measure it again.
  std::vector<Vec3> far;
  QuadrangulationResult r = measuredPass(options, options.fieldDirections.empty() ? nullptr : &far);
  if (r.mesh.numQuads() == 0) return r;  // nothing to measure
  // Where the field-aligned maps miss the bound (patches stretched along the field where the
  // surface curves across them, or sides sampled unevenly to follow it), first only the
  // patches near the points found too far get arc length on their sides, keeping the field
  // inside; then, if that is not enough, mean-value coordinates inside as well. The other
  // patches keep their field-aligned grids. A few rounds each, as the points too far may move
  // on to the next patches. Replaces `start` (its points too far `startFar`) if it meets the
  // bound touching at most kLocalFallbackShare of the patches; if it touches more, it is kept
  // in `patchwise` (below) if `lastResort`, else given up as soon as it does.
  std::optional<QuadrangulationResult> patchwise;  // a fallback that touched too many patches
  auto patchwiseFrom = [&](QuadrangulationResult& start, const std::vector<Vec3>& startFar,
                           const QuadrangulationOptions& o, bool lastResort) {
    std::vector<char> marks(layout.patches.size(), kFieldPatch);
    QuadrangulationResult local = start;
    std::vector<Vec3> localFar = startFar;
    for (const char level : {kArcLengthSides, kMeanValuePatch}) {
      for (int round = 0; round < 3 && local.deviationBound > limit && !localFar.empty(); ++round) {
        // Each point too far (on the quads, or on the surface where the quads do not cover it)
        // marks the patch of the quad nearest to it.
        const ClosestPointIndex quadIndex(local.mesh.positions, quadTriangles(local.mesh));
        int marked = 0;
        for (const Vec3& point : localFar) {
          const int q = quadIndex.closest(point).triangle / 2;
          const int p = q < int(local.mesh.quadPatch.size()) ? local.mesh.quadPatch[q] : -1;
          if (p >= 0 && p < int(marks.size()) && departure(marks[p]) < departure(level)) marks[p] = level, ++marked;
        }
        if (marked == 0) break;
        if (!lastResort && double(marks.size() - std::count(marks.begin(), marks.end(), kFieldPatch)) >
                               kLocalFallbackShare * double(marks.size()))
          return;
        try {
          QuadrangulationResult next = quadrangulateOnce(layout, o, topology, cache, &marks, &local);
          measure(next, &localFar);
          const bool closer = next.deviationBound < local.deviationBound;
          local = std::move(next);
          // A round that got no closer ends the rounds of this level: the points too far are
          // then not where the patches' sides or maps stray (features finer than the quads,
          // which only smaller quads follow), and more rounds would only repeat it (the dragon
          // with fcql's own field, at 3 times the bound: 4.28 → 4.27 → 4.27 → 4.27, and with
          // mean-value maps 4.49 twice; 4.6 s of each of its two fallbacks).
          if (!closer) break;
        } catch (const std::runtime_error&) {
          break;  // the whole stage without the field is tried below
        }
      }
      if (local.deviationBound <= limit) break;
    }
    // A fallback that had to touch many patches is no longer local: the field-aligned grid
    // with smaller quads (the refinements below) follows the field far better (kitten: 10.0%
    // of the quads off it, against 26.7% with 69 of its 70 patches' sides by arc length). It
    // stays the answer if the refinements do not meet the bound.
    if (local.deviationBound <= limit) {
      const std::size_t touched = std::size_t(local.boundArcLengthPatches + local.boundMeanValuePatches);
      if (double(touched) <= kLocalFallbackShare * double(layout.patches.size())) start = std::move(local);
      else if (lastResort) patchwise = std::move(local);
    }
  };
  // The field-aligned grid, smoothed only around its poor quads, misses the bound: first the
  // patch-wise fallbacks from it, then, if they miss, the grid smoothed everywhere (which keeps
  // quads evenly spread over curved parts), and the fallbacks from that one too if it is
  // closer to the surface. The refinements below start from the grid smoothed everywhere,
  // which meets the bound with larger quads (camelhead: 22.4K quads after three refinements,
  // against 28.8K from the other). So a mesh the fallbacks bring within the bound from the
  // field-aligned grid is smoothed everywhere no more (the dragon: 33.5% of the quads off the
  // field, against 36.7% from the grid smoothed everywhere, which was farther from the
  // surface, 1.27 against 1.10 times the bound, and one whole pass less).
  if (r.deviationBound > limit && !options.fieldDirections.empty()) {
    patchwiseFrom(r, far, options, !options.keepFieldGrid);
    if (r.deviationBound > limit && options.keepFieldGrid) {
      options.keepFieldGrid = false;
      const double fieldGridBound = r.deviationBound;
      r = measuredPass(options, &far);
      if (r.deviationBound > limit && r.deviationBound < fieldGridBound) patchwiseFrom(r, far, options, true);
    }
  }
  // Still too far: the field-aligned grid is refined below; the stage without the field comes
  // only after the refinements (last block), even where it would meet the bound at the asked
  // size. The kitten decimated to half its faces met it without the field at
  // 6.8K quads with 34.9% of them more than π/16 off the field; refined once, 11.5K quads and
  // 12.6%. (Before, the stage without the field was tried here first, at the asked size.)
  // Each finer pass is sized from the last one tried. One that gets no closer (a sharp tip
  // that a grid of that size happens to cut deeper, stretched or distorted patches) does not
  // end the refinements: the closer mesh is kept and the next size tried, up to the limit (the
  // camelhead's field-aligned quads, at most 1.15% of the diagonal from its surface after one
  // refinement, came 1.39% after the second, which ended the stage with an error, and within
  // the bound of 1% after the third).
  QuadrangulationOptions finer = options;
  int refinements = r.refinements;
  double lastBound = r.boundBeforeSnapping;
  int lastQuads = r.mesh.numQuads();
  while (r.deviationBound > limit && refinements < options.maxRefinements) {
    const double step = std::clamp(0.9 * std::sqrt(limit / lastBound), 0.5, 0.9);
    if (double(lastQuads) / (step * step) > double(options.maxQuads)) {
      r.refinementProblem = "a finer pass would give about " + std::to_string(long(lastQuads / (step * step))) +
                            " quads, more than the limit of " + std::to_string(options.maxQuads);
      break;
    }
    finer.targetEdgeLength *= step;
    ++refinements;
    try {
      QuadrangulationResult next = quadrangulateOnce(layout, finer, topology, cache);
      next.refinements = refinements;
      measure(next);
      lastBound = next.boundBeforeSnapping;
      lastQuads = next.mesh.numQuads();
      if (!(next.deviationBound < r.deviationBound)) {
        // Smaller quads that got no closer: the closer mesh stays, and says so if it is the last.
        char line[160];
        std::snprintf(line, sizeof line, "target edge %g: the mesh got no closer (%.3g%% of the diagonal)",
                      finer.targetEdgeLength, 100 * options.maxDeviation * next.deviationBound / limit);
        r.refinementProblem = line;
        continue;
      }
      r = std::move(next);
      r.refinementProblem.clear();
    } catch (const std::runtime_error& e) {
      // A finer pass that fails (zero chains that do not resolve at that size, say) leaves
      // the last good mesh, which says why it is still too far from the surface.
      r.refinementProblem = "target edge " + std::to_string(finer.targetEdgeLength) + ": " + e.what();
      break;
    }
  }
  if (r.deviationBound > limit && patchwise) r = std::move(*patchwise);
  // The whole stage without the field, for the two fallbacks below: run at most once (none
  // if neither needs it); null if it fails.
  std::optional<QuadrangulationResult> withoutField;
  bool withoutFieldRun = false;
  auto stageWithoutField = [&]() -> const QuadrangulationResult* {
    if (!withoutFieldRun) {
      withoutFieldRun = true;
      QuadrangulationOptions plain = options;
      plain.fieldDirections.clear();
      try {
        withoutField = quadrangulateWith(layout, plain, cache);
      } catch (const std::runtime_error&) {
        // The stage without the field fails where this one did not: keep this one.
      }
    }
    return withoutField ? &*withoutField : nullptr;
  };
  {
    // Folds left by the field-aligned pass the refinements kept: other ways to sample it,
    // kept if they fold fewer and stay within the bound (or no farther than this one).
    const double bound = std::max(limit, r.deviationBound);
    reduceFolds(r, layout, options, cache.grids, [&](QuadrangulationResult& c) {
      measure(c);
      return c.deviationBound <= bound;
    });
    // Still folded: the stage without the field, kept if it folds fewer, so that the field
    // never leaves more folds than the stage without it. Where the field's passes were not
    // refined, the first pass without it (at the asked size, cached) decides: if that folds no
    // fewer, the whole stage is not run on to its refinements, which are there for the
    // distance bound, not for folds (the dragon: 18 folds against the field's 15, then 15
    // after a refinement that cost 9 s). Where they were, the pass without the field at the
    // size they ended at (its counts cached) is itself the candidate, kept if it folds fewer
    // and is within the bound (or no farther than this one): the whole stage would start again
    // at the asked size and refine on its own (the dragon with fcql's own field: the pass
    // without it folded 2 quads at the asked size against the field's 5 after three
    // refinements; the stage then refined four times in 24 s, missed the bound and failed).
    const int left = options.fieldDirections.empty() ? 0 : foldedQuads(r.mesh);
    if (left > 0) {
      QuadrangulationOptions plain = options;
      plain.fieldDirections.clear();
      const bool refined = r.targetEdgeLength != options.targetEdgeLength;
      if (refined) plain.targetEdgeLength = r.targetEdgeLength;
      std::optional<QuadrangulationResult> first;
      try {
        first = measuredPass(plain);
      } catch (const std::runtime_error&) {
        // the stage without the field fails at this size
      }
      const QuadrangulationResult* without = nullptr;
      if (first && foldedQuads(first->mesh) < left) {
        if (!refined) without = stageWithoutField();
        else if (first->deviationBound <= bound) without = &*first;
      }
      if (without && foldedQuads(without->mesh) < left) {
        const int refinementsDone = r.refinements;
        const std::string refinementProblem = r.refinementProblem;
        r = *without;
        if (refined) r.refinements = refinementsDone, r.refinementProblem = refinementProblem;
        r.foldsWithoutField = true;
        r.foldsResmoothed = r.foldsResampled = r.foldsSidesByArcLength = false;
      }
    }
  }
  if (r.deviationBound > limit && !options.fieldDirections.empty()) {
    // Refined, the field-aligned maps still miss the bound: the whole stage without the field
    // (its own refinements) is kept if it meets it.
    if (const QuadrangulationResult* without = stageWithoutField(); without && without->deviationBound <= limit) {
      r = *without;
      r.boundWithoutField = true;
    }
  }
  r.deviationLimit = limit;
  if (r.deviationBound > limit) {
    // Exit 0 means the bound holds: a mesh that may be farther is not returned.
    char line[400];
    std::snprintf(line, sizeof line,
                  "the quad mesh may be up to %.3g%% of the diagonal from the surface (at least %.3g%% measured), "
                  "above the bound of %g%% (--max-deviation), after %d refinement(s) down to a target edge of %g%s%s; "
                  "give a larger bound, smaller quads (--scale) or 0 to disable the check",
                  100 * options.maxDeviation * r.deviationBound / limit, 100 * options.maxDeviation * r.deviation / limit,
                  100 * options.maxDeviation, r.refinements, r.targetEdgeLength,
                  r.refinementProblem.empty() ? "" : "; the next finer pass failed: ", r.refinementProblem.c_str());
    throw std::runtime_error(line);
  }
  r.deviationLimit = limit;
  return r;
}

}  // namespace

QuadrangulationResult quadrangulate(const PatchLayout& layout, const QuadrangulationOptions& options) {
  PassCache cache;
  return quadrangulateWith(layout, options, cache);
}

std::vector<std::string> refinementNotes(const QuadrangulationResult& r, const QuadrangulationOptions& options) {
  std::vector<std::string> notes;
  if (r.stretchBoundDropped)
    notes.push_back("zero-chain splits did not settle in " + std::to_string(options.maxSplitRounds) +
                    " rounds with every segment sampled at most 1.5 times coarser than the target: that bound was "
                    "dropped, so some quads may be stretched");
  if (r.splitEverything)
    notes.push_back("zero chains were left even then: every patch was split once more (the last resort of section "
                    "4.4), which makes the counts agree (patches with t-junctions get an irregular vertex inside)");
  if (r.boundWithoutField)
    notes.push_back("the field-aligned patch maps stayed farther than the distance bound from the surface; the quads "
                    "were made without the field (mean-value maps), which meet it");
  if (r.boundArcLengthPatches > 0)
    notes.push_back("the field-aligned patch maps strayed farther than the distance bound from the surface near " +
                    std::to_string(r.boundArcLengthPatches) +
                    " layout patches: their sides were sampled by arc length (the field kept inside), which meets it");
  if (r.boundMeanValuePatches > 0)
    notes.push_back("the field-aligned patch maps strayed farther than the distance bound from the surface near " +
                    std::to_string(r.boundMeanValuePatches) +
                    " layout patches: those were mapped with mean-value coordinates inside (arc length on their sides), "
                    "which meets it");
  if (options.maxDeviation <= 0) return notes;
  char line[400];
  const double diagonal = r.deviationLimit / options.maxDeviation;
  if (r.refinements > 0) {
    std::snprintf(line, sizeof line,
                  "refined %d time(s) to stay within %g%% of the diagonal: target quad edge %g -> %g, deviation at most %.3g%%%s",
                  r.refinements, 100 * options.maxDeviation, options.targetEdgeLength, r.targetEdgeLength,
                  diagonal > 0 ? 100 * r.deviationBound / diagonal : 0.0,
                  r.deviationBound <= r.deviationLimit ? ""
                  : r.refinementProblem.empty()   ? " (still above: refinements exhausted)"
                                                  : " (still above: the next finer pass failed, see below)");
    notes.push_back(line);
  }
  if (r.restoredVertices > 0) {
    std::snprintf(line, sizeof line,
                  "smoothing undone for %d vertices where the quads strayed more than %g%% from the surface (sharp tips)",
                  r.restoredVertices, 100 * options.maxDeviation);
    notes.push_back(line);
  }
  if (!r.refinementProblem.empty()) {
    std::snprintf(line, sizeof line, "warning: a finer pass to get within %g%% of the diagonal failed, the coarser mesh is kept (",
                  100 * options.maxDeviation);
    notes.push_back(line + r.refinementProblem + ")");
  }
  return notes;
}

}  // namespace fcql
