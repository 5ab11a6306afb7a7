// Stage 1 of the pipeline (DESIGN.md §2): the cross field (read from a file, kept from the
// caller, or computed) and its analysis (singularities, ports). Called by fcql and by the
// filters alike; they only load the mesh and format what comes back.
#pragma once

#include "field/cross_field.h"
#include "field/field_analysis.h"
#include "field/field_generation.h"
#include "mesh/surface_mesh.h"
#include "pipeline/figures.h"
#include "pipeline/parameters.h"
#include "pipeline/stage_log.h"

#include <functional>
#include <string>
#include <vector>

namespace fcql {

/// The mesh a run starts from, as its front end loaded it.
struct MeshInput {
  const SurfaceMesh* mesh = nullptr;
  std::string name;          ///< input.mesh: a file name, "example:NAME" or a layer's name
  int weldedVertices = 0;    ///< vertices that lay on another and were merged
  std::string weldingNote;   ///< for the log; empty if none
  double loadSeconds = 0;    ///< time_s.load
};

/// Where a field other than a computed one comes from.
struct FieldSource {
  /// A field already on the mesh (the filters' "use existing field"); used when
  /// parameters.useExisting is set and no field file is named.
  const CrossField* kept = nullptr;
  /// Applied to the field before it is analysed: the filters store the field in the document's
  /// precision and the later stages read it back, so they analyse it as stored. May be empty.
  std::function<CrossField(const CrossField&)> asStored;
};

struct FieldStageResult {
  CrossField field;
  FieldAnalysis analysis;
  FieldGenerationReport generation;
  bool computed = false;       ///< the field was computed (not read, not kept)
  Figures figures;             ///< input.* mesh.* field.* params.* time_s.load time_s.field
  std::vector<LogLine> log;
  double seconds = 0;          ///< field and analysis
};

/// Throws fcql's load errors (FieldError for a bad field file) and std::invalid_argument.
FieldStageResult runFieldStage(const MeshInput& input, const PipelineParameters& parameters, const FieldSource& source,
                               const StageObserver& observer);


}  // namespace fcql
