#!/usr/bin/env bash
# Frame times of this working tree against another revision, measured side by side: builds
# REV's benchmark in a scratch worktree, then runs both benchmarks' quick mode in turns
# (old, new, old, new, ...) ROUNDS times on the same machine, and prints, per row, the
# median frame time of each and their ratio. Use it to show that a change did not slow
# anything down (the machine is shared and noisy: alternating runs share its moods).
# Usage: scripts/compare-revisions.sh REV [ROUNDS] [extra benchmark args...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rev=${1:?usage: scripts/compare-revisions.sh REV [ROUNDS] [benchmark args...]}
rounds=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
work="${TMPDIR:-/tmp}/clustered-lighting-compare-$(git -C "$root" rev-parse --short "$rev")"
if [ ! -d "$work" ]; then
  git -C "$root" worktree add --detach "$work" "$rev" > /dev/null
fi
"$work/scripts/build.sh" "$work/build" > /dev/null
"$root/scripts/build.sh" "$root/build" > /dev/null
out="$(mktemp -d)"
for ((r = 1; r <= rounds; ++r)); do
  for side in old new; do
    tree=$root
    [ "$side" = old ] && tree=$work
    echo "round $r: $side" >&2
    "$root/scripts/with-display.sh" "$tree/build/Testing/Benchmark/ClusteredLightingBenchmark" \
      --quick --output "$out/$side-$r" "$@" > "$out/$side-$r.log"
  done
done
/usr/bin/python3 - "$out" "$rounds" "$rev" <<'EOF'
import csv, statistics, sys
out, rounds, rev = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def load(side):
    rows = {}
    for r in range(1, rounds + 1):
        for row in csv.DictReader(open(f"{out}/{side}-{r}/results.csv")):
            key = "/".join(row[k] for k in ("scene", "layout", "lights", "method", "sweep", "value"))
            rows.setdefault(key, []).append(float(row["ms_median"]))
    return {k: statistics.median(v) for k, v in rows.items()}
old, new = load("old"), load("new")
print(f"{'row (scene/layout/lights/method/sweep/value)':<58} {rev+' ms':>12} {'this ms':>10} {'ratio':>7}")
ratios = []
for key in old:
    if key in new:
        ratios.append(new[key] / old[key])
        print(f"{key:<58} {old[key]:12.1f} {new[key]:10.1f} {ratios[-1]:7.3f}")
print(f"median ratio (this / {rev}) over {len(ratios)} rows: {statistics.median(ratios):.3f}")
EOF
