// Parameters of the Field-Coherent Quad Layout filters (DESIGN.md §3, §4), made from the
// pipeline's one parameter table (vcg_ext/pipeline/parameters.h): each filter adds the groups
// of the stages it runs (Solve Layout: tracing and layout; All Steps: all four), with the
// table's names (valid Python identifiers: .mlx scripts and pymeshlab keywords), labels,
// defaults and help texts, and reads them back validated against the table's ranges: MeshLab
// passes out-of-range and unparsable values through, so validation is the filter's job. A
// parameter absent from the list (an .mlx script written before it existed) takes its default.
#pragma once

#include "meshlab_api.h"

#include "pipeline/parameters.h"

namespace fcql_meshlab {

using ParameterError = fcql::ParameterError;

/// Adds the table's parameters of `stage` that the filters have.
void addStageParameters(fcql::PipelineStage stage, RichParameterList& list);

/// Every table parameter present in `list`, validated (throws ParameterError naming it, its
/// value and the valid range); the others keep their defaults.
fcql::PipelineParameters readPipelineParameters(const RichParameterList& list);

}  // namespace fcql_meshlab
