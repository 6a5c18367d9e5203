// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingOpaqueStep
 * @brief   the opaque step of the clustered pass's delegate, with the renderer's SSAO and
 *          hidden-line removal
 *
 * Private to the module. vtkClusteredLightingPass renders its delegate (a
 * vtkRenderStepsPass) with this as the opaque step. VTK's render steps render opaque
 * geometry with a plain vtkOpaquePass and so skip two renderer options that only the
 * renderer's own render applies (vtkOpenGLRenderer::DeviceRenderOpaqueGeometry, VTK 9.1
 * and 9.2). This step applies them as that method does, in the same order:
 *
 *   - UseHiddenLineRemoval, when a prop is drawn as wireframe: a vtkHiddenLineRemovalPass
 *     draws the props (wireframe surfaces into depth first, then the lines);
 *   - otherwise UseSSAO: a vtkSSAOPass around a vtkOpaquePass, with the renderer's
 *     radius, bias, kernel size and blur: ambient occlusion from the rendered positions
 *     and normals darkens the lit colour (col.rgb * ao), clustered lights included;
 *   - otherwise a vtkOpaquePass.
 *
 * The clustered shading is part of every prop's shaders (the pass's shader hooks), so it
 * lights the props whichever of the three draws them. The SSAO pass is kept per renderer
 * (vtkClusteredLightingRendererObjects), as the renderer keeps its own.
 *
 * Neither option draws on the depths of a depth prepass, so the pass draws none while
 * one applies (DrawsOnPrepassDepths), and its clusters span the camera's depth range:
 *
 *   - hidden-line removal draws the other props first, then the wireframes' surfaces
 *     into depth only, so a prop behind such a surface stays visible through it while
 *     the lines behind it are hidden. A prepass puts the wireframes' lines in the depth
 *     buffer before that prop is drawn and hides the prop there (the background showed
 *     through instead).
 *   - SSAO renders the opaque step into a framebuffer of its own with a cleared depth
 *     buffer. Where two fragments lie at almost the same depth (the edge of a front and a
 *     back face), the one that lands there may not be the prepass's nearest, and a
 *     cluster cut to the prepass's depths may not hold it: it was shaded without its
 *     lights (a wireframe pixel lost the clustered light, 92 steps).
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightingTranslucentStep
 */
#ifndef vtkClusteredLightingOpaqueStep_h
#define vtkClusteredLightingOpaqueStep_h

#include "vtkNew.h"
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr

class vtkClusteredLightingBackfaceCulling;
class vtkHiddenLineRemovalPass;
class vtkOpaquePass;
class vtkSSAOPass;
template <typename T>
class vtkClusteredLightingRendererObjects;

class vtkClusteredLightingOpaqueStep : public vtkRenderPass
{
public:
  static vtkClusteredLightingOpaqueStep* New();
  vtkTypeMacro(vtkClusteredLightingOpaqueStep, vtkRenderPass)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Renders the opaque geometry of `s`, with the renderer's hidden-line removal or SSAO
  /// when it asks for them.
  void Render(const vtkRenderState* s) override;

  /// The culling of hidden faces active while this step draws (the pass's
  /// AutomaticBackfaceCulling; nullptr: none), not owned; ended after each prop. Not
  /// under hidden-line removal, whose pass draws the props itself.
  void SetBackfaceCulling(vtkClusteredLightingBackfaceCulling* culling);

  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// Whether the renderer of `s` removes hidden lines in this render (UseHiddenLineRemoval
  /// on and a prop drawn as wireframe), as the renderer's own render decides it.
  static bool RemovesHiddenLines(const vtkRenderState* s);

  /// Whether the opaque geometry of this render is drawn on the depths a depth prepass
  /// laid down, which the prepass and depth-aware clusters need: false under the
  /// renderer's hidden-line removal or SSAO (whoever applies them: this step, or the
  /// renderer's own render under an application's delegate).
  static bool DrawsOnPrepassDepths(const vtkRenderState* s);

  /// What the last Render() drew the opaque geometry with.
  enum class Method
  {
    Opaque,
    HiddenLineRemoval,
    SSAO
  };
  Method GetLastMethod() const { return this->LastMethod; }

protected:
  vtkClusteredLightingOpaqueStep();
  ~vtkClusteredLightingOpaqueStep() override;

private:
  vtkClusteredLightingBackfaceCulling* BackfaceCulling = nullptr;
  vtkClusteredLightingOpaqueStep(const vtkClusteredLightingOpaqueStep&) = delete;
  void operator=(const vtkClusteredLightingOpaqueStep&) = delete;

  vtkSmartPointer<vtkOpaquePass> Opaque; ///< prop by prop (ends their culling)
  vtkNew<vtkHiddenLineRemovalPass> HiddenLineRemoval;
  std::unique_ptr<vtkClusteredLightingRendererObjects<vtkSSAOPass>> SSAO;
  Method LastMethod = Method::Opaque;
};

#endif
