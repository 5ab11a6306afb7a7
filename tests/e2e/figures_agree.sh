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
host_bin="$build/bin/fcql_pymeshlab_host"
plugin2025="$build/lib/meshlab-2025.07/libfilter_fieldquadlayout2025.so"
[ -x "$host_bin" ] && [ -f "$plugin2025" ] || skip "the pymeshlab host is not built (FCQL_BUILD_PLUGIN_2025=OFF)"
ml_setup "$build" figures_agree
all=$(example_script all_steps) || ml_finish figures_agree
ml_prepare_meshes "$fcql" "$shared"

# compare NAME: the three records of NAME agree (python3: JSON and the host's dict literal).
compare() {
  python3 - "$work/$1/cli/stats.json" "$work/$1/server.log" "$work/$1/host.out" "$1" <<'PY'
import ast, json, sys
stats_path, server_log, host_out, name = sys.argv[1:]

# A computed field agrees between processes to rounding only (the CLI and MeshLab's process
# give the sparse solves the same input but not bit for bit the same output), and the quality
# measures below look up the field per face at each quad's centre: a quad whose centre moves
# across a face edge by rounding changes them by a step. They are compared to within that; every
# count, flag, text and other real exactly (to the 6 digits stats.json keeps).
ROUNDING_SENSITIVE = {"quad.mean_misalignment_deg": 0.01, "quad.misaligned_pct": 0.1,
                      "quad.misaligned_faces_pct": 0.1, "quad.hausdorff_bound_rel": 1e-6,
                      "quad.hausdorff_rel": 1e-6, "quad.hausdorff": 1e-5}

def flat(tree, prefix=""):
    out = {}
    for key, value in tree.items():
        if isinstance(value, dict) and value:
            out.update(flat(value, prefix + key + "."))
        elif not isinstance(value, dict):
            out[prefix + key] = value
    return out

cli = flat(json.load(open(stats_path)))
lines = [l.split("Figures: ", 1)[1] for l in open(server_log, errors="replace") if "Figures: {" in l]
server = json.loads(lines[-1]) if lines else {}
text = [l.split(" -> ", 1)[1] for l in open(host_out, errors="replace")
        if l.startswith("compute_field_coherent_quad_layout -> ")]
host = ast.literal_eval(text[0]) if text else {}
records = {"fcql run": cli, "meshlabserver": server, "pymeshlab host": host}
bad = []
for other in ("meshlabserver", "pymeshlab host"):
    if not records[other]:
        bad.append("%s gave no figures" % other)
        continue
    for k in sorted(set(cli) | set(records[other])):
        if k.startswith(("time_s.", "input.")):
            continue
        a, b = cli.get(k), records[other].get(k)
        if k in ROUNDING_SENSITIVE:
            same = a is not None and b is not None and abs(a - b) <= ROUNDING_SENSITIVE[k]
        elif isinstance(a, float) or isinstance(b, float):
            same = a is not None and b is not None and abs(a - b) <= 1e-5 * max(abs(a), abs(b), 1e-12)
        else:
            same = a == b
        if not same:
            bad.append("%s: fcql run %r, %s %r" % (k, a, other, b))
compared = len([k for k in cli if not k.startswith(("time_s.", "input."))])
if bad:
    print("FAIL: %s: %d differences:\n    %s" % (name, len(bad), "\n    ".join(bad)))
    sys.exit(1)
print("%s: %d figures agree in all three (layout.patches %s, quad.faces %s)"
      % (name, compared, cli.get("layout.patches"), cli.get("quad.faces")))
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
