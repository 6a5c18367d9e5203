// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVClusteredLightingView.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVSynchronizedRenderer.h"

#include <vector>

vtkStandardNewMacro(vtkPVClusteredLightingView);

//------------------------------------------------------------------------------
vtkPVClusteredLightingView::vtkPVClusteredLightingView()
{
  this->SetClusteredLightingPass(nullptr);
}

//------------------------------------------------------------------------------
vtkPVClusteredLightingView::~vtkPVClusteredLightingView()
{
  if (this->ClusteredLightingPass)
  {
    this->ClusteredLightingPass->RemoveAllLightSets();
  }
}

//------------------------------------------------------------------------------
void vtkPVClusteredLightingView::SetClusteredLightingPass(vtkClusteredLightingPass* pass)
{
  if (pass && pass == this->ClusteredLightingPass)
  {
    return;
  }
  vtkSmartPointer<vtkClusteredLightingPass> next = pass;
  if (!next)
  {
    next = vtkSmartPointer<vtkClusteredLightingPass>::New();
  }
  if (this->ClusteredLightingPass)
  {
    std::vector<vtkClusteredLightSet*> sets;
    for (int i = 0; i < this->ClusteredLightingPass->GetNumberOfLightSets(); ++i)
    {
      sets.push_back(this->ClusteredLightingPass->GetLightSet(i));
    }
    for (vtkClusteredLightSet* set : sets)
    {
      next->AddLightSet(set);
    }
    this->ClusteredLightingPass->RemoveAllLightSets();
  }
  next->SetDelegatePass(this->DefaultPass);
  if (this->GeometryBounds.IsValid())
  {
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    next->SetFarFieldRegion(bounds);
  }
  this->ClusteredLightingPass = next;
  this->SynchronizedRenderers->SetRenderPass(next);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVClusteredLightingView::Update()
{
  this->Superclass::Update();
  if (this->ClusteredLightingPass && this->GeometryBounds.IsValid())
  {
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    this->ClusteredLightingPass->SetFarFieldRegion(bounds);
  }
}

//------------------------------------------------------------------------------
vtkClusteredLightingPass* vtkPVClusteredLightingView::GetClusteredLightingPass()
{
  return this->ClusteredLightingPass;
}

//------------------------------------------------------------------------------
void vtkPVClusteredLightingView::AddLightSet(vtkClusteredLightSet* lights)
{
  if (!lights)
  {
    vtkErrorMacro("AddLightSet: the light set is null.");
    return;
  }
  this->ClusteredLightingPass->AddLightSet(lights);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVClusteredLightingView::RemoveLightSet(vtkClusteredLightSet* lights)
{
  if (lights)
  {
    this->ClusteredLightingPass->RemoveLightSet(lights);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVClusteredLightingView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ClusteredLightingPass: " << this->ClusteredLightingPass.GetPointer() << "\n";
  os << indent << "DefaultPass: " << this->DefaultPass.GetPointer() << "\n";
}
