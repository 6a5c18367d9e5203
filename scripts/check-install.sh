#!/usr/bin/env bash
# Checks the installed package as a user gets it: installs a build into a temporary
# prefix, configures and builds Examples/Downstream against that prefix only
# (find_package(ClusteredLighting) + ClusteredLighting::RenderingClustered), runs it, and
# runs the Python example with the installed clusteredlighting package.
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
echo "== install check passed"
