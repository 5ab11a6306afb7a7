#include "filter_parameters.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>

namespace fcql_meshlab {

namespace {

using fcql::ParameterNaming;
using fcql::ParameterSpec;

QString tooltip(const ParameterSpec& s) {
  std::string text = s.help;
  text += " Valid range: " + s.rangeText() + ".";
  return QString::fromUtf8(text.c_str());
}

/// MeshLab's RichFloat holds a float in single-precision builds (MeshLab 2020.09): the value is
/// taken back to the 7 digits a float carries, so that 0.02 stays 0.02 as fcql reads it.
double asTyped(Scalarm value) {
  if (!std::is_same<Scalarm, float>::value) return double(value);
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", double(value));
  return std::strtod(text, nullptr);
}

}  // namespace

void addStageParameters(fcql::PipelineStage stage, RichParameterList& list) {
  for (const ParameterSpec& s : fcql::parameterTable()) {
    if (s.stage != stage || !s.inFilters()) continue;
    const QString name = QString::fromUtf8(s.name), label = QString::fromUtf8(s.label);
    switch (s.kind) {
      case ParameterSpec::Real: list.addParam(RichFloat(name, Scalarm(s.defaultValue), label, tooltip(s))); break;
      case ParameterSpec::Integer: list.addParam(RichInt(name, int(s.defaultValue), label, tooltip(s))); break;
      case ParameterSpec::Flag: list.addParam(RichBool(name, s.defaultValue != 0, label, tooltip(s))); break;
      case ParameterSpec::Text:
        list.addParam(RichString(name, QString::fromUtf8(s.defaultText), label, tooltip(s)));
        break;
      case ParameterSpec::File:
        addOpenFileParameter(list, name, QStringLiteral("*.ffield *.rosy"), label, tooltip(s));
        break;
    }
  }
}

fcql::PipelineParameters readPipelineParameters(const RichParameterList& list) {
  fcql::PipelineParameters p;
  const ParameterNaming naming = ParameterNaming::FilterName;
  for (const ParameterSpec& s : fcql::parameterTable()) {
    if (!s.inFilters() || !list.hasParameter(QString::fromUtf8(s.name))) continue;
    const QString name = QString::fromUtf8(s.name);
    switch (s.kind) {
      case ParameterSpec::Real: p.setReal(s, asTyped(list.getFloat(name)), naming); break;
      case ParameterSpec::Integer: p.setInteger(s, list.getInt(name), naming); break;
      case ParameterSpec::Flag: p.setFlag(s, list.getBool(name)); break;
      case ParameterSpec::Text: p.setText(s, list.getString(name).toStdString(), naming); break;
      case ParameterSpec::File: p.setText(s, list.getOpenFileName(name).toStdString(), naming); break;
    }
  }
  return p;
}

}  // namespace fcql_meshlab
