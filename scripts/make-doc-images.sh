#!/usr/bin/env bash
# Regenerates the README's images in docs/images from the examples (run scripts/build.sh
# first). Usage: scripts/make-doc-images.sh [build-dir]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="$(cd "${1:-$root/build}" && pwd)"
if [ -z "${DISPLAY:-}" ]; then
  exec "$root/scripts/with-display.sh" "$0" "$build_dir"
fi
out="$root/docs/images"
mkdir -p "$out"

# 4,096 lights over the bunny, and the lights-per-pixel heat map of the same view.
"$build_dir/Examples/ManyLights" --frames 1 --brute-frames 0 \
  --output "$out/many-lights.png" --heatmap "$out/many-lights-heatmap.png"
# 2,048 lights driven by a VTK pipeline (last frame of the animation), and its heat map.
"$build_dir/Examples/PipelineLights" \
  --output "$out/pipeline-lights.png" --heatmap "$out/pipeline-lights-heatmap.png"
# The Python example (the lights built as a vtkPolyData in Python).
python="$(sed -n 's/^CLUSTERED_LIGHTING_PYTHON_EXECUTABLE:[^=]*=//p' "$build_dir/CMakeCache.txt")"
pydest="$(sed -n 's/^CLUSTERED_LIGHTING_PYTHON_DESTINATION:[^=]*=//p' "$build_dir/CMakeCache.txt")"
if [ -n "$pydest" ]; then
  PYTHONPATH="$build_dir/$pydest" "$python" "$root/Examples/Python/many_lights.py" \
    --size 800 600 --output "$out/many-lights-python.png"
fi
