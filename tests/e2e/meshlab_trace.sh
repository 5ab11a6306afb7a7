#!/usr/bin/env bash
# End-to-end test of the MeshLab plugin's "Field-Coherent Quad Layout: Trace Separatrices",
# run by Debian's meshlabserver through examples/trace_separatrices.mlx (Compute Cross Field,
# then Trace Separatrices) on generated meshes and on the shared eight.obj.
#
# Checks, per mesh: the filter succeeds; the log gives graphs G and H; the layer
# "candidate separatrices" saved as OBJ has `l` lines only, forming exactly one chain per
# candidate of H; the input mesh keeps its faces; the per-face count covers every face; graph H
# has as many arcs as `fcql trace` finds on the same file. (The crossing pairs are not
# compared: the plugin traces on the field as stored in single precision, fcql in double, and
# on meshes with exact ties, like the cube, a few tangential/orthogonal classifications flip.)
#
# Usage: meshlab_trace.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
ml_setup "$build" meshlab_trace
script=$(example_script trace_separatrices) || ml_finish meshlab_trace
ml_prepare_meshes "$fcql" "$shared"

for i in "${!mesh_names[@]}"; do
  name=${mesh_names[$i]}
  input=${mesh_files[$i]}
  log="$work/$name.log"
  if ! run_server "$log" -i "$input" -o "$work/${name}_out.ply" -m sa \
         -o "$work/${name}_candidates.obj" -l 1 -s "$script"; then
    fail "$name: meshlabserver exited with $?"
    tail -20 "$log" | sed 's/^/    /'
    continue
  fi
  g=$(log_line "$log" '^Graph G: ')
  h=$(log_line "$log" '^Graph H: ')
  crossed=$(log_line "$log" '^Candidate separatrices cross ')
  echo "$name: $g"
  echo "$name: $h"
  [ -n "$g" ] && [ -n "$h" ] && [ -n "$crossed" ] || { fail "$name: the log lacks the graph sizes"; continue; }
  arcs=$(number_before "$h" 'candidate separatrices')
  [ "${arcs:-0}" -gt 0 ] || fail "$name: no candidate separatrices"

  # The layer: l lines only, one chain per candidate.
  read -r lines chains faces < <(obj_polylines "$work/${name}_candidates.obj")
  [ "$lines" -gt 0 ] || fail "$name: candidates.obj has no l lines"
  [ "$faces" = 0 ] || fail "$name: candidates.obj has $faces faces"
  [ "$chains" = "$arcs" ] || fail "$name: candidates.obj has $chains polylines, the log says $arcs candidates"

  # The input mesh is unchanged in size; the per-face count covers all its faces.
  nin=$(ply_faces "$input")
  [ -n "$nin" ] || nin=$(off_faces "$input")
  [ "$(ply_faces "$work/${name}_out.ply")" = "$nin" ] || fail "$name: the mesh lost or gained faces"
  case "$crossed" in
    *" of $nin faces"*) ;;
    *) fail "$name: the per-face counts do not cover the $nin faces: $crossed" ;;
  esac

  # Same core, same file: fcql finds the same graph H.
  if stats=$(cli_stats "$fcql" trace "$name" "$input"); then
    cli_arcs=$(json_key "$stats" graph_h arcs)
    [ "$cli_arcs" = "$arcs" ] || fail "$name: fcql trace finds $cli_arcs candidates, the plugin $arcs"
  else
    echo "note: fcql trace unavailable for $name, comparison skipped"
  fi
done

ml_finish meshlab_trace
