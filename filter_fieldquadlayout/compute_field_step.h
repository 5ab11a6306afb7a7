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

#include "field/field_analysis.h"
#include "field/field_generation.h"
#include "filter_parameters.h"
#include "meshlab_mesh_adapter.h"
#include "step_common.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

constexpr const char* kSingularAttribute = "fcql_singular";

struct FieldStepResult {
  ConvertedMesh converted;
  fcql::CrossField field;
  fcql::FieldAnalysis analysis;
  bool keptExistingField = false;     ///< the field came from the mesh's PD1
  std::string fieldFile;              ///< the field came from this file (if not empty)
  bool existingFieldMissing = false;  ///< use_existing was asked but the mesh had no field
  fcql::FieldGenerationReport generation;
  double conversionSeconds = 0, fieldSeconds = 0, analysisSeconds = 0;
};

FieldStepResult computeFieldStep(const CMeshO& cm, const FieldParameters& params,
                                 const Progress& progress);

void storeFieldStep(MeshModel& mm, const FieldStepResult& result);

/// Lines for the MeshLab log: sizes, field source, singularities by index, ports, times.
std::vector<std::string> describeFieldStep(const FieldStepResult& result,
                                           const FieldParameters& params);

/// "-1/4: 16, 1/4: 8", or "none".
std::string formatHistogram(const fcql::FieldAnalysis& analysis);

}  // namespace fcql_meshlab
