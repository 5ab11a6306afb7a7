// Cross field files.
//
// .ffield (vcglib/MeshLab):      .rosy:
//   # comment lines                nF
//   target frame                   4
//   nF                             x y z        <- one line per face, the first direction
//   k1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z  (header line, ignored)
//   k1 k2 d1x d1y d1z d2x d2y d2z  <- one line per face
// Face order is the mesh's. Both readers are strict: a wrong face count, a truncated file,
// a non-number, a NaN or infinity, or a zero (or face-normal) vector is a FieldError whose
// message names the file, the line and the problem. Vectors are projected onto their face and
// normalised.
#pragma once

#include "field/cross_field.h"

#include <string>

namespace fcql {

/// By extension (.ffield or .rosy).
CrossField loadField(const SurfaceMesh& mesh, const std::string& path);
CrossField loadFFieldFile(const SurfaceMesh& mesh, const std::string& path);
CrossField loadRosyFile(const SurfaceMesh& mesh, const std::string& path);
/// Parsers working on the text itself (the file name is used in messages only).
CrossField parseFField(const SurfaceMesh& mesh, const std::string& text, const std::string& name);
CrossField parseRosy(const SurfaceMesh& mesh, const std::string& text, const std::string& name);

void saveFField(const SurfaceMesh& mesh, const CrossField& field, const std::string& path);
void saveRosy(const SurfaceMesh& mesh, const CrossField& field, const std::string& path);

}  // namespace fcql
