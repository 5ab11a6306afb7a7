#!/usr/bin/env bash
# End-to-end test of the MeshLab plugin's "Field-Coherent Quad Layout: All Steps" against the
# four filters run one after the other: examples/all_steps.mlx and examples/step_by_step.mlx on
# generated meshes and on the shared eight.obj.
#
# Checks, per mesh: both scripts succeed and log the same figures (singularities, graphs G and
# H, layout, quad mesh, quality), since All Steps traces on the field as the document stores
# it; both leave the same five layers (0 the input mesh coloured by patch, 1 candidate
# separatrices, 2 separatrices, 3 patch layout, 4 quad mesh), checked against the logged
# counts; All Steps reports the progress of every stage in order.
#
# Usage: meshlab_all_steps.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
ml_setup "$build" meshlab_all_steps
all=$(example_script all_steps) || ml_finish meshlab_all_steps
steps=$(example_script step_by_step) || ml_finish meshlab_all_steps
ml_prepare_meshes "$fcql" "$shared"

figures='^(Singularities|Graph G|Graph H|Layout|Closing|Quad mesh|Quality|Zero chains): '

# check_layers NAME RUN LOG: the five saved layers of RUN agree with LOG.
check_layers() {
  local name=$1 run=$2 log=$3 h layout doc quad
  h=$(log_line "$log" '^Graph H: ')
  doc=$(log_line "$log" '^Input mesh: ')
  quad=$(log_line "$log" '^Quad mesh: ')
  local arcs patches owning polylines q lines chains faces
  arcs=$(number_before "$h" 'candidate separatrices')
  patches=$(number_before "$(log_line "$log" '^Layout: ')" 'patches')
  owning=$(number_before "$doc" "of $patches patches cover")
  polylines=$(number_before "$doc" 'polylines')
  q=$(number_before "$quad" 'quads')
  [ -n "$arcs" ] && [ -n "$patches" ] && [ -n "$q" ] || { fail "$name/$run: figures missing in the log"; return; }
  [ "$(distinct_face_colours "$work/${name}_${run}_0.ply")" = "$owning" ] ||
    fail "$name/$run: layer 0 is not coloured by the $owning patches owning faces"
  read -r lines chains faces < <(obj_polylines "$work/${name}_${run}_1.obj")
  [ "$chains" = "$arcs" ] && [ "$faces" = 0 ] ||
    fail "$name/$run: layer 1 has $chains polylines and $faces faces, expected $arcs candidates"
  read -r lines chains faces < <(obj_polylines "$work/${name}_${run}_2.obj")
  [ "$chains" = "$polylines" ] && [ "$faces" = 0 ] ||
    fail "$name/$run: layer 2 has $chains polylines and $faces faces, expected $polylines separatrices"
  [ "$(distinct_face_colours "$work/${name}_${run}_3.ply")" = "$patches" ] ||
    fail "$name/$run: layer 3 does not have one colour per patch ($patches)"
  [ "$(ply_faces "$work/${name}_${run}_4.ply")" = $((2 * q)) ] ||
    fail "$name/$run: layer 4 does not have 2 x $q triangles"
}

for i in "${!mesh_names[@]}"; do
  name=${mesh_names[$i]}
  input=${mesh_files[$i]}
  ok=1
  for run in all steps; do
    mlx=$all
    [ $run = steps ] && mlx=$steps
    p="$work/${name}_$run"
    if ! run_server "$p.log" -i "$input" -o "${p}_0.ply" -m fc vq sa -o "${p}_1.obj" -l 1 \
           -o "${p}_2.obj" -l 2 -o "${p}_3.ply" -l 3 -m fc sa -o "${p}_4.ply" -l 4 -m ff sa -s "$mlx"; then
      fail "$name/$run: meshlabserver exited with $?"
      tail -20 "$p.log" | sed 's/^/    /'
      ok=0
      continue
    fi
    check_layers "$name" "$run" "$p.log"
  done
  [ $ok = 1 ] || continue
  grep -a '^LOG: ' "$work/${name}_all.log" | sed 's/^LOG: [0-9]* //' | grep -aE "$figures" >"$work/${name}_all.figures"
  # The separate filters log the trace and layout again in Solve Layout and Quadrangulate: keep
  # the first of each.
  grep -a '^LOG: ' "$work/${name}_steps.log" | sed 's/^LOG: [0-9]* //' | grep -aE "$figures" |
    awk '!seen[$0]++' >"$work/${name}_steps.figures"
  if cmp -s "$work/${name}_all.figures" "$work/${name}_steps.figures"; then
    echo "$name: All Steps = the four filters: $(grep -a '^Quad mesh' "$work/${name}_all.figures")"
  else
    fail "$name: All Steps and the separate filters differ:"
    diff "$work/${name}_all.figures" "$work/${name}_steps.figures" | sed 's/^/    /'
  fi
  # Progress of every stage, in order (meshlabserver prints a message only when the percentage
  # changes, so the messages checked are ones that move it).
  order=$(grep -aoE 'Field-Coherent Quad Layout: (cross field|tracing separatrices|cutting the surface into patches|quad layer|quad mesh done)$' \
            "$work/${name}_all.log" | awk '!seen[$0]++' | sed 's/.*: //' | tr '\n' ';')
  [ "$order" = "cross field;tracing separatrices;cutting the surface into patches;quad layer;quad mesh done;" ] ||
    fail "$name: All Steps progress out of order: $order"
done

ml_finish meshlab_all_steps
