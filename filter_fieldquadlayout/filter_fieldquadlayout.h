// MeshLab 2020.09 filter plugin for "Tracing Field-Coherent Quad Layouts" (Pietroni et al.
// 2016). Interface glue only: names, descriptions, parameters, dispatch and error reporting.
// Each filter's work lives in its own *_step.cpp (conversion + fcql calls), the algorithm in
// fcql_core (vcg_ext/).
//
// Filters (DESIGN.md §4; class Remeshing):
//   1. Field-Coherent Quad Layout: Compute Cross Field        (implemented)
//   2. Field-Coherent Quad Layout: Trace Separatrices         (planned)
//   3. Field-Coherent Quad Layout: Solve Layout               (planned)
//   4. Field-Coherent Quad Layout: Quadrangulate              (planned)
//   5. Field-Coherent Quad Layout: All Steps                  (planned)
// A planned filter is registered by adding its id to kImplementedFilters in the .cpp and a case
// in each switch; the ids, names and infos are already defined.
#pragma once

#include <common/interfaces.h>

#include <QObject>
#include <QString>

class FilterFieldQuadLayoutPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
  enum FilterId {
    FP_COMPUTE_CROSS_FIELD = 0,
    FP_TRACE_SEPARATRICES,
    FP_SOLVE_LAYOUT,
    FP_QUADRANGULATE,
    FP_ALL_STEPS,
  };

  FilterFieldQuadLayoutPlugin();

  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;
  using MeshFilterInterface::initParameterSet;

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parameters) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                   vcg::CallBackPos* cb) override;

private:
  bool applyComputeCrossField(MeshModel& mm, const RichParameterList& parameters,
                              vcg::CallBackPos* cb);
  /// Logs the reason (meshlabserver does not print errorMessage), sets errorMessage, returns false.
  bool fail(FilterIDType filter, const QString& reason);
};
