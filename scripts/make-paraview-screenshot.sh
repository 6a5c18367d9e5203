#!/usr/bin/env bash
# Takes docs/images/paraview-gui.png: the ParaView GUI, connected to pvserver on 2 MPI
# ranks (client-server mode), with the plugin loaded on both sides, a Clustered Lighting
# view of an isosurface lit by 16,384 pipeline-fed lights and two Light Inspector lights,
# and the Properties panel showing the view's and the representation's properties
# (Plugins/ParaView/Demo/gui_scene.py). Everything runs under a private Xvfb server; the
# screenshot is taken with ImageMagick's import, the window sized with xdotool (both
# installed here if missing; not needed by the plugin or its tests).
# Writes output.png (the View panel), output-display.png (the Display panel) and
# output-advanced.png (the View panel with its advanced properties, scrolled to the end).
# Usage: scripts/make-paraview-screenshot.sh [output.png]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(realpath -m "${1:-$root/docs/images/paraview-gui.png}")"
here="$root/Plugins/ParaView/Testing"
if [ -z "${CLUSTERED_LIGHTING_IN_XVFB:-}" ]; then
  "$root/scripts/install-paraview.sh"
  # ImageMagick (import), xdotool, and Qt's SVG module for ParaView's toolbar icons.
  missing=()
  for p in imagemagick xdotool libqt5svg5; do
    dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" ||
      missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
      "${missing[@]}" > /dev/null
  fi
  plugin="$root/build-paraview/lib/paraview-5.11/plugins/ClusteredLighting/ClusteredLighting.so"
  [ -f "$plugin" ] || "$root/scripts/build-paraview-plugin.sh" "$root/build-paraview" > /dev/null
  export CLUSTERED_LIGHTING_PLUGIN="$plugin"
  XVFB_SCREEN=1600x1200x24 exec "$here/with-xvfb.sh" env CLUSTERED_LIGHTING_IN_XVFB=1 \
    "$0" "$@"
fi
prefix=${CLUSTERED_LIGHTING_PARAVIEW_PREFIX:-/opt/clustered-lighting/paraview-5.11}
export PYTHONPATH="$prefix/python3-paraview/usr/lib/python3/dist-packages"
work="$(mktemp -d "${TMPDIR:-/tmp}/paraview-gui.XXXXXX")"
export HOME="$work" # no user settings of this machine's ParaView, but these:
mkdir -p "$HOME/.config/ParaView"
# Source, display and view properties in separate panels (the view's on screen).
cat > "$HOME/.config/ParaView/ParaView-UserSettings.json" << 'JSON'
{ "settings" : { "GeneralSettings" : { "PropertiesPanelMode" : 3 } } }
JSON
# No welcome dialog (it waits for a click).
printf '[General]\nGeneralSettings.ShowWelcomeDialog=false\n' > "$HOME/.config/ParaView/ParaView5.11.0.ini"
export CLUSTERED_LIGHTING_READY="$work/ready"
port=$(/usr/bin/python3 -c \
  'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')
mpi=(--oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
: > "$work/pvserver.log"
mpirun "${mpi[@]}" -np 2 pvserver --force-offscreen-rendering --server-port="$port" \
  > "$work/pvserver.log" 2>&1 &
server=$!
for _ in $(seq 120); do
  grep -q "Accepting connection" "$work/pvserver.log" && break
  sleep 0.5
done
paraview --server-url="cs://localhost:$port" \
  --script="$root/Plugins/ParaView/Demo/gui_scene.py" > "$work/paraview.log" 2>&1 &
client=$!
cleanup() {
  kill "$client" 2> /dev/null || true
  wait "$client" 2> /dev/null || true
  for _ in $(seq 20); do
    kill -0 "$server" 2> /dev/null || break
    sleep 0.5
  done
  kill "$server" 2> /dev/null || true
  wait "$server" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
for _ in $(seq 240); do
  [ -f "$CLUSTERED_LIGHTING_READY" ] && break
  kill -0 "$client" 2> /dev/null || { cat "$work/paraview.log"; exit 1; }
  sleep 0.5
done
[ -f "$CLUSTERED_LIGHTING_READY" ] || {
  echo "the GUI scene did not finish:" >&2
  cat "$work/paraview.log" >&2
  import -window root "$work/../paraview-gui-failed.png" || true
  exit 1
}
sleep 3
window=$(xdotool search --sync --onlyvisible --name "ParaView" | head -n 1)
for _ in $(seq 10); do # (no window manager: the first request may come too early)
  xdotool windowmove "$window" 0 0 windowsize "$window" 1600 1200
  sleep 1
  xdotool getwindowgeometry "$window" | grep -q "Geometry: 1600x1200" && break
done
xdotool getwindowgeometry "$window"
sleep 8 # the GUI repaints, the view renders
shot() { # shot <file>: the whole screen
  import -window root "$1"
}
if [ -n "${CLUSTERED_LIGHTING_SCREENSHOT_STEPS:-}" ]; then
  shot "$out.step1.png"
fi
# Places in ParaView 5.11's default window at 1600 x 1200 (measured on the first
# screenshot of this script): the panels' tabs (Properties, View, Display, Information)
# at y = 524, View at x = 118, Display at x = 183; a panel's "advanced" toggle at
# (300, 578). Clicks need the pointer moved first (--sync), then a separate click; the first
# click on the window goes to no widget.
click() { # click <x> <y>
  xdotool mousemove --sync "$1" "$2"
  sleep 0.5
  xdotool click 1
  sleep 3
}
click 118 524 # View (the first click on the window only makes it active)
click 118 524 # View
shot "$out"
echo "wrote $out"
click 183 524 # Display
shot "${out%.png}-display.png"
echo "wrote ${out%.png}-display.png"
click 118 524 # View
click 300 578 # advanced properties
xdotool mousemove --sync 150 900 click --repeat 60 --delay 40 5 # scroll to the end
sleep 3
shot "${out%.png}-advanced.png"
echo "wrote ${out%.png}-advanced.png"
grep -i -E "error|warn" "$work/paraview.log" | grep -v -i "deprecat" || true
