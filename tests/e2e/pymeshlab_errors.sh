#!/usr/bin/env bash
# End-to-end test of the FilterPlugin adapter's loading and error handling through
# fcql_pymeshlab_host, which goes through MeshLab 2025.07's plugin manager and
# pymeshlab::FunctionSet as pymeshlab does:
#  - the loader accepts libfilter_fieldquadlayout2025.so: PluginManager::loadPlugin runs its
#    checks (Qt plugin, MeshLab plugin, float/double precision, version "2025.0", filter class
#    and arity) and the plugin says it was built for MeshLab 2025.07 in double precision (as
#    pymeshlab builds MeshLab); the 2020.09
#    build, when there is one, is refused;
#  - the five python names are listed, with parameter names that are Python identifiers;
#  - pymeshlab's kind of messages: an unknown filter, an unknown parameter ("Parameter X not
#    found for filter Y. Please check the documentation."), a value of the wrong type, and the
#    plugin's MLException for out-of-range values and out-of-order calls, wrapped as pymeshlab
#    wraps it ("Failed to apply filter: NAME" / "Details: <the 2020.09 adapter's message>").
#
# Usage: pymeshlab_errors.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/pymeshlab_host.bash
source "$here/lib/pymeshlab_host.bash"
pm_setup "$build" pymeshlab_errors
write_cube "$work/cube.off" 3
mkdir -p "$work/no_plugins"

# ---- the loader -------------------------------------------------------------------------------
if host "$work/load.out" --plugins "$work/no_plugins" load_plugin "$plugin2025"; then
  line=$(grep -a '^loaded plugin ' "$work/load.out")
  echo "$line"
  case "$line" in
    *"built for MeshLab 2025.07 (double), this MeshLab 2025.07 (double)"*) ;;
    *) fail "unexpected version or precision: $line" ;;
  esac
else
  fail "MeshLab 2025.07's loader refused the plugin: $(tail -3 "$work/load.out")"
fi
plugin2020="$build/lib/libfilter_fieldquadlayout.so"
if [ -f "$plugin2020" ]; then
  if host "$work/load2020.out" --plugins "$work/no_plugins" load_plugin "$plugin2020"; then
    fail "the loader accepted the MeshLab 2020.09 build"
  else
    echo "2020.09 build refused: $(grep -a PyMeshLabException "$work/load2020.out" | head -1 | cut -c1-160)"
  fi
fi

# ---- python names ---------------------------------------------------------------------------
host "$work/filters.out" filters || fail "filters: $(tail -3 "$work/filters.out")"
for f in compute_field_coherent_cross_field trace_field_coherent_separatrices \
         solve_field_coherent_quad_layout quadrangulate_field_coherent_quad_layout \
         compute_field_coherent_quad_layout; do
  grep -q "^$f(" "$work/filters.out" || fail "the python filter $f is not listed"
done
grep '# Field-Coherent Quad Layout: ' "$work/filters.out" | sed 's/^[^(]*(//; s/)  #.*//' |
  tr ',' '\n' | sed 's/^ *//; s/:.*//' | sort -u >"$work/params.txt"
echo "parameters: $(tr '\n' ' ' <"$work/params.txt")"
for p in alpha k phi sharp_angle use_existing field_file field_scale ilp_time_limit ilp_stall completion_trials scale; do
  grep -qx "$p" "$work/params.txt" || fail "parameter $p is not listed"
done
if grep -qvE '^[a-z_][a-z0-9_]*$' "$work/params.txt"; then
  fail "parameter names that are not Python identifiers: $(grep -vE '^[a-z_][a-z0-9_]*$' "$work/params.txt")"
fi

# ---- errors ---------------------------------------------------------------------------------
# expect_error NAME PATTERN ARGS...: the host exits with 1 (not a crash) and its
# PyMeshLabException message matches PATTERN (an extended regex over the joined lines).
expect_error() {
  local name=$1 pattern=$2 out="$work/$1.out" status message
  shift 2
  host "$out" "$@"
  status=$?
  [ $status -eq 1 ] || { fail "$name: exit status $status, expected 1"; tail -3 "$out"; return; }
  message=$(sed -n '/^PyMeshLabException: /,$p' "$out" | tr '\n' ' ')
  printf '%s\n' "$message" | grep -qE -- "$pattern" ||
    { fail "$name: the message does not match '$pattern': $message"; return; }
  echo "$name: $message"
}
field=(load "$work/cube.off" apply compute_field_coherent_cross_field)
expect_error unknown_filter \
  "Failed to apply filter: compute_quad_layout Filter does not exists" \
  load "$work/cube.off" apply compute_quad_layout
expect_error unknown_parameter \
  "Parameter alpah not found for filter compute_field_coherent_quad_layout\. Please check the documentation\." \
  load "$work/cube.off" apply compute_field_coherent_quad_layout alpah=30
expect_error wrong_type "Parameter k: unable to cast 'ten' to int" \
  "${field[@]}" apply trace_field_coherent_separatrices k=ten
expect_error alpha_negative \
  "Failed to apply filter: trace_field_coherent_separatrices Details: Field-Coherent Quad Layout: Trace Separatrices failed: parameter 'alpha' \(drift penalty\) is -1, must be between 0 and 1e\+06" \
  "${field[@]}" apply trace_field_coherent_separatrices alpha=-1
expect_error k_zero \
  "Details: Field-Coherent Quad Layout: Solve Layout failed: parameter 'k' \(sinks per source\) is 0, must be between 1 and 1000000" \
  "${field[@]}" apply solve_field_coherent_quad_layout k=0
expect_error phi_large \
  "Details: Field-Coherent Quad Layout: All Steps failed: parameter 'phi' .* is 60, must be between 1 and 45" \
  load "$work/cube.off" apply compute_field_coherent_quad_layout phi=60
expect_error scale_zero \
  "Details: Field-Coherent Quad Layout: Quadrangulate failed: parameter 'scale' .* is 0, must be between" \
  "${field[@]}" apply quadrangulate_field_coherent_quad_layout scale=0
expect_error sharp_angle \
  "Details: Field-Coherent Quad Layout: Compute Cross Field failed: parameter 'sharp_angle' .* is 500, must be between 0 and 180" \
  load "$work/cube.off" apply compute_field_coherent_cross_field sharp_angle=500
expect_error no_field \
  "Details: Field-Coherent Quad Layout: Trace Separatrices failed: no cross field on the mesh: run Compute Cross Field first" \
  load "$work/cube.off" apply trace_field_coherent_separatrices
expect_error no_mesh "solve_field_coherent_quad_layout requires at least one mesh loaded in the MeshSet" \
  apply solve_field_coherent_quad_layout

# A failed filter leaves the MeshSet as it was: a valid run afterwards still works and adds
# only its own layers (the host stops at the first error, so this runs the valid part alone).
host "$work/after.out" "${field[@]}" apply trace_field_coherent_separatrices alpha=5 info ||
  fail "a valid trace after the cross field failed: $(tail -3 "$work/after.out")"
[ "$(grep -c "^mesh [0-9]* '" "$work/after.out")" = 2 ] || fail "unexpected layers: $(grep '^mesh' "$work/after.out")"

pm_finish pymeshlab_errors
