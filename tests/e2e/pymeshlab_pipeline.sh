#!/usr/bin/env bash
# End-to-end test of the FilterPlugin adapter (MeshLab 2022.02+/2025.07, what pymeshlab loads):
# fcql_pymeshlab_host loads libfilter_fieldquadlayout2025.so through MeshLab 2025.07's own
# plugin manager and runs the pipeline by python names, as `ms.apply_filter(...)` would, on
#   dtorus  fcql's generated double torus cut along its layout (`fcql layout --example
#           double_torus`, layout.ply), and
#   eight   the shared eight.obj (skipped when SHARED_DIR lacks it).
# Per mesh:
#  - All Steps (compute_field_coherent_quad_layout) returns the run's figures under stats.json's
#    names (field.singularities, graph_g.nodes, layout.patches, quad.faces, time_s.*, ...);
#  - the four steps by their own python names, one after the other in the same MeshSet, give
#    the same figures, and the layers they add are there;
#  - the saved "quad mesh" layer has 2 triangles per quad;
#  - `fcql quad` on the mesh as MeshLab loaded it (single-precision coordinates, saved by the
#    host) gives the same patches, t-junctions, quads and irregular vertices.
#
# Usage: pymeshlab_pipeline.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
set -u
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/pymeshlab_host.bash
source "$here/lib/pymeshlab_host.bash"
pm_setup "$build" pymeshlab_pipeline

names=()
files=()
if [ -x "$fcql" ] && "$fcql" layout --example double_torus --out "$work/gen_dtorus" --quiet \
     >"$work/gen_dtorus.log" 2>&1; then
  names+=(dtorus)
  files+=("$work/gen_dtorus/layout.ply")
else
  fail "fcql layout --example double_torus failed (see $work/gen_dtorus.log)"
fi
if [ -n "$shared" ] && [ -f "$shared/data/meshes/eight.obj" ]; then
  names+=(eight)
  files+=("$shared/data/meshes/eight.obj")
else
  echo "note: $shared/data/meshes/eight.obj is absent, shared-mesh checks skipped"
fi

for i in "${!names[@]}"; do
  name=${names[$i]}
  input=${files[$i]}
  as_loaded="$work/${name}_as_loaded.ply"
  quads_ply="$work/${name}_quads.ply"
  out="$work/$name.out"
  # ms.load_new_mesh(input); ms.save_current_mesh(as_loaded);
  # ms.compute_field_coherent_quad_layout(); ms.save_layer('quad mesh')
  if ! host "$out" load "$input" save "$as_loaded" \
         apply compute_field_coherent_quad_layout alpha=20 k=10 phi=10 \
         info save_layer "quad mesh" "$quads_ply"; then
    fail "$name: All Steps through the host failed"; sed 's/^/    /' "$out" | tail -5; continue
  fi
  all=$(dict_of "$out" compute_field_coherent_quad_layout)
  echo "$name: compute_field_coherent_quad_layout -> $all"
  for key in field.singularities field.ports graph_g.nodes graph_h.arcs layout.patches layout.t_junctions \
             quad.faces quad.irregular_vertices quad.base_complex_patches time_s.field time_s.graph \
             time_s.tracing time_s.ilp time_s.quadrangulation time_s.total; do
    [ -n "$(dict_value "$all" "$key")" ] || fail "$name: the returned dict lacks '$key'"
  done
  patches=$(dict_value "$all" layout.patches)
  quads=$(dict_value "$all" quad.faces)
  [ "${patches:-0}" -gt 0 ] && [ "${quads:-0}" -gt 0 ] || fail "$name: no patches or no quads: $all"
  [ "$(dict_value "$all" layout.invalid_patches)" = 0 ] || fail "$name: invalid patches: $all"
  for layer in "candidate separatrices" "separatrices" "patch layout" "quad mesh"; do
    grep -q "^mesh [0-9]* '$layer': " "$out" || fail "$name: no layer '$layer' after All Steps"
  done
  [ "$(ply_faces "$quads_ply")" = $((2 * quads)) ] ||
    fail "$name: the saved quad layer has $(ply_faces "$quads_ply") triangles for $quads quads"

  # The four steps by their python names, in one MeshSet.
  steps="$work/${name}_steps.out"
  if host "$steps" load "$input" \
       apply compute_field_coherent_cross_field \
       apply trace_field_coherent_separatrices \
       apply solve_field_coherent_quad_layout \
       apply quadrangulate_field_coherent_quad_layout info; then
    field=$(dict_of "$steps" compute_field_coherent_cross_field)
    trace=$(dict_of "$steps" trace_field_coherent_separatrices)
    layout=$(dict_of "$steps" solve_field_coherent_quad_layout)
    quad=$(dict_of "$steps" quadrangulate_field_coherent_quad_layout)
    same "$name" "cross field" "$field" "$all" field.singularities field.ports mesh.genus
    same "$name" "trace" "$trace" "$all" graph_g.nodes graph_g.arcs graph_h.arcs graph_h.tangential_pairs
    same "$name" "layout" "$layout" "$all" layout.patches layout.t_junctions layout.separatrices
    same "$name" "quadrangulate" "$quad" "$all" layout.patches quad.faces quad.irregular_vertices
    layers=$(grep -c "^mesh [0-9]* '" "$steps")
    # input + candidates (trace) + separatrices + patch layout (solve) + quad mesh
    [ "$layers" = 5 ] || fail "$name: $layers meshes after the four steps, expected 5"
  else
    fail "$name: the four steps through the host failed"; tail -5 "$steps" | sed 's/^/    /'
  fi

  # The command-line tool on the same single-precision coordinates.
  cli="$work/cli_$name"
  if "$fcql" quad "$as_loaded" --out "$cli" --quiet >"$cli.log" 2>&1 && [ -f "$cli/stats.json" ]; then
    cli_p=$(json_key "$cli/stats.json" layout patches)
    cli_t=$(json_key "$cli/stats.json" layout t_junctions)
    cli_q=$(json_key "$cli/stats.json" quad faces)
    cli_i=$(json_key "$cli/stats.json" quad irregular_vertices)
    echo "$name: fcql quad: $cli_p patches, $cli_t t-junctions, $cli_q quads, $cli_i irregular vertices"
    [ "$cli_p" = "$patches" ] && [ "$cli_t" = "$(dict_value "$all" layout.t_junctions)" ] &&
      [ "$cli_q" = "$quads" ] && [ "$cli_i" = "$(dict_value "$all" quad.irregular_vertices)" ] ||
      fail "$name: fcql quad gives $cli_p patches / $cli_t t-junctions / $cli_q quads / $cli_i irregular, the host $all"
  else
    fail "$name: fcql quad failed on $as_loaded"; tail -3 "$cli.log"
  fi
done

pm_finish pymeshlab_pipeline
