#!/usr/bin/env bash
# Set-up, build and run every test (unit tests, CLI end-to-end tests, meshlabserver tests, and
# the MeshLab 2025.07 / pymeshlab adapter's tests through fcql_pymeshlab_host).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
# FCQL_BUILD_PLUGIN_2025: the first configure builds the MeshLab 2025.07 SDK once into
# /var/cache/fcql/meshlab-2025.07d (double precision, as pymeshlab; scripts/meshlab2025_sdk.sh, ~4 min);
# later runs reuse it.
cmake -S . -B build -DFCQL_BUILD_PLUGIN_2025=ON >/dev/null
cmake --build build -j2
cd build
ctest --output-on-failure -j2
