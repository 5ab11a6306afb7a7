#include "filter_fieldquadlayout_2025.h"

#include "filter_actions.h"

#include <common/mlexception.h>

#include <QAction>

using namespace fcql_meshlab;

FieldQuadLayoutFilterPlugin::FieldQuadLayoutFilterPlugin() {
  for (FilterId id : allFilters()) typeList.push_back(id);
  for (ActionIDType id : types()) actionList.push_back(new QAction(filterName(id), this));
}

QString FieldQuadLayoutFilterPlugin::pluginName() const {
  return QStringLiteral("FilterFieldQuadLayout");
}

QString FieldQuadLayoutFilterPlugin::vendor() const {
  return QStringLiteral("Field-Coherent Quad Layout project");
}

QString FieldQuadLayoutFilterPlugin::filterName(ActionIDType filter) const {
  return fcql_meshlab::filterName(FilterId(filter));
}

QString FieldQuadLayoutFilterPlugin::pythonFilterName(ActionIDType filter) const {
  return fcql_meshlab::pythonFilterName(FilterId(filter));
}

QString FieldQuadLayoutFilterPlugin::filterInfo(ActionIDType filter) const {
  return fcql_meshlab::filterInfo(FilterId(filter));
}

FilterPlugin::FilterClass FieldQuadLayoutFilterPlugin::getClass(const QAction*) const {
  return FilterPlugin::Remeshing;
}

FilterPlugin::FilterArity FieldQuadLayoutFilterPlugin::filterArity(const QAction*) const {
  return FilterPlugin::SINGLE_MESH;
}

int FieldQuadLayoutFilterPlugin::getPreConditions(const QAction* action) const {
  return filterPreConditions(FilterId(ID(action)));
}

int FieldQuadLayoutFilterPlugin::postCondition(const QAction* action) const {
  return filterPostConditions(FilterId(ID(action)));
}

RichParameterList FieldQuadLayoutFilterPlugin::initParameterList(const QAction* action,
                                                                 const MeshModel&) {
  RichParameterList parameters;
  addFilterParameters(FilterId(ID(action)), parameters);
  return parameters;
}

std::map<std::string, QVariant> FieldQuadLayoutFilterPlugin::applyFilter(
    const QAction* action, const RichParameterList& parameters, MeshDocument& md,
    unsigned int& /*postConditionMask: postCondition() applies*/, vcg::CallBackPos* cb) {
  FilterOutcome outcome;
  try {
    outcome = runFilter(FilterId(ID(action)), md, parameters, cb);
  } catch (const FilterFailure& failure) {
    log(GLLogStream::WARNING, failure.what());
    throw MLException(QString::fromStdString(failure.what()));
  }
  for (const std::string& line : outcome.log)
    if (line.compare(0, 9, "Warning: ") == 0)
      log(GLLogStream::WARNING, line);
    else
      log(line);
  std::map<std::string, QVariant> figures;
  for (const fcql::Figures::Entry& f : outcome.figures.entries()) {
    switch (f.kind) {
      case fcql::Figures::Entry::Integer: figures[f.key] = QVariant(int(f.integer)); break;  // counts fit; pymeshlab maps int
      case fcql::Figures::Entry::Real: figures[f.key] = QVariant(f.real); break;
      case fcql::Figures::Entry::Flag: figures[f.key] = QVariant(f.flag); break;
      case fcql::Figures::Entry::Text: figures[f.key] = QVariant(QString::fromStdString(f.text)); break;
      case fcql::Figures::Entry::EmptyObject: break;  // an empty count list: no key
    }
  }
  return figures;
}
