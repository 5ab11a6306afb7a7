#include "pipeline_trace.h"

#include <cstdio>

namespace fcql_meshlab {

fcql::TracingParameters toCoreParameters(const TracingParameters& params) {
  fcql::TracingParameters p;
  p.alpha = params.alpha;
  p.k = params.k;
  p.phiDeg = params.phiDeg;
  p.threads = 0;
  p.validate();
  return p;
}

TraceResult traceSeparatrices(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                              const fcql::FieldAnalysis& analysis, const TracingParameters& params,
                              const Progress& progress) {
  TraceResult r;
  const fcql::TracingParameters core = toCoreParameters(params);
  progress(0, "building graph G");
  auto start = Clock::now();
  r.graph.reset(new fcql::GeodesicGraph(mesh, field, analysis, core));
  r.graphSeconds = secondsSince(start);

  const Progress tracing = progress.sub(30, 100);
  tracing(0, "tracing separatrices");
  int lastPercent = -1;
  start = Clock::now();
  r.h = fcql::traceCandidateSeparatrices(*r.graph, [&](int done, int total) {
    const int percent = total > 0 ? 100 * done / total : 100;
    if (percent == lastPercent) return;
    lastPercent = percent;
    tracing(percent, "tracing separatrices (" + std::to_string(done) + "/" +
                         std::to_string(total) + " ports)");
  });
  r.tracingSeconds = secondsSince(start);
  return r;
}

std::vector<std::string> describeTrace(const TraceResult& t) {
  const fcql::TracingParameters& p = t.graph->parameters();
  char params[96];
  std::snprintf(params, sizeof params, "alpha %g, k %d, phi %g deg", p.alpha, p.k, p.phiDeg);
  std::vector<std::string> lines;
  lines.push_back("Graph G: " + std::to_string(t.graph->numNodes()) + " nodes, " +
                  std::to_string(t.graph->numArcs()) + " arcs, " +
                  std::to_string(t.graph->sampling().numSamples()) + " auxiliary points, " +
                  std::to_string(t.graph->ports().size()) + " ports (" + params + ")");
  lines.push_back("Graph H: " + std::to_string(t.h.arcs.size()) + " candidate separatrices, " +
                  std::to_string(t.h.tangentialPairs.size()) + " pairs crossing tangentially");
  return lines;
}

}  // namespace fcql_meshlab
