// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingSampleDepths
 * @brief   the window depths each pixel's fragments have, in a multisampled framebuffer
 *
 * Private to the module; the depth prepass (vtkClusteredLightingDepthPrepass) records
 * through it when the framebuffer it draws into is multisampled (VTK's default window
 * asks for 8 samples) and depth-aware clusters are on.
 *
 * Why one depth per pixel is not enough: a multisampled render shades a fragment once per
 * pixel for every primitive that covers at least one of the pixel's samples, and
 * interpolates it at the pixel centre. At a primitive's edge the centre may lie outside
 * the primitive, so the fragment's depth (and the view depth the shader finds its cluster
 * from) is extrapolated along the primitive's plane and may match none of the depths the
 * depth buffer holds: a single-sampled readback, or a resolve of the samples' own depths,
 * can miss it by as much as the primitive's depth slope.
 *
 * So the prepass records the shaded depths themselves:
 *  1. Begin(): the prepass draws into this object's framebuffer instead of the window's:
 *     a multisampled depth buffer of the window's format, sample count and sample
 *     positions (the window's depth copied in first, cleared or kept as the renderer
 *     asked), and a multisampled RG32F colour buffer cleared to (0, -1).
 *  2. Every program the prepass draws writes (z, -z), z = gl_FragCoord.z at the pixel
 *     centre, as its second output (vtkClusteredLightingDepthPrepass::AddDepthOutput), and
 *     blending takes the maximum (GL_MAX): each sample keeps the largest z and the
 *     smallest z of the fragments that passed its depth test.
 *  3. End(): the depth is copied back into the window for the shading render; a
 *     full-screen pass (vtkClusteredLightingSampleDepthsFS.glsl) takes, per pixel, the
 *     smallest and largest z over its samples (1 and 1 where no fragment was drawn), and
 *     reads both back: the DepthImage's Depth and DepthMax.
 *
 * Conservative: the shading render shades a fragment at a pixel only when it passes the
 * depth test (GL_LEQUAL) at one of the pixel's samples against the prepass's depth, that
 * is when its depth there equals the smallest any prepass fragment had there. The same
 * fragment of the prepass (the same vertex code, `invariant gl_Position`) then passed its
 * own test at that sample when it was drawn, so its centre depth was blended into the
 * sample and lies in the pixel's [Depth, DepthMax]. Props that the prepass does not draw
 * (translucent ones) are not covered: the pass does not use depth-aware clusters with
 * them in a multisampled framebuffer.
 *
 * Begin() refuses (GetProblem()) when the copy cannot be exact: a depth format other
 * than 24-bit or 32-bit float (each with or without 8 stencil bits), 32-bit fixed point
 * (VTK 9.1's own render framebuffer) or 16-bit, or a recording target whose sample
 * count or positions differ from the window's. The prepass then draws into the window as
 * before and the pass uses whole clusters.
 *
 * @sa vtkClusteredLightingDepthPrepass, vtkClusteredLightingDepthBounds.h
 */
#ifndef vtkClusteredLightingSampleDepths_h
#define vtkClusteredLightingSampleDepths_h

#include "vtkClusteredLightingGLHelpers.h" // for vtkClusteredLightingVertexArray
#include "vtkWeakPointer.h"                // for vtkWeakPointer

#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkClusteredLightingSampleDepths
{
public:
  vtkClusteredLightingSampleDepths() = default;
  ~vtkClusteredLightingSampleDepths();

  /// True when the current draw framebuffer has sample buffers.
  static bool IsDrawFramebufferMultisampled();

  /// Redirects drawing into the recording framebuffer for the viewport (origin, size) of
  /// the current draw framebuffer, whose depth is copied in. False (with GetProblem(), and
  /// nothing changed) when it cannot record exactly.
  bool Begin(vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2]);

  /// Copies the depth back into the framebuffer that was bound at Begin() and binds it
  /// again; takes each pixel's range and reads it back into `lo` and `hi` (size[0] x
  /// size[1], row-major from the bottom row). False (with GetProblem()) when the range
  /// could not be read; the depth is copied back in any case.
  bool End(vtkOpenGLRenderWindow* rw, std::vector<float>& lo, std::vector<float>& hi);

  const std::string& GetProblem() const { return this->Problem; }

  /// Deletes the GL objects, in their window's context (made current meanwhile; `w` is
  /// used only when that window is gone).
  void Release(vtkWindow* w);
  int GetNumberOfGLObjects() const;
  /// Appends (GL_TEXTURE or GL_FRAMEBUFFER, name) of the live objects.
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;

private:
  vtkClusteredLightingSampleDepths(const vtkClusteredLightingSampleDepths&) = delete;
  void operator=(const vtkClusteredLightingSampleDepths&) = delete;

  bool Allocate(vtkOpenGLRenderWindow* rw, int width, int height, int samples, int depthFormat);
  bool Resolve(vtkOpenGLRenderWindow* rw, std::vector<float>& lo, std::vector<float>& hi);

  vtkWeakPointer<vtkOpenGLRenderWindow> Window; ///< the context of the objects below
  vtkOpenGLFramebufferObject* Target = nullptr; ///< multisampled depth and (z, -z)
  vtkTextureObject* Depth = nullptr;
  vtkTextureObject* Samples = nullptr;
  vtkOpenGLFramebufferObject* ResolveTarget = nullptr; ///< per pixel (lo, hi)
  vtkTextureObject* Range = nullptr;
  vtkClusteredLightingVertexArray VAO;
  int TargetSize[2] = { 0, 0 };
  int SampleCount = 0;
  int DepthFormat = 0;

  // Between Begin() and End().
  unsigned int WindowBinding = 0; ///< the draw framebuffer that was bound
  int Origin[2] = { 0, 0 };
  int Size[2] = { 0, 0 };
  std::string Problem;
};

#endif
