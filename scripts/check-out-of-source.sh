#!/usr/bin/env bash
# Checks that ClusteredLighting builds from a build directory outside the source tree, as
# IDEs, packagers and CI place them, and that doing so writes nothing into the sources:
#  1. configures the project (default options: tests, examples and Python on) in a
#     temporary directory outside the source tree, builds the library and its Python
#     module there, and imports the package from that build;
#  2. configures the module as VTK's Remote/ build sees it (a parent project whose
#     vtk_module_scan/vtk_module_build pick up a copy of the repository) to check module
#     mode;
#  3. compares `git status --porcelain --ignored` (or, outside a git checkout, the files
#     newer than the start) of the source tree before and after: nothing may appear.
# Run by scripts/check-install.sh. Usage: scripts/check-out-of-source.sh [cmake args...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)

work="$(mktemp -d "${TMPDIR:-/tmp}/clustered-out-of-source.XXXXXX")"
trap 'rm -rf "$work"' EXIT
case "$work/" in
  "$root"/*) echo "the temporary directory $work is inside the source tree"; exit 1 ;;
esac

snapshot() {
  if git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    git -C "$root" status --porcelain --ignored --untracked-files=all -- . \
      ':(exclude)build*' | sort
  else
    find "$root" -path "$root/build*" -prune -o -newer "$work/start" -print | sort
  fi
}
touch "$work/start"
sleep 1 # time stamps of files written after this are newer than the start
snapshot > "$work/before"

build="$work/some/other/dir"
echo "== configure in $build"
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
echo "== build the library and its Python module there"
targets=(RenderingClustered)
if grep -q "^CLUSTERED_LIGHTING_WRAP_PYTHON:BOOL=ON" "$build/CMakeCache.txt"; then
  targets+=(vtkRenderingClusteredPython)
fi
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"
ls "$build"/lib/libvtkRenderingClustered*.so* > /dev/null
if [[ " ${targets[*]} " == *" vtkRenderingClusteredPython "* ]]; then
  python="$(sed -n 's/^CLUSTERED_LIGHTING_PYTHON_EXECUTABLE:[^=]*=//p' "$build/CMakeCache.txt")"
  pydest="$(sed -n 's/^CLUSTERED_LIGHTING_PYTHON_DESTINATION:[^=]*=//p' "$build/CMakeCache.txt")"
  PYTHONPATH="$build/$pydest" "$python" -c "import clusteredlighting, sys
path = clusteredlighting.vtkRenderingClustered.__file__
print('clusteredlighting', clusteredlighting.__version__, 'from', path)
sys.exit(0 if path.startswith('$build/') else 1)"
fi

echo "== module mode, as in VTK's Remote/ build (configure only)"
remote="$work/vtk-like"
mkdir -p "$remote/Remote/ClusteredLighting"
# The working tree as it is (tracked and new files, not ignored ones such as build/).
if git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  (cd "$root" && git ls-files -z --cached --others --exclude-standard |
    tar --null -T - --ignore-failed-read -cf - 2> /dev/null) |
    tar -xf - -C "$remote/Remote/ClusteredLighting"
else
  (cd "$root" && find . -path './build*' -prune -o -type f -print0 |
    tar --null -T - -cf -) | tar -xf - -C "$remote/Remote/ClusteredLighting"
fi
cat > "$remote/CMakeLists.txt" << 'EOF'
# A parent project that builds ClusteredLighting as a module of its own, the way VTK's
# Remote/ directory does: the module's CMakeLists.txt runs in module mode.
cmake_minimum_required(VERSION 3.14)
project(VTKLike LANGUAGES C CXX)
include(GNUInstallDirs)
set(BUILD_SHARED_LIBS ON)
set(CMAKE_CXX_STANDARD 17)
include(CTest)
find_package(VTK 9.1 REQUIRED COMPONENTS CommonCore CommonDataModel CommonExecutionModel
  CommonMath CommonTransforms RenderingCore RenderingOpenGL2
  # the module's TEST_DEPENDS: its Testing/ directory is configured too
  TestingCore TestingRendering FiltersCore FiltersGeneral FiltersModeling FiltersSources
  IOGeometry IOImport InteractionStyle)
vtk_module_scan(
  MODULE_FILES "${CMAKE_CURRENT_SOURCE_DIR}/Remote/ClusteredLighting/vtk.module"
  REQUEST_MODULES ClusteredLighting::RenderingClustered
  PROVIDES_MODULES modules
  ENABLE_TESTS ON)
vtk_module_build(MODULES ${modules} INSTALL_HEADERS OFF)
if (NOT TARGET ClusteredLighting::RenderingClustered OR
    NOT TARGET vtkRenderingClusteredCxxTests)
  message(FATAL_ERROR "module mode did not declare the module and its tests")
endif ()
EOF
cmake -S "$remote" -B "$remote/build" "${generator[@]}" > "$work/remote.log" 2>&1 ||
  { cat "$work/remote.log"; exit 1; }

echo "== the source tree is unchanged"
snapshot > "$work/after"
if ! diff "$work/before" "$work/after"; then
  echo "building outside the source tree changed the source tree (lines above: > new)"
  exit 1
fi
echo "== out-of-source check passed"
