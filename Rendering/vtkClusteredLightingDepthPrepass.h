// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingDepthPrepass
 * @brief   depth-only render of a renderer's opaque geometry, and its depth readback
 *
 * Private to the module; used by vtkClusteredLightingPass before the light assignment:
 *
 *   1. Render(): the viewport and scissor as vtkCameraPass sets them, the depth cleared
 *      when the renderer would clear it, colour writes masked, then every visible prop's
 *      opaque geometry. The pass's shader hook sets clDepthOnly = 1 meanwhile, so the
 *      clustered code walks no light (the mappers keep their one program).
 *   2. ReadDepth(): the viewport's window depths (glReadPixels, GL_FLOAT), the input of
 *      depth-aware clusters (Rendering/Core/vtkClusteredLightingDepthBounds.h).
 *   3. The pass then renders its delegate with the renderer's depth buffer preserved:
 *      the camera pass clears colour only, and every opaque fragment behind the visible
 *      surface fails the depth test (GL_LEQUAL, VTK's default) before it is shaded.
 *
 * While rendering it notes what each program writes to depth (NoteProgram): VTK's
 * coincident-topology offset (gl_FragDepth = gl_FragCoord.z + cOffset / 65000) widens
 * the readback's margin by the largest |cOffset|; any other gl_FragDepth write (impostor
 * spheres and tubes, or VTK 9.2's offset with a non-zero slope factor cFactor) makes the
 * depths unusable for depth-aware clusters this frame.
 *
 * The clustered samplers of a program never sample in a depth-only render, but GL still
 * rejects a draw whose samplers of different types share a unit: the prepass allocates
 * distinct units for them (GetSamplerUnit) and frees them afterwards.
 *
 * @sa vtkClusteredLightingPass
 */
#ifndef vtkClusteredLightingDepthPrepass_h
#define vtkClusteredLightingDepthPrepass_h

#include "vtkClusteredLightingDepthBounds.h" // for DepthImage

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkOpenGLRenderWindow;
class vtkRenderState;
class vtkShaderProgram;

class vtkClusteredLightingDepthPrepass
{
public:
  /// Renders the opaque props of `s` depth-only; `pre` and `post` wrap the props (the
  /// pass's PreRender/PostRender). With `finish`, waits for the GPU so that the render
  /// time is the prepass's own (a deferred renderer would otherwise bill it to the next
  /// GL work). Returns the number of props rendered.
  int Render(const vtkRenderState* s, vtkOpenGLRenderWindow* rw, const std::function<void()>& pre,
    const std::function<void()>& post, bool finish);

  /// Reads the viewport's depth back. False (with GetProblem()) when it cannot: a
  /// multisampled framebuffer, or a GL error.
  bool ReadDepth(vtkOpenGLRenderWindow* rw);

  /// The last readback (valid after ReadDepth returned true).
  vtkClusteredLighting::DepthImage GetImage() const;

  /// Called by the pass's shader hook for every program drawn in Render().
  void NoteProgram(vtkShaderProgram* program);

  /// Distinct texture units for the clustered samplers during Render() (index < 16).
  int GetSamplerUnit(int index) const;

  bool IsRendering() const { return this->Rendering; }
  double GetMaximumCoincidentOffset() const { return this->MaxCoincidentOffset; }
  bool GetUnknownDepthWrites() const { return this->UnknownDepthWrites; }
  const std::string& GetProblem() const { return this->Problem; }
  double GetRenderTime() const { return this->RenderTime; } ///< ms, render and readback

private:
  bool Rendering = false;
  double MaxCoincidentOffset = 0.0;
  bool UnknownDepthWrites = false;
  std::vector<int> Units;
  std::vector<float> Depth;
  std::vector<unsigned int> Packed; ///< the packed depth-stencil read (3 MiB at 1024x768)
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  std::string Problem;
  double RenderTime = 0.0;
};

#endif
