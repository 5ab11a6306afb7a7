// The quadrangulation stage (§4.4–4.5): patch sides, integer side lengths, zero-chain splits
// until every patch has equal opposite sides, then patch sampling.
#pragma once

#include "quadrangulation/patch_sampling.h"
#include "quadrangulation/quad_smoothing.h"
#include "quadrangulation/zero_chains.h"

namespace fcql {

struct QuadrangulationResult {
  PatchGraph graph;
  SideLengths lengths;
  QuadMesh mesh;
  QuadMeshReport report;
  int splitRounds = 0;     ///< rounds of zero-chain splits
  int splitPatches = 0;    ///< patches split in four, in all
  SmoothingReport smoothing;
};

constexpr double kMaxSideLengthSeconds = 10;

struct QuadrangulationOptions {
  double targetEdgeLength = 0;  ///< wanted quad edge length (> 0), in mesh units
  /// Seconds per side-length program, at most kMaxSideLengthSeconds: the first solutions
  /// lp_solve finds are already consistent, more time only improves the rounding a little.
  double ilpTimeLimit = 10;
  int maxSplitRounds = 8;       ///< rounds of zero-chain splits before giving up
  SmoothingOptions smoothing;   ///< iterations = 0 keeps the sampled positions
};

/// Throws std::invalid_argument for bad options, std::runtime_error (with the reason) if a
/// patch is not a 4-cornered disk or zero chains remain after `maxSplitRounds` rounds.
QuadrangulationResult quadrangulate(const PatchLayout& layout, const QuadrangulationOptions& options);

/// The same with default smoothing.
QuadrangulationResult quadrangulate(const PatchLayout& layout, double targetEdgeLength, double ilpTimeLimit,
                                    int maxSplitRounds = 8);

}  // namespace fcql
