#!/usr/bin/env bash
# Configures and builds the ParaView plugin (Plugins/ParaView) against Debian's ParaView
# 5.11 in its own build tree (default build-paraview), through the overlay prefix of
# scripts/install-paraview.sh (run that first; it is idempotent).
# Usage: scripts/build-paraview-plugin.sh [build-dir] [cmake args...]
# CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS=ON in the environment makes warnings in our code
# errors, as for the main build. The plugin is then
#   <build-dir>/lib/paraview-5.11/plugins/ClusteredLighting/ClusteredLighting.so
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir=${1:-"$root/build-paraview"}
shift || true
prefix=${CLUSTERED_LIGHTING_PARAVIEW_PREFIX:-/opt/clustered-lighting/paraview-5.11}
paraview_dir="$prefix/overlay/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11"
if [ ! -f "$paraview_dir/paraview-config.cmake" ]; then
  echo "No overlay prefix at $prefix: run scripts/install-paraview.sh first." >&2
  exit 1
fi
werror=()
if [ -n "${CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS:-}" ]; then
  werror=(-DCLUSTERED_LIGHTING_WARNINGS_AS_ERRORS="$CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS")
fi
cmake -S "$root/Plugins/ParaView" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DParaView_DIR="$paraview_dir" -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DCLUSTERED_LIGHTING_PARAVIEW_PREFIX="$prefix" "${werror[@]}" "$@"
cmake --build "$build_dir" --parallel "${CLUSTERED_LIGHTING_JOBS:-2}"
