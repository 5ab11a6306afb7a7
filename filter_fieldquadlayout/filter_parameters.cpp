#include "filter_parameters.h"

#include <cmath>
#include <sstream>
#include <string>

namespace fcql_meshlab {

// Out-of-line definitions of the constants (needed in C++14 when they are odr-used).
constexpr const char* FieldParameters::kSharpAngle;
constexpr const char* FieldParameters::kUseExisting;
constexpr const char* FieldParameters::kFieldFile;
constexpr double FieldParameters::kDefaultSharpAngle;
constexpr double FieldParameters::kMinSharpAngle;
constexpr double FieldParameters::kMaxSharpAngle;
constexpr const char* FieldParameters::kFieldScale;
constexpr double FieldParameters::kDefaultFieldScale;
constexpr double FieldParameters::kMinFieldScale;
constexpr double FieldParameters::kMaxFieldScale;
constexpr const char* TracingParameters::kAlpha;
constexpr const char* TracingParameters::kK;
constexpr const char* TracingParameters::kPhi;
constexpr double TracingParameters::kDefaultAlpha;
constexpr int TracingParameters::kDefaultK;
constexpr double TracingParameters::kDefaultPhi;
constexpr const char* LayoutParameters::kIlpTimeLimit;
constexpr double LayoutParameters::kDefaultIlpTimeLimit;
constexpr double LayoutParameters::kMinIlpTimeLimit;
constexpr double LayoutParameters::kMaxIlpTimeLimit;
constexpr const char* LayoutParameters::kIlpStall;
constexpr const char* LayoutParameters::kCompletionTrials;
constexpr int LayoutParameters::kDefaultIlpStall;
constexpr int LayoutParameters::kMaxIlpStall;
constexpr int LayoutParameters::kDefaultCompletionTrials;
constexpr int LayoutParameters::kMaxCompletionTrials;
constexpr const char* QuadParameters::kScale;
constexpr double QuadParameters::kDefaultScale;
constexpr double QuadParameters::kMinScale;
constexpr double QuadParameters::kMaxScale;

namespace {

void requirePresent(const RichParameterList& list, const char* key) {
  if (!list.hasParameter(QString(key)))
    throw ParameterError(std::string("parameter '") + key + "' is missing");
}

std::string formatNumber(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

double readFloatInRange(const RichParameterList& list, const char* key, double lo, double hi,
                        const char* what) {
  requirePresent(list, key);
  const double value = list.getFloat(QString(key));
  if (!std::isfinite(value) || value < lo || value > hi)
    throw ParameterError(std::string("parameter '") + key + "' (" + what + ") is " +
                         formatNumber(value) + ", must be between " + formatNumber(lo) +
                         " and " + formatNumber(hi));
  return value;
}

double readFloatAtLeast(const RichParameterList& list, const char* key, double lo, const char* what) {
  requirePresent(list, key);
  const double value = list.getFloat(QString(key));
  if (!std::isfinite(value) || value < lo)
    throw ParameterError(std::string("parameter '") + key + "' (" + what + ") is " +
                         formatNumber(value) + ", must be a number >= " + formatNumber(lo));
  return value;
}

/// An integer parameter added after the first release: absent in older scripts, where it takes
/// its default; present, it must lie in [lo, hi].
int readOptionalIntInRange(const RichParameterList& list, const char* key, int fallback, int lo, int hi,
                           const char* what) {
  if (!list.hasParameter(QString(key))) return fallback;
  const int value = list.getInt(QString(key));
  if (value < lo || value > hi)
    throw ParameterError(std::string("parameter '") + key + "' (" + what + ") is " + std::to_string(value) +
                         ", must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return value;
}

}  // namespace

void addFieldParameters(RichParameterList& list) {
  list.addParam(RichFloat(
      QString(FieldParameters::kSharpAngle), float(FieldParameters::kDefaultSharpAngle),
      "Sharp angle (degrees)",
      "Edges whose dihedral angle (angle between the normals of the two faces) exceeds this "
      "many degrees are sharp features; the cross field is aligned to feature lines made of "
      "sharp edges. Valid range 0..180; 180 disables the alignment to sharp edges. Ignored when "
      "the existing field is kept."));
  list.addParam(RichBool(
      QString(FieldParameters::kUseExisting), false, "Use existing field",
      "If the mesh already has a per-face cross field (per-face curvature directions PD1/PD2, "
      "e.g. loaded from a .ffield/.rosy file or left by a previous run), keep it and only "
      "analyse it (singularities and ports). If the mesh has none, a new field is computed."));
  addOpenFileParameter(
      list, QString(FieldParameters::kFieldFile), QStringLiteral("*.ffield *.rosy"),
      "Cross field file",
      "A cross field to read instead of computing one: a .ffield (vcglib frame field) or .rosy "
      "(4-RoSy) file with one direction per face, in the mesh's face order, as `fcql field "
      "--field` reads it. Empty (the default): no file. A file of the wrong face count, "
      "truncated, with NaNs or zero vectors makes the filter fail and leaves the mesh as it "
      "was. Takes precedence over 'Use existing field'.");
  list.addParam(RichFloat(
      QString(FieldParameters::kFieldScale), float(FieldParameters::kDefaultFieldScale),
      "Field scale (fraction of the diagonal)",
      "Length over which the surface's curvature is spread before the computed field places "
      "its singularities, as a fraction of the bounding-box diagonal (like fcql field "
      "--field-scale): bumps smaller than this make no singularity pairs. 0 gives the field of "
      "the unmodified surface (one pair per bump of noise). Valid range 0..1. Ignored when a "
      "field is read or kept."));
}

FieldParameters readFieldParameters(const RichParameterList& list) {
  FieldParameters p;
  p.sharpAngleDeg = readFloatInRange(list, FieldParameters::kSharpAngle,
                                     FieldParameters::kMinSharpAngle,
                                     FieldParameters::kMaxSharpAngle, "sharp angle in degrees");
  requirePresent(list, FieldParameters::kUseExisting);
  p.useExisting = list.getBool(QString(FieldParameters::kUseExisting));
  // Absent in scripts written before it existed: no file then.
  if (list.hasParameter(QString(FieldParameters::kFieldFile)))
    p.fieldFile = list.getOpenFileName(QString(FieldParameters::kFieldFile)).toStdString();
  // Absent in scripts written before it existed: the default then.
  if (list.hasParameter(QString(FieldParameters::kFieldScale)))
    p.fieldScale = readFloatInRange(list, FieldParameters::kFieldScale, FieldParameters::kMinFieldScale,
                                    FieldParameters::kMaxFieldScale, "field scale as a fraction of the diagonal");
  return p;
}

void addTracingParameters(RichParameterList& list) {
  list.addParam(RichFloat(
      QString(TracingParameters::kAlpha), float(TracingParameters::kDefaultAlpha),
      "Drift penalty \u03b1",
      "Weight of the drift of a separatrix from the cross field in the tracing metric "
      "(Eq. 1 of the paper). 0 gives geodesics; larger values follow the field more closely. "
      "Must be >= 0."));
  list.addParam(RichInt(
      QString(TracingParameters::kK), TracingParameters::kDefaultK, "K: sinks per source",
      "Number of candidate separatrices (sinks) traced from each source. Must be >= 1."));
  list.addParam(RichFloat(
      QString(TracingParameters::kPhi), float(TracingParameters::kDefaultPhi),
      "Phi: auxiliary point angle (degrees)",
      "Auxiliary points are inserted on a mesh edge until the angle it subtends at the "
      "opposite vertex is below phi. Valid range 1..45 degrees."));
}

TracingParameters readTracingParameters(const RichParameterList& list) {
  TracingParameters p;
  p.alpha = readFloatAtLeast(list, TracingParameters::kAlpha, 0.0, "drift penalty");
  requirePresent(list, TracingParameters::kK);
  p.k = list.getInt(QString(TracingParameters::kK));
  if (p.k < 1)
    throw ParameterError(std::string("parameter '") + TracingParameters::kK +
                         "' (sinks per source) is " + std::to_string(p.k) + ", must be >= 1");
  p.phiDeg = readFloatInRange(list, TracingParameters::kPhi, 1.0, 45.0,
                              "auxiliary point angle in degrees");
  return p;
}

void addLayoutParameters(RichParameterList& list) {
  list.addParam(RichFloat(
      QString(LayoutParameters::kIlpTimeLimit), float(LayoutParameters::kDefaultIlpTimeLimit),
      "ILP time limit (seconds)",
      "Time limit of each 0-1 program that selects the separatrices (lp_solve), and of the "
      "side-length program of the quad mesh in all. When it is reached the best selection "
      "found so far is used and the log says so. Valid range 1..86400 seconds."));
  list.addParam(RichInt(
      QString(LayoutParameters::kIlpStall), LayoutParameters::kDefaultIlpStall,
      "ILP stall (branch-and-bound nodes)",
      "Branch and bound on the separatrix selection stops once this many of its nodes brought "
      "no better selection (like fcql layout --ilp-stall); counted in nodes, so the same input "
      "gives the same layout on any machine. 0: only the time limit stops it."));
  list.addParam(RichInt(
      QString(LayoutParameters::kCompletionTrials), LayoutParameters::kDefaultCompletionTrials,
      "Completion trials",
      "Where ports are left dangling after the solving cycle, up to this many sets of the "
      "separatrices in their way are freed and their ports matched again, each kept only if "
      "fewer t-junctions remain (like fcql layout --completion-trials). 0: no completion."));
}

LayoutParameters readLayoutParameters(const RichParameterList& list) {
  LayoutParameters p;
  p.ilpTimeLimit = readFloatInRange(list, LayoutParameters::kIlpTimeLimit,
                                    LayoutParameters::kMinIlpTimeLimit,
                                    LayoutParameters::kMaxIlpTimeLimit, "ILP time limit in seconds");
  p.ilpStall = readOptionalIntInRange(list, LayoutParameters::kIlpStall, LayoutParameters::kDefaultIlpStall, 0,
                                      LayoutParameters::kMaxIlpStall, "branch-and-bound nodes without improvement");
  p.completionTrials =
      readOptionalIntInRange(list, LayoutParameters::kCompletionTrials, LayoutParameters::kDefaultCompletionTrials, 0,
                             LayoutParameters::kMaxCompletionTrials, "completion trials");
  return p;
}

void addQuadParameters(RichParameterList& list) {
  list.addParam(RichFloat(
      QString(QuadParameters::kScale), float(QuadParameters::kDefaultScale),
      "Quad size (fraction of the diagonal)",
      "Target edge length of the quads, as a fraction of the diagonal of the bounding box "
      "(0.02 = 2% of the diagonal, like fcql run --scale). Smaller values give more quads. "
      "Valid range 0.00001..1."));
}

QuadParameters readQuadParameters(const RichParameterList& list) {
  QuadParameters p;
  p.scale = readFloatInRange(list, QuadParameters::kScale, QuadParameters::kMinScale,
                             QuadParameters::kMaxScale,
                             "target quad edge length as a fraction of the bounding-box diagonal");
  return p;
}

}  // namespace fcql_meshlab
