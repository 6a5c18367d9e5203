// SPDX-License-Identifier: BSD-3-Clause
// Many point lights over a real mesh with vtkClusteredLightingPass.
//
// Renders the Stanford bunny on a floor lit by 4,096 (or --lights N) colored point lights
// at 1024x768, writes the image, and prints the clustered frame time next to the
// brute-force frame time of the same scene (same shading code, every light for every
// fragment). With -I it opens an interactive window instead.
//
// The lights use the "game engine" light model that the pass offers next to VTK's exact
// one: each has an explicit radius (0.45) and the windowed falloff, so it lights a
// visible pool that fades smoothly to zero at its radius. (With VTK's inverse-square
// attenuation and the default 1/1024 cutoff, a light's bright spot is only about 1/20 of
// its influence radius; see the README's accuracy section and TestClusteredLightingManyLights.)
//
//   ManyLights [--lights N] [--size W H] [--frames F] [--brute-frames B]
//              [--subdivide L] [--output image.png] [--heatmap heat.png] [-I]
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCleanPolyData.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace
{
const char* BunnyPath = "/usr/share/glmark2/models/bunny.obj"; // Debian's glmark2-data

// The Stanford bunny (about [-1, 1]^3) with normals, Loop-subdivided `levels` times, on a
// 6 x 6 floor at y = -1.
bool AddBunnyOnFloor(vtkRenderer* ren, int levels, vtkIdType& triangles)
{
  const char* dir = std::getenv("CLUSTERED_LIGHTING_DATA");
  const std::string local = dir ? std::string(dir) + "/bunny.obj" : std::string();
  const std::string path = vtksys::SystemTools::FileExists(local) ? local : BunnyPath;
  if (!vtksys::SystemTools::FileExists(path))
  {
    std::fprintf(
      stderr, "bunny mesh not found at %s (run scripts/install-deps.sh)\n", path.c_str());
    return false;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkLoopSubdivisionFilter> subdivide;
  subdivide->SetInputConnection(clean->GetOutputPort());
  subdivide->SetNumberOfSubdivisions(std::max(levels, 0));
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(levels > 0 ? subdivide->GetOutputPort() : clean->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  triangles = normals->GetOutput()->GetNumberOfPolys();
  vtkNew<vtkPolyDataMapper> bunnyMapper;
  bunnyMapper->SetInputConnection(normals->GetOutputPort());
  vtkNew<vtkActor> bunny;
  bunny->SetMapper(bunnyMapper);
  bunny->GetProperty()->SetColor(0.85, 0.85, 0.8);
  bunny->GetProperty()->SetSpecular(0.3);
  bunny->GetProperty()->SetSpecularPower(20);
  ren->AddActor(bunny);

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3, -1, -3);
  plane->SetPoint1(3, -1, -3);
  plane->SetPoint2(-3, -1, 3);
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> floor;
  floor->SetMapper(floorMapper);
  floor->GetProperty()->SetColor(0.7, 0.7, 0.7);
  ren->AddActor(floor);
  return true;
}

// n seeded lights in the box [lo, hi] with saturated random colors.
void MakeLights(vtkClusteredLightSet* lights, int n, const double lo[3], const double hi[3])
{
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  lights->SetNumberOfLights(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    lights->SetPosition(i, lo[0] + U(rng) * (hi[0] - lo[0]), lo[1] + U(rng) * (hi[1] - lo[1]),
      lo[2] + U(rng) * (hi[2] - lo[2]));
    const double hue = 6.0 * U(rng);
    auto channel = [hue](double offset)
    { return std::clamp(std::abs(std::fmod(hue + offset, 6.0) - 3.0) - 1.0, 0.0, 1.0); };
    lights->SetColor(
      i, 0.3 + 0.7 * channel(0.0), 0.3 + 0.7 * channel(4.0), 0.3 + 0.7 * channel(2.0));
  }
}

double TimeRender(vtkRenderWindow* rw)
{
  const auto t0 = std::chrono::steady_clock::now();
  rw->Render();
  rw->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void WritePNG(vtkRenderWindow* rw, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(rw);
  w2i->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(w2i->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
}
}

int main(int argc, char* argv[])
{
  int numberOfLights = 4096;
  int width = 1024, height = 768;
  int frames = 10, bruteFrames = 2, subdivide = 0;
  bool interactive = false;
  std::string output = "many-lights.png", heatmap;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--lights" && i + 1 < argc)
    {
      numberOfLights = std::atoi(argv[++i]);
    }
    else if (a == "--size" && i + 2 < argc)
    {
      width = std::atoi(argv[++i]);
      height = std::atoi(argv[++i]);
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--brute-frames" && i + 1 < argc)
    {
      bruteFrames = std::max(0, std::atoi(argv[++i]));
    }
    else if (a == "--subdivide" && i + 1 < argc)
    {
      subdivide = std::atoi(argv[++i]);
    }
    else if (a == "--output" && i + 1 < argc)
    {
      output = argv[++i];
    }
    else if (a == "--heatmap" && i + 1 < argc)
    {
      heatmap = argv[++i];
    }
    else if (a == "-I")
    {
      interactive = true;
    }
    else
    {
      std::fprintf(stderr, "unknown argument %s\n", argv[i]);
      return EXIT_FAILURE;
    }
  }

  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(width, height);
  renWin->SetMultiSamples(0);
  renWin->SetOffScreenRendering(interactive ? 0 : 1);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.02, 0.02, 0.03);
  renWin->AddRenderer(ren);
  vtkNew<vtkLight> headlight; // a dim headlight keeps the shapes readable
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.12);
  ren->AddLight(headlight);
  vtkIdType triangles = 0;
  if (!AddBunnyOnFloor(ren, subdivide, triangles))
  {
    return EXIT_FAILURE;
  }

  // The lights: one compact set, no vtkLight objects. Seeded positions in a box around
  // the bunny, intensity 1.2, attenuation (1, 0, 60) capped by a radius of 0.45.
  vtkNew<vtkClusteredLightSet> lights;
  const double lo[3] = { -3.0, -0.98, -3.0 }, hi[3] = { 3.0, 1.0, 3.0 };
  MakeLights(lights, numberOfLights, lo, hi);
  for (vtkIdType i = 0; i < lights->GetNumberOfLights(); ++i)
  {
    lights->SetIntensity(i, 1.2);
    lights->SetAttenuation(i, 1.0, 0.0, 60.0);
    lights->SetRadius(i, 0.45);
  }

  // One line to enable clustered lighting, plus the light set and the falloff.
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  pass->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED);
  ren->SetPass(pass);

  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetPosition(0.0, 1.6, 4.6);
  camera->SetFocalPoint(0.0, -0.3, 0.0);
  camera->SetViewAngle(40.0);
  ren->ResetCameraClippingRange();

  if (interactive)
  {
    vtkNew<vtkRenderWindowInteractor> iren;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    iren->SetInteractorStyle(style);
    iren->SetRenderWindow(renWin);
    renWin->Render();
    iren->Start();
    return EXIT_SUCCESS;
  }

  // Warm up (shader compilation), then time a slowly orbiting camera: every frame
  // reassigns the lights, so the time includes the list and master passes.
  renWin->Render();
  renWin->Render();
  WritePNG(renWin, output);
  // One orbiting frame, timed.
  auto orbit = [&]()
  {
    camera->Azimuth(1.0);
    ren->ResetCameraClippingRange();
    return TimeRender(renWin);
  };
  std::vector<double> clusteredMs, assignMs;
  for (int f = 0; f < frames; ++f)
  {
    clusteredMs.push_back(orbit());
  }
  // The light assignment's time comes from as many frames again with MeasureTimings on,
  // after the timed ones: its glFinish calls would stall a GPU's pipeline in a timed frame.
  pass->MeasureTimingsOn();
  for (int f = 0; f < frames; ++f)
  {
    orbit();
    assignMs.push_back(pass->GetLastAssignmentTime());
  }
  pass->MeasureTimingsOff();
  camera->Azimuth(-2.0 * frames);
  ren->ResetCameraClippingRange();

  if (!heatmap.empty())
  {
    pass->SetDebugView(vtkClusteredLightingPass::DEBUG_HEAT_MAP);
    renWin->Render();
    WritePNG(renWin, heatmap);
    pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  }

  std::vector<double> bruteMs;
  if (bruteFrames > 0)
  {
    pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
    renWin->Render(); // compile
    for (int f = 0; f < bruteFrames; ++f)
    {
      bruteMs.push_back(orbit());
    }
  }

  if (pass->GetNumberOfClusteredLights() != numberOfLights ||
    pass->GetNumberOfAssignedLights() == 0)
  {
    std::fprintf(stderr, "expected %d clustered lights, got %d (%d assigned)\n", numberOfLights,
      pass->GetNumberOfClusteredLights(), pass->GetNumberOfAssignedLights());
    return EXIT_FAILURE;
  }
  const double clustered = Median(clusteredMs);
  const double brute = Median(bruteMs);
  std::printf("ClusteredLighting many-lights example\n");
  std::printf("mesh:        Stanford bunny (%lld triangles) on a floor, window %dx%d\n",
    static_cast<long long>(triangles), width, height);
  std::printf("lights:      %d clustered point lights (%d rejected, %d always-on), radius 0.45, "
              "windowed falloff, grid %dx%dx%d\n",
    pass->GetNumberOfClusteredLights(), pass->GetNumberOfRejectedLights(),
    pass->GetNumberOfAlwaysOnLights(), pass->GetTilesX(), pass->GetTilesY(), pass->GetSlices());
  std::printf(
    "clustered:   %.1f ms/frame (median of %d, orbiting camera; light assignment %.1f ms)\n",
    clustered, frames, Median(assignMs));
  if (!bruteMs.empty())
  {
    std::printf("brute force: %.1f ms/frame (median of %d, same scene and shading code)\n", brute,
      bruteFrames);
    std::printf("speed-up:    %.1fx\n", brute / clustered);
  }
  std::printf("memory:      list %.2f MiB, master %.3f MiB, light records %.2f MiB\n",
    pass->GetListTextureBytes() / 1048576.0, pass->GetMasterTextureBytes() / 1048576.0,
    pass->GetLightBufferBytes() / 1048576.0);
  std::printf("image:       %s\n", output.c_str());
  if (!heatmap.empty())
  {
    std::printf("heat map:    %s (lights evaluated per pixel, hottest = %g, mean %.2f)\n",
      heatmap.c_str(), pass->GetHeatMapScale(), pass->GetMeanLightsEvaluatedPerPixel());
  }
  return EXIT_SUCCESS;
}
