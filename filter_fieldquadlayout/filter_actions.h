// The five Field-Coherent Quad Layout filters, independent of the plugin interface: what both
// adapters (MeshLab 2020.09's MeshFilterInterface in filter_fieldquadlayout.cpp, the
// FilterPlugin API of MeshLab 2022.02+ and pymeshlab in filter_fieldquadlayout_2025.cpp) ask
// of a filter: its name, python name, description, pre/post conditions and parameters, and
// runFilter(), which does the work and returns the log lines and the run's figures. The
// adapters only translate these into their API (QAction ids, Log()/log(), errorMessage +
// false or MLException, the returned std::map<std::string, QVariant>).
//
// Filters (DESIGN.md §4; class Remeshing):
//   1. Field-Coherent Quad Layout: Compute Cross Field    (compute_field_step.h)
//   2. Field-Coherent Quad Layout: Trace Separatrices     (trace_step.h)
//   3. Field-Coherent Quad Layout: Solve Layout           (layout_step.h)
//   4. Field-Coherent Quad Layout: Quadrangulate          (quad_step.h)
//   5. Field-Coherent Quad Layout: All Steps              (the four steps above in one go)
// Filters 2-4 start from the cross field that filter 1 leaves on the mesh (per-face PD1) and
// re-trace from it (deterministic), so each needs only filter 1 to have run. Every filter
// computes everything first and writes the document last: a failure leaves it unchanged.
#pragma once

#include "meshlab_api.h"

#include "pipeline/figures.h"

#include <QString>

#include <stdexcept>
#include <string>
#include <vector>

namespace fcql_meshlab {

enum FilterId {
  FP_COMPUTE_CROSS_FIELD = 0,
  FP_TRACE_SEPARATRICES,
  FP_SOLVE_LAYOUT,
  FP_QUADRANGULATE,
  FP_ALL_STEPS,
};

/// The filters in menu order.
const std::vector<FilterId>& allFilters();

/// "Field-Coherent Quad Layout: Compute Cross Field", ... (menu names, .mlx filter names).
QString filterName(FilterId id);
/// compute_field_coherent_cross_field, trace_field_coherent_separatrices,
/// solve_field_coherent_quad_layout, quadrangulate_field_coherent_quad_layout,
/// compute_field_coherent_quad_layout (All Steps): the names pymeshlab users call.
QString pythonFilterName(FilterId id);
/// HTML description shown by MeshLab (and pymeshlab's documentation).
QString filterInfo(FilterId id);
/// MeshModel::MM_* masks.
int filterPreConditions(FilterId id);
int filterPostConditions(FilterId id);
/// Adds the filter's parameters (filter_parameters.h) to `list`.
void addFilterParameters(FilterId id, RichParameterList& list);

struct FilterOutcome {
  /// Lines for the log; problems start with "Warning: ". The last is "Figures: {...}", all the
  /// figures as one line of flat JSON.
  std::vector<std::string> log;
  /// The figures of every stage the filter ran, under the names of fcql's stats.json
  /// (vcg_ext/pipeline/figures.h): what pymeshlab's returned dictionary holds.
  fcql::Figures figures;
};

/// Why a filter failed: what() is the whole message, "<filter name> failed: <reason>".
struct FilterFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs the filter on the current mesh of `md` with `parameters` (validated first; a bad value
/// fails before any work). Throws FilterFailure, and then leaves the document unchanged.
FilterOutcome runFilter(FilterId id, MeshDocument& md, const RichParameterList& parameters,
                        vcg::CallBackPos* cb);

}  // namespace fcql_meshlab
