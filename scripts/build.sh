#!/usr/bin/env bash
# Configures and builds ClusteredLighting (Release: VTK 9.1's debug test driver enables
# FP exceptions that crash Mesa's llvmpipe). Usage: scripts/build.sh [build-dir] [cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build_dir" --parallel "$(nproc)"
