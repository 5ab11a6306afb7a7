#!/usr/bin/env bash
# End-to-end tests of `fcql field`: outputs on a generated mesh and on a shared mesh with its
# field, and one clear error line (non-zero exit, no output files) for each kind of bad input.
# Usage: cli_field.sh FCQL SHARED_DIR BUILD_DIR
set -u
fcql=$1 shared=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# json_int FILE KEY: the integer value of "KEY": N in a stats.json (first match).
json_int() { grep -o "\"$2\": *-\?[0-9]*" "$1" | head -1 | grep -o -- '-\?[0-9]*$'; }

# ---- a generated mesh --------------------------------------------------------------------
if "$fcql" field --example rounded_box --out "$tmp/box" --quiet; then
  [ -s "$tmp/box/field.ffield" ] || fail "rounded_box: field.ffield missing"
  [ -s "$tmp/box/stats.json" ] || fail "rounded_box: stats.json missing"
  s=$(json_int "$tmp/box/stats.json" singularities)
  [ "$s" = 8 ] || fail "rounded_box: expected 8 singularities, stats say '$s'"
  grep -q '"1/4": 8' "$tmp/box/stats.json" || fail "rounded_box: by_index is not {1/4: 8}"
  grep -q '"index_sum": "2"' "$tmp/box/stats.json" || fail "rounded_box: index sum is not 2"
  faces=$(json_int "$tmp/box/stats.json" faces)
  lines=$(grep -c '^1 1 ' "$tmp/box/field.ffield")
  [ "$faces" = "$lines" ] || fail "rounded_box: field.ffield has $lines faces, mesh $faces"
  # The written field reads back and gives the same singularities.
  "$fcql" field --example rounded_box --field "$tmp/box/field.ffield" --out "$tmp/box2" --quiet ||
    fail "rounded_box: cannot read back its own field"
  [ "$(json_int "$tmp/box2/stats.json" singularities)" = 8 ] || fail "rounded_box: read-back field changed"
else
  fail "fcql field --example rounded_box exited non-zero"
fi

# ---- a shared mesh with its own field ----------------------------------------------------------
if [ -f "$shared/data/meshes/eight.obj" ]; then
  if "$fcql" field "$shared/data/meshes/eight.obj" --field "$shared/data/meshes/eight.ffield" --out "$tmp/eight" --quiet; then
    [ "$(json_int "$tmp/eight/stats.json" singularities)" = 24 ] || fail "eight: expected 24 singularities"
    grep -q '"-1/4": 16' "$tmp/eight/stats.json" || fail "eight: expected 16 of index -1/4"
    grep -q '"1/4": 8' "$tmp/eight/stats.json" || fail "eight: expected 8 of index 1/4"
    [ "$(json_int "$tmp/eight/stats.json" genus)" = 2 ] || fail "eight: genus is not 2"
    [ "$(json_int "$tmp/eight/stats.json" ports)" = 104 ] || fail "eight: expected 104 ports"
  else
    fail "fcql field on eight.obj exited non-zero"
  fi
else
  echo "skip: $shared/data/meshes is absent, shared-mesh checks skipped"
fi

# ---- bad input: one error line, non-zero exit, no outputs --------------------------------------
# expect_error NAME PATTERN ARGS...: runs fcql ARGS, expects exit != 0, exactly one stderr line
# matching PATTERN, and no stats.json in the output directory.
expect_error() {
  local name=$1 pattern=$2
  shift 2
  local out="$tmp/err_$name"
  "$fcql" "$@" --out "$out" --quiet >"$tmp/stdout" 2>"$tmp/stderr"
  local status=$?
  [ $status -ne 0 ] || fail "$name: exit status 0"
  [ $status -lt 128 ] || fail "$name: crashed (status $status)"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "$name: expected one error line, got: $(cat "$tmp/stderr")"
  grep -qi -- "$pattern" "$tmp/stderr" || fail "$name: message '$(cat "$tmp/stderr")' does not match '$pattern'"
  [ ! -e "$out/stats.json" ] || fail "$name: stats.json was written"
  [ ! -e "$out/field.ffield" ] || fail "$name: field.ffield was written"
}

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 2 3\nf 2 1 4\nf 2 1 5\n' >"$tmp/nonmanifold.obj"
expect_error nonmanifold "non-manifold edge" field "$tmp/nonmanifold.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n' >"$tmp/flipped.obj"
expect_error orientation "inconsistent orientation" field "$tmp/flipped.obj"
: >"$tmp/empty.obj"
expect_error empty_mesh "empty" field "$tmp/empty.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$tmp/badindex.obj"
expect_error bad_index "out of range" field "$tmp/badindex.obj"
expect_error missing_mesh "cannot open" field "$tmp/does_not_exist.obj"
expect_error unknown_format "unsupported mesh format" field "$tmp/mesh.stl"
expect_error unknown_example "rounded_box" field --example teapot

# A valid closed mesh (tetrahedron) for the field-file errors.
printf 'v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n' >"$tmp/tet.obj"
printf 'target frame\n3\n1 1 1 0 0 0 1 0\n1 1 1 0 0 0 1 0\n1 1 1 0 0 0 1 0\n' >"$tmp/short.ffield"
expect_error wrong_face_count "3 faces but the mesh has 4" field "$tmp/tet.obj" --field "$tmp/short.ffield"
printf '4\n4\n1 0 0\n1 0 0\nnan 0 0\n1 0 0\n' >"$tmp/nan.rosy"
expect_error nan_field "not a finite number" field "$tmp/tet.obj" --field "$tmp/nan.rosy"
: >"$tmp/empty.ffield"
expect_error empty_field "empty" field "$tmp/tet.obj" --field "$tmp/empty.ffield"
printf '4\n4\n1 0 0\n1 0 0\n' >"$tmp/truncated.rosy"
expect_error truncated_field "truncated" field "$tmp/tet.obj" --field "$tmp/truncated.rosy"
expect_error sharp_angle_range "sharp-angle must be between 0 and 180" field "$tmp/tet.obj" --sharp-angle 500
expect_error sharp_angle_nan "sharp-angle must be a number" field "$tmp/tet.obj" --sharp-angle abc
expect_error field_scale_range "field-scale must be between 0 and 1" field "$tmp/tet.obj" --field-scale 2
expect_error unknown_option "unknown option --alpah" field "$tmp/tet.obj" --alpah 3

if [ $failures -gt 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all cli_field checks passed"
