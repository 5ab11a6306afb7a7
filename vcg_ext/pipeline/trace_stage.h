// Stage 2 (DESIGN.md §2): graph G on the field, the searches from every port and graph H of
// candidate separatrices.
#pragma once

#include "pipeline/field_stage.h"
#include "tracing/geodesic_graph.h"
#include "tracing/separatrix_graph.h"

#include <memory>
#include <string>
#include <vector>

namespace fcql {

struct TraceStageResult {
  /// Refers to the mesh, field and analysis it was built on: the caller keeps them in place.
  std::unique_ptr<GeodesicGraph> graph;
  SeparatrixGraph h;
  Figures figures;  ///< params.alpha .k .phi .threads, graph_g.*, graph_h.*, time_s.graph, time_s.tracing
  std::vector<LogLine> log;
  double graphSeconds = 0, tracingSeconds = 0;
};

/// The observer's progress gets "tracing separatrices (done/total ports)" as the searches end.
TraceStageResult runTraceStage(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                               const PipelineParameters& parameters, const StageObserver& observer);

/// The core's tracing parameters of a run.
TracingParameters tracingParameters(const PipelineParameters& parameters);

}  // namespace fcql
