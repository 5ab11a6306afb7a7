#include "quadrangulation/quadrangulation.h"

#include <stdexcept>

namespace fcql {

QuadrangulationResult quadrangulate(const PatchLayout& layout, double targetEdgeLength, double ilpTimeLimit,
                                    int maxSplitRounds) {
  QuadrangulationResult r;
  r.graph = buildPatchGraph(layout);
  r.lengths = solveSideLengths(r.graph, targetEdgeLength, ilpTimeLimit);
  while (!r.lengths.inconsistentPatches.empty()) {
    if (r.splitRounds >= maxSplitRounds)
      throw std::runtime_error(std::to_string(r.lengths.inconsistentPatches.size()) +
                               " patches still have unequal opposite sides after " + std::to_string(maxSplitRounds) +
                               " rounds of zero-chain splits");
    r.splitPatches += int(r.lengths.inconsistentPatches.size());
    splitPatches(r.graph, layout, r.lengths.inconsistentPatches);
    ++r.splitRounds;
    r.lengths = solveSideLengths(r.graph, targetEdgeLength, ilpTimeLimit);
  }
  r.mesh = samplePatches(layout, r.graph, r.lengths);
  r.report = checkQuadMesh(r.mesh);
  return r;
}

}  // namespace fcql
