// SPDX-License-Identifier: BSD-3-Clause
// Lights as data: vtkClusteredLightSet fed by a VTK pipeline. Checks that
//  - an animated vtkProgrammableSource drives the lights: each frame the light count,
//    positions, colors (unsigned char, scaled), intensities, radii and spots follow the
//    source's output, the pass clusters exactly those lights (zero false negatives
//    against the CPU reference on the last frame), the image changes with the lights,
//    and the shaders are built in the first frame only;
//  - an unchanged pipeline is neither re-read nor re-uploaded;
//  - configurable array names, documented defaults for missing arrays, an input
//    modified in place (SetInputData), and a vtkPointSource without any array;
//  - bad arrays (wrong component count, non-numeric, too few tuples) and a wrong input
//    type give a clear error and no lights, never a crash; fixing the input brings the
//    lights back.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkPointSource.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkProgrammableSource.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
int Status = EXIT_SUCCESS;

void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::printf("FAILED: %s\n", what.c_str());
    Status = EXIT_FAILURE;
  }
}

bool Near(const double a[3], double x, double y, double z)
{
  return std::abs(a[0] - x) < 1e-6 && std::abs(a[1] - y) < 1e-6 && std::abs(a[2] - z) < 1e-6;
}

bool HasError(ClusteredLightingTest::MessageCollector* m, const char* a, const char* b)
{
  for (const std::string& e : m->Errors)
  {
    if (e.find(a) != std::string::npos && e.find(b) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// The animated source: a ring of lights over the floor that turns and grows each frame,
// every fourth light a spot pointing down.
struct Ring
{
  vtkProgrammableSource* Source = nullptr;
  int Frame = 0;
  int Count() const { return 96 + 16 * this->Frame; }
};

void MakeRing(void* arg)
{
  const Ring* ring = static_cast<Ring*>(arg);
  vtkPolyData* out = ring->Source->GetPolyDataOutput();
  const int n = ring->Count();
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> intensity;
  intensity->SetName("Intensity");
  vtkNew<vtkDoubleArray> attenuation;
  attenuation->SetName("Attenuation");
  attenuation->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkFloatArray> direction;
  direction->SetName("SpotDirection");
  direction->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> cone;
  cone->SetName("ConeAngle");
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / n + 0.4 * ring->Frame;
    const double r = 1.4 + 0.9 * ((i * 7) % 11) / 10.0;
    points->InsertNextPoint(r * std::cos(a), r * std::sin(a), 0.15 + 0.05 * (i % 5));
    color->InsertNextTuple3(55 + (i * 37) % 200, 55 + (i * 91) % 200, 55 + (i * 53) % 200);
    intensity->InsertNextValue(static_cast<float>(0.6 + 0.1 * (i % 4)));
    attenuation->InsertNextTuple3(1.0, 0.0, 40.0);
    radius->InsertNextValue(0.7f);
    direction->InsertNextTuple3(0.0, 0.0, -1.0);
    cone->InsertNextValue(i % 4 == 0 ? 50.0f : 180.0f);
  }
  out->SetPoints(points);
  out->GetPointData()->AddArray(color);
  out->GetPointData()->AddArray(intensity);
  out->GetPointData()->AddArray(attenuation);
  out->GetPointData()->AddArray(radius);
  out->GetPointData()->AddArray(direction);
  out->GetPointData()->AddArray(cone);
}

// Every light of the set equals the matching point and point-data tuple of the output.
bool LightsMatchRing(vtkClusteredLightSet* set, vtkPolyData* out)
{
  if (set->GetNumberOfLights() != out->GetNumberOfPoints())
  {
    return false;
  }
  vtkDataArray* color = out->GetPointData()->GetArray("Color");
  vtkDataArray* intensity = out->GetPointData()->GetArray("Intensity");
  vtkDataArray* cone = out->GetPointData()->GetArray("ConeAngle");
  for (vtkIdType i = 0; i < set->GetNumberOfLights(); ++i)
  {
    double p[3], q[3], c[3], d[3], at[3];
    set->GetPosition(i, p);
    out->GetPoint(i, q);
    set->GetColor(i, c);
    set->GetSpotDirection(i, d);
    set->GetAttenuation(i, at);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2] ||
      !Near(c, color->GetComponent(i, 0) / 255.0, color->GetComponent(i, 1) / 255.0,
        color->GetComponent(i, 2) / 255.0) ||
      set->GetIntensity(i) != intensity->GetComponent(i, 0) || !set->HasRadius(i) ||
      std::abs(set->GetRadius(i) - 0.7) > 1e-6 || !Near(at, 1.0, 0.0, 40.0) ||
      !Near(d, 0.0, 0.0, -1.0) || set->GetConeAngle(i) != cone->GetComponent(i, 0) ||
      set->GetExponent(i) != 1.0)
    {
      std::printf("light %lld differs from the pipeline output\n", static_cast<long long>(i));
      return false;
    }
  }
  return true;
}

// A polydata of n points along x with the named point-data arrays added by the caller.
vtkSmartPointer<vtkPolyData> MakePoints(int n)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < n; ++i)
  {
    points->InsertNextPoint(-1.0 + 0.5 * i, 0.5, 0.3);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  return pd;
}

template <class ArrayT>
vtkSmartPointer<ArrayT> MakeArray(const char* name, int components, int tuples, double value)
{
  auto a = vtkSmartPointer<ArrayT>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  for (int i = 0; i < tuples; ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      a->SetComponent(i, c, value + i + 0.25 * c);
    }
  }
  return a;
}
}

int TestClusteredLightingPipeline(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(240, 180);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  renWin->AddRenderer(ren);
  ClusteredLightingTest::AddFloor(ren, 3);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.8);
  sphere->SetCenter(0, 0, 0.6);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  ren->AddActor(sphereActor);
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.1);
  ren->AddLight(headlight);
  ren->GetActiveCamera()->SetPosition(0, -5, 5);
  ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();

  // ---- 1. An animated source drives the lights --------------------------------------
  vtkNew<vtkProgrammableSource> source;
  Ring ring;
  ring.Source = source;
  source->SetExecuteMethod(MakeRing, &ring);
  vtkNew<vtkClusteredLightSet> lights;
  lights->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(lights);
  messages->Watch(pass);

  int shaderBuildsAfterFirstFrame = 0;
  std::vector<float> previous;
  const int frames = 5;
  for (ring.Frame = 0; ring.Frame < frames; ++ring.Frame)
  {
    source->Modified();
    const int uploads = pass->GetNumberOfLightUploads();
    renWin->Render();
    const std::vector<float> pixels = ClusteredLightingTest::CapturePixels(renWin);
    const std::string frame = "frame " + std::to_string(ring.Frame) + ": ";
    std::printf("%s%d lights clustered (%d spots), %d shader builds, %d light uploads, "
                "%d input reads\n",
      frame.c_str(), pass->GetNumberOfClusteredLights(), pass->GetNumberOfSpotLights(),
      pass->GetNumberOfShaderBuilds(), pass->GetNumberOfLightUploads(),
      lights->GetNumberOfInputReads());
    Check(lights->GetNumberOfInputReads() == ring.Frame + 1, frame + "input read once");
    Check(LightsMatchRing(lights, source->GetPolyDataOutput()), frame + "lights follow the data");
    Check(pass->GetNumberOfClusteredLights() == ring.Count(), frame + "every light clustered");
    Check(pass->GetNumberOfSpotLights() == (ring.Count() + 3) / 4, frame + "spot count");
    Check(pass->GetNumberOfLightUploads() == uploads + 1, frame + "lights uploaded");
    if (ring.Frame == 0)
    {
      shaderBuildsAfterFirstFrame = pass->GetNumberOfShaderBuilds();
      Check(shaderBuildsAfterFirstFrame > 0, "shaders built in the first frame");
    }
    else
    {
      Check(pass->GetNumberOfShaderBuilds() == shaderBuildsAfterFirstFrame,
        frame + "no shader rebuild while the source animates");
      const auto diff = ClusteredLightingTest::CompareImages(previous, pixels);
      ClusteredLightingTest::PrintComparison(("  change from the previous " + frame).c_str(), diff);
      Check(diff.MaxAbsError > 0.2 && diff.FractionOverOneStep > 0.01,
        frame + "the image follows the moving lights");
    }
    previous = pixels;
  }
  ring.Frame = frames - 1; // what the source holds (it is not modified again)
  const int ringLights = ring.Count();
  const auto assignment = ClusteredLightingTest::CheckAssignment(pass, ren, "last frame");
  Check(assignment.FalseNegatives == 0 && assignment.MasterMismatches == 0,
    "exact assignment of pipeline lights");

  // An unchanged pipeline: no re-read, no upload, same MTime.
  const vtkMTimeType mtime = lights->GetMTime();
  const int reads = lights->GetNumberOfInputReads();
  const int uploads = pass->GetNumberOfLightUploads();
  renWin->Render();
  renWin->Render();
  Check(lights->GetNumberOfInputReads() == reads && lights->GetMTime() == mtime &&
      pass->GetNumberOfLightUploads() == uploads,
    "an unchanged pipeline is not re-read or re-uploaded");
  Check(messages->Errors.empty() && messages->Warnings.empty(), "no message while animating");

  // ---- 2. Configurable names, defaults, SetInputData modified in place ---------------
  vtkNew<vtkClusteredLightSet> named;
  vtkSmartPointer<vtkPolyData> data = MakePoints(4);
  data->GetPointData()->AddArray(MakeArray<vtkDoubleArray>("rgb", 3, 4, 0.1));
  data->GetPointData()->AddArray(MakeArray<vtkFloatArray>("power", 1, 4, 2.0));
  data->GetPointData()->AddArray(MakeArray<vtkDoubleArray>("falloff", 3, 4, 1.0));
  data->GetPointData()->AddArray(MakeArray<vtkDoubleArray>("reach", 1, 4, 0.5));
  named->SetInputData(data);
  named->SetDefaultColor(0.2, 0.4, 0.6);
  named->SetDefaultIntensity(5.0);
  named->UpdateLights();
  double v[3];
  named->GetColor(2, v);
  Check(named->GetNumberOfLights() == 4 && Near(v, 0.2, 0.4, 0.6) &&
      named->GetIntensity(2) == 5.0 && !named->HasRadius(2),
    "arrays with other names are ignored: defaults apply");
  named->SetColorArrayName("rgb");
  named->SetIntensityArrayName("power");
  named->SetAttenuationArrayName("falloff");
  named->SetRadiusArrayName("reach");
  named->UpdateLights();
  named->GetColor(2, v);
  double at[3];
  named->GetAttenuation(3, at);
  Check(Near(v, 2.1, 2.35, 2.6) && named->GetIntensity(1) == 3.0 && Near(at, 4.0, 4.25, 4.5) &&
      named->HasRadius(0) && named->GetRadius(2) == 2.5,
    "configurable array names are read");
  named->SetIntensityArrayName(nullptr);
  named->UpdateLights();
  Check(named->GetIntensity(1) == 5.0 && named->GetNumberOfInputReads() == 3,
    "a null array name uses the default");
  data->GetPoints()->SetPoint(1, 7.0, 8.0, 9.0);
  data->GetPoints()->Modified();
  named->UpdateLights();
  named->GetPosition(1, v);
  Check(Near(v, 7.0, 8.0, 9.0), "an input modified in place is re-read");

  // A vtkPointSource has no arrays at all: every light gets the defaults.
  vtkNew<vtkPointSource> cloud;
  cloud->SetNumberOfPoints(50);
  cloud->SetCenter(0, 0, 1);
  cloud->SetRadius(1.5);
  vtkNew<vtkClusteredLightSet> plain;
  plain->SetInputConnection(cloud->GetOutputPort());
  plain->SetDefaultColor(1.0, 0.5, 0.25);
  plain->SetDefaultAttenuation(1.0, 0.0, 4.0);
  plain->SetDefaultRadius(0.5);
  plain->UpdateLights();
  bool defaultsOk = plain->GetNumberOfLights() == 50;
  for (vtkIdType i = 0; defaultsOk && i < 50; ++i)
  {
    double c[3], p[3], q[3];
    plain->GetColor(i, c);
    plain->GetAttenuation(i, at);
    plain->GetPosition(i, p);
    cloud->GetOutput()->GetPoint(i, q);
    defaultsOk = Near(c, 1.0, 0.5, 0.25) && Near(at, 1.0, 0.0, 4.0) && plain->HasRadius(i) &&
      plain->GetRadius(i) == 0.5 && plain->GetIntensity(i) == 1.0 &&
      plain->GetConeAngle(i) == 180.0 && Near(p, q[0], q[1], q[2]);
  }
  Check(defaultsOk, "a point source without arrays gets the documented defaults");
  pass->AddLightSet(plain);
  renWin->Render();
  Check(pass->GetNumberOfClusteredLights() == ringLights + 50 &&
      pass->GetNumberOfShaderBuilds() == shaderBuildsAfterFirstFrame,
    "a second pipeline set is clustered without shader rebuild");

  // ---- 3. Bad input: clear errors, no lights, no crash ------------------------------
  vtkNew<ClusteredLightingTest::MessageCollector> errors;
  errors->Watch(plain);
  errors->Watch(plain->GetExecutive());
  vtkSmartPointer<vtkPolyData> bad = MakePoints(3);
  bad->GetPointData()->AddArray(MakeArray<vtkFloatArray>("Color", 2, 3, 0.5));
  plain->SetInputData(bad);
  renWin->Render();
  Check(HasError(errors, "'Color'", "2 components") && plain->GetNumberOfLights() == 0 &&
      pass->GetNumberOfClusteredLights() == ringLights,
    "a 2-component color array is an error and gives no lights");

  bad->GetPointData()->RemoveArray("Color");
  vtkNew<vtkStringArray> names;
  names->SetName("Intensity");
  names->SetNumberOfValues(3);
  bad->GetPointData()->AddArray(names);
  errors->Clear();
  plain->UpdateLights();
  Check(HasError(errors, "'Intensity'", "vtkStringArray") && plain->GetNumberOfLights() == 0,
    "a string intensity array is an error");

  bad->GetPointData()->RemoveArray("Intensity");
  bad->GetPointData()->AddArray(MakeArray<vtkFloatArray>("Radius", 1, 2, 0.5));
  errors->Clear();
  plain->UpdateLights();
  Check(HasError(errors, "'Radius'", "2 tuples for 3 points") && plain->GetNumberOfLights() == 0,
    "a radius array shorter than the points is an error");

  bad->GetPointData()->RemoveArray("Radius");
  bad->Modified();
  errors->Clear();
  renWin->Render();
  Check(errors->Errors.empty() && plain->GetNumberOfLights() == 3 &&
      pass->GetNumberOfClusteredLights() == ringLights + 3,
    "fixed input: the lights come back");

  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 2);
  plain->SetInputDataObject(image);
  errors->Clear();
  renWin->Render();
  Check(HasError(errors, "vtkImageData", "vtkPolyData") && plain->GetNumberOfLights() == 0,
    "an image input is an error and gives no lights");
  Check(pass->GetNumberOfClusteredLights() == ringLights, "the other set still renders");

  // Disconnected: the set keeps its lights and the per-light API works again.
  plain->SetInputConnection(cloud->GetOutputPort());
  plain->UpdateLights();
  plain->SetInputConnection(nullptr);
  plain->SetColor(0, 0.0, 1.0, 0.0);
  plain->UpdateLights();
  plain->GetColor(0, v);
  Check(plain->GetNumberOfLights() == 50 && Near(v, 0.0, 1.0, 0.0),
    "a disconnected set keeps its lights and per-light edits");
  Check(messages->Errors.empty(), "no error from the animated set");
  return Status;
}
