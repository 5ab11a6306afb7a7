#include "parameters.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fcql {

namespace {

using P = PipelineParameters;
using S = ParameterSpec;

S real(const char* name, const char* option, PipelineStage stage, double P::*field, double def, double min, double max,
       const char* unit, const char* label, const char* meaning, const char* help) {
  S s;
  s.name = name;
  s.option = option;
  s.kind = S::Real;
  s.stage = stage;
  s.real = field;
  s.defaultValue = def;
  s.min = min;
  s.max = max;
  s.unit = unit;
  s.label = label;
  s.meaning = meaning;
  s.help = help;
  return s;
}

S integer(const char* name, const char* option, PipelineStage stage, int P::*field, int def, int min, int max,
          const char* unit, const char* label, const char* meaning, const char* help) {
  S s = real(name, option, stage, nullptr, def, min, max, unit, label, meaning, help);
  s.kind = S::Integer;
  s.integer = field;
  return s;
}

S text(S::Kind kind, const char* name, const char* option, PipelineStage stage, std::string P::*field, const char* def,
       const char* choices, const char* label, const char* meaning, const char* help) {
  S s = real(name, option, stage, nullptr, 0, 0, 0, "", label, meaning, help);
  s.kind = kind;
  s.text = field;
  s.defaultText = def;
  s.choices = choices;
  return s;
}

S flag(const char* name, const char* option, PipelineStage stage, bool P::*field, bool def, const char* label,
       const char* meaning, const char* help) {
  S s = real(name, option, stage, nullptr, def ? 1 : 0, 0, 1, "", label, meaning, help);
  s.kind = S::Flag;
  s.flag = field;
  return s;
}

std::vector<S> makeTable() {
  const auto F = PipelineStage::Field, T = PipelineStage::Trace, L = PipelineStage::Layout, Q = PipelineStage::Quad;
  std::vector<S> t;
  // ---- Field
  t.push_back(real("sharp_angle", "sharp-angle", F, &P::sharpAngleDeg, 35, 0, 180, "degrees", "Sharp angle (degrees)",
                   "sharp angle in degrees",
                   "Edges whose dihedral angle (between the normals of their two faces) exceeds this are sharp "
                   "features: a computed cross field follows the feature lines they make, and the quad mesh's "
                   "vertices stay on them. 180 disables the alignment to sharp edges."));
  t.push_back(real("field_scale", "field-scale", F, &P::fieldScale, 0.02, 0, 1, "of the bounding-box diagonal",
                   "Field scale (fraction of the diagonal)", "field scale as a fraction of the diagonal",
                   "Length over which the surface's curvature is spread before a computed field places its "
                   "singularities: bumps smaller than this make no singularity pairs, and a +1/4 and a -1/4 "
                   "closer than this are cancelled. 0: the curvature at each vertex (one singularity pair per "
                   "bump of noise). Ignored when a field is read or kept."));
  t.push_back(text(S::File, "field_file", "field", F, &P::fieldFile, "", "", "Cross field file", "cross field file",
                   "A cross field to read instead of computing one: a .ffield (vcglib frame field) or .rosy "
                   "(4-RoSy) file with one direction per face, in the mesh's face order. A file of the wrong "
                   "face count, truncated, with NaNs or zero vectors is refused with a clear error."));
  t.push_back(flag("use_existing", "", F, &P::useExisting, false, "Use existing field", "use the existing field",
                   "If the mesh already has a per-face cross field (per-face curvature directions PD1/PD2, "
                   "e.g. left by a previous run), keep it and only analyse it (singularities and ports); "
                   "if it has none, a new field is computed. A cross field file takes precedence."));
  // ---- Trace
  t.push_back(real("alpha", "alpha", T, &P::alpha, 20, 0, 1e6, "", "Drift penalty \u03b1", "drift penalty",
                   "Weight of a separatrix's drift from the cross field in the tracing metric (Eq. 1 of the "
                   "paper): 0 gives geodesics, larger values follow the field more closely."));
  t.push_back(integer("k", "k", T, &P::k, 10, 1, 1000000, "", "K: sinks per source", "sinks per source",
                      "Number of candidate separatrices (sinks) a search from each port finds before it stops."));
  t.push_back(real("phi", "phi", T, &P::phiDeg, 10, 1, 45, "degrees", "Phi: auxiliary point angle (degrees)",
                   "auxiliary point angle in degrees",
                   "Auxiliary points are inserted on every mesh edge until the angle it subtends at the opposite "
                   "vertex is below phi: smaller values give a denser graph G (more memory, straighter paths)."));
  t.push_back(integer("threads", "threads", T, &P::threads, 0, 0, 1024, "", "Threads", "threads",
                      "Threads that trace the separatrices and smooth the quads; 0: all hardware threads. The "
                      "result does not depend on it."));
  // ---- Layout
  t.push_back(real("ilp_time_limit", "ilp-time-limit", L, &P::ilpTimeLimit, 60, 1, 86400, "seconds",
                   "ILP time limit (seconds)", "ILP time limit in seconds",
                   "Safety stop of each 0-1 program (lp_solve) that selects the separatrices, and of the side-length "
                   "programs of the quad mesh in all: where it is reached the best solution found is used, and "
                   "the log and the figures say so (the result then depends on the machine's speed)."));
  t.push_back(integer("ilp_stall", "ilp-stall", L, &P::ilpStall, 50, 0, 100000000, "nodes",
                      "ILP stall (branch-and-bound nodes)", "branch-and-bound nodes without improvement",
                      "Branch and bound on the separatrix selection stops once this many of its nodes brought no "
                      "better selection; counted in nodes, so the same input gives the same layout on any "
                      "machine. 0: only the time limit stops it."));
  t.push_back(integer("completion_trials", "completion-trials", L, &P::completionTrials, 24, 0, 100000, "",
                      "Completion trials", "completion trials",
                      "Where ports are left dangling after the solving cycle, sets of the separatrices in their "
                      "way are freed and their ports matched again, each kept only if fewer t-junctions remain: "
                      "up to this many trials plus 1.25 per t-junction the layout had before (a bound in work, "
                      "not time, that grows with what is left to mend). 0: no completion."));
  // ---- Quad
  t.push_back(real("scale", "scale", Q, &P::scale, 0.02, 1e-5, 1, "of the bounding-box diagonal",
                   "Quad size (fraction of the diagonal)",
                   "target quad edge length as a fraction of the bounding-box diagonal",
                   "Target edge length of the quads, as a fraction of the bounding-box diagonal (0.02 = 2%); "
                   "smaller values give more quads."));
  t.push_back(integer("target_faces", "target-faces", Q, &P::targetFaces, 0, 0, 20000000, "quads",
                      "Target quads (0: by quad size)", "target number of quads",
                      "About how many quads to make, instead of a quad size (the edge length is then the square "
                      "root of the area per quad). 0: the quad size decides."));
  t.push_back(integer("smooth", "smooth", Q, &P::smooth, 5, 0, 1000, "iterations", "Smoothing iterations",
                      "smoothing iterations",
                      "Smoothing passes over the quad mesh (towards the cross field, reprojected on the surface; "
                      "a move that would fold a quad is not taken, folds the sampling left are untangled, and any "
                      "that remain are counted in quad.inverted_quads with a warning). 0 keeps the sampled "
                      "positions."));
  t.push_back(real("max_deviation", "max-deviation", Q, &P::maxDeviation, 0.01, 0, 1, "of the bounding-box diagonal",
                   "Largest deviation (fraction of the diagonal)", "largest deviation from the surface",
                   "Largest distance allowed between the quad mesh and the surface. Where it may be exceeded "
                   "the smoothing is undone around those places, then the patches are sampled again with "
                   "smaller quads, up to 4 times; if the bound still fails, the run fails saying how far the "
                   "quads are. 0: no check."));
  t.push_back(text(S::Text, "param", "param", Q, &P::param, "field", "field|mean-value", "Patch parametrization",
                   "patch parametrization",
                   "How each patch is mapped onto its grid of quads: field (each patch's grid follows the cross "
                   "field inside it) or mean-value (mean-value coordinates, the boundary by arc length)."));
  t.push_back(real("misalignment_threshold", "misalignment-threshold", Q, &P::misalignmentThresholdDeg, 11.25, 0, 45,
                   "degrees", "Misalignment threshold (degrees)", "misalignment threshold in degrees",
                   "A quad counts as misaligned (quad.misaligned_pct, and per input face quad.misaligned_faces_pct) "
                   "where one of its directions is more than this far from the cross field; 11.25 is pi/16, the "
                   "paper's threshold. It changes only these figures, not the quads."));
  return t;
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string shownName(const S& s, ParameterNaming naming) {
  if (naming == ParameterNaming::CliOption) return std::string("--") + s.option;
  return std::string("parameter '") + s.name + "' (" + s.meaning + ")";
}

[[noreturn]] void outOfRange(const S& s, const std::string& value, ParameterNaming naming) {
  const std::string range = s.kind == S::Integer ? std::to_string(static_cast<long long>(s.min)) + " and " + std::to_string(static_cast<long long>(s.max))
                                                 : formatNumber(s.min) + " and " + formatNumber(s.max);
  if (naming == ParameterNaming::CliOption)
    throw ParameterError(shownName(s, naming) + " must be between " + range + ", got " + value);
  throw ParameterError(shownName(s, naming) + " is " + value + ", must be between " + range);
}

bool isChoice(const S& s, const std::string& value) {
  std::string choices = s.choices;
  std::size_t begin = 0;
  while (true) {
    const std::size_t bar = choices.find('|', begin);
    if (choices.substr(begin, bar == std::string::npos ? std::string::npos : bar - begin) == value) return true;
    if (bar == std::string::npos) return false;
    begin = bar + 1;
  }
}

}  // namespace

const std::vector<ParameterSpec>& parameterTable() {
  static const std::vector<ParameterSpec> table = makeTable();
  return table;
}

const ParameterSpec& parameterSpec(const std::string& name) {
  for (const S& s : parameterTable())
    if (name == s.name || name == s.option) return s;
  throw std::out_of_range("no pipeline parameter named '" + name + "'");
}

std::string ParameterSpec::rangeText() const {
  switch (kind) {
    case Real: return formatNumber(min) + ".." + formatNumber(max) + (unit[0] ? std::string(" ") + unit : "");
    case Integer: return std::to_string(long(min)) + ".." + std::to_string(long(max)) + (unit[0] ? std::string(" ") + unit : "");
    case Flag: return "true/false";
    case Text: return choices;
    case File: return "a file path";
  }
  return "";
}

std::string ParameterSpec::defaultAsText() const {
  switch (kind) {
    case Real: return formatNumber(defaultValue);
    case Integer: return std::to_string(long(defaultValue));
    case Flag: return defaultValue != 0 ? "true" : "false";
    case Text:
    case File: return defaultText;
  }
  return "";
}

PipelineParameters::PipelineParameters() {
  for (const S& s : parameterTable()) {
    if (s.real) this->*s.real = s.defaultValue;
    if (s.integer) this->*s.integer = int(s.defaultValue);
    if (s.flag) this->*s.flag = s.defaultValue != 0;
    if (s.text) this->*s.text = s.defaultText;
  }
}

void PipelineParameters::setReal(const ParameterSpec& s, double value, ParameterNaming naming) {
  if (!std::isfinite(value) || value < s.min || value > s.max) outOfRange(s, formatNumber(value), naming);
  this->*s.real = value;
}

void PipelineParameters::setInteger(const ParameterSpec& s, long long value, ParameterNaming naming) {
  if (value < s.min || value > s.max) outOfRange(s, std::to_string(value), naming);
  this->*s.integer = int(value);
}

void PipelineParameters::setFlag(const ParameterSpec& s, bool value) { this->*s.flag = value; }

void PipelineParameters::setText(const ParameterSpec& s, const std::string& value, ParameterNaming naming) {
  if (s.kind == S::Text && !isChoice(s, value)) {
    std::string choices = s.choices;
    for (char& c : choices)
      if (c == '|') c = '/';
    if (naming == ParameterNaming::CliOption)
      throw ParameterError(shownName(s, naming) + " must be one of " + choices + ", got '" + value + "'");
    throw ParameterError(shownName(s, naming) + " is '" + value + "', must be one of " + choices);
  }
  this->*s.text = value;
}

void PipelineParameters::setFromText(const ParameterSpec& s, const std::string& value, ParameterNaming naming) {
  const char* begin = value.c_str();
  char* end = nullptr;
  switch (s.kind) {
    case S::Real: {
      const double v = std::strtod(begin, &end);
      if (end == begin || *end != '\0' || !std::isfinite(v))
        throw ParameterError(shownName(s, naming) + " must be a number, got '" + value + "'");
      if (v < s.min || v > s.max) outOfRange(s, value, naming);
      this->*s.real = v;
      return;
    }
    case S::Integer: {
      const long long v = std::strtoll(begin, &end, 10);
      if (end == begin || *end != '\0')
        throw ParameterError(shownName(s, naming) + " must be an integer, got '" + value + "'");
      if (v < s.min || v > s.max) outOfRange(s, value, naming);
      this->*s.integer = int(v);
      return;
    }
    case S::Flag:
      if (value != "true" && value != "false")
        throw ParameterError(shownName(s, naming) + " must be true or false, got '" + value + "'");
      this->*s.flag = value == "true";
      return;
    case S::Text:
    case S::File: setText(s, value, naming); return;
  }
}

std::string PipelineParameters::valueText(const ParameterSpec& s) const {
  switch (s.kind) {
    case S::Real: return formatNumber(this->*s.real);
    case S::Integer: return std::to_string(this->*s.integer);
    case S::Flag: return this->*s.flag ? "true" : "false";
    case S::Text:
    case S::File: return this->*s.text;
  }
  return "";
}

void recordParameters(Figures& figures, const PipelineParameters& parameters, PipelineStage stage) {
  for (const ParameterSpec& s : parameterTable()) {
    if (s.stage != stage || s.kind == ParameterSpec::File || !s.inCli()) continue;  // use_existing: an input choice
    const std::string key = std::string("params.") + (s.inFilters() ? s.name : s.option);
    switch (s.kind) {
      case ParameterSpec::Real: figures.set(key, parameters.*s.real); break;
      case ParameterSpec::Integer: figures.set(key, parameters.*s.integer); break;
      case ParameterSpec::Flag: figures.set(key, parameters.*s.flag); break;
      default: figures.set(key, parameters.valueText(s)); break;
    }
  }
}

namespace {

const char* stageTitle(PipelineStage stage) {
  switch (stage) {
    case PipelineStage::Field: return "Cross field";
    case PipelineStage::Trace: return "Tracing (graphs G and H)";
    case PipelineStage::Layout: return "Layout (0-1 programs, solving cycle, completion)";
    case PipelineStage::Quad: return "Quad mesh";
  }
  return "";
}

}  // namespace

std::string parametersMarkdown() {
  std::string out;
  for (PipelineStage stage : {PipelineStage::Field, PipelineStage::Trace, PipelineStage::Layout, PipelineStage::Quad}) {
    out += std::string("**") + stageTitle(stage) + "**\n\n";
    out += "| fcql option | filter / pymeshlab name | default | range | meaning |\n|---|---|---|---|---|\n";
    for (const S& s : parameterTable()) {
      if (s.stage != stage) continue;
      const std::string def = s.defaultAsText();
      out += std::string("| ") + (s.inCli() ? std::string("`--") + s.option + "`" : "—") + " | " +
             (s.inFilters() ? std::string("`") + s.name + "`" : "—") + " | " + (def.empty() ? "none" : "`" + def + "`") +
             " | " + s.rangeText() + " | " + s.help + " |\n";
    }
    out += "\n";
  }
  return out;
}

std::string parametersUsage(PipelineStage stage) {
  std::string out;
  for (const S& s : parameterTable()) {
    if (s.stage != stage || !s.inCli()) continue;
    const std::string def = s.defaultAsText();
    out += std::string("  --") + s.option + " (" + s.rangeText() + (def.empty() ? "" : ", default " + def) + ")\n";
    // The help text wrapped at 90 columns, indented.
    std::istringstream words(s.help);
    std::string word, line = "     ";
    while (words >> word) {
      if (line.size() + word.size() + 1 > 94) {
        out += line + "\n";
        line = "     ";
      }
      line += " " + word;
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace fcql
