#!/usr/bin/env bash
# End-to-end test of the MeshLab plugin's "Field-Coherent Quad Layout: Quadrangulate", run by
# Debian's meshlabserver through examples/quadrangulate.mlx (Compute Cross Field, then
# Quadrangulate) on generated meshes and on the shared eight.obj.
#
# Checks, per mesh, on the saved layer "quad mesh" (layer 1, PLY with face flags, colours and
# quality): twice as many triangles as the logged quads, the logged vertex count; every
# triangle has exactly one faux edge and each faux edge is shared by exactly two triangles (one
# quad each); the face quality (scaled Jacobian) lies in [-1, 1] and its minimum is the logged
# one; the quad mesh has the genus of the input; `fcql quad` on the same file gives the same
# numbers of quads and irregular vertices.
#
# Usage: meshlab_quad.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
ml_setup "$build" meshlab_quad
script=$(example_script quadrangulate) || ml_finish meshlab_quad
ml_prepare_meshes "$fcql" "$shared"

# faux_check PLY: "FACES ONE_FAUX PAIRED_EDGES BAD_EDGES": faces, faces with exactly one faux
# edge, faux edges shared by exactly two such faces, other faux edges.
faux_check() {
  ply_face_props "$1" vertices flags | awk '
    { split($1 " " $2 " " $3, v, " "); flags = $4; faces++
      bits = int(flags / 262144) % 8                 # FAUX0 = 0x40000, FAUX1, FAUX2
      n = 0; for (i = 0; i < 3; i++) if (int(bits / 2 ^ i) % 2) { n++; e = i }
      if (n != 1) next
      one++
      a = v[e + 1]; b = v[(e + 1) % 3 + 1]
      key = (a < b) ? a "-" b : b "-" a
      count[key]++ }
    END { for (k in count) if (count[k] == 2) paired++; else bad++
          print faces + 0, one + 0, paired + 0, bad + 0 }'
}

for i in "${!mesh_names[@]}"; do
  name=${mesh_names[$i]}
  input=${mesh_files[$i]}
  log="$work/$name.log"
  quads_ply="$work/${name}_quads.ply"
  if ! run_server "$log" -i "$input" -o "$quads_ply" -l 1 -m ff fc fq sa -s "$script"; then
    fail "$name: meshlabserver exited with $?"
    tail -20 "$log" | sed 's/^/    /'
    continue
  fi
  quad=$(log_line "$log" '^Quad mesh: ')
  jac=$(log_line "$log" '^Quality: ')
  mesh=$(log_line "$log" '^Mesh: ')
  echo "$name: $quad"
  [ -n "$quad" ] && [ -n "$jac" ] || { fail "$name: the log lacks the quad mesh figures"; continue; }
  q=$(number_before "$quad" 'quads')
  nv=$(number_before "$quad" 'vertices')
  irregular=$(number_before "$quad" 'irregular')
  [ "${q:-0}" -gt 0 ] || { fail "$name: no quads"; continue; }
  head -c 4096 "$quads_ply" | grep -aq '^property int flags' || fail "$name: no face flags saved"

  [ "$(ply_faces "$quads_ply")" = $((2 * q)) ] ||
    fail "$name: the quad layer has $(ply_faces "$quads_ply") triangles for $q quads"
  saved_nv=$(head -c 4096 "$quads_ply" | grep -a '^element vertex' | awk '{print $3}')
  [ "$saved_nv" = "$nv" ] || fail "$name: the quad layer has $saved_nv vertices, the log says $nv"
  read -r faces one paired bad < <(faux_check "$quads_ply")
  [ "$one" = "$faces" ] || fail "$name: $((faces - one)) of $faces triangles do not have exactly one faux edge"
  [ "$paired" = "$q" ] && [ "$bad" = 0 ] ||
    fail "$name: faux diagonals: $paired shared by two triangles, $bad not (expected $q and 0)"

  # Face quality = scaled Jacobian per quad, in [-1, 1]; the minimum is the logged one.
  read -r qmin qmax < <(ply_face_props "$quads_ply" quality |
    awk 'NR == 1 { lo = hi = $1 } { if ($1 < lo) lo = $1; if ($1 > hi) hi = $1 } END { printf "%.3f %.3f\n", lo, hi }')
  awk -v lo="$qmin" -v hi="$qmax" 'BEGIN { exit !(lo >= -1 && hi <= 1.0005) }' ||
    fail "$name: face quality out of [-1, 1]: $qmin..$qmax"
  case "$jac" in *"scaled Jacobian min $qmin "*) ;; *) fail "$name: saved minimum quality $qmin, log: $jac" ;; esac

  genus=$(printf '%s\n' "$mesh" | grep -oE 'genus [0-9]+')
  case "$quad" in *"$genus,"*) ;; *) fail "$name: the quad mesh does not have the input's $genus: $quad" ;; esac
  echo "$name: $faces triangles, $paired faux diagonals, quality $qmin..$qmax"

  if stats=$(cli_stats "$fcql" quad "$name" "$input"); then
    cli_q=$(json_key "$stats" quad faces)
    cli_i=$(json_key "$stats" quad irregular_vertices)
    [ "$cli_q" = "$q" ] && [ "$cli_i" = "$irregular" ] ||
      fail "$name: fcql quad gives $cli_q quads / $cli_i irregular vertices, the plugin $q / $irregular"
  else
    echo "note: fcql quad unavailable for $name, comparison skipped"
  fi
done

ml_finish meshlab_quad
