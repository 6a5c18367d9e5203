// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingLightCollector.h"

#include "vtkClusteredLightSet.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"

#include <algorithm> // for std::max
#include <sstream>   // for std::ostringstream

using namespace vtkClusteredLighting;

//------------------------------------------------------------------------------
std::string vtkClusteredLightingLightCollection::NameOf(std::size_t i) const
{
  std::ostringstream os;
  if (i < this->ClusteredLights.size())
  {
    os << "vtkLight " << this->ClusteredLights[i] << " (renderer light " << i << ")";
    return os.str();
  }
  for (auto it = this->SetRanges.rbegin(); it != this->SetRanges.rend(); ++it)
  {
    if (i >= it->First)
    {
      os << "vtkClusteredLightSet " << it->Set << " light " << (i - it->First);
      return os.str();
    }
  }
  os << "light " << i;
  return os.str();
}

//------------------------------------------------------------------------------
std::vector<vtkSmartPointer<vtkLight>> vtkClusteredLightingLightCollector::GetRendererLights(
  vtkRenderer* renderer)
{
  std::vector<vtkSmartPointer<vtkLight>> out;
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    out.emplace_back(light);
  }
  return out;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingLightCollector::SetRendererLights(
  vtkRenderer* renderer, const std::vector<vtkSmartPointer<vtkLight>>& lights)
{
  vtkLightCollection* collection = renderer->GetLights();
  collection->RemoveAllItems();
  for (const auto& light : lights)
  {
    collection->AddItem(light);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingLightCollector::CollectRendererLights(
  vtkRenderer* renderer, bool cluster, vtkClusteredLightingLightCollection& c)
{
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  bool anyOn = false;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    anyOn = anyOn || light->GetSwitch();
  }
  if (!anyOn && renderer->GetAutomaticLightCreation())
  {
    renderer->CreateLight(); // what VTK would do in UpdateLights
  }
  std::vector<vtkLight*> all;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    all.push_back(light);
    c.RendererLights.emplace_back(light);
    if (cluster && light->GetSwitch() && light->GetPositional())
    {
      c.ClusteredLights.push_back(light);
      vtkMTimeType t = light->GetMTime();
      if (vtkMatrix4x4* m = light->GetTransformMatrix())
      {
        t = std::max(t, m->GetMTime());
      }
      c.Key.Objects.push_back(light);
      c.Key.NewestMTime = std::max(c.Key.NewestMTime, t);
    }
    else
    {
      c.StockLights.emplace_back(light);
    }
  }
  c.RendererComplexity = ComputeVTKLightingComplexity(all);
}

//------------------------------------------------------------------------------
int vtkClusteredLightingLightCollector::ComputeVTKLightingComplexity(
  const std::vector<vtkLight*>& lights)
{
  int complexity = 0;
  int count = 0;
  for (vtkLight* light : lights)
  {
    if (light->GetSwitch())
    {
      ++count;
      complexity = std::max(complexity, 1);
    }
    if (complexity == 1 && (count > 1 || light->GetLightType() != VTK_LIGHT_TYPE_HEADLIGHT))
    {
      complexity = 2;
    }
    if (complexity < 3 && light->GetPositional())
    {
      complexity = 3;
    }
  }
  return complexity;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingLightCollector::CollectLightSets(
  const std::vector<vtkSmartPointer<vtkClusteredLightSet>>& sets,
  vtkClusteredLightingLightCollection& c)
{
  for (const auto& set : sets)
  {
    set->UpdateLights(); // a set fed by a pipeline reads its input here
    // A disabled set counts too: switching it (SetEnabled modifies it) changes the key.
    c.Key.Objects.push_back(set.Get());
    c.Key.NewestMTime = std::max(c.Key.NewestMTime, set->GetMTime());
    if (set->GetEnabled())
    {
      c.LightSets.push_back(set.Get());
    }
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingLightCollector::Read(vtkClusteredLightingLightCollection& c)
{
  c.Sources.clear();
  c.SetRanges.clear();
  ReadRendererLights(c);
  ReadLightSets(c);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingLightCollector::ReadRendererLights(vtkClusteredLightingLightCollection& c)
{
  for (vtkLight* l : c.ClusteredLights)
  {
    LightSource src;
    const double* p = l->GetTransformedPosition();
    const double* focal = l->GetTransformedFocalPoint();
    src.PositionWC = glm::dvec3(p[0], p[1], p[2]);
    src.DirectionWC = glm::dvec3(focal[0] - p[0], focal[1] - p[1], focal[2] - p[2]);
    const double* color = l->GetDiffuseColor();
    src.Color = glm::dvec3(color[0], color[1], color[2]);
    src.Intensity = l->GetIntensity();
    const double* a = l->GetAttenuationValues();
    src.Attenuation = glm::dvec3(a[0], a[1], a[2]);
    src.ConeAngle = l->GetConeAngle();
    src.Exponent = l->GetExponent();
    c.Sources.push_back(src);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingLightCollector::ReadLightSets(vtkClusteredLightingLightCollection& c)
{
  for (vtkClusteredLightSet* set : c.LightSets)
  {
    c.SetRanges.push_back({ set, c.Sources.size() });
    const vtkIdType n = set->GetNumberOfLights();
    c.Sources.reserve(c.Sources.size() + static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      LightSource src;
      double v[3];
      set->GetPosition(i, v);
      src.PositionWC = glm::dvec3(v[0], v[1], v[2]);
      set->GetColor(i, v);
      src.Color = glm::dvec3(v[0], v[1], v[2]);
      src.Intensity = set->GetScaledIntensity(i); // with the set's IntensityScale
      set->GetAttenuation(i, v);
      src.Attenuation = glm::dvec3(v[0], v[1], v[2]);
      src.HasRadius = set->HasRadius(i);
      src.Radius = set->GetRadius(i);
      src.ConeAngle = set->GetConeAngle(i);
      src.Exponent = set->GetExponent(i);
      set->GetSpotDirection(i, v);
      src.DirectionWC = glm::dvec3(v[0], v[1], v[2]);
      c.Sources.push_back(src);
    }
  }
}
