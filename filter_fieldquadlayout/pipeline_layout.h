// Layout stage shared by Solve Layout and All Steps, as the command-line tool runs it
// (apps/fcql/layout_command.cpp): fcql::solveLayout (0-1 programs, solving cycle,
// propagation), fcql::buildPatchLayout (cut into patches), and fcql::closeNonDiskPatches when
// some patch is not a disk (cylinders, tori).
#pragma once

#include "filter_parameters.h"
#include "pipeline_trace.h"

#include "layout/layout_solver.h"
#include "layout/patch_closing.h"
#include "layout/patch_layout.h"

#include <string>
#include <vector>

namespace fcql_meshlab {

struct LayoutResult {
  fcql::Layout layout;
  fcql::PatchLayout patches;
  bool closingRan = false;     ///< some patch was not a disk
  fcql::ClosingReport closing;
  double cutSeconds = 0;       ///< cutting into patches (and closing)
};

/// `mesh`, `field` and `analysis` are the ones `trace.graph` was built on. Throws
/// std::invalid_argument for bad parameters, std::runtime_error if the layout cannot be cut.
LayoutResult solveLayoutStage(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                              const fcql::FieldAnalysis& analysis, const TraceResult& trace,
                              const LayoutParameters& params, const Progress& progress);

/// Log lines: separatrices, patches with the corner histogram, t-junctions, iterations,
/// invalid patches with their problems, solver notes, times. Lines about problems start with
/// "Warning: ".
std::vector<std::string> describeLayout(const LayoutResult& result);

}  // namespace fcql_meshlab
