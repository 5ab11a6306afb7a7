// Cancelling pairs of opposite singularities (+1/4 and −1/4, +1/2 and −1/2, ...) that sit on
// the two ends of one mesh edge, and pairs of opposite quarters closer than the field's scale.
//
// Such a pair is finer than anything a quad layout can serve: its separatrices cut patches a
// fraction of a triangle wide (on a noisy scan, a sliver triangle whose angles the noise
// turned over makes one). The field is changed in one of the two triangles on the pair's
// edge, a quarter off each end at a time: one cross turns by the smallest multiple of 5
// degrees (up to 45 either way) that takes a quarter off the index of both ends and leaves the
// triangles' other vertices as they were, or else both crosses together. What no such turn
// cancels is left as it is. Faces marked fixed (crosses constrained to sharp or border edges)
// are never changed.
#pragma once

#include "field/cross_field.h"

#include <array>
#include <vector>

namespace fcql {

/// Returns the number of quarter pairs cancelled (a ±1/2 pair counts 2). `fixedFace` (empty:
/// none) marks the faces to keep.
int cancelAdjacentSingularityPairs(const SurfaceMesh& mesh, CrossField& field, const std::vector<char>& fixedFace = {});

// Pairs a little farther apart: an interior +1/4 and an interior −1/4 closer than `reach` (a
// length; the field's scale, FieldGenerationOptions::scale, which the connection's curvature is
// spread over: bumps smaller than it are to make no singularities). A pair closer than a quad
// cuts patches thinner than a quad between its separatrices, and noise makes them: the bunny
// with noise of 0.05% of its diagonal had pairs 0.6 and 1.0 default quad edges apart, the clean
// bunny none closer than 2.7. Pairs of quarters each nearest to the other are taken nearest
// first. Each pair's neighbourhood (the faces reached across the surface from the +1/4's star
// whose centroid lies within `radius` of the segment between the two, radius the pair's
// distance but at least two mean edges; twice that if the first does not do it) gets the
// smoothest field with its surroundings held: one sparse Hermitian solve of
// Σ w_e |z_g − r_e z_f|² over its edges (z = e^{4iθ}, w_e = |e|² / (A_f + A_g): edgeSmoothness
// of cross_field.h, as in field_generation.cpp; r_e the transport of the connection the field
// was solved with, its curvature spread over the field's scale: with the Levi-Civita transport
// itself the smoothest field gathers the noise's own curvature into new singularities beside
// the pair). The index inside sums to zero (the field around it is the same), and a smooth
// field with nothing to follow inside has no singularity there. Kept only if the index of the
// neighbourhood's vertices drops by two quarters in all (a third singularity of a cluster may
// move), no index of a half or more appears and no border vertex's changes; faces marked fixed
// stay as they are.

/// Returns the number of pairs cancelled. `connectionCorrection[f][i]`: the rotation added to
/// the transport across edge i of face f (ρ of field_generation.cpp: the connection whose
/// curvature is spread over the field's scale; all zero for the Levi-Civita connection itself).
/// `fixedFace` (empty: none) marks the faces to keep.
int cancelCloseSingularityPairs(const SurfaceMesh& mesh, CrossField& field, double reach,
                                const std::vector<std::array<double, 3>>& connectionCorrection,
                                const std::vector<char>& fixedFace = {});

}  // namespace fcql
