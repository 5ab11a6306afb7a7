#!/usr/bin/env bash
# The one figures record (vcg_ext/pipeline/figures.h) through the three front ends: for the
# same mesh and the default parameters, `fcql run`'s stats.json, the "Figures: {...}" line that
# meshlabserver's All Steps logs (MeshLab 2020.09, examples/all_steps.mlx) and the dict the
# pymeshlab host returns for compute_field_coherent_quad_layout (MeshLab 2025.07) hold the
# same keys with the same values, key by key (reals to the 6 digits stats.json keeps; times and
# the input's name aside), on two meshes: fcql's double torus cut along its layout, and the
# shared eight (or, without the shared folder, a 6×6×6 cube). The meshes went through MeshLab
# once, so all three read the same single-precision coordinates.
#
# Usage: figures_agree.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/pymeshlab_host.bash
source "$here/lib/pymeshlab_host.bash"
[ -x "$fcql" ] || skip "fcql is not built"
pm_require_host "$build"
ml_setup "$build" figures_agree
pm_host_dirs
all=$(example_script all_steps) || ml_finish figures_agree
ml_prepare_meshes "$fcql" "$shared"

# compare NAME: the three records of NAME agree (python3: JSON and the host's dict literal).
compare() {
  PYTHONPATH="$here/lib" python3 - "$work/$1/cli/stats.json" "$work/$1/server.log" "$work/$1/host.out" "$1" <<'PY'
import ast, json, sys
from figures import compared_keys, differences, flat
stats_path, server_log, host_out, name = sys.argv[1:]
cli = flat(json.load(open(stats_path)))
lines = [l.split("Figures: ", 1)[1] for l in open(server_log, errors="replace") if "Figures: {" in l]
server = flat(json.loads(lines[-1])) if lines else {}
text = [l.split(" -> ", 1)[1] for l in open(host_out, errors="replace")
        if l.startswith("compute_field_coherent_quad_layout -> ")]
host = ast.literal_eval(text[0]) if text else {}
bad = []
for other, record in (("meshlabserver", server), ("pymeshlab host", host)):
    bad += differences(cli, record, ("fcql run", other)) if record else ["%s gave no figures" % other]
if bad:
    print("FAIL: %s: %d differences:\n    %s" % (name, len(bad), "\n    ".join(bad)))
    sys.exit(1)
print("%s: %d figures agree in all three (layout.patches %s, quad.faces %s)"
      % (name, len(compared_keys(cli, {})), cli.get("layout.patches"), cli.get("quad.faces")))
PY
}

checked=0
for i in "${!mesh_names[@]}"; do
  name=${mesh_names[$i]}
  input=${mesh_files[$i]}
  [ "$name" = cube ] && [ ${#mesh_names[@]} -gt 2 ] && continue  # two meshes: dtorus and eight
  mkdir -p "$work/$name"
  if ! "$fcql" run "$input" --out "$work/$name/cli" --quiet >"$work/$name/cli.log" 2>&1; then
    fail "$name: fcql run failed: $(tail -1 "$work/$name/cli.log")"; continue
  fi
  if ! run_server "$work/$name/server.log" -i "$input" -s "$all"; then
    fail "$name: meshlabserver exited with $?"; tail -5 "$work/$name/server.log" | sed 's/^/    /'; continue
  fi
  if ! host "$work/$name/host.out" load "$input" apply compute_field_coherent_quad_layout; then
    fail "$name: the pymeshlab host failed"; tail -5 "$work/$name/host.out" | sed 's/^/    /'; continue
  fi
  if compare "$name"; then checked=$((checked + 1)); else failures=$((failures + 1)); fi
done
[ $checked -ge 2 ] || [ $failures -gt 0 ] || fail "only $checked meshes compared"
ml_finish figures_agree
