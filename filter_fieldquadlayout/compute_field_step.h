// Filter 1, "Compute Cross Field", split in two phases so that a failure leaves the document
// untouched: computeFieldStep() only reads the MeshLab mesh and may throw (fcql::MeshError,
// fcql::FieldError, std::bad_alloc, ...); storeFieldStep() writes the results and does not
// throw on valid input.
//
// What is stored on the mesh:
//  - per-face PD1 = direction 0 of the cross, PD2 = direction 1 (= n × PD1);
//  - per-vertex quality = index × 4 (interior vertices: field index; border vertices: border
//    index; 0 on regular vertices);
//  - per-vertex bool attribute "fcql_singular": vertices listed by fcql::analyzeField as
//    singular (interior singularities and border vertices with a non-zero border index);
//  - the vertex selection is replaced by those vertices.
#pragma once

#include "meshlab_api.h"

#include "filter_parameters.h"
#include "meshlab_mesh_adapter.h"
#include "pipeline/field_stage.h"
#include "step_common.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

constexpr const char* kSingularAttribute = "fcql_singular";

/// The message of the error thrown when filters 2-4 find no field on the mesh.
constexpr const char* kNoFieldMessage = "no cross field on the mesh: run Compute Cross Field first";

struct FieldStepResult {
  ConvertedMesh converted;
  fcql::FieldStageResult stage;  ///< the field as the document stores it, its analysis, figures, log
};

/// Filter 1: the mesh converted and the pipeline's field stage run on it (a file, the field
/// already on the mesh if asked, or a computed one). The field is analysed as the document
/// will store it (single precision in MeshLab 2020.09), so later filters find the same.
FieldStepResult computeFieldStep(const CMeshO& cm, const std::string& meshName, const fcql::PipelineParameters& params,
                                 const Progress& progress);

/// Filters 2-4: the field Compute Cross Field left on the mesh (per-face PD1), kept and
/// analysed by the field stage. Throws fcql::FieldError(kNoFieldMessage) if there is none.
FieldStepResult readStoredFieldStep(const CMeshO& cm, const std::string& meshName,
                                    const fcql::PipelineParameters& params, const Progress& progress);

void storeFieldStep(MeshModel& mm, const FieldStepResult& result);

}  // namespace fcql_meshlab
