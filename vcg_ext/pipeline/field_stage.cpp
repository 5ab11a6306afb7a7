#include "field_stage.h"

#include "field/field_io.h"

#include <chrono>
#include <cstdio>

namespace fcql {

namespace {

/// "-1/4: 16, 1/4: 8" or "none".
std::string formatIndexHistogram(const FieldAnalysis& analysis) {
  std::string out;
  for (const auto& h : analysis.interiorHistogram()) out += (out.empty() ? "" : ", ") + h.first + ": " + std::to_string(h.second);
  return out.empty() ? std::string("none") : out;
}

}  // namespace

FieldStageResult runFieldStage(const MeshInput& input, const PipelineParameters& p, const FieldSource& source,
                               const StageObserver& observer) {
  const SurfaceMesh& mesh = *input.mesh;
  FieldStageResult r;
  StageLog log(observer);
  Figures& f = r.figures;
  log.info("Mesh: " + std::to_string(mesh.numFaces()) + " faces, " + std::to_string(mesh.numVertices()) +
           " vertices, genus " + std::to_string(mesh.genus()) + ", " + std::to_string(mesh.numBorderLoops()) +
           " border loops (" + input.name + ")");
  if (!input.weldingNote.empty()) log.note("Mesh: " + input.weldingNote);

  const auto start = std::chrono::steady_clock::now();
  log.progress(10, "cross field");
  std::string fieldName = "computed";
  if (!p.fieldFile.empty()) {
    r.field = loadField(mesh, p.fieldFile);
    fieldName = p.fieldFile;
    log.info("Cross field: read from " + p.fieldFile);
  } else if (p.useExisting && source.kept) {
    r.field = *source.kept;
    fieldName = "kept";
    log.info("Cross field: kept the field already on the mesh (per-face PD1/PD2)");
  } else {
    FieldGenerationOptions options;
    options.sharpAngleDeg = p.sharpAngleDeg;
    options.scale = p.fieldScale;
    r.field = generateCrossField(mesh, options, &r.generation);
    r.computed = true;
    char angle[80];
    std::snprintf(angle, sizeof angle, "%g deg, field scale %g", p.sharpAngleDeg, p.fieldScale);
    log.info(std::string("Cross field: computed") + (p.useExisting ? " (the mesh had no field to keep)" : "") +
             ", sharp angle " + angle + ": " + std::to_string(r.generation.sharpEdges) + " sharp edges, " +
             std::to_string(r.generation.constrainedFaces) + " constrained faces" +
             (r.generation.conesKept > 0
                  ? ", " + std::to_string(r.generation.conesKept) +
                        (r.generation.conesKept == 1 ? " cone vertex keeps a quarter turn of its"
                                                     : " cone vertices keep a quarter turn of their") +
                        " curvature (index +1/2 or more there otherwise)"
                  : std::string()) +
             (r.generation.pairsCancelled > 0
                  ? ", " + std::to_string(r.generation.pairsCancelled) +
                        (r.generation.pairsCancelled == 1 ? " quarter pair" : " quarter pairs") +
                        " of opposite singularities on the two ends of one edge cancelled"
                  : std::string()));
  }
  if (source.asStored) r.field = source.asStored(r.field);
  log.progress(80, "singularities and ports");
  r.analysis = analyzeField(mesh, r.field);
  r.seconds = secondsSince(start);
  const FieldAnalysis& a = r.analysis;
  log.info("Singularities: " + std::to_string(a.numInteriorSingularities()) + " (by index: " + formatIndexHistogram(a) +
           "), border singularities: " + std::to_string(a.numBorderSingularities()) + ", ports: " +
           std::to_string(a.numPorts()) + ", index sum: " + formatQuarterIndex(a.indexSumQuarters()) +
           " (Euler characteristic " + std::to_string(mesh.eulerCharacteristic()) + ")");
  for (const std::string& warning : fieldWarnings(mesh, a)) log.warning(warning);
  log.info("Time: cross field and analysis " + formatSeconds(r.seconds));
  log.progress(100, "cross field done");

  f.set("input.mesh", input.name);
  f.set("input.field", fieldName);
  f.set("mesh.faces", mesh.numFaces());
  f.set("mesh.vertices", mesh.numVertices());
  f.set("mesh.border_loops", mesh.numBorderLoops());
  f.set("mesh.genus", mesh.genus());
  f.set("mesh.euler_characteristic", mesh.eulerCharacteristic());
  f.set("mesh.welded_vertices", input.weldedVertices);
  f.set("field.singularities", a.numInteriorSingularities());
  f.setCounts("field.by_index", a.interiorHistogram());
  f.set("field.border_singularities", a.numBorderSingularities());
  f.set("field.ports", a.numPorts());
  f.set("field.index_sum", formatQuarterIndex(a.indexSumQuarters()));
  f.set("field.computed", r.computed);
  f.set("field.sharp_edges", r.generation.sharpEdges);
  f.set("field.constrained_faces", r.generation.constrainedFaces);
  f.set("field.quarter_cones", r.generation.conesKept);
  f.set("field.cancelled_pairs", r.generation.pairsCancelled);
  recordParameters(f, p, PipelineStage::Field);
  f.set("time_s.load", input.loadSeconds);
  f.set("time_s.field", r.seconds);
  r.log = std::move(log.lines);
  return r;
}

}  // namespace fcql
