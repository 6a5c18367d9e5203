#!/usr/bin/env bash
# Scale demonstration of the ParaView plugin (docs/ParaView.md): 65,536 clustered lights
# fed from a pipeline over an isosurface of a 201^3 Wavelet, rendered at 1024 x 768 by
# pvbatch on 1, 2 and 4 MPI ranks, one after the other in this one run
# (Plugins/ParaView/Demo/scale_demo.py). Prints a table of the frame times.
# Installs and builds what is missing (scripts/install-paraview.sh,
# scripts/build-paraview-plugin.sh). llvmpipe gets the machine's cores shared between
# the ranks (LP_NUM_THREADS = cores / ranks, at least 1).
# Usage: scripts/run-paraview-demo.sh [--wait-idle] [--docs | --table] [ranks...]
#   ranks: default 1 2 4
#   --wait-idle: before each rank count, wait (up to an hour) until the CPUs were more
#     than 90% idle for 10 s: on a machine shared with other work, each measurement then
#     starts on idle CPUs (the table prints the load averages)
#   --docs: copy the last rank count's images to docs/images/paraview-scale-demo*.png
#   --table: print the table of the last run again (from build-paraview/demo/*.log)
# Run it on an otherwise idle machine: the numbers are wall-clock frame times.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
docs=false
table_only=false
wait_idle=false
if [ "${1:-}" = "--wait-idle" ]; then
  wait_idle=true
  shift
fi
if [ "${1:-}" = "--docs" ]; then
  docs=true
  shift
elif [ "${1:-}" = "--table" ]; then
  table_only=true
  shift
fi
rank_counts=("${@:-1 2 4}")
read -r -a rank_counts <<< "${rank_counts[*]}"
build="$root/build-paraview"
out="$build/demo"
$table_only || "$root/scripts/install-paraview.sh"
plugin="$build/lib/paraview-5.11/plugins/ClusteredLighting/ClusteredLighting.so"
$table_only || [ -f "$plugin" ] || "$root/scripts/build-paraview-plugin.sh" "$build" > /dev/null
mkdir -p "$out"
cores=$(nproc)
idle_for_5s() { # true if the CPUs were more than 90% idle over the next 5 s
  local u n s i w q sq st t1 i1 t2 i2
  read -r _ u n s i w q sq st _ < /proc/stat
  t1=$((u + n + s + i + w + q + sq + st)) i1=$((i + w))
  sleep 5
  read -r _ u n s i w q sq st _ < /proc/stat
  t2=$((u + n + s + i + w + q + sq + st)) i2=$((i + w))
  [ $(((i2 - i1) * 100 / (t2 - t1))) -ge 90 ]
}
wait_until_idle() {
  for _ in $(seq 360); do
    idle_for_5s && idle_for_5s && return 0
  done
  echo "the CPUs were not idle for an hour: measuring anyway" >&2
}

results=()
loads=()
for ranks in "${rank_counts[@]}"; do
  if $table_only; then
    results+=("$(grep "^RESULT" "$out/demo-np$ranks.log")")
    continue
  fi
  threads=$((cores / ranks))
  [ "$threads" -ge 1 ] || threads=1
  $wait_idle && wait_until_idle
  loads+=("$ranks rank(s): $(cut -d' ' -f1-3 /proc/loadavg) at the start")
  echo "=== $ranks rank(s), LP_NUM_THREADS=$threads"
  LP_NUM_THREADS=$threads "$root/Plugins/ParaView/Testing/pvbatch-test.sh" "$ranks" \
    "$root/Plugins/ParaView/Demo/scale_demo.py" --plugin "$plugin" --output "$out" \
    2>&1 | tee "$out/demo-np$ranks.log" | grep "RESULT"
  results+=("$(grep "^RESULT" "$out/demo-np$ranks.log")")
done

field() { # field <name> <RESULT line>
  sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<< " $2"
}
echo
$table_only || echo "Machine: $(nproc) cores, $(LC_ALL=C lscpu | sed -n 's/^Model name: *//p'), Mesa llvmpipe;" \
  "ParaView $(dpkg-query -W -f='${Version}' paraview)"
echo
$table_only || echo "Load averages (1, 5, 15 min): ${loads[*]}; at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| ranks | isosurface triangles | lights (rank 0) | in view | first frame (s) | frame, median (ms) | frame, fastest (ms) | assignment (ms) | shading (ms) | lights evaluated / reaching per pixel | without the lights (ms) | against 1 rank: max step, pixels > 1 step | stock view against 1 rank |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for r in "${results[@]}"; do
  echo "| $(field ranks "$r") | $(field triangles "$r") | $(field lights "$r") | $(field assigned "$r") |" \
    "$(field first_frame_s "$r") | $(field frame_ms_median "$r") | $(field frame_ms_min "$r") |" \
    "$(field assignment_ms "$r") | $(field shading_ms "$r") |" \
    "$(field evaluated_per_pixel "$r") / $(field reaching_per_pixel "$r") |" \
    "$(field unlit_frame_ms_median "$r") |" \
    "$(field diff_max "$r"), $(field diff_pixels "$r") |" \
    "$(field stock_diff_max "$r"), $(field stock_diff_pixels "$r") |"
done
echo
echo "Triangles: the sum of the ranks' pieces (ParaView's data information)."
if $docs; then
  last=${rank_counts[-1]}
  cp "$out/paraview-scale-demo-np$last.png" "$root/docs/images/paraview-scale-demo.png"
  cp "$out/paraview-scale-demo-ranks-np$last.png" "$root/docs/images/paraview-scale-demo-ranks.png"
  echo "copied the $last-rank images to docs/images/paraview-scale-demo*.png"
fi
