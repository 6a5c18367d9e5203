// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingSampleZero
 * @brief   reads one sample of each pixel of a multisampled framebuffer: colour and depth
 *
 * Private to the module; the pass's counts of the lights evaluated per pixel
 * (DEBUG_EVALUATED_COUNT, and the heat map scaled to the data) read them from the colour
 * a counting frame wrote, and its counts of shaded fragments take the visible pixels from
 * the depths. A multisampled framebuffer (VTK's default window asks for 8
 * samples) cannot be read back, and resolving it averages each pixel's samples: at an
 * edge a surface's count is averaged with the background's colour or another surface's
 * count, and the encoding (R + 256 G) does not survive averaging (a G of 0.5 rounds to 0
 * or 1: 128 lights off). Interior pixels would resolve exactly, edges would not.
 *
 * So this reads sample 0 of each pixel, its colour and its depth (the same sample, so a
 * pixel counts as covered by geometry exactly when the colour read is a fragment's):
 *  1. the viewport's colour and depth are copied sample by sample (glBlitFramebuffer
 *     between two multisampled framebuffers of the same sample count, which copies
 *     without resolving) into multisampled textures: RGBA8, and the framebuffer's own
 *     depth format (vtkClusteredLightingQueryDepthFormat; a depth copy must match it);
 *  2. a full-screen pass (vtkClusteredLightingSampleZeroFS.glsl) writes sample 0 of both
 *     into single-sampled RGBA8 and R32F textures, which are read back.
 *
 * Every GL object it makes is deleted before Read() returns (the shader program stays in
 * the window's cache): a diagnostic, not a cost of every frame. It needs a current
 * context and leaves the framebuffer bindings, viewport and the state it changes as it
 * found them.
 *
 * @sa vtkClusteredLightingPass::GetMeanLightsEvaluatedPerPixel,
 * vtkClusteredLightingSampleDepths (the prepass's per-pixel depth ranges)
 */
#ifndef vtkClusteredLightingSampleZero_h
#define vtkClusteredLightingSampleZero_h

#include <string> // for std::string
#include <vector> // for std::vector

class vtkOpenGLRenderWindow;

class vtkClusteredLightingSampleZero
{
public:
  /// Reads sample 0 of every pixel of the rectangle (x0, y0, width, height) of the current
  /// draw framebuffer, which must be multisampled: `rgba` gets 4 bytes per pixel, `depth`
  /// its window depth, row-major from the bottom row. False (with `problem` saying why,
  /// and the vectors unchanged) when it cannot.
  static bool Read(vtkOpenGLRenderWindow* rw, const int rectangle[4],
    std::vector<unsigned char>& rgba, std::vector<float>& depth, std::string& problem);
};

#endif
