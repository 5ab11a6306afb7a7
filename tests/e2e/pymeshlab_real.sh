#!/usr/bin/env bash
# End-to-end test of the plugin in the real PyMeshLab 2025.7 (../shared/tools/pymeshlab-2025.7,
# double precision, as pip users get it): a copy of the package with
# libfilter_fieldquadlayout2025.so added to its lib/plugins, driven by /usr/bin/python3 through
# pymeshlab_real.py (the README's snippet as written, the five filters by their method names,
# the returned dicts, quads saved as quads, every bad parameter, calls out of order, failing and
# succeeding calls in one process followed by new MeshSets, and the same figures as `fcql run`).
#
# Usage: pymeshlab_real.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=$1 shared=$2 build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
package="$shared/tools/pymeshlab-2025.7/pymeshlab"
plugin="$build/lib/meshlab-2025.07/libfilter_fieldquadlayout2025.so"
[ -d "$package" ] || { echo "skip: $package is absent"; exit 77; }
[ -f "$plugin" ] || { echo "skip: $plugin not built (FCQL_BUILD_PLUGIN_2025=OFF)"; exit 77; }
[ -f "$shared/data/meshes/eight.obj" ] || { echo "skip: the shared meshes are absent"; exit 77; }
/usr/bin/python3 -c 'import numpy' 2>/dev/null || { echo "FAIL: /usr/bin/python3 has no numpy (apt-get install python3-numpy)"; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -a "$package" "$work/"
chmod -R u+w "$work/pymeshlab"
cp "$plugin" "$work/pymeshlab/lib/plugins/"
mkdir -p "$work/run" "$work/xdg" && chmod 700 "$work/xdg"
for m in eight kitten fertility; do ln -s "$shared/data/meshes/$m.obj" "$work/run/$m.obj"; done
ln -s "$shared/data/meshes/eight.ffield" "$work/run/eight.ffield"

# The CLI's figures for the comparison (same parameters as the Python side).
"$fcql" run "$work/run/eight.obj" --field "$work/run/eight.ffield" --out "$work/cli_eight" --quiet || { echo "FAIL: fcql run eight"; exit 1; }
"$fcql" run "$work/run/kitten.obj" --out "$work/cli_kitten" --quiet || { echo "FAIL: fcql run kitten"; exit 1; }

# A sanitized plugin (FCQL_SANITIZE=ON) needs the sanitizer runtimes loaded before Python starts:
# the build gives their paths in FCQL_PYTHON_PRELOAD. Leak checking is off for the interpreter
# (it keeps its objects to the end by design); any other report fails the test.
preload=()
if [ -n "${FCQL_PYTHON_PRELOAD:-}" ]; then
  echo "python runs with the sanitizer runtimes preloaded: $FCQL_PYTHON_PRELOAD"
  preload=(env "LD_PRELOAD=$FCQL_PYTHON_PRELOAD"
    "ASAN_OPTIONS=detect_leaks=0:verify_asan_link_order=0:abort_on_error=0:exitcode=1"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
fi
cd "$work/run"
QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR="$work/xdg" XDG_CONFIG_HOME="$work/xdg" PYTHONPATH="$work" \
  "${preload[@]}" /usr/bin/python3 "$here/pymeshlab_real.py" "$here/../../README.md" "$work"
