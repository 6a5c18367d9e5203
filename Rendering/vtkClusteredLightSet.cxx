// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightSet.h"

#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <sstream> // for std::ostringstream
#include <string>  // for std::string
#include <vector>  // for std::vector

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
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(0);
  this->SetColorArrayName("Color");
  this->SetIntensityArrayName("Intensity");
  this->SetAttenuationArrayName("Attenuation");
  this->SetRadiusArrayName("Radius");
  this->SetSpotDirectionArrayName("SpotDirection");
  this->SetConeAngleArrayName("ConeAngle");
  this->SetExponentArrayName("Exponent");
}

//------------------------------------------------------------------------------
vtkClusteredLightSet::~vtkClusteredLightSet()
{
  this->SetColorArrayName(nullptr);
  this->SetIntensityArrayName(nullptr);
  this->SetAttenuationArrayName(nullptr);
  this->SetRadiusArrayName(nullptr);
  this->SetSpotDirectionArrayName(nullptr);
  this->SetConeAngleArrayName(nullptr);
  this->SetExponentArrayName(nullptr);
}

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
void vtkClusteredLightSet::SetInputData(vtkPolyData* input)
{
  this->SetInputDataInternal(0, input);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkClusteredLightSet::GetInput()
{
  return this->GetNumberOfInputConnections(0) > 0
    ? vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0))
    : nullptr;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::UpdateLights()
{
  if (this->GetNumberOfInputConnections(0) == 0)
  {
    return;
  }
  // The executive reports what failed (e.g. an input that is not a vtkPolyData); the set
  // then holds no lights rather than stale ones.
  if (!this->GetExecutive()->Update() && this->GetNumberOfLights() > 0)
  {
    this->Internals->Resize(0);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkClusteredLightSet::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port != 0)
  {
    return 0;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkClusteredLightSet::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inInfo, outInfo);
  }
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

namespace
{
// One optional point-data array of the input: which parameter it holds, how many
// components it may have, and the array found (null: use the default).
struct InputArray
{
  const char* Option;   // the name option, for messages
  const char* Name;     // the array name asked for (null or empty: none)
  int Components;       // required number of components
  int OtherComponents;  // also accepted (0: none)
  bool IsColor = false; // unsigned char colors are scaled to [0, 1]
  vtkDataArray* Array = nullptr;
  double Scale = 1.0; // 1/255 for an unsigned char color array
};

// Finds the array; returns false (with a message) when it exists but cannot be used.
bool FindInputArray(vtkPointData* pd, vtkIdType numberOfPoints, InputArray& a, std::string& error)
{
  a.Array = nullptr;
  if (!a.Name || !*a.Name || !pd)
  {
    return true;
  }
  vtkAbstractArray* abstract = pd->GetAbstractArray(a.Name);
  if (!abstract)
  {
    return true;
  }
  std::ostringstream os;
  os << "Point-data array '" << a.Name << "' (" << a.Option << ") ";
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
  const int nc = abstract->GetNumberOfComponents();
  if (!array)
  {
    os << "is a " << abstract->GetClassName() << "; it must be a numeric array (vtkDataArray)";
  }
  else if (nc != a.Components && (a.OtherComponents == 0 || nc != a.OtherComponents))
  {
    os << "has " << nc << " component" << (nc == 1 ? "" : "s") << "; it must have " << a.Components;
    if (a.OtherComponents)
    {
      os << " or " << a.OtherComponents;
    }
  }
  else if (array->GetNumberOfTuples() < numberOfPoints)
  {
    os << "has " << array->GetNumberOfTuples() << " tuples for " << numberOfPoints << " points";
  }
  else
  {
    a.Array = array;
    a.Scale = (a.IsColor && array->GetDataType() == VTK_UNSIGNED_CHAR) ? 1.0 / 255.0 : 1.0;
    return true;
  }
  error = os.str();
  return false;
}
}

//------------------------------------------------------------------------------
int vtkClusteredLightSet::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  if (!input)
  {
    return 1; // no input: the lights are the ones set through the per-light API
  }
  const vtkIdType n = input->GetNumberOfPoints();
  vtkPointData* pd = input->GetPointData();
  InputArray color{ "ColorArrayName", this->ColorArrayName, 3, 4, true };
  InputArray intensity{ "IntensityArrayName", this->IntensityArrayName, 1, 0 };
  InputArray attenuation{ "AttenuationArrayName", this->AttenuationArrayName, 3, 0 };
  InputArray radius{ "RadiusArrayName", this->RadiusArrayName, 1, 0 };
  InputArray direction{ "SpotDirectionArrayName", this->SpotDirectionArrayName, 3, 0 };
  InputArray cone{ "ConeAngleArrayName", this->ConeAngleArrayName, 1, 0 };
  InputArray exponent{ "ExponentArrayName", this->ExponentArrayName, 1, 0 };
  InputArray* arrays[] = { &color, &intensity, &attenuation, &radius, &direction, &cone,
    &exponent };

  ++this->NumberOfInputReads;
  vtkInternals& in = *this->Internals;
  for (InputArray* a : arrays)
  {
    std::string error;
    if (!FindInputArray(pd, n, *a, error))
    {
      vtkErrorMacro(<< error << ". The light set holds no lights until this is fixed.");
      in.Resize(0);
      this->Modified();
      return 1;
    }
  }

  in.Resize(static_cast<std::size_t>(n));
  double t[4];
  auto read3 = [&t](const InputArray& a, vtkIdType i, const double fallback[3], double* out)
  {
    if (a.Array)
    {
      a.Array->GetTuple(i, t);
      out[0] = a.Scale * t[0];
      out[1] = a.Scale * t[1];
      out[2] = a.Scale * t[2];
    }
    else
    {
      out[0] = fallback[0];
      out[1] = fallback[1];
      out[2] = fallback[2];
    }
  };
  auto read1 = [](const InputArray& a, vtkIdType i, double fallback)
  { return a.Array ? a.Array->GetComponent(i, 0) : fallback; };
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, &in.Position[3 * i]);
    read3(color, i, this->DefaultColor, &in.Color[3 * i]);
    in.Intensity[i] = read1(intensity, i, this->DefaultIntensity);
    read3(attenuation, i, this->DefaultAttenuation, &in.Attenuation[3 * i]);
    in.Radius[i] = read1(radius, i, this->DefaultRadius);
    in.HasRadius[i] = (radius.Array || this->DefaultRadius >= 0.0) ? 1 : 0;
    read3(direction, i, this->DefaultSpotDirection, &in.Direction[3 * i]);
    in.ConeAngle[i] = read1(cone, i, this->DefaultConeAngle);
    in.Exponent[i] = read1(exponent, i, this->DefaultExponent);
  }
  // The lights changed: a newer MTime makes the pass re-upload them. (Modifying the
  // algorithm inside RequestData does not make the pipeline execute again.)
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto name = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "NumberOfLights: " << this->GetNumberOfLights() << "\n";
  os << indent << "Enabled: " << (this->Enabled ? "On" : "Off") << "\n";
  os << indent << "ColorArrayName: " << name(this->ColorArrayName) << "\n";
  os << indent << "IntensityArrayName: " << name(this->IntensityArrayName) << "\n";
  os << indent << "AttenuationArrayName: " << name(this->AttenuationArrayName) << "\n";
  os << indent << "RadiusArrayName: " << name(this->RadiusArrayName) << "\n";
  os << indent << "SpotDirectionArrayName: " << name(this->SpotDirectionArrayName) << "\n";
  os << indent << "ConeAngleArrayName: " << name(this->ConeAngleArrayName) << "\n";
  os << indent << "ExponentArrayName: " << name(this->ExponentArrayName) << "\n";
  os << indent << "DefaultColor: (" << this->DefaultColor[0] << ", " << this->DefaultColor[1]
     << ", " << this->DefaultColor[2] << ")\n";
  os << indent << "DefaultIntensity: " << this->DefaultIntensity << "\n";
  os << indent << "DefaultAttenuation: (" << this->DefaultAttenuation[0] << ", "
     << this->DefaultAttenuation[1] << ", " << this->DefaultAttenuation[2] << ")\n";
  os << indent << "DefaultRadius: " << this->DefaultRadius << "\n";
  os << indent << "DefaultSpotDirection: (" << this->DefaultSpotDirection[0] << ", "
     << this->DefaultSpotDirection[1] << ", " << this->DefaultSpotDirection[2] << ")\n";
  os << indent << "DefaultConeAngle: " << this->DefaultConeAngle << "\n";
  os << indent << "DefaultExponent: " << this->DefaultExponent << "\n";
  os << indent << "NumberOfInputReads: " << this->NumberOfInputReads << "\n";
}
