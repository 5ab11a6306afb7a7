#!/usr/bin/env bash
# End-to-end test of the MeshLab 2020.09 plugin, filter "Field-Coherent Quad Layout: Compute
# Cross Field", run by Debian's meshlabserver through examples/compute_cross_field.mlx.
#
# Usage: meshlab_field.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
# Work files go to BUILD_DIR/e2e_meshlab_field (removed on success unless FCQL_KEEP_E2E=1).
#
# The overlay prefix, meshlabserver runner and mesh helpers are in lib/meshlab_overlay.bash.
# Input meshes are written as OFF: Debian's meshlabserver 2020.09 aborts on any OBJ input, so
# the shared eight.obj is converted to OFF first.
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
debian_lib=$ml_debian_lib
ml_setup "$build" meshlab_field
script=$(example_script compute_cross_field) || ml_finish meshlab_field

# singularity_line LOG: the log line with the singularity counts.
singularity_line() { grep -a 'Singularities: [0-9]* (by index: ' "$1" | head -1 | sed 's/^LOG: [0-9]* //'; }

# nonzero_quality PLY: "x y z quality" of the vertices with a non-zero quality, from the binary
# PLY that meshlabserver -m vq writes (vertex = float x y z quality, checked); nothing and
# status 1 if the layout differs.
nonzero_quality() {
  local ply=$1 start nv
  head -c 4096 "$ply" | grep -a -A5 '^element vertex' | tr '\n' ' ' |
    grep -q 'property float x property float y property float z property float quality element face' ||
    return 1
  start=$(( $(grep -abo 'end_header' "$ply" | head -1 | cut -d: -f1) + 11 ))
  nv=$(head -c 4096 "$ply" | grep -a '^element vertex' | awk '{print $3}')
  od -A n -v -t f4 -j "$start" -N $((nv * 16)) "$ply" | tr -s ' \t' '\n' | grep -v '^$' |
    paste - - - - | awk '$4 != 0 { print $1, $2, $3, $4 }'
}

# check_corner_quality NAME PLY COUNT "XS" "YS" "ZS": exactly COUNT vertices have a non-zero
# quality, all equal to 1 (index +1/4), with x in XS, y in YS, z in ZS (space-separated lists).
check_corner_quality() {
  local name=$1 ply=$2 count=$3 q n bad
  if ! q=$(nonzero_quality "$ply"); then
    fail "$name: unexpected vertex layout in $ply"
    return
  fi
  n=$(printf '%s\n' "$q" | grep -c .)
  bad=$(printf '%s\n' "$q" | awk -v xs="$4" -v ys="$5" -v zs="$6" '
    function in_list(v, list,   a, i, k) { k = split(list, a, " "); for (i = 1; i <= k; i++) if (v == a[i]) return 1; return 0 }
    NF && !($4 == 1 && in_list($1, xs) && in_list($2, ys) && in_list($3, zs))' | wc -l)
  [ "$n" = "$count" ] && [ "$bad" = 0 ] ||
    fail "$name: expected quality 1 on $count corners only, got: $(printf '%s\n' "$q" | tr '\n' ';')"
}

# expect_success NAME INPUT.off: runs the example script; exit 0, log has the counts, the
# output has the same number of faces. Leaves the log in $work/NAME.log.
expect_success() {
  local name=$1 input=$2 log="$work/$1.log" out="$work/$1_out.ply"
  run_server "$log" -i "$input" -o "$out" -m vq -s "$script"
  local status=$?
  if [ $status -ne 0 ]; then
    fail "$name: meshlabserver exited with $status"
    sed 's/^/    /' "$log" | tail -20
    return 1
  fi
  local line
  line=$(singularity_line "$log")
  [ -n "$line" ] || fail "$name: the log does not give the singularity counts"
  echo "$name: $line"
  [ -s "$out" ] || { fail "$name: $out was not written"; return 1; }
  local nin nout
  nin=$(off_faces "$input")
  nout=$(ply_faces "$out")
  [ "$nin" = "$nout" ] || fail "$name: output has '$nout' faces, input $nin"
  head -c 4096 "$out" | grep -aq '^property float quality' ||
    fail "$name: the output has no per-vertex quality (singularity index)"
  return 0
}

# expect_failure NAME INPUT SCRIPT PATTERN: meshlabserver exits non-zero, without crashing, and
# its output matches PATTERN (the reason).
expect_failure() {
  local name=$1 input=$2 mlx=$3 pattern=$4 log="$work/$1.log" out="$work/$1_out.ply"
  run_server "$log" -i "$input" -o "$out" -m vq -s "$mlx"
  local status=$?
  [ $status -ne 0 ] || fail "$name: meshlabserver exited with 0"
  [ $status -ne 134 ] && [ $status -ne 139 ] || fail "$name: meshlabserver crashed (status $status)"
  grep -aq "Compute Cross Field failed: " "$log" || fail "$name: no failure reason in the output"
  grep -aqE "$pattern" "$log" || fail "$name: the output does not match '$pattern'"
  echo "$name: exit $status, $(grep -a 'Compute Cross Field failed: ' "$log" | head -1 | sed 's/^LOG: [0-9]* //')"
}

# ---- 1. a generated cube: 8 singularities of index +1/4 at the corners ---------------------
write_cube "$work/cube.off" 4
if expect_success cube "$work/cube.off"; then
  line=$(singularity_line "$work/cube.log")
  case "$line" in
    *"(by index: 1/4: 8)"*) ;;
    *) fail "cube: expected 8 singularities of index 1/4, got: $line" ;;
  esac
  case "$line" in
    *"index sum: 2 "*) ;;
    *) fail "cube: the index sum is not 2 (Poincare-Hopf): $line" ;;
  esac
  # Per-vertex quality = index x 4: 1 at the 8 corners, 0 elsewhere.
  check_corner_quality cube "$work/cube_out.ply" 8 "0 4" "0 4" "0 4"
fi

# ---- 2. keeping the field: a second run with use_existing=true analyses the stored PD1/PD2 ----
sed -e 's|</FilterScript>||' "$script" >"$work/twice.mlx"
sed -n '/<filter /,/<\/filter>/p' "$script" |
  sed 's|name="use_existing" value="false"|name="use_existing" value="true"|' >>"$work/twice.mlx"
echo '</FilterScript>' >>"$work/twice.mlx"
grep -q 'name="use_existing" value="true"' "$work/twice.mlx" || fail "could not write twice.mlx"
if run_server "$work/twice.log" -i "$work/cube.off" -o "$work/twice_out.ply" -s "$work/twice.mlx"; then
  grep -aq 'kept the field already on the mesh' "$work/twice.log" ||
    fail "use_existing: the second run did not keep the stored field"
  n=$(grep -ac 'Singularities: [0-9]* (by index: ' "$work/twice.log")
  distinct=$(grep -a 'Singularities: [0-9]* (by index: ' "$work/twice.log" | sed 's/^LOG: [0-9]* //' | sort -u | wc -l)
  [ "$n" -ge 2 ] && [ "$distinct" -eq 1 ] ||
    fail "use_existing: the stored field does not give the same singularities ($n lines, $distinct distinct)"
else
  fail "use_existing: meshlabserver exited with $?"
  tail -20 "$work/twice.log"
fi

# ---- 3. deleted elements and a border: MeshLab deletes the top of the cube first -------------
# (needs Debian's filter_func and filter_select plugins). The filter must map indices around the
# deleted faces and vertices: an open box has the 4 bottom corners as +1/4 singularities, its
# top rim is a straight border (index sum = Euler characteristic 1), and 160 faces remain.
if [ -f "$debian_lib/plugins/libfilter_func.so" ] && [ -f "$debian_lib/plugins/libfilter_select.so" ]; then
  ln -s "$debian_lib/plugins/libfilter_func.so" "$debian_lib/plugins/libfilter_select.so" "$plugins/"
  {
    echo '<!DOCTYPE FilterScript>'
    echo '<FilterScript>'
    echo ' <filter name="Conditional Face Selection">'
    echo '  <Param type="RichString" name="condSelect" value="(z0 &gt; 3.5) &amp;&amp; (z1 &gt; 3.5) &amp;&amp; (z2 &gt; 3.5)"/>'
    echo ' </filter>'
    echo ' <filter name="Delete Selected Faces and Vertices"/>'
    sed -n '/<filter /,/<\/filter>/p' "$script"
    echo '</FilterScript>'
  } >"$work/open_box.mlx"
  if run_server "$work/open_box.log" -i "$work/cube.off" -o "$work/open_box_out.ply" -m vq -s "$work/open_box.mlx"; then
    grep -aq 'Deleted 32 faces' "$work/open_box.log" || fail "open_box: MeshLab did not delete the top"
    line=$(singularity_line "$work/open_box.log")
    echo "open_box: $line"
    case "$line" in
      *"(by index: 1/4: 4)"*"index sum: 1 "*) ;;
      *) fail "open_box: expected 4 singularities of index 1/4 and index sum 1, got: $line" ;;
    esac
    grep -aq 'Mesh: 160 faces, 89 vertices, genus 0, 1 border loops' "$work/open_box.log" ||
      fail "open_box: the converted mesh is not 160 faces, 89 vertices, 1 border loop"
    [ "$(ply_faces "$work/open_box_out.ply")" = 160 ] || fail "open_box: the output does not have 160 faces"
    check_corner_quality open_box "$work/open_box_out.ply" 4 "0 4" "0 4" "0"
  else
    fail "open_box: meshlabserver exited with non-zero status"
    tail -20 "$work/open_box.log"
  fi
else
  echo "note: MeshLab's filter_func/filter_select plugins are absent, open-box check skipped"
fi

# ---- 4. a shared real mesh ------------------------------------------------------------------
if [ -n "$shared" ] && [ -f "$shared/data/meshes/eight.obj" ]; then
  obj_to_off "$shared/data/meshes/eight.obj" "$work/eight.off"
  if expect_success eight "$work/eight.off"; then
    line=$(singularity_line "$work/eight.log")
    # Genus 2: the interior indices sum to the Euler characteristic -2.
    case "$line" in
      *"index sum: -2 "*) ;;
      *) fail "eight: the index sum is not -2: $line" ;;
    esac
    grep -aq 'genus 2' "$work/eight.log" || fail "eight: the log does not say genus 2"
    # Same core, same mesh: the command-line tool (if built) finds the same singularities.
    if [ -x "$fcql" ] && "$fcql" field "$shared/data/meshes/eight.obj" --out "$work/eight_cli" --quiet \
         >/dev/null 2>&1 && [ -f "$work/eight_cli/stats.json" ]; then
      cli_s=$(json_int "$work/eight_cli/stats.json" singularities)
      cli_p=$(json_int "$work/eight_cli/stats.json" ports)
      case "$line" in
        "Singularities: $cli_s "*"ports: $cli_p,"*) ;;
        *) fail "eight: the plugin and fcql disagree (fcql: $cli_s singularities, $cli_p ports; plugin: $line)" ;;
      esac
    else
      echo "note: the fcql tool is not available, plugin/CLI comparison skipped"
    fi
  fi
  # Its shipped field through field_file: 24 singularities (16 of index -1/4, 8 of +1/4), as
  # `fcql field --field` reads it; a field file of the wrong face count fails and names it.
  sed "s|name=\"field_file\" value=\"\"|name=\"field_file\" value=\"$shared/data/meshes/eight.ffield\"|" \
    "$script" >"$work/eight_field.mlx"
  grep -q 'eight.ffield' "$work/eight_field.mlx" || fail "could not write eight_field.mlx"
  run_server "$work/eight_field.log" -i "$work/eight.off" -o "$work/eight_field_out.ply" -m vq -s "$work/eight_field.mlx"
  line=$(singularity_line "$work/eight_field.log")
  case "$line" in
    *"Singularities: 24 (by index: -1/4: 16, 1/4: 8)"*) echo "eight with its field file: $line" ;;
    *) fail "eight with its field file: $line" ;;
  esac
  grep -aq "Cross field: read from .*eight.ffield" "$work/eight_field.log" || fail "eight: the log does not name the field file"
  printf '3\n4\n1 0 0\n1 0 0\n1 0 0\n' >"$work/short.rosy"
  sed "s|name=\"field_file\" value=\"\"|name=\"field_file\" value=\"$work/short.rosy\"|" "$script" >"$work/short_field.mlx"
  expect_failure short_field "$work/eight.off" "$work/short_field.mlx" "the field has 3 faces but the mesh has"
else
  echo "note: $shared/data/meshes/eight.obj is absent, shared-mesh check skipped"
fi

# ---- 5. an out-of-range parameter: non-zero exit and the reason --------------------------------
sed 's|name="sharp_angle" value="[^"]*"|name="sharp_angle" value="500"|' "$script" >"$work/bad_angle.mlx"
grep -q 'value="500"' "$work/bad_angle.mlx" || fail "could not write bad_angle.mlx"
expect_failure bad_angle "$work/cube.off" "$work/bad_angle.mlx" "sharp_angle.*500.*between 0 and 180"
[ ! -e "$work/bad_angle_out.ply" ] || fail "bad_angle: an output was written after the failure"

# ---- 5b. an unwelded cube: every face with its own three vertices ---------------------------
# The filter merges the vertices that lie on one another (and says so): the cube's 8 corners
# are found as on the welded cube.
awk 'NR == 1 { next } NR == 2 { nv = $1; nf = $2; next }
     NR <= 2 + nv { v[NR - 3] = $1 " " $2 " " $3; next }
     { f[++k] = v[$2] "\n" v[$3] "\n" v[$4] }
     END { print "OFF"; print 3 * nf, nf, 0; for (i = 1; i <= k; i++) print f[i];
           for (i = 0; i < nf; i++) print 3, 3 * i, 3 * i + 1, 3 * i + 2 }' "$work/cube.off" >"$work/unwelded.off"
if expect_success unwelded "$work/unwelded.off"; then
  grep -aq 'lie exactly on another vertex: merged' "$work/unwelded.log" ||
    fail "unwelded: the log does not say that the vertices were merged"
  case "$(singularity_line "$work/unwelded.log")" in
    *"(by index: 1/4: 8)"*"index sum: 2 "*) ;;
    *) fail "unwelded: expected the cube's 8 singularities, got: $(singularity_line "$work/unwelded.log")" ;;
  esac
fi

# ---- 6. a non-manifold mesh: three triangles sharing one edge ------------------------------
cat >"$work/fin.off" <<'EOF'
OFF
5 3 0
0 0 0
1 0 0
0.5 1 0
0.5 -1 0.2
0.5 0 1
3 0 1 2
3 1 0 3
3 0 1 4
EOF
expect_failure non_manifold "$work/fin.off" "$script" "non-manifold|orientation"

# ---- 7. a point cloud: no faces -----------------------------------------------------------------
printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' >"$work/points.off"
run_server "$work/points.log" -i "$work/points.off" -o "$work/points_out.ply" -s "$script"
status=$?
[ $status -ne 0 ] || fail "points: meshlabserver exited with 0 on a mesh without faces"
[ $status -ne 134 ] && [ $status -ne 139 ] || fail "points: meshlabserver crashed (status $status)"

ml_finish meshlab_field
