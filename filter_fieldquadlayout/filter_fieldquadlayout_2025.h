// MeshLab 2022.02+ / 2025.07 filter plugin (FilterPlugin API, the one pymeshlab loads) for
// "Tracing Field-Coherent Quad Layouts": libfilter_fieldquadlayout2025.so.
//
// How the code is shared with the MeshLab 2020.09 adapter (filter_fieldquadlayout.{h,cpp}):
//  - every filter lives in filter_actions.{h,cpp} (names, python names, descriptions, masks,
//    parameters, runFilter()), on top of the *_step, pipeline_*, document_layers,
//    meshlab_mesh_adapter, stored_field and filter_parameters files; CMake compiles all of them
//    once per plugin target, against that target's MeshLab headers (FCQL_MESHLAB_API=2025
//    here, 2020 there);
//  - the few header differences between the two MeshLab versions are in meshlab_api.h, the
//    only #if FCQL_MESHLAB_API;
//  - this adapter is interface glue only: FilterPlugin's const-QAction signatures,
//    pythonFilterName(), log() for the log lines, the run's figures as the returned
//    std::map<std::string, QVariant> (pymeshlab's dict: ints for counts, doubles for the
//    time_* seconds), and MLException (same message as the 2020.09 errorMessage) on failure.
//
// Python names: compute_field_coherent_cross_field, trace_field_coherent_separatrices,
// solve_field_coherent_quad_layout, quadrangulate_field_coherent_quad_layout,
// compute_field_coherent_quad_layout (All Steps); parameters alpha, k, phi, sharp_angle,
// use_existing, ilp_time_limit, scale, as in the .mlx scripts.
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

#include <QObject>
#include <QString>

#include <map>
#include <string>

class FieldQuadLayoutFilterPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

public:
  FieldQuadLayoutFilterPlugin();

  QString pluginName() const override;
  QString vendor() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  int getPreConditions(const QAction* action) const override;
  int postCondition(const QAction* action) const override;
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;
  std::map<std::string, QVariant> applyFilter(const QAction* action,
                                              const RichParameterList& parameters,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;
};
