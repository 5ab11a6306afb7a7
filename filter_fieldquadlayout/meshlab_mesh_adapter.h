// Conversions between MeshLab's CMeshO and fcql's types.
//
// CMeshO -> fcql::SurfaceMesh: live (non-deleted) vertices and faces, in container order, so a
// mesh without deleted elements keeps its numbering. The MeshLab mesh is not modified (no
// compaction); the maps below translate indices both ways. Vertices lying exactly on another
// (an unwelded mesh) are merged when that leaves a valid mesh; faces keep their order.
//
// fcql::CrossField <-> per-face PD1/PD2 (vcglib convention): PD1 = direction 0 = u[f],
// PD2 = direction 1 = n × u[f].
#pragma once

#include "meshlab_api.h"

#include "field/cross_field.h"
#include "mesh/surface_mesh.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

/// A SurfaceMesh built from a CMeshO, with the index maps between the two.
struct ConvertedMesh {
  fcql::SurfaceMesh mesh;
  std::vector<int> meshLabVertex;     ///< SurfaceMesh vertex -> index in cm.vert
  std::vector<int> meshLabFace;       ///< SurfaceMesh face -> index in cm.face
  std::vector<int> vertexOfMeshLab;   ///< index in cm.vert -> SurfaceMesh vertex, -1 if deleted
  std::vector<int> faceOfMeshLab;     ///< index in cm.face -> SurfaceMesh face, -1 if deleted
  /// Vertices lying exactly on another were merged (fcql::weldCoincidentVertices): then
  /// meshLabVertex names the first of them, vertexOfMeshLab maps each to the merged one.
  int weldedVertices = 0;
  std::string weldingNote;            ///< for the log (empty if no vertex lies on another)
};

/// Builds the SurfaceMesh (double precision) of the live part of `cm`. Throws fcql::MeshError
/// if the mesh has no faces, a live face uses a deleted vertex, or the SurfaceMesh validation
/// fails (non-manifold, inconsistently oriented or degenerate input).
ConvertedMesh toSurfaceMesh(const CMeshO& cm);

/// True if `cm` carries per-face curvature directions (the optional component is enabled).
bool hasFaceField(const CMeshO& cm);

/// Reads the cross field from per-face PD1 (PD2 is implied by the 4-fold symmetry). Requires
/// hasFaceField(cm). Throws fcql::FieldError naming the face if a PD1 vector is zero, not
/// finite, or orthogonal to its face.
fcql::CrossField readFaceField(const CMeshO& cm, const ConvertedMesh& converted);

/// The field exactly as readFaceField() reads it back after writeFaceField() (PD1 holds
/// single-precision numbers). All Steps traces on this, so that its results are those of the
/// separate filters run one after the other on the stored field.
fcql::CrossField fieldAsStored(const ConvertedMesh& converted, const fcql::CrossField& field);

/// Writes PD1 = u, PD2 = n × u on the live faces. Requires the per-face curvature directions
/// to be enabled (MeshModel::updateDataMask(MM_FACECURVDIR)).
void writeFaceField(CMeshO& cm, const ConvertedMesh& converted, const fcql::CrossField& field);

}  // namespace fcql_meshlab
