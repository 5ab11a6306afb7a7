// Stage 4 (DESIGN.md §2): integer side lengths, zero-chain splits, patch sampling, smoothing
// and the distance check (quadrangulation/), then the quad mesh's quality and its own coarse
// structure (metrics/).
#pragma once

#include "metrics/quad_quality.h"
#include "pipeline/layout_stage.h"
#include "quadrangulation/quadrangulation.h"

#include <string>
#include <vector>

namespace fcql {

/// The most quads a run may ask for: the quad stage took 1.14 GB for 2M quads (a sphere), so
/// 20M take about 11 GB, within a 16 GB machine.
constexpr long kMaxQuads = 20000000;

struct QuadStageResult {
  QuadrangulationResult quad;
  QuadQuality quality;
  int baseComplexPatches = -1;  ///< the quad mesh's own patches (-1: not manifold)
  double targetEdgeLength = 0;  ///< asked for (quad.targetEdgeLength: after refinements)
  Figures figures;              ///< params.scale ... .param, quad.*, time_s.quadrangulation, time_s.metrics
  std::vector<LogLine> log;
  double seconds = 0;           ///< the quad mesh, metrics left out
};

/// The target quad edge of parameters.targetFaces (if > 0) or parameters.scale on `mesh`.
/// Throws ParameterError if it asks for more than kMaxQuads quads, naming the finest value
/// allowed as `naming` shows parameters.
double quadTargetEdge(const SurfaceMesh& mesh, const PipelineParameters& parameters, ParameterNaming naming);

QuadStageResult runQuadStage(const SurfaceMesh& mesh, const CrossField& field, const LayoutStageResult& layout,
                             const PipelineParameters& parameters, const StageObserver& observer);

}  // namespace fcql
