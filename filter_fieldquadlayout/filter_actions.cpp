#include "filter_actions.h"

#include "compute_field_step.h"
#include "filter_parameters.h"
#include "layout_step.h"
#include "quad_step.h"
#include "stored_field.h"
#include "trace_step.h"

#include <exception>
#include <new>

namespace fcql_meshlab {

namespace {

// How All Steps splits its progress bar between the stages (percent).
constexpr int kAllFieldEnd = 10, kAllTraceEnd = 45, kAllLayoutEnd = 80;

const char* const kNeedsField =
    "<br>Needs the cross field left on the mesh by <i>Compute Cross Field</i> (run it first; "
    "the filter fails with that message otherwise). The separatrices are traced again from "
    "that field with the given parameters, which gives the same result every time.";

const char* const kReference =
    "<br><br>See: <i>Nico Pietroni, Enrico Puppo, Giorgio Marcias, Roberto Scopigno, Paolo "
    "Cignoni</i><br><b>\"Tracing Field-Coherent Quad Layouts\"</b><br>Computer Graphics Forum "
    "35(7), Pacific Graphics 2016.";


void addInt(FilterOutcome& o, const char* key, long long value) {
  o.figures.push_back({key, double(value), true});
}
void addSeconds(FilterOutcome& o, const char* key, double seconds) {
  o.figures.push_back({key, seconds, false});
}
void addLines(FilterOutcome& o, const std::vector<std::string>& lines) {
  o.log.insert(o.log.end(), lines.begin(), lines.end());
}

// ---- the figures of each stage, for pymeshlab's dictionary --------------------------------

void addFieldFigures(FilterOutcome& o, const fcql::SurfaceMesh& mesh,
                     const fcql::FieldAnalysis& a) {
  addInt(o, "faces", mesh.numFaces());
  addInt(o, "vertices", mesh.numVertices());
  addInt(o, "genus", mesh.genus());
  addInt(o, "border_loops", mesh.numBorderLoops());
  addInt(o, "singularities", a.numInteriorSingularities());
  addInt(o, "border_singularities", a.numBorderSingularities());
  addInt(o, "ports", a.numPorts());
}

void addTraceFigures(FilterOutcome& o, const TraceStepResult& t) {
  addInt(o, "graph_g_nodes", t.trace.graph->numNodes());
  addInt(o, "graph_g_arcs", t.trace.graph->numArcs());
  addInt(o, "h_arcs", long(t.trace.h.arcs.size()));
  addInt(o, "tangential_pairs", long(t.trace.h.tangentialPairs.size()));
  addSeconds(o, "time_graph", t.trace.graphSeconds);
  addSeconds(o, "time_tracing", t.trace.tracingSeconds);
}

void addLayoutFigures(FilterOutcome& o, const LayoutStepResult& r) {
  const fcql::Layout& l = r.layout.layout;
  addInt(o, "separatrices", long(l.separatrices.size()));
  addInt(o, "patches", r.layout.patches.numPatches());
  addInt(o, "invalid_patches", r.layout.patches.numInvalidPatches());
  addInt(o, "t_junctions", l.tJunctions);
  addInt(o, "border_connections", l.borderConnections);
  addInt(o, "iterations", l.iterations);
  addInt(o, "dangling_ports", l.danglingAfterCycle);  // as fcql's layout.dangling_ports
  addInt(o, "unresolved_ports", long(l.unresolvedPorts.size()));
  addInt(o, "completion_accepted", l.completion.accepted);
  addInt(o, "dead_ends_removed", l.deadEndsRemoved);
  addInt(o, "added_corners", r.layout.patches.addedCorners);
  addInt(o, "ilp_time_limited", l.ilpTimeLimited);
  addSeconds(o, "time_ilp", l.ilpSeconds);
  addSeconds(o, "time_layout", r.seconds);
}

void addQuadFigures(FilterOutcome& o, const QuadStepResult& q) {
  addInt(o, "quads", q.quad.mesh.numQuads());
  addInt(o, "quad_vertices", q.quad.mesh.numVertices());
  addInt(o, "irregular_vertices", q.quad.report.irregularVertices);
  addInt(o, "base_complex_patches", q.baseComplexPatches);
  addInt(o, "quad_genus", q.quad.report.genus);
  addInt(o, "split_patches", q.quad.splitPatches);
  addInt(o, "time_limited_parts", q.quad.timeLimitedParts);
  addInt(o, "inverted_quads", q.invertedQuads);
  addSeconds(o, "time_quadrangulation", q.seconds);
}

// ---- the filters ----------------------------------------------------------------------------

FilterOutcome computeCrossField(MeshModel& mm, const RichParameterList& parameters,
                                vcg::CallBackPos* cb) {
  const FieldParameters params = readFieldParameters(parameters);  // throws ParameterError
  const FieldStepResult result = computeFieldStep(mm.cm, params, Progress{cb});
  storeFieldStep(mm, result);
  FilterOutcome o;
  addLines(o, describeFieldStep(result, params));
  addFieldFigures(o, result.converted.mesh, result.analysis);
  addSeconds(o, "time_field", result.conversionSeconds + result.fieldSeconds +
                                  result.analysisSeconds);
  return o;
}

// Filters 2-4: parameters first (a bad value fails before any work), then the stored field,
// the stages, and the document writes last.

FilterOutcome traceSeparatrices(MeshDocument& md, MeshModel& mm,
                                const RichParameterList& parameters, vcg::CallBackPos* cb) {
  const TracingParameters tp = readTracingParameters(parameters);
  const Progress progress{cb};
  progress(0, "reading the cross field");
  const StoredField s = readStoredField(mm.cm);
  const TraceStepResult t =
      computeTraceStep(s.converted.mesh, s.field, s.analysis, tp, progress.sub(5, 100));
  storeTraceStep(md, mm, s.converted, t);
  FilterOutcome o;
  addLines(o, describeTraceStep(t, true));
  addFieldFigures(o, s.converted.mesh, s.analysis);
  addTraceFigures(o, t);
  return o;
}

FilterOutcome solveLayout(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                          vcg::CallBackPos* cb) {
  const TracingParameters tp = readTracingParameters(parameters);
  const LayoutParameters lp = readLayoutParameters(parameters);
  const Progress progress{cb};
  progress(0, "reading the cross field");
  const StoredField s = readStoredField(mm.cm);
  const fcql::SurfaceMesh& mesh = s.converted.mesh;
  const TraceStepResult t = computeTraceStep(mesh, s.field, s.analysis, tp, progress.sub(2, 40));
  const LayoutStepResult l =
      computeLayoutStep(mesh, s.field, s.analysis, t.trace, lp, progress.sub(40, 100));
  storeLayoutStep(md, mm, s.converted, l);
  FilterOutcome o;
  addLines(o, describeTraceStep(t, false));
  addLines(o, describeLayoutStep(l, true));
  addFieldFigures(o, mesh, s.analysis);
  addTraceFigures(o, t);
  addLayoutFigures(o, l);
  return o;
}

FilterOutcome quadrangulate(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                            vcg::CallBackPos* cb) {
  const TracingParameters tp = readTracingParameters(parameters);
  const LayoutParameters lp = readLayoutParameters(parameters);
  const QuadParameters qp = readQuadParameters(parameters);
  const Progress progress{cb};
  progress(0, "reading the cross field");
  const StoredField s = readStoredField(mm.cm);
  const fcql::SurfaceMesh& mesh = s.converted.mesh;
  const TraceStepResult t = computeTraceStep(mesh, s.field, s.analysis, tp, progress.sub(2, 35));
  const LayoutStepResult l =
      computeLayoutStep(mesh, s.field, s.analysis, t.trace, lp, progress.sub(35, 70));
  const QuadStepResult q = computeQuadStep(mesh, s.field, l.layout, lp, qp, progress.sub(70, 100));
  storeQuadStep(md, q);
  FilterOutcome o;
  addLines(o, describeTraceStep(t, false));
  addLines(o, describeLayoutStep(l, false));
  addLines(o, describeQuadStep(q));
  addFieldFigures(o, mesh, s.analysis);
  addTraceFigures(o, t);
  addLayoutFigures(o, l);
  addQuadFigures(o, q);
  return o;
}

FilterOutcome allSteps(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                       vcg::CallBackPos* cb) {
  const auto start = Clock::now();
  const FieldParameters fp = readFieldParameters(parameters);
  const TracingParameters tp = readTracingParameters(parameters);
  const LayoutParameters lp = readLayoutParameters(parameters);
  const QuadParameters qp = readQuadParameters(parameters);
  const Progress progress{cb};
  const FieldStepResult f = computeFieldStep(mm.cm, fp, progress.sub(0, kAllFieldEnd));
  // The later stages run on the field as the document will hold it (single precision), as
  // the separate filters would read it back: All Steps gives exactly their results.
  const fcql::SurfaceMesh& mesh = f.converted.mesh;
  const fcql::CrossField field = fieldAsStored(f.converted, f.field);
  const fcql::FieldAnalysis analysis = fcql::analyzeField(mesh, field);
  const TraceStepResult t =
      computeTraceStep(mesh, field, analysis, tp, progress.sub(kAllFieldEnd, kAllTraceEnd));
  const LayoutStepResult l = computeLayoutStep(mesh, field, analysis, t.trace, lp,
                                               progress.sub(kAllTraceEnd, kAllLayoutEnd));
  const QuadStepResult q =
      computeQuadStep(mesh, field, l.layout, lp, qp, progress.sub(kAllLayoutEnd, 100));
  storeFieldStep(mm, f);
  storeTraceStep(md, mm, f.converted, t);
  storeLayoutStep(md, mm, f.converted, l);
  storeQuadStep(md, q);
  FilterOutcome o;
  addLines(o, describeFieldStep(f, fp));
  addLines(o, describeTraceStep(t, true));
  addLines(o, describeLayoutStep(l, true));
  addLines(o, describeQuadStep(q));
  addFieldFigures(o, mesh, analysis);
  addSeconds(o, "time_field", f.conversionSeconds + f.fieldSeconds + f.analysisSeconds);
  addTraceFigures(o, t);
  addLayoutFigures(o, l);
  addQuadFigures(o, q);
  addSeconds(o, "time_total", secondsSince(start));
  return o;
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
      addFieldParameters(parameters);
      break;
    case FP_TRACE_SEPARATRICES:
      addTracingParameters(parameters);
      break;
    case FP_SOLVE_LAYOUT:
      addTracingParameters(parameters);
      addLayoutParameters(parameters);
      break;
    case FP_QUADRANGULATE:
      addTracingParameters(parameters);
      addLayoutParameters(parameters);
      addQuadParameters(parameters);
      break;
    case FP_ALL_STEPS:
      addFieldParameters(parameters);
      addTracingParameters(parameters);
      addLayoutParameters(parameters);
      addQuadParameters(parameters);
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
      case FP_COMPUTE_CROSS_FIELD: return computeCrossField(*mm, parameters, cb);
      case FP_TRACE_SEPARATRICES: return traceSeparatrices(md, *mm, parameters, cb);
      case FP_SOLVE_LAYOUT: return solveLayout(md, *mm, parameters, cb);
      case FP_QUADRANGULATE: return quadrangulate(md, *mm, parameters, cb);
      case FP_ALL_STEPS: return allSteps(md, *mm, parameters, cb);
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
