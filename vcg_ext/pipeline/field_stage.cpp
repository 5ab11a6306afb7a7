#include "field_stage.h"

#include "field/field_io.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace fcql {

namespace {

/// "-1/4: 16, 1/4: 8" or "none".
std::string formatIndexHistogram(const FieldAnalysis& analysis) {
  std::string out;
  for (const auto& h : analysis.interiorHistogram()) out += (out.empty() ? "" : ", ") + h.first + ": " + std::to_string(h.second);
  return out.empty() ? std::string("none") : out;
}

/// Half the mesh's edges (each counted once per face it bounds) are at least this long.
double medianEdgeLength(const SurfaceMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(3 * std::size_t(mesh.numFaces()));
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int i = 0; i < 3; ++i)
      lengths.push_back((mesh.position(mesh.face(f)[(i + 1) % 3]) - mesh.position(mesh.face(f)[i])).norm());
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

/// A mesh whose median edge is longer than this share of its bounding-box diagonal is too
/// coarse for a cross field with one direction per triangle and singularities only on
/// vertices. Measured (share of the diagonal): an icosahedron (0.36), a cube of 12 triangles
/// (0.58) and an STL-like cylinder with fans on its caps (0.29) got poor layouts (the cube 34
/// patches, 46-74% of the quads off the field), the same meshes split by midpoint subdivision
/// good ones (6 patches, under 1%); an 80-face icosahedron (0.17) and a cube of 4x4 squares a
/// face (0.14) were fine; the shared meshes are at 0.008-0.021.
constexpr double kCoarseMedianEdge = 0.2;

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
                  : std::string()) +
             (r.generation.closePairsCancelled > 0
                  ? ", " + std::to_string(r.generation.closePairsCancelled) +
                        (r.generation.closePairsCancelled == 1 ? " pair" : " pairs") +
                        " of opposite quarters closer than the field scale cancelled"
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
  const double diagonal = mesh.boundingBoxDiagonal(), medianEdge = medianEdgeLength(mesh);
  if (diagonal > 0 && medianEdge > kCoarseMedianEdge * diagonal) {
    char line[640];
    std::snprintf(line, sizeof line,
                  "The mesh is coarse: half its edges are longer than %.0f%% of its bounding-box diagonal. The cross "
                  "field has one direction per triangle and its singularities lie on vertices, so large triangles give "
                  "a poor layout (extra patches, quads off the field); subdivide the mesh first (midpoint subdivision "
                  "keeps its shape: MeshLab's Subdivision Surfaces: Midpoint) until its edges are a few quad edges long",
                  std::floor(100 * medianEdge / diagonal));
    log.warning(line);
  }
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
  f.set("field.cancelled_close_pairs", r.generation.closePairsCancelled);
  recordParameters(f, p, PipelineStage::Field);
  f.set("time_s.load", input.loadSeconds);
  f.set("time_s.field", r.seconds);
  r.log = std::move(log.lines);
  return r;
}

}  // namespace fcql
