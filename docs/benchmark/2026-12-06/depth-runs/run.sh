#!/usr/bin/env bash
# Builds depth_bounds_timing.cxx against the header at BASE (default 7129128, before the
# runs) and at the working tree, and runs them alternately, ten processes each: one
# process's best of 15 is steady, but from process to process it moves between two levels
# (the memory each one gets), so the processes' results are all printed.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../../.." && pwd)"
base="${BASE:-7129128}"
tmp="$(mktemp -d)"
mkdir -p "$tmp/base"
git -C "$root" show "$base:Rendering/Core/vtkClusteredLightingDepthBounds.h" \
  > "$tmp/base/vtkClusteredLightingDepthBounds.h"
flags=(-O3 -std=c++17 -I"$root/Rendering/Core" -I"$root/Testing/Unit")
g++ "${flags[@]}" -I"$tmp/base" "$here/depth_bounds_timing.cxx" -o "$tmp/base.bin" \
  -iquote "$tmp/base"
g++ "${flags[@]}" "$here/depth_bounds_timing.cxx" -o "$tmp/now.bin"
for round in $(seq 10); do
  echo "round $round base ($base): $("$tmp/base.bin")"
  echo "round $round now: $("$tmp/now.bin")"
done
rm -rf "$tmp"
