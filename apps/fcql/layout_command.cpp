#include "command_line.h"
#include "commands.h"
#include "output_dir.h"

#include "field/field_io.h"
#include "layout/layout_io.h"
#include "layout/patch_closing.h"

#include <algorithm>

#include <chrono>

namespace fcql {

LayoutParameters readLayoutParameters(const CommandLine& cl) {
  LayoutParameters p;
  p.ilpTimeLimit = cl.number("ilp-time-limit", p.ilpTimeLimit, 1.0, 86400.0);
  p.ilpStallNodes = cl.integer("ilp-stall", int(p.ilpStallNodes), 0, 100000000);
  p.completionTrials = cl.integer("completion-trials", p.completionTrials, 0, 100000);
  return p;
}

LayoutStage runLayoutStage(const FieldStage& fs, const TraceStage& ts, const LayoutParameters& params, StatsJson& stats, bool quiet) {
  LayoutStage ls;
  progress(quiet, "solving the layout (0-1 programs with lp_solve, branch and bound until " + std::to_string(params.ilpStallNodes) +
                      " nodes bring nothing better; safety time limit " + std::to_string(int(params.ilpTimeLimit)) + " s each)");
  ls.layout = solveLayout(*ts.graph, ts.h, params);
  for (const auto& m : ls.layout.messages) progress(quiet, "note: " + m);
  const CompletionReport& completion = ls.layout.completion;
  if (completion.trials > 0)
    progress(quiet, "completion: t-junctions and unresolved ports " + std::to_string(completion.tJunctionsBefore) + " -> " +
                        std::to_string(completion.tJunctionsAfter) + " (" + std::to_string(completion.accepted) + " of " +
                        std::to_string(completion.trials) + " trials kept, " + std::to_string(completion.freedSeparatrices) +
                        " separatrices freed and their ports matched again)");
  for (std::size_t i = 0; i < ls.layout.leftPorts.size() && i < kLeftPortLines; ++i)
    progress(quiet, "left: " + ls.layout.leftPorts[i]);
  if (ls.layout.leftPorts.size() > kLeftPortLines)
    progress(quiet, "... and " + std::to_string(ls.layout.leftPorts.size() - kLeftPortLines) + " more ports left");
  if (ls.layout.ilpTimeLimited > 0)
    progress(quiet, "warning: the 0-1 programs' time limit (--ilp-time-limit, a safety stop) cut " +
                        std::to_string(ls.layout.ilpTimeLimited) + " parts short: this layout depends on the machine's speed");
  auto cutStart = std::chrono::steady_clock::now();
  ls.patches = buildPatchLayout(*ts.graph, ls.layout);
  ClosingReport closing;
  if (ls.patches.numPatches() > 0 &&
      std::any_of(ls.patches.patches.begin(), ls.patches.patches.end(), [](const PatchReport& p) { return !p.isDisk; })) {
    progress(quiet, "some regions are not disks: tracing field lines to close them");
    ls.analysis = fs.analysis;
    ls.graph = std::make_unique<GeodesicGraph>(fs.mesh, fs.field, ls.analysis, ts.graph->parameters(),
                                               GeodesicGraph::SinkDistances::Skipped);
    closing = closeNonDiskPatches(fs.mesh, fs.field, ls.analysis, ls.graph, ls.layout, ls.patches);
  }
  ls.cutSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - cutStart).count();
  std::string hist;
  for (const auto& h : ls.patches.cornerHistogram()) hist += (hist.empty() ? "" : ", ") + std::to_string(h.first) + " corners: " + std::to_string(h.second);
  progress(quiet, "layout: " + std::to_string(ls.layout.separatrices.size()) + " separatrices, " +
                      std::to_string(ls.patches.numPatches()) + " patches (" + hist + "), " +
                      std::to_string(ls.layout.tJunctions) + " t-junctions, " + std::to_string(ls.layout.iterations) +
                      " iterations, " + std::to_string(ls.patches.numInvalidPatches()) + " invalid patches");
  for (int p = 0; p < ls.patches.numPatches(); ++p)
    if (!ls.patches.patches[p].valid) progress(quiet, "warning: patch " + std::to_string(p) + ": " + ls.patches.patches[p].problem);
  stats.set("params.ilp_time_limit", params.ilpTimeLimit);
  stats.set("graph_h.selected", ls.layout.selectedFromCandidates);
  stats.set("layout.separatrices", int(ls.layout.separatrices.size()));
  stats.set("layout.patches", ls.patches.numPatches());
  stats.set("layout.t_junctions", ls.layout.tJunctions);
  stats.set("layout.border_connections", ls.layout.borderConnections);
  stats.set("layout.iterations", ls.layout.iterations);
  stats.set("layout.dangling_ports", ls.layout.danglingAfterCycle);
  stats.set("layout.unresolved_ports", int(ls.layout.unresolvedPorts.size()));
  stats.set("layout.dead_ends_removed", ls.layout.deadEndsRemoved);
  stats.set("layout.added_corners", ls.patches.addedCorners);
  stats.set("layout.invalid_patches", ls.patches.numInvalidPatches());
  stats.set("layout.closing_lines", closing.linesAdded);
  std::vector<std::pair<std::string, int>> corners;
  for (const auto& h : ls.patches.cornerHistogram()) corners.push_back({std::to_string(h.first), h.second});
  stats.setCounts("layout.corner_histogram", corners);
  stats.set("layout.ilp_time_limit_hit", ls.layout.ilpTimeLimitHit);
  stats.set("layout.ilp_stalled", ls.layout.ilpStalled);
  stats.set("layout.ilp_time_limited", ls.layout.ilpTimeLimited);
  stats.set("params.ilp_stall_nodes", int(params.ilpStallNodes));
  stats.set("time_s.ilp", ls.layout.ilpSeconds);
  stats.set("time_s.cycle_tracing", ls.layout.cycleTracingSeconds);
  stats.set("time_s.propagation", ls.layout.propagationSeconds);
  stats.set("time_s.completion", ls.layout.completionSeconds);
  stats.set("params.completion_trials", params.completionTrials);
  stats.set("layout.completion_trials", completion.trials);
  stats.set("layout.completion_accepted", completion.accepted);
  stats.set("layout.completion_freed", completion.freedSeparatrices);
  stats.set("layout.t_junctions_before_completion", completion.tJunctionsBefore);
  stats.set("time_s.cut", ls.cutSeconds);
  return ls;
}

int layoutCommand(int argc, char** argv) {
  CommandLine cl(argc, argv, 2,
                 {"field", "sharp-angle", "field-scale", "out", "example", "alpha", "k", "phi", "threads", "ilp-time-limit", "ilp-stall", "completion-trials"}, {"quiet"});
  requireOutputDir(cl);
  bool quiet = cl.has("quiet");
  TracingParameters tp = readTracingParameters(cl);
  LayoutParameters lp = readLayoutParameters(cl);
  StatsJson stats;
  auto start = std::chrono::steady_clock::now();
  FieldStage fs = runFieldStage(cl, stats, quiet);
  TraceStage ts = runTraceStage(fs, tp, stats, quiet);
  LayoutStage ls = runLayoutStage(fs, ts, lp, stats, quiet);
  const auto outputStart = Clock::now();
  OutputDir out(cl.value("out"));
  out.write("field.ffield", [&](const std::string& path) { saveFField(fs.mesh, fs.field, path); });
  out.writeText("candidates.obj", candidatesObj(ts.h));
  out.writeText("separatrices.obj", separatricesToObj(ls.layout));
  out.writeText("layout.ply", patchLayoutToPly(ls.patches));
  recordTotalTime(stats, start, outputStart);
  out.writeText("stats.json", stats.toString());
  out.commit();
  progress(quiet, "wrote separatrices.obj, layout.ply, candidates.obj, field.ffield and stats.json in " + cl.value("out"));
  return 0;
}

}  // namespace fcql
