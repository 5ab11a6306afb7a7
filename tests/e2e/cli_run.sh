#!/usr/bin/env bash
# End-to-end tests of `fcql run` (the whole pipeline down to quad.obj): the quad mesh is pure
# quads with valid indices and agrees with stats.json, the resolution options scale the face
# count, the quality figures are there and sane, and bad options give one clear error line.
# Usage: cli_run.sh FCQL SHARED_DIR BUILD_DIR
set -u
fcql=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# quad_value FILE KEY: the value of "KEY" inside the "quad" section of a stats.json.
quad_value() { sed -n '/^  "quad": {/,/^  }/p' "$1" | grep -o "\"$2\": *[-0-9.e+a-z]*" | head -1 | sed 's/.*: *//'; }

# check_quads DIR: quad.obj holds only v and 4-index f lines, indices in range, as many faces
# as stats.json says.
check_quads() {
  local d=$1
  [ -s "$d/quad.obj" ] || { fail "$d: quad.obj missing"; return; }
  local bad
  bad=$(awk '/^(#|$)/ {next} $1=="v" {nv++; next}
             $1=="f" { if (NF != 5) {print "a face with " NF-1 " vertices"; exit}
                       for (i = 2; i <= 5; i++) if ($i < 1 || $i > nv) {print "index " $i " out of range"; exit}
                       nf++; next }
             {print "unexpected line: " $0; exit}
             END {if (nf == 0) print "no faces"}' "$d/quad.obj")
  [ -z "$bad" ] || fail "$d/quad.obj: $bad"
  local faces
  faces=$(grep -c '^f ' "$d/quad.obj")
  [ "$faces" = "$(quad_value "$d/stats.json" faces)" ] || fail "$d: quad.obj has $faces faces, stats.json says $(quad_value "$d/stats.json" faces)"
}

# ---- the rounded box at two resolutions --------------------------------------------------------
if "$fcql" run --example rounded_box --out "$tmp/box" --quiet && "$fcql" run --example rounded_box --scale 0.04 --out "$tmp/coarse" --quiet; then
  check_quads "$tmp/box"
  check_quads "$tmp/coarse"
  s="$tmp/box/stats.json"
  [ "$(quad_value "$s" manifold)" = true ] || fail "rounded_box: quad mesh not manifold"
  [ "$(quad_value "$s" genus)" = 0 ] || fail "rounded_box: quad mesh genus $(quad_value "$s" genus)"
  [ "$(quad_value "$s" irregular_vertices)" = 8 ] || fail "rounded_box: expected 8 irregular vertices"
  [ "$(quad_value "$s" inverted_quads)" = 0 ] || fail "rounded_box: inverted quads"
  awk -v h="$(quad_value "$s" hausdorff_rel)" 'BEGIN {exit !(h > 0 && h < 0.01)}' || fail "rounded_box: Hausdorff $(quad_value "$s" hausdorff_rel) not in (0, 1%)"
  awk -v m="$(quad_value "$s" misaligned_pct)" 'BEGIN {exit !(m >= 0 && m < 5)}' || fail "rounded_box: $(quad_value "$s" misaligned_pct)% misaligned quads"
  awk -v j="$(quad_value "$s" min_scaled_jacobian)" 'BEGIN {exit !(j > 0.3 && j <= 1)}' || fail "rounded_box: min scaled Jacobian $(quad_value "$s" min_scaled_jacobian)"
  fine=$(quad_value "$s" faces) coarse=$(quad_value "$tmp/coarse/stats.json" faces)
  awk -v f="$fine" -v c="$coarse" 'BEGIN {r = f / c; exit !(r > 3 && r < 5.5)}' || fail "halving the edge length gave $fine vs $coarse quads"
  [ "$(quad_value "$tmp/coarse/stats.json" irregular_vertices)" = 8 ] || fail "coarse rounded box: irregular vertices changed"
else
  fail "fcql run --example rounded_box exited non-zero"
fi

# ---- --max-deviation that cannot be met: exit 1, a clear error, nothing written ---------------------
if "$fcql" run --example rounded_box --scale 0.3 --max-deviation 0.00001 --out "$tmp/unmet" 2>"$tmp/unmet.err"; then
  fail "--max-deviation 0.00001 at --scale 0.3 exited 0"
else
  grep -q "above the bound of 0.001%" "$tmp/unmet.err" || fail "unmet bound: no clear error ($(tail -1 "$tmp/unmet.err"))"
  [ ! -e "$tmp/unmet" ] || fail "unmet bound: $tmp/unmet was written"
fi

# ---- --max-deviation: quads far coarser than the rounded edges are refined, unless disabled --------
if "$fcql" run --example rounded_box --scale 0.3 --out "$tmp/refined" --quiet &&
   "$fcql" run --example rounded_box --scale 0.3 --max-deviation 0 --out "$tmp/unrefined" --quiet; then
  r="$tmp/refined/stats.json" u="$tmp/unrefined/stats.json"
  check_quads "$tmp/refined"
  [ "$(quad_value "$u" refinements)" = 0 ] || fail "--max-deviation 0: $(quad_value "$u" refinements) refinements"
  awk -v h="$(quad_value "$u" hausdorff_rel)" 'BEGIN {exit !(h > 0.01)}' ||
    fail "--scale 0.3 unrefined is already within 1% ($(quad_value "$u" hausdorff_rel)): pick a coarser scale"
  awk -v n="$(quad_value "$r" refinements)" 'BEGIN {exit !(n >= 1)}' || fail "--scale 0.3: not refined"
  awk -v h="$(quad_value "$r" hausdorff_rel)" 'BEGIN {exit !(h > 0 && h < 0.01)}' ||
    fail "--scale 0.3 refined: Hausdorff $(quad_value "$r" hausdorff_rel) not below 1%"
  awk -v a="$(quad_value "$r" faces)" -v b="$(quad_value "$u" faces)" 'BEGIN {exit !(a > b)}' ||
    fail "refining did not add quads ($(quad_value "$r" faces) vs $(quad_value "$u" faces))"
else
  fail "fcql run --example rounded_box --scale 0.3 exited non-zero"
fi

# ---- --target-faces ---------------------------------------------------------------------------
if "$fcql" run --example torus --target-faces 1500 --out "$tmp/torus" --quiet; then
  check_quads "$tmp/torus"
  n=$(quad_value "$tmp/torus/stats.json" faces)
  [ "$n" -ge 750 ] && [ "$n" -le 3000 ] || fail "torus --target-faces 1500 gave $n quads"
  [ "$(quad_value "$tmp/torus/stats.json" genus)" = 1 ] || fail "torus: quad mesh genus is not 1"
else
  fail "fcql run --example torus --target-faces 1500 exited non-zero"
fi

# ---- the same result on any machine: 1, 2 or 8 threads, and both cores kept busy ------------------
# Every budget that can change a result is counted in work (nodes, rounds), not seconds.
for t in 1 2 8; do
  "$fcql" run --example double_torus --threads $t --out "$tmp/threads$t" --quiet || fail "double_torus --threads $t failed"
done
busy=()
for i in 1 2; do timeout 120 sh -c 'while :; do :; done' & busy+=($!); done
"$fcql" run --example double_torus --threads 2 --out "$tmp/busy" --quiet || fail "double_torus on a busy machine failed"
kill "${busy[@]}" 2>/dev/null
for dir in threads2 threads8 busy; do
  for f in quad.obj separatrices.obj candidates.obj layout.ply field.ffield; do
    cmp -s "$tmp/threads1/$f" "$tmp/$dir/$f" || fail "double_torus: $f differs between --threads 1 and $dir"
  done
done

# ---- bad options: one error line, non-zero exit, no output directory ------------------------------
expect_error() {  # WHAT ARGS...
  local what=$1
  shift
  local out="$tmp/bad"
  rm -rf "$out"
  if "$fcql" run --example rounded_box "$@" --out "$out" --quiet 2>"$tmp/err"; then
    fail "$what: exited 0"
  fi
  [ "$(wc -l < "$tmp/err")" = 1 ] || fail "$what: expected one error line, got: $(cat "$tmp/err")"
  grep -q '^fcql: error: ' "$tmp/err" || fail "$what: no 'fcql: error:' line: $(cat "$tmp/err")"
  [ ! -e "$out" ] || fail "$what: left $out behind"
}
expect_error "--scale 0" --scale 0
expect_error "--scale 2" --scale 2
expect_error "--scale and --target-faces" --scale 0.02 --target-faces 100
expect_error "--target-faces -1" --target-faces -1
expect_error "--smooth -1" --smooth -1
expect_error "--max-deviation -0.1" --max-deviation -0.1
expect_error "--max-deviation 2" --max-deviation 2
expect_error "--smooth abc" --smooth abc

if [ "$failures" -gt 0 ]; then
  echo "cli_run: $failures failures"
  exit 1
fi
echo "cli_run: all checks passed"
