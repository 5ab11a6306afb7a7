#include "command_line.h"
#include "commands.h"
#include "output_dir.h"

#include "field/field_io.h"
#include "tracing/polyline_io.h"
#include "tracing/separatrix_graph.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>
#include <stdexcept>

namespace fcql {

TracingParameters readTracingParameters(const CommandLine& cl) {
  TracingParameters p;
  p.alpha = cl.number("alpha", p.alpha, 0.0, 1e6);
  p.k = cl.integer("k", p.k, 1, 1000000);
  p.phiDeg = cl.number("phi", p.phiDeg, 1.0, 45.0);
  p.threads = cl.integer("threads", 0, 0, 1024);
  return p;
}

namespace {

/// The memory a whole run takes, estimated before graph G is built: about 500/φ nodes per face
/// (the shared meshes at φ 10°: 48–65; a 1M-face kitten: 48) and about 130 bytes a node over
/// the run (that kitten peaked at 6.08 GB with 48M nodes).
double estimatedRunBytes(int faces, double phiDeg) { return 130.0 * faces * 500.0 / phiDeg; }

double availableMemoryBytes() {
  const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? double(pages) * double(size) : 0;
}

}  // namespace

TraceStage runTraceStage(const FieldStage& fs, const TracingParameters& params, StatsJson& stats, bool quiet) {
  TraceStage t;
  auto start = std::chrono::steady_clock::now();
  const double needed = estimatedRunBytes(fs.mesh.numFaces(), params.phiDeg), free = availableMemoryBytes();
  if (free > 0 && needed > 0.8 * free) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "warning: graph G on %d faces at phi %g deg needs about %.1f GB in this run (an estimate), near or "
                  "beyond the %.1f GB this machine has free; a larger --phi (fewer auxiliary points) or a coarser "
                  "mesh needs less",
                  fs.mesh.numFaces(), params.phiDeg, needed / 1e9, free / 1e9);
    progress(quiet, line);
  }
  progress(quiet, "building graph G (phi " + std::to_string(params.phiDeg) + " deg)");
  t.graph = std::make_unique<GeodesicGraph>(fs.mesh, fs.field, fs.analysis, params);
  auto built = std::chrono::steady_clock::now();
  progress(quiet, "graph G: " + std::to_string(t.graph->numNodes()) + " nodes, " + std::to_string(t.graph->numArcs()) +
                      " arcs; tracing from " + std::to_string(t.graph->ports().size()) + " ports (k " +
                      std::to_string(params.k) + ")");
  // Progress: a line rewritten in place on a terminal, a line per quarter otherwise.
  const bool terminal = isatty(2);
  const int step = terminal ? 5 : 25;
  int lastPercent = -step;
  t.h = traceCandidateSeparatrices(*t.graph, [&](int done, int total) {
    int percent = total ? 100 * done / total : 100;
    if (quiet || percent - lastPercent < step || percent == 100) return;
    lastPercent = percent;
    std::cerr << "fcql: tracing " << percent << "% (" << done << "/" << total << " ports)" << (terminal ? "\r" : "\n")
              << std::flush;
  });
  if (!quiet && terminal) std::cerr << std::string(60, ' ') << "\r" << std::flush;
  auto traced = std::chrono::steady_clock::now();
  t.graphSeconds = std::chrono::duration<double>(built - start).count();
  t.tracingSeconds = std::chrono::duration<double>(traced - built).count();
  progress(quiet, "graph H: " + std::to_string(t.h.arcs.size()) + " candidate separatrices, " +
                      std::to_string(t.h.tangentialPairs.size()) + " pairs crossing tangentially (" +
                      std::to_string(t.h.tangentialCliques.size()) + " cliques)");
  stats.set("params.alpha", params.alpha);
  stats.set("params.k", params.k);
  stats.set("params.phi", params.phiDeg);
  stats.set("graph_g.nodes", t.graph->numNodes());
  stats.set("graph_g.arcs", t.graph->numArcs());
  stats.set("graph_g.auxiliary_points", t.graph->sampling().numSamples());
  stats.set("graph_g.ports", int(t.graph->ports().size()));
  stats.set("graph_h.arcs", int(t.h.arcs.size()));
  stats.set("graph_h.tangential_pairs", int(t.h.tangentialPairs.size()));
  stats.set("graph_h.tangential_cliques", int(t.h.tangentialCliques.size()));
  stats.set("time_s.graph", t.graphSeconds);
  stats.set("time_s.tracing", t.tracingSeconds);
  return t;
}

std::string candidatesObj(const SeparatrixGraph& h) {
  std::vector<const TracedPath*> paths;
  std::vector<std::string> comments;
  for (std::size_t i = 0; i < h.arcs.size(); ++i) {
    paths.push_back(&h.arcs[i].path);
    comments.push_back("candidate " + std::to_string(i) + ": port " + std::to_string(h.arcs[i].portA) + " -> port " +
                       std::to_string(h.arcs[i].portB) + ", length " + std::to_string(h.arcs[i].length));
  }
  return polylinesToObj(paths, comments);
}

int traceCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2, {"field", "sharp-angle", "field-scale", "out", "example", "alpha", "k", "phi", "threads"}, {"quiet"});
  requireOutputDir(cl);
  bool quiet = cl.has("quiet");
  TracingParameters params = readTracingParameters(cl);
  StatsJson stats;
  auto start = std::chrono::steady_clock::now();
  FieldStage fs = runFieldStage(cl, stats, quiet);
  TraceStage ts = runTraceStage(fs, params, stats, quiet);
  const auto outputStart = Clock::now();
  OutputDir out(cl.value("out"));
  out.write("field.ffield", [&](const std::string& path) { saveFField(fs.mesh, fs.field, path); });
  out.writeText("candidates.obj", candidatesObj(ts.h));
  recordTotalTime(stats, start, outputStart);
  out.writeText("stats.json", stats.toString());
  out.commit();
  progress(quiet, "wrote " + out.finalPath("candidates.obj") + " and " + out.finalPath("stats.json"));
  return 0;
}

}  // namespace fcql
