#include "command_line.h"
#include "commands.h"
#include "output_dir.h"

#include "field/field_io.h"
#include "layout/layout_io.h"
#include "quadrangulation/quadrangulation.h"

#include <chrono>
#include <cmath>

namespace fcql {

QuadStage runQuadStage(const FieldStage& fs, const LayoutStage& ls, const CommandLine& cl, StatsJson& stats, bool quiet) {
  QuadStage qs;
  auto start = std::chrono::steady_clock::now();
  double diagonal = fs.mesh.boundingBoxDiagonal();
  double target;
  if (cl.has("target-faces")) {
    int faces = cl.integer("target-faces", 1000, 1, 100000000);
    double area = 0;
    for (int f = 0; f < fs.mesh.numFaces(); ++f) area += fs.mesh.faceArea(f);
    target = std::sqrt(area / faces);
  } else {
    target = cl.number("scale", 0.02, 1e-5, 1.0) * diagonal;
  }
  progress(quiet, "quadrangulating: integer side lengths (target quad edge " + std::to_string(target) + ")");
  QuadrangulationResult r = quadrangulate(ls.patches, target, cl.number("ilp-time-limit", 60, 1, 86400));
  qs.graph = std::move(r.graph);
  qs.lengths = std::move(r.lengths);
  qs.mesh = std::move(r.mesh);
  qs.report = r.report;
  if (r.splitPatches > 0)
    progress(quiet, "zero chains: " + std::to_string(r.splitPatches) + " patches split in four (" +
                        std::to_string(r.splitRounds) + " rounds)");
  stats.set("quad.zero_chain_splits", r.splitPatches);
  qs.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress(quiet, "quad mesh: " + std::to_string(qs.mesh.numQuads()) + " quads, " + std::to_string(qs.mesh.numVertices()) +
                      " vertices, genus " + std::to_string(qs.report.genus) + ", " + std::to_string(qs.report.borderLoops) +
                      " border loops, " + std::to_string(qs.report.irregularVertices) + " irregular vertices" +
                      (qs.report.manifold ? "" : ", NOT MANIFOLD: " + qs.report.problem));
  stats.set("params.target_edge_length", target);
  stats.set("quad.faces", qs.mesh.numQuads());
  stats.set("quad.vertices", qs.mesh.numVertices());
  stats.set("quad.irregular_vertices", qs.report.irregularVertices);
  stats.set("quad.genus", qs.report.genus);
  stats.set("quad.border_loops", qs.report.borderLoops);
  stats.set("quad.manifold", qs.report.manifold);
  stats.set("quad.segments", int(qs.graph.segments.size()));
  stats.set("time_s.quadrangulation", qs.seconds);
  return qs;
}

int quadCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2,
                 {"field", "sharp-angle", "out", "example", "alpha", "k", "phi", "threads", "ilp-time-limit", "scale",
                  "target-faces"},
                 {"quiet"});
  if (!cl.has("out")) throw UsageError("missing --out DIR");
  if (cl.has("scale") && cl.has("target-faces")) throw UsageError("give --scale or --target-faces, not both");
  bool quiet = cl.has("quiet");
  TracingParameters tp = readTracingParameters(cl);
  LayoutParameters lp = readLayoutParameters(cl);
  cl.number("scale", 0.02, 1e-5, 1.0);
  cl.integer("target-faces", 1000, 1, 100000000);
  StatsJson stats;
  auto start = std::chrono::steady_clock::now();
  FieldStage fs = runFieldStage(cl, stats, quiet);
  TraceStage ts = runTraceStage(fs, tp, stats, quiet);
  LayoutStage ls = runLayoutStage(fs, ts, lp, stats, quiet);
  QuadStage qs = runQuadStage(fs, ls, cl, stats, quiet);
  stats.set("time_s.total", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  OutputDir out(cl.value("out"));
  saveFField(fs.mesh, fs.field, out.stage("field.ffield"));
  out.writeText("candidates.obj", candidatesObj(ts.h));
  out.writeText("separatrices.obj", separatricesToObj(ls.layout));
  out.writeText("layout.ply", patchLayoutToPly(ls.patches));
  out.writeText("quad.obj", quadMeshToObj(qs.mesh));
  out.writeText("stats.json", stats.toString());
  out.commit();
  progress(quiet, "wrote quad.obj, layout.ply, separatrices.obj, candidates.obj, field.ffield and stats.json in " + cl.value("out"));
  return 0;
}

}  // namespace fcql
