#!/usr/bin/env bash
# Checks the installed package as a user gets it: installs a build into a temporary
# prefix, configures and builds Examples/Downstream against that prefix only
# (find_package(ClusteredLighting) + ClusteredLighting::RenderingClustered), runs it,
# configures variants of it that enable only CXX or link a VTK module that needs MPI
# (the package finds MPI's C component when needed, or stops with its own message when
# C is not enabled), runs the Python example with the installed clusteredlighting
# package, and builds the project in a directory outside the source tree
# (scripts/check-out-of-source.sh).
# Usage: scripts/check-install.sh [build-dir]   (default: build; run scripts/build.sh first)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="$(cd "${1:-$root/build}" && pwd)"

# One X display for everything below (Debian's VTK needs one even offscreen).
if [ -z "${DISPLAY:-}" ]; then
  exec "$root/scripts/with-display.sh" "$0" "$build_dir"
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/clustered-install.XXXXXX")"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

echo "== install into $prefix"
cmake --install "$build_dir" --prefix "$prefix" > "$work/install.log"
for f in vtkClusteredLightingPass.h vtkClusteredLightSet.h vtkRenderingClusteredModule.h; do
  test -f "$prefix/include/ClusteredLighting/$f" || { echo "missing header $f"; exit 1; }
done
for f in vtkClusteredLightingFrameState.h vtkClusteredLightingGrid.h vtkClusteredLightingGPUResources.h; do
  if [ -e "$prefix/include/ClusteredLighting/$f" ]; then
    echo "private header $f is installed"
    exit 1
  fi
done

echo "== build Examples/Downstream against the installed package"
cmake -S "$root/Examples/Downstream" -B "$work/downstream" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" | tee "$work/configure.log"
grep -q "ClusteredLighting .* from $prefix/" "$work/configure.log" || {
  echo "find_package(ClusteredLighting) did not use the installed copy"
  exit 1
}
cmake --build "$work/downstream" --parallel 2
"$work/downstream/DownstreamApp"

# Variants of the downstream project: its languages, and whether it links a VTK module
# that needs MPI (Debian's VTK::InteractionStyle -> ... -> VTK::mpi -> MPI::MPI_C)
# without asking VTK for it. Configure only; each must end as stated.
downstream_variant() { # name languages extra-link expected(ok|fail) [message]
  local dir="$work/variant-$1"
  mkdir -p "$dir"
  cp "$root/Examples/Downstream/DownstreamApp.cxx" "$dir/"
  cat > "$dir/CMakeLists.txt" << EOF
cmake_minimum_required(VERSION 3.14)
project(Variant LANGUAGES $2)
set(CMAKE_CXX_STANDARD 17)
find_package(ClusteredLighting 0.1 REQUIRED)
find_package(VTK REQUIRED COMPONENTS FiltersSources)
add_executable(DownstreamApp DownstreamApp.cxx)
target_link_libraries(DownstreamApp PRIVATE ClusteredLighting::RenderingClustered
  VTK::FiltersSources $3)
vtk_module_autoinit(TARGETS DownstreamApp
  MODULES ClusteredLighting::RenderingClustered VTK::FiltersSources $3)
EOF
  local rc=0
  cmake -S "$dir" -B "$dir/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
    > "$dir/configure.log" 2>&1 || rc=$?
  if [ "$4" = ok ] && [ "$rc" -ne 0 ]; then
    cat "$dir/configure.log"
    echo "downstream variant '$1' (LANGUAGES $2, links $3) failed to configure"
    exit 1
  fi
  if [ "$4" = fail ]; then
    # CMake wraps long messages: compare without line breaks and indentation.
    if [ "$rc" -eq 0 ] || ! tr -s ' \n' ' ' < "$dir/configure.log" | grep -qF -- "$5"; then
      cat "$dir/configure.log"
      echo "downstream variant '$1' should stop with: $5"
      exit 1
    fi
    if grep -q 'The link interface of target "VTK::mpi"' "$dir/configure.log"; then
      echo "downstream variant '$1' still shows CMake's own link-interface error"
      exit 1
    fi
  fi
  echo "   $1: $([ "$rc" -eq 0 ] && echo configured || echo "stopped with the expected message")"
}
echo "== downstream variants (configure only)"
downstream_variant cxx-only "CXX" "" ok
downstream_variant c-cxx-mpi-module "C CXX" "VTK::InteractionStyle" ok
downstream_variant cxx-only-mpi-module "CXX" "VTK::InteractionStyle" fail \
  "-> VTK::mpi, and the link interface of VTK::mpi names MPI::MPI_C (this VTK was built with MPI), but the C language is not enabled, so MPI's C component cannot be found. Enable C: project(Variant LANGUAGES C CXX)"

python="$(sed -n 's/^CLUSTERED_LIGHTING_PYTHON_EXECUTABLE:[^=]*=//p' "$build_dir/CMakeCache.txt")"
pydest="$(sed -n 's/^CLUSTERED_LIGHTING_PYTHON_DESTINATION:[^=]*=//p' "$build_dir/CMakeCache.txt")"
if [ -n "$pydest" ]; then
  echo "== the installed Python package ($python)"
  export PYTHONPATH="$prefix/$pydest"
  "$python" -c "import clusteredlighting, sys
path = clusteredlighting.vtkRenderingClustered.__file__
print('clusteredlighting', clusteredlighting.__version__, 'from', path)
sys.exit(0 if path.startswith('$prefix/') else 1)"
  "$python" "$root/Examples/Python/many_lights.py" --lights 256 --size 160 120 \
    --output "$work/many-lights-python.png"
fi

echo "== build outside the source tree"
"$root/scripts/check-out-of-source.sh"
echo "== install check passed"
