#!/usr/bin/env bash
# End-to-end test of the MeshLab plugin's "Field-Coherent Quad Layout: Solve Layout", run by
# Debian's meshlabserver through examples/solve_layout.mlx (Compute Cross Field, then Solve
# Layout) on generated meshes (a cube, fcql's double torus, a torus that needs closing lines)
# and on the shared eight.obj.
#
# Checks, per mesh, on the saved layers:
#  - the input mesh (layer 0, face colours): as many distinct face colours as the log says
#    patches own the majority of some face, at least half of all patches, and no more;
#  - the layer "patch layout" (layer 2, the surface cut along the separatrices): exactly one
#    colour per patch, as many triangles as logged, patch corners in the vertex quality;
#  - the layer "separatrices" (layer 1, OBJ): `l` lines only, one chain per separatrix;
#  - `fcql layout` on the same file finds the same numbers of patches and t-junctions.
#
# Usage: meshlab_layout.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
ml_setup "$build" meshlab_layout
script=$(example_script solve_layout) || ml_finish meshlab_layout
ml_prepare_meshes "$fcql" "$shared" torus

for i in "${!mesh_names[@]}"; do
  name=${mesh_names[$i]}
  input=${mesh_files[$i]}
  log="$work/$name.log"
  out="$work/${name}_out.ply"
  sep="$work/${name}_separatrices.obj"
  cut="$work/${name}_layout.ply"
  if ! run_server "$log" -i "$input" -o "$out" -m fc sa -o "$sep" -l 1 -o "$cut" -l 2 -m fc vq sa \
         -s "$script"; then
    fail "$name: meshlabserver exited with $?"
    tail -20 "$log" | sed 's/^/    /'
    continue
  fi
  layout=$(log_line "$log" '^Layout: ')
  doc=$(log_line "$log" '^Input mesh: ')
  echo "$name: $layout"
  [ -n "$layout" ] && [ -n "$doc" ] || { fail "$name: the log lacks the layout figures"; continue; }
  patches=$(number_before "$layout" 'patches')
  tjunctions=$(number_before "$layout" 't-junctions')
  owning=$(number_before "$doc" "of $patches patches cover")
  triangles=$(number_before "$doc" 'triangles cut')
  polylines=$(number_before "$doc" 'polylines')
  [ "${patches:-0}" -gt 0 ] || { fail "$name: no patches"; continue; }
  case "$layout" in *" 0 invalid patches"*) ;; *) fail "$name: invalid patches: $layout" ;; esac

  # Layer 0: the input mesh coloured by the majority patch of each face.
  colours=$(distinct_face_colours "$out")
  [ "$colours" = "$owning" ] ||
    fail "$name: the input mesh has $colours face colours, the log says $owning patches own faces"
  [ "$colours" -le "$patches" ] && [ $((2 * colours)) -ge "$patches" ] ||
    fail "$name: $colours face colours for $patches patches"

  # Layer 2: the cut surface, one colour per patch, corners flagged.
  [ "$(ply_faces "$cut")" = "$triangles" ] ||
    fail "$name: the patch layout has $(ply_faces "$cut") triangles, the log says $triangles"
  cut_colours=$(distinct_face_colours "$cut")
  [ "$cut_colours" = "$patches" ] ||
    fail "$name: the patch layout has $cut_colours colours for $patches patches"
  corners=$(ply_vertex_prop "$cut" quality | grep -c '^1$')
  [ "$corners" -gt 0 ] || fail "$name: no patch corner has vertex quality 1"

  # Layer 1: the separatrices as polylines.
  read -r lines chains faces < <(obj_polylines "$sep")
  [ "$lines" -gt 0 ] && [ "$faces" = 0 ] || fail "$name: separatrices.obj: $lines l lines, $faces faces"
  [ "$chains" = "$polylines" ] ||
    fail "$name: separatrices.obj has $chains polylines, the log says $polylines separatrices"
  echo "$name: $colours colours on the input mesh, $cut_colours on the patch layout, $corners corners, $chains separatrices"

  # Same core, same file: fcql finds the same layout.
  if stats=$(cli_stats "$fcql" layout "$name" "$input"); then
    cli_patches=$(json_key "$stats" layout patches)
    cli_tj=$(json_key "$stats" layout t_junctions)
    [ "$cli_patches" = "$patches" ] && [ "$cli_tj" = "$tjunctions" ] ||
      fail "$name: fcql layout finds $cli_patches patches / $cli_tj t-junctions, the plugin $patches / $tjunctions"
  else
    echo "note: fcql layout unavailable for $name, comparison skipped"
  fi
done

ml_finish meshlab_layout
