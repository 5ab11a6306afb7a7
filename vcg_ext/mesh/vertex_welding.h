// Merging vertices that lie exactly on another vertex (an unwelded mesh).
//
// Triangle soups exported vertex by vertex (STL converted to OBJ, PLY files split along texture
// seams) repeat a position once per triangle or per side of a seam. Read as they are, every
// triangle is its own component with a border, and the pipeline would cut each into three
// quads. Merging the vertices that share a position exactly gives the surface back, with the
// faces in the same order (so a per-face field still matches). The merged mesh is used only
// if it is itself valid (manifold, consistently oriented): two surfaces touching at a point
// would become non-manifold there, and are then left apart.
#pragma once

#include "mesh/surface_mesh.h"

#include <string>
#include <vector>

namespace fcql {

struct VertexWelding {
  int merged = 0;               ///< vertices lying exactly on an earlier one
  bool welded = false;          ///< the merged mesh is valid and `mesh` holds it
  SurfaceMesh mesh;             ///< the merged mesh (if welded)
  std::vector<int> newIndex;    ///< per input vertex: its vertex in `mesh` (if welded)
  std::string problem;          ///< why the merged mesh was not valid (if merged > 0 and not welded)

  /// One line for the log (empty when no vertex lies on another).
  std::string note() const;
};

VertexWelding weldCoincidentVertices(const SurfaceMesh& mesh);

}  // namespace fcql
