// A strict reader for PLY polygon meshes, for untrusted bytes: ASCII and binary (little- and
// big-endian). It keeps the vertex element's x, y, z, the face element's index list
// (vertex_indices or vertex_index) and any scalar face properties asked for by name; every
// other element and property is skipped by its declared type, within the file's bounds.
//
// Nothing is allocated from a declared count before the count has been checked against the
// bytes the file holds, and every error is one line naming the file and the header line, the
// body line (ASCII) or the byte offset (binary) where it was found. It never reads past the
// buffer, whatever the header declares.
#pragma once

#include "mesh/surface_mesh.h"

#include <string>
#include <vector>

namespace fcql {

/// The polygons of a PLY file, as written: face f has the corners
/// corners[faceStart[f] .. faceStart[f + 1]), each in [0, positions.size()), at least 3.
struct PlyPolygons {
  std::vector<Vec3> positions;
  std::vector<int> faceStart{0};
  std::vector<int> corners;
  /// One vector per name asked for in parsePly's `faceProperties`, one value per face.
  std::vector<std::vector<double>> faceValues;

  int numFaces() const { return int(faceStart.size()) - 1; }
};

/// Parses the bytes of a PLY file; `name` starts every message. `faceProperties` are scalar
/// face properties to keep (each must be declared). Throws MeshError on anything that is not a
/// valid PLY mesh: a bad or truncated header, counts the file cannot hold, a non-finite
/// coordinate, a face with fewer than 3 corners or an index out of range, a missing or
/// repeated element or property, a truncated body or (ASCII) data after the last element.
PlyPolygons parsePly(const std::string& bytes, const std::string& name,
                     const std::vector<std::string>& faceProperties = {});

}  // namespace fcql
