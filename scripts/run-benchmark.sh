#!/usr/bin/env bash
# Reproduces the published benchmark results (docs/benchmark/): installs what is needed,
# builds, and runs the full benchmark at 1024x768 (about an hour on 2 cores). Extra
# arguments go to the benchmark (e.g. --quick for the 2-minute version, --output DIR).
# Run it on an otherwise idle machine: the numbers are wall-clock frame times.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build" > /dev/null
export MESA_SHADER_CACHE_DISABLE=true # compile times of stock VTK are part of the results
"$root/scripts/with-display.sh" "$root/build/Testing/Benchmark/ClusteredLightingBenchmark" \
  --output "$root/docs/benchmark" "$@"
