#include "filter_fieldquadlayout.h"

#include "compute_field_step.h"
#include "filter_parameters.h"

#include <QAction>

#include <exception>
#include <new>
#include <string>

using namespace fcql_meshlab;

namespace {

// Filters offered by this build; the others of FilterId are planned (see the header).
const FilterFieldQuadLayoutPlugin::FilterId kImplementedFilters[] = {
    FilterFieldQuadLayoutPlugin::FP_COMPUTE_CROSS_FIELD,
};

const char* const kReference =
    "<br><br>See: <i>Nico Pietroni, Enrico Puppo, Giorgio Marcias, Roberto Scopigno, Paolo "
    "Cignoni</i><br><b>\"Tracing Field-Coherent Quad Layouts\"</b><br>Computer Graphics Forum "
    "35(7), Pacific Graphics 2016.";

}  // namespace

FilterFieldQuadLayoutPlugin::FilterFieldQuadLayoutPlugin() {
  for (FilterId id : kImplementedFilters) typeList << id;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterFieldQuadLayoutPlugin::pluginName() const {
  return QStringLiteral("FilterFieldQuadLayout");
}

QString FilterFieldQuadLayoutPlugin::filterName(FilterIDType filter) const {
  switch (filter) {
    case FP_COMPUTE_CROSS_FIELD: return QStringLiteral("Field-Coherent Quad Layout: Compute Cross Field");
    case FP_TRACE_SEPARATRICES: return QStringLiteral("Field-Coherent Quad Layout: Trace Separatrices");
    case FP_SOLVE_LAYOUT: return QStringLiteral("Field-Coherent Quad Layout: Solve Layout");
    case FP_QUADRANGULATE: return QStringLiteral("Field-Coherent Quad Layout: Quadrangulate");
    case FP_ALL_STEPS: return QStringLiteral("Field-Coherent Quad Layout: All Steps");
  }
  return QString();
}

QString FilterFieldQuadLayoutPlugin::filterInfo(FilterIDType filter) const {
  QString info;
  switch (filter) {
    case FP_COMPUTE_CROSS_FIELD:
      info = QStringLiteral(
          "First step of the field-coherent quad layout: computes a smooth cross field "
          "(4-RoSy) on the faces of the mesh, aligned to the principal curvature directions "
          "where they are well defined, to feature lines of sharp edges and to the borders, "
          "then finds its singular vertices and the directions of the separatrices leaving "
          "them.<br>The field is stored per face as curvature directions (PD1 = one direction "
          "of the cross, PD2 = PD1 rotated by 90 degrees). Singular vertices are selected, "
          "their index times 4 is stored in the per-vertex quality (-1 for index -1/4, +1 for "
          "+1/4, 0 elsewhere), and they are flagged in the per-vertex attribute "
          "<i>fcql_singular</i>. The counts of singularities by index are written to the log."
          "<br>The mesh must be an oriented 2-manifold triangle mesh without degenerate faces.");
      break;
    case FP_TRACE_SEPARATRICES:
      info = QStringLiteral("Traces the candidate separatrices of the field-coherent quad layout.");
      break;
    case FP_SOLVE_LAYOUT:
      info = QStringLiteral("Selects the separatrices that form the field-coherent quad layout.");
      break;
    case FP_QUADRANGULATE:
      info = QStringLiteral("Builds a quad mesh from the field-coherent quad layout.");
      break;
    case FP_ALL_STEPS:
      info = QStringLiteral("Runs all the steps of the field-coherent quad layout.");
      break;
  }
  return info + QString::fromUtf8(kReference);
}

MeshFilterInterface::FilterClass FilterFieldQuadLayoutPlugin::getClass(QAction*) {
  return MeshFilterInterface::Remeshing;
}

MeshFilterInterface::FILTER_ARITY FilterFieldQuadLayoutPlugin::filterArity(QAction*) const {
  return MeshFilterInterface::SINGLE_MESH;
}

int FilterFieldQuadLayoutPlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterFieldQuadLayoutPlugin::postCondition(QAction* action) const {
  switch (ID(action)) {
    case FP_COMPUTE_CROSS_FIELD:
      return MeshModel::MM_FACECURVDIR | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTFLAGSELECT;
    default:
      return MeshModel::MM_ALL;
  }
}

void FilterFieldQuadLayoutPlugin::initParameterSet(QAction* action, MeshModel&,
                                                   RichParameterList& parameters) {
  switch (ID(action)) {
    case FP_COMPUTE_CROSS_FIELD:
      addFieldParameters(parameters);
      break;
    default:
      break;
  }
}

bool FilterFieldQuadLayoutPlugin::applyFilter(QAction* action, MeshDocument& md,
                                              const RichParameterList& parameters,
                                              vcg::CallBackPos* cb) {
  const FilterIDType id = ID(action);
  errorMessage.clear();
  MeshModel* mm = md.mm();
  if (!mm) return fail(id, QStringLiteral("there is no current mesh"));
  // Everything is computed before the document is written, so any exception leaves it as it was.
  try {
    switch (id) {
      case FP_COMPUTE_CROSS_FIELD: return applyComputeCrossField(*mm, parameters, cb);
      default: return fail(id, QStringLiteral("this filter is not implemented yet"));
    }
  } catch (const std::bad_alloc&) {
    return fail(id, QStringLiteral("out of memory"));
  } catch (const std::exception& e) {
    return fail(id, QString::fromUtf8(e.what()));
  } catch (...) {
    return fail(id, QStringLiteral("unexpected error"));
  }
}

bool FilterFieldQuadLayoutPlugin::applyComputeCrossField(MeshModel& mm,
                                                         const RichParameterList& parameters,
                                                         vcg::CallBackPos* cb) {
  const FieldParameters params = readFieldParameters(parameters);  // throws ParameterError
  const FieldStepResult result = computeFieldStep(mm.cm, params, Progress{cb});
  storeFieldStep(mm, result);
  for (const std::string& line : describeFieldStep(result, params)) Log(line);
  return true;
}

bool FilterFieldQuadLayoutPlugin::fail(FilterIDType filter, const QString& reason) {
  errorMessage = filterName(filter) + QStringLiteral(" failed: ") + reason;
  Log(GLLogStream::WARNING, errorMessage.toStdString());
  return false;
}
