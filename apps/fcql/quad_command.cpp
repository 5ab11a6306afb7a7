#include "command_line.h"
#include "commands.h"
#include "output_dir.h"

#include "field/field_io.h"
#include "layout/layout_io.h"
#include "metrics/base_complex.h"
#include "metrics/quad_quality.h"
#include "quadrangulation/quadrangulation.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>

namespace fcql {

namespace {

/// The most quads a run may ask for: the quad stage took 1.14 GB for 2M quads (a sphere), so
/// 20M take about 11 GB, within a 16 GB machine.
constexpr long kMaxQuads = 20000000;

}  // namespace

std::string quadParametrization(const CommandLine& cl) {
  const std::string param = cl.value("param", "field");
  if (param != "field" && param != "mean-value") throw UsageError("--param must be field or mean-value, not " + param);
  return param;
}

double quadTargetEdge(const SurfaceMesh& mesh, const CommandLine& cl) {
  double area = 0;
  for (int f = 0; f < mesh.numFaces(); ++f) area += mesh.faceArea(f);
  if (cl.has("target-faces")) {
    const int faces = cl.integer("target-faces", 1000, 1, int(kMaxQuads));
    return std::sqrt(area / faces);
  }
  const double scale = cl.number("scale", 0.02, 1e-5, 1.0);
  const double target = scale * mesh.boundingBoxDiagonal();
  const double quads = area / (target * target);
  if (quads > double(kMaxQuads)) {
    const double smallest = std::sqrt(area / double(kMaxQuads)) / mesh.boundingBoxDiagonal();
    char line[300];
    std::snprintf(line, sizeof line,
                  "--scale %g asks for about %.3g quads on this surface, more than the limit of %ld; use --scale %.2g or "
                  "larger, or --target-faces %ld or fewer",
                  scale, quads, kMaxQuads, smallest * 1.01, kMaxQuads);
    throw UsageError(line);
  }
  return target;
}

QuadStage runQuadStage(const FieldStage& fs, const LayoutStage& ls, const CommandLine& cl, StatsJson& stats, bool quiet) {
  QuadStage qs;
  auto start = std::chrono::steady_clock::now();
  const double target = quadTargetEdge(fs.mesh, cl);
  progress(quiet, "quadrangulating: integer side lengths (target quad edge " + std::to_string(target) + ")");
  QuadrangulationOptions options;
  options.targetEdgeLength = target;
  options.ilpTimeLimit = cl.number("ilp-time-limit", 60, 1, 86400);
  options.smoothing.iterations = cl.integer("smooth", 5, 0, 1000);
  options.smoothing.sharpAngleDeg = cl.number("sharp-angle", 35.0, 0.0, 180.0);
  options.maxDeviation = cl.number("max-deviation", 0.01, 0.0, 1.0);
  options.maxQuads = kMaxQuads;
  const std::string param = quadParametrization(cl);
  if (param == "field") options.fieldDirections = fs.field.u;
  QuadrangulationResult r = quadrangulate(ls.patches, options);
  for (const std::string& note : refinementNotes(r, options)) progress(quiet, note);
  qs.graph = std::move(r.graph);
  qs.lengths = std::move(r.lengths);
  qs.mesh = std::move(r.mesh);
  qs.report = r.report;
  if (r.splitPatches > 0)
    progress(quiet, "zero chains: " + std::to_string(r.splitPatches) + " patches split by Catmull-Clark steps (" +
                        std::to_string(r.splitRounds) + " rounds)");
  stats.set("quad.zero_chain_splits", r.splitPatches);
  stats.set("quad.time_limited_parts", r.timeLimitedParts);
  if (r.timeLimitedParts > 0)
    progress(quiet, "warning: the side-length time limit (--ilp-time-limit, a safety stop) cut " +
                        std::to_string(r.timeLimitedParts) + " parts short: these quads depend on the machine's speed");
  stats.set("quad.polygon_patches", r.polygonPatches);
  stats.set("quad.dissolved_vertices", r.dissolvedVertices);
  stats.set("quad.outside_points", qs.mesh.outsidePoints);
  stats.set("params.param", param);
  stats.set("quad.field_folds_resmoothed", r.foldsResmoothed);
  stats.set("quad.field_folds_resampled", r.foldsResampled);
  stats.set("quad.field_folds_without_field", r.foldsWithoutField);
  stats.set("quad.field_bound_without_field", r.boundWithoutField);
  if (r.foldsResmoothed || r.foldsResampled || r.foldsWithoutField)
    progress(quiet, std::string("folds left by the field-aligned pass: ") +
                        (r.foldsWithoutField ? "the pass without the field folded fewer and was kept"
                         : r.foldsResampled  ? "their patches were sampled again with mean-value coordinates"
                                             : "the plain smoothing folded fewer and was kept"));
  stats.set("quad.field_aligned_patches", qs.mesh.alignedPatches);
  stats.set("quad.field_blended_patches", qs.mesh.blendedPatches);
  stats.set("quad.field_mean_value_patches", qs.mesh.meanValuePatches);
  if (qs.mesh.blendedPatches + qs.mesh.meanValuePatches > 0)
    progress(quiet, "field-aligned maps: " + std::to_string(qs.mesh.alignedPatches) + " patches aligned, " +
                        std::to_string(qs.mesh.blendedPatches) + " blended towards mean-value coordinates and " +
                        std::to_string(qs.mesh.meanValuePatches) + " left to them, where the aligned map folded");
  if (qs.mesh.outsidePoints > 0)
    progress(quiet, "warning: " + std::to_string(qs.mesh.outsidePoints) +
                        " grid points fell outside their patch map (degenerate patches): their quads are distorted");
  if (r.polygonPatches > 0)
    progress(quiet, std::to_string(r.polygonPatches) + " layout patches with 3, 5 or more corners cut into quads as n-gons");
  qs.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress(quiet, "quad mesh: " + std::to_string(qs.mesh.numQuads()) + " quads, " + std::to_string(qs.mesh.numVertices()) +
                      " vertices, genus " + std::to_string(qs.report.genus) + ", " + std::to_string(qs.report.borderLoops) +
                      " border loops, " + std::to_string(qs.report.irregularVertices) + " irregular vertices");
  stats.set("params.target_edge_length", target);
  stats.set("params.max_deviation", options.maxDeviation);
  stats.set("quad.refinements", r.refinements);
  stats.set("quad.restored_vertices", r.restoredVertices);
  stats.set("quad.stretch_bound_dropped", r.stretchBoundDropped);
  stats.set("quad.split_every_patch", r.splitEverything);
  stats.set("quad.target_edge_length", r.targetEdgeLength);
  stats.set("params.smooth", options.smoothing.iterations);
  stats.set("quad.faces", qs.mesh.numQuads());
  stats.set("quad.vertices", qs.mesh.numVertices());
  stats.set("quad.irregular_vertices", qs.report.irregularVertices);
  // The quad mesh's own coarse structure: as many patches as the layout's when it kept it.
  const int baseComplexPatches = qs.report.manifold ? measureBaseComplex(qs.mesh).patches : -1;
  stats.set("quad.base_complex_patches", baseComplexPatches);
  if (baseComplexPatches >= 0)
    progress(quiet, "base complex of the quad mesh: " + std::to_string(baseComplexPatches) + " patches (the layout has " +
                        std::to_string(ls.patches.patches.size()) + ")");
  stats.set("quad.genus", qs.report.genus);
  stats.set("quad.border_loops", qs.report.borderLoops);
  stats.set("quad.manifold", qs.report.manifold);
  stats.set("quad.segments", int(qs.graph.segments.size()));
  stats.set("quad.smoothing_fixed_vertices", r.smoothing.fixedVertices);
  stats.set("time_s.quadrangulation", qs.seconds);

  const auto metricsStart = std::chrono::steady_clock::now();
  const ClosestPointIndex surfaceIndex(fs.mesh);
  const QuadQuality quality =
      measureQuadQuality(qs.mesh, fs.mesh, fs.field, surfaceIndex, options.maxDeviation * fs.mesh.boundingBoxDiagonal());
  stats.set("quad.misaligned_pct", quality.misalignedPercent);
  stats.set("quad.mean_misalignment_deg", quality.meanMisalignmentDeg);
  stats.set("quad.misaligned_faces_pct", quality.misalignedFacesPercent);
  stats.set("quad.min_scaled_jacobian", quality.minScaledJacobian);
  stats.set("quad.mean_scaled_jacobian", quality.meanScaledJacobian);
  stats.set("quad.inverted_quads", quality.invertedQuads);
  stats.set("quad.hausdorff", quality.hausdorff);
  stats.set("quad.hausdorff_rel", quality.hausdorffRelative);
  stats.set("quad.hausdorff_bound_rel", quality.hausdorffBoundRelative);
  stats.set("time_s.metrics", std::chrono::duration<double>(std::chrono::steady_clock::now() - metricsStart).count());
  char line[300];
  std::snprintf(line, sizeof line,
                "quality: %.2f%% quads misaligned > pi/16 (mean %.2f deg; %.2f%% of the faces as the paper counts "
                "them), scaled Jacobian min %.3f mean %.3f, Hausdorff %.3g%% of the diagonal (at most %.3g%%)",
                quality.misalignedPercent, quality.meanMisalignmentDeg, quality.misalignedFacesPercent,
                quality.minScaledJacobian, quality.meanScaledJacobian, 100 * quality.hausdorffRelative,
                100 * quality.hausdorffBoundRelative);
  progress(quiet, line);
  if (quality.invertedQuads > 0)
    progress(quiet, "warning: " + std::to_string(quality.invertedQuads) +
                        " quads are folded or turned against the surface (scaled Jacobian <= 0) after smoothing and "
                        "untangling (quad.inverted_quads)");
  return qs;
}

int quadCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2,
                 {"field", "sharp-angle", "field-scale", "out", "example", "alpha", "k", "phi", "threads", "ilp-time-limit", "ilp-stall", "completion-trials", "scale",
                  "target-faces", "smooth", "max-deviation", "param"},
                 {"quiet"});
  requireOutputDir(cl);
  if (cl.has("scale") && cl.has("target-faces")) throw UsageError("give --scale or --target-faces, not both");
  bool quiet = cl.has("quiet");
  TracingParameters tp = readTracingParameters(cl);
  LayoutParameters lp = readLayoutParameters(cl);
  cl.number("scale", 0.02, 1e-5, 1.0);
  cl.integer("target-faces", 1000, 1, int(kMaxQuads));
  cl.integer("smooth", 5, 0, 1000);
  cl.number("max-deviation", 0.01, 0.0, 1.0);
  quadParametrization(cl);
  StatsJson stats;
  auto start = std::chrono::steady_clock::now();
  // A quad count out of reach fails as soon as the mesh is loaded, not after the layout.
  FieldStage fs = runFieldStage(cl, stats, quiet, [&cl](const SurfaceMesh& mesh) { quadTargetEdge(mesh, cl); });
  TraceStage ts = runTraceStage(fs, tp, stats, quiet);
  LayoutStage ls = runLayoutStage(fs, ts, lp, stats, quiet);
  // The layout's files are formatted on another thread while the quad stage runs (the graph H
  // candidates alone are tens of MB of text; with --threads 1, afterwards); they are written
  // once the quads exist, so a failed quad stage still leaves no file behind. The future's
  // destructor joins the thread on any exit.
  struct LayoutTexts {
    std::string candidates, separatrices, layout;
  };
  const auto policy = tp.threads == 1 ? std::launch::deferred : std::launch::async;
  std::future<LayoutTexts> texts = std::async(policy, [&ts, &ls] {
    return LayoutTexts{candidatesObj(ts.h), separatricesToObj(ls.layout), patchLayoutToPly(ls.patches)};
  });
  QuadStage qs = runQuadStage(fs, ls, cl, stats, quiet);
  const auto outputStart = Clock::now();
  const LayoutTexts layoutTexts = texts.get();
  OutputDir out(cl.value("out"));
  out.write("field.ffield", [&](const std::string& path) { saveFField(fs.mesh, fs.field, path); });
  out.writeText("candidates.obj", layoutTexts.candidates);
  out.writeText("separatrices.obj", layoutTexts.separatrices);
  out.writeText("layout.ply", layoutTexts.layout);
  out.writeText("quad.obj", quadMeshToObj(qs.mesh));
  recordTotalTime(stats, start, outputStart);
  out.writeText("stats.json", stats.toString());
  out.commit();
  progress(quiet, "wrote quad.obj, layout.ply, separatrices.obj, candidates.obj, field.ffield and stats.json in " + cl.value("out"));
  return 0;
}

}  // namespace fcql
