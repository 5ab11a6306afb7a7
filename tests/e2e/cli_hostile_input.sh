#!/usr/bin/env bash
# End-to-end tests of the hostile inputs of the adversarial campaigns: each gives exactly one
# `fcql: error:` line, the documented exit status (1 bad input, 2 bad usage), no crash, no
# output left behind, and fails before any work is done (no progress line is printed).
# Usage: cli_hostile_input.sh FCQL SHARED_DIR BUILD_DIR
set -u
fcql=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect STATUS NAME PATTERN ARGS...: runs `fcql ARGS --quiet --out DIR` within 20 s, and
# checks the status, the single line and no output. With early=1, runs without --quiet: then
# any progress line would show, so the one line also proves that no work was done first.
early=0
expect() {
  local want=$1 name=$2 pattern=$3
  shift 3
  local out="$tmp/out_$name" arg
  for arg in "$@"; do [ "$arg" != --out ] || out=""; done
  if [ -n "$out" ]; then set -- "$@" --out "$out"; fi
  if [ $early = 0 ]; then set -- "$@" --quiet; fi
  timeout 20 "$fcql" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local status=$?
  [ $status -eq "$want" ] || fail "$name: exit status $status, expected $want ($(head -c 300 "$tmp/stderr"))"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "$name: expected one line, got: $(head -c 600 "$tmp/stderr")"
  grep -q '^fcql: error: ' "$tmp/stderr" || fail "$name: no 'fcql: error:' line"
  grep -qi -- "$pattern" "$tmp/stderr" || fail "$name: message '$(cat "$tmp/stderr")' does not match '$pattern'"
  [ -z "$out" ] || [ ! -e "$out" ] || fail "$name: $out was created"
}

tet='v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n'
printf "$tet" >"$tmp/tet.obj"

# ---- files that are not regular files ------------------------------------------------------
ln -s /dev/zero "$tmp/zero.obj"
expect 1 device "zero.obj: is not a regular file" field "$tmp/zero.obj"
mkfifo "$tmp/fifo.ply"
expect 1 fifo "fifo.ply: is not a regular file" field "$tmp/fifo.ply"
mkdir "$tmp/dir.off" "$tmp/dir.rosy"
expect 1 mesh_directory "dir.off: is a directory, not a file" field "$tmp/dir.off"
expect 1 field_directory "dir.rosy: is a directory, not a file" field "$tmp/tet.obj" --field "$tmp/dir.rosy"

# ---- PLY files that crashed or corrupted the stack of the former vcglib/plylib reader ---------
head3='ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
faces1='element face 1\nproperty list uchar int vertex_indices\n'
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\nAAAAAAAAAAAAAAAAAAAAAAAA' >"$tmp/huge.ply"
expect 1 ply_huge_count "declares 2000000000 vertices but the file holds at most 2" field "$tmp/huge.ply"
printf 'ply\nformat ascii 1.0\nelement vertex\nend_header\n' >"$tmp/nocount.ply"
expect 1 ply_no_count "line 3: an element line must be" field "$tmp/nocount.ply"
printf "${head3}${faces1}end_header\n0 0 0\n1 0 0\n0 1 0\n5 0 1 2 1 70000\n" >"$tmp/index.ply"
expect 1 ply_polygon_index "face 0 refers to vertex 70000, out of range" field "$tmp/index.ply"
printf "${head3}element vertex 3\nproperty float x\nproperty float y\nproperty float z\n${faces1}end_header\n" >"$tmp/twice.ply"
expect 1 ply_two_vertex_elements "element 'vertex' is declared twice" field "$tmp/twice.ply"
printf "${head3}${faces1}end_header\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n" >"$tmp/short.ply"
expect 1 ply_two_corners "face 0 has 2 corners" field "$tmp/short.ply"
printf 'ply\nformat ascii 1.0\nelement vertex -3\nend_header\n' >"$tmp/negative.ply"
expect 1 ply_negative_count "non-negative integer" field "$tmp/negative.ply"
# A blank header line, a long TextureFile comment and a long unknown binary list: all read.
{
  printf 'ply\nformat binary_little_endian 1.0\ncomment hello\n\ncomment TextureFile %0480d\n' 0
  printf 'element vertex 4\nproperty float x\nproperty float y\nproperty float z\n'
  printf 'element face 4\nproperty list uchar int vertex_indices\nproperty list uchar int junk\nend_header\n'
  python3 - <<'EOF'
import struct, sys
v = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
f = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
out = b"".join(struct.pack("<fff", *p) for p in v)
for c in f:
    out += struct.pack("<Biii", 3, *c) + struct.pack("<B", 255) + struct.pack("<i", 0x41414141) * 255
sys.stdout.buffer.write(out)
EOF
} >"$tmp/odd.ply"
"$fcql" field "$tmp/odd.ply" --out "$tmp/odd" --quiet 2>"$tmp/stderr" || fail "odd.ply: $(cat "$tmp/stderr")"

# ---- fields that give no direction ---------------------------------------------------------------
# Per-face normals of the tetrahedron (its faces, in order), then the same plus a tiny tangent.
printf '4\n4\n1 1 -1\n1 -1 1\n-1 1 1\n-1 -1 -1\n' >"$tmp/normal.rosy"
expect 1 field_along_normal "vector of face 0 is more than 60 degrees out of the face's plane" \
  field "$tmp/tet.obj" --field "$tmp/normal.rosy"
printf '4\n4\n1 1 -0.98\n1 -1 1\n-1 1 1\n-1 -1 -1\n' >"$tmp/nearly.rosy"
expect 1 field_nearly_normal "vector of face 0 is more than 60 degrees" field "$tmp/tet.obj" --field "$tmp/nearly.rosy"
# Huge components are no overflow: tangent vectors of 1e300 are read (edge directions).
printf '4\n4\n0 -2e300 -2e300\n-2e300 -2e300 0\n-2e300 0 -2e300\n-2e300 0 2e300\n' >"$tmp/huge.rosy"
"$fcql" field "$tmp/tet.obj" --field "$tmp/huge.rosy" --out "$tmp/hugefield" --quiet 2>"$tmp/stderr" ||
  fail "huge tangent components: $(cat "$tmp/stderr")"
printf '4\n4\n1e300 1e300 -1e300\n1 -1 1\n-1 1 1\n-1 -1 -1\n' >"$tmp/hugenormal.rosy"
expect 1 field_huge_normal "more than 60 degrees out of the face's plane" field "$tmp/tet.obj" --field "$tmp/hugenormal.rosy"

# ---- coordinates out of range ------------------------------------------------------------------
printf 'v 1e-100 1e-100 1e-100\nv 1e-100 -1e-100 -1e-100\nv -1e-100 1e-100 -1e-100\nv -1e-100 -1e-100 1e-100\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n' >"$tmp/tiny.obj"
expect 1 tiny_mesh "coordinates are out of the supported range: the mesh spans 2e-100 units" field "$tmp/tiny.obj"
printf 'v 1e300 1e300 1e300\nv 1e300 -1e300 -1e300\nv -1e300 1e300 -1e300\nv -1e300 -1e300 1e300\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n' >"$tmp/vast.obj"
expect 1 vast_mesh "out of the supported range.*reaches out to 1e+300" field "$tmp/vast.obj"

# ---- the other classes of bad meshes ------------------------------------------------------------
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n' >"$tmp/index0.obj"
expect 1 zero_index "bad vertex reference '0'" field "$tmp/index0.obj"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n' >"$tmp/negative.off"
expect 1 negative_index "bad vertex index '-2'" field "$tmp/negative.off"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n' >"$tmp/collinear.obj"
expect 1 degenerate_face "face 0 is degenerate" field "$tmp/collinear.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 2 3 1\n' >"$tmp/duplicated.obj"
expect 1 duplicated_face "faces 0 and 1 are the same triangle" field "$tmp/duplicated.obj"
printf 'v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n' >"$tmp/inf.obj"
expect 1 infinite_coordinate "coordinate 'inf' is not finite" field "$tmp/inf.obj"
python3 - "$tmp/mobius.obj" <<'PY'
import math, sys
n, w, v, f = 12, 0.3, [], []
for i in range(n):
    t = 2 * math.pi * i / n
    for s in (-w, w):
        v.append(((1 + s * math.cos(t / 2)) * math.cos(t), (1 + s * math.cos(t / 2)) * math.sin(t), s * math.sin(t / 2)))
for i in range(n):
    a, b = 2 * i, 2 * i + 1
    c, d = (2 * i + 2, 2 * i + 3) if i < n - 1 else (1, 0)  # the half twist
    f += [(a, b, d), (a, d, c)]
open(sys.argv[1], "w").write("".join("v %f %f %f\n" % p for p in v) + "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in f))
PY
expect 1 moebius "non-orientable surface" field "$tmp/mobius.obj"
# Accepted: a single triangle (one disk, quads of its genus and border), isolated vertices (kept
# apart, unused), an output folder whose name holds spaces.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n' >"$tmp/triangle.obj"
"$fcql" run "$tmp/triangle.obj" --out "$tmp/with spaces/triangle" --quiet 2>"$tmp/stderr" || fail "a single triangle with an isolated vertex: $(cat "$tmp/stderr")"
[ -s "$tmp/with spaces/triangle/quad.obj" ] && ! grep -q '^f [0-9]* [0-9]* [0-9]*$' "$tmp/with spaces/triangle/quad.obj" ||
  fail "a single triangle: no pure-quad quad.obj in a folder whose name holds spaces"

# ---- options that used to fail only after the whole run (or ran out of memory) ----------------
touch "$tmp/a_file"
early=1
expect 2 out_empty "--out needs a directory name" run "$tmp/tet.obj" --out ""
expect 2 out_is_file "a_file: is a file, not a directory" run "$tmp/tet.obj" --out "$tmp/a_file"
expect 2 out_under_file "is a file, not a directory" run "$tmp/tet.obj" --out "$tmp/a_file/sub"
expect 2 bogus_example "unknown --example 'bogus'" run --example bogus
expect 2 too_many_quads "asks for about .* quads on this surface, more than the limit" run --example sphere --scale 1e-5
expect 2 too_many_target_faces "target-faces must be between 0 and 20000000" run --example sphere --target-faces 100000000

if [ $failures -gt 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all cli_hostile_input checks passed"
