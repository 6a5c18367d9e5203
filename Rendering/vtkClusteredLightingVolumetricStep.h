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
 * Volumes are lit by their own mappers (vtkGPUVolumeRayCastMapper, vtkSmartVolumeMapper,
 * ...), which read the renderer's vtkLights when they render and which the pass's shader
 * hooks do not reach. While the pass hides its clustered vtkLights from VTK's lighting
 * code (the polydata shaders light them), it hands every light of the renderer to this
 * step (SetVolumeLights), and the renderer's collection holds them while the volumes
 * render: the volumes are lit as without the pass (a shaded volume had lost its
 * positional lights, up to 217 steps darker). The lights of vtkClusteredLightSets do not
 * light volumes.
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightingOpaqueStep
 */
#ifndef vtkClusteredLightingVolumetricStep_h
#define vtkClusteredLightingVolumetricStep_h

#include "vtkNew.h"
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for the volume lights

#include <memory> // for std::unique_ptr
#include <vector> // for the volume lights

class vtkLight;
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

  /// The renderer's own lights, all of them, for the volumes of the renders until the next
  /// call, while the pass hides some of them from VTK's lighting code; null (the default)
  /// when it hides none. The list must outlive those renders.
  void SetVolumeLights(const std::vector<vtkSmartPointer<vtkLight>>* lights)
  {
    this->VolumeLights = lights;
  }

  /// Whether the state holds a visible volume (vtkVolume, vtkMultiVolume); with
  /// `shadedOnly`, a visible volume whose property has shading on (lit by the lights).
  static bool HasVolumes(const vtkRenderState* s, bool shadedOnly = false);

protected:
  vtkClusteredLightingVolumetricStep();
  ~vtkClusteredLightingVolumetricStep() override;

private:
  vtkClusteredLightingVolumetricStep(const vtkClusteredLightingVolumetricStep&) = delete;
  void operator=(const vtkClusteredLightingVolumetricStep&) = delete;

  vtkNew<vtkVolumetricPass> Volumes;
  std::unique_ptr<vtkClusteredLightingRendererObjects<vtkOpenGLFXAAFilter>> FXAA;
  const std::vector<vtkSmartPointer<vtkLight>>* VolumeLights = nullptr;
};

#endif
