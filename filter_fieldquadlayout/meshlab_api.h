// The MeshLab headers the shared filter code needs, for either of the two plugin APIs this
// directory is built for. It is the ONLY place where the shared code (filter_actions, *_step,
// pipeline_*, document_layers, meshlab_mesh_adapter, stored_field, filter_parameters) sees a
// difference between them; the two adapters (filter_fieldquadlayout.cpp for 2020.09,
// filter_fieldquadlayout_2025.cpp for 2022.02+/2025.07) hold the rest of the interface glue.
//
// FCQL_MESHLAB_API is set by CMake on each plugin target:
//   2020  MeshLab 2020.09 (Debian bookworm): <common/meshmodel.h>, <common/filter_parameter/...>
//   2025  MeshLab 2022.02 .. 2025.07 (FilterPlugin API, pymeshlab): <common/ml_document/...>,
//         <common/parameters/...>
// Both have the same MeshModel / MeshDocument / CMeshO / RichParameterList members that the
// shared code uses (cm, updateDataMask, MM_* masks, addNewMesh(path, label, current),
// RichFloat/RichInt/RichBool(name, default, label, tooltip), hasParameter, getFloat/Int/Bool),
// except the bounding-box update, renamed between the two (see updateBoxAndNormals below).
#pragma once

#ifndef FCQL_MESHLAB_API
#error "FCQL_MESHLAB_API must be defined (2020 or 2025): see filter_fieldquadlayout/CMakeLists.txt"
#endif

#if FCQL_MESHLAB_API >= 2022
#include <common/ml_document/mesh_document.h>
#include <common/parameters/rich_parameter_list.h>
#else
#include <common/filter_parameter/rich_parameter_list.h>
#include <common/meshmodel.h>
#endif

namespace fcql_meshlab {

/// A file-name parameter for opening a file (RichOpenFile in 2020.09, RichFileOpen from 2021
/// on); its value is read with getOpenFileName in both.
inline void addOpenFileParameter(RichParameterList& list, const QString& name, const QString& extensions,
                                 const QString& label, const QString& tooltip) {
#if FCQL_MESHLAB_API >= 2022
  list.addParam(RichFileOpen(name, QString(), QStringList() << extensions, label, tooltip));
#else
  list.addParam(RichOpenFile(name, QString(), QStringList() << extensions, label, tooltip));
#endif
}

/// Bounding box and normals after the coordinates changed (UpdateBoxAndNormals in 2020.09,
/// updateBoxAndNormals from 2021 on).
inline void updateBoxAndNormals(MeshModel& mm) {
#if FCQL_MESHLAB_API >= 2022
  mm.updateBoxAndNormals();
#else
  mm.UpdateBoxAndNormals();
#endif
}

}  // namespace fcql_meshlab
