// Stage 3 (DESIGN.md §2): the separatrices of the layout (0-1 programs, solving cycle,
// completion, propagation), the cut into patches, and the closing of patches that are not
// disks (field lines through virtual singularities on cylinders and tori).
#pragma once

#include "layout/layout_solver.h"
#include "layout/patch_closing.h"
#include "layout/patch_layout.h"
#include "pipeline/trace_stage.h"

#include <string>
#include <vector>

namespace fcql {

struct LayoutStageResult {
  Layout layout;
  PatchLayout patches;
  bool closingRan = false;  ///< some patch was not a disk
  ClosingReport closing;
  Figures figures;          ///< params.ilp_* .completion_trials, graph_h.selected, layout.*, time_s.ilp ... time_s.cut
  std::vector<LogLine> log;
  double cutSeconds = 0;    ///< cutting into patches, closing included
};

/// `mesh`, `field` and `analysis` are the ones `trace.graph` was built on. Throws
/// std::invalid_argument for bad parameters, std::runtime_error if the layout cannot be cut.
LayoutStageResult runLayoutStage(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                                 const TraceStageResult& trace, const PipelineParameters& parameters,
                                 const StageObserver& observer);

}  // namespace fcql
