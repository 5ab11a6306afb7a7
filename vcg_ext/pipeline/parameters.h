// The pipeline's parameters, defined once: for each, its name in the MeshLab filters, .mlx
// scripts and pymeshlab ("sharp_angle"), its fcql option ("--sharp-angle"), type, default,
// range, unit and help text. fcql's option parsing and usage, the filters' parameter lists and
// their validation, and the README's list (`fcql parameters --markdown`) are all made from
// this table; PipelineParameters holds the values a run uses.
#pragma once

#include "pipeline/figures.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace fcql {

/// The stage whose filter group a parameter belongs to (the filters of later stages add the
/// groups they re-run: Solve Layout has Trace and Layout; All Steps has all four).
enum class PipelineStage { Field, Trace, Layout, Quad };

/// A parameter value out of range or unparsable; what() names the parameter as the front end
/// shows it (fcql: "--alpha ...", the filters: "parameter 'alpha' (drift penalty) ...").
struct ParameterError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct PipelineParameters;

struct ParameterSpec {
  enum Kind { Real, Integer, Flag, Text, File };
  const char* name = "";     ///< filters, .mlx, pymeshlab; "" if the filters lack it
  const char* option = "";   ///< fcql option without "--"; "" if fcql lacks it
  Kind kind = Real;
  PipelineStage stage = PipelineStage::Field;
  double defaultValue = 0;   ///< Real, Integer, Flag (0/1)
  double min = 0, max = 0;   ///< Real, Integer: the valid range, both included
  const char* defaultText = "";  ///< Text, File
  const char* choices = "";      ///< Text: the allowed values separated by '|'
  const char* unit = "";         ///< "degrees", "of the bounding-box diagonal", ...
  const char* label = "";        ///< the filters' label
  const char* meaning = "";      ///< a few words for error messages ("drift penalty")
  const char* help = "";         ///< the one help text: fcql usage, tooltips, README
  // Where the value lives in PipelineParameters (one of them, by kind).
  double PipelineParameters::*real = nullptr;
  int PipelineParameters::*integer = nullptr;
  bool PipelineParameters::*flag = nullptr;
  std::string PipelineParameters::*text = nullptr;

  bool inFilters() const { return name[0] != '\0'; }
  bool inCli() const { return option[0] != '\0'; }
  /// "0..180 degrees", "field|mean-value", "a .ffield or .rosy file", "true/false".
  std::string rangeText() const;
  /// The default as text ("35", "field", "false", "" for no file).
  std::string defaultAsText() const;
};

/// Every parameter, grouped by stage in pipeline order.
const std::vector<ParameterSpec>& parameterTable();
/// The entry of filter name `name` (or fcql option `name`); throws std::out_of_range.
const ParameterSpec& parameterSpec(const std::string& name);

/// How a front end names a parameter in messages.
enum class ParameterNaming { CliOption, FilterName };

/// The values of one run, with the table's defaults.
struct PipelineParameters {
  // Field
  double sharpAngleDeg = 0, fieldScale = 0;
  std::string fieldFile;
  bool useExisting = false;
  // Trace
  double alpha = 0, phiDeg = 0;
  int k = 0, threads = 0;
  // Layout
  double ilpTimeLimit = 0;
  int ilpStall = 0, completionTrials = 0;
  // Quad
  double scale = 0, maxDeviation = 0, misalignmentThresholdDeg = 0;
  int targetFaces = 0, smooth = 0;
  std::string param;

  PipelineParameters();  ///< the table's defaults

  /// Sets `spec` from text (fcql's option values): numbers must parse entirely and lie in the
  /// range, Text values be one of the choices. Throws ParameterError.
  void setFromText(const ParameterSpec& spec, const std::string& value, ParameterNaming naming);
  /// Typed setters (the filters' values), validated the same way. Throws ParameterError.
  void setReal(const ParameterSpec& spec, double value, ParameterNaming naming);
  void setInteger(const ParameterSpec& spec, long long value, ParameterNaming naming);
  void setFlag(const ParameterSpec& spec, bool value);
  void setText(const ParameterSpec& spec, const std::string& value, ParameterNaming naming);

  /// The value of `spec` as text (as stats.json's params.* and the log show it).
  std::string valueText(const ParameterSpec& spec) const;
};

/// Records params.NAME for the parameters of `stage` that fcql has (use_existing, an input
/// choice of the filters, and file names left out): each stage's figures say what it ran with.
void recordParameters(Figures& figures, const PipelineParameters& parameters, PipelineStage stage);

/// The parameters as a Markdown list by stage (the README's parameter section).
std::string parametersMarkdown();
/// fcql's usage lines for the options of `stage` ("  --alpha A  drift penalty ... (default 20)").
std::string parametersUsage(PipelineStage stage);

}  // namespace fcql
