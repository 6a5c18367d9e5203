// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMClusteredLightingPassProxy.h"

#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPVSession.h"
#include "vtkSMSession.h"

vtkStandardNewMacro(vtkSMClusteredLightingPassProxy);

//------------------------------------------------------------------------------
vtkSMClusteredLightingPassProxy::vtkSMClusteredLightingPassProxy() = default;

//------------------------------------------------------------------------------
vtkSMClusteredLightingPassProxy::~vtkSMClusteredLightingPassProxy() = default;

//------------------------------------------------------------------------------
void vtkSMClusteredLightingPassProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReadsServerStatistics: " << this->GetReadsServerStatistics() << "\n";
}

//------------------------------------------------------------------------------
bool vtkSMClusteredLightingPassProxy::GetReadsServerStatistics()
{
  vtkSMSession* session = this->GetSession();
  // Builtin sessions run the client and the server in one process (rank 0 under MPI).
  if (!session || !session->IsA("vtkSMSessionClient") || !(this->Location & vtkPVSession::CLIENT) ||
    !(this->Location & vtkPVSession::RENDER_SERVER))
  {
    return false;
  }
  vtkSMProxy* view = this->GetParentProxy();
  vtkPVRenderView* renderView =
    view ? vtkPVRenderView::SafeDownCast(view->GetClientSideObject()) : nullptr;
  if (!renderView)
  {
    return false;
  }
  return renderView->GetUsedLODForLastRender()
    ? renderView->GetUseDistributedRenderingForLODRender()
    : renderView->GetUseDistributedRenderingForRender();
}

//------------------------------------------------------------------------------
void vtkSMClusteredLightingPassProxy::UpdatePropertyInformationInternal(vtkSMProperty* prop)
{
  if (!this->GetReadsServerStatistics())
  {
    this->Superclass::UpdatePropertyInformationInternal(prop);
    return;
  }
  // The pull goes to the first of client, data server and render server that the
  // proxy's location names. Without a separate render server the session routes the
  // render server to the data server, whose root answers.
  const vtkTypeUInt32 location = this->Location;
  this->Location = location & vtkPVSession::RENDER_SERVER;
  this->Superclass::UpdatePropertyInformationInternal(prop);
  this->Location = location;
}
