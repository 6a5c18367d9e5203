# Warning flags for the project's own targets (VTK's headers come in as system headers).
function (clustered_lighting_add_warnings target)
  if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
    if (CLUSTERED_LIGHTING_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif ()
  endif ()
endfunction ()
