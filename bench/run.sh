#!/usr/bin/env bash
# Benchmark driver: runs `fcql layout` on every shared mesh with the paper's α and k where the
# paper gives them (bunny 15/30, fertility 30/30, rockerarm 30/30, dragon 15/10), defaults
# elsewhere, φ = 10°, in the Release build, and writes bench/RESULTS.md.
# Usage: bash bench/run.sh [MESH_NAME ...]   (default: all meshes in ../shared/data/meshes)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
shared="$here/../shared/data/meshes"
fcql="$here/build/bin/fcql"
if [ ! -x "$fcql" ]; then
  bash scripts/build.sh
fi
if [ ! -d "$shared" ]; then
  echo "bench: $shared is absent: nothing to run" >&2
  exit 0
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for f in "$shared"/*.obj; do names+=("$(basename "$f" .obj)"); done
fi

# value FILE SECTION KEY: a number from stats.json ("SECTION": { ... "KEY": value ...}).
value() {
  awk -v sec="\"$2\":" -v key="\"$3\":" '
    $1 == sec { inside = 1; next }
    inside && /^  }/ { inside = 0 }
    inside && $1 == key { v = $2; gsub(/[,"]/, "", v); print v; exit }' "$1"
}

machine="$(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
{
  echo "# Benchmark results"
  echo
  echo "Measured $(date -u +%Y-%m-%d) on: $machine. Release build, \`fcql layout\`, φ = 10°,"
  echo "fields computed by fcql unless the mesh ships one (dragon, eight, lilium: their own field)."
  echo "Times in seconds (wall clock; tracing runs on all cores). Paper: Table 1 of Pietroni et al. 2016,"
  echo "on their machine, with their own fields and, for rockerarm, a 70K-face mesh."
  echo
  echo "| mesh | faces | S | α | k | G nodes | G arcs | H arcs | patches | t-junctions | invalid | field | graph | tracing | ILP | total | peak MiB | paper |G| / patches / t-j / time |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
} > "$out/results.md"

for name in "${names[@]}"; do
  mesh="$shared/$name.obj"
  [ -f "$mesh" ] || { echo "bench: $mesh missing, skipped" >&2; continue; }
  alpha=20 k=10 paper="–"
  case "$name" in
    bunny) alpha=15 k=30 paper="528K / 179 / 0 / 26.3" ;;
    fertility) alpha=30 k=30 paper="492K / 128 / 0 / 22.0" ;;
    rockerarm) alpha=30 k=30 paper="1239K / 75 / 0 / 43.3" ;;
    dragon) alpha=15 k=10 paper="466K / 1024 / 90 / 64.0" ;;
  esac
  field=()
  [ -f "$shared/$name.ffield" ] && field=(--field "$shared/$name.ffield")
  echo "bench: $name (alpha $alpha, k $k)" >&2
  if /usr/bin/time -f "%M" -o "$out/$name.mem" "$fcql" layout "$mesh" "${field[@]}" --alpha "$alpha" --k "$k" --phi 10 \
       --out "$out/$name" --quiet 2>"$out/$name.err"; then
    s="$out/$name/stats.json"
    mem=$(( $(tail -1 "$out/$name.mem") / 1024 ))
    printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %s |\n' \
      "$name" "$(value "$s" mesh faces)" "$(value "$s" field singularities)" "$alpha" "$k" \
      "$(value "$s" graph_g nodes)" "$(value "$s" graph_g arcs)" "$(value "$s" graph_h arcs)" \
      "$(value "$s" layout patches)" "$(value "$s" layout t_junctions)" "$(value "$s" layout invalid_patches)" \
      "$(value "$s" time_s field)" "$(value "$s" time_s graph)" "$(value "$s" time_s tracing)" "$(value "$s" time_s ilp)" \
      "$(value "$s" time_s total)" "$mem" "$paper" >> "$out/results.md"
  else
    echo "| $name | failed: $(tail -1 "$out/$name.err") |" >> "$out/results.md"
  fi
done
cp "$out/results.md" "$here/bench/RESULTS.md"
echo "bench: wrote bench/RESULTS.md" >&2
