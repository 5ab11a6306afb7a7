// MeshLab 2020.09 filter plugin for "Tracing Field-Coherent Quad Layouts" (Pietroni et al.
// 2016). Interface glue only: names, descriptions, parameters, dispatch and error reporting.
// Each filter's work lives in its own *_step.cpp (conversion + fcql calls), the algorithm in
// fcql_core (vcg_ext/).
//
// Filters (DESIGN.md §4; class Remeshing):
//   1. Field-Coherent Quad Layout: Compute Cross Field    (compute_field_step.h)
//   2. Field-Coherent Quad Layout: Trace Separatrices     (trace_step.h)
//   3. Field-Coherent Quad Layout: Solve Layout           (layout_step.h)
//   4. Field-Coherent Quad Layout: Quadrangulate          (quad_step.h)
//   5. Field-Coherent Quad Layout: All Steps              (the four steps above in one go)
// Filters 2-4 start from the cross field that filter 1 leaves on the mesh (per-face PD1) and
// re-trace from it (deterministic), so each needs only filter 1 to have run. Every filter
// computes everything first and writes the document last: a failure leaves it unchanged.
#pragma once

#include <common/interfaces.h>

#include <QObject>
#include <QString>

#include <string>
#include <vector>

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
  bool applyTraceSeparatrices(MeshDocument& md, MeshModel& mm,
                              const RichParameterList& parameters, vcg::CallBackPos* cb);
  bool applySolveLayout(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                        vcg::CallBackPos* cb);
  bool applyQuadrangulate(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                          vcg::CallBackPos* cb);
  bool applyAllSteps(MeshDocument& md, MeshModel& mm, const RichParameterList& parameters,
                     vcg::CallBackPos* cb);
  void logLines(const std::vector<std::string>& lines);
  /// Logs the reason (meshlabserver does not print errorMessage), sets errorMessage, returns false.
  bool fail(FilterIDType filter, const QString& reason);
};
