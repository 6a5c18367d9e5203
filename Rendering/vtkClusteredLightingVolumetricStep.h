// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingVolumetricStep
 * @brief   the volumetric step of the clustered pass's delegate, after the renderer's FXAA
 *
 * Private to the module. vtkClusteredLightingPass renders its delegate (a
 * vtkRenderStepsPass) with this as the volumetric step. VTK's render steps skip the
 * renderer's UseFXAA, which only the renderer's own render applies
 * (vtkOpenGLRenderer::UpdateGeometry, VTK 9.1 and 9.2): after the opaque and translucent
 * geometry, before volumes and overlays ("volumes don't need AA, and overlays are usually
 * things like text, which are already antialiased"). This step does the same: with
 * UseFXAA on it runs a vtkOpenGLFXAAFilter with the renderer's FXAAOptions on what is
 * rendered so far, then renders the volumes (a vtkVolumetricPass); the overlay step
 * follows it. The filter is kept per renderer (vtkClusteredLightingRendererObjects), as
 * the renderer keeps its own.
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightingOpaqueStep
 */
#ifndef vtkClusteredLightingVolumetricStep_h
#define vtkClusteredLightingVolumetricStep_h

#include "vtkNew.h"
#include "vtkRenderPass.h"

#include <memory> // for std::unique_ptr

class vtkOpenGLFXAAFilter;
class vtkVolumetricPass;
template <typename T>
class vtkClusteredLightingRendererObjects;

class vtkClusteredLightingVolumetricStep : public vtkRenderPass
{
public:
  static vtkClusteredLightingVolumetricStep* New();
  vtkTypeMacro(vtkClusteredLightingVolumetricStep, vtkRenderPass)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Applies the renderer's FXAA when it asks for it, then renders the volumes of `s`.
  void Render(const vtkRenderState* s) override;

  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkClusteredLightingVolumetricStep();
  ~vtkClusteredLightingVolumetricStep() override;

private:
  vtkClusteredLightingVolumetricStep(const vtkClusteredLightingVolumetricStep&) = delete;
  void operator=(const vtkClusteredLightingVolumetricStep&) = delete;

  vtkNew<vtkVolumetricPass> Volumes;
  std::unique_ptr<vtkClusteredLightingRendererObjects<vtkOpenGLFXAAFilter>> FXAA;
};

#endif
