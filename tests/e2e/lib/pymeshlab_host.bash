# Helpers for the end-to-end tests of the FilterPlugin adapter through fcql_pymeshlab_host
# (tests/e2e/pymeshlab_*.sh). Sourced, not run (lib/ is outside the CMake glob of tests).
# Reuses the mesh and stats readers of meshlab_overlay.bash (write_cube, ply_faces, json_key).

# shellcheck source=meshlab_overlay.bash
source "$(dirname "${BASH_SOURCE[0]}")/meshlab_overlay.bash"

# pm_require_host BUILD_DIR: sets $host_bin and $plugin2025; skips the test when the build has
# no FilterPlugin adapter (FCQL_BUILD_PLUGIN_2025=OFF).
pm_require_host() {
  host_bin="$1/bin/fcql_pymeshlab_host"
  plugin2025="$1/lib/meshlab-2025.07/libfilter_fieldquadlayout2025.so"
  [ -x "$host_bin" ] && [ -f "$plugin2025" ] ||
    skip "fcql_pymeshlab_host / libfilter_fieldquadlayout2025.so not built (FCQL_BUILD_PLUGIN_2025=OFF)"
}

# pm_host_dirs: the host's private runtime and configuration folder, $work/xdg (see host).
pm_host_dirs() {
  mkdir -p "$work/xdg"
  chmod 700 "$work/xdg"
}

# pm_setup BUILD_DIR NAME: sets $work (BUILD_DIR/e2e_NAME, emptied), $host_bin, $plugin2025;
# skips the test when the build has no FilterPlugin adapter (FCQL_BUILD_PLUGIN_2025=OFF).
pm_setup() {
  local build=$1 name=$2
  [ -n "$build" ] && [ -d "$build" ] || skip "no build directory given"
  pm_require_host "$build"
  work="$build/e2e_$name"
  rm -rf "$work"
  pm_host_dirs
}

pm_finish() { ml_finish "$@"; }

# host OUT ARGS...: fcql_pymeshlab_host ARGS (default plugin folders: the SDK's io_base and the
# built adapter), headless, stdout and stderr into OUT; returns the host's exit status.
host() {
  local out=$1
  shift
  QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR="$work/xdg" XDG_CONFIG_HOME="$work/xdg" \
    timeout 600 "$host_bin" "$@" >"$out" 2>&1
}

# dict_of OUT NAME: the dict printed for `apply NAME` ("NAME -> {...}").
dict_of() { grep -a "^$2 -> {" "$1" | head -1 | sed "s/^$2 -> //"; }
# dict_value DICT KEY: the value of 'KEY' in a printed dict.
dict_value() { printf '%s\n' "$1" | grep -oE "'$2': [^,}]+" | head -1 | sed "s/^'$2': //"; }

# same MESH WHAT DICT REFERENCE KEY...: DICT has the REFERENCE's value for each KEY.
same() {
  local mesh=$1 what=$2 dict=$3 ref=$4 key a b
  shift 4
  for key in "$@"; do
    a=$(dict_value "$dict" "$key")
    b=$(dict_value "$ref" "$key")
    [ -n "$a" ] && [ "$a" = "$b" ] || fail "$mesh: $what gives $key = '$a', All Steps '$b'"
  done
}
