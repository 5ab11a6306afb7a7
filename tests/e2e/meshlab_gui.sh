#!/usr/bin/env bash
# GUI smoke test of the MeshLab 2020.09 plugin: the `meshlab` GUI of the overlay prefix (Debian's
# executable, io_base and libfilter_fieldquadlayout.so) on a private Xvfb display without a
# window manager, driven with xdotool.
#
# Checks:
#   1. MeshLab starts with the overlay's plugin folder and opens the mesh given on the command
#      line (its log on stdout);
#   2. Filters -> Remeshing, Simplification and Reconstruction holds the five filters: each
#      entry of the submenu, chosen with the keyboard, opens a parameter dialog whose title is
#      one of the five filter names, and all five come up (screenshot of the open submenu);
#   3. All Steps, applied from its dialog on the loaded mesh, succeeds ("Applied filter ..."
#      in the log, no "Failure of filter" box) with its figures in the log;
#   4. the document holds its result: File -> Export Mesh As saves layer 0 (the input mesh)
#      from the GUI, and the saved PLY has the input's faces coloured by patch, one colour per
#      patch owning faces as the log counts them.
# Screenshots: BUILD_DIR/test-artifacts/meshlab_gui_menu.png (the submenu),
# meshlab_gui.png (after All Steps: five layers), meshlab_gui_failure.png (on a failure).
#
# The mesh is the shared eight.obj (genus 2, about 4 s for All Steps) as OFF, since MeshLab
# 2020.09 aborts on OBJ input; without it a generated 6x6x6 cube. Every wait has a timeout and
# the GUI and Xvfb are killed on exit.
#
# Usage: meshlab_gui.sh FCQL SHARED_DIR BUILD_DIR      (exit 0 pass, 1 fail, 77 skip)
# shellcheck disable=SC2317  # functions called through wait_for and the traps
set -u
# The whole test is bounded: it runs under timeout(1), which on expiry signals the test's
# process group (the GUI, Xvfb, xdotool) and the EXIT trap below cleans up.
if [ -z "${FCQL_GUI_BOUNDED:-}" ]; then
  FCQL_GUI_BOUNDED=1 exec timeout -k 5 "${FCQL_GUI_TIMEOUT:-150}" "$0" "$@"
fi
fcql=${1:-}
shared=${2:-}
build=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=lib/meshlab_overlay.bash
source "$here/lib/meshlab_overlay.bash"
: "$fcql"

# xdotool and imagemagick's import: installed by scripts/setup.sh; as root with apt-get, the
# test installs them itself when they are missing (FCQL_NO_INSTALL=1 prevents it).
if ! command -v xdotool >/dev/null || ! command -v import >/dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null && [ -z "${FCQL_NO_INSTALL:-}" ]; then
    echo "note: installing xdotool and imagemagick"
    export DEBIAN_FRONTEND=noninteractive
    { timeout 300 apt-get install -y -qq --no-install-recommends xdotool imagemagick ||
      { timeout 300 apt-get update -qq &&
        timeout 300 apt-get install -y -qq --no-install-recommends xdotool imagemagick; }; } >/dev/null 2>&1
  fi
  command -v xdotool >/dev/null || skip "xdotool is not installed (scripts/setup.sh installs it)"
  command -v import >/dev/null || skip "imagemagick's import is not installed (scripts/setup.sh installs it)"
fi
command -v Xvfb >/dev/null || skip "Xvfb is not installed"
[ -x /usr/bin/meshlab ] || skip "Debian's meshlab GUI is not installed"
ml_setup "$build" meshlab_gui
# Absolute paths: MeshLab runs in the work dir.
work=$(cd "$work" && pwd)
prefix="$work/prefix"
plugins="$prefix/lib/x86_64-linux-gnu/meshlab/plugins"
cp /usr/bin/meshlab "$prefix/bin/"
artifacts="$build/test-artifacts"
mkdir -p "$artifacts"
rm -f "$artifacts"/meshlab_gui*.png

if [ -n "$shared" ] && [ -f "$shared/data/meshes/eight.obj" ]; then
  mesh_name=eight
  obj_to_off "$shared/data/meshes/eight.obj" "$work/eight.off"
else
  echo "note: $shared/data/meshes/eight.obj is absent, running on a generated cube"
  mesh_name=cube
  write_cube "$work/cube.off" 6
fi
mesh="$work/$mesh_name.off"
mesh_faces=$(off_faces "$mesh")

filters=("All Steps" "Compute Cross Field" "Quadrangulate" "Solve Layout" "Trace Separatrices")
log="$work/gui.log"
xvfb_pid=
gui_pid=

cleanup() {
  [ -n "$gui_pid" ] && kill "$gui_pid" 2>/dev/null
  [ -n "$gui_pid" ] && { sleep 0.5; kill -9 "$gui_pid" 2>/dev/null; }
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
  wait 2>/dev/null
}
trap cleanup EXIT
trap 'echo "FAIL: meshlab_gui interrupted or timed out (logs in $work)"; exit 1' INT TERM

shot() { import -window root "$1" 2>/dev/null; }
# abort MESSAGE: a failure that stops the test (a screenshot and the visible windows first).
abort() {
  fail "$*"
  shot "$artifacts/meshlab_gui_failure.png"
  echo "  visible windows: $(visible_windows | tr '\n' ';')"
  echo "  GUI log: $log (last lines below)"
  tail -15 "$log" | sed 's/^/    /'
  ml_finish meshlab_gui
}
visible_windows() {
  xdotool search --onlyvisible --name . 2>/dev/null | while read -r w; do xdotool getwindowname "$w"; done |
    grep -v '^MeshLab_64bit_fp$' | sort -u
}
# wait_for SECONDS COMMAND...: polls COMMAND every 0.2 s until it succeeds or SECONDS pass.
wait_for() {
  local end=$((SECONDS + $1))
  shift
  until "$@"; do
    [ $SECONDS -lt $end ] || return 1
    sleep 0.2
  done
}
window_named() { xdotool search --onlyvisible --name "$1" >/dev/null 2>&1; }
no_window_named() { ! window_named "$1"; }
log_has() { grep -aqE -- "$1" "$log"; }
# focus_main: gives the keyboard to the main window (there is no window manager).
focus_main() { xdotool windowfocus --sync "$main_win" 2>/dev/null; sleep 0.2; }

# ---- Xvfb and MeshLab -----------------------------------------------------------------------
# A 1280x1024 screen: the All Steps dialog, with every parameter of the four stages, is taller
# than 768 pixels (the MeshLab window itself stays 1024x768).
exec 5>"$work/display"
Xvfb -displayfd 5 -screen 0 1280x1024x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 5>&-
wait_for 10 test -s "$work/display" || abort "Xvfb did not start"
DISPLAY=":$(head -1 "$work/display")"
export DISPLAY
export XDG_CONFIG_HOME="$work/xdg" XDG_RUNTIME_DIR="$work/xdg"
t0=$SECONDS

(cd "$work" && exec "$prefix/bin/meshlab" "$mesh") >"$log" 2>&1 &
gui_pid=$!
wait_for 20 window_named '^MeshLab 2020' || abort "no MeshLab window after 20 s"
main_win=$(xdotool search --onlyvisible --name '^MeshLab 2020' | head -1)
wait_for 10 log_has "^LOG: [0-9]+ Opened mesh .*$mesh_name.off" || abort "MeshLab did not open $mesh"
# The whole screen (MeshLab sets its own size once it is up: repeat until it holds).
full_screen() {
  xdotool windowmove "$main_win" 0 0 windowsize "$main_win" 1024 768
  sleep 0.3
  xdotool getwindowgeometry "$main_win" | grep -q 'Geometry: 1024x768'
}
wait_for 5 full_screen || fail "could not resize the MeshLab window to 1024x768"
grep -aqF "Current Plugins Dir is: $plugins" "$log" ||
  fail "MeshLab did not take its plugins from the overlay ($plugins): $(grep -a 'Plugins Dir' "$log")"
sleep 0.5

# ---- the five filters in Filters -> Remeshing, Simplification and Reconstruction ----------
# Keyboard only: Alt selects the menu bar, Right Right goes to Filters, Down opens it (first
# enabled entry selected), Up wraps to the last class submenu (Camera); twelve more Up reach
# "Remeshing, Simplification and Reconstruction" (MeshLab 2020.09's fixed order of the class
# submenus); Right opens it with its first entry selected.
open_remeshing_menu() {
  focus_main
  xdotool key alt
  sleep 0.2
  xdotool key Right Right Down Up
  local i
  for i in $(seq 12); do xdotool key Up; done
  xdotool key Right
  sleep 0.4
}
# dialog_button DIALOG left|right: clicks Close (left) or Apply (right), the bottom row of a
# MeshLab filter dialog.
dialog_button() {
  local WIDTH=0 HEIGHT=0 x
  eval "$(xdotool getwindowgeometry --shell "$1" | grep -E '^(WIDTH|HEIGHT)=[0-9]+$')"
  x=$((WIDTH / 4))
  [ "$2" = right ] && x=$((WIDTH * 3 / 4))
  xdotool mousemove --window "$1" "$x" $((HEIGHT - 22)) click 1
}
dialog_window() { xdotool search --onlyvisible --name '^Field-Coherent Quad Layout: ' 2>/dev/null | head -1; }

seen=()
for i in "${!filters[@]}"; do
  open_remeshing_menu
  [ "$i" = 0 ] && shot "$artifacts/meshlab_gui_menu.png"
  for _ in $(seq "$i"); do xdotool key Down; done
  xdotool key Return
  if ! wait_for 10 window_named '^Field-Coherent Quad Layout: '; then
    abort "entry $((i + 1)) of the Remeshing submenu opened no Field-Coherent Quad Layout dialog"
  fi
  dlg=$(dialog_window)
  title=$(xdotool getwindowname "$dlg")
  seen+=("${title#Field-Coherent Quad Layout: }")
  dialog_button "$dlg" left
  wait_for 5 no_window_named '^Field-Coherent Quad Layout: ' || abort "the dialog \"$title\" did not close"
done
got=$(printf '%s\n' "${seen[@]}" | sort | tr '\n' ';')
want=$(printf '%s\n' "${filters[@]}" | sort | tr '\n' ';')
if [ "$got" = "$want" ]; then
  echo "Filters menu: the five filters (${got%;})"
else
  abort "the Remeshing submenu's entries opened \"$got\", expected \"$want\""
fi

# ---- All Steps on the loaded mesh ------------------------------------------------------------
open_remeshing_menu
xdotool key Return
wait_for 10 window_named '^Field-Coherent Quad Layout: All Steps$' || abort "the All Steps dialog did not open"
dlg=$(dialog_window)
t1=$SECONDS
dialog_button "$dlg" right
failed_box() { window_named 'Failure|Error'; }
done_or_failed() { log_has '^LOG: [0-9]+ Applied filter Field-Coherent Quad Layout: All Steps' || failed_box; }
wait_for 60 done_or_failed || abort "All Steps did not finish within 60 s"
failed_box && abort "All Steps failed: a box \"$(visible_windows | grep -i 'rror\|fail' | head -1)\" came up"
echo "All Steps: applied in $((SECONDS - t1)) s; $(log_line "$log" '^Quad mesh: ')"
for figure in '^Singularities: ' '^Graph H: ' '^Layout: ' '^Quad mesh: [0-9]+ quads' '^Layer "quad mesh": '; do
  [ -n "$(log_line "$log" "$figure")" ] || fail "All Steps logged no \"$figure\" line"
done
dialog_button "$dlg" left
wait_for 5 no_window_named '^Field-Coherent Quad Layout: ' || fail "the All Steps dialog did not close"
# Turn the mesh a little (a drag in the 3D view) so that the screenshot shows its patches.
xdotool mousemove --window "$main_win" 300 300 mousedown 1
for i in $(seq 10); do xdotool mousemove --window "$main_win" 300 $((300 + 10 * i)); sleep 0.03; done
xdotool mouseup 1
sleep 0.7
shot "$artifacts/meshlab_gui.png"

# ---- the document: layer 0 exported from the GUI -------------------------------------------
owning=$(number_before "$(log_line "$log" '^Input mesh: ')" 'of [0-9]+ patches cover')
saved="$work/gui_saved.ply"
focus_main
xdotool key ctrl+shift+e
wait_for 10 window_named "^Save \"$mesh_name.off\" Layer" ||
  abort "File -> Export Mesh As (Ctrl+Shift+E) opened no save dialog for layer 0 ($mesh_name.off)"
xdotool windowfocus --sync "$(xdotool search --onlyvisible --name '^Save ".*" Layer' | head -1)"
sleep 0.3
xdotool key ctrl+a
xdotool type --delay 5 "$saved"
xdotool key Return
wait_for 10 window_named '^Choose Saving Options' || abort "no saving options dialog after the file dialog"
xdotool windowfocus --sync "$(xdotool search --onlyvisible --name '^Choose Saving Options' | head -1)"
sleep 0.3
xdotool key Return
wait_for 10 log_has "^LOG: [0-9]+ Saved Mesh .*gui_saved.ply" || abort "MeshLab did not save $saved"
# The GUI writes binary PLY: meshlabserver turns it into ASCII for the awk helpers.
if run_server "$work/convert_saved.log" -i "$saved" -o "$work/gui_saved_ascii.ply" -m fc sa; then
  faces=$(ply_faces "$work/gui_saved_ascii.ply")
  colours=$(distinct_face_colours "$work/gui_saved_ascii.ply")
  [ "$faces" = "$mesh_faces" ] || fail "the exported layer 0 has $faces faces, the input $mesh_faces"
  if [ -n "$owning" ] && [ "$colours" = "$owning" ]; then
    echo "Exported layer 0: $faces faces in $colours patch colours"
  else
    fail "the exported layer 0 has $colours face colours, expected one per patch owning faces ($owning)"
  fi
else
  fail "meshlabserver could not read the PLY the GUI saved"
fi

echo "GUI session: $((SECONDS - t0)) s; screenshots in $artifacts"
ml_finish meshlab_gui
