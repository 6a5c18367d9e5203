// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVClusteredLightingView
 * @brief   ParaView render view whose geometry is shaded by vtkClusteredLightingPass
 *
 * A vtkPVRenderView in which thousands of point and spot lights light the scene. The
 * view hands a vtkClusteredLightingPass to its vtkPVSynchronizedRenderer as the geometry
 * render pass (SetRenderPass), so every rendering rank runs the pass on its own piece
 * inside ParaView's camera pass and, in parallel, inside IceT's compositing pass. The
 * pass's delegate is a vtkPVDefaultPass: the renderer then draws as ParaView's stock
 * render view does (FXAA, depth peeling, ordered compositing of translucent geometry),
 * and only the shading of positional lights changes.
 *
 * Lights:
 *  - positional vtkLights of the renderer (ParaView's Light Inspector, or AddLight() in
 *    Python with Type 'Positional'), clustered when the pass's ClusterRendererLights is
 *    on (default); the light kit and the headlight stay with VTK's lighting;
 *  - vtkClusteredLightSets added with AddLightSet(), which is what the "Clustered Lights"
 *    representation (vtkClusteredLightsRepresentation) does with its data.
 *
 * The far field's region: after each Update() the view gives the pass its geometry
 * bounds, which ParaView reduces over all ranks (FarFieldRegion), so every rank builds
 * the same far field whatever piece it renders, and a selection's highlight, which shows
 * cells of the data inside those bounds, moves nothing.
 *
 * The pass's options are not forwarded by this class: the server manager creates the
 * pass as a subproxy of the view proxy, whose properties the view proxy exposes, and
 * hands it to SetClusteredLightingPass(). Each rank has its own pass, so its statistics
 * (GetNumberOfClusteredLights(), ...) describe that rank's last render; the pass's proxy
 * (vtkSMClusteredLightingPassProxy) reads them from the process that rendered: rank 0,
 * or in client-server mode the server's rank 0 after a remote render and the client
 * after a local one.
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightsRepresentation vtkPVDefaultPass
 */
#ifndef vtkPVClusteredLightingView_h
#define vtkPVClusteredLightingView_h

#include "vtkClusteredLightingViewModule.h" // For export macro
#include "vtkNew.h"                         // For vtkNew
#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkClusteredLightSet;
class vtkClusteredLightingPass;
class vtkPVDefaultPass;

class VTKCLUSTEREDLIGHTINGVIEW_EXPORT vtkPVClusteredLightingView : public vtkPVRenderView
{
public:
  static vtkPVClusteredLightingView* New();
  vtkTypeMacro(vtkPVClusteredLightingView, vtkPVRenderView)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The pass that renders the view's geometry. Setting a pass makes a vtkPVDefaultPass
   * its delegate, moves the light sets of the previous pass to it, and gives it to the
   * synchronized renderers; null goes back to a pass of the view's own. The server
   * manager sets the view proxy's "ClusteredLightingPass" subproxy here. Default is a
   * pass of the view's own.
   */
  void SetClusteredLightingPass(vtkClusteredLightingPass* pass);
  vtkClusteredLightingPass* GetClusteredLightingPass();
  ///@}

  ///@{
  /**
   * Light sets shaded by the view's pass, in addition to the renderer's positional
   * lights. Representations add and remove their sets here.
   */
  void AddLightSet(vtkClusteredLightSet* lights);
  void RemoveLightSet(vtkClusteredLightSet* lights);
  ///@}

  /// Updates the view, then gives the pass the geometry bounds of all ranks as its far
  /// field's region.
  void Update() override;

protected:
  vtkPVClusteredLightingView();
  ~vtkPVClusteredLightingView() override;

  vtkSmartPointer<vtkClusteredLightingPass> ClusteredLightingPass;
  vtkNew<vtkPVDefaultPass> DefaultPass;

private:
  vtkPVClusteredLightingView(const vtkPVClusteredLightingView&) = delete;
  void operator=(const vtkPVClusteredLightingView&) = delete;
};

#endif
