// SPDX-License-Identifier: BSD-3-Clause
// 65,536 lights within 2 steps of brute force (issue 11's target), with the pass's
// defaults: the benchmark's bunny scene (uniform inverse-square lights in the box over the
// bunny and its floor, no radius). Lights that hold still get the refined far field
// (FarFieldRefineStillLights: FarFieldCellsPerRadius 3 at 110,592 nodes, the default's
// near radius of 2 spacings at 32,768 nodes, and the far specular from its directional
// bins); lights that change in two frames running get the options' own far field, and the
// first frame after they stop the refined one again. Unrefined, the benchmark's 1024x768
// image is 3 steps off at 302 pixels (the far field's interpolation and its order-2
// specular lobe, docs/far-field.md, "The 65,536-light image within 2 steps"). Checks, at
// 320x240 (brute force at 65,536 lights is slow on llvmpipe):
//  - every light is split, the far field is refined and its bins are read;
//  - zero false negatives, every pixel within the stated bound of brute force, no NaN
//    (CheckClusteredFrame);
//  - every pixel within 2 steps of brute force, under 1% of them more than one step off;
//  - one change of the lights keeps the refined far field, a change in two frames running
//    builds the options' own (32,768 nodes, no bins), and a still frame after it the
//    refined one; FarFieldRefineLeastLights n and FarFieldRefineStillLights off leave it
//    unrefined.
//  - a ball lit by 500 lights, refined from 100: where the bins' texture is too deep for
//    the GPU (llvmpipe), one warning naming FarFieldRefineStillLights and no bins.
// Measured: max 2 steps, RMSE 0.408, 0.25% of the pixels over a step; with the far field
// unrefined the same render is max 3 and 1.55%, with the bins alone max 3 and 1.27%.
#include "ClusteredLightingScenes.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtk_glew.h" // GL_MAX_3D_TEXTURE_SIZE

#include <algorithm>

#include <cstdio>

int TestClusteredLightingManyLightsAccurate(int, char*[])
{
  vtkSmartPointer<vtkPolyData> bunny = ClusteredLightingScenes::LoadBunny(0);
  if (!bunny)
  {
    std::printf("bunny mesh missing: %s\n", ClusteredLightingScenes::BunnyPath().c_str());
    return EXIT_FAILURE;
  }
  int failed = 0;
  auto check = [&](bool ok, const std::string& what)
  {
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
    failed += ok ? 0 : 1;
  };
  vtkNew<vtkRenderWindow> rw;
  rw->SetSize(320, 240);
  rw->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.02, 0.02, 0.03);
  ren->AutomaticLightCreationOff();
  rw->AddRenderer(ren);
  ClusteredLightingScenes::AddBunnyScene(ren, bunny);
  const double eye[3] = { 0.0, 1.6, 4.6 };
  ren->GetActiveCamera()->SetPosition(eye);
  ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  ren->GetActiveCamera()->SetViewAngle(40.0);
  ren->ResetCameraClippingRange();

  // The benchmark's uniform lights: attenuation (1, 0, k) with an influence radius of 0.35
  // at the cutoff, intensity 1, random colours, no radius.
  const int n = 65536;
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingScenes::LightParameters params;
  params.Intensity = 1.0;
  params.TargetRadius = 0.35;
  const double lo[3] = { -3.0, -0.98, -3.0 }, hi[3] = { 3.0, 1.0, 3.0 };
  ClusteredLightingScenes::MakeLights(
    lights, n, ClusteredLightingScenes::Layout::Uniform, lo, hi, params, 7, eye);

  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  rw->Render();

  check(pass->GetNumberOfFarFieldLights() == n, "every light is split");
  const auto refined = [&]()
  {
    return pass->GetFarFieldRefinedUsed() && pass->GetFarFieldResolutionInUse() == 110592 &&
      pass->GetFarFieldSpecularBinsUsed();
  };
  check(refined(), "the far field of still lights is refined (110,592 nodes, bins)");
  check(pass->GetFarFieldSpecularBinsUsed(), "the far specular's bins are read");
  ClusteredLightingTest::BruteForceCheck comparison;
  // Bunny: Diffuse 1 + Specular 0.3; floor: Diffuse 1.
  check(ClusteredLightingTest::CheckClusteredFrame(
          pass, rw, ren, 1.3, "65536 lights", 0, &comparison) == 0,
    "within the stated bound of brute force, zero false negatives, finite");
  const double maxSteps = 255.0 * comparison.Image.MaxAbsError;
  std::printf("65536 lights: max %.2f steps, RMSE %.3f steps, %.3f%% of pixels over one step\n",
    maxSteps, 255.0 * comparison.Image.RMSE, 100.0 * comparison.Image.FractionOverOneStep);
  // Whole steps (8-bit images), read back as floats.
  check(maxSteps < 2.5, "within 2 steps of brute force at every pixel");
  check(comparison.Image.FractionOverOneStep < 0.01, "under 1% of pixels more than a step off");

  // Lights edited once, then changed in two frames running (moving), then still.
  lights->Modified();
  rw->Render();
  check(refined(), "one change of the lights keeps the refined far field");
  lights->Modified();
  rw->Render();
  check(!pass->GetFarFieldRefinedUsed() && pass->GetFarFieldResolutionInUse() == 32768 &&
      !pass->GetFarFieldSpecularBinsUsed(),
    "lights changed in two frames running: the options' own far field");
  rw->Render();
  check(refined(), "the first frame after they stop: refined again");

  // The options that turn it off: a threshold of n lights (more than n are refined), and
  // the option itself.
  pass->SetFarFieldRefineLeastLights(n);
  rw->Render();
  check(!pass->GetFarFieldRefinedUsed() && pass->GetFarFieldResolutionInUse() == 32768,
    "FarFieldRefineLeastLights n: n lights are not refined");
  pass->SetFarFieldRefineLeastLights(n - 1);
  rw->Render();
  check(refined(), "FarFieldRefineLeastLights n - 1: refined");
  pass->FarFieldRefineStillLightsOff();
  rw->Render();
  check(!pass->GetFarFieldRefinedUsed() && pass->GetFarFieldResolutionInUse() == 32768,
    "FarFieldRefineStillLights off: the options' own far field");

  // The refinement's bins on a grid too deep for them: a ball (a cubic region) lit by 500
  // lights, refined from 100 lights on. At 110,592 nodes over a cube the bins' texture
  // stacks 52 slabs of 49 layers (26 with a shared colour), past llvmpipe's
  // GL_MAX_3D_TEXTURE_SIZE of 2,048: the far specular then comes from the moments, with one
  // warning that names the option that asked for the bins, not FarFieldSpecularBins,
  // which the application never set.
  {
    vtkNew<vtkRenderWindow> ballWindow;
    ballWindow->SetSize(160, 120);
    ballWindow->SetMultiSamples(0);
    vtkNew<vtkRenderer> ballRenderer;
    ballRenderer->AutomaticLightCreationOff();
    ballWindow->AddRenderer(ballRenderer);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(1.0);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> ball;
    ball->SetMapper(mapper);
    ball->GetProperty()->SetSpecular(0.3);
    ball->GetProperty()->SetSpecularPower(20.0);
    ballRenderer->AddActor(ball);
    ballRenderer->GetActiveCamera()->SetPosition(0.0, 0.0, 6.0);
    ballRenderer->ResetCameraClippingRange();
    vtkNew<vtkClusteredLightSet> ballLights;
    const double blo[3] = { -1.5, -1.5, -1.5 }, bhi[3] = { 1.5, 1.5, 1.5 };
    ClusteredLightingScenes::MakeLights(
      ballLights, 500, ClusteredLightingScenes::Layout::Uniform, blo, bhi, params, 3);
    vtkNew<vtkClusteredLightingPass> ballPass;
    ballPass->AddLightSet(ballLights);
    ballPass->SetFarFieldRefineLeastLights(100);
    vtkNew<ClusteredLightingTest::MessageCollector> messages;
    messages->Watch(ballPass);
    ballRenderer->SetPass(ballPass);
    ballWindow->Render();
    GLint deepest = 0;
    ballWindow->MakeCurrent();
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &deepest);
    int dims[3];
    ballPass->GetFarFieldDimensions(dims);
    const int slabs = ballPass->GetFarFieldSharedColorUsed() ? 26 : 52;
    const bool tooDeep = slabs * std::min({ dims[0], dims[1], dims[2] }) > deepest;
    std::printf(
      "ball: %d x %d x %d nodes, %d slabs, GL_MAX_3D_TEXTURE_SIZE %d; %zu warning(s)%s%s\n",
      dims[0], dims[1], dims[2], slabs, static_cast<int>(deepest), messages->Warnings.size(),
      messages->Warnings.empty() ? "" : ": ",
      messages->Warnings.empty() ? "" : messages->Warnings[0].c_str());
    check(ballPass->GetFarFieldRefinedUsed() && ballPass->GetFarFieldResolutionInUse() == 110592,
      "500 still lights, refined from 100: refined");
    if (tooDeep)
    {
      check(!ballPass->GetFarFieldSpecularBinsUsed() && messages->Warnings.size() == 1 &&
          messages->Warnings[0].find("FarFieldRefineStillLights: ") != std::string::npos &&
          messages->Warnings[0].find("FarFieldSpecularBins") == std::string::npos,
        "bins too deep for this GPU: one warning naming FarFieldRefineStillLights");
    }
    else
    {
      check(ballPass->GetFarFieldSpecularBinsUsed() && messages->Warnings.empty(),
        "bins that fit: read, no warning");
    }
    check(messages->Errors.empty(), "no error");
  }
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
