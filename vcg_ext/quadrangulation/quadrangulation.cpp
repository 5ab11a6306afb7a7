#include "quadrangulation/quadrangulation.h"

#include <algorithm>
#include <stdexcept>

namespace fcql {

QuadrangulationResult quadrangulate(const PatchLayout& layout, const QuadrangulationOptions& options) {
  if (!(options.targetEdgeLength > 0)) throw std::invalid_argument("the target quad edge length must be positive");
  if (options.maxSplitRounds < 0) throw std::invalid_argument("the number of zero-chain split rounds must be >= 0");
  if (!(options.ilpTimeLimit >= 1)) throw std::invalid_argument("the side-length time limit must be at least 1 s");
  auto solveLengths = [&](const PatchGraph& graph) {
    if (options.ilpTimeLimit > kQuickSideLengthSeconds) {
      try {
        return solveSideLengths(graph, options.targetEdgeLength, kQuickSideLengthSeconds);
      } catch (const std::runtime_error&) {
        // no solution in the short run: give it the whole limit
      }
    }
    return solveSideLengths(graph, options.targetEdgeLength, options.ilpTimeLimit);
  };
  QuadrangulationResult r;
  r.graph = buildPatchGraph(layout);
  r.polygonPatches = splitPolygonPatches(r.graph, layout);
  r.lengths = solveLengths(r.graph);
  while (!r.lengths.inconsistentPatches.empty()) {
    if (r.splitRounds >= options.maxSplitRounds)
      throw std::runtime_error(std::to_string(r.lengths.inconsistentPatches.size()) +
                               " patches still have unequal opposite sides after " +
                               std::to_string(options.maxSplitRounds) + " rounds of zero-chain splits");
    r.splitPatches += int(r.lengths.inconsistentPatches.size());
    splitPatches(r.graph, layout, r.lengths.inconsistentPatches);
    ++r.splitRounds;
    r.lengths = solveLengths(r.graph);
  }
  r.mesh = samplePatches(layout, r.graph, r.lengths);
  r.smoothing = smoothQuadMesh(r.mesh, layout.positions, layout.triangles, options.smoothing);
  r.report = checkQuadMesh(r.mesh);
  if (!r.report.manifold)
    throw std::runtime_error("the quad mesh came out non-manifold (" + r.report.problem +
                             "): the layout has a patch the sampling cannot handle");
  return r;
}

}  // namespace fcql
