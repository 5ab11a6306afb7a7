#include "filter_actions.h"

#include "compute_field_step.h"
#include "filter_parameters.h"
#include "layout_step.h"
#include "quad_step.h"
#include "trace_step.h"

#include <exception>
#include <memory>
#include <new>

namespace fcql_meshlab {

namespace {

const char* const kNeedsField =
    "<br>Needs the cross field left on the mesh by <i>Compute Cross Field</i> (run it first; "
    "the filter fails with that message otherwise). The separatrices are traced again from "
    "that field with the given parameters, which gives the same result every time.";

const char* const kReference =
    "<br><br>See: <i>Nico Pietroni, Enrico Puppo, Giorgio Marcias, Roberto Scopigno, Paolo "
    "Cignoni</i><br><b>\"Tracing Field-Coherent Quad Layouts\"</b><br>Computer Graphics Forum "
    "35(7), Pacific Graphics 2016.";

using fcql::PipelineStage;

bool upTo(PipelineStage stage, PipelineStage last) { return int(stage) <= int(last); }

/// What a filter ran: the field stage and the later ones up to its own.
struct StageRun {
  FieldStepResult field;
  std::unique_ptr<TraceStepResult> trace;
  std::unique_ptr<LayoutStepResult> layout;
  std::unique_ptr<QuadStepResult> quad;
};

/// The progress bar's share of each stage (end percent of field, trace, layout; quad ends at
/// 100), by the last stage the filter runs; the field is computed only by filters 1 and 5.
const int* progressEnds(PipelineStage last, bool computeField) {
  static const int all[] = {10, 45, 80}, trace[] = {5, 100, 100}, layout[] = {2, 40, 100}, quad[] = {2, 35, 70},
                   field[] = {100, 100, 100};
  if (computeField) return last == PipelineStage::Field ? field : all;
  return last == PipelineStage::Trace ? trace : last == PipelineStage::Layout ? layout : quad;
}

/// Runs the pipeline's stages up to `last`: filters 1 and 5 compute the field, filters 2-4
/// start from the one on the mesh. Nothing is written to the document.
StageRun runStages(const MeshModel& mm, const fcql::PipelineParameters& params, bool computeField, PipelineStage last,
                   const Progress& progress) {
  const int* end = progressEnds(last, computeField);
  const std::string name = mm.label().toStdString();
  StageRun r;
  r.field = computeField ? computeFieldStep(mm.cm, name, params, progress.sub(0, end[0]))
                         : readStoredFieldStep(mm.cm, name, params, progress.sub(0, end[0]));
  const fcql::SurfaceMesh& mesh = r.field.converted.mesh;
  const fcql::CrossField& field = r.field.stage.field;
  const fcql::FieldAnalysis& analysis = r.field.stage.analysis;
  // A quad count out of reach fails before any tracing.
  if (last == PipelineStage::Quad) fcql::quadTargetEdge(mesh, params, fcql::ParameterNaming::FilterName);
  if (upTo(PipelineStage::Trace, last))
    r.trace.reset(new TraceStepResult(computeTraceStep(mesh, field, analysis, params, progress.sub(end[0], end[1]))));
  if (upTo(PipelineStage::Layout, last))
    r.layout.reset(new LayoutStepResult(
        computeLayoutStep(mesh, field, analysis, r.trace->trace, params, progress.sub(end[1], end[2]))));
  if (last == PipelineStage::Quad)
    r.quad.reset(new QuadStepResult(computeQuadStep(mesh, field, r.layout->layout, params, progress.sub(end[2], 100))));
  return r;
}

/// Writes what the filter stores: the stages from `firstStored` on (filters 2-4 store only
/// their own stage, filters 1 and 5 all).
void store(MeshDocument& md, MeshModel& mm, const StageRun& r, PipelineStage firstStored) {
  if (firstStored == PipelineStage::Field) storeFieldStep(mm, r.field);
  if (r.trace && upTo(firstStored, PipelineStage::Trace)) storeTraceStep(md, mm, r.field.converted, *r.trace);
  if (r.layout && upTo(firstStored, PipelineStage::Layout)) storeLayoutStep(md, mm, r.field.converted, *r.layout);
  if (r.quad) storeQuadStep(md, *r.quad);
}

/// The stages' log lines and figures, what was stored, and the last line with every figure.
FilterOutcome outcomeOf(const StageRun& r, PipelineStage firstStored, Clock::time_point start) {
  FilterOutcome o;
  appendLog(o.log, r.field.stage.log);
  o.figures = r.field.stage.figures;
  const auto storedLines = [&](PipelineStage stage, const std::vector<std::string>& lines) {
    if (upTo(firstStored, stage)) o.log.insert(o.log.end(), lines.begin(), lines.end());
  };
  if (r.trace) {
    appendLog(o.log, r.trace->trace.log);
    storedLines(PipelineStage::Trace, describeTraceLayers(*r.trace));
    o.figures.append(r.trace->trace.figures);
  }
  if (r.layout) {
    appendLog(o.log, r.layout->layout.log);
    storedLines(PipelineStage::Layout, describeLayoutLayers(*r.layout));
    o.figures.append(r.layout->layout.figures);
  }
  if (r.quad) {
    appendLog(o.log, r.quad->quad.log);
    storedLines(PipelineStage::Quad, describeQuadLayer(*r.quad));
    o.figures.append(r.quad->quad.figures);
  }
  o.figures.set("time_s.total", secondsSince(start));
  o.log.push_back("Figures: " + o.figures.toFlatJson());
  return o;
}

/// A filter: parameters first (a bad value fails before any work), then the stages, and the
/// document writes last, so that a failure leaves the document as it was.
FilterOutcome runPipelineFilter(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                                vcg::CallBackPos* cb, PipelineStage last, bool computeField) {
  const auto start = Clock::now();
  const fcql::PipelineParameters params = readPipelineParameters(parameters);  // throws ParameterError
  const StageRun run = runStages(mm, params, computeField, last, Progress{cb});
  const PipelineStage firstStored = computeField ? PipelineStage::Field : last;
  store(md, mm, run, firstStored);
  return outcomeOf(run, firstStored, start);
}

}  // namespace

const std::vector<FilterId>& allFilters() {
  static const std::vector<FilterId> filters = {FP_COMPUTE_CROSS_FIELD, FP_TRACE_SEPARATRICES,
                                                FP_SOLVE_LAYOUT, FP_QUADRANGULATE, FP_ALL_STEPS};
  return filters;
}

QString filterName(FilterId id) {
  switch (id) {
    case FP_COMPUTE_CROSS_FIELD: return QStringLiteral("Field-Coherent Quad Layout: Compute Cross Field");
    case FP_TRACE_SEPARATRICES: return QStringLiteral("Field-Coherent Quad Layout: Trace Separatrices");
    case FP_SOLVE_LAYOUT: return QStringLiteral("Field-Coherent Quad Layout: Solve Layout");
    case FP_QUADRANGULATE: return QStringLiteral("Field-Coherent Quad Layout: Quadrangulate");
    case FP_ALL_STEPS: return QStringLiteral("Field-Coherent Quad Layout: All Steps");
  }
  return QString();
}

QString pythonFilterName(FilterId id) {
  switch (id) {
    case FP_COMPUTE_CROSS_FIELD: return QStringLiteral("compute_field_coherent_cross_field");
    case FP_TRACE_SEPARATRICES: return QStringLiteral("trace_field_coherent_separatrices");
    case FP_SOLVE_LAYOUT: return QStringLiteral("solve_field_coherent_quad_layout");
    case FP_QUADRANGULATE: return QStringLiteral("quadrangulate_field_coherent_quad_layout");
    case FP_ALL_STEPS: return QStringLiteral("compute_field_coherent_quad_layout");
  }
  return QString();
}

QString filterInfo(FilterId filter) {
  QString info;
  switch (filter) {
    case FP_COMPUTE_CROSS_FIELD:
      info = QStringLiteral(
          "First step of the field-coherent quad layout: computes a smooth cross field "
          "(4-RoSy) on the faces of the mesh, aligned to the principal curvature directions "
          "where they are well defined, to feature lines of sharp edges and to the borders, "
          "then finds its singular vertices and the directions of the separatrices leaving "
          "them.<br>The field is stored per face as curvature directions (PD1 = one direction "
          "of the cross, PD2 = PD1 rotated by 90 degrees). Singular vertices are selected, "
          "their index times 4 is stored in the per-vertex quality (-1 for index -1/4, +1 for "
          "+1/4, 0 elsewhere), and they are flagged in the per-vertex attribute "
          "<i>fcql_singular</i>. The counts of singularities by index are written to the log."
          "<br>The mesh must be an oriented 2-manifold triangle mesh without degenerate faces.");
      break;
    case FP_TRACE_SEPARATRICES:
      info = QStringLiteral(
          "Second step of the field-coherent quad layout: traces the candidate separatrices. "
          "A graph G is built on the mesh (its vertices, auxiliary points on the edges placed "
          "every <i>phi</i> degrees, and the separatrix ports of the singularities); from "
          "every port a Dijkstra search in the field-aware metric (drift penalty "
          "<i>alpha</i>) finds paths to the <i>k</i> nearest ports. These paths form the "
          "graph H of candidates; pairs of candidates that cross tangentially (they cannot "
          "both be in a layout) or orthogonally are listed.<br>Stored: per face, the number "
          "of candidates crossing it (attributes <i>fcql_candidates</i>, int, and "
          "<i>fcql_candidates_f</i>, float); a new layer <i>candidate separatrices</i> with "
          "the candidates as polylines (an edge mesh: save it as OBJ to get <i>l</i> lines). "
          "The log gives the sizes of G and H, the crossing pairs and the times.");
      info += QString::fromUtf8(kNeedsField);
      break;
    case FP_SOLVE_LAYOUT:
      info = QStringLiteral(
          "Third step of the field-coherent quad layout: selects among the candidate "
          "separatrices those forming the layout (0-1 programs solved with lp_solve, each "
          "within <i>ilp_time_limit</i> seconds, repeated on the ports left dangling), joins "
          "the remaining ports to the layout with t-junctions or to the border, and cuts the "
          "surface into patches, which should all be 4-sided disks.<br>The patches follow the "
          "separatrices exactly only on a refined copy of the surface in which every face "
          "crossed by a separatrix is split along it. The input mesh keeps its faces and its "
          "field (so any filter can be run again on it) and gets, per face, the patch that "
          "covers most of the face's area: attributes <i>fcql_patch</i> (int) and "
          "<i>fcql_patch_f</i> (float), and the face colour (one colour per patch); faces "
          "crossed by separatrices are counted in <i>fcql_separatrices</i> / "
          "<i>fcql_separatrices_f</i>. New layers: <i>separatrices</i>, the separatrices of "
          "the layout as polylines (edge mesh), and <i>patch layout</i>, the refined surface "
          "cut along them, coloured by patch with the exact <i>fcql_patch</i> / "
          "<i>fcql_patch_f</i> and vertex quality 1 at the patch corners. The log gives "
          "patches with their corner counts, t-junctions, iterations, invalid patches and "
          "times.");
      info += QString::fromUtf8(kNeedsField);
      break;
    case FP_QUADRANGULATE:
      info = QStringLiteral(
          "Fourth step of the field-coherent quad layout: builds the quad mesh. The layout "
          "is computed as <i>Solve Layout</i> does, then every patch side gets an integer "
          "number of quad edges close to its length divided by the target edge length "
          "(<i>scale</i> times the bounding-box diagonal), with opposite sides of a patch "
          "equal (an integer program; patches that would get no quads are split), and each "
          "patch is sampled into a grid of quads.<br>Stored: a new layer <i>quad mesh</i>. "
          "MeshLab has no quads, so each quad is two triangles whose shared diagonal is a "
          "faux edge (hidden in wireframe; keep it when saving with the face flags). Faces "
          "are coloured by the layout patch they come from and their quality is the scaled "
          "Jacobian of the quad (1 = square, 0 or less = folded). The log gives quads, "
          "vertices, irregular vertices, genus and times.");
      info += QString::fromUtf8(kNeedsField);
      break;
    case FP_ALL_STEPS:
      info = QStringLiteral(
          "Runs the whole field-coherent quad layout in one go, with all the parameters: "
          "<i>Compute Cross Field</i>, <i>Trace Separatrices</i>, <i>Solve Layout</i> and "
          "<i>Quadrangulate</i>, and stores what each of them stores: the field, "
          "singularities and per-face attributes on the input mesh, and the layers "
          "<i>candidate separatrices</i>, <i>separatrices</i>, <i>patch layout</i> and "
          "<i>quad mesh</i>. Nothing is written if any step fails.");
      break;
  }
  return info + QString::fromUtf8(kReference);
}

int filterPreConditions(FilterId) { return MeshModel::MM_FACENUMBER; }

int filterPostConditions(FilterId id) {
  switch (id) {
    case FP_COMPUTE_CROSS_FIELD:
      return MeshModel::MM_FACECURVDIR | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTFLAGSELECT;
    case FP_TRACE_SEPARATRICES:
      return MeshModel::MM_NONE;  // attributes and a new layer only
    case FP_SOLVE_LAYOUT:
      return MeshModel::MM_FACECOLOR;
    case FP_QUADRANGULATE:
      return MeshModel::MM_NONE;  // a new layer only
    case FP_ALL_STEPS:
      return MeshModel::MM_FACECURVDIR | MeshModel::MM_VERTQUALITY |
             MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_FACECOLOR;
  }
  return MeshModel::MM_ALL;
}

void addFilterParameters(FilterId id, RichParameterList& parameters) {
  switch (id) {
    case FP_COMPUTE_CROSS_FIELD:
      addStageParameters(fcql::PipelineStage::Field, parameters);
      break;
    case FP_TRACE_SEPARATRICES:
      addStageParameters(fcql::PipelineStage::Trace, parameters);
      break;
    case FP_SOLVE_LAYOUT:
      addStageParameters(fcql::PipelineStage::Trace, parameters);
      addStageParameters(fcql::PipelineStage::Layout, parameters);
      break;
    case FP_QUADRANGULATE:
      addStageParameters(fcql::PipelineStage::Trace, parameters);
      addStageParameters(fcql::PipelineStage::Layout, parameters);
      addStageParameters(fcql::PipelineStage::Quad, parameters);
      break;
    case FP_ALL_STEPS:
      addStageParameters(fcql::PipelineStage::Field, parameters);
      addStageParameters(fcql::PipelineStage::Trace, parameters);
      addStageParameters(fcql::PipelineStage::Layout, parameters);
      addStageParameters(fcql::PipelineStage::Quad, parameters);
      break;
  }
}

FilterOutcome runFilter(FilterId id, MeshDocument& md, const RichParameterList& parameters,
                        vcg::CallBackPos* cb) {
  const auto failure = [id](const std::string& reason) {
    return FilterFailure(filterName(id).toStdString() + " failed: " + reason);
  };
  MeshModel* mm = md.mm();
  if (!mm) throw failure("there is no current mesh");
  // Everything is computed before the document is written, so any exception leaves it as it was.
  try {
    switch (id) {
      case FP_COMPUTE_CROSS_FIELD: return runPipelineFilter(md, *mm, parameters, cb, PipelineStage::Field, true);
      case FP_TRACE_SEPARATRICES: return runPipelineFilter(md, *mm, parameters, cb, PipelineStage::Trace, false);
      case FP_SOLVE_LAYOUT: return runPipelineFilter(md, *mm, parameters, cb, PipelineStage::Layout, false);
      case FP_QUADRANGULATE: return runPipelineFilter(md, *mm, parameters, cb, PipelineStage::Quad, false);
      case FP_ALL_STEPS: return runPipelineFilter(md, *mm, parameters, cb, PipelineStage::Quad, true);
    }
  } catch (const std::bad_alloc&) {
    throw failure("out of memory");
  } catch (const std::exception& e) {
    throw failure(e.what());
  } catch (...) {
    throw failure("unexpected error");
  }
  throw failure("this filter is not implemented");
}

}  // namespace fcql_meshlab
