// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingVolumetricStep.h"

#include "vtkClusteredLightingRendererObjects.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"
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
  this->Volumes->Render(s);
  this->NumberOfRenderedProps = this->Volumes->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkClusteredLightingVolumetricStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Volumes->ReleaseGraphicsResources(w);
  this->FXAA->Release(w);
}
