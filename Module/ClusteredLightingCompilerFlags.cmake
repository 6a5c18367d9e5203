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

# Sanitizer builds: link Testing/Sanitizers/ClusteredLightingPinGLDriver.cxx into a GL
# executable (see that file: keeps Mesa's driver mapped so LeakSanitizer sees its globals).
function (clustered_lighting_pin_gl_driver target)
  if (NOT CLUSTERED_LIGHTING_SANITIZE)
    return ()
  endif ()
  find_file(CLUSTERED_LIGHTING_GL_DRIVER swrast_dri.so
    PATHS "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri" /usr/lib/dri /usr/lib64/dri
    DOC "Mesa DRI driver kept loaded in sanitizer builds"
    NO_DEFAULT_PATH)
  if (NOT CLUSTERED_LIGHTING_GL_DRIVER)
    message(FATAL_ERROR "CLUSTERED_LIGHTING_SANITIZE: Mesa's swrast_dri.so was not found")
  endif ()
  target_sources(${target} PRIVATE
    "${PROJECT_SOURCE_DIR}/Testing/Sanitizers/ClusteredLightingPinGLDriver.cxx")
  set_property(SOURCE "${PROJECT_SOURCE_DIR}/Testing/Sanitizers/ClusteredLightingPinGLDriver.cxx"
    TARGET_DIRECTORY ${target}
    APPEND PROPERTY COMPILE_DEFINITIONS "CLUSTERED_LIGHTING_GL_DRIVER=\"${CLUSTERED_LIGHTING_GL_DRIVER}\"")
  target_link_libraries(${target} PRIVATE ${CMAKE_DL_LIBS})
endfunction ()
