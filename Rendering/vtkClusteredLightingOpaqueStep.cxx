// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingOpaqueStep.h"

#include "vtkClusteredLightingBackfaceCulling.h"
#include "vtkClusteredLightingRendererObjects.h"
#include "vtkHiddenLineRemovalPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"

vtkStandardNewMacro(vtkClusteredLightingOpaqueStep);

//------------------------------------------------------------------------------
vtkClusteredLightingOpaqueStep::vtkClusteredLightingOpaqueStep()
  : SSAO(new vtkClusteredLightingRendererObjects<vtkSSAOPass>(
      [](vtkSSAOPass* ssao, vtkWindow* w) { ssao->ReleaseGraphicsResources(w); }))
{
}

//------------------------------------------------------------------------------
vtkClusteredLightingOpaqueStep::~vtkClusteredLightingOpaqueStep() = default;

//------------------------------------------------------------------------------
void vtkClusteredLightingOpaqueStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* names[] = { "Opaque", "HiddenLineRemoval", "SSAO" };
  os << indent << "LastMethod: " << names[static_cast<int>(this->LastMethod)] << "\n";
}

//------------------------------------------------------------------------------
void vtkClusteredLightingOpaqueStep::Render(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkRenderPass* pass = this->Opaque;
  this->LastMethod = Method::Opaque;
  if (RemovesHiddenLines(s))
  {
    pass = this->HiddenLineRemoval;
    this->LastMethod = Method::HiddenLineRemoval;
  }
  else if (ren->GetUseSSAO())
  {
    vtkSSAOPass* ssao = this->SSAO->Get(ren);
    if (!ssao->GetDelegatePass())
    {
      ssao->SetDelegatePass(this->Opaque);
    }
    ssao->SetRadius(ren->GetSSAORadius());
    ssao->SetBias(ren->GetSSAOBias());
    ssao->SetKernelSize(ren->GetSSAOKernelSize());
    ssao->SetBlur(ren->GetSSAOBlur());
    pass = ssao;
    this->LastMethod = Method::SSAO;
  }
  if (this->BackfaceCulling)
  {
    this->BackfaceCulling->SetActive(true);
  }
  pass->Render(s);
  if (this->BackfaceCulling)
  {
    this->BackfaceCulling->SetActive(false);
  }
  this->NumberOfRenderedProps = pass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingOpaqueStep::RemovesHiddenLines(const vtkRenderState* s)
{
  return s->GetRenderer()->GetUseHiddenLineRemoval() &&
    vtkHiddenLineRemovalPass::WireframePropsExist(s->GetPropArray(), s->GetPropArrayCount());
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingOpaqueStep::DrawsOnPrepassDepths(const vtkRenderState* s)
{
  return !s->GetRenderer()->GetUseSSAO() && !RemovesHiddenLines(s);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingOpaqueStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Opaque->ReleaseGraphicsResources(w);
  this->HiddenLineRemoval->ReleaseGraphicsResources(w);
  this->SSAO->Release(w);
}
