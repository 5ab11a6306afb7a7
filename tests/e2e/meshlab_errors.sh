#!/usr/bin/env bash
# End-to-end test of the MeshLab plugin's error handling for filters 2-5 (Trace Separatrices,
# Solve Layout, Quadrangulate, All Steps), run by Debian's meshlabserver on a small cube:
#  - out-of-range parameters (meshlabserver passes them through silently, the filters must
#    refuse them): k = 0, alpha < 0, phi = 90 or 0.5, ilp_time_limit = 0, scale = 0 or 2,
#    sharp_angle = 500;
#  - out-of-order calls: Trace Separatrices, Solve Layout and Quadrangulate on a mesh without a
#    cross field must say to run Compute Cross Field first;
#  - a failure in the last filter of a script (the earlier ones ran).
# Each time meshlabserver must exit non-zero without crashing, its output must give the
# failing filter and the reason, and no output mesh may be written.
#
# Usage: meshlab_errors.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
ml_setup "$build" meshlab_errors
trace=$(example_script trace_separatrices) || ml_finish meshlab_errors
layout=$(example_script solve_layout) || ml_finish meshlab_errors
quad=$(example_script quadrangulate) || ml_finish meshlab_errors
all=$(example_script all_steps) || ml_finish meshlab_errors
steps=$(example_script step_by_step) || ml_finish meshlab_errors
write_cube "$work/cube.off" 3

# expect_failure NAME SCRIPT FILTER PATTERN: meshlabserver on the cube with SCRIPT exits
# non-zero, without crashing, writes no output, and says "FILTER failed: " and PATTERN.
expect_failure() {
  local name=$1 mlx=$2 filter=$3 pattern=$4 log="$work/$1.log" out="$work/$1_out.ply" status line
  run_server "$log" -i "$work/cube.off" -o "$out" -s "$mlx"
  status=$?
  [ $status -ne 0 ] || fail "$name: meshlabserver exited with 0"
  [ $status -ne 134 ] && [ $status -ne 139 ] || fail "$name: meshlabserver crashed (status $status)"
  [ ! -e "$out" ] || fail "$name: an output was written after the failure"
  line=$(log_line "$log" "Field-Coherent Quad Layout: $filter failed: ")
  [ -n "$line" ] || { fail "$name: no '$filter failed' reason in the output"; tail -5 "$log"; return; }
  printf '%s\n' "$line" | grep -qE -- "$pattern" || fail "$name: the reason does not match '$pattern': $line"
  echo "$name: exit $status, $line"
}

# bad_param NAME SCRIPT FILTER PARAM VALUE PATTERN
bad_param() {
  set_param "$2" "$work/$1.mlx" "$4" "$5"
  expect_failure "$1" "$work/$1.mlx" "$3" "$6"
}

bad_param k0 "$trace" "Trace Separatrices" k 0 "'k' .* is 0, must be between 1 and 1000000"
bad_param alpha_negative "$trace" "Trace Separatrices" alpha -1 "'alpha' .* is -1, must be between 0 and 1e\+06"
bad_param phi90 "$layout" "Solve Layout" phi 90 "'phi' .* is 90, must be between 1 and 45"
bad_param ilp0 "$layout" "Solve Layout" ilp_time_limit 0 "'ilp_time_limit' .* is 0, must be between 1 and 86400"
bad_param scale0 "$quad" "Quadrangulate" scale 0 "'scale' .* is 0, must be between 1e-05 and 1"
bad_param scale2 "$quad" "Quadrangulate" scale 2 "'scale' .* is 2, must be between"
bad_param all_phi "$all" "All Steps" phi 0.5 "'phi' .* is 0.5, must be between 1 and 45"
bad_param all_k "$all" "All Steps" k -3 "'k' .* is -3, must be between 1 and 1000000"
bad_param all_sharp "$all" "All Steps" sharp_angle 500 "'sharp_angle' .* is 500, must be between 0 and 180"
bad_param all_scale "$all" "All Steps" scale 0 "'scale' .* is 0"
bad_param stall_negative "$layout" "Solve Layout" ilp_stall -1 "'ilp_stall' .* is -1, must be between 0 and"
bad_param all_completion "$all" "All Steps" completion_trials -2 "'completion_trials' .* is -2, must be between 0 and"
bad_param all_field_scale "$all" "All Steps" field_scale 2 "'field_scale' .* is 2, must be between 0 and 1"

# Out of order: the step without Compute Cross Field before it.
for case in "trace|$trace|Trace Separatrices" "layout|$layout|Solve Layout" "quad|$quad|Quadrangulate"; do
  IFS='|' read -r name mlx filter <<<"$case"
  drop_filter "$mlx" "$work/no_field_$name.mlx" "Compute Cross Field"
  grep -q 'Compute Cross Field' "$work/no_field_$name.mlx" && fail "could not drop Compute Cross Field from $mlx"
  expect_failure "no_field_$name" "$work/no_field_$name.mlx" "$filter" \
    "no cross field on the mesh: run Compute Cross Field first"
done

# The last filter of a script fails: the earlier ones ran and logged, the run still fails.
awk '/<filter name="Field-Coherent Quad Layout: Quadrangulate">/ { q = 1 }
     q && /name="scale"/ { sub(/value="[^"]*"/, "value=\"0\"") } { print }' "$steps" >"$work/late.mlx"
expect_failure late "$work/late.mlx" "Quadrangulate" "'scale' .* is 0"
[ -n "$(log_line "$work/late.log" '^Layout: ')" ] || fail "late: Solve Layout did not run before the failure"

ml_finish meshlab_errors
