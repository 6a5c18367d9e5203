#!/usr/bin/env bash
# Builds the suite with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan,
# RelWithDebInfo, -DCLUSTERED_LIGHTING_SANITIZE=ON, warnings as errors) and runs all of
# it: core and fuzz tests, every GL test, the soak test, the example and the leak canary.
# Any ASan, LSan or UBSan report fails the test that caused it (UBSan is built with
# -fno-sanitize-recover=all). VTK, Mesa and GoogleTest are not instrumented.
# Python wrapping is off here: an instrumented module cannot be loaded into the system's
# uninstrumented python3 ("ASan runtime does not come first"); the Python tests run in the
# normal suite only.
# Debug information is line tables only (-g1): a sanitizer's report names each frame's
# function, file and line from them, and the full -g nearly doubled the compile of a GL
# test (34 s against 19 s, most of it the debug information of VTK's templates). No test
# runs the far-field study, so this build leaves it out (Testing/Benchmark), and the
# tests run two at a time (Module/ClusteredLightingTesting.cmake). The far-field build's
# instruction-set copies are not flattened here (vtkClusteredLightingFarFieldTree.h,
# VTK_CLUSTERED_LIGHTING_FLATTEN): instrumented and flattened, the library's file that
# holds them compiled in 1,778 s, 82 s without (each beside other jobs on 2 cores).
# Usage: scripts/run-sanitizers.sh [build-dir] [ctest args...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir=${1:-"$root/build-asan"}
shift || true
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCLUSTERED_LIGHTING_SANITIZE=ON -DCLUSTERED_LIGHTING_WARNINGS_AS_ERRORS=ON \
  -DCLUSTERED_LIGHTING_WRAP_PYTHON=OFF

# detect_leaks: LeakSanitizer at exit (suppressions: third-party code only, see the file).
# detect_stack_use_after_return, check_initialization_order, strict_init_order: extra
# ASan checks that are off by default. The fast (frame-pointer) unwinder stays on: the
# slow one deadlocks in llvmpipe's JIT (it takes libgcc's unwinder lock, then mallocs).
# intercept_tls_get_addr=0: GCC 12's __tls_get_addr interceptor misreads a dynamic TLS
# block that malloc placed 16 bytes into a page (it takes it for a pre-2.25 glibc block
# with a header) and LeakSanitizer's tracer dies on the bogus range at exit ("Tracer
# caught signal 11"; google/sanitizers#1322). Libraries loaded with dlopen, Mesa's GL
# libraries among them, keep their thread_local data in such blocks, and where malloc
# puts them depends on the heap's history (here it ends TestClusteredLightingBadInput, run
# directly with LP_NUM_THREADS=1, 20 times in 20; the likely cause of that test's two CI
# failures). Sanitizers.LeakCheckDynamicTls provokes it on every run. Without the
# interceptor the leak check no longer takes dynamic TLS blocks as roots of their own;
# fewer roots can only add leak reports, never hide one.
export ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:halt_on_error=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$root/Testing/Sanitizers/lsan.supp:print_suppressions=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

cd "$build_dir"
"$root/scripts/run-ctest.sh" "$@"
