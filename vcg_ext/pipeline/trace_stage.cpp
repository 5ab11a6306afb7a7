#include "trace_stage.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace fcql {

namespace {

/// The memory a whole run takes, estimated before graph G is built: about 500/φ nodes per face
/// and about 130 bytes a node over the run (bench/RESULTS.md has the measurements).
double estimatedRunBytes(int faces, double phiDeg) { return 130.0 * faces * 500.0 / phiDeg; }

double availableMemoryBytes() {
  const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? double(pages) * double(size) : 0;
}

}  // namespace

TracingParameters tracingParameters(const PipelineParameters& p) {
  TracingParameters t;
  t.alpha = p.alpha;
  t.k = p.k;
  t.phiDeg = p.phiDeg;
  t.threads = p.threads;
  t.validate();
  return t;
}

TraceStageResult runTraceStage(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                               const PipelineParameters& p, const StageObserver& observer) {
  TraceStageResult r;
  StageLog log(observer);
  const TracingParameters params = tracingParameters(p);
  const double needed = estimatedRunBytes(mesh.numFaces(), params.phiDeg), free = availableMemoryBytes();
  if (free > 0 && needed > 0.8 * free) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "Graph G on %d faces at phi %g deg needs about %.1f GB in this run (an estimate), near or beyond the "
                  "%.1f GB this machine has free; a larger phi (fewer auxiliary points) or a coarser mesh needs less",
                  mesh.numFaces(), params.phiDeg, needed / 1e9, free / 1e9);
    log.warning(line);
  }
  char described[96];
  std::snprintf(described, sizeof described, "alpha %g, k %d, phi %g deg", params.alpha, params.k, params.phiDeg);
  log.progress(0, std::string("building graph G (") + described + ")");
  auto start = std::chrono::steady_clock::now();
  r.graph.reset(new GeodesicGraph(mesh, field, analysis, params));
  r.graphSeconds = secondsSince(start);
  log.info("Graph G: " + std::to_string(r.graph->numNodes()) + " nodes, " + std::to_string(r.graph->numArcs()) +
           " arcs, " + std::to_string(r.graph->sampling().numSamples()) + " auxiliary points, " +
           std::to_string(r.graph->ports().size()) + " ports (" + described + ")");

  log.progress(30, "tracing separatrices");
  int lastPercent = -1;
  start = std::chrono::steady_clock::now();
  r.h = traceCandidateSeparatrices(*r.graph, [&](int done, int total) {
    const int percent = total > 0 ? 100 * done / total : 100;
    if (percent == lastPercent) return;
    lastPercent = percent;
    log.progress(30 + 70 * percent / 100,
                 "tracing separatrices (" + std::to_string(done) + "/" + std::to_string(total) + " ports)");
  });
  r.tracingSeconds = secondsSince(start);
  log.info("Graph H: " + std::to_string(r.h.arcs.size()) + " candidate separatrices, " +
           std::to_string(r.h.tangentialPairs.size()) + " pairs crossing tangentially (" +
           std::to_string(r.h.tangentialCliques.size()) + " cliques)");
  log.info("Time: graph G " + formatSeconds(r.graphSeconds) + ", tracing " + formatSeconds(r.tracingSeconds));

  Figures& f = r.figures;
  recordParameters(f, p, PipelineStage::Trace);
  f.set("graph_g.nodes", r.graph->numNodes());
  f.set("graph_g.arcs", r.graph->numArcs());
  f.set("graph_g.auxiliary_points", r.graph->sampling().numSamples());
  f.set("graph_g.ports", r.graph->ports().size());
  f.set("graph_h.arcs", r.h.arcs.size());
  f.set("graph_h.tangential_pairs", r.h.tangentialPairs.size());
  f.set("graph_h.tangential_cliques", r.h.tangentialCliques.size());
  f.set("time_s.graph", r.graphSeconds);
  f.set("time_s.tracing", r.tracingSeconds);
  r.log = std::move(log.lines);
  return r;
}

}  // namespace fcql
