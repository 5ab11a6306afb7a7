#include "quad_stage.h"

#include "mesh/closest_point_index.h"
#include "metrics/base_complex.h"
#include "util/math_constants.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace fcql {

namespace {

double surfaceArea(const SurfaceMesh& mesh) {
  double area = 0;
  for (int f = 0; f < mesh.numFaces(); ++f) area += mesh.faceArea(f);
  return area;
}

QuadrangulationOptions quadOptions(const SurfaceMesh& mesh, const CrossField& field, const PipelineParameters& p,
                                   double target) {
  QuadrangulationOptions options;
  options.targetEdgeLength = target;
  options.ilpTimeLimit = p.ilpTimeLimit;
  options.smoothing.iterations = p.smooth;
  options.smoothing.sharpAngleDeg = p.sharpAngleDeg;
  options.smoothing.threads = p.threads;
  options.maxDeviation = p.maxDeviation;
  options.maxQuads = kMaxQuads;
  if (p.param == "field") options.fieldDirections = field.u;
  return options;
}

void describe(const QuadStageResult& s, const QuadrangulationOptions& options, int layoutPatches,
              double misalignmentThresholdDeg, StageLog& log) {
  const QuadrangulationResult& r = s.quad;
  const QuadMesh& q = r.mesh;
  for (const std::string& note : refinementNotes(r, options)) log.info(note);
  if (r.snappedVertices > 0)
    log.info(std::to_string(r.snappedVertices) + " quad vertices moved onto points of the surface that the quads missed "
             "by more than the distance bound (tips, spikes or fins narrower than a quad)");
  if (r.splitPatches > 0)
    log.info("Zero chains: " + std::to_string(r.splitPatches) + " patches split by Catmull-Clark steps (" +
             std::to_string(r.splitRounds) + " rounds)");
  if (r.timeLimitedParts > 0)
    log.warning("The side-length time limit (ilp_time_limit, a safety stop) cut " + std::to_string(r.timeLimitedParts) +
                " parts short: these quads depend on the machine's speed");
  if (r.foldsResmoothed || r.foldsResampled || r.foldsWithoutField)
    log.info(std::string("Folds left by the field-aligned pass: ") +
             (r.foldsWithoutField ? "the pass without the field folded fewer and was kept"
              : r.foldsSidesByArcLength
                  ? "their patches were sampled again with arc length on their sides (the field kept inside)"
              : r.foldsResampled ? "their patches were sampled again with mean-value coordinates"
                                  : "the plain smoothing folded fewer and was kept"));
  if (q.blendedPatches + q.meanValuePatches > 0)
    log.info("Field-aligned maps: " + std::to_string(q.alignedPatches) + " patches aligned, " +
             std::to_string(q.blendedPatches) + " blended towards mean-value coordinates and " +
             std::to_string(q.meanValuePatches) + " left to them, where the aligned map folded" +
             (r.boundMeanValuePatches > 0 ? " or strayed from the surface" : ""));
  if (q.outsidePoints > 0)
    log.warning(std::to_string(q.outsidePoints) +
                " grid points fell outside their patch map (degenerate patches): their quads are distorted");
  if (r.polygonPatches > 0)
    log.info(std::to_string(r.polygonPatches) + " layout patches with 3, 5 or more corners cut into quads as n-gons");
  // The edge length the quads were made with: the asked one unless the distance bound refined it.
  char target[96];
  if (r.targetEdgeLength > 0 && r.targetEdgeLength != s.targetEdgeLength)
    std::snprintf(target, sizeof target, "%.6g, refined from %.6g", r.targetEdgeLength, s.targetEdgeLength);
  else
    std::snprintf(target, sizeof target, "%.6g", s.targetEdgeLength);
  log.info("Quad mesh: " + std::to_string(q.numQuads()) + " quads, " + std::to_string(q.numVertices()) + " vertices, " +
           std::to_string(r.report.irregularVertices) + " irregular vertices, genus " + std::to_string(r.report.genus) +
           ", " + std::to_string(r.report.borderLoops) + " border loops (target edge length " + target + ")");
  if (s.baseComplexPatches >= 0)
    log.info("Base complex of the quad mesh: " + std::to_string(s.baseComplexPatches) + " patches (the layout has " +
             std::to_string(layoutPatches) + ")");
  const QuadQuality& m = s.quality;
  char line[300];
  std::snprintf(line, sizeof line,
                "Quality: %.2f%% quads misaligned > %g deg (mean %.2f deg; %.2f%% of the faces as the paper counts "
                "them), scaled Jacobian min %.3f mean %.3f, Hausdorff %.3g%% of the diagonal (at most %.3g%%)",
                m.misalignedPercent, misalignmentThresholdDeg, m.meanMisalignmentDeg, m.misalignedFacesPercent, m.minScaledJacobian,
                m.meanScaledJacobian, 100 * m.hausdorffRelative, 100 * m.hausdorffBoundRelative);
  log.info(line);
  if (m.invertedQuads > 0)
    log.warning(std::to_string(m.invertedQuads) +
                " quads are folded or turned against the surface (scaled Jacobian <= 0) after smoothing and "
                "untangling (quad.inverted_quads)");
  log.info("Time: quadrangulation " + formatSeconds(s.seconds));
}

void record(const QuadStageResult& s, const PipelineParameters& p, Figures& f) {
  const QuadrangulationResult& r = s.quad;
  const QuadMesh& q = r.mesh;
  recordParameters(f, p, PipelineStage::Quad);
  f.set("params.target_edge_length", s.targetEdgeLength);
  f.set("quad.faces", q.numQuads());
  f.set("quad.vertices", q.numVertices());
  f.set("quad.irregular_vertices", r.report.irregularVertices);
  f.setCounts("quad.irregular_by_valence", r.report.irregularByValence);
  f.set("quad.base_complex_patches", s.baseComplexPatches);
  f.set("quad.genus", r.report.genus);
  f.set("quad.border_loops", r.report.borderLoops);
  f.set("quad.manifold", r.report.manifold);
  f.set("quad.segments", r.graph.segments.size());
  f.set("quad.target_edge_length", r.targetEdgeLength);
  f.set("quad.refinements", r.refinements);
  f.set("quad.restored_vertices", r.restoredVertices);
  f.set("quad.snapped_vertices", r.snappedVertices);
  f.set("quad.stretch_bound_dropped", r.stretchBoundDropped);
  f.set("quad.split_every_patch", r.splitEverything);
  f.set("quad.zero_chain_splits", r.splitPatches);
  f.set("quad.time_limited_parts", r.timeLimitedParts);
  f.set("quad.polygon_patches", r.polygonPatches);
  f.set("quad.dissolved_vertices", r.dissolvedVertices);
  f.set("quad.outside_points", q.outsidePoints);
  f.set("quad.smoothing_fixed_vertices", r.smoothing.fixedVertices);
  f.set("quad.field_folds_resmoothed", r.foldsResmoothed);
  f.set("quad.field_folds_resampled", r.foldsResampled);
  f.set("quad.field_folds_without_field", r.foldsWithoutField);
  f.set("quad.field_bound_without_field", r.boundWithoutField);
  f.set("quad.field_bound_mean_value_patches", r.boundMeanValuePatches);
  f.set("quad.field_bound_arc_length_patches", r.boundArcLengthPatches);
  f.set("quad.field_grid_kept", r.fieldGridKept);
  f.set("quad.field_aligned_patches", q.alignedPatches);
  f.set("quad.field_blended_patches", q.blendedPatches);
  f.set("quad.field_mean_value_patches", q.meanValuePatches);
  const QuadQuality& m = s.quality;
  f.set("quad.misaligned_pct", m.misalignedPercent);
  f.set("quad.mean_misalignment_deg", m.meanMisalignmentDeg);
  f.set("quad.misaligned_faces_pct", m.misalignedFacesPercent);
  f.set("quad.min_scaled_jacobian", m.minScaledJacobian);
  f.set("quad.mean_scaled_jacobian", m.meanScaledJacobian);
  f.set("quad.inverted_quads", m.invertedQuads);
  f.set("quad.hausdorff", m.hausdorff);
  f.set("quad.hausdorff_rel", m.hausdorffRelative);
  f.set("quad.hausdorff_bound_rel", m.hausdorffBoundRelative);
  f.set("time_s.quadrangulation", s.seconds);
}

}  // namespace

double quadTargetEdge(const SurfaceMesh& mesh, const PipelineParameters& p, ParameterNaming naming) {
  const double area = surfaceArea(mesh);
  if (p.targetFaces > 0) return std::sqrt(area / p.targetFaces);
  const double target = p.scale * mesh.boundingBoxDiagonal();
  const double quads = area / (target * target);
  if (quads > double(kMaxQuads)) {
    const double smallest = std::sqrt(area / double(kMaxQuads)) / mesh.boundingBoxDiagonal();
    const bool cli = naming == ParameterNaming::CliOption;
    char line[400];
    std::snprintf(line, sizeof line,
                  "%s %g asks for about %.3g quads on this surface, more than the limit of %ld; use %s %.2g or larger, "
                  "or %s %ld or fewer",
                  cli ? "--scale" : "parameter 'scale' =", p.scale, quads, kMaxQuads, cli ? "--scale" : "scale",
                  smallest * 1.01, cli ? "--target-faces" : "target_faces", kMaxQuads);
    throw ParameterError(line);
  }
  return target;
}

QuadStageResult runQuadStage(const SurfaceMesh& mesh, const CrossField& field, const LayoutStageResult& layout,
                             const PipelineParameters& p, const StageObserver& observer) {
  QuadStageResult s;
  StageLog log(observer);
  const auto start = std::chrono::steady_clock::now();
  s.targetEdgeLength = quadTargetEdge(mesh, p, ParameterNaming::FilterName);
  log.progress(0, "side lengths and patch sampling (target quad edge " + std::to_string(s.targetEdgeLength) + ")");
  const QuadrangulationOptions options = quadOptions(mesh, field, p, s.targetEdgeLength);
  s.quad = quadrangulate(layout.patches, options);
  if (s.quad.report.manifold) s.baseComplexPatches = measureBaseComplex(s.quad.mesh).patches;
  s.seconds = secondsSince(start);

  log.progress(80, "quality of the quad mesh");
  const auto metricsStart = std::chrono::steady_clock::now();
  const ClosestPointIndex surfaceIndex(mesh);
  s.quality = measureQuadQuality(s.quad.mesh, mesh, field, surfaceIndex, p.maxDeviation * mesh.boundingBoxDiagonal(),
                                 p.misalignmentThresholdDeg * kPi / 180);
  describe(s, options, layout.patches.numPatches(), p.misalignmentThresholdDeg, log);
  record(s, p, s.figures);
  s.figures.set("time_s.metrics", secondsSince(metricsStart));
  log.progress(90, "quad mesh measured");
  s.log = std::move(log.lines);
  return s;
}

}  // namespace fcql
