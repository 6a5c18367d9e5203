// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingSavedDepth
 * @brief   a copy of the depth prepass's depth buffer, put back on a frame that would redraw it
 *
 * Private to the module; the depth prepass (vtkClusteredLightingDepthPrepass) keeps its
 * last depths here, so that a frame whose prepass would draw the same depths (the same
 * camera, viewport, props and data: vtkClusteredLightingDepthPrepass::ComputeReuseSignature)
 * copies them back instead of drawing the opaque geometry again:
 *
 *   1. Save(): after the prepass drew, its viewport's depth is copied (glBlitFramebuffer,
 *      sample by sample when the framebuffer is multisampled) into a renderbuffer of the
 *      same internal format and sample count, as large as the viewport's far corner.
 *   2. Restore(): on a later frame, the same copy back, only into the framebuffer it came
 *      from (its name, depth format, sample count and sample positions) and the same
 *      viewport; anything else refuses and the prepass draws.
 *
 * A copy is exact (same format, same samples, no filtering), so a frame that restores
 * renders the same image, bit for bit, as one that draws the prepass. On llvmpipe the
 * copy back of a 1024x768 depth buffer takes about a quarter of a millisecond, the
 * bunny's prepass 110 to 125 ms (docs/depth.md, "Still frames reuse the prepass").
 *
 * @sa vtkClusteredLightingDepthPrepass, vtkClusteredLightingSampleDepths
 */
#ifndef vtkClusteredLightingSavedDepth_h
#define vtkClusteredLightingSavedDepth_h

#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkOpenGLRenderWindow;
class vtkWindow;

class vtkClusteredLightingSavedDepth
{
public:
  vtkClusteredLightingSavedDepth() = default;
  ~vtkClusteredLightingSavedDepth();

  /// Copies the depth of the viewport (origin, size) of the current draw framebuffer.
  /// False (nothing kept) when it cannot copy exactly: a depth format
  /// vtkClusteredLightingQueryDepthFormat does not know, or a GL error.
  bool Save(vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2]);

  /// Copies the saved depth back into the current draw framebuffer: only the one it was
  /// saved from, with the same depth format and samples, and the same viewport. False
  /// (nothing drawn) otherwise.
  bool Restore(vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2]);

  /// Forgets the saved depth (Restore refuses until the next Save); keeps the objects.
  void Forget() { this->Saved = false; }

  /// Deletes the GL objects, in their window's context (made current meanwhile; `w` is
  /// used only when that window is gone).
  void Release(vtkWindow* w);
  int GetNumberOfGLObjects() const;
  /// Appends (GL_RENDERBUFFER or GL_FRAMEBUFFER, name) of the live objects.
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;

private:
  vtkClusteredLightingSavedDepth(const vtkClusteredLightingSavedDepth&) = delete;
  void operator=(const vtkClusteredLightingSavedDepth&) = delete;

  /// The copy's renderbuffer and framebuffer for (width, height, samples, format).
  bool Allocate(vtkOpenGLRenderWindow* rw, int width, int height, int samples, unsigned int format);
  /// One depth blit between the current framebuffer bindings, over the viewport.
  static bool Copy(vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2]);

  vtkWeakPointer<vtkOpenGLRenderWindow> Window; ///< the context of the objects below
  unsigned int Framebuffer = 0;
  unsigned int Renderbuffer = 0;
  int TargetSize[2] = { 0, 0 };
  int SampleCount = 0;
  unsigned int DepthFormat = 0;

  // What was saved, and from where.
  bool Saved = false;
  unsigned int Source = 0; ///< the draw framebuffer's name
  std::vector<float> SamplePositions;
  int Origin[2] = { 0, 0 };
  int Size[2] = { 0, 0 };
};

#endif
