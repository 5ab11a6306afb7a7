#!/usr/bin/env bash
# Set-up, build and run every test (unit tests, CLI end-to-end tests, meshlabserver tests, the
# MeshLab 2025.07 adapter's tests through fcql_pymeshlab_host and the real PyMeshLab, the fuzz
# smoke run), then the unit, CLI and pymeshlab tests once more built with AddressSanitizer and
# UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
# FCQL_BUILD_PLUGIN_2025: the first configure builds the MeshLab 2025.07 SDK once into
# /var/cache/fcql/meshlab-2025.07d (double precision, as pymeshlab; scripts/meshlab2025_sdk.sh, ~4 min);
# later runs reuse it.
cmake -S . -B build -DFCQL_BUILD_PLUGIN_2025=ON >/dev/null
cmake --build build -j2
(cd build && ctest --output-on-failure -j2)
# The sanitizer build: the core, fcql, the unit tests and the MeshLab 2025.07 adapter with its
# host (not the 2020.09 plugin), RelWithDebInfo. Its ctest runs the unit tests, the CLI
# end-to-end tests (the readers, the layout cut, the quadrangulation, every bad-input class) and
# the plugin's tests through fcql_pymeshlab_host and in the real PyMeshLab (its python process
# with the sanitizer runtimes preloaded, tests/CMakeLists.txt). The meshlabserver and fuzz tests,
# and the quality sweep over every shared mesh at two sizes (e2e.cli_run_shared, minutes even
# unsanitized), are left to the build above.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFCQL_SANITIZE=ON -DFCQL_BUILD_PLUGIN=OFF \
  -DFCQL_BUILD_PLUGIN_2025=ON >/dev/null
cmake --build build-sanitize -j2
cd build-sanitize
ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j2 -E '^(fuzz|e2e\.meshlab|e2e\.cli_run_shared)'
