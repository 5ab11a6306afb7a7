#!/usr/bin/env bash
# Scale series: one shape at about 28K, 112K, 447K and 1.8M faces (fertility.obj and its Loop
# subdivisions, bench/subdivide.py), each run through the whole pipeline (`fcql run`, default
# parameters) in the Release build. Prints a Markdown table with the time of every stage
# (time_s.* of stats.json), the whole run's wall time and its peak resident memory (GNU time),
# the sizes of graph G and the quad mesh, or the error line of a run that stopped.
#
# Usage: bash bench/scale.sh [LEVELS...]      (default: 0 1 2 3; level L has 4^L × 28K faces)
#   FCQL=path/to/fcql picks the tool (default build/bin/fcql); SCALE_DIR=DIR keeps the meshes
#   and outputs there (default: a temporary folder); SCALE_TIMEOUT=S stops a run after S seconds.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
fcql="${FCQL:-$here/build/bin/fcql}"
mesh="$here/../shared/data/meshes/fertility.obj"
[ -f "$mesh" ] || { echo "scale: $mesh is absent: nothing to run" >&2; exit 0; }
[ -x "$fcql" ] || { echo "scale: $fcql is not built (bash scripts/build.sh)" >&2; exit 1; }
levels=("$@")
[ ${#levels[@]} -gt 0 ] || levels=(0 1 2 3)
if [ -n "${SCALE_DIR:-}" ]; then
  work=$SCALE_DIR
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
limit=${SCALE_TIMEOUT:-3600}

value() {  # value STATS SECTION KEY
  python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print(s.get(sys.argv[2], {}).get(sys.argv[3], ''))" "$@"
}
seconds() { python3 -c "print('%.2f' % float('$1'))" 2>/dev/null || echo "$1"; }

echo "| faces | G nodes | field | graph | tracing | ILP | propagation | cut | quad | metrics | total | wall | peak MiB | quads |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for level in "${levels[@]}"; do
  input="$work/fertility_$level.obj"
  if [ ! -f "$input" ]; then
    if [ "$level" = 0 ]; then cp "$mesh" "$input"; else python3 "$here/bench/subdivide.py" "$mesh" "$level" "$input"; fi
  fi
  out="$work/run_$level"
  rm -rf "$out"
  if timeout "$limit" /usr/bin/time -f '%e %M' -o "$work/time_$level" "$fcql" run "$input" --out "$out" --quiet \
       2>"$work/err_$level"; then
    read -r wall kb <"$work/time_$level"
    s="$out/stats.json"
    row="| $(value "$s" mesh faces) | $(value "$s" graph_g nodes)"
    for key in field graph tracing ilp propagation cut quadrangulation metrics total; do
      row+=" | $(seconds "$(value "$s" time_s "$key")")"
    done
    echo "$row | $wall | $((kb / 1024)) | $(value "$s" quad faces) |"
  else
    echo "| level $level | stopped: $(tail -1 "$work/err_$level" | cut -c1-200) |||||||||||||"
  fi
done
