// Reading and writing triangle meshes (OBJ, PLY in ASCII or binary, OFF) with the project's own
// strict readers (no vcglib/plylib code touches a file), into a validated SurfaceMesh. Polygons
// with more than three corners are fan-triangulated; duplicate vertices are not merged (the
// file's connectivity is the mesh's). Only regular files are read.
#pragma once

#include "mesh/surface_mesh.h"

#include <string>

namespace fcql {

/// Throws MeshError (one line: file name and reason) if the file cannot be read, has no faces,
/// or is not a valid oriented 2-manifold (see SurfaceMesh).
SurfaceMesh loadMesh(const std::string& path);

/// The same from the bytes of a file in `format` ("obj", "ply" or "off"); `name` starts every
/// message.
SurfaceMesh parseMesh(const std::string& bytes, const std::string& name, const std::string& format);

/// Writes OBJ, PLY (ASCII, double coordinates) or OFF by extension, coordinates to 17 digits.
/// Throws MeshError if the file cannot be written.
void saveMesh(const SurfaceMesh& mesh, const std::string& path);

}  // namespace fcql
