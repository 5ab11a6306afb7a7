// Grid lines of the sampled quads that run along a feature line (a sharp edge), a little off
// it, moved onto it.
//
// A separatrix that follows a crease cannot run on it: graph G's moves cross triangles, so the
// traced path runs parallel to the crease inside the triangles beside it (on a cube of 15×15
// squares a face, a third of a quad's edge from the edges), and the layout's side, with the
// quads' vertices sampled on it, runs there too. The patch across that side then holds a strip
// of the neighbouring face and its quads bend across the crease. Smoothing snaps a vertex
// only when it moves, and keeps a sampled field-aligned grid where its quads are good.
//
// So before smoothing, every free vertex v is moved to its nearest point on the feature lines
// when all of these hold:
// - that point lies on a segment the caller marks snappable (smoothQuadMesh: a crease sharper
//   than 60° and straight, turning by less than 20° at each vertex that continues it: a CAD
//   edge; on scans, whose creases are zigzag ridges at the resolution of the triangles, moving
//   grid lines onto them bent the quads) and part of a run of such segments at least three of
//   v's quad edges long (a crease of a few triangles on a scan, such as the four sharper than
//   60° on the bunny, took the bunny at 1% from 6.3% to 9.6% of its quads off the field);
// - it is within 0.6 of v's mean quad edge (a grid line at most about halfway to the next);
// - v's grid line runs along the line there: a quad edge at v is within 20° of the segment;
// - no neighbour across it (along a quad edge more than 20° off the segment) is nearer the
//   line: only the grid line nearest the crease, on whichever side, goes onto it;
// and the moves are undone, a quad at a time, wherever they take a quad's scaled Jacobian from
// above 0.1 to 0.1 or below. The vertices moved are then on the line, where the smoothing
// keeps them (or slides them along it).
#pragma once

#include "mesh/closest_point_index.h"
#include "mesh/quad_mesh.h"

#include <array>
#include <vector>

namespace fcql {

/// `features`: the feature lines as degenerate triangles (a, b, b) over `surfacePositions`,
/// indexed as `featureSegments`; `snappable[i]`: whether grid lines may go onto segment i;
/// `movable[v]`: whether vertex v may move; `neighbours[v]`: its neighbours along quad edges.
/// Returns how many vertices were moved onto a line.
int snapGridLinesToFeatures(QuadMesh& quads, const std::vector<Vec3>& surfacePositions,
                            const std::vector<std::array<int, 3>>& featureSegments, const std::vector<char>& snappable,
                            const ClosestPointIndex& features, const std::vector<char>& movable,
                            const std::vector<std::vector<int>>& neighbours);

}  // namespace fcql
