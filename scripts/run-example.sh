#!/usr/bin/env bash
# Main job on a fresh Debian bookworm machine: installs what is needed, builds, and runs
# the many-lights example (4,096 point lights over the Stanford bunny at 1024x768). It
# writes many-lights.png and many-lights-heatmap.png in the current directory and prints
# the clustered frame time next to the brute-force frame time of the same scene.
# Extra arguments go to the example (e.g. --lights 16384, or -I for an interactive window).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build" > /dev/null
"$root/scripts/with-display.sh" "$root/build/Examples/ManyLights" \
  --output many-lights.png --heatmap many-lights-heatmap.png "$@"
