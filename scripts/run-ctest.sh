#!/usr/bin/env bash
# Runs ctest in the current build directory under an X display (scripts/with-display.sh)
# with the given arguments, after the checks of the machine itself
# (scripts/check-machine.sh: an X server that does not reset, and in sanitizer builds the
# sanitizer runtime), which stop the run if they fail. If a test fails, the output of each failing test is printed
# once more (its last 100 lines, from Testing/Temporary/LastTest.log) just before ctest's
# summary ("NN% tests passed, ..."), which is held back until then: a CI log read from its
# summary backwards shows why, not only which. Then the failing tests are run once more
# (the result stays a failure even if they pass then).
# Tests run on every core at once where they may: the GL-free core tests beside each other,
# every test that renders alone (RUN_SERIAL; Module/ClusteredLightingTesting.cmake).
# Usage (from a build directory): scripts/run-ctest.sh [ctest args...]
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
summary="$(mktemp "${TMPDIR:-/tmp}/ctest-summary.XXXXXX")"
trap 'rm -f "$summary"' EXIT
# Streams ctest's output as it comes, but keeps its summary for the end.
# The machine first (with DISPLAY unset, with-display.sh starts an X server exactly like
# the one ctest gets below).
"$root/scripts/with-display.sh" "$root/scripts/check-machine.sh" || exit 1
"$root/scripts/with-display.sh" ctest --output-on-failure --timeout 900 \
  --parallel "$(nproc)" "$@" 2>&1 |
  awk -v held="$summary" '
    /^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+/ { hold = 1 }
    hold { print > held; next }
    { print; fflush() }'
rc=${PIPESTATUS[0]}
failed=false
[ "$rc" -ne 0 ] && [ -f Testing/Temporary/LastTest.log ] && failed=true
if $failed; then
  echo "=== ctest failed (exit code $rc): output of the failing tests ==="
  # Each failing test's block of LastTest.log runs from its "Testing: <name>" line to its
  # "time elapsed" line (output, result, and the reason when ctest gives one).
  cut -d: -f2- Testing/Temporary/LastTestsFailed.log 2>/dev/null | while IFS= read -r name; do
    echo "--- $name"
    awk -v name="$name" '
      index($0, " Testing: " name) && substr($0, length($0) - length(name) + 1) == name { on = 1 }
      on { print }
      on && index($0, "time elapsed:") { exit }
    ' Testing/Temporary/LastTest.log | tail -n 100
  done
  echo "=== end of the failing tests' output ==="
  echo
fi
cat "$summary"
if $failed; then
  # Once more, to tell a failure that repeats from one that does not; the exit code stays
  # that of the first run either way.
  echo "=== running the failing tests once more ==="
  "$root/scripts/with-display.sh" ctest --rerun-failed --output-on-failure --timeout 900 || true
fi
exit "$rc"
