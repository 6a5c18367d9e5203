// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingLightCollector
 * @brief   light gathering: the light sources of one render, and what identifies them
 *
 * Private to the module; the first stage of vtkClusteredLightingPass::Render():
 *
 *   light gathering -> assignment (vtkClusteredLightingAssigner) -> shading (the pass)
 *
 * Every kind of light source appends to one vtkClusteredLightingLightCollection in two
 * steps:
 *  - Collect (every frame, cheap): the objects that hold lights and the newest MTime
 *    among them, enough for the assigner to tell whether anything changed;
 *  - Read (only when the assigner found a change): LightSource records in world
 *    coordinates (Rendering/Core/vtkClusteredLightingLights.h), in collection order.
 *
 * Kinds today:
 *  - renderer lights: every switched-on positional vtkLight of the renderer (point and
 *    spot lights) when clustering them is on; the rest (headlight, camera and
 *    directional lights, switched-off lights) stay with VTK's lighting code;
 *  - light sets: each enabled vtkClusteredLightSet (its UpdateLights() is called first, so
 *    a set fed by a pipeline reads its input here).
 * A new kind of light (say, area lights approximated by points, or lights of another
 * class) gets its own Collect/Read pair here and nothing else changes: the assigner and
 * the shading code see only LightSource records.
 *
 * @sa vtkClusteredLightingAssigner vtkClusteredLightingPass
 */
#ifndef vtkClusteredLightingLightCollector_h
#define vtkClusteredLightingLightCollector_h

#include "vtkClusteredLightingLights.h" // for LightSource
#include "vtkSmartPointer.h"            // for vtkSmartPointer
#include "vtkType.h"                    // for vtkMTimeType

#include <string> // for std::string
#include <vector> // for std::vector

class vtkClusteredLightSet;
class vtkLight;
class vtkRenderer;

/// What identifies the light sources of a render: change detection compares these.
struct vtkClusteredLightingSourceKey
{
  std::vector<const void*> Objects; ///< every object that holds lights, in order
  vtkMTimeType NewestMTime = 0;     ///< the newest MTime among them (MTimes only grow)

  bool operator==(const vtkClusteredLightingSourceKey& o) const
  {
    return this->NewestMTime == o.NewestMTime && this->Objects == o.Objects;
  }
  bool operator!=(const vtkClusteredLightingSourceKey& o) const { return !(*this == o); }
};

/// The light sources of one render.
struct vtkClusteredLightingLightCollection
{
  vtkClusteredLightingSourceKey Key;

  std::vector<vtkSmartPointer<vtkLight>> RendererLights; ///< all of them, in order
  std::vector<vtkSmartPointer<vtkLight>> StockLights;    ///< left to VTK's lighting code
  std::vector<vtkLight*> ClusteredLights;                ///< clustered renderer lights
  std::vector<vtkClusteredLightSet*> LightSets;          ///< enabled sets
  /// The lighting complexity VTK picks for all the renderer's lights (see
  /// vtkClusteredLightingLightCollector::ComputeVTKLightingComplexity).
  int RendererComplexity = 0;

  /// Filled by vtkClusteredLightingLightCollector::Read.
  std::vector<vtkClusteredLighting::LightSource> Sources;

  /// Names source i for messages ("vtkLight 0x... (renderer light 3)", "vtkClusteredLightSet
  /// 0x... light 12").
  std::string NameOf(std::size_t i) const;

private:
  friend class vtkClusteredLightingLightCollector;
  struct SetRange
  {
    vtkClusteredLightSet* Set;
    std::size_t First;
  };
  std::vector<SetRange> SetRanges; ///< where each set's lights start in Sources
};

class vtkClusteredLightingLightCollector
{
public:
  /**
   * Renderer lights. If no light is switched on and the renderer creates lights
   * automatically, creates its headlight first (what VTK's UpdateLights would do).
   */
  static void CollectRendererLights(
    vtkRenderer* renderer, bool cluster, vtkClusteredLightingLightCollection& c);

  /// Light sets (UpdateLights() on each, then the enabled ones).
  static void CollectLightSets(const std::vector<vtkSmartPointer<vtkClusteredLightSet>>& sets,
    vtkClusteredLightingLightCollection& c);

  /// The renderer's light collection, in order.
  static std::vector<vtkSmartPointer<vtkLight>> GetRendererLights(vtkRenderer* renderer);

  /// Makes the renderer's light collection hold exactly `lights`, in order (the pass hides
  /// its clustered lights from VTK's lighting code this way, and gives them back).
  static void SetRendererLights(
    vtkRenderer* renderer, const std::vector<vtkSmartPointer<vtkLight>>& lights);

  /// Fills c.Sources from everything collected, in collection order.
  static void Read(vtkClusteredLightingLightCollection& c);

  /**
   * The lighting complexity vtkOpenGLRenderer::UpdateLights (VTK 9.1 and 9.2) picks for
   * these lights, in their order: 0 none switched on, 1 a lone headlight, 2 several lights
   * or any other kind, 3 any positional light. VTK generates different code for each:
   * at 1 the headlight's specular is pow(N.z, power), at 2 and 3 reflect()-based Phong,
   * and PBR directional lights take their direction from the light's position at 3.
   * Mirrors VTK's loop exactly, quirks included: a positional light raises the complexity
   * to 3 even when switched off, and a second light (or a non-headlight) raises it to 2
   * once a switched-on light came before it. The pass keeps the complexity VTK would have
   * picked with the clustered lights (vtkClusteredLightingPass::RenderDelegate), so VTK's
   * own lights look exactly as without the pass.
   */
  static int ComputeVTKLightingComplexity(const std::vector<vtkLight*>& lights);

private:
  static void ReadRendererLights(vtkClusteredLightingLightCollection& c);
  static void ReadLightSets(vtkClusteredLightingLightCollection& c);
};

#endif
