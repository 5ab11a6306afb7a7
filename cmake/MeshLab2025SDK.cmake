# Locates (and, the first time, builds) the MeshLab 2025.07 SDK used by the FilterPlugin adapter
# and the pymeshlab-like host (FCQL_BUILD_PLUGIN_2025=ON). scripts/meshlab2025_sdk.sh builds
# MeshLab's libmeshlab-common.so and io_base from Debian's source package into a cache outside
# the build tree (default /var/cache/fcql/meshlab-2025.07d, or $FCQL_MESHLAB2025_CACHE), in double precision, once;
# this module runs it at configure time when the cache has no stamp (FCQL_MESHLAB2025_AUTO_BUILD)
# and defines:
#   fcql::meshlab2025_common   imported target: the library, its headers (src/common, vcglib),
#                              MESHLAB_VERSION=2025.07 and MESHLAB_SCALAR=double (the loader
#                              compares both with its own)
#   FCQL_MESHLAB2025_DIR       the cache folder
#   FCQL_MESHLAB2025_PLUGINS   folder with MeshLab's own plugins (libio_base.so)
# MeshLab exports no CMake package, hence the imported target.

if(DEFINED ENV{FCQL_MESHLAB2025_CACHE})
  set(_fcql_ml2025_default "$ENV{FCQL_MESHLAB2025_CACHE}")
else()
  set(_fcql_ml2025_default "/var/cache/fcql/meshlab-2025.07d")
endif()
set(FCQL_MESHLAB2025_DIR "${_fcql_ml2025_default}" CACHE PATH
    "MeshLab 2025.07 SDK cache built by scripts/meshlab2025_sdk.sh")
option(FCQL_MESHLAB2025_AUTO_BUILD
       "Run scripts/meshlab2025_sdk.sh at configure time if the MeshLab 2025.07 SDK cache is missing" ON)

set(_fcql_ml2025_stamp "${FCQL_MESHLAB2025_DIR}/.complete")
if(NOT EXISTS "${_fcql_ml2025_stamp}" AND FCQL_MESHLAB2025_AUTO_BUILD)
  message(STATUS "MeshLab 2025.07 SDK not in ${FCQL_MESHLAB2025_DIR}: building it once "
                 "(scripts/meshlab2025_sdk.sh, ~4 min on 2 cores)")
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env FCQL_MESHLAB2025_CACHE=${FCQL_MESHLAB2025_DIR}
            bash ${PROJECT_SOURCE_DIR}/scripts/meshlab2025_sdk.sh
    RESULT_VARIABLE _fcql_ml2025_result
    OUTPUT_QUIET)
  if(NOT _fcql_ml2025_result EQUAL 0)
    message(FATAL_ERROR "scripts/meshlab2025_sdk.sh failed (see ${FCQL_MESHLAB2025_DIR}/build.log); "
                        "configure with -DFCQL_BUILD_PLUGIN_2025=OFF to build without the "
                        "MeshLab 2025.07 adapter.")
  endif()
endif()

set(_fcql_ml2025_src "${FCQL_MESHLAB2025_DIR}/src/src")
set(_fcql_ml2025_lib "${FCQL_MESHLAB2025_DIR}/lib/libmeshlab-common.so")
if(NOT EXISTS "${_fcql_ml2025_stamp}" OR NOT EXISTS "${_fcql_ml2025_lib}"
   OR NOT EXISTS "${_fcql_ml2025_src}/common/plugins/interfaces/filter_plugin.h")
  message(FATAL_ERROR "MeshLab 2025.07 SDK not found in ${FCQL_MESHLAB2025_DIR}: run "
                      "scripts/meshlab2025_sdk.sh (or set FCQL_MESHLAB2025_DIR / "
                      "FCQL_MESHLAB2025_CACHE), or configure with -DFCQL_BUILD_PLUGIN_2025=OFF.")
endif()
file(READ "${_fcql_ml2025_stamp}" _fcql_ml2025_stamp_text)
if(NOT _fcql_ml2025_stamp_text MATCHES "scalar=double")
  message(FATAL_ERROR "${FCQL_MESHLAB2025_DIR} holds a single-precision MeshLab 2025.07 (an older cache): "
                      "pymeshlab loads only double-precision plugins. Configure with "
                      "-DFCQL_MESHLAB2025_DIR=/var/cache/fcql/meshlab-2025.07d (built on first use).")
endif()
set(FCQL_MESHLAB2025_PLUGINS "${FCQL_MESHLAB2025_DIR}/lib/plugins")

find_package(Qt5 5.15 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml Network)
find_package(GLEW REQUIRED)

if(NOT TARGET fcql::meshlab2025_common)
  add_library(fcql::meshlab2025_common SHARED IMPORTED)
  set_target_properties(fcql::meshlab2025_common PROPERTIES
    IMPORTED_LOCATION "${_fcql_ml2025_lib}"
    INTERFACE_INCLUDE_DIRECTORIES "${_fcql_ml2025_src};${_fcql_ml2025_src}/vcglib"
    INTERFACE_COMPILE_DEFINITIONS "MESHLAB_VERSION=2025.07;MESHLAB_SCALAR=double"
    INTERFACE_LINK_LIBRARIES "Qt5::Core;Qt5::Gui;Qt5::Widgets;Qt5::OpenGL;Qt5::Xml;GLEW::GLEW;Eigen3::Eigen")
endif()
