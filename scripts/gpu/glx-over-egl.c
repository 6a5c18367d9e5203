// SPDX-License-Identifier: BSD-3-Clause
// GLX over EGL: runs Debian's X11-only VTK 9.1 on a headless NVIDIA GPU.
//
// Debian's VTK creates its windows and contexts with GLX, which needs an X server whose
// GLX the GPU's driver serves. A headless GPU machine has none: NVIDIA's GLX refuses Xvfb.
// Preloaded (LD_PRELOAD), this library answers the GLX calls VTK 9.1 and GLEW make (and
// nothing more): the X window still comes from Xvfb, but the context is an EGL context on
// the GPU (EGL's device platform) and the window's drawable is an EGL pbuffer of the
// window's size. VTK renders into its own framebuffer objects and reads its images from
// them, so the pbuffer only receives VTK's final blit. GL calls reach the EGL context
// through libglvnd's shared dispatch (libGL and libEGL share libGLdispatch).
//
// Used by scripts/gpu/run.sh; not part of the module, and nothing in the build or the
// tests depends on it.
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct Context
{
  EGLContext Egl;
};

enum
{
  MaxSurfaces = 64
};

static EGLDisplay Egl = EGL_NO_DISPLAY;
static EGLConfig Config;
static Display* CurrentDisplay;
static GLXDrawable CurrentDrawable;
static GLXContext CurrentContext;
static int ConfigToken; // the one GLXFBConfig handed out points here
static int NextEvicted; // the surface slot to reuse next when all are taken
static struct
{
  GLXDrawable Drawable;
  EGLSurface Surface;
  unsigned int Width, Height;
} Surfaces[MaxSurfaces];

static int InitializeEgl(void)
{
  if (Egl != EGL_NO_DISPLAY)
  {
    return 1;
  }
  PFNEGLQUERYDEVICESEXTPROC queryDevices =
    (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
  PFNEGLGETPLATFORMDISPLAYEXTPROC platformDisplay =
    (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
  EGLDeviceEXT devices[8];
  EGLint count = 0;
  if (queryDevices && platformDisplay && queryDevices(8, devices, &count) && count > 0)
  {
    Egl = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], NULL);
  }
  if (Egl == EGL_NO_DISPLAY)
  {
    Egl = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  }
  EGLint major = 0, minor = 0;
  if (Egl == EGL_NO_DISPLAY || !eglInitialize(Egl, &major, &minor))
  {
    fprintf(stderr, "glx-over-egl: no EGL display\n");
    Egl = EGL_NO_DISPLAY;
    return 0;
  }
  eglBindAPI(EGL_OPENGL_API);
  const EGLint attributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE,
    8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
    EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLint configs = 0;
  if (!eglChooseConfig(Egl, attributes, &Config, 1, &configs) || configs < 1)
  {
    fprintf(stderr, "glx-over-egl: no EGL config with RGBA8, depth 24 and stencil 8\n");
    return 0;
  }
  fprintf(
    stderr, "glx-over-egl: EGL %d.%d, vendor %s\n", major, minor, eglQueryString(Egl, EGL_VENDOR));
  return 1;
}

static GLXFBConfig* OneConfig(int* count)
{
  *count = 0;
  if (!InitializeEgl())
  {
    return NULL;
  }
  GLXFBConfig* configs = (GLXFBConfig*)malloc(sizeof(GLXFBConfig)); // the caller XFrees it
  configs[0] = (GLXFBConfig)&ConfigToken;
  *count = 1;
  return configs;
}

GLXFBConfig* glXChooseFBConfig(Display* dpy, int screen, const int* attributes, int* count)
{
  (void)dpy, (void)screen, (void)attributes;
  return OneConfig(count);
}

GLXFBConfig* glXGetFBConfigs(Display* dpy, int screen, int* count)
{
  (void)dpy, (void)screen;
  return OneConfig(count);
}

int glXGetFBConfigAttrib(Display* dpy, GLXFBConfig config, int attribute, int* value)
{
  (void)dpy, (void)config;
  switch (attribute)
  {
    case GLX_RED_SIZE:
    case GLX_GREEN_SIZE:
    case GLX_BLUE_SIZE:
    case GLX_ALPHA_SIZE:
      *value = 8;
      break;
    case GLX_DEPTH_SIZE:
      *value = 24;
      break;
    case GLX_STENCIL_SIZE:
      *value = 8;
      break;
    case GLX_DOUBLEBUFFER:
      *value = 1;
      break;
    default:
      *value = 0;
  }
  return 0;
}

XVisualInfo* glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig config)
{
  (void)config;
  XVisualInfo visual;
  if (!XMatchVisualInfo(dpy, DefaultScreen(dpy), 24, TrueColor, &visual))
  {
    return NULL;
  }
  XVisualInfo* result = (XVisualInfo*)malloc(sizeof(visual)); // the caller XFrees it
  *result = visual;
  return result;
}

XVisualInfo* glXChooseVisual(Display* dpy, int screen, int* attributes)
{
  (void)screen, (void)attributes;
  return glXGetVisualFromFBConfig(dpy, NULL);
}

static GLXContext CreateContext(GLXContext share, const int* glx)
{
  if (!InitializeEgl())
  {
    return NULL;
  }
  int major = 0, minor = 0, profile = 0;
  for (; glx && glx[0]; glx += 2)
  {
    if (glx[0] == GLX_CONTEXT_MAJOR_VERSION_ARB)
    {
      major = glx[1];
    }
    else if (glx[0] == GLX_CONTEXT_MINOR_VERSION_ARB)
    {
      minor = glx[1];
    }
    else if (glx[0] == GLX_CONTEXT_PROFILE_MASK_ARB)
    {
      profile = glx[1];
    }
  }
  EGLint egl[8];
  int k = 0;
  if (major)
  {
    egl[k++] = EGL_CONTEXT_MAJOR_VERSION;
    egl[k++] = major;
    egl[k++] = EGL_CONTEXT_MINOR_VERSION;
    egl[k++] = minor;
  }
  if (profile & GLX_CONTEXT_CORE_PROFILE_BIT_ARB)
  {
    egl[k++] = EGL_CONTEXT_OPENGL_PROFILE_MASK;
    egl[k++] = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
  }
  egl[k] = EGL_NONE;
  EGLContext context =
    eglCreateContext(Egl, Config, share ? ((struct Context*)share)->Egl : EGL_NO_CONTEXT, egl);
  if (context == EGL_NO_CONTEXT)
  {
    fprintf(
      stderr, "glx-over-egl: eglCreateContext %d.%d failed (0x%x)\n", major, minor, eglGetError());
    return NULL;
  }
  struct Context* result = (struct Context*)malloc(sizeof(*result));
  result->Egl = context;
  return (GLXContext)result;
}

GLXContext glXCreateContextAttribsARB(
  Display* dpy, GLXFBConfig config, GLXContext share, Bool direct, const int* attributes)
{
  (void)dpy, (void)config, (void)direct;
  return CreateContext(share, attributes);
}

GLXContext glXCreateContext(Display* dpy, XVisualInfo* visual, GLXContext share, Bool direct)
{
  (void)dpy, (void)visual, (void)direct;
  return CreateContext(share, NULL);
}

GLXContext glXCreateNewContext(
  Display* dpy, GLXFBConfig config, int type, GLXContext share, Bool direct)
{
  (void)dpy, (void)config, (void)type, (void)direct;
  return CreateContext(share, NULL);
}

void glXDestroyContext(Display* dpy, GLXContext context)
{
  (void)dpy;
  if (!context)
  {
    return;
  }
  if (context == CurrentContext)
  {
    eglMakeCurrent(Egl, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    CurrentContext = NULL;
  }
  eglDestroyContext(Egl, ((struct Context*)context)->Egl);
  free(context);
}

// The pbuffer standing in for an X window, remade when the window's size changes.
static EGLSurface SurfaceFor(Display* dpy, GLXDrawable drawable)
{
  Window root;
  int x, y;
  unsigned int width = 1, height = 1, border, depth;
  XGetGeometry(dpy, drawable, &root, &x, &y, &width, &height, &border, &depth);
  int slot = -1;
  for (int i = 0; i < MaxSurfaces; ++i)
  {
    if (Surfaces[i].Drawable == drawable)
    {
      if (Surfaces[i].Width == width && Surfaces[i].Height == height)
      {
        return Surfaces[i].Surface;
      }
      eglDestroySurface(Egl, Surfaces[i].Surface);
      Surfaces[i].Drawable = 0;
      slot = i;
      break;
    }
    if (!Surfaces[i].Drawable && slot < 0)
    {
      slot = i;
    }
  }
  for (int tries = 0; slot < 0 && tries < MaxSurfaces; ++tries)
  {
    // All slots taken (windows are never said to be gone): reuse one not current now.
    const int i = NextEvicted;
    NextEvicted = (NextEvicted + 1) % MaxSurfaces;
    if (Surfaces[i].Surface != eglGetCurrentSurface(EGL_DRAW))
    {
      eglDestroySurface(Egl, Surfaces[i].Surface);
      Surfaces[i].Drawable = 0;
      slot = i;
    }
  }
  if (slot < 0)
  {
    return EGL_NO_SURFACE;
  }
  const EGLint attributes[] = { EGL_WIDTH, (EGLint)width, EGL_HEIGHT, (EGLint)height, EGL_NONE };
  Surfaces[slot].Drawable = drawable;
  Surfaces[slot].Surface = eglCreatePbufferSurface(Egl, Config, attributes);
  Surfaces[slot].Width = width;
  Surfaces[slot].Height = height;
  return Surfaces[slot].Surface;
}

Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext context)
{
  if (!InitializeEgl())
  {
    return False;
  }
  if (!context)
  {
    eglMakeCurrent(Egl, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    CurrentContext = NULL;
    CurrentDrawable = 0;
    return True;
  }
  EGLSurface surface = drawable ? SurfaceFor(dpy, drawable) : EGL_NO_SURFACE;
  if (!eglMakeCurrent(Egl, surface, surface, ((struct Context*)context)->Egl))
  {
    fprintf(stderr, "glx-over-egl: eglMakeCurrent failed (0x%x)\n", eglGetError());
    return False;
  }
  CurrentDisplay = dpy;
  CurrentDrawable = drawable;
  CurrentContext = context;
  return True;
}

Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext context)
{
  (void)read;
  return glXMakeCurrent(dpy, draw, context);
}

void glXSwapBuffers(Display* dpy, GLXDrawable drawable)
{
  (void)dpy, (void)drawable;
  if (CurrentContext && CurrentDrawable)
  {
    eglSwapBuffers(Egl, eglGetCurrentSurface(EGL_DRAW));
  }
}

GLXContext glXGetCurrentContext(void)
{
  return CurrentContext;
}

Display* glXGetCurrentDisplay(void)
{
  return CurrentDisplay;
}

GLXDrawable glXGetCurrentDrawable(void)
{
  return CurrentDrawable;
}

Bool glXIsDirect(Display* dpy, GLXContext context)
{
  (void)dpy, (void)context;
  return True;
}

Bool glXQueryExtension(Display* dpy, int* errorBase, int* eventBase)
{
  (void)dpy;
  if (errorBase)
  {
    *errorBase = 0;
  }
  if (eventBase)
  {
    *eventBase = 0;
  }
  return True;
}

Bool glXQueryVersion(Display* dpy, int* major, int* minor)
{
  (void)dpy;
  if (major)
  {
    *major = 1;
  }
  if (minor)
  {
    *minor = 4;
  }
  return True;
}

static const char* Extensions = "GLX_ARB_create_context GLX_ARB_create_context_profile "
                                "GLX_ARB_get_proc_address GLX_EXT_swap_control";

static const char* Answer(int name)
{
  return name == GLX_EXTENSIONS ? Extensions : name == GLX_VERSION ? "1.4" : "glx-over-egl";
}

const char* glXQueryExtensionsString(Display* dpy, int screen)
{
  (void)dpy, (void)screen;
  return Extensions;
}

const char* glXQueryServerString(Display* dpy, int screen, int name)
{
  (void)dpy, (void)screen;
  return Answer(name);
}

const char* glXGetClientString(Display* dpy, int name)
{
  (void)dpy;
  return Answer(name);
}

void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval)
{
  (void)dpy, (void)drawable, (void)interval;
}

typedef void (*Function)(void);

// GLX entry points are this library's own; everything else is the EGL driver's.
Function glXGetProcAddressARB(const GLubyte* name)
{
  if (!strncmp((const char*)name, "glX", 3))
  {
    void* own = dlsym(RTLD_DEFAULT, (const char*)name);
    if (own)
    {
      return (Function)own;
    }
  }
  return (Function)eglGetProcAddress((const char*)name);
}

Function glXGetProcAddress(const GLubyte* name)
{
  return glXGetProcAddressARB(name);
}
