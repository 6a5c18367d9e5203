// SPDX-License-Identifier: BSD-3-Clause
// Volumes under the pass (vtkGPUVolumeRayCastMapper and vtkSmartVolumeMapper, shading on),
// beside a polydata sphere. Until 2026-11-28 both failed:
//  - the ray caster's shaders did not compile: the pass declared `invariant gl_Position`
//    above the #extension directive VTK's ray caster writes in its own vertex shader, and
//    every volume vanished, whatever the lights;
//  - its positional lights did not light it: the pass hides its clustered vtkLights from
//    VTK's lighting code while the delegate renders, volumes included (up to 217 steps
//    darker).
// Checks, against stock VTK (the same scene without the pass):
//  1. headlight only: the image is stock VTK's, bit for bit;
//  2. two positional vtkLights, which the pass clusters: the volume's pixels are stock
//     VTK's bit for bit (VTK's own volume lighting, every light), the sphere's within one
//     step (clustered shading against VTK's, float sums in another order);
//  3. a vtkClusteredLightSet added: one warning says volumes are lit by the renderer's
//     vtkLights only; the volume's pixels do not change, the sphere's do;
//  4. through an application's delegate (as in ParaView), which renders the volumes with
//     the surfaces, so the pass cannot hand the volumes their lights: with a shaded volume
//     in the frame the renderer's lights stay with VTK (GetRendererLightsLeftToVTK), and
//     the image is stock VTK's bit for bit, volume and sphere; without the volume, or with
//     an unshaded one, the pass clusters them again. No warning (until 2026-11-29 the
//     volume missed those lights, with a warning).
// Nothing reaches VTK's output window (a shader that fails to compile would).
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderStepsPass.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

constexpr int Width = 200;
constexpr int Height = 150;
constexpr int VolumeColumns = 120; ///< the volume lies left of this column, the sphere right

/// A shaded volume of VTK's analytic wavelet (an opaque blob), drawn by a
/// vtkGPUVolumeRayCastMapper or a vtkSmartVolumeMapper, and a sphere to its right; the
/// volume (the renderer holds it).
vtkVolume* AddScene(vtkRenderer* ren, bool smart)
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-20, 20, -20, 20, -20, 20);
  vtkSmartPointer<vtkVolumeMapper> mapper;
  if (smart)
  {
    mapper = vtkSmartPointer<vtkSmartVolumeMapper>::New();
  }
  else
  {
    mapper = vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
  }
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(40.0, 0.9, 0.9, 0.9);
  color->AddRGBPoint(280.0, 1.0, 1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(40.0, 0.0);
  opacity->AddPoint(150.0, 0.0);
  opacity->AddPoint(160.0, 1.0);
  opacity->AddPoint(280.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->ShadeOn();
  property->SetInterpolationTypeToLinear();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  ren->AddVolume(volume);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(30.0, 0.0, 0.0);
  sphere->SetRadius(8.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);
  ren->AddActor(actor);
  ren->SetBackground(0.05, 0.05, 0.08);
  ren->ResetCamera();
  return volume;
}

void AddPositionalLights(vtkRenderer* ren)
{
  const double positions[2][3] = { { -40, 30, 40 }, { 40, -20, 40 } };
  const double colors[2][3] = { { 1, 0.4, 0.3 }, { 0.3, 0.5, 1 } };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetConeAngle(180.0);
    light->SetPosition(positions[i]);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetColor(colors[i]);
    ren->AddLight(light);
  }
}

/// Renders a fresh window of the scene (with the pass when given) twice; its pixels. With
/// `volumeShown` false the volume is hidden; with `shaded` false it is not shaded.
std::vector<float> Render(bool positional, vtkClusteredLightingPass* pass, bool smart = false,
  bool volumeShown = true, bool shaded = true)
{
  vtkNew<vtkRenderWindow> rw;
  rw->SetSize(Width, Height);
  rw->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  rw->AddRenderer(ren);
  vtkVolume* volume = AddScene(ren, smart);
  volume->SetVisibility(volumeShown);
  volume->GetProperty()->SetShade(shaded);
  if (positional)
  {
    AddPositionalLights(ren);
  }
  if (pass)
  {
    ren->SetPass(pass);
  }
  rw->Render();
  rw->Render();
  std::vector<float> pixels = ClusteredLightingTest::CapturePixels(rw);
  if (pass)
  {
    pass->ReleaseGraphicsResources(rw);
  }
  return pixels;
}

/// Largest difference in steps in columns [x0, x1), and the pixels over `tolerance` steps.
double MaxSteps(const std::vector<float>& a, const std::vector<float>& b, int x0, int x1,
  double tolerance, int& over)
{
  double worst = 0.0;
  over = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      double pixel = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * Width + x) + k;
        pixel = std::max(pixel, std::abs(double(a[i]) - double(b[i])) * 255.0);
      }
      worst = std::max(worst, pixel);
      over += pixel > tolerance + 0.01 ? 1 : 0;
    }
  }
  return worst;
}

/// Pixels in columns [x0, x1) that are not the background.
int Covered(const std::vector<float>& image, int x0, int x1)
{
  int n = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      n += std::abs(image[3 * (static_cast<std::size_t>(y) * Width + x)] - 0.05f) > 0.01f ? 1 : 0;
    }
  }
  return n;
}
}

int TestClusteredLightingVolumes(int, char*[])
{
  ClusteredLightingTest::OutputCapture output;

  vtkNew<vtkClusteredLightingPass> pass;
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  int over = 0;

  for (bool smart : { false, true })
  {
    const std::string mapper = smart ? "vtkSmartVolumeMapper" : "vtkGPUVolumeRayCastMapper";
    // 1. Headlight only.
    const std::vector<float> stockHead = Render(false, nullptr, smart);
    Check(Covered(stockHead, 0, VolumeColumns) > 3000,
      mapper + ": the volume covers the left of the image");
    const std::vector<float> passHead = Render(false, pass, smart);
    const double head = MaxSteps(passHead, stockHead, 0, Width, 0.0, over);
    Check(head == 0.0,
      mapper + ", headlight only: stock VTK's image, bit for bit (max " + std::to_string(head) +
        " steps)");

    // 2. Two positional lights, clustered.
    const std::vector<float> stockLit = Render(true, nullptr, smart);
    Check(MaxSteps(stockLit, stockHead, 0, VolumeColumns, 0.0, over) > 50.0,
      mapper + ": the positional lights change stock VTK's volume");
    const std::vector<float> passLit = Render(true, pass, smart);
    Check(pass->GetNumberOfClusteredLights() == 2,
      mapper + ": the pass clusters the 2 positional lights");
    const double volume = MaxSteps(passLit, stockLit, 0, VolumeColumns, 0.0, over);
    Check(volume == 0.0,
      mapper + ", positional lights: the volume is stock VTK's, bit for bit (max " +
        std::to_string(volume) + " steps, " + std::to_string(over) + " pixels differ)");
    const double sphere = MaxSteps(passLit, stockLit, VolumeColumns, Width, 1.0, over);
    Check(sphere <= 1.0 && MaxSteps(passLit, passHead, VolumeColumns, Width, 0.0, over) > 10.0,
      mapper + ", positional lights: the sphere, clustered, within 1 step of stock VTK's (max " +
        std::to_string(sphere) + ")");
  }
  Check(messages->Warnings.empty(), "no warning without light sets");
  const std::vector<float> passLit = Render(true, pass);

  // 3. A light set too: it lights the sphere, not the volume, and says so once.
  vtkNew<vtkClusteredLightSet> set;
  set->SetNumberOfLights(1);
  set->SetPosition(0, 30.0, 0.0, 20.0);
  set->SetColor(0, 0.2, 1.0, 0.2);
  pass->AddLightSet(set);
  const std::vector<float> withSet = Render(true, pass);
  Check(MaxSteps(withSet, passLit, 0, VolumeColumns, 0.0, over) == 0.0,
    "a light set: the volume's pixels do not change");
  Check(MaxSteps(withSet, passLit, VolumeColumns, Width, 0.0, over) > 10.0,
    "a light set: it lights the sphere");
  Render(true, pass);
  Check(messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("volumes are lit by the renderer's vtkLights only") !=
        std::string::npos,
    "one warning in two windows says the light sets do not light volumes");
  if (!messages->Warnings.empty())
  {
    std::printf("the warning: %s\n", messages->Warnings[0].c_str());
  }
  Check(messages->Errors.empty(), "no error");

  // 4. An application's delegate (ParaView's renders through the renderer): it renders the
  // volume with the surfaces, so a shaded volume keeps the renderer's lights with VTK.
  pass->RemoveAllLightSets();
  messages->Warnings.clear();
  vtkNew<vtkRenderStepsPass> foreign;
  pass->SetDelegatePass(foreign);
  for (bool smart : { false, true })
  {
    const std::string mapper = smart ? "vtkSmartVolumeMapper" : "vtkGPUVolumeRayCastMapper";
    const std::vector<float> stockLit = Render(true, nullptr, smart);
    const std::vector<float> viaForeign = Render(true, pass, smart);
    Check(pass->GetRendererLightsLeftToVTK() && pass->GetNumberOfClusteredLights() == 0,
      mapper + ", an application's delegate: the 2 positional lights are left to VTK (" +
        std::to_string(pass->GetNumberOfClusteredLights()) + " clustered)");
    const double all = MaxSteps(viaForeign, stockLit, 0, Width, 0.0, over);
    Check(all == 0.0,
      mapper + ", an application's delegate: stock VTK's image, volume and sphere, bit for " +
        "bit (max " + std::to_string(all) + " steps, " + std::to_string(over) + " pixels differ)");
  }
  const std::vector<float> stockHidden = Render(true, nullptr, false, false);
  const std::vector<float> hidden = Render(true, pass, false, false);
  Check(!pass->GetRendererLightsLeftToVTK() && pass->GetNumberOfClusteredLights() == 2,
    "an application's delegate, the volume hidden: the pass clusters the 2 lights (" +
      std::to_string(pass->GetNumberOfClusteredLights()) + ")");
  const double sphereHidden = MaxSteps(hidden, stockHidden, 0, Width, 1.0, over);
  Check(sphereHidden <= 1.0,
    "an application's delegate, the volume hidden: within 1 step of stock VTK (max " +
      std::to_string(sphereHidden) + ")");
  const std::vector<float> stockUnshaded = Render(true, nullptr, false, true, false);
  const std::vector<float> unshaded = Render(true, pass, false, true, false);
  Check(!pass->GetRendererLightsLeftToVTK() && pass->GetNumberOfClusteredLights() == 2,
    "an application's delegate, an unshaded volume: the pass clusters the 2 lights (" +
      std::to_string(pass->GetNumberOfClusteredLights()) + ")");
  const double volumeUnshaded = MaxSteps(unshaded, stockUnshaded, 0, VolumeColumns, 0.0, over);
  const double sphereUnshaded = MaxSteps(unshaded, stockUnshaded, VolumeColumns, Width, 1.0, over);
  Check(volumeUnshaded == 0.0 && sphereUnshaded <= 1.0,
    "an application's delegate, an unshaded volume: the volume stock VTK's bit for bit (max " +
      std::to_string(volumeUnshaded) + "), the sphere within 1 step (max " +
      std::to_string(sphereUnshaded) + ")");
  Check(messages->Warnings.empty() && messages->Errors.empty(),
    "an application's delegate: no warning, no error");

  const std::string printed = output.Finish();
  Check(printed.empty(), "nothing reached VTK's output window: " + printed);
  return ClusteredLightingTest::CheckStatus();
}
