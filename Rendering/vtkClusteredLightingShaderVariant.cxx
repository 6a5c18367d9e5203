// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingShaderVariant.h"

#include "vtkClusteredLightingPass.h" // for DebugViews

#include "vtkClusteredLightingDebugImpl.h"
#include "vtkClusteredLightingShadingDec.h"
#include "vtkClusteredLightingShadingImpl.h"

#include <sstream> // for std::istringstream
#include <vector>  // for std::vector

//------------------------------------------------------------------------------
bool vtkClusteredLightingShaderVariant::SameGlobalPart(
  const vtkClusteredLightingShaderVariant& o) const
{
  return this->Enabled == o.Enabled && this->Clustered == o.Clustered && this->Spot == o.Spot &&
    this->Window == o.Window && this->LinearSlices == o.LinearSlices &&
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
    if (this->Window)
    {
      f.insert("WINDOW");
    }
    if (this->LinearSlices)
    {
      f.insert("LINEAR_SLICES");
    }
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
  switch (this->DebugView)
  {
    case vtkClusteredLightingPass::DEBUG_CLUSTER_INDEX:
      if (this->Clustered)
      {
        f.insert("CLUSTER_INDEX");
      }
      break;
    case vtkClusteredLightingPass::DEBUG_HEAT_MAP:
      f.insert("COUNT");
      f.insert("HEAT_MAP");
      break;
    case vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT:
      f.insert("COUNT");
      f.insert("EVALUATED_COUNT");
      break;
    case vtkClusteredLightingPass::DEBUG_REACHED_COUNT:
      f.insert("COUNT");
      f.insert("REACHED_COUNT");
      break;
    case vtkClusteredLightingPass::DEBUG_NON_FINITE:
      f.insert("NON_FINITE");
      break;
    default:
      break;
  }
  return f;
}

//------------------------------------------------------------------------------
std::string vtkClusteredLightingShaderVariant::SelectCode(
  const std::string& source, const std::set<std::string>& flags)
{
  std::istringstream in(source);
  std::string line, out;
  // Stack of (condition of this block, block currently emitting).
  std::vector<std::pair<bool, bool>> stack;
  auto active = [&stack]() { return stack.empty() || stack.back().second; };
  while (std::getline(in, line))
  {
    const auto first = line.find_first_not_of(" \t");
    const std::string trimmed = first == std::string::npos ? std::string() : line.substr(first);
    if (trimmed.rfind("//CL_IF(", 0) == 0)
    {
      const auto close = trimmed.find(')');
      const std::string flag = trimmed.substr(8, close - 8);
      const bool cond = flags.count(flag) > 0;
      const bool parent = active();
      stack.emplace_back(cond, parent && cond);
      continue;
    }
    if (trimmed.rfind("//CL_ELSE", 0) == 0 && !stack.empty())
    {
      const bool cond = stack.back().first;
      stack.pop_back();
      const bool parent = active();
      stack.emplace_back(!cond, parent && !cond);
      continue;
    }
    if (trimmed.rfind("//CL_ENDIF", 0) == 0 && !stack.empty())
    {
      stack.pop_back();
      continue;
    }
    if (active())
    {
      out += line;
      out += '\n';
    }
  }
  return out;
}

//------------------------------------------------------------------------------
std::string vtkClusteredLightingShaderVariant::GetDeclarations() const
{
  std::string code = SelectCode(vtkClusteredLightingShadingDec, this->GetFlags());
  const std::string key = "@CL_MASTER_TEXELS@";
  const auto pos = code.find(key);
  if (pos != std::string::npos)
  {
    code.replace(pos, key.size(), std::to_string(this->MasterTexels));
  }
  return code;
}

std::string vtkClusteredLightingShaderVariant::GetImplementation() const
{
  return SelectCode(vtkClusteredLightingShadingImpl, this->GetFlags());
}

std::string vtkClusteredLightingShaderVariant::GetDebugImplementation() const
{
  return SelectCode(vtkClusteredLightingDebugImpl, this->GetFlags());
}
