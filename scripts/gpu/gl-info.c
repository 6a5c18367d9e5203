// SPDX-License-Identifier: BSD-3-Clause
// Prints the GL vendor, renderer and version a GLX window gets (scripts/gpu/run.sh checks
// that the renderer is the GPU before it runs anything).
#include <GL/gl.h>
#include <GL/glx.h>
#include <stdio.h>

int main(void)
{
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy)
  {
    puts("no X display");
    return 1;
  }
  int attributes[] = { GLX_RGBA, GLX_DEPTH_SIZE, 24, GLX_DOUBLEBUFFER, None };
  XVisualInfo* visual = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  if (!visual)
  {
    puts("no GLX visual");
    return 2;
  }
  GLXContext context = glXCreateContext(dpy, visual, NULL, True);
  if (!context)
  {
    puts("no GLX context");
    return 3;
  }
  XSetWindowAttributes window;
  window.colormap =
    XCreateColormap(dpy, RootWindow(dpy, visual->screen), visual->visual, AllocNone);
  window.border_pixel = 0;
  Window w = XCreateWindow(dpy, RootWindow(dpy, visual->screen), 0, 0, 64, 64, 0, visual->depth,
    InputOutput, visual->visual, CWColormap | CWBorderPixel, &window);
  glXMakeCurrent(dpy, w, context);
  printf("GL vendor: %s\nGL renderer: %s\nGL version: %s\n", glGetString(GL_VENDOR),
    glGetString(GL_RENDERER), glGetString(GL_VERSION));
  return 0;
}
