# Locates the MeshLab 2020.09 SDK that scripts/setup.sh unpacks from Debian's source package
# (vcglib and MeshLab's src/common headers) and Debian's libmeshlab-common.so.
set(FCQL_MESHLAB_SDK_DIR "${CMAKE_CURRENT_SOURCE_DIR}/third_party/meshlab-2020.09"
    CACHE PATH "MeshLab 2020.09 source tree (vcglib/ and src/common/), from scripts/setup.sh")
set(FCQL_VCGLIB_DIR "${FCQL_MESHLAB_SDK_DIR}/vcglib")
set(FCQL_MESHLAB_COMMON_DIR "${FCQL_MESHLAB_SDK_DIR}/src/common")
if(NOT EXISTS "${FCQL_VCGLIB_DIR}/vcg/complex/complex.h")
  message(FATAL_ERROR "vcglib not found in ${FCQL_MESHLAB_SDK_DIR}: run scripts/setup.sh first "
                      "(it fetches MeshLab 2020.09's Debian source package), or set FCQL_MESHLAB_SDK_DIR.")
endif()
