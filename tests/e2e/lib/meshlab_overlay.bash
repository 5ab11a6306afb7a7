# Helpers for the end-to-end tests of the MeshLab 2020.09 plugin (tests/e2e/meshlab_*.sh).
# Sourced, not run: it lives in lib/ so that the CMake glob tests/e2e/*.sh does not take it for
# a test.
#
# MeshLab 2020.09 has no option for a plugin folder, so ml_setup builds an overlay prefix in the
# work dir (MESHLAB.md): a copy of meshlabserver in PREFIX/bin, a symlink to
# libmeshlab-common.so in PREFIX/lib/x86_64-linux-gnu/meshlab/, and plugins/ with symlinks to
# Debian's io_base and to the freshly built libfilter_fieldquadlayout.so.
#
# Input meshes are OFF or PLY: Debian's meshlabserver 2020.09 aborts on any OBJ input (an
# assert in vcglib's ImporterOBJ, exit 134); obj_to_off converts.
#
# Outputs are saved as ASCII PLY (`-m ... sa`) so that awk can read them.

ml_debian_lib=/usr/lib/x86_64-linux-gnu/meshlab
ml_source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
ml_examples="$ml_source_dir/examples"
failures=0

skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# ml_setup BUILD_DIR NAME: checks the prerequisites (skips the test when one is missing), sets
# $work (BUILD_DIR/e2e_NAME, emptied), $prefix, $plugins, $plugin and builds the overlay.
ml_setup() {
  local build=$1 name=$2
  [ -n "$build" ] && [ -d "$build" ] || skip "no build directory given"
  command -v xvfb-run >/dev/null || skip "xvfb-run is not installed"
  [ -x /usr/bin/meshlabserver ] || skip "Debian's meshlabserver is not installed"
  [ -f "$ml_debian_lib/libmeshlab-common.so" ] || skip "libmeshlab-common.so is not installed"
  [ -f "$ml_debian_lib/plugins/libio_base.so" ] || skip "MeshLab's io_base plugin is not installed"
  work="$build/e2e_$name"
  rm -rf "$work"
  mkdir -p "$work"
  plugin=$(find "$build" -path "$build/e2e_*" -prune -o -type f -name libfilter_fieldquadlayout.so \
           -print | head -1)
  [ -n "$plugin" ] || skip "libfilter_fieldquadlayout.so not built in $build (FCQL_BUILD_PLUGIN=OFF?)"
  plugin=$(cd "$(dirname "$plugin")" && pwd)/$(basename "$plugin")
  prefix="$work/prefix"
  plugins="$prefix/lib/x86_64-linux-gnu/meshlab/plugins"
  mkdir -p "$prefix/bin" "$plugins" "$work/xdg"
  chmod 700 "$work/xdg"
  cp /usr/bin/meshlabserver "$prefix/bin/"
  ln -s "$ml_debian_lib/libmeshlab-common.so" "$prefix/lib/x86_64-linux-gnu/meshlab/"
  ln -s "$ml_debian_lib/plugins/libio_base.so" "$plugins/"
  ln -s "$plugin" "$plugins/"
}

# ml_finish NAME: the verdict (exit 1 on failures; on success the work dir is removed unless
# FCQL_KEEP_E2E is set).
ml_finish() {
  if [ $failures -ne 0 ]; then
    echo "$failures failure(s); logs in $work"
    exit 1
  fi
  echo "PASS: $1"
  [ -n "${FCQL_KEEP_E2E:-}" ] || rm -rf "$work"
  exit 0
}

# run_server LOG ARGS...: meshlabserver ARGS under a virtual X server, output into LOG;
# returns meshlabserver's exit status.
run_server() {
  local log=$1
  shift
  XDG_CONFIG_HOME="$work/xdg" XDG_RUNTIME_DIR="$work/xdg" \
    timeout 600 xvfb-run -a "$prefix/bin/meshlabserver" "$@" >"$log" 2>&1
}

# example_script NAME: path of examples/NAME.mlx (fails the test if it is missing).
example_script() {
  local f="$ml_examples/$1.mlx"
  [ -f "$f" ] || { fail "$f is missing"; return 1; }
  echo "$f"
}

# set_param MLX_IN MLX_OUT NAME VALUE: a copy of a script with every parameter NAME set to VALUE.
set_param() {
  sed "s|name=\"$3\" value=\"[^\"]*\"|name=\"$3\" value=\"$4\"|" "$1" >"$2"
  grep -q "name=\"$3\" value=\"$4\"" "$2" || fail "could not set $3=$4 in $2"
}

# drop_filter MLX_IN MLX_OUT NAME: a copy of a script without the filter NAME (the part after
# "Field-Coherent Quad Layout: ").
drop_filter() {
  awk -v n="Field-Coherent Quad Layout: $3" '
    index($0, "<filter name=\"" n "\"") { skip = 1 }
    !skip { print }
    skip && /<\/filter>/ { skip = 0 }' "$1" >"$2"
}

# log_line LOG PATTERN: the first LOG: line of meshlabserver's output matching PATTERN (an
# extended regex), without the "LOG: N " prefix.
log_line() { grep -a '^LOG: ' "$1" | sed 's/^LOG: [0-9]* //' | grep -aE -- "$2" | head -1; }

# number_before TEXT WORDS: the integer just before WORDS in TEXT ("12 patches" -> 12).
number_before() { printf '%s\n' "$1" | grep -oE "[0-9]+ $2" | head -1 | grep -oE '^[0-9]+'; }

# json_int FILE KEY: the first integer value of KEY in a stats.json.
json_int() { grep -o "\"$2\": *-\?[0-9]*" "$1" | head -1 | grep -o -- '-\?[0-9]*$'; }
# json_key FILE SECTION KEY: the value of SECTION.KEY in a stats.json (fcql writes one key per
# line, sections one level deep).
json_key() {
  awk -v s="\"$2\":" -v k="\"$3\":" '
    $1 == s && $2 == "{" { in_s = 1; next }
    in_s && /^ *}/ { in_s = 0 }
    in_s && $1 == k { v = $2; sub(/,$/, "", v); gsub(/"/, "", v); print v; exit }' "$1"
}

# ---- meshes ---------------------------------------------------------------------------------

# write_cube FILE N: a closed cube of side N, N×N quads per side split in two triangles each,
# welded vertices, outward orientation (counter-clockwise seen from outside).
write_cube() {
  awk -v n="$2" '
    function id(x, y, z,   k) {
      k = x "," y "," z
      if (!(k in ids)) { ids[k] = nv; vx[nv] = x; vy[nv] = y; vz[nv] = z; nv++ }
      return ids[k]
    }
    # side: origin (ox,oy,oz), axes U and V (unit lattice vectors) with U x V = outward normal.
    function side(ox, oy, oz, ux, uy, uz, wx, wy, wz,   a, b, p00, p10, p11, p01) {
      for (a = 0; a < n; a++) for (b = 0; b < n; b++) {
        p00 = id(ox + a*ux + b*wx,         oy + a*uy + b*wy,         oz + a*uz + b*wz)
        p10 = id(ox + (a+1)*ux + b*wx,     oy + (a+1)*uy + b*wy,     oz + (a+1)*uz + b*wz)
        p11 = id(ox + (a+1)*ux + (b+1)*wx, oy + (a+1)*uy + (b+1)*wy, oz + (a+1)*uz + (b+1)*wz)
        p01 = id(ox + a*ux + (b+1)*wx,     oy + a*uy + (b+1)*wy,     oz + a*uz + (b+1)*wz)
        f[nf++] = p00 " " p10 " " p11
        f[nf++] = p00 " " p11 " " p01
      }
    }
    BEGIN {
      nv = 0; nf = 0
      side(0, 0, 0,  0, 1, 0,  1, 0, 0)   # z = 0, normal -z
      side(0, 0, n,  1, 0, 0,  0, 1, 0)   # z = n, normal +z
      side(0, 0, 0,  0, 0, 1,  0, 1, 0)   # x = 0, normal -x
      side(n, 0, 0,  0, 1, 0,  0, 0, 1)   # x = n, normal +x
      side(0, 0, 0,  1, 0, 0,  0, 0, 1)   # y = 0, normal -y
      side(0, n, 0,  0, 0, 1,  1, 0, 0)   # y = n, normal +y
      print "OFF"; print nv, nf, 0
      for (i = 0; i < nv; i++) print vx[i], vy[i], vz[i]
      for (i = 0; i < nf; i++) print 3, f[i]
    }' >"$1"
}

# write_torus FILE NU NV: a torus (radii 3 and 1), NU×NV quads split in two triangles each,
# outward orientation. It has no singularities: its layout needs field lines through regular
# vertices to close the patches, and t-junctions.
write_torus() {
  awk -v nu="$2" -v nv="$3" 'BEGIN {
    pi = atan2(0, -1); print "OFF"; print nu * nv, 2 * nu * nv, 0
    for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
      u = 2 * pi * i / nu; v = 2 * pi * j / nv
      printf "%.9g %.9g %.9g\n", (3 + cos(v)) * cos(u), (3 + cos(v)) * sin(u), sin(v)
    }
    for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
      a = i * nv + j; b = ((i + 1) % nu) * nv + j; c = ((i + 1) % nu) * nv + (j + 1) % nv
      d = i * nv + (j + 1) % nv
      print 3, a, b, c; print 3, a, c, d
    } }' >"$1"
}

# obj_to_off OBJ OFF: triangles of an OBJ (1-based, v/vt/vn allowed) as OFF (0-based).
obj_to_off() {
  awk '$1 == "v" { v[nv++] = $2 " " $3 " " $4 }
       $1 == "f" { for (i = 2; i <= 4; i++) { split($i, p, "/"); c[i] = p[1] - 1 }
                   f[nf++] = "3 " c[2] " " c[3] " " c[4] }
       END { print "OFF"; print nv, nf, 0
             for (i = 0; i < nv; i++) print v[i]
             for (i = 0; i < nf; i++) print f[i] }' "$1" >"$2"
}

# ml_convert IN OUT.ply: the mesh as MeshLab loads it (single-precision coordinates), saved as
# PLY, so that fcql and the plugin read exactly the same numbers.
ml_convert() {
  run_server "$work/convert_$(basename "$2").log" -i "$1" -o "$2" && [ -s "$2" ]
}

# ---- reading outputs ------------------------------------------------------------------------

# ply_faces FILE: the face count in a PLY header (ASCII or binary).
ply_faces() { head -c 4096 "$1" | tr -d '\r' | grep -a '^element face ' | head -1 | awk '{print $3}'; }
# off_faces FILE: the face count of an OFF file written by the helpers above.
off_faces() { sed -n 2p "$1" | awk '{print $2}'; }

# ply_face_props PLY PROP...: per face of an ASCII PLY, the values of the scalar face
# properties PROP (in that order), space-separated, one line per face. The vertex_indices list
# is "i0 i1 i2" under the name "vertices".
ply_face_props() {
  local ply=$1
  shift
  awk -v want="$*" '
    BEGIN { nw = split(want, w, " ") }
    !body {
      if ($1 == "element") { el = $2; count[el] = $3; order[++ne] = el }
      else if ($1 == "property" && el == "face") {
        if ($2 == "list") names[++np] = "vertices"; else names[++np] = $3
      }
      else if ($1 == "end_header") { body = 1; row = 0; e = 1 }
      next
    }
    {
      while (e <= ne && row >= count[order[e]]) { e++; row = 0 }
      if (order[e] != "face") { row++; next }
      k = 1; delete val
      for (p = 1; p <= np; p++) {
        if (names[p] == "vertices") { n = $k; val["vertices"] = $(k + 1) " " $(k + 2) " " $(k + 3); k += n + 1 }
        else { val[names[p]] = $k; k++ }
      }
      line = ""
      for (i = 1; i <= nw; i++) line = line (i > 1 ? " " : "") val[w[i]]
      print line
      row++
    }' "$ply"
}

# ply_vertex_prop PLY PROP: per vertex of an ASCII PLY, the value of the scalar property PROP.
ply_vertex_prop() {
  awk -v want="$2" '
    !body {
      if ($1 == "element") { el = $2; if (el == "vertex") nv = $3 }
      else if ($1 == "property" && el == "vertex") { np++; if ($3 == want) col = np }
      else if ($1 == "end_header") body = 1
      next
    }
    row < nv && col { print $col }
    { row++ }' "$1"
}

# distinct_face_colours PLY: the number of distinct face colours of an ASCII PLY saved with fc.
distinct_face_colours() { ply_face_props "$1" red green blue | sort -u | grep -c .; }

# obj_polylines OBJ: "LINES CHAINS FACES": the number of `l` lines, of connected chains of
# them (polylines, when polylines do not share vertices), and of `f` lines.
obj_polylines() {
  awk 'function root(x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x }
       $1 == "l" { lines++
                   for (i = 2; i <= NF; i++) { v = $i + 0; if (!(v in parent)) parent[v] = v }
                   for (i = 3; i <= NF; i++) { a = root($(i - 1) + 0); b = root($i + 0); if (a != b) parent[a] = b } }
       $1 == "f" { faces++ }
       END { for (v in parent) if (parent[v] == v) chains++
             print lines + 0, chains + 0, faces + 0 }' "$1"
}

# ---- the test meshes --------------------------------------------------------------------------

# ml_prepare_meshes FCQL SHARED_DIR [torus]: writes the meshes the pipeline tests run on into
# $work and lists them in the arrays mesh_names / mesh_files:
#   cube    a 6×6×6 cube (welded, integer coordinates): 6 patches;
#   dtorus  fcql's generated double torus, cut along its layout (`fcql layout --example
#           double_torus`, layout.ply): genus 2, 50 patches (needs the fcql tool);
#   torus   with the argument "torus": a torus without singularities (closing lines,
#           t-junctions);
#   eight   the shared eight.obj (genus 2), when SHARED_DIR has it.
# The generated PLY and eight go through MeshLab once (ml_convert), so that fcql and the plugin
# read the same single-precision coordinates.
ml_prepare_meshes() {
  local fcql=$1 shared=$2
  mesh_names=()
  mesh_files=()
  write_cube "$work/cube.off" 6
  mesh_names+=(cube)
  mesh_files+=("$work/cube.off")
  if [ -x "$fcql" ] && "$fcql" layout --example double_torus --out "$work/gen_dtorus" --quiet \
       >"$work/gen_dtorus.log" 2>&1 && ml_convert "$work/gen_dtorus/layout.ply" "$work/dtorus.ply"; then
    mesh_names+=(dtorus)
    mesh_files+=("$work/dtorus.ply")
  else
    echo "note: fcql is not available or failed, generated double torus skipped"
  fi
  if [ "${3:-}" = torus ]; then
    write_torus "$work/torus.off" 48 16
    mesh_names+=(torus)
    mesh_files+=("$work/torus.off")
  fi
  if [ -n "$shared" ] && [ -f "$shared/data/meshes/eight.obj" ]; then
    obj_to_off "$shared/data/meshes/eight.obj" "$work/eight.off"
    if ml_convert "$work/eight.off" "$work/eight.ply"; then
      mesh_names+=(eight)
      mesh_files+=("$work/eight.ply")
    else
      fail "MeshLab could not convert eight.off"
    fi
  else
    echo "note: $shared/data/meshes/eight.obj is absent, shared-mesh checks skipped"
  fi
}

# cli_stats FCQL COMMAND NAME MESH: runs `fcql COMMAND MESH --out $work/cli_NAME` (quietly) and
# prints the path of its stats.json; nothing (status 1) if fcql is missing or fails.
cli_stats() {
  local out="$work/cli_$3"
  [ -x "$1" ] || return 1
  "$1" "$2" "$4" --out "$out" --quiet >"$out.log" 2>&1 || return 1
  [ -f "$out/stats.json" ] && echo "$out/stats.json"
}
