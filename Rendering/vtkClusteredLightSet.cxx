// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightSet.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkWeakPointer.h"

#include <algorithm> // for std::copy
#include <cmath>     // for std::isnan
#include <sstream>   // for std::ostringstream
#include <string>    // for std::string
#include <vector>    // for std::vector

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

  // The input connection a per-light setter was last warned about (item: the input
  // defines the lights); a new connection warns again.
  vtkWeakPointer<vtkAlgorithmOutput> WarnedConnection;
  // The input-type error last reported and the connection it was about, so that it is
  // given once while it persists.
  std::string ReportedInputError;
  vtkWeakPointer<vtkAlgorithmOutput> ReportedInputConnection;

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
void vtkClusteredLightSet::WarnIfInputDefinesLights(const char* setter)
{
  vtkAlgorithmOutput* connection =
    this->GetNumberOfInputConnections(0) > 0 ? this->GetInputConnection(0, 0) : nullptr;
  if (!connection || connection == this->Internals->WarnedConnection.GetPointer())
  {
    return;
  }
  this->Internals->WarnedConnection = connection;
  vtkAlgorithm* producer = connection->GetProducer();
  vtkWarningMacro(<< setter << "() changes the lights of a light set that has an input ("
                  << (producer ? producer->GetClassName() : "a pipeline")
                  << "): the input defines the lights, and the change is replaced when the "
                     "set reads its input again (at the next render, or UpdateLights()). "
                     "Give the parameters as point-data arrays of the input, or disconnect "
                     "it (SetInputConnection(nullptr)) to set lights one by one. Not "
                     "reported again while this input stays connected.");
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetNumberOfLights(vtkIdType n)
{
  this->WarnIfInputDefinesLights("SetNumberOfLights");
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
  this->WarnIfInputDefinesLights("AddLight");
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
  this->WarnIfInputDefinesLights("RemoveAllLights");
  if (this->GetNumberOfLights() > 0)
  {
    this->Internals->Resize(0);
    this->Modified();
  }
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
// What the value getters return for an index out of range (after the error).
const double NoValue[3] = { 0.0, 0.0, 0.0 };

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
  this->WarnIfInputDefinesLights("SetPosition");
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
  this->WarnIfInputDefinesLights("SetColor");
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
  this->WarnIfInputDefinesLights("SetIntensity");
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
  this->WarnIfInputDefinesLights("SetAttenuation");
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
  this->WarnIfInputDefinesLights("SetRadius");
  if (this->CheckIndex(i))
  {
    this->Internals->Radius[i] = radius;
    this->Internals->HasRadius[i] = 1;
    this->Modified();
  }
}

void vtkClusteredLightSet::UnsetRadius(vtkIdType i)
{
  this->WarnIfInputDefinesLights("UnsetRadius");
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
  this->WarnIfInputDefinesLights("SetSpot");
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
  this->WarnIfInputDefinesLights("SetPointLight");
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
const double* vtkClusteredLightSet::GetPosition(vtkIdType i) const
{
  return this->CheckIndex(i) ? &this->Internals->Position[3 * i] : NoValue;
}

const double* vtkClusteredLightSet::GetColor(vtkIdType i) const
{
  return this->CheckIndex(i) ? &this->Internals->Color[3 * i] : NoValue;
}

const double* vtkClusteredLightSet::GetAttenuation(vtkIdType i) const
{
  return this->CheckIndex(i) ? &this->Internals->Attenuation[3 * i] : NoValue;
}

const double* vtkClusteredLightSet::GetSpotDirection(vtkIdType i) const
{
  return this->CheckIndex(i) ? &this->Internals->Direction[3 * i] : NoValue;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::SetIntensityScale(double scale)
{
  if (std::isnan(scale))
  {
    vtkErrorMacro("IntensityScale NaN ignored.");
    return;
  }
  const double clamped =
    scale < 0.0 ? 0.0 : (scale > VTK_FLOAT_MAX ? static_cast<double>(VTK_FLOAT_MAX) : scale);
  if (clamped != this->IntensityScale)
  {
    this->IntensityScale = clamped;
    this->Modified();
  }
}

double vtkClusteredLightSet::GetScaledIntensity(vtkIdType i) const
{
  return this->GetIntensity(i) * this->IntensityScale;
}

//------------------------------------------------------------------------------
void vtkClusteredLightSet::ReportProblem(const char* message)
{
  if (!message || !vtkObject::GetGlobalWarningDisplay() ||
    !this->HasObserver(vtkCommand::WarningEvent))
  {
    return;
  }
  std::ostringstream os;
  os << "Warning: " << this->GetClassName() << " (" << this << "): " << message << "\n";
  std::string text = os.str();
  this->InvokeEvent(vtkCommand::WarningEvent, &text[0]);
}

//------------------------------------------------------------------------------
// Bulk access: one tuple per light.
namespace
{
// Copies `array` into `values` (`components` per light) after checking it: `tuples` tuples
// (any number when negative) of `components` (or `other`) components. Reports what is
// wrong on `self` and returns false, changing nothing.
bool CopyFromArray(vtkClusteredLightSet* self, const char* method, vtkDataArray* array,
  vtkIdType tuples, int components, int other, std::vector<double>& values, double scale = 1.0)
{
  std::ostringstream os;
  const int nc = array ? array->GetNumberOfComponents() : 0;
  if (!array)
  {
    os << method << "(): the array is null";
  }
  else if (nc != components && (other == 0 || nc != other))
  {
    os << method << "(): the " << array->GetClassName() << " has " << nc << " component"
       << (nc == 1 ? "" : "s") << "; it must have " << components;
    if (other)
    {
      os << " or " << other;
    }
  }
  else if (tuples >= 0 && array->GetNumberOfTuples() != tuples)
  {
    os << method << "(): the array has " << array->GetNumberOfTuples() << " tuples for " << tuples
       << " lights (SetPositions() sets the number of lights)";
  }
  if (!os.str().empty())
  {
    vtkErrorWithObjectMacro(self, << os.str() << ". Nothing was changed.");
    return false;
  }
  const vtkIdType n = array->GetNumberOfTuples();
  values.resize(static_cast<std::size_t>(components * n));
  std::vector<double> tuple(static_cast<std::size_t>(nc));
  for (vtkIdType i = 0; i < n; ++i)
  {
    array->GetTuple(i, tuple.data());
    for (int c = 0; c < components; ++c)
    {
      values[static_cast<std::size_t>(components * i + c)] =
        scale * tuple[static_cast<std::size_t>(c)];
    }
  }
  return true;
}

void CopyToArray(const std::vector<double>& values, int components, vtkDoubleArray* array)
{
  if (!array)
  {
    return;
  }
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  array->Modified();
}
} // namespace

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetPositions(vtkDataArray* positions)
{
  this->WarnIfInputDefinesLights("SetPositions");
  std::vector<double> values;
  if (!CopyFromArray(this, "SetPositions", positions, -1, 3, 0, values))
  {
    return false;
  }
  this->Internals->Resize(values.size() / 3);
  this->Internals->Position.swap(values);
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetPositions(vtkDoubleArray* positions) const
{
  CopyToArray(this->Internals->Position, 3, positions);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetColors(vtkDataArray* colors)
{
  this->WarnIfInputDefinesLights("SetColors");
  const double scale = colors && colors->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  if (!CopyFromArray(
        this, "SetColors", colors, this->GetNumberOfLights(), 3, 4, this->Internals->Color, scale))
  {
    return false;
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetColors(vtkDoubleArray* colors) const
{
  CopyToArray(this->Internals->Color, 3, colors);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetIntensities(vtkDataArray* intensities)
{
  this->WarnIfInputDefinesLights("SetIntensities");
  if (!CopyFromArray(this, "SetIntensities", intensities, this->GetNumberOfLights(), 1, 0,
        this->Internals->Intensity))
  {
    return false;
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetIntensities(vtkDoubleArray* intensities) const
{
  CopyToArray(this->Internals->Intensity, 1, intensities);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetAttenuations(vtkDataArray* attenuations)
{
  this->WarnIfInputDefinesLights("SetAttenuations");
  if (!CopyFromArray(this, "SetAttenuations", attenuations, this->GetNumberOfLights(), 3, 0,
        this->Internals->Attenuation))
  {
    return false;
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetAttenuations(vtkDoubleArray* attenuations) const
{
  CopyToArray(this->Internals->Attenuation, 3, attenuations);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetRadii(vtkDataArray* radii)
{
  this->WarnIfInputDefinesLights("SetRadii");
  std::vector<double> values;
  if (!CopyFromArray(this, "SetRadii", radii, this->GetNumberOfLights(), 1, 0, values))
  {
    return false;
  }
  vtkInternals& in = *this->Internals;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    // Negative: no explicit radius. NaN is kept (and rejected when lights are prepared).
    in.HasRadius[i] = values[i] < 0.0 ? 0 : 1;
    in.Radius[i] = values[i] < 0.0 ? 0.0 : values[i];
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetRadii(vtkDoubleArray* radii) const
{
  const vtkInternals& in = *this->Internals;
  std::vector<double> values(in.Radius.size());
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    values[i] = in.HasRadius[i] ? in.Radius[i] : -1.0;
  }
  CopyToArray(values, 1, radii);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetSpotDirections(vtkDataArray* directions)
{
  this->WarnIfInputDefinesLights("SetSpotDirections");
  if (!CopyFromArray(this, "SetSpotDirections", directions, this->GetNumberOfLights(), 3, 0,
        this->Internals->Direction))
  {
    return false;
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetSpotDirections(vtkDoubleArray* directions) const
{
  CopyToArray(this->Internals->Direction, 3, directions);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetConeAngles(vtkDataArray* coneAngles)
{
  this->WarnIfInputDefinesLights("SetConeAngles");
  if (!CopyFromArray(this, "SetConeAngles", coneAngles, this->GetNumberOfLights(), 1, 0,
        this->Internals->ConeAngle))
  {
    return false;
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetConeAngles(vtkDoubleArray* coneAngles) const
{
  CopyToArray(this->Internals->ConeAngle, 1, coneAngles);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightSet::SetExponents(vtkDataArray* exponents)
{
  this->WarnIfInputDefinesLights("SetExponents");
  if (!CopyFromArray(this, "SetExponents", exponents, this->GetNumberOfLights(), 1, 0,
        this->Internals->Exponent))
  {
    return false;
  }
  this->Modified();
  return true;
}

void vtkClusteredLightSet::GetExponents(vtkDoubleArray* exponents) const
{
  CopyToArray(this->Internals->Exponent, 1, exponents);
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
  // Any data object: RequestData() reports an input that is not a vtkPolyData itself, on
  // the set (where observers look), once while it persists. With "vtkPolyData" here the
  // executive reported it on every update, and only on the executive.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
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
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkDataObject* object = inInfo ? inInfo->Get(vtkDataObject::DATA_OBJECT()) : nullptr;
  if (!object)
  {
    return 1; // no input: the lights are the ones set through the per-light API
  }
  vtkInternals& in = *this->Internals;
  vtkPolyData* input = vtkPolyData::SafeDownCast(object);
  if (!input)
  {
    std::ostringstream os;
    os << "The input is a " << object->GetClassName()
       << "; a light set needs a vtkPolyData (every point is a light, its parameters come "
          "from point-data arrays). The light set holds no lights until this is fixed.";
    // Once while it persists: the same message for the same connection is not repeated
    // when the input is modified or the pipeline updates again.
    vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
    if (os.str() != in.ReportedInputError || connection != in.ReportedInputConnection)
    {
      in.ReportedInputError = os.str();
      in.ReportedInputConnection = connection;
      vtkErrorMacro(<< in.ReportedInputError);
    }
    if (this->GetNumberOfLights() > 0)
    {
      in.Resize(0);
      this->Modified();
    }
    return 1;
  }
  in.ReportedInputError.clear();
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
  os << indent << "IntensityScale: " << this->IntensityScale << "\n";
  os << indent << "NumberOfInputReads: " << this->NumberOfInputReads << "\n";
}
