// The base complex of a quad mesh: the coarse patches its own structure makes (Bommes et al.,
// "Quad-mesh generation and processing: a survey", 2013).
//
// Separatrices are traced along edges from every irregular vertex (interior valence ≠ 4; on a
// border, valence other than 3, a border corner of valence 2 starting none), each edge leaving
// the vertex into the surface; through a regular interior vertex a separatrix goes on along the
// opposite edge, and it stops at an irregular vertex, at the border, or on an edge already
// traced (a line that closes on itself or runs into another one). The border edges bound too.
// The base-complex patches are the regions of quads these lines bound. A quad mesh that keeps
// a conforming layout's structure has as many of them as the layout has patches; each
// t-junction of the layout lets a separatrix run on and cut more.
#pragma once

#include "mesh/quad_mesh.h"

namespace fcql {

struct BaseComplex {
  int patches = 0;           ///< regions of quads bounded by the separatrices and the border
  int separatrices = 0;      ///< traced lines (each from one irregular vertex along one edge)
  int separatrixEdges = 0;   ///< interior edges on a separatrix
  int irregularVertices = 0; ///< the vertices they start from
};

/// Requires a manifold quad mesh (checkQuadMesh's `manifold`); throws std::invalid_argument
/// otherwise.
BaseComplex measureBaseComplex(const QuadMesh& mesh);

}  // namespace fcql
