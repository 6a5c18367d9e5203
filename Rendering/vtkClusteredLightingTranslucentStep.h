// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingTranslucentStep
 * @brief   the translucent step of the clustered pass's delegate, and its fragment counts
 *
 * Private to the module. vtkClusteredLightingPass renders its delegate (a
 * vtkRenderStepsPass) with this as the translucent step. It renders translucent geometry
 * as stock VTK does: ren->DeviceRenderTranslucentPolygonalGeometry(), that is
 * order-independent translucency, or (dual) depth peeling when the renderer has
 * UseDepthPeeling on.
 *
 * It also counts, on request (the pass's MeasureTimings), the fragments of the shading
 * render that pass the depth test, with GL_SAMPLES_PASSED queries, in two parts:
 *
 *   - opaque: from BeginCounting() (called before the delegate renders) to the start of
 *     this step: the opaque draws.
 *   - translucent: the translucent draws. Order-independent translucency (VTK 9.1 and
 *     9.2, vtkOrderIndependentTranslucentPass) ends with one full-viewport quad drawn at
 *     GL_ALWAYS without discard, which composites the layers and lights nothing; a query
 *     around the step counts it as one more fragment per viewport pixel, so
 *     that many are subtracted, once, when the step had translucent geometry to render.
 *     Depth peeling runs GL_SAMPLES_PASSED queries of its own (its occlusion ratio), and
 *     only one query of a target may be active: none of ours is active while it renders,
 *     and the translucent part is not measured. Nor is it in a multisampled framebuffer:
 *     order-independent translucency draws the layers into single-sampled textures and
 *     composites them into the multisampled one, and the query cannot tell the two
 *     counts apart (a translucent sphere read 0 there, 0.118 single-sampled).
 *
 * What comes after this step (volumes, overlays) is not counted.
 *
 * @sa vtkClusteredLightingPass
 */
#ifndef vtkClusteredLightingTranslucentStep_h
#define vtkClusteredLightingTranslucentStep_h

#include "vtkRenderPass.h"

#include <cstdint> // for std::uint64_t

class vtkClusteredLightingTranslucentStep : public vtkRenderPass
{
public:
  static vtkClusteredLightingTranslucentStep* New();
  vtkTypeMacro(vtkClusteredLightingTranslucentStep, vtkRenderPass)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Renders the translucent geometry of `s` (counting its fragments when counting).
  void Render(const vtkRenderState* s) override;

  /// Starts counting in the current context: the opaque part begins now. Call before the
  /// delegate renders, then EndCounting() in the same context.
  void BeginCounting();

  /// Samples that passed the depth test, as EndCounting() gives them.
  struct Counts
  {
    std::uint64_t Opaque = 0;
    std::uint64_t Translucent = 0;
    /// false: depth peeling, or translucency in a multisampled framebuffer, rendered
    /// translucent geometry
    bool TranslucentMeasured = true;
  };

  /// Ends counting (waits for the queries' results).
  Counts EndCounting();

protected:
  vtkClusteredLightingTranslucentStep() = default;
  ~vtkClusteredLightingTranslucentStep() override = default;

private:
  vtkClusteredLightingTranslucentStep(const vtkClusteredLightingTranslucentStep&) = delete;
  void operator=(const vtkClusteredLightingTranslucentStep&) = delete;

  /// Ends the active query, if any.
  void EndQuery();

  unsigned int Queries[2] = { 0, 0 }; ///< opaque, translucent (GL names; 0: none)
  int ActiveQuery = -1;               ///< the query counting now (-1: none)
  bool Counting = false;
  bool TranslucentBegun = false;      ///< the translucent query ran this frame
  std::uint64_t CompositeSamples = 0; ///< the compositing quad's samples, to subtract
  bool TranslucentMeasured = true;    ///< see Counts
};

#endif
