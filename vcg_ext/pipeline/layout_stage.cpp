#include "layout_stage.h"

#include <algorithm>
#include <chrono>
#include <memory>

namespace fcql {

namespace {

/// Invalid patches named in the log's warning; the count says how many more.
constexpr int kInvalidPatchLines = 5;

LayoutParameters layoutParameters(const PipelineParameters& p) {
  LayoutParameters l;
  l.ilpTimeLimit = p.ilpTimeLimit;
  l.ilpStallNodes = p.ilpStall;
  l.completionTrials = p.completionTrials;
  l.validate();
  return l;
}

/// Cuts the surface along the layout; where a region is not a disk, field lines through
/// virtual singularities close it (on a copy of the analysis and a graph G rebuilt on it,
/// both only alive while the closing runs).
void cutIntoPatches(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                    const TraceStageResult& trace, LayoutStageResult& r, StageLog& log) {
  r.patches = buildPatchLayout(*trace.graph, r.layout);
  const auto& patches = r.patches.patches;
  if (std::none_of(patches.begin(), patches.end(), [](const PatchReport& p) { return !p.isDisk; })) return;
  log.progress(90, "closing the patches that are not disks");
  FieldAnalysis withAnchors = analysis;
  std::unique_ptr<GeodesicGraph> graph(new GeodesicGraph(mesh, field, withAnchors, trace.graph->parameters(),
                                                         GeodesicGraph::SinkDistances::Skipped));
  r.closing = closeNonDiskPatches(mesh, field, withAnchors, graph, r.layout, r.patches);
  r.closingRan = true;
}

void describe(const LayoutStageResult& r, StageLog& log) {
  const Layout& l = r.layout;
  const PatchLayout& p = r.patches;
  for (const std::string& m : l.messages) log.note(m);
  const CoverageRepairReport& cr = l.coverageRepair;
  if (cr.programs > 0)
    log.info("Coverage repair: " + std::to_string(cr.portsGained) + " more ports covered by the first program's selection (" +
             std::to_string(cr.accepted) + " of " + std::to_string(cr.programs) +
             " neighbourhoods of dangling ports selected again, covering ports first)");
  const CompletionReport& c = l.completion;
  if (c.trials > 0)
    log.info("Completion: t-junctions and unresolved ports " + std::to_string(c.tJunctionsBefore) + " -> " +
             std::to_string(c.tJunctionsAfter) + " (" + std::to_string(c.accepted) + " of " + std::to_string(c.trials) +
             " trials kept, " + std::to_string(c.freedSeparatrices) + " separatrices freed and their ports matched again)");
  for (std::size_t i = 0; i < l.leftPorts.size() && i < kLeftPortLines; ++i) log.info("Left: " + l.leftPorts[i]);
  if (l.leftPorts.size() > kLeftPortLines)
    log.info("... and " + std::to_string(l.leftPorts.size() - kLeftPortLines) + " more ports left");
  if (l.ilpTimeLimited > 0)
    log.warning("The 0-1 programs' time limit (ilp_time_limit, a safety stop) cut " + std::to_string(l.ilpTimeLimited) +
                " parts short; the best selection found was used, and this layout depends on the machine's speed");
  std::string corners;
  for (const auto& h : p.cornerHistogram())
    corners += (corners.empty() ? "" : ", ") + std::to_string(h.first) + " corners: " + std::to_string(h.second);
  log.info("Layout: " + std::to_string(l.separatrices.size()) + " separatrices (" + std::to_string(l.tJunctions) +
           " t-junctions, " + std::to_string(l.borderConnections) + " border connections), " +
           std::to_string(p.numPatches()) + " patches (" + (corners.empty() ? std::string("no disks") : corners) + "), " +
           std::to_string(p.numInvalidPatches()) + " invalid patches, " + std::to_string(l.iterations) + " iterations, " +
           std::to_string(l.selectedFromCandidates) + " separatrices selected from H");
  if (r.closingRan)
    log.info("Closing: some patches were not disks; " + std::to_string(r.closing.linesAdded) +
             " field lines added through " + std::to_string(r.closing.virtualVertices) + " regular vertices");
  if (p.numInvalidPatches() > 0) {
    // One warning, naming the first few: a layout of a ragged surface can have hundreds.
    std::string named;
    int count = 0;
    for (int i = 0; i < p.numPatches(); ++i) {
      if (p.patches[i].valid) continue;
      if (count++ < kInvalidPatchLines)
        named += (named.empty() ? "" : "; ") + std::string("patch ") + std::to_string(i) + ": " + p.patches[i].problem;
    }
    if (count > kInvalidPatchLines) named += "; and " + std::to_string(count - kInvalidPatchLines) + " more";
    log.warning(std::to_string(count) + " layout patches are not disks with 4 corners (" + named +
                "); the quad mesh gets irregular vertices there");
  }
  if (!l.unresolvedPorts.empty())
    log.warning(std::to_string(l.unresolvedPorts.size()) + " ports could not be connected to the layout");
  log.info("Time: 0-1 programs " + formatSeconds(l.ilpSeconds) + ", solving cycle tracing " +
           formatSeconds(l.cycleTracingSeconds) + ", completion " + formatSeconds(l.completionSeconds) +
           ", propagation " + formatSeconds(l.propagationSeconds) + ", cut into patches " + formatSeconds(r.cutSeconds));
}

void record(const LayoutStageResult& r, const PipelineParameters& p, Figures& f) {
  const Layout& l = r.layout;
  recordParameters(f, p, PipelineStage::Layout);
  f.set("graph_h.selected", l.selectedFromCandidates);
  f.set("layout.separatrices", l.separatrices.size());
  f.set("layout.patches", r.patches.numPatches());
  f.set("layout.t_junctions", l.tJunctions);
  f.set("layout.border_connections", l.borderConnections);
  f.set("layout.iterations", l.iterations);
  f.set("layout.dangling_ports", l.danglingAfterCycle);
  f.set("layout.unresolved_ports", l.unresolvedPorts.size());
  f.set("layout.dead_ends_removed", l.deadEndsRemoved);
  f.set("layout.added_corners", r.patches.addedCorners);
  f.set("layout.invalid_patches", r.patches.numInvalidPatches());
  f.set("layout.closing_lines", r.closing.linesAdded);
  std::vector<std::pair<std::string, int>> corners;
  for (const auto& h : r.patches.cornerHistogram()) corners.push_back({std::to_string(h.first), h.second});
  f.setCounts("layout.corner_histogram", corners);
  f.set("layout.ilp_time_limit_hit", l.ilpTimeLimitHit);
  f.set("layout.ilp_stalled", l.ilpStalled);
  f.set("layout.ilp_time_limited", l.ilpTimeLimited);
  f.set("layout.coverage_repair_programs", l.coverageRepair.programs);
  f.set("layout.coverage_repair_accepted", l.coverageRepair.accepted);
  f.set("layout.coverage_repair_ports", l.coverageRepair.portsGained);
  f.set("layout.completion_trials", l.completion.trials);
  f.set("layout.completion_accepted", l.completion.accepted);
  f.set("layout.completion_freed", l.completion.freedSeparatrices);
  f.set("layout.t_junctions_before_completion", l.completion.tJunctionsBefore);
  f.set("time_s.ilp", l.ilpSeconds);
  f.set("time_s.cycle_tracing", l.cycleTracingSeconds);
  f.set("time_s.completion", l.completionSeconds);
  f.set("time_s.propagation", l.propagationSeconds);
  f.set("time_s.cut", r.cutSeconds);
}

}  // namespace

LayoutStageResult runLayoutStage(const SurfaceMesh& mesh, const CrossField& field, const FieldAnalysis& analysis,
                                 const TraceStageResult& trace, const PipelineParameters& p,
                                 const StageObserver& observer) {
  const LayoutParameters params = layoutParameters(p);
  LayoutStageResult r;
  StageLog log(observer);
  log.progress(0, "selecting the separatrices (0-1 programs with lp_solve, branch and bound until " +
                      std::to_string(params.ilpStallNodes) + " nodes bring nothing better)");
  r.layout = solveLayout(*trace.graph, trace.h, params);
  log.progress(80, "cutting the surface into patches");
  const auto start = std::chrono::steady_clock::now();
  cutIntoPatches(mesh, field, analysis, trace, r, log);
  r.cutSeconds = secondsSince(start);
  describe(r, log);
  record(r, p, r.figures);
  log.progress(100, "layout done");
  r.log = std::move(log.lines);
  return r;
}

}  // namespace fcql
