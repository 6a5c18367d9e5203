// SPDX-License-Identifier: BSD-3-Clause
// Exposure (issue 14, item 8): vtkClusteredLightSet::IntensityScale.
//  - 400 lights at intensity 1 saturate the room: many channels reach 255;
//  - the image of the set with IntensityScale 0.5 equals, within one 8-bit step, the image
//    of the same lights with every intensity halved (and is visibly darker than scale 1);
//  - the same for a set fed by a pipeline (its intensities from a point-data array);
//  - scale 0 renders as lights of intensity 0 (black: the room has no other light);
//  - changing the scale re-uploads the lights without rebuilding a shader.
#include "ClusteredLightingHardCase.h"

#include "vtkClusteredLightSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <random>
#include <string>

using namespace ClusteredLightingTest;

namespace
{
int Status = EXIT_SUCCESS;

void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok)
  {
    Status = EXIT_FAILURE;
  }
}

double Saturated(const std::vector<float>& image)
{
  std::size_t n = 0;
  for (float v : image)
  {
    n += v >= 1.0f ? 1 : 0;
  }
  return double(n) / double(image.size());
}

double Mean(const std::vector<float>& image)
{
  double sum = 0.0;
  for (float v : image)
  {
    sum += v;
  }
  return sum / double(image.size());
}

// n lights spread through the room, random colors, the given intensity, attenuation
// (1, 0, 3): each light reaches the whole room.
void MakeBrightLights(vtkClusteredLightSet* set, int n, double intensity)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(-4.5, 4.5);
  std::uniform_real_distribution<double> C(0.2, 1.0);
  set->SetNumberOfLights(n);
  for (int i = 0; i < n; ++i)
  {
    const double x = U(rng), y = U(rng), z = U(rng);
    set->SetPosition(i, x, y, z);
    const double r = C(rng), g = C(rng), b = C(rng);
    set->SetColor(i, r, g, b);
    set->SetIntensity(i, intensity);
    set->SetAttenuation(i, 1.0, 0.0, 3.0);
  }
}

// The set's lights as a polydata with "Color", "Intensity" and "Attenuation" arrays,
// intensities multiplied by `factor`.
vtkSmartPointer<vtkPolyData> AsPolyData(vtkClusteredLightSet* set, double factor)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> color, intensity;
  vtkNew<vtkDoubleArray> attenuation;
  color->SetName("Color");
  color->SetNumberOfComponents(3);
  intensity->SetName("Intensity");
  attenuation->SetName("Attenuation");
  attenuation->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < set->GetNumberOfLights(); ++i)
  {
    points->InsertNextPoint(set->GetPosition(i));
    color->InsertNextTuple(set->GetColor(i));
    intensity->InsertNextValue(static_cast<float>(factor * set->GetIntensity(i)));
    attenuation->InsertNextTuple(set->GetAttenuation(i));
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(color);
  pd->GetPointData()->AddArray(intensity);
  pd->GetPointData()->AddArray(attenuation);
  return pd;
}
} // namespace

int TestClusteredLightingIntensityScale(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  SetUpRoomWindow(renWin, ren);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0.3, 0.2, 4.5);
  cam->SetFocalPoint(0, 0, -2);
  cam->SetViewAngle(60);
  cam->SetClippingRange(0.5, 12.0);

  // 400 lights of intensity 1 that reach far (attenuation (1, 0, 3)): too bright.
  vtkNew<vtkClusteredLightSet> scaled;
  MakeBrightLights(scaled, 400, 1.0);
  // The same lights with every intensity halved.
  vtkNew<vtkClusteredLightSet> halved;
  MakeBrightLights(halved, 400, 0.5);

  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(scaled);
  ren->SetPass(pass);
  renWin->Render();
  const std::vector<float> full = CapturePixels(renWin);
  const int builds = pass->GetNumberOfShaderBuilds();
  const int uploads = pass->GetNumberOfLightUploads();
  scaled->SetIntensityScale(0.5);
  renWin->Render();
  const std::vector<float> half = CapturePixels(renWin);
  Check(pass->GetNumberOfShaderBuilds() == builds && pass->GetNumberOfLightUploads() == uploads + 1,
    "a new scale re-uploads the lights and rebuilds no shader");

  pass->RemoveAllLightSets();
  pass->AddLightSet(halved);
  renWin->Render();
  const std::vector<float> reference = CapturePixels(renWin);

  std::printf("saturated channels: scale 1 %.1f%%, scale 0.5 %.1f%%; mean %.3f vs %.3f\n",
    100.0 * Saturated(full), 100.0 * Saturated(half), Mean(full), Mean(half));
  Check(Saturated(full) > 0.05, "400 lights at intensity 1 saturate the room (> 5% of channels)");
  const ImageComparison same = CompareImages(half, reference);
  PrintComparison("scale 0.5 vs intensities halved", same);
  Check(same.MaxAbsError <= 1.0 / 255.0 + 1e-6,
    "scale 0.5 equals every intensity halved within one step");
  const ImageComparison darker = CompareImages(full, half);
  Check(Mean(half) < 0.8 * Mean(full) && darker.MaxAbsError > 20.0 / 255.0,
    "scale 0.5 is visibly darker than scale 1");

  // A set fed by a pipeline: the scale applies to the intensities read from the input.
  vtkNew<vtkClusteredLightSet> fed;
  fed->SetInputData(AsPolyData(scaled, 1.0));
  fed->SetIntensityScale(0.5);
  pass->RemoveAllLightSets();
  pass->AddLightSet(fed);
  renWin->Render();
  const std::vector<float> fedHalf = CapturePixels(renWin);
  const ImageComparison fedSame = CompareImages(fedHalf, reference);
  PrintComparison("pipeline-fed set, scale 0.5 vs intensities halved", fedSame);
  Check(fedSame.MaxAbsError <= 1.0 / 255.0 + 1e-6 && fed->GetNumberOfLights() == 400,
    "a pipeline-fed set: scale 0.5 equals every intensity halved within one step");

  // Scale 0: as dark as lights of intensity 0 (the room has no other light).
  fed->SetIntensityScale(0.0);
  renWin->Render();
  const std::vector<float> zero = CapturePixels(renWin);
  vtkNew<vtkClusteredLightSet> unlit;
  MakeBrightLights(unlit, 400, 0.0);
  pass->RemoveAllLightSets();
  pass->AddLightSet(unlit);
  renWin->Render();
  const std::vector<float> black = CapturePixels(renWin);
  const ImageComparison dark = CompareImages(zero, black);
  PrintComparison("scale 0 vs intensity 0", dark);
  Check(dark.MaxAbsError <= 1.0 / 255.0 + 1e-6 && Mean(zero) < 0.01,
    "scale 0 renders as lights of intensity 0: black");
  return Status;
}
