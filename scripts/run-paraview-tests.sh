#!/usr/bin/env bash
# CI stage for ParaView 5.11 (Debian's, with its own VTK 9.2), on a fresh Debian bookworm
# machine, as root or with sudo:
#  1. installs what is needed (scripts/install-deps.sh, scripts/install-paraview.sh);
#  2. builds the project against ParaView's VTK 9.2 (build-vtk92: warnings as errors,
#     Python wrapping off: Debian's python3 loads Debian's VTK 9.1) and runs its C++
#     ctest suite there: every test that uses VTK, as against VTK 9.1 (the GL-free core's
#     unit tests and lint, which use no VTK, ran in scripts/run-tests.sh; the benchmark's
#     smoke test, a tool's, too);
#  3. builds the ParaView plugin in its own build tree (build-paraview);
#  4. runs the plugin's pvbatch tests at 1, 2 and 4 MPI ranks (ctest in build-paraview).
# Every X display is a private Xvfb server that picked a free display number itself
# (Plugins/ParaView/Testing/with-xvfb.sh). Prints the time of each step.
# Usage: scripts/run-paraview-tests.sh [ctest args for the pvbatch tests, e.g. -L np1]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
prefix=${CLUSTERED_LIGHTING_PARAVIEW_PREFIX:-/opt/clustered-lighting/paraview-5.11}
export CLUSTERED_LIGHTING_PARAVIEW_PREFIX="$prefix"
vtk92_dir="$prefix/overlay/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk"
export CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS=${CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS:-ON}
times=()
step() { # step <name> <command...>: runs and times one step
  local name=$1 start=$SECONDS
  shift
  echo "=== $name"
  "$@"
  times+=("$name $((SECONDS - start)) s")
}

step "install" bash -c "'$root/scripts/install-deps.sh' && '$root/scripts/install-paraview.sh'"
step "build against VTK 9.2" nice -n 10 "$root/scripts/build.sh" "$root/build-vtk92" \
  -DVTK_DIR="$vtk92_dir" -DCLUSTERED_LIGHTING_WRAP_PYTHON=OFF \
  -DCLUSTERED_LIGHTING_BUILD_CORE_TESTS=OFF
# The library must link ParaView's VTK only.
if ldd "$root/build-vtk92/lib/libvtkRenderingClustered.so" | grep -q "libvtk.*-9\.1"; then
  echo "build-vtk92 links Debian's VTK 9.1" >&2
  exit 1
fi
step "C++ ctest against VTK 9.2" bash -c "cd '$root/build-vtk92' && \
  '$root/Plugins/ParaView/Testing/with-xvfb.sh' '$root/scripts/run-ctest.sh' -LE benchmark"
step "build the plugin" nice -n 10 "$root/scripts/build-paraview-plugin.sh" \
  "$root/build-paraview"
step "pvbatch tests" bash -c "cd '$root/build-paraview' && \
  ctest --output-on-failure $(printf "'%s' " "$@")"

echo "=== ParaView stage:"
printf '  %s\n' "${times[@]}"
