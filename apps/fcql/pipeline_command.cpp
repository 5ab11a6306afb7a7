// fcql field / trace / layout / run: parse the options from the parameter table, load the
// mesh, call the pipeline's stages (vcg_ext/pipeline/) and write their files and figures.
#include "command_line.h"
#include "commands.h"
#include "output_dir.h"

#include "field/field_io.h"
#include "layout/layout_io.h"
#include "mesh/generators.h"
#include "mesh/mesh_io.h"
#include "mesh/vertex_welding.h"
#include "pipeline/quad_stage.h"
#include "tracing/polyline_io.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <iostream>
#include <memory>

namespace fcql {

namespace {

using Clock = std::chrono::steady_clock;

bool upTo(PipelineStage stage, PipelineStage last) { return int(stage) <= int(last); }

CommandLine parseOptions(PipelineStage last, int argc, char** argv) {
  std::set<std::string> options = {"out", "example"};
  for (const ParameterSpec& s : parameterTable())
    if (s.inCli() && upTo(s.stage, last)) options.insert(s.option);
  return CommandLine(argc, argv, 2, options, {"quiet"});
}

PipelineParameters readParameters(const CommandLine& cl, PipelineStage last) {
  PipelineParameters p;
  for (const ParameterSpec& s : parameterTable())
    if (s.inCli() && upTo(s.stage, last) && cl.has(s.option))
      p.setFromText(s, cl.value(s.option), ParameterNaming::CliOption);
  if (last == PipelineStage::Quad && cl.has("scale") && cl.has("target-faces"))
    throw UsageError("give --scale or --target-faces, not both");
  return p;
}

void requireOutputDir(const CommandLine& cl) {
  if (!cl.has("out")) throw UsageError("missing --out DIR");
  const std::string problem = OutputDir::problem(cl.value("out"));
  if (!problem.empty()) throw UsageError(problem);
}

/// The mesh of MESH or --example NAME, coincident vertices welded.
struct LoadedMesh {
  SurfaceMesh mesh;
  MeshInput input;
};

LoadedMesh loadInput(const CommandLine& cl) {
  const auto& pos = cl.positional();
  const bool example = cl.has("example");
  if (example && !pos.empty()) throw UsageError("give either a MESH file or --example NAME, not both");
  if (!example && pos.empty()) throw UsageError("missing input: give a MESH file (.obj .ply .off) or --example NAME");
  if (pos.size() > 1) throw UsageError("unexpected argument '" + pos[1] + "'");
  const auto start = Clock::now();
  LoadedMesh m;
  if (example) {
    const std::string name = cl.value("example");
    const auto names = exampleNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw UsageError("unknown --example '" + name + "' (choose one of: " + list + ")");
    }
    m.mesh = makeExample(name);
    m.input.name = "example:" + name;
  } else {
    m.mesh = loadMesh(pos[0]);
    m.input.name = pos[0];
    VertexWelding welding = weldCoincidentVertices(m.mesh);
    if (welding.merged > 0) m.input.weldingNote = welding.note();
    if (welding.welded) {
      m.mesh = std::move(welding.mesh);
      m.input.weldedVertices = welding.merged;
    }
  }
  m.input.loadSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  return m;
}

/// Log lines as "fcql: ..." on stderr; of the progress messages, what a stage starts with, and
/// the tracing's count of ports every 25% (rewritten in place every 5% on a terminal). Quiet:
/// the warnings alone (what went wrong without failing the run: folded quads, ports left).
StageObserver cliObserver(bool quiet) {
  StageObserver o;
  o.line = [quiet](const LogLine& line) {
    if (quiet && line.kind != LogLine::Warning) return;
    const char* kind = line.kind == LogLine::Warning ? "warning: " : line.kind == LogLine::Note ? "note: " : "";
    std::cerr << "fcql: " << kind << line.text << std::endl;
  };
  if (quiet) return o;
  const bool terminal = isatty(2);
  auto last = std::make_shared<int>(-100);
  o.progress = [terminal, last](int percent, const std::string& what) {
    if (what.find(" ports)") == std::string::npos) {
      if (percent != 0) return;  // a stage starting: what it does next
      std::cerr << "fcql: " << what << "..." << std::endl;
      *last = -100;
      return;
    }
    const int step = terminal ? 5 : 25;
    if (percent - *last < step || percent == 100) return;
    *last = percent;
    std::cerr << "fcql: " << what << (terminal ? "\r" : "\n") << std::flush;
  };
  return o;
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

/// The text files of the trace and layout stages (the graph H candidates alone are tens of MB).
struct StageTexts {
  std::string candidates, separatrices, layout;
};

StageTexts formatTexts(const TraceStageResult* trace, const LayoutStageResult* layout) {
  StageTexts t;
  if (trace) t.candidates = candidatesObj(trace->h);
  if (layout) {
    t.separatrices = separatricesToObj(layout->layout);
    t.layout = patchLayoutToPly(layout->patches);
  }
  return t;
}

}  // namespace

void progress(bool quiet, const std::string& line) {
  if (!quiet) std::cerr << "fcql: " << line << std::endl;
}

int pipelineCommand(PipelineStage last, int argc, char** argv) {
  const CommandLine cl = parseOptions(last, argc, argv);
  requireOutputDir(cl);
  const bool quiet = cl.has("quiet");
  const PipelineParameters p = readParameters(cl, last);
  const auto start = Clock::now();
  const LoadedMesh loaded = loadInput(cl);
  const SurfaceMesh& mesh = loaded.mesh;
  MeshInput input = loaded.input;
  input.mesh = &mesh;
  // A quad count out of reach fails as soon as the mesh is loaded, not after the layout.
  if (last == PipelineStage::Quad) quadTargetEdge(mesh, p, ParameterNaming::CliOption);

  const StageObserver observer = cliObserver(quiet);
  const FieldStageResult field = runFieldStage(input, p, FieldSource{}, observer);
  Figures figures = field.figures;
  std::unique_ptr<TraceStageResult> trace;
  std::unique_ptr<LayoutStageResult> layout;
  std::unique_ptr<QuadStageResult> quad;
  if (upTo(PipelineStage::Trace, last)) {
    trace.reset(new TraceStageResult(runTraceStage(mesh, field.field, field.analysis, p, observer)));
    figures.append(trace->figures);
  }
  if (upTo(PipelineStage::Layout, last)) {
    layout.reset(new LayoutStageResult(runLayoutStage(mesh, field.field, field.analysis, *trace, p, observer)));
    figures.append(layout->figures);
  }
  // The layout's files are formatted on another thread while the quad stage runs (with
  // --threads 1, afterwards); all files are written once every stage succeeded, so a failed
  // stage leaves no file behind. The future's destructor joins the thread on any exit.
  const auto policy = last == PipelineStage::Quad && p.threads != 1 ? std::launch::async : std::launch::deferred;
  std::future<StageTexts> texts = std::async(policy, formatTexts, trace.get(), layout.get());
  if (last == PipelineStage::Quad) {
    quad.reset(new QuadStageResult(runQuadStage(mesh, field.field, *layout, p, observer)));
    figures.append(quad->figures);
  }

  const auto outputStart = Clock::now();
  const StageTexts stageTexts = texts.get();
  OutputDir out(cl.value("out"));
  std::vector<std::string> written = {"field.ffield"};
  out.write("field.ffield", [&](const std::string& path) { saveFField(mesh, field.field, path); });
  if (trace) {
    out.writeText("candidates.obj", stageTexts.candidates);
    written.push_back("candidates.obj");
  }
  if (layout) {
    out.writeText("separatrices.obj", stageTexts.separatrices);
    out.writeText("layout.ply", stageTexts.layout);
    written.push_back("separatrices.obj");
    written.push_back("layout.ply");
  }
  if (quad) {
    out.writeText("quad.obj", quadMeshToObj(quad->quad.mesh));
    written.push_back("quad.obj");
  }
  const auto now = Clock::now();
  figures.set("time_s.output", std::chrono::duration<double>(now - outputStart).count());
  figures.set("time_s.total", std::chrono::duration<double>(now - start).count());
  out.writeText("stats.json", figures.toJson());
  out.commit();
  std::string list;
  for (const std::string& name : written) list += name + ", ";
  progress(quiet, "wrote " + list + "stats.json in " + cl.value("out"));
  return 0;
}

namespace {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

PipelineStage stageNamed(const std::string& name) {
  if (name == "field") return PipelineStage::Field;
  if (name == "trace") return PipelineStage::Trace;
  if (name == "layout") return PipelineStage::Layout;
  if (name == "quad") return PipelineStage::Quad;
  throw UsageError("--mlx takes stages field, trace, layout, quad separated by commas, not '" + name + "'");
}

/// The <Param> lines of a MeshLab filter script for the filters' parameters of `stages`
/// (meshlabserver 2020.09 aborts on a script that does not list every parameter).
std::string mlxParams(const std::string& stages) {
  std::string out;
  std::size_t begin = 0;
  while (begin <= stages.size()) {
    const std::size_t comma = std::min(stages.find(',', begin), stages.size());
    const PipelineStage stage = stageNamed(stages.substr(begin, comma - begin));
    for (const ParameterSpec& s : parameterTable()) {
      if (s.stage != stage || !s.inFilters()) continue;
      static const char* const types[] = {"RichFloat", "RichInt", "RichBool", "RichString", "RichOpenFile"};
      out += std::string("  <Param type=\"") + types[s.kind] + "\" name=\"" + s.name + "\" value=\"" +
             xmlEscaped(s.defaultAsText()) + "\"" +
             (s.kind == ParameterSpec::File ? " exts_cardinality=\"1\" exts_val0=\"*.ffield *.rosy\"" : "") +
             " description=\"" + xmlEscaped(s.label) + "\" tooltip=\"" + xmlEscaped(s.help) + "\"/>\n";
    }
    begin = comma + 1;
  }
  return out;
}

}  // namespace

int parametersCommand(int argc, char** argv) {
  const CommandLine cl(argc, argv, 2, {"mlx"}, {"markdown"});
  if (!cl.positional().empty()) throw UsageError("unexpected argument '" + cl.positional()[0] + "'");
  if (cl.has("markdown")) {
    std::cout << parametersMarkdown();
    return 0;
  }
  if (cl.has("mlx")) {
    std::cout << mlxParams(cl.value("mlx"));
    return 0;
  }
  for (PipelineStage stage : {PipelineStage::Field, PipelineStage::Trace, PipelineStage::Layout, PipelineStage::Quad})
    std::cout << parametersUsage(stage);
  return 0;
}

}  // namespace fcql
