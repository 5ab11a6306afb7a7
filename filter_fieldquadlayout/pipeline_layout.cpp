#include "pipeline_layout.h"

#include <algorithm>
#include <memory>

namespace fcql_meshlab {

LayoutResult solveLayoutStage(const fcql::SurfaceMesh& mesh, const fcql::CrossField& field,
                              const fcql::FieldAnalysis& analysis, const TraceResult& trace,
                              const LayoutParameters& params, const Progress& progress) {
  fcql::LayoutParameters core;
  core.ilpTimeLimit = params.ilpTimeLimit;
  core.ilpStallNodes = params.ilpStall;
  core.completionTrials = params.completionTrials;
  core.validate();

  LayoutResult r;
  progress(0, "selecting the separatrices (0-1 programs)");
  r.layout = fcql::solveLayout(*trace.graph, trace.h, core);

  progress(80, "cutting the surface into patches");
  const auto start = Clock::now();
  r.patches = fcql::buildPatchLayout(*trace.graph, r.layout);
  const auto& patches = r.patches.patches;
  if (std::any_of(patches.begin(), patches.end(),
                  [](const fcql::PatchReport& p) { return !p.isDisk; })) {
    // As the command-line tool does: the closing adds virtual singularities to a copy of the
    // analysis and rebuilds graph G on it; both only live while the closing runs.
    progress(90, "closing the patches that are not disks");
    fcql::FieldAnalysis withAnchors = analysis;
    std::unique_ptr<fcql::GeodesicGraph> graph(
        new fcql::GeodesicGraph(mesh, field, withAnchors, trace.graph->parameters(),
                                fcql::GeodesicGraph::SinkDistances::Skipped));
    r.closing = fcql::closeNonDiskPatches(mesh, field, withAnchors, graph, r.layout, r.patches);
    r.closingRan = true;
  }
  r.cutSeconds = secondsSince(start);
  progress(100, "layout done");
  return r;
}

std::vector<std::string> describeLayout(const LayoutResult& r) {
  const fcql::Layout& l = r.layout;
  const fcql::PatchLayout& p = r.patches;
  std::string corners;
  for (const auto& h : p.cornerHistogram())
    corners += (corners.empty() ? "" : ", ") + std::to_string(h.first) + " corners: " +
               std::to_string(h.second);
  std::vector<std::string> lines;
  lines.push_back("Layout: " + std::to_string(l.separatrices.size()) + " separatrices (" +
                  std::to_string(l.tJunctions) + " t-junctions, " +
                  std::to_string(l.borderConnections) + " border connections), " +
                  std::to_string(p.numPatches()) + " patches (" +
                  (corners.empty() ? std::string("no disks") : corners) + "), " +
                  std::to_string(p.numInvalidPatches()) + " invalid patches, " +
                  std::to_string(l.iterations) + " iterations, " +
                  std::to_string(l.selectedFromCandidates) + " separatrices selected from H");
  if (r.closingRan)
    lines.push_back("Closing: some patches were not disks; " +
                    std::to_string(r.closing.linesAdded) + " field lines added through " +
                    std::to_string(r.closing.virtualVertices) + " regular vertices");
  for (int i = 0; i < p.numPatches(); ++i)
    if (!p.patches[i].valid)
      lines.push_back("Warning: patch " + std::to_string(i) + ": " + p.patches[i].problem);
  if (!l.unresolvedPorts.empty())
    lines.push_back("Warning: " + std::to_string(l.unresolvedPorts.size()) +
                    " ports could not be connected to the layout");
  if (l.ilpTimeLimitHit)
    lines.push_back("Warning: the 0-1 programs' time limit (a safety stop) cut " + std::to_string(l.ilpTimeLimited) +
                    " parts short; the best selection found was used, and this layout depends on the machine's speed");
  for (const std::string& m : l.messages) lines.push_back("Note: " + m);
  const fcql::CompletionReport& c = l.completion;
  if (c.trials > 0)
    lines.push_back("Completion: t-junctions and unresolved ports " + std::to_string(c.tJunctionsBefore) + " -> " +
                    std::to_string(c.tJunctionsAfter) + " (" + std::to_string(c.accepted) + " of " +
                    std::to_string(c.trials) + " trials kept)");
  for (std::size_t i = 0; i < l.leftPorts.size() && i < fcql::kLeftPortLines; ++i) lines.push_back("Left: " + l.leftPorts[i]);
  if (l.leftPorts.size() > fcql::kLeftPortLines)
    lines.push_back("... and " + std::to_string(l.leftPorts.size() - fcql::kLeftPortLines) + " more ports left");
  lines.push_back("Time: 0-1 programs " + formatSeconds(l.ilpSeconds) + ", solving cycle tracing " +
                  formatSeconds(l.cycleTracingSeconds) + ", completion " + formatSeconds(l.completionSeconds) + ", propagation " +
                  formatSeconds(l.propagationSeconds) + ", cut into patches " +
                  formatSeconds(r.cutSeconds));
  return lines;
}

}  // namespace fcql_meshlab
