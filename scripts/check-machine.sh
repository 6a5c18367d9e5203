#!/usr/bin/env bash
# Checks of the machine the suite runs on, not of the product. scripts/run-ctest.sh runs
# this in the build directory before ctest, under the same X display; a failure stops the
# run with a message about the machine instead of failing product tests at random.
#  - The X server must accept a connection right after its last client closed one. VTK
#    9.1 makes such a connection whenever a program destroys its only window and creates
#    another, and aborts when it fails ("bad X server connection ... Aborting."). An X
#    server resets when its last client leaves and refuses connections meanwhile, unless
#    it was started with -noreset (scripts/with-display.sh does). Without it about a fifth
#    of such reopenings failed here (601 of 3,000), and the Python test aborted in 13 runs
#    of 150; see docs/reliability.md.
#  - Sanitizer builds (scripts/run-sanitizers.sh) only: LeakSanitizer, with this run's
#    options and suppressions, must report a leak of our own code (the canary), and its
#    leak check must not crash on dynamic TLS (GCC 12 runtime bug, google/sanitizers#1322).
# Usage (from a build directory): scripts/check-machine.sh
set -uo pipefail
checks=Testing/MachineChecks
status=0

if [ -x "$checks/ClusteredLightingDisplayCheck" ]; then
  if ! "$checks/ClusteredLightingDisplayCheck" 300; then
    echo "check-machine: the X server on DISPLAY=${DISPLAY:-} resets when its last client" \
      "leaves; VTK's renders would abort at random. Start it with -noreset (as" \
      "scripts/with-display.sh does), or unset DISPLAY to let the scripts start one." >&2
    status=1
  fi
fi

if [ -x "$checks/ClusteredLightingLeakCanary" ]; then
  out=$("$checks/ClusteredLightingLeakCanary" 2>&1)
  if grep -Pzq 'Direct leak of [0-9]+ byte[^\n]*\n[^\n]*\n[^\n]*vtkClusteredLightingPass::New' \
    <<<"$out"; then
    echo "check-machine: LeakSanitizer reports the canary's leak"
  else
    echo "$out" | tail -n 30
    echo "check-machine: LeakSanitizer did not report the canary's deliberate leak of a" \
      "vtkClusteredLightingPass: a leak of ours could go unseen with these options" \
      "(ASAN_OPTIONS/LSAN_OPTIONS, Testing/Sanitizers/lsan.supp)." >&2
    status=1
  fi
fi

if [ -x "$checks/ClusteredLightingDynamicTlsCheck" ]; then
  module=$(ls "$checks"/libClusteredLightingDynamicTlsModule.so 2>/dev/null | head -n 1)
  out=$("$checks/ClusteredLightingDynamicTlsCheck" "$module" 2>&1)
  rc=$?
  if [ "$rc" -ne 0 ] || grep -Eq "LeakSanitizer has encountered a fatal error|Tracer caught signal" \
    <<<"$out"; then
    echo "$out" | tail -n 30
    echo "check-machine: LeakSanitizer's leak check fails on dynamic TLS blocks (exit code" \
      "$rc); run with intercept_tls_get_addr=0 in ASAN_OPTIONS (scripts/run-sanitizers.sh)." >&2
    status=1
  else
    echo "check-machine: the leak check survives dynamic TLS"
  fi
fi
exit "$status"
