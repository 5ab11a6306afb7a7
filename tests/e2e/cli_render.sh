#!/usr/bin/env bash
# End-to-end tests of `fcql render`: pictures of the rounded box run (layout, quad, both) are
# valid PNGs of the asked size (signature, IHDR, every chunk CRC, zlib data, row filters) and
# show something (several colours, a uniform background border, the object covering a fair
# part); bad input gets one `fcql: error:` line, a non-zero exit and no picture.
# Usage: cli_render.sh FCQL SHARED_DIR BUILD_DIR
set -u
fcql=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
python=$(command -v python3 || true)
if [ -z "$python" ]; then echo "skip: python3 is needed to decode the pictures"; exit 77; fi

# check_png FILE WIDTH HEIGHT MIN_COLOURS: prints nothing if fine, else the problems.
check_png() {
  "$python" - "$@" <<'PY'
import struct, sys, zlib
path, width, height, min_colours = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
data = open(path, 'rb').read()
problems = []
if data[:8] != b'\x89PNG\r\n\x1a\n':
    print('bad PNG signature'); sys.exit()
at, chunks = 8, []
while at + 12 <= len(data):
    n, kind = struct.unpack('>I4s', data[at:at + 8])
    body = data[at + 8:at + 8 + n]
    crc, = struct.unpack('>I', data[at + 8 + n:at + 12 + n])
    if zlib.crc32(kind + body) & 0xffffffff != crc:
        problems.append('CRC mismatch in %s' % kind.decode())
    chunks.append((kind, body))
    at += 12 + n
kinds = [k for k, _ in chunks]
if not kinds or kinds[0] != b'IHDR' or kinds[-1] != b'IEND' or at != len(data):
    print('bad chunk sequence %s' % kinds); sys.exit()
w, h, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', chunks[0][1])
if (w, h) != (width, height): problems.append('size %dx%d, expected %dx%d' % (w, h, width, height))
if (depth, colour, interlace) != (8, 2, 0): problems.append('not 8-bit RGB non-interlaced')
try:
    raw = zlib.decompress(b''.join(b for k, b in chunks if k == b'IDAT'))
except zlib.error as e:
    print('; '.join(problems + ['bad compressed data: %s' % e])); sys.exit()
stride = 3 * w
if len(raw) != (stride + 1) * h:
    print('decoded data has %d bytes, expected %d' % (len(raw), (stride + 1) * h)); sys.exit()
rows, prev = [], bytearray(stride)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - 3] if i >= 3 else 0
        b = prev[i]
        c = prev[i - 3] if i >= 3 else 0
        if f == 1: p = a
        elif f == 2: p = b
        elif f == 3: p = (a + b) // 2
        elif f == 4:
            q = a + b - c
            pa, pb, pc = abs(q - a), abs(q - b), abs(q - c)
            p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
        elif f == 0: p = 0
        else: print('bad filter type %d' % f); sys.exit()
        line[i] = (line[i] + p) & 0xff
    rows.append(bytes(line)); prev = line
px = lambda x, y: rows[y][3 * x:3 * x + 3]
bg = px(0, 0)
border = [px(x, y) for x in range(w) for y in (0, 1, h - 2, h - 1)] + [px(x, y) for y in range(h) for x in (0, 1, w - 2, w - 1)]
if any(p != bg for p in border): problems.append('background border is not uniform')
counts = {}
for r in rows:
    for i in range(0, stride, 3):
        counts[r[i:i + 3]] = counts.get(r[i:i + 3], 0) + 1
covered = 1 - counts.get(bg, 0) / (w * h)
if not 0.15 <= covered <= 0.9: problems.append('object covers %.0f%% of the picture' % (100 * covered))
# Distinct colours that fill a real area (not anti-aliasing blends), by coarse hue bins.
bins = {}
for p, n in counts.items():
    if p == bg: continue
    key = (p[0] // 48, p[1] // 48, p[2] // 48)
    bins[key] = bins.get(key, 0) + n
big = [k for k, n in bins.items() if n >= 0.002 * w * h]
if len(big) < min_colours: problems.append('only %d distinct colours' % len(big))
if problems: print('; '.join(problems))
PY
  [ $? -eq 0 ] || echo "the PNG checker failed"
}

# ---- the rounded box ------------------------------------------------------------------------
if "$fcql" run --example rounded_box --out "$tmp/box" --quiet; then
  if "$fcql" render "$tmp/box" --out "$tmp/layout.png" --quiet; then
    r=$(check_png "$tmp/layout.png" 800 800 5); [ -z "$r" ] || fail "layout view: $r"
  else fail "fcql render (layout view) exited non-zero"; fi
  if "$fcql" render "$tmp/box" --view quad --size 300 --azimuth -40 --elevation 35 --out "$tmp/quad.png" --quiet; then
    r=$(check_png "$tmp/quad.png" 300 300 2); [ -z "$r" ] || fail "quad view: $r"
  else fail "fcql render --view quad exited non-zero"; fi
  if "$fcql" render "$tmp/box" --view both --size 200 --up z --out "$tmp/both.png" --quiet; then
    r=$(check_png "$tmp/both.png" 400 200 5); [ -z "$r" ] || fail "both views: $r"
  else fail "fcql render --view both exited non-zero"; fi
  # The layout view changes with the camera.
  "$fcql" render "$tmp/box" --size 200 --azimuth 120 --out "$tmp/a.png" --quiet
  "$fcql" render "$tmp/box" --size 200 --azimuth 200 --elevation -30 --out "$tmp/b.png" --quiet
  cmp -s "$tmp/a.png" "$tmp/b.png" && fail "two camera positions gave the same picture"
else
  fail "fcql run --example rounded_box exited non-zero"
fi

# ---- bad input: one error line, non-zero exit, no picture -----------------------------------
expect_error() {  # NAME PATTERN ARGS...
  local name=$1 pattern=$2
  shift 2
  rm -f "$tmp/err.png"
  "$fcql" render "$@" >/dev/null 2>"$tmp/stderr"
  local status=$?
  [ $status -ne 0 ] || fail "$name: exit status 0"
  [ "$(wc -l <"$tmp/stderr")" -eq 1 ] || fail "$name: expected one error line, got: $(cat "$tmp/stderr")"
  grep -q "^fcql: error: .*$pattern" "$tmp/stderr" || fail "$name: message '$(cat "$tmp/stderr")' lacks '$pattern'"
  [ ! -e "$tmp/err.png" ] && [ ! -e "$tmp/err.png.tmp" ] || fail "$name: a picture was written"
}
mkdir -p "$tmp/empty" "$tmp/broken" "$tmp/noquad"
expect_error missing_dir "no such directory" "$tmp/nothing" --out "$tmp/err.png"
expect_error empty_dir "layout.ply: cannot open the file (no such file)" "$tmp/empty" --out "$tmp/err.png"
expect_error no_out "missing --out" "$tmp/box"
expect_error no_dir "missing input" --out "$tmp/err.png"
expect_error bad_view "view must be layout, quad or both" "$tmp/box" --view top --out "$tmp/err.png"
expect_error bad_size "size must be" "$tmp/box" --size 10 --out "$tmp/err.png"
expect_error bad_up "up must be x, y or z" "$tmp/box" --up w --out "$tmp/err.png"
if [ -f "$tmp/box/layout.ply" ]; then
  cp "$tmp/box/layout.ply" "$tmp/box/separatrices.obj" "$tmp/noquad/"
  expect_error no_quad "quad.obj: cannot open the file (no such file)" "$tmp/noquad" --view quad --out "$tmp/err.png"
  "$fcql" render "$tmp/noquad" --size 100 --out "$tmp/noquad.png" --quiet || fail "layout view needs no quad.obj"
  head -n 2000 "$tmp/box/layout.ply" >"$tmp/broken/layout.ply"
  cp "$tmp/box/separatrices.obj" "$tmp/broken/"
  expect_error truncated_ply "layout.ply, line 9: declares [0-9]* faces but the file holds at most" "$tmp/broken" --out "$tmp/err.png"
  cp "$tmp/box/layout.ply" "$tmp/broken/layout.ply"
  printf 'v 0 0 0\nl 1 7\n' >"$tmp/broken/separatrices.obj"
  expect_error bad_obj "separatrices.obj: line 2: index 7 out of range" "$tmp/broken" --out "$tmp/err.png"
  expect_error unwritable "cannot write" "$tmp/box" --size 64 --out "$tmp/nowhere/x.png"
fi

if [ $failures -gt 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all cli_render checks passed"
