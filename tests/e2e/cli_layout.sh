#!/usr/bin/env bash
# End-to-end tests of `fcql trace` and `fcql layout`: outputs and their consistency on
# generated meshes and a shared mesh, and clear errors for bad parameters.
# Usage: cli_layout.sh FCQL SHARED_DIR BUILD_DIR
set -u
fcql=$1 shared=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
json_int() { grep -o "\"$2\": *-\?[0-9]*" "$1" | head -1 | grep -o -- '-\?[0-9]*$'; }

# ---- trace on the rounded box: 24 ports, candidates as polylines ------------------------------
if "$fcql" trace --example rounded_box --out "$tmp/trace" --quiet; then
  s="$tmp/trace/stats.json"
  [ "$(json_int "$s" ports)" = 24 ] || fail "rounded_box: expected 24 ports in graph G"
  arcs=$(json_int "$s" arcs)  # graph_g.arcs comes first
  [ "${arcs:-0}" -gt 0 ] || fail "rounded_box: graph G has no arcs"
  h=$(grep -A3 '"graph_h"' "$s" | json_int /dev/stdin arcs)
  lines=$(grep -c '^l ' "$tmp/trace/candidates.obj")
  [ "$h" = "$lines" ] || fail "rounded_box: candidates.obj has $lines polylines, stats say $h H arcs"
  [ "$lines" -ge 12 ] || fail "rounded_box: fewer than 12 candidates"
  pairs=$(json_int "$s" tangential_pairs)
  cliques=$(json_int "$s" tangential_cliques)
  [ -n "$cliques" ] || fail "rounded_box: stats.json has no graph_h.tangential_cliques"
  if [ "${pairs:-0}" -gt 0 ]; then
    [ "${cliques:-0}" -gt 0 ] || fail "rounded_box: $pairs tangential pairs but no clique holds them"
  fi
else
  fail "fcql trace --example rounded_box exited non-zero"
fi

# ---- layout on generated meshes --------------------------------------------------------------
check_layout() {  # NAME DIR EXPECTED_PATCHES(or -)
  local s="$2/stats.json"
  [ -s "$2/layout.ply" ] || fail "$1: layout.ply missing"
  [ -s "$2/separatrices.obj" ] || fail "$1: separatrices.obj missing"
  local patches invalid seps lines
  patches=$(grep -A3 '"layout"' "$s" | json_int /dev/stdin patches)
  invalid=$(json_int "$s" invalid_patches)
  seps=$(grep -A2 '"layout"' "$s" | json_int /dev/stdin separatrices)
  lines=$(grep -c '^l ' "$2/separatrices.obj")
  [ "$invalid" = 0 ] || fail "$1: $invalid invalid patches"
  [ "$seps" = "$lines" ] || fail "$1: separatrices.obj has $lines polylines, stats say $seps"
  [ "$3" = - ] || [ "$patches" = "$3" ] || fail "$1: expected $3 patches, got $patches"
  # layout.ply: as many distinct patch ids on faces as patches.
  local faces ids
  faces=$(grep -m1 '^element face' "$2/layout.ply" | awk '{print $3}')
  ids=$(awk '/^end_header/ {body = 1; next} body && NF == 8 {print $5}' "$2/layout.ply" | sort -u | wc -l)
  [ "$ids" = "$patches" ] || fail "$1: layout.ply has $ids patch ids for $patches patches"
  [ "$faces" -gt 0 ] || fail "$1: layout.ply has no faces"
}
for ex in rounded_box:6 open_cylinder:1 torus:1 double_torus:-; do
  name=${ex%%:*} expected=${ex##*:}
  if "$fcql" layout --example "$name" --out "$tmp/$name" --quiet; then
    check_layout "$name" "$tmp/$name" "$expected"
  else
    fail "fcql layout --example $name exited non-zero"
  fi
done

if [ -f "$shared/data/meshes/eight.obj" ]; then
  if "$fcql" layout "$shared/data/meshes/eight.obj" --field "$shared/data/meshes/eight.ffield" --out "$tmp/eight" --quiet; then
    check_layout eight "$tmp/eight" -
  else
    fail "fcql layout on eight exited non-zero"
  fi
  # --quiet keeps the warnings: the lilium (open, its own field) leaves ports dangling.
  if "$fcql" layout "$shared/data/meshes/lilium.obj" --field "$shared/data/meshes/lilium.ffield" \
    --out "$tmp/lilium" --quiet 2>"$tmp/lilium.err"; then
    grep -q '^fcql: warning: .*ports could not be connected' "$tmp/lilium.err" ||
      fail "lilium --quiet: no warning about its dangling ports: $(head -c 300 "$tmp/lilium.err")"
    ! grep -qv '^fcql: warning: ' "$tmp/lilium.err" || fail "lilium --quiet: lines other than warnings: $(head -c 300 "$tmp/lilium.err")"
  else
    fail "fcql layout on lilium exited non-zero"
  fi
else
  echo "skip: $shared/data/meshes is absent, shared-mesh checks skipped"
fi

# ---- bad parameters: one error line, exit 2, nothing written ---------------------------------
expect_usage_error() {
  local name=$1 pattern=$2
  shift 2
  "$fcql" "$@" --out "$tmp/err_$name" --quiet >/dev/null 2>"$tmp/stderr"
  local status=$?
  [ $status -eq 2 ] || fail "$name: exit status $status, expected 2"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "$name: expected one error line, got: $(cat "$tmp/stderr")"
  grep -q -- "$pattern" "$tmp/stderr" || fail "$name: message '$(cat "$tmp/stderr")' lacks '$pattern'"
  [ ! -e "$tmp/err_$name/stats.json" ] || fail "$name: stats.json written"
}
expect_usage_error alpha "alpha must be between 0" trace --example sphere --alpha -1
expect_usage_error k "k must be between 1" trace --example sphere --k 0
expect_usage_error phi_low "phi must be between 1 and 45" trace --example sphere --phi 0.5
expect_usage_error phi_high "phi must be between 1 and 45" layout --example sphere --phi 50
expect_usage_error k_text "k must be an integer" layout --example sphere --k ten
expect_usage_error ilp "ilp-time-limit must be between 1" layout --example sphere --ilp-time-limit 0
expect_usage_error ilp_stall "ilp-stall must be between 0" layout --example sphere --ilp-stall -1
"$fcql" layout --example sphere --quiet 2>"$tmp/stderr"
[ $? -eq 2 ] && grep -q "missing --out DIR" "$tmp/stderr" || fail "no --out: $(cat "$tmp/stderr")"

if [ $failures -gt 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all cli_layout checks passed"
