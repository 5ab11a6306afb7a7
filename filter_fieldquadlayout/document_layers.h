// Results of the later filters as plain data (computed before the document is touched), and
// the few functions that write them into MeshLab's document: per-face attributes on the input
// mesh, new layers (polylines as edge meshes, triangle meshes with faux edges for quads).
//
// Per-face values come in two copies: an int attribute NAME and a float attribute NAME_f,
// because MeshLab 2020.09 saves only float attributes correctly (MESHLAB.md).
#pragma once

#include "meshlab_api.h"

#include "meshlab_mesh_adapter.h"
#include "tracing/traced_path.h"

#include <QString>

#include <array>
#include <string>
#include <vector>

namespace fcql_meshlab {

/// Polylines as an edge mesh: one vertex per path point (paths do not share vertices, so each
/// polyline stays a chain of its own), one edge per pair of consecutive distinct points.
struct PolylineLayerData {
  std::vector<fcql::Vec3> positions;
  std::vector<std::array<int, 2>> edges;
};
PolylineLayerData polylineLayer(const std::vector<const fcql::TracedPath*>& paths);

/// A triangle mesh for a new layer. Optional per-element arrays are empty when unused.
struct TriangleLayerData {
  std::vector<fcql::Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<char, 3>> faux;   ///< per triangle and edge i -> i+1: 1 = faux
  std::vector<int> facePatch;              ///< per triangle: colour and fcql_patch(_f)
  std::vector<float> faceQuality;          ///< per triangle
  std::vector<float> vertexQuality;        ///< per vertex
};

/// Per SurfaceMesh face: how many of `paths` have a segment inside it.
std::vector<int> pathsPerFace(const std::vector<const fcql::TracedPath*>& paths, int numFaces);

/// Writes per SurfaceMesh face `values` into the int attribute `name` and the float attribute
/// `name`_f of the MeshLab faces (replacing attributes of those names; `absent` on deleted
/// faces).
void setPerFaceValues(CMeshO& cm, const ConvertedMesh& converted, const std::string& name,
                      const std::vector<int>& values, int absent);

/// Colours the live faces by `patchOfFace` (per SurfaceMesh face, fcql::patchColour; grey for
/// -1). Enables MM_FACECOLOR first.
void colourFacesByPatch(MeshModel& mm, const ConvertedMesh& converted,
                        const std::vector<int>& patchOfFace);

/// New layers, added after the existing ones without becoming current (the next filter of a
/// script still works on the input mesh).
MeshModel* addPolylineLayer(MeshDocument& md, const QString& label, const PolylineLayerData& data);
MeshModel* addTriangleLayer(MeshDocument& md, const QString& label, const TriangleLayerData& data);

}  // namespace fcql_meshlab
