// The cross field left on a mesh by "Compute Cross Field" (per-face PD1/PD2), read back for the
// later filters together with the converted mesh and the field analysis (singularities, ports).
// The field is deterministic data on the mesh, so re-tracing from it gives the same graph every
// time.
#pragma once

#include "meshlab_api.h"

#include "field/field_analysis.h"
#include "meshlab_mesh_adapter.h"

namespace fcql_meshlab {

/// The message of the error thrown when the mesh carries no field.
constexpr const char* kNoFieldMessage =
    "no cross field on the mesh: run Compute Cross Field first";

struct StoredField {
  ConvertedMesh converted;
  fcql::CrossField field;
  fcql::FieldAnalysis analysis;
  double seconds = 0;  ///< conversion, reading and analysis
};

/// True if the per-face curvature directions are enabled and some live face has a non-zero
/// PD1 (what Compute Cross Field leaves).
bool hasStoredField(const CMeshO& cm);

/// Converts the mesh, reads the field from PD1 and analyses it. Throws fcql::FieldError with
/// kNoFieldMessage if !hasStoredField(cm); fcql::MeshError / fcql::FieldError (naming the face)
/// for a bad mesh or a partial field.
StoredField readStoredField(const CMeshO& cm);

}  // namespace fcql_meshlab
