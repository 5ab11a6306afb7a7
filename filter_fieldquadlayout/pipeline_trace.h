// Tracing stage shared by Trace Separatrices, Solve Layout and All Steps: graph G on the
// field (fcql::GeodesicGraph), then the candidate separatrices, graph H
// (fcql::traceCandidateSeparatrices).
#pragma once

#include "filter_parameters.h"
#include "step_common.h"

#include "tracing/geodesic_graph.h"
#include "tracing/separatrix_graph.h"

#include <memory>
#include <string>
#include <vector>

namespace fcql_meshlab {

struct TraceResult {
  /// Refers to the mesh, field and analysis given to traceSeparatrices(): the caller keeps
  /// them alive and in place as long as the graph is used.
  std::unique_ptr<fcql::GeodesicGraph> graph;
  fcql::SeparatrixGraph h;
  double graphSeconds = 0, tracingSeconds = 0;
};

/// The core's parameters (all hardware threads); throws std::invalid_argument if invalid.
fcql::TracingParameters toCoreParameters(const TracingParameters& params);

TraceResult traceSeparatrices(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                              const fcql::FieldAnalysis& analysis, const TracingParameters& params,
                              const Progress& progress);

/// Log lines: graph G (nodes, arcs, auxiliary points, ports), graph H (arcs, pairs).
std::vector<std::string> describeTrace(const TraceResult& trace);

}  // namespace fcql_meshlab
