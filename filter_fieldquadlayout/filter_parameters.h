// Parameters of the Field-Coherent Quad Layout filters (DESIGN.md §3, §4).
//
// Each group of parameters (one per pipeline stage) has: its keys (valid Python identifiers, as
// they appear in .mlx scripts and as pymeshlab keywords), a function that adds the group to a
// RichParameterList with labels and tooltips, and a function that reads and validates it. The
// readers throw ParameterError with one line naming the parameter, its value and the valid
// range: MeshLab passes out-of-range and unparsable values through (or silently replaces them
// by the default), so validation is the filter's job. A filter made of several stages (e.g.
// "All Steps") adds and reads several groups.
#pragma once

#include "meshlab_api.h"

#include <stdexcept>
#include <string>

namespace fcql_meshlab {

struct ParameterError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// ---- Compute Cross Field ------------------------------------------------------------------
struct FieldParameters {
  static constexpr const char* kSharpAngle = "sharp_angle";
  static constexpr const char* kUseExisting = "use_existing";
  static constexpr const char* kFieldFile = "field_file";
  static constexpr const char* kFieldScale = "field_scale";
  static constexpr double kDefaultSharpAngle = 35.0;
  static constexpr double kMinSharpAngle = 0.0;
  static constexpr double kMaxSharpAngle = 180.0;
  static constexpr double kDefaultFieldScale = 0.02;  ///< as `fcql field --field-scale`
  static constexpr double kMinFieldScale = 0.0;
  static constexpr double kMaxFieldScale = 1.0;

  double sharpAngleDeg = kDefaultSharpAngle;  ///< dihedral angle above which an edge is a feature
  bool useExisting = false;                   ///< keep the field already in PD1/PD2, if any
  std::string fieldFile;                      ///< a .ffield/.rosy to read (empty: none)
  double fieldScale = kDefaultFieldScale;     ///< curvature scale, fraction of the diagonal
};

void addFieldParameters(RichParameterList& list);
FieldParameters readFieldParameters(const RichParameterList& list);

// ---- Trace Separatrices (filter 2; filters 3 and 5 re-trace with the same group) ----------
struct TracingParameters {
  static constexpr const char* kAlpha = "alpha";
  static constexpr const char* kK = "k";
  static constexpr const char* kPhi = "phi";
  static constexpr double kDefaultAlpha = 20.0;
  static constexpr int kDefaultK = 10;
  static constexpr double kDefaultPhi = 10.0;

  double alpha = kDefaultAlpha;  ///< drift penalty of the metric (Eq. 1), >= 0
  int k = kDefaultK;             ///< sinks per source, >= 1
  double phiDeg = kDefaultPhi;   ///< auxiliary-point angle, 1..45 degrees
};

void addTracingParameters(RichParameterList& list);
TracingParameters readTracingParameters(const RichParameterList& list);

// ---- Solve Layout (filter 3; filter 5 adds it after the field and tracing groups) ------------
struct LayoutParameters {
  static constexpr const char* kIlpTimeLimit = "ilp_time_limit";
  static constexpr const char* kIlpStall = "ilp_stall";
  static constexpr const char* kCompletionTrials = "completion_trials";
  static constexpr double kDefaultIlpTimeLimit = 60.0;
  static constexpr double kMinIlpTimeLimit = 1.0;
  static constexpr double kMaxIlpTimeLimit = 86400.0;
  static constexpr int kDefaultIlpStall = 50;          ///< as `fcql layout --ilp-stall`
  static constexpr int kMaxIlpStall = 100000000;
  static constexpr int kDefaultCompletionTrials = 24;  ///< as `fcql layout --completion-trials`
  static constexpr int kMaxCompletionTrials = 100000;

  double ilpTimeLimit = kDefaultIlpTimeLimit;  ///< seconds per 0-1 program
  int ilpStall = kDefaultIlpStall;             ///< branch-and-bound nodes without improvement
  int completionTrials = kDefaultCompletionTrials;  ///< sets of separatrices the completion may free
};

void addLayoutParameters(RichParameterList& list);
LayoutParameters readLayoutParameters(const RichParameterList& list);

// ---- Quadrangulate (filter 4; filter 5 adds it last) ----------------------------------------
struct QuadParameters {
  static constexpr const char* kScale = "scale";
  static constexpr double kDefaultScale = 0.02;
  static constexpr double kMinScale = 1e-5;
  static constexpr double kMaxScale = 1.0;

  /// Target quad edge length as a fraction of the bounding-box diagonal (as `fcql run --scale`).
  double scale = kDefaultScale;
};

void addQuadParameters(RichParameterList& list);
QuadParameters readQuadParameters(const RichParameterList& list);

}  // namespace fcql_meshlab
