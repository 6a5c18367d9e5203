# How the project's tests share the machine when ctest runs several at once
# (scripts/run-ctest.sh runs ctest -j<cores>).
#
# Only the GL-free core tests (GoogleTest, label "core") and the clang-tidy lint run beside
# each other: they use one core each and read no clock. Every test that renders (llvmpipe
# spreads a frame over every core), runs a Python interpreter or an example, or times
# something runs alone.
#
# Except in the sanitizer build (CLUSTERED_LIGHTING_SANITIZE, scripts/run-sanitizers.sh),
# where every test runs beside another: there most of a GL test's time is our
# instrumented code, not llvmpipe's (the GL tests took 235 s in all in the normal build,
# 777 s under AddressSanitizer; two at a time and the soak test's shorter run there cut
# that stage's ctest from 923 s to 715 s on the 2-core machine), and no test checks a time
# (the benchmark's smoke test and the examples print theirs; the soak test skips its
# memory checks there).

# Marks every test added so far in the calling directory to run alone (RUN_SERIAL), but
# not in the sanitizer build (above).
function (clustered_lighting_run_tests_alone)
  if (CLUSTERED_LIGHTING_SANITIZE)
    return ()
  endif ()
  get_property(tests DIRECTORY PROPERTY TESTS)
  if (tests)
    set_tests_properties(${tests} PROPERTIES RUN_SERIAL TRUE)
  endif ()
endfunction ()
