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
 * Flags: CLUSTERED or BRUTE_FORCE, CUTOFF (radius test, clustered only), PHONG or PBR,
 * SPECULAR, SPOT, WINDOW, LINEAR_SLICES, COUNT, CLUSTER_INDEX, HEAT_MAP, EVALUATED_COUNT,
 * REACHED_COUNT, NON_FINITE.
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
  bool Window = false;
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
    NonFinite
  };
  Debug DebugView = Debug::None;

  // Parts that depend on the actor.
  bool PBR = false;
  bool Specular = true;

  bool SameGlobalPart(const vtkClusteredLightingShaderVariant& o) const;
  std::set<std::string> GetFlags() const;

  std::string GetDeclarations() const;
  std::string GetImplementation() const;
  std::string GetDebugImplementation() const;
};

#endif
