// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingShaderVariant
 * @brief   which code paths the clustered shading GLSL needs, and the GLSL text itself
 *
 * Private helper of vtkClusteredLightingPass. The shading sources
 * (glsl/vtkClusteredLightingShading{Dec,Impl}.glsl, vtkClusteredLightingDebugImpl.glsl)
 * mark optional blocks with //CL_IF(FLAG) ... //CL_ELSE ... //CL_ENDIF lines;
 * vtkClusteredLighting::SelectShaderCode (Rendering/Core/vtkClusteredLightingShaderCode.h,
 * unit-tested) keeps only the blocks of the flags this variant sets, so the text injected
 * into a mapper's shader holds no code path the actor or the light set does not need.
 *
 * Flags: CLUSTERED or BRUTE_FORCE, CUTOFF (the culling-radius test, clustered only),
 * MODEL_RADIUS (the explicit radius of the light model is read: brute force stops there,
 * windows end there), VIEW1 (the second view texel is read: spot axis, explicit radius),
 * FAR_FIELD (clustered only: split lights' near parts are windowed and the far field is
 * added), FAR_SHARED_COLOR (with FAR_FIELD: the far-field lights share a colour, so the
 * far field is one channel in 5 textures times clFarFieldColor, 3 at order 2), FAR_ORDER4
 * (with FAR_FIELD: the far diffuse to order 4, which reads the fourth moments too),
 * FAR_EXACT_SUMS (with
 * FAR_FIELD: fragments the moments leave uncertain sum the far parts exactly; without it
 * the code is not there at all, which on llvmpipe is cheaper than a test that fails),
 * FAR_SUM_BLOCKS (those sums take 16 lights per loop iteration), PHONG or PBR, SPECULAR, SPOT,
 * WINDOW, LINEAR_SLICES, SATURATION (clustered Phong whose colour nothing rescales after the
 * lighting: a fragment stops at saturation where the uniform clClampsAtOne says the target clamps),
 * COUNT, CLUSTER_INDEX, HEAT_MAP, EVALUATED_COUNT, REACHED_COUNT, NON_FINITE, NORMAL.
 *
 * Brute force evaluates the same light model as clustered shading (explicit radius,
 * windowed falloff, spot cone) and differs only in not culling: lights without an explicit
 * radius are evaluated everywhere, with no cutoff.
 */
#ifndef vtkClusteredLightingShaderVariant_h
#define vtkClusteredLightingShaderVariant_h

#include <set>    // for std::set
#include <string> // for std::string

class vtkClusteredLightingShaderVariant
{
public:
  // Parts that depend on the light set and the pass options (shared by all actors).
  bool Enabled = false;  ///< false: no clustered lights, no clustered code at all
  bool Clustered = true; ///< false: brute force (every light, no cutoff)
  bool Spot = false;
  bool Window = false;   ///< windowed falloff (FALLOFF_WINDOWED)
  bool Explicit = false; ///< some light has an explicit radius (its model's range)
  bool FarField = false; ///< lights have far parts: window their near parts, add the far field
  bool FarFieldOneChannel = false;   ///< the far-field lights share a colour: 5 textures, not 14
  bool FarFieldOrder4 = false;       ///< the far diffuse to order 4 (FarFieldOrder4Diffuse)
  bool FarFieldSpecularBins = false; ///< the far specular from bins (FarFieldSpecularBins)
  /// the far parts may be summed exactly (FarFieldTolerance) for Phong actors (up to
  /// FarFieldExactSumLimit lights) and for PBR actors: FAR_EXACT_SUMS
  bool PhongExactFarSums = false;
  bool PbrExactFarSums = false;
  /// the exact far sums take 16 lights per loop iteration (ComputeFarPartsPerIteration):
  /// FAR_SUM_BLOCKS
  bool FarSumBlocks = false;
  bool LinearSlices = false;
  int MasterTexels = 1;

  /// Debug views (the pass maps its DebugView option to these).
  enum class Debug
  {
    None,
    ClusterIndex,
    HeatMap,
    EvaluatedCount,
    ReachedCount,
    NonFinite,
    Normal
  };
  Debug DebugView = Debug::None;

  // Parts that depend on the actor.
  bool PBR = false;
  bool Specular = true;
  /// no code after the lighting rescales the colour (a texture, for one): a fragment
  /// saturated by the lights so far may stop walking the rest (SATURATION, clustered Phong)
  bool Saturation = false;

  bool SameGlobalPart(const vtkClusteredLightingShaderVariant& o) const;
  std::set<std::string> GetFlags() const;

  std::string GetDeclarations() const;
  std::string GetImplementation() const;
  std::string GetDebugImplementation() const;
  /// The count views' code for a fragment VTK does not light (no normal or no position:
  /// points, and lines without normals): 0 lights evaluated and reaching. Empty for
  /// the other views.
  std::string GetUnlitDebugImplementation() const;
};

#endif
