// MeshLab 2020.09 filter plugin (MeshFilterInterface) for "Tracing Field-Coherent Quad Layouts"
// (Pietroni et al. 2016): libfilter_fieldquadlayout.so for Debian's MeshLab 2020.09.
//
// How the code is shared with the FilterPlugin adapter for MeshLab 2022.02+ / pymeshlab
// (filter_fieldquadlayout_2025.{h,cpp}):
//  - every filter lives in filter_actions.{h,cpp} (names, python names, descriptions, masks,
//    parameters, runFilter()), on top of the *_step, pipeline_*, document_layers,
//    meshlab_mesh_adapter, stored_field and filter_parameters files; all of them are compiled
//    once per plugin target, against that target's MeshLab headers;
//  - the few header differences between the two MeshLab versions are in meshlab_api.h (the
//    only #if FCQL_MESHLAB_API);
//  - this adapter is interface glue only: QAction ids <-> FilterId, Log() for the log lines,
//    errorMessage + false on failure (also logged, since meshlabserver does not print
//    errorMessage).
#pragma once

#include <common/interfaces.h>

#include <QObject>
#include <QString>

class FilterFieldQuadLayoutPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

public:
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
};
