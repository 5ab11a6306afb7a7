// The quadrangulation stage (§4.4–4.5): patch sides, integer side lengths, zero-chain splits
// until every patch has equal opposite sides, then patch sampling.
#pragma once

#include "quadrangulation/patch_sampling.h"
#include "quadrangulation/quad_smoothing.h"
#include "quadrangulation/zero_chains.h"

#include <string>
#include <vector>

namespace fcql {

struct QuadrangulationResult {
  PatchGraph graph;
  SideLengths lengths;
  QuadMesh mesh;
  QuadMeshReport report;
  int splitRounds = 0;     ///< rounds of zero-chain splits
  int splitPatches = 0;    ///< patches split for zero chains, in all
  /// Side-length parts the safety time limit cut short, over all rounds: where it is not 0 the
  /// quads depend on the machine's speed.
  int timeLimitedParts = 0;
  /// The zero-chain splits had not settled when the rounds ran out, and the side lengths were
  /// then solved once more without the bound on how coarse a segment may be sampled.
  bool stretchBoundDropped = false;
  /// Even then some disagreed, and every patch was split once more (§4.4's worst case), which
  /// always makes the counts agree.
  bool splitEverything = false;
  int polygonPatches = 0;  ///< layout patches with 3, 5 or more corners, split into quads first
  /// Inner vertices in only two quads, which were merged into one (dissolveTwoValentVertices).
  int dissolvedVertices = 0;
  SmoothingReport smoothing;
  /// With a field, a few quads were left folded after smoothing towards it: the plain
  /// smoothing folded fewer (foldsResmoothed), or their patches sampled again did
  /// (foldsResampled): with mean-value coordinates inside, or with arc length on their sides
  /// alone, the field kept inside (foldsSidesByArcLength as well).
  bool foldsResmoothed = false;
  bool foldsResampled = false;
  bool foldsSidesByArcLength = false;
  /// ... or, still folded, the pass (or, last, the whole stage) made without the field folded
  /// fewer and was kept.
  bool foldsWithoutField = false;
  /// The field-aligned pass missed maxDeviation, also with mean-value maps in the patches near
  /// where it strayed (meanValuePatches) and after its refinements; the whole stage without
  /// the field (mean-value maps) met it and was kept.
  bool boundWithoutField = false;
  /// Per layout patch (patch_sampling.h): kMeanValuePatch where it was mapped with mean-value
  /// coordinates inside instead of the field, kArcLengthSides where only its sides were
  /// sampled by arc length, because the field-aligned quads near it strayed farther than
  /// maxDeviation from the surface (or, kMeanValuePatch, folded); empty if none.
  std::vector<char> meanValuePatches;
  int boundMeanValuePatches = 0;  ///< how many are marked kMeanValuePatch in meanValuePatches
  /// How many are marked kArcLengthSides: the field inside, arc length on their sides (a
  /// first step, tried before mean-value maps).
  int boundArcLengthPatches = 0;
  /// The sampled field-aligned grid was smoothed only around its poor quads (see
  /// QuadrangulationOptions::keepFieldGrid); false when it was smoothed everywhere.
  bool fieldGridKept = false;
  std::vector<Vec3> sampledPositions;  ///< the mesh's vertex positions before smoothing
  /// Vertices put back towards their sampled positions where the smoothed quads strayed more
  /// than maxDeviation from the surface (restoreSampledPositions).
  int restoredVertices = 0;
  /// Vertices moved onto points of the surface the quads missed by more than maxDeviation
  /// (snapVerticesToFarPoints: spikes and fins narrower than a quad).
  int snappedVertices = 0;
  double boundBeforeSnapping = 0;  ///< deviationBound before snapVerticesToFarPoints
  double targetEdgeLength = 0;  ///< the target edge length the mesh was sampled with
  int refinements = 0;          ///< times the target was lowered to meet maxDeviation
  double deviation = 0;         ///< Hausdorff distance to the surface found, absolute (0 if not measured)
  double deviationBound = 0;    ///< upper bound on it (measureDeviation), ≤ deviationLimit when returned
  double deviationLimit = 0;    ///< maxDeviation in mesh units (0 if not asked for)
  std::string refinementProblem;  ///< why a finer pass failed (the mesh is then the last good one)
};

struct QuadrangulationOptions {
  double targetEdgeLength = 0;  ///< wanted quad edge length (> 0), in mesh units
  /// Seconds for the side lengths, in all (see solveSideLengths for how they are shared
  /// among the independent parts).
  double ilpTimeLimit = 60;
  int maxSplitRounds = 8;       ///< rounds of zero-chain splits before giving up
  SmoothingOptions smoothing;   ///< iterations = 0 keeps the sampled positions
  /// The cross field, direction 0 per input face (PatchLayout::originalFace indexes it): each
  /// patch is then mapped onto its rectangle field-aligned (samplePatches). Empty: mean-value
  /// coordinates, the boundary by arc length.
  std::vector<Vec3> fieldDirections;
  /// With fieldDirections: the smoothing moves only the vertices within two rings of a quad
  /// whose scaled Jacobian is below 0.5 (SmoothingOptions::keepGridAbove), keeping the
  /// field-aligned grid the maps sampled elsewhere (smoothing it everywhere turned it away from
  /// the field: bunny 4.6% of the quads more than π/16 off it unsmoothed, 9.4% smoothed). If
  /// that mesh misses maxDeviation, the patch-wise fallbacks start from it; if they miss too,
  /// the stage smooths everywhere, tries them from there if that mesh is closer to the surface,
  /// and refines from there.
  bool keepFieldGrid = true;
  /// Largest Hausdorff distance to the surface allowed, relative to the bounding-box diagonal
  /// (0: no check). Where the mesh may deviate more (measureDeviation's upper bound: curved
  /// parts finer than the target edge), the stage runs again with a smaller target edge
  /// length, up to maxRefinements times; the result says how often. If the bound still does
  /// not hold, quadrangulate throws std::runtime_error saying how far the mesh may be.
  double maxDeviation = 0.01;
  int maxRefinements = 4;
  /// A refinement that would give more quads than this (estimated from the last pass) is not
  /// made: the result keeps the last mesh and says why.
  long maxQuads = 20000000;
};

/// Throws std::invalid_argument for bad options, std::runtime_error (with the reason) if a
/// patch is not a disk with at least 3 corners or zero chains remain after `maxSplitRounds`
/// rounds, if the quad mesh comes out non-manifold (never returned as if valid) or if it may be
/// farther than maxDeviation from the surface after the refinements. Disks
/// with 3, 5 or more corners are cut into quads as n-gons (zero_chains.h).
QuadrangulationResult quadrangulate(const PatchLayout& layout, const QuadrangulationOptions& options);

/// An inner vertex in only two quads, (v, a, x, b) and (v, b, y, a), makes them share two
/// edges: their corners at v add up to a full turn, so on a flat part one of them is folded
/// whatever the smoothing does. The two quads become one, (a, x, b, y), and v goes (repeated
/// while any is left; vertices and quads are renumbered, quadPatch kept). Returns how many went.
int dissolveTwoValentVertices(QuadMesh& mesh);

/// Log lines about the distance check of a result made with `options`: how often and how far
/// the target was lowered, and why a finer pass failed (none if nothing happened).
std::vector<std::string> refinementNotes(const QuadrangulationResult& r, const QuadrangulationOptions& options);

}  // namespace fcql
