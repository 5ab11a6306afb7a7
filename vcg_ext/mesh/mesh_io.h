// Reading and writing triangle meshes (OBJ, PLY, OFF) through vcglib's importers, into a
// validated SurfaceMesh. Polygons with more than three corners are fan-triangulated by vcglib;
// duplicate vertices are not merged (the file's connectivity is the mesh's).
#pragma once

#include "mesh/surface_mesh.h"

#include <string>

namespace fcql {

/// Throws MeshError (one line: file name and reason) if the file cannot be read, has no faces,
/// or is not a valid oriented 2-manifold (see SurfaceMesh).
SurfaceMesh loadMesh(const std::string& path);

/// Writes OBJ, PLY or OFF by extension. Throws MeshError if the file cannot be written.
void saveMesh(const SurfaceMesh& mesh, const std::string& path);

}  // namespace fcql
