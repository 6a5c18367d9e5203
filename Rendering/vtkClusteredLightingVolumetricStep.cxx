// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingVolumetricStep.h"

#include "vtkClusteredLightingLightCollector.h"
#include "vtkClusteredLightingRendererObjects.h"
#include "vtkLight.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumetricPass.h"

vtkStandardNewMacro(vtkClusteredLightingVolumetricStep);

//------------------------------------------------------------------------------
vtkClusteredLightingVolumetricStep::vtkClusteredLightingVolumetricStep()
  : FXAA(new vtkClusteredLightingRendererObjects<vtkOpenGLFXAAFilter>(
      [](vtkOpenGLFXAAFilter* filter, vtkWindow*) { filter->ReleaseGraphicsResources(); }))
{
}

//------------------------------------------------------------------------------
vtkClusteredLightingVolumetricStep::~vtkClusteredLightingVolumetricStep() = default;

//------------------------------------------------------------------------------
void vtkClusteredLightingVolumetricStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingVolumetricStep::Render(const vtkRenderState* s)
{
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (ren && ren->GetUseFXAA())
  {
    vtkOpenGLFXAAFilter* filter = this->FXAA->Get(ren);
    if (ren->GetFXAAOptions())
    {
      filter->UpdateConfiguration(ren->GetFXAAOptions());
    }
    filter->Execute(ren);
  }
  // Every light of the renderer, the clustered ones too, while the volumes render.
  vtkRenderer* renderer = s->GetRenderer();
  const bool swap = this->VolumeLights && HasVolumes(s);
  std::vector<vtkSmartPointer<vtkLight>> shading;
  if (swap)
  {
    shading = vtkClusteredLightingLightCollector::GetRendererLights(renderer);
    vtkClusteredLightingLightCollector::SetRendererLights(renderer, *this->VolumeLights);
  }
  this->Volumes->Render(s);
  this->NumberOfRenderedProps = this->Volumes->GetNumberOfRenderedProps();
  if (swap)
  {
    vtkClusteredLightingLightCollector::SetRendererLights(renderer, shading);
  }
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingVolumetricStep::HasVolumes(const vtkRenderState* s, bool shadedOnly)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkVolume* volume = vtkVolume::SafeDownCast(s->GetPropArray()[i]);
    if (volume && volume->GetVisibility() &&
      (!shadedOnly || (volume->GetProperty() && volume->GetProperty()->GetShade())))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingVolumetricStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Volumes->ReleaseGraphicsResources(w);
  this->FXAA->Release(w);
}
