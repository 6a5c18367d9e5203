#!/usr/bin/env bash
# Frame times of this working tree against another revision, measured side by side: builds
# REV's benchmark in a scratch worktree, then runs both benchmarks in turns (old, new, old,
# new, ...) ROUNDS times on the same machine, and prints, per row, the median of each
# side's values and their ratio. Use it to show what a change did to speed (the machine is
# shared and noisy: alternating runs share its moods).
# Usage: scripts/compare-revisions.sh REV [ROUNDS] [extra benchmark args...]
# Environment:
#   COMPARE_COLUMNS  the results.csv columns compared (default "ms_median", the frame
#                    time; e.g. "far_build_ms assign_ms" for the far field's rebuild and
#                    the light assignment)
#   COMPARE_QUICK    1 (default) runs the benchmark's --quick mode (400x300, 3 frames);
#                    0 its full size (1024x768), for use with --filter and --frames
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rev=${1:?usage: scripts/compare-revisions.sh REV [ROUNDS] [benchmark args...]}
rounds=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
columns=${COMPARE_COLUMNS:-ms_median}
quick=()
[ "${COMPARE_QUICK:-1}" = 1 ] && quick=(--quick)
work="${TMPDIR:-/tmp}/clustered-lighting-compare-$(git -C "$root" rev-parse --short "$rev")"
if [ ! -d "$work" ]; then
  git -C "$root" worktree add --detach "$work" "$rev" > /dev/null
fi
# REV's benchmark only (and the library it links), not its tests.
cmake -S "$work" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$work/build" --target ClusteredLightingBenchmark > /dev/null
"$root/scripts/build.sh" "$root/build" > /dev/null
out="$(mktemp -d)"
for ((r = 1; r <= rounds; ++r)); do
  for side in old new; do
    tree=$root
    [ "$side" = old ] && tree=$work
    echo "round $r: $side" >&2
    "$root/scripts/with-display.sh" "$tree/build/Testing/Benchmark/ClusteredLightingBenchmark" \
      "${quick[@]}" --output "$out/$side-$r" "$@" > "$out/$side-$r.log"
  done
done
echo "results of each run: $out" >&2
/usr/bin/python3 - "$out" "$rounds" "$rev" "$columns" <<'PY'
import csv, statistics, sys
out, rounds, rev, columns = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4].split()
def load(side, column):
    rows = {}
    for r in range(1, rounds + 1):
        for row in csv.DictReader(open(f"{out}/{side}-{r}/results.csv")):
            if row.get(column, "") == "":
                continue
            key = "/".join(row[k] for k in ("scene", "layout", "lights", "method", "sweep", "value"))
            rows.setdefault(key, []).append(float(row[column]))
    return {k: (statistics.median(v), v) for k, v in rows.items()}
for column in columns:
    old, new = load("old", column), load("new", column)
    print(f"{column}, median of {rounds} runs (each run's value in brackets)")
    print(f"{'row (scene/layout/lights/method/sweep/value)':<58} {rev:>10} {'this':>10} {'ratio':>7}")
    ratios = []
    for key in old:
        if key in new and old[key][0] > 0:
            ratios.append(new[key][0] / old[key][0])
            print(f"{key:<58} {old[key][0]:10.2f} {new[key][0]:10.2f} {ratios[-1]:7.3f}"
                  f"  [{', '.join(f'{x:.2f}' for x in old[key][1])}] "
                  f"[{', '.join(f'{x:.2f}' for x in new[key][1])}]")
    if ratios:
        print(f"median ratio (this / {rev}) over {len(ratios)} rows: {statistics.median(ratios):.3f}\n")
PY
