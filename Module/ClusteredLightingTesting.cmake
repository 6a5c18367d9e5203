# How the project's tests share the machine when ctest runs several at once
# (scripts/run-ctest.sh runs ctest -j<cores>).
#
# Only the GL-free core tests (GoogleTest, label "core") and the clang-tidy lint run beside
# each other: they use one core each and read no clock. Every test that renders (llvmpipe
# spreads a frame over every core), runs a Python interpreter or an example, or times
# something runs alone.

# Marks every test added so far in the calling directory to run alone (RUN_SERIAL).
function (clustered_lighting_run_tests_alone)
  get_property(tests DIRECTORY PROPERTY TESTS)
  if (tests)
    set_tests_properties(${tests} PROPERTIES RUN_SERIAL TRUE)
  endif ()
endfunction ()
