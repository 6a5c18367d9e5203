#!/usr/bin/env bash
# Test job on a fresh Debian bookworm machine: installs what is needed, builds, and runs
# the whole ctest suite (GL-free core tests, real renders under Xvfb, examples, benchmark
# smoke test). Extra arguments go to ctest (e.g. -R Limits, or -L core).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build"
cd "$root/build"
"$root/scripts/run-ctest.sh" "$@"
