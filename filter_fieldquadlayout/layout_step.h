// Filter 3, "Solve Layout": selects the separatrices (0-1 programs, solving cycle,
// t-junction and border propagation) and cuts the surface into patches.
//
// The patches live on a refined copy of the surface: every triangle crossed by separatrices is
// split along them (fcql::PatchLayout), so a patch boundary follows the separatrices exactly
// while the input mesh's faces do not. The input mesh is left as it is (its field stays valid
// for re-running any filter) and gets, per face, the patch covering most of the face's area;
// the exact patches are a new layer. What is stored:
//  - on the input mesh: per-face int attribute "fcql_patch" and float copy "fcql_patch_f"
//    (majority patch by area), face colour by that patch, per-face "fcql_separatrices" /
//    "fcql_separatrices_f" (how many layout separatrices cross the face);
//  - a new edge-mesh layer "separatrices": one polyline per separatrix of the layout
//    (including t-junction and border propagations);
//  - a new layer "patch layout": the surface cut along the separatrices, faces coloured by
//    patch with "fcql_patch"/"fcql_patch_f", vertex quality 1 at patch corners (0 elsewhere).
#pragma once

#include "meshlab_api.h"

#include "document_layers.h"
#include "pipeline/layout_stage.h"
#include "step_common.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

constexpr const char* kPatchAttribute = "fcql_patch";
constexpr const char* kSeparatricesAttribute = "fcql_separatrices";
constexpr const char* kSeparatricesLayer = "separatrices";
constexpr const char* kPatchLayoutLayer = "patch layout";

struct LayoutStepResult {
  fcql::LayoutStageResult layout;
  std::vector<int> patchOfFace;           ///< per SurfaceMesh face (majority by area)
  std::vector<int> separatricesPerFace;   ///< per SurfaceMesh face
  PolylineLayerData polylines;
  TriangleLayerData patchLayer;
};

LayoutStepResult computeLayoutStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                                   const fcql::FieldAnalysis& analysis, const fcql::TraceStageResult& trace,
                                   const fcql::PipelineParameters& params, const Progress& progress);

void storeLayoutStep(MeshDocument& md, MeshModel& mm, const ConvertedMesh& converted,
                     const LayoutStepResult& result);

/// What the step stored, for the log.
std::vector<std::string> describeLayoutLayers(const LayoutStepResult& result);

/// Per face of `numFaces`: the patch of the layout triangles covering most of its area
/// (-1 for a face without triangles, which does not happen on a valid layout).
std::vector<int> majorityPatchOfFaces(const fcql::PatchLayout& layout, int numFaces);

}  // namespace fcql_meshlab
