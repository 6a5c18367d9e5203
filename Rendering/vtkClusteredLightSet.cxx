// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightSet.h"

#include "vtkObjectFactory.h"

#include <vector> // for std::vector

vtkStandardNewMacro(vtkClusteredLightSet);

// Structure of arrays: 3 doubles per vector parameter.
struct vtkClusteredLightSet::vtkInternals
{
  std::vector<double> Position;
  std::vector<double> Color;
  std::vector<double> Intensity;
  std::vector<double> Attenuation;
  std::vector<double> Radius;
  std::vector<unsigned char> HasRadius;
  std::vector<double> Direction;
  std::vector<double> ConeAngle;
  std::vector<double> Exponent;

  void Resize(std::size_t n)
  {
    const std::size_t old = this->Intensity.size();
    this->Position.resize(3 * n, 0.0);
    this->Color.resize(3 * n, 1.0);
    this->Intensity.resize(n, 1.0);
    this->Attenuation.resize(3 * n, 0.0);
    this->Radius.resize(n, 0.0);
    this->HasRadius.resize(n, 0);
    this->Direction.resize(3 * n, 0.0);
    this->ConeAngle.resize(n, 180.0);
    this->Exponent.resize(n, 1.0);
    for (std::size_t i = old; i < n; ++i)
    {
      this->Attenuation[3 * i] = 1.0; // vtkLight's default (1, 0, 0)
      this->Direction[3 * i + 2] = -1.0;
    }
  }
};

//------------------------------------------------------------------------------
vtkClusteredLightSet::vtkClusteredLightSet()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkClusteredLightSet::~vtkClusteredLightSet() = default;

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetNumberOfLights(vtkIdType n)
{
  if (n < 0)
  {
    vtkErrorMacro("Negative number of lights " << n << " ignored.");
    return;
  }
  if (static_cast<std::size_t>(n) != this->Internals->Intensity.size())
  {
    this->Internals->Resize(static_cast<std::size_t>(n));
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkClusteredLightSet::GetNumberOfLights() const
{
  return static_cast<vtkIdType>(this->Internals->Intensity.size());
}

//------------------------------------------------------------------------------
vtkIdType vtkClusteredLightSet::AddLight(double x, double y, double z)
{
  const vtkIdType i = this->GetNumberOfLights();
  this->Internals->Resize(static_cast<std::size_t>(i + 1));
  this->Internals->Position[3 * i] = x;
  this->Internals->Position[3 * i + 1] = y;
  this->Internals->Position[3 * i + 2] = z;
  this->Modified();
  return i;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::RemoveAllLights()
{
  this->SetNumberOfLights(0);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::CheckIndex(vtkIdType i) const
{
  if (i < 0 || i >= this->GetNumberOfLights())
  {
    vtkErrorMacro(
      "Light index " << i << " is out of range [0, " << this->GetNumberOfLights() << ").");
    return false;
  }
  return true;
}

namespace
{
void Set3(std::vector<double>& v, vtkIdType i, double a, double b, double c)
{
  v[3 * i] = a;
  v[3 * i + 1] = b;
  v[3 * i + 2] = c;
}
void Get3(const std::vector<double>& v, vtkIdType i, double out[3])
{
  out[0] = v[3 * i];
  out[1] = v[3 * i + 1];
  out[2] = v[3 * i + 2];
}
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetPosition(vtkIdType i, double x, double y, double z)
{
  if (this->CheckIndex(i))
  {
    Set3(this->Internals->Position, i, x, y, z);
    this->Modified();
  }
}

void vtkClusteredLightSet::GetPosition(vtkIdType i, double position[3]) const
{
  if (this->CheckIndex(i))
  {
    Get3(this->Internals->Position, i, position);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetColor(vtkIdType i, double r, double g, double b)
{
  if (this->CheckIndex(i))
  {
    Set3(this->Internals->Color, i, r, g, b);
    this->Modified();
  }
}

void vtkClusteredLightSet::GetColor(vtkIdType i, double color[3]) const
{
  if (this->CheckIndex(i))
  {
    Get3(this->Internals->Color, i, color);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetIntensity(vtkIdType i, double intensity)
{
  if (this->CheckIndex(i))
  {
    this->Internals->Intensity[i] = intensity;
    this->Modified();
  }
}

double vtkClusteredLightSet::GetIntensity(vtkIdType i) const
{
  return this->CheckIndex(i) ? this->Internals->Intensity[i] : 0.0;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetAttenuation(
  vtkIdType i, double constant, double linear, double quadratic)
{
  if (this->CheckIndex(i))
  {
    Set3(this->Internals->Attenuation, i, constant, linear, quadratic);
    this->Modified();
  }
}

void vtkClusteredLightSet::GetAttenuation(vtkIdType i, double attenuation[3]) const
{
  if (this->CheckIndex(i))
  {
    Get3(this->Internals->Attenuation, i, attenuation);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetRadius(vtkIdType i, double radius)
{
  if (this->CheckIndex(i))
  {
    this->Internals->Radius[i] = radius;
    this->Internals->HasRadius[i] = 1;
    this->Modified();
  }
}

void vtkClusteredLightSet::UnsetRadius(vtkIdType i)
{
  if (this->CheckIndex(i))
  {
    this->Internals->HasRadius[i] = 0;
    this->Modified();
  }
}

bool vtkClusteredLightSet::HasRadius(vtkIdType i) const
{
  return this->CheckIndex(i) && this->Internals->HasRadius[i] != 0;
}

double vtkClusteredLightSet::GetRadius(vtkIdType i) const
{
  return this->CheckIndex(i) ? this->Internals->Radius[i] : 0.0;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetSpot(
  vtkIdType i, double dx, double dy, double dz, double coneAngle, double exponent)
{
  if (this->CheckIndex(i))
  {
    Set3(this->Internals->Direction, i, dx, dy, dz);
    this->Internals->ConeAngle[i] = coneAngle;
    this->Internals->Exponent[i] = exponent;
    this->Modified();
  }
}

void vtkClusteredLightSet::SetPointLight(vtkIdType i)
{
  if (this->CheckIndex(i))
  {
    this->Internals->ConeAngle[i] = 180.0;
    this->Modified();
  }
}

void vtkClusteredLightSet::GetSpotDirection(vtkIdType i, double direction[3]) const
{
  if (this->CheckIndex(i))
  {
    Get3(this->Internals->Direction, i, direction);
  }
}

double vtkClusteredLightSet::GetConeAngle(vtkIdType i) const
{
  return this->CheckIndex(i) ? this->Internals->ConeAngle[i] : 180.0;
}

double vtkClusteredLightSet::GetExponent(vtkIdType i) const
{
  return this->CheckIndex(i) ? this->Internals->Exponent[i] : 1.0;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLights: " << this->GetNumberOfLights() << "\n";
  os << indent << "Enabled: " << (this->Enabled ? "On" : "Off") << "\n";
}
