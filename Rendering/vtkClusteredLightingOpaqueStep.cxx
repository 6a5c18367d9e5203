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
#include "vtkSmartPointer.h"

namespace
{
/// VTK's opaque pass (vtkDefaultPass::RenderFilteredOpaqueGeometry), prop by prop, with
/// the face culling a prop's draws set (AutomaticBackfaceCulling) ended after the prop:
/// props drawn by mappers that do not set it themselves (image slices, say) are never
/// drawn culled.
class vtkClusteredLightingOpaqueProps : public vtkOpaquePass
{
public:
  static vtkClusteredLightingOpaqueProps* New();
  vtkTypeMacro(vtkClusteredLightingOpaqueProps, vtkOpaquePass)

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    for (int i = 0; i < s->GetPropArrayCount(); ++i)
    {
      vtkProp* prop = s->GetPropArray()[i];
      if (prop->HasKeys(s->GetRequiredKeys()))
      {
        this->NumberOfRenderedProps +=
          prop->RenderFilteredOpaqueGeometry(s->GetRenderer(), s->GetRequiredKeys());
      }
      if (this->Culling)
      {
        this->Culling->EndProp();
      }
    }
  }

  vtkClusteredLightingBackfaceCulling* Culling = nullptr;

protected:
  vtkClusteredLightingOpaqueProps() = default;
  ~vtkClusteredLightingOpaqueProps() override = default;

private:
  vtkClusteredLightingOpaqueProps(const vtkClusteredLightingOpaqueProps&) = delete;
  void operator=(const vtkClusteredLightingOpaqueProps&) = delete;
};
vtkStandardNewMacro(vtkClusteredLightingOpaqueProps);
}

vtkStandardNewMacro(vtkClusteredLightingOpaqueStep);

//------------------------------------------------------------------------------
vtkClusteredLightingOpaqueStep::vtkClusteredLightingOpaqueStep()
  : Opaque(vtkSmartPointer<vtkClusteredLightingOpaqueProps>::New())
  , SSAO(new vtkClusteredLightingRendererObjects<vtkSSAOPass>(
      [](vtkSSAOPass* ssao, vtkWindow* w) { ssao->ReleaseGraphicsResources(w); }))
{
}

//------------------------------------------------------------------------------
void vtkClusteredLightingOpaqueStep::SetBackfaceCulling(
  vtkClusteredLightingBackfaceCulling* culling)
{
  this->BackfaceCulling = culling;
  static_cast<vtkClusteredLightingOpaqueProps*>(this->Opaque.Get())->Culling = culling;
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
  // Not under hidden-line removal, which draws the props itself.
  const bool cull = this->BackfaceCulling && this->LastMethod != Method::HiddenLineRemoval;
  if (cull)
  {
    this->BackfaceCulling->SetActive(true);
  }
  pass->Render(s);
  if (cull)
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
