// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMClusteredLightingPassProxy
 * @brief   Server-manager proxy of a view's vtkClusteredLightingPass: reads its statistics
 *          where the last render ran
 *
 * The pass of a Clustered Lighting view is a subproxy of the view, so it lives wherever the
 * view does: on the client and on every server rank. ParaView reads a proxy's information
 * properties from one process only, the client when the proxy lives there. In client-server
 * mode with remote rendering, though, the server ranks render (and IceT composites) while
 * the client only shows the image it receives, so the client's pass says nothing about the
 * frame on screen (no geometry, no prepass, no pixels).
 *
 * This proxy reads the statistics (NumberOfClusteredLights, LastShadingTime,
 * DepthPrepassUsed, MeanLightsEvaluatedPerPixel, ...) from the process that rendered:
 *  - builtin sessions (the GUI without a server, pvbatch, pvpython): the local process,
 *    rank 0 under MPI, as for any proxy;
 *  - client-server sessions whose view's last render was local (the geometry delivered to
 *    the client): the client, which rendered;
 *  - client-server sessions whose view's last render was remote: the render server's root
 *    (rank 0), the same rank whose statistics pvbatch reports.
 * The choice follows vtkPVRenderView's own decision for the last render
 * (GetUseDistributedRenderingForRender, or ...ForLODRender after an interactive render
 * with level of detail). Only where the information is pulled from changes: the request
 * and its answer are ParaView's own (vtkSMProxy::UpdatePropertyInformation).
 *
 * The XML element of the pass proxy, ClusteredLightingPassProxy, names this class.
 *
 * @sa vtkPVClusteredLightingView vtkClusteredLightingPass
 */
#ifndef vtkSMClusteredLightingPassProxy_h
#define vtkSMClusteredLightingPassProxy_h

#include "vtkClusteredLightingViewModule.h" // For export macro
#include "vtkSMProxy.h"

class VTKCLUSTEREDLIGHTINGVIEW_EXPORT vtkSMClusteredLightingPassProxy : public vtkSMProxy
{
public:
  static vtkSMClusteredLightingPassProxy* New();
  vtkTypeMacro(vtkSMClusteredLightingPassProxy, vtkSMProxy)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Whether the statistics are read from the render server's root: true in a
   * client-server session when the parent view's last render was remote (the server
   * ranks rendered), false otherwise (the local process rendered).
   */
  bool GetReadsServerStatistics();

protected:
  vtkSMClusteredLightingPassProxy();
  ~vtkSMClusteredLightingPassProxy() override;

  /// Pulls the information properties from the render server's root instead of the
  /// client when the server rendered (GetReadsServerStatistics).
  void UpdatePropertyInformationInternal(vtkSMProperty* prop = nullptr) override;

private:
  vtkSMClusteredLightingPassProxy(const vtkSMClusteredLightingPassProxy&) = delete;
  void operator=(const vtkSMClusteredLightingPassProxy&) = delete;
};

#endif
