# Compiler flags for the project's own targets (VTK's headers come in as system headers).

# Warning flags: every target of ours calls this (library, VTK test driver, GoogleTest
# executable, examples). CI builds with CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS=ON.
function (clustered_lighting_add_warnings target)
  if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
    if (CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif ()
  endif ()
endfunction ()

# AddressSanitizer + UndefinedBehaviorSanitizer for everything built in this directory
# and below (our library, tests and examples; VTK, Mesa and GoogleTest stay as
# installed, uninstrumented). float-cast-overflow is added because GCC's "undefined" set
# does not include it and out-of-range float-to-int conversions are UB the fuzz tests
# look for. -fno-sanitize-recover=all makes every UBSan report fatal.
# Used by scripts/run-sanitizers.sh; see the README's "Reliability" section.
macro (clustered_lighting_enable_sanitizers)
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "CLUSTERED_LIGHTING_SANITIZE needs GCC or Clang")
  endif ()
  set(_clustered_lighting_sanitize_flags
    -fsanitize=address,undefined,float-cast-overflow
    -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  add_compile_options(${_clustered_lighting_sanitize_flags})
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
endmacro ()
