#include "filter_fieldquadlayout.h"

#include "filter_actions.h"

#include <QAction>

#include <string>

using namespace fcql_meshlab;

FilterFieldQuadLayoutPlugin::FilterFieldQuadLayoutPlugin() {
  for (FilterId id : allFilters()) typeList << id;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterFieldQuadLayoutPlugin::pluginName() const {
  return QStringLiteral("FilterFieldQuadLayout");
}

QString FilterFieldQuadLayoutPlugin::filterName(FilterIDType filter) const {
  return fcql_meshlab::filterName(FilterId(filter));
}

QString FilterFieldQuadLayoutPlugin::filterInfo(FilterIDType filter) const {
  return fcql_meshlab::filterInfo(FilterId(filter));
}

MeshFilterInterface::FilterClass FilterFieldQuadLayoutPlugin::getClass(QAction*) {
  return MeshFilterInterface::Remeshing;
}

MeshFilterInterface::FILTER_ARITY FilterFieldQuadLayoutPlugin::filterArity(QAction*) const {
  return MeshFilterInterface::SINGLE_MESH;
}

int FilterFieldQuadLayoutPlugin::getPreConditions(QAction* action) const {
  return filterPreConditions(FilterId(ID(action)));
}

int FilterFieldQuadLayoutPlugin::postCondition(QAction* action) const {
  return filterPostConditions(FilterId(ID(action)));
}

void FilterFieldQuadLayoutPlugin::initParameterSet(QAction* action, MeshModel&,
                                                   RichParameterList& parameters) {
  addFilterParameters(FilterId(ID(action)), parameters);
}

bool FilterFieldQuadLayoutPlugin::applyFilter(QAction* action, MeshDocument& md,
                                              const RichParameterList& parameters,
                                              vcg::CallBackPos* cb) {
  errorMessage.clear();
  try {
    const FilterOutcome outcome = runFilter(FilterId(ID(action)), md, parameters, cb);
    for (const std::string& line : outcome.log)
      if (line.compare(0, 9, "Warning: ") == 0)
        Log(GLLogStream::WARNING, line);
      else
        Log(line);
    return true;
  } catch (const FilterFailure& failure) {
    // meshlabserver does not print errorMessage: the log carries it too.
    errorMessage = QString::fromStdString(failure.what());
    Log(GLLogStream::WARNING, errorMessage.toStdString());
    return false;
  }
}
