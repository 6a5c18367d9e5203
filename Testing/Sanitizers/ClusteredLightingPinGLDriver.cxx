// SPDX-License-Identifier: BSD-3-Clause
// Sanitizer builds only (CLUSTERED_LIGHTING_SANITIZE): keeps Mesa's DRI driver mapped
// until the process exits.
//
// Mesa dlclose()s its driver (swrast_dri.so for llvmpipe) when VTK closes the X display.
// LeakSanitizer runs after that, at exit: the driver's global variables are gone, so
// the blocks they pointed to look leaked (Mesa 22.3: two 56-byte blocks per process,
// reproduced with an empty vtkRenderWindow and no ClusteredLighting code), and their
// stack frames point into unmapped memory ("<unknown module>"), so no suppression can
// name them. Loading the driver once more with RTLD_NODELETE keeps it (and its globals)
// mapped: those blocks stay reachable and no suppression is needed for them. It changes
// nothing else: Mesa's own dlopen() of the same file returns this same mapping.
#include <dlfcn.h> // for dlopen

#ifndef CLUSTERED_LIGHTING_GL_DRIVER
#error "CLUSTERED_LIGHTING_GL_DRIVER (path of the DRI driver) must be defined"
#endif

namespace
{
struct ClusteredLightingPinGLDriver
{
  ClusteredLightingPinGLDriver()
  {
    // The handle is deliberately never closed.
    static_cast<void>(dlopen(CLUSTERED_LIGHTING_GL_DRIVER, RTLD_LAZY | RTLD_NODELETE));
  }
};
const ClusteredLightingPinGLDriver Pin;
}
