// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingShaderVariant.h"

#include "vtkClusteredLightingShaderCode.h"

#include "vtkClusteredLightingDebugImpl.h"
#include "vtkClusteredLightingShadingDec.h"
#include "vtkClusteredLightingShadingImpl.h"

#include <map>   // for the selections already made
#include <mutex> // for their cache
#include <utility>

using namespace vtkClusteredLighting;

namespace
{
// SelectShaderCode parses a whole GLSL file. A mapper rebuilds its shader source whenever
// the render passes its prop carries change, which around the depth prepass is twice a
// frame for every actor: the same selections, asked again and again. Each selection is
// made once (a few hundred variants at most) and kept for the process's life.
const std::string& SelectOnce(const char* code, const std::set<std::string>& flags)
{
  static std::mutex mutex;
  static std::map<std::pair<const char*, std::set<std::string>>, std::string> selections;
  const std::lock_guard<std::mutex> lock(mutex);
  auto key = std::make_pair(code, flags);
  auto it = selections.find(key);
  if (it == selections.end())
  {
    it = selections.emplace(std::move(key), SelectShaderCode(code, flags)).first;
  }
  return it->second; // map elements stay where they are; none is ever erased
}
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingShaderVariant::SameGlobalPart(
  const vtkClusteredLightingShaderVariant& o) const
{
  return this->Enabled == o.Enabled && this->Clustered == o.Clustered && this->Spot == o.Spot &&
    this->Window == o.Window && this->Explicit == o.Explicit && this->FarField == o.FarField &&
    this->FarFieldOneChannel == o.FarFieldOneChannel && this->FarFieldOrder4 == o.FarFieldOrder4 &&
    this->FarFieldSpecularBins == o.FarFieldSpecularBins &&
    this->PhongExactFarSums == o.PhongExactFarSums && this->PbrExactFarSums == o.PbrExactFarSums &&
    this->FarSumBlocks == o.FarSumBlocks && this->LinearSlices == o.LinearSlices &&
    this->MasterTexels == o.MasterTexels && this->DebugView == o.DebugView;
}

//------------------------------------------------------------------------------
std::set<std::string> vtkClusteredLightingShaderVariant::GetFlags() const
{
  std::set<std::string> f;
  f.insert(this->Clustered ? "CLUSTERED" : "BRUTE_FORCE");
  if (this->Clustered)
  {
    f.insert("CUTOFF");
    if (this->LinearSlices)
    {
      f.insert("LINEAR_SLICES");
    }
    if (this->FarField)
    {
      f.insert("FAR_FIELD");
      if (this->FarFieldOneChannel)
      {
        f.insert("FAR_SHARED_COLOR");
      }
      if (this->FarFieldOrder4)
      {
        f.insert("FAR_ORDER4");
      }
      if (this->FarFieldSpecularBins && this->Specular && !this->PBR)
      {
        f.insert("FAR_SPECULAR_BINS");
      }
      if (this->PBR ? this->PbrExactFarSums : this->PhongExactFarSums)
      {
        f.insert("FAR_EXACT_SUMS");
        if (this->FarSumBlocks)
        {
          f.insert("FAR_SUM_BLOCKS");
        }
      }
    }
  }
  // The light model: brute force stops at explicit radii and windows only there.
  const bool modelRadius = this->Explicit && (!this->Clustered || this->Window);
  if (modelRadius)
  {
    f.insert("MODEL_RADIUS");
  }
  if (this->Window && (this->Clustered || this->Explicit))
  {
    f.insert("WINDOW");
  }
  if (this->Spot || modelRadius)
  {
    f.insert("VIEW1");
  }
  f.insert(this->PBR ? "PBR" : "PHONG");
  if (this->Specular && !this->PBR)
  {
    f.insert("SPECULAR");
  }
  if (this->Spot)
  {
    f.insert("SPOT");
  }
  // Brute force stays the plain reference; the count of lights that reach a fragment
  // counts them all.
  if (this->Saturation && this->Clustered && !this->PBR && this->DebugView != Debug::ReachedCount)
  {
    f.insert("SATURATION");
  }
  if (this->DebugView != Debug::None)
  {
    f.insert("DEBUG");
  }
  switch (this->DebugView)
  {
    case Debug::ClusterIndex:
      if (this->Clustered)
      {
        f.insert("CLUSTER_INDEX");
      }
      break;
    case Debug::HeatMap:
      f.insert("COUNT");
      f.insert("HEAT_MAP");
      break;
    case Debug::EvaluatedCount:
      f.insert("COUNT");
      f.insert("EVALUATED_COUNT");
      break;
    case Debug::ReachedCount:
      f.insert("COUNT");
      f.insert("REACHED_COUNT");
      break;
    case Debug::NonFinite:
      f.insert("NON_FINITE");
      break;
    case Debug::Normal:
      f.insert("NORMAL");
      break;
    case Debug::None:
      break;
  }
  return f;
}

//------------------------------------------------------------------------------
std::string vtkClusteredLightingShaderVariant::GetDeclarations() const
{
  std::string code = SelectOnce(vtkClusteredLightingShadingDec, this->GetFlags());
  ReplaceShaderKey(code, "@CL_MASTER_TEXELS@", std::to_string(this->MasterTexels));
  return code;
}

std::string vtkClusteredLightingShaderVariant::GetImplementation() const
{
  return SelectOnce(vtkClusteredLightingShadingImpl, this->GetFlags());
}

std::string vtkClusteredLightingShaderVariant::GetDebugImplementation() const
{
  return SelectOnce(vtkClusteredLightingDebugImpl, this->GetFlags());
}

std::string vtkClusteredLightingShaderVariant::GetUnlitDebugImplementation() const
{
  const bool counts = this->DebugView == Debug::HeatMap ||
    this->DebugView == Debug::EvaluatedCount || this->DebugView == Debug::ReachedCount;
  return counts ? SelectOnce(vtkClusteredLightingDebugImpl, { "DEBUG", "UNLIT_COUNT" })
                : std::string();
}
