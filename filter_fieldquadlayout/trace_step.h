// Filter 2, "Trace Separatrices": graph G and the candidate separatrices (graph H) traced on
// the cross field left by "Compute Cross Field". As for every filter, computeTraceStep() only
// reads and may throw; storeTraceStep() writes the document.
//
// What is stored:
//  - per-face int attribute "fcql_candidates" and float copy "fcql_candidates_f": how many
//    candidate separatrices (arcs of H) cross each face;
//  - a new edge-mesh layer "candidate separatrices": one polyline per arc of H.
#pragma once

#include "meshlab_api.h"

#include "document_layers.h"
#include "pipeline/trace_stage.h"
#include "step_common.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

constexpr const char* kCandidatesAttribute = "fcql_candidates";
constexpr const char* kCandidatesLayer = "candidate separatrices";

struct TraceStepResult {
  fcql::TraceStageResult trace;
  std::vector<int> candidatesPerFace;  ///< per SurfaceMesh face
  PolylineLayerData polylines;
};

/// Traces on `mesh`/`field`/`analysis`, which must outlive the result (graph G refers to them).
TraceStepResult computeTraceStep(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                                 const fcql::FieldAnalysis& analysis,
                                 const fcql::PipelineParameters& params, const Progress& progress);

void storeTraceStep(MeshDocument& md, MeshModel& mm, const ConvertedMesh& converted,
                    const TraceStepResult& result);

/// Log lines: graphs G and H, crossing pairs, times, and with `stored` what went into the
/// document (false for the filters that trace again but store something else).
/// What the step stored, for the log.
std::vector<std::string> describeTraceLayers(const TraceStepResult& result);

}  // namespace fcql_meshlab
