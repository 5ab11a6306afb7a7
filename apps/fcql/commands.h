// The fcql subcommands. Each returns the process exit status; errors are thrown and reported
// by main as one line.
#pragma once

#include "field/cross_field.h"
#include "field/field_analysis.h"
#include "mesh/surface_mesh.h"
#include "stats_json.h"
#include "layout/patch_layout.h"
#include "mesh/quad_mesh.h"
#include "quadrangulation/side_lengths.h"
#include "tracing/separatrix_graph.h"

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace fcql {

class CommandLine;

/// What the input stage (mesh + cross field + analysis) produced.
struct FieldStage {
  std::string meshName;
  SurfaceMesh mesh;
  CrossField field;
  FieldAnalysis analysis;
  double seconds = 0;
};

/// Throws UsageError unless --out is given and names a directory that exists and can be written,
/// or can be created: checked before any work, so a long run never ends on a bad --out.
void requireOutputDir(const CommandLine& cl);

/// Progress and information lines on stderr, silenced by --quiet.
void progress(bool quiet, const std::string& line);

using Clock = std::chrono::steady_clock;
/// Records time_s.output (writing the result files, since `outputStart`) and time_s.total
/// (the whole command since `start`, those files included): call just before stats.json is
/// written, the one file it leaves out.
void recordTotalTime(StatsJson& stats, Clock::time_point start, Clock::time_point outputStart);

/// Loads MESH (first positional) or builds --example NAME, then reads --field or computes a
/// field (--sharp-angle), analyses it and records mesh.* field.* time_s.field in `stats`.
/// `checkMesh`, if given, sees the mesh as soon as it is loaded, before the field is computed
/// (to refuse options that the mesh makes impossible before any work).
FieldStage runFieldStage(const CommandLine& cl, StatsJson& stats, bool quiet,
                         const std::function<void(const SurfaceMesh&)>& checkMesh = nullptr);

/// What the tracing stage (graph G, searches, graph H) produced.
struct TraceStage {
  std::unique_ptr<GeodesicGraph> graph;
  SeparatrixGraph h;
  double graphSeconds = 0, tracingSeconds = 0;
};

/// Reads --alpha --k --phi --threads (validated, with the option named in errors).
TracingParameters readTracingParameters(const CommandLine& cl);
TraceStage runTraceStage(const FieldStage& fs, const TracingParameters& params, StatsJson& stats, bool quiet);
std::string candidatesObj(const SeparatrixGraph& h);

/// What the layout stage (selection, cycle, propagation, cut, patches) produced.
struct LayoutStage {
  FieldAnalysis analysis;                 ///< the field analysis plus any virtual anchors
  std::unique_ptr<GeodesicGraph> graph;   ///< rebuilt if anchors were added, else null
  Layout layout;
  PatchLayout patches;
  double cutSeconds = 0;
};
LayoutParameters readLayoutParameters(const CommandLine& cl);
LayoutStage runLayoutStage(const FieldStage& fs, const TraceStage& ts, const LayoutParameters& params, StatsJson& stats, bool quiet);

/// What the quadrangulation stage produced.
struct QuadStage {
  PatchGraph graph;
  SideLengths lengths;
  QuadMesh mesh;
  QuadMeshReport report;
  double seconds = 0;
};
/// The target quad edge of --scale or --target-faces on `mesh`; throws UsageError if it asks for
/// more quads than the quad stage can hold (saying which value is the finest allowed).
double quadTargetEdge(const SurfaceMesh& mesh, const CommandLine& cl);
/// --param: "field" (default, each patch mapped field-aligned) or "mean-value" (the former
/// map); throws UsageError otherwise.
std::string quadParametrization(const CommandLine& cl);
QuadStage runQuadStage(const FieldStage& fs, const LayoutStage& ls, const CommandLine& cl, StatsJson& stats, bool quiet);

int fieldCommand(int argc, char** argv);
int quadCommand(int argc, char** argv);
int layoutCommand(int argc, char** argv);
int traceCommand(int argc, char** argv);
/// `fcql render DIR --out FILE.png`: pictures of a run's output directory (render_command.cpp).
int renderCommand(int argc, char** argv);

}  // namespace fcql
