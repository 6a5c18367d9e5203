// SPDX-License-Identifier: BSD-3-Clause
// Lights as data: a VTK pipeline drives 2,048 (or --lights N) point lights over a terrain.
//
//   vtkPointSource  ->  vtkTransformPolyDataFilter  ->  vtkElevationFilter  ->  vtkArrayCalculator
//   (points on a        (flattened into a swarm that    ("Elevation": 0 at     ("Color" = blue ->
//    sphere)             turns over the terrain)         x = -3, 1 at x = 3)    red along x)
//        ->  vtkClusteredLightSet (every point a light, "Color" read by name; intensity,
//            attenuation and radius are the set's defaults)  ->  vtkClusteredLightingPass
//
// Each frame only the transform changes: the pipeline re-executes, the light set re-reads
// its input and the pass re-uploads the lights; no shader is rebuilt. The lights change
// color as they swing from one side to the other. Writes the last frame (and with
// --heatmap the lights-per-pixel debug view of it) as PNG, prints the time per frame, and
// fails if a frame did not cluster every light or rebuilt a shader. With -I it opens a
// window where the swarm keeps turning.
//
//   PipelineLights [--lights N] [--size W H] [--frames F] [--output image.png]
//                  [--heatmap heat.png] [-I]
#include "vtkActor.h"
#include "vtkArrayCalculator.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkElevationFilter.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricRandomHills.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
// Rolling hills in x and z over [-3, 3], heights between -1 and about -0.6.
void AddTerrain(vtkRenderer* ren)
{
  vtkNew<vtkParametricRandomHills> hills;
  hills->SetRandomSeed(3);
  hills->SetNumberOfHills(24);
  vtkNew<vtkParametricFunctionSource> surface;
  surface->SetParametricFunction(hills);
  surface->SetUResolution(200);
  surface->SetVResolution(200);
  vtkNew<vtkTransform> place; // (u in [-10, 10], v in [0, 20], height 0..8) -> (x, y, z)
  place->Translate(0.0, -1.0, 0.0);
  place->RotateX(-90.0);
  place->Scale(0.3, 0.3, 0.05);
  place->Translate(0.0, -10.0, 0.0);
  vtkNew<vtkTransformPolyDataFilter> placed;
  placed->SetInputConnection(surface->GetOutputPort());
  placed->SetTransform(place);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(placed->GetOutputPort());
  normals->SplittingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> terrain;
  terrain->SetMapper(mapper);
  terrain->GetProperty()->SetColor(0.75, 0.75, 0.72);
  ren->AddActor(terrain);
}

void WriteImage(vtkRenderWindow* rw, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(rw);
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(capture->GetOutputPort());
  png->SetFileName(path.c_str());
  png->Write();
}

// The swarm at a given angle: flattened to a band 0.05-0.95 above the floor (y = -1),
// turned about the vertical axis.
void PlaceSwarm(vtkTransform* transform, double degrees)
{
  transform->Identity();
  transform->RotateY(degrees);
  transform->Translate(0.0, -0.5, 0.0);
  transform->Scale(1.0, 0.155, 1.0);
}

struct Animation
{
  vtkTransform* Transform;
  vtkRenderWindow* Window;
  double Degrees = 0.0;
};

void OnTimer(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* animation = static_cast<Animation*>(clientData);
  animation->Degrees += 1.0;
  PlaceSwarm(animation->Transform, animation->Degrees);
  animation->Window->Render();
}
}

int main(int argc, char* argv[])
{
  int numberOfLights = 2048;
  int width = 1024, height = 768;
  int frames = 24;
  bool interactive = false;
  std::string output = "pipeline-lights.png", heatmap;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--lights" && i + 1 < argc)
    {
      numberOfLights = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--size" && i + 2 < argc)
    {
      width = std::atoi(argv[++i]);
      height = std::atoi(argv[++i]);
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      frames = std::max(2, std::atoi(argv[++i]));
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
  AddTerrain(ren);

  // The light pipeline.
  vtkNew<vtkPointSource> cloud;
  cloud->SetNumberOfPoints(numberOfLights);
  cloud->SetRadius(2.5);
  cloud->SetDistributionToShell(); // a ring-like swarm, denser at its rim
  vtkNew<vtkTransform> transform;
  PlaceSwarm(transform, 0.0);
  vtkNew<vtkTransformPolyDataFilter> swarm;
  swarm->SetInputConnection(cloud->GetOutputPort());
  swarm->SetTransform(transform);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(swarm->GetOutputPort());
  elevation->SetLowPoint(-3.0, 0.0, 0.0);
  elevation->SetHighPoint(3.0, 0.0, 0.0);
  vtkNew<vtkArrayCalculator> color;
  color->SetInputConnection(elevation->GetOutputPort());
  color->AddScalarArrayName("Elevation");
  color->SetFunction(
    "(0.2 + 0.8 * Elevation) * iHat + 0.3 * jHat + (1.0 - 0.8 * Elevation) * kHat");
  color->SetResultArrayName("Color");

  vtkNew<vtkClusteredLightSet> lights;
  lights->SetInputConnection(color->GetOutputPort());
  lights->SetColorArrayName("Color"); // the default; shown for clarity
  lights->SetDefaultIntensity(1.3);
  lights->SetDefaultAttenuation(1.0, 0.0, 60.0);
  lights->SetDefaultRadius(0.45);

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
    Animation animation{ transform, renWin };
    vtkNew<vtkCallbackCommand> tick;
    tick->SetCallback(OnTimer);
    tick->SetClientData(&animation);
    iren->Initialize();
    iren->AddObserver(vtkCommand::TimerEvent, tick);
    iren->CreateRepeatingTimer(30);
    renWin->Render();
    iren->Start();
    return EXIT_SUCCESS;
  }

  // Animate: a quarter turn over the frames. The first frame compiles the shaders.
  std::vector<double> ms;
  int shaderBuilds = 0;
  bool ok = true;
  for (int f = 0; f < frames; ++f)
  {
    PlaceSwarm(transform, 90.0 * f / (frames - 1));
    const auto start = std::chrono::steady_clock::now();
    renWin->Render();
    renWin->WaitForCompletion();
    const double t =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (f == 0)
    {
      shaderBuilds = pass->GetNumberOfShaderBuilds();
    }
    else
    {
      ms.push_back(t);
    }
    if (pass->GetNumberOfClusteredLights() != numberOfLights ||
      pass->GetNumberOfShaderBuilds() != shaderBuilds)
    {
      std::fprintf(stderr,
        "frame %d: %d of %d lights clustered, %d shader builds (first frame %d)\n", f,
        pass->GetNumberOfClusteredLights(), numberOfLights, pass->GetNumberOfShaderBuilds(),
        shaderBuilds);
      ok = false;
    }
  }
  WriteImage(renWin, output);
  if (!heatmap.empty())
  {
    pass->SetDebugView(vtkClusteredLightingPass::DEBUG_HEAT_MAP);
    renWin->Render();
    WriteImage(renWin, heatmap);
    pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  }

  std::sort(ms.begin(), ms.end()); // for the median
  std::printf("ClusteredLighting pipeline-lights example\n");
  std::printf("pipeline:    vtkPointSource -> vtkTransformPolyDataFilter -> vtkElevationFilter -> "
              "vtkArrayCalculator -> vtkClusteredLightSet\n");
  std::printf(
    "lights:      %d clustered point lights, radius 0.45, windowed falloff, window %dx%d\n",
    pass->GetNumberOfClusteredLights(), width, height);
  std::printf("animation:   %d frames, %.1f ms/frame (median, pipeline update + light upload + "
              "assignment + shading)\n",
    frames, ms[ms.size() / 2]);
  std::printf("re-reads:    %d (one per frame); shader builds: %d, all in the first frame\n",
    lights->GetNumberOfInputReads(), pass->GetNumberOfShaderBuilds());
  std::printf("image:       %s\n", output.c_str());
  if (!heatmap.empty())
  {
    std::printf("heat map:    %s (lights evaluated per pixel, hottest = %g, mean %.2f)\n",
      heatmap.c_str(), pass->GetHeatMapScale(), pass->GetMeanLightsEvaluatedPerPixel());
  }
  if (lights->GetNumberOfInputReads() != frames)
  {
    std::fprintf(stderr, "expected the light set to read its input once per frame\n");
    ok = false;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
