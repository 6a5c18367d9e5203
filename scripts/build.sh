#!/usr/bin/env bash
# Configures and builds ClusteredLighting (Release: VTK 9.1's debug test driver enables
# FP exceptions that crash Mesa's llvmpipe). Usage: scripts/build.sh [build-dir] [cmake args...]
# CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS=ON in the environment (as .ci/run sets it) makes
# warnings in our own code errors.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
werror=()
if [ -n "${CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS:-}" ]; then
  werror=(-DCLUSTERED_LIGHTING_WARNINGS_AS_ERRORS="$CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS")
fi
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "${werror[@]}" "$@"
cmake --build "$build_dir" --parallel "$(nproc)"
