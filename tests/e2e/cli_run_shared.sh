#!/usr/bin/env bash
# End-to-end test of `fcql run` on every shared mesh (bench parameters: the paper's alpha and
# k where it gives them, the mesh's own field where it ships one), at the default quad size
# and at half of it (--scale 0.01): every run exits 0, its quad mesh is within --max-deviation
# (1%) by the upper bound the stage decides with, and no quad is folded (scaled Jacobian <= 0,
# at any corner, against the quad's own normal or the surface normal there).
# Known exceptions are listed below with the number of folded quads they had when this test
# was written: they fail the test if they get worse, and should go to 0.
# Usage: cli_run_shared.sh FCQL SHARED_DIR BUILD_DIR (skipped without SHARED_DIR/data/meshes)
set -u
fcql=$1 shared=${2:-}
meshes="$shared/data/meshes"
if [ ! -d "$meshes" ]; then
  echo "skip: $meshes is absent, shared-mesh runs skipped"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
quad_value() { sed -n '/^  "quad": {/,/^  }/p' "$1" | grep -o "\"$2\": *[-0-9.e+a-z]*" | head -1 | sed 's/.*: *//'; }

# Folded quads still left (issue 21): MESH@SCALE=COUNT. Everything else must have none. The
# dragon's count varies from run to run (39-81 at 0.02: its side-length parts stop at their
# time limits), hence its margin. Fandisk's came with the conforming layout (issue 20): at a
# corner where three creases meet, a thin patch beside a separatrix the completion re-routed
# is sampled as one row of quads twisted across the corner (its two long sides cross); the
# field-aligned maps and the untangling that slides vertices along creases leave 0 at 0.02.
# Deckel's are in one patch whose map folds (outside_points). Camelhead, joint and rockerarm
# have none since the conforming layouts and the field-aligned maps.
known_folds="dragon@0.02=90 deckel@0.01=7 dragon@0.01=110 fandisk@0.01=1"

# Runs that may fail in the zero-chain rounds (their side-length parts stop at time limits, so
# the counts differ from run to run; it happened before this test's changes as well):
# MESH@SCALE. Such a failure is reported, not counted; any other failure counts.
known_zero_chain_failures="dragon@0.01"

for scale in 0.02 0.01; do
  for obj in "$meshes"/*.obj; do
    name=$(basename "$obj" .obj)
    alpha=20 k=10
    case "$name" in
      bunny) alpha=15 k=30 ;;
      fertility | rockerarm) alpha=30 k=30 ;;
      dragon) alpha=15 k=10 ;;
    esac
    field=()
    [ -f "$meshes/$name.ffield" ] && field=(--field "$meshes/$name.ffield")
    out="$tmp/$name-$scale"
    if ! "$fcql" run "$obj" "${field[@]}" --alpha "$alpha" --k "$k" --scale "$scale" --out "$out" --quiet 2>"$out.err"; then
      if [[ " $known_zero_chain_failures " == *" $name@$scale "* ]] && grep -q "rounds of zero-chain splits" "$out.err"; then
        echo "known: $name at --scale $scale failed in the zero-chain rounds: $(tail -1 "$out.err")"
      else
        fail "$name at --scale $scale: exit non-zero: $(tail -1 "$out.err")"
      fi
      continue
    fi
    s="$out/stats.json"
    bound=$(quad_value "$s" hausdorff_bound_rel)
    awk -v b="$bound" 'BEGIN {exit !(b > 0 && b <= 0.01)}' || fail "$name at --scale $scale: distance bound $bound above 1%"
    folded=$(quad_value "$s" inverted_quads)
    allowed=0
    for entry in $known_folds; do
      [ "${entry%%=*}" = "$name@$scale" ] && allowed=${entry#*=}
    done
    if [ "$folded" -gt "$allowed" ]; then
      fail "$name at --scale $scale: $folded folded quads (allowed $allowed), min scaled Jacobian $(quad_value "$s" min_scaled_jacobian)"
    fi
    echo "$name at --scale $scale: $folded folded quads, min scaled Jacobian $(quad_value "$s" min_scaled_jacobian), bound $bound"
  done
done

if [ $failures -gt 0 ]; then
  echo "cli_run_shared: $failures failure(s)"
  exit 1
fi
echo "cli_run_shared: all checks passed"
