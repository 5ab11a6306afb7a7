#include "command_line.h"
#include "commands.h"
#include "output_dir.h"

#include "field/field_generation.h"
#include "field/field_io.h"
#include "mesh/generators.h"
#include "mesh/mesh_io.h"
#include "mesh/vertex_welding.h"

#include <algorithm>
#include <chrono>
#include <iostream>

namespace fcql {

void requireOutputDir(const CommandLine& cl) {
  if (!cl.has("out")) throw UsageError("missing --out DIR");
  const std::string problem = OutputDir::problem(cl.value("out"));
  if (!problem.empty()) throw UsageError(problem);
}

void progress(bool quiet, const std::string& line) {
  if (!quiet) std::cerr << "fcql: " << line << std::endl;
}

void recordTotalTime(StatsJson& stats, Clock::time_point start, Clock::time_point outputStart) {
  const auto now = Clock::now();
  stats.set("time_s.output", std::chrono::duration<double>(now - outputStart).count());
  stats.set("time_s.total", std::chrono::duration<double>(now - start).count());
}

FieldStage runFieldStage(const CommandLine& cl, StatsJson& stats, bool quiet,
                         const std::function<void(const SurfaceMesh&)>& checkMesh) {
  const auto& pos = cl.positional();
  bool example = cl.has("example");
  if (example && !pos.empty()) throw UsageError("give either a MESH file or --example NAME, not both");
  if (!example && pos.empty()) throw UsageError("missing input: give a MESH file (.obj .ply .off) or --example NAME");
  if (pos.size() > 1) throw UsageError("unexpected argument '" + pos[1] + "'");
  double sharpAngle = cl.number("sharp-angle", 35.0, 0.0, 180.0);
  double fieldScale = cl.number("field-scale", 0.02, 0.0, 1.0);

  FieldStage s;
  auto start = std::chrono::steady_clock::now();
  if (example) {
    s.meshName = "example:" + cl.value("example");
    const auto names = exampleNames();
    if (std::find(names.begin(), names.end(), cl.value("example")) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw UsageError("unknown --example '" + cl.value("example") + "' (choose one of: " + list + ")");
    }
    s.mesh = makeExample(cl.value("example"));
  } else {
    s.meshName = pos[0];
    s.mesh = loadMesh(pos[0]);
    VertexWelding welding = weldCoincidentVertices(s.mesh);
    if (welding.merged > 0) progress(quiet, welding.note());
    if (welding.welded) s.mesh = std::move(welding.mesh);
    stats.set("mesh.welded_vertices", welding.welded ? welding.merged : 0);
  }
  if (checkMesh) checkMesh(s.mesh);
  progress(quiet, "mesh " + s.meshName + ": " + std::to_string(s.mesh.numFaces()) + " faces, " +
                      std::to_string(s.mesh.numVertices()) + " vertices, genus " + std::to_string(s.mesh.genus()) +
                      ", " + std::to_string(s.mesh.numBorderLoops()) + " border loops");
  auto fieldStart = std::chrono::steady_clock::now();
  FieldGenerationReport report;
  if (cl.has("field")) {
    s.field = loadField(s.mesh, cl.value("field"));
    progress(quiet, "field read from " + cl.value("field"));
  } else {
    progress(quiet, "computing a smooth curvature-aligned cross field");
    FieldGenerationOptions options;
    options.sharpAngleDeg = sharpAngle;
    options.scale = fieldScale;
    s.field = generateCrossField(s.mesh, options, &report);
  }
  s.analysis = analyzeField(s.mesh, s.field);
  auto end = std::chrono::steady_clock::now();
  s.seconds = std::chrono::duration<double>(end - fieldStart).count();

  stats.set("input.mesh", s.meshName);
  stats.set("input.field", cl.has("field") ? cl.value("field") : std::string("computed"));
  stats.set("mesh.faces", s.mesh.numFaces());
  stats.set("mesh.vertices", s.mesh.numVertices());
  stats.set("mesh.border_loops", s.mesh.numBorderLoops());
  stats.set("mesh.genus", s.mesh.genus());
  stats.set("mesh.euler_characteristic", s.mesh.eulerCharacteristic());
  stats.set("field.singularities", s.analysis.numInteriorSingularities());
  stats.setCounts("field.by_index", s.analysis.interiorHistogram());
  stats.set("field.border_singularities", s.analysis.numBorderSingularities());
  stats.set("field.ports", s.analysis.numPorts());
  stats.set("field.index_sum", formatQuarterIndex(s.analysis.indexSumQuarters()));
  if (!cl.has("field")) {
    stats.set("field.sharp_angle", sharpAngle);
    stats.set("field.scale", fieldScale);
    stats.set("field.sharp_edges", report.sharpEdges);
    stats.set("field.constrained_faces", report.constrainedFaces);
  }
  stats.set("time_s.field", s.seconds);
  stats.set("time_s.load", std::chrono::duration<double>(fieldStart - start).count());

  std::string hist;
  for (const auto& h : s.analysis.interiorHistogram()) hist += (hist.empty() ? "" : ", ") + h.first + ": " + std::to_string(h.second);
  progress(quiet, std::to_string(s.analysis.numInteriorSingularities()) + " singularities (" +
                      (hist.empty() ? std::string("none") : hist) + "), " +
                      std::to_string(s.analysis.numPorts()) + " ports, index sum " +
                      formatQuarterIndex(s.analysis.indexSumQuarters()));
  for (const std::string& warning : fieldWarnings(s.mesh, s.analysis)) progress(quiet, "warning: " + warning);
  return s;
}

int fieldCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2, {"field", "sharp-angle", "field-scale", "out", "example"}, {"quiet"});
  requireOutputDir(cl);
  bool quiet = cl.has("quiet");
  StatsJson stats;
  FieldStage s = runFieldStage(cl, stats, quiet);
  OutputDir out(cl.value("out"));
  out.write("field.ffield", [&](const std::string& path) { saveFField(s.mesh, s.field, path); });
  out.writeText("stats.json", stats.toString());
  out.commit();
  progress(quiet, "wrote " + out.finalPath("field.ffield") + " and " + out.finalPath("stats.json"));
  return 0;
}

}  // namespace fcql
