// Smoothing of the sampled quad mesh with reprojection onto the input surface (§4.5).
//
// Each round moves every free vertex a fraction `step` towards the average of its edge
// neighbours, tangentially (the normal component, taken from the surface triangle nearest to
// the vertex, is removed), then puts it back on the surface at its closest point, or onto the
// nearest feature line (sharp edges, dihedral angle above `sharpAngleDeg`) when that is closer
// than about a third of the vertex's mean edge length, so that quads follow creases instead of
// cutting across them. Vertices on the border of the quad mesh and vertices lying on a sharp
// edge stay where they are, except that the untangling below may slide a corner of a folded
// quad along the crease it lies on, when that crease is sharp (dihedral above 60°) and straight
// (turning by less than 20° at each of its vertices: a CAD edge, not a scan's ridge), never off
// it nor onto another line: a vertex pushed past its neighbour on a crease folds the quads on
// both sides, and only it can unfold them. No step folds a quad: after each round, every quad
// the round took from above kMinScaledJacobian (0.1) to it or below, at any of its four corners, against its
// own normal or the surface normal there (QuadJacobian, metrics/quad_quality.h), has the moves
// it depends on undone. With a field, the rounds are followed by the relaxation towards it
// solved for all vertices at once (field_relaxation.h: local averages cannot turn a grid), the
// vertices near feature lines kept out, its moves kept from folding the same way (those undone
// tried again half and a quarter of the way). Last, the quads still folded or nearly flat are untangled, first
// against the input surface's normal at each quad (which folded quads do not disturb: the
// mean normal of the surface triangles its corners lie on), then against the surface normal
// at each corner as it is measured: each vertex around them tries
// the parallelogram completions of its quads, its neighbours' average and its quads' centre (on
// the surface), then a pattern search in the tangent plane, and keeps the position that most
// lowers the quads' shortfall below the threshold (folds weighing ten times more) without
// folding any quad, worsening a folded one or taking a good one below 0.02; folds left in
// clusters are smoothed as regions of 2, 4 and 8 rings, kept
// only when fewer quads are folded and none newly. The untangling runs twice from the smoothed
// positions, the second time with each vertex's nearest point on a feature line among its
// candidates (a grid line beside a crease may unfold only on it), and the run leaving fewer
// folded quads is kept. Folds still left go to repairFolds (fold_repair.h), which moves the
// vertices around them together (feature vertices along their line, border vertices not at
// all). What cannot be unfolded stays (counted by the caller: quad.inverted_quads).
#pragma once

#include "mesh/quad_mesh.h"

#include <array>
#include <vector>

namespace fcql {

struct SmoothingOptions {
  int iterations = 5;
  double step = 0.5;          ///< 0..1: share of the way to the neighbours' average per round
  double sharpAngleDeg = 35;  ///< surface edges above this dihedral angle are kept
  /// The cross field, one of its directions per surface triangle (tangent). Given, each vertex
  /// moves towards the mean of the corners it would have in the rectangles aligned with the
  /// field that best fit its quads (same centre, extents along the field's two directions)
  /// instead of its neighbours' average: the quads turn to the field, across patch sides too.
  std::vector<Vec3> triangleDirections;
  /// With triangleDirections: a vertex moves only within two rings of a quad whose scaled
  /// Jacobian is below this (at the start of each round), or of a quad without a field; the
  /// sampled field-aligned grid stays as it is elsewhere, as smoothing towards the field turns
  /// such a grid away from it (a fit per quad to one field direction, averaged over the quads
  /// around a vertex). 0: every free vertex moves.
  double keepGridAbove = 0;
  /// With triangleDirections: rounds of the relaxation towards the field, solved for all
  /// vertices at once (field_relaxation.h), after the iterations; and its anchor μ.
  int fieldRelaxationRounds = 2;
  double fieldRelaxationAnchor = 0.1;
  /// Per quad-mesh vertex, 1 for one that stays where it is, as a border vertex does (empty:
  /// none). A pass that smooths again only part of a mesh smoothed before (reduceFolds in
  /// quadrangulation.cpp) freezes the rest; the figures then cost in proportion to that part.
  std::vector<char> frozen;
  /// Worker threads for the per-vertex moves (0: all hardware threads); the result does not
  /// depend on it.
  int threads = 0;
};

struct SmoothingReport {
  int fixedVertices = 0;      ///< border and feature vertices (not those frozen by SmoothingOptions::frozen)
  int revertedMoves = 0;      ///< vertex moves undone because they folded a quad
  int snappedMoves = 0;       ///< vertex moves that ended on a feature line
  int untangledMoves = 0;     ///< vertex moves of the untangling pass
  int repairedFolds = 0;      ///< quads unfolded by repairFolds (fold_repair.h) after the untangling
  int relaxedMoves = 0;       ///< vertex moves of the relaxation towards the field that were kept (summed over its rounds)
};

/// `surfacePositions` / `surfaceTriangles`: the surface the quads sample (e.g. the layout's
/// refined triangles). Throws std::invalid_argument for bad options (and for `frozen` not empty
/// nor one entry per vertex).
SmoothingReport smoothQuadMesh(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                               const std::vector<std::array<int, 3>>& surfaceTriangles,
                               const SmoothingOptions& options);

/// Undoes smoothing near the points where the quads stray from the surface. Smoothing keeps
/// vertices on the surface but lets them slide off sharp tips (an ear's tip, a cone's apex),
/// whose surface is then no longer covered. Every vertex within `radius` of a point of `far`
/// goes back towards its `sampled` position: all the way within radius / 2, by a share
/// falling linearly to 0 at `radius`. Vertices go back one by one in index order; one whose
/// return would fold or nearly flatten a quad that depends on it, given where the others are by
/// then (QuadJacobian at most 0.1 where it was above), keeps its smoothed position. Returns how
/// many vertices moved. Throws std::invalid_argument unless `sampled` has one position per vertex.
int restoreSampledPositions(QuadMesh& quads, const std::vector<Vec3>& sampled, const std::vector<Vec3>& far,
                            double radius);

}  // namespace fcql
