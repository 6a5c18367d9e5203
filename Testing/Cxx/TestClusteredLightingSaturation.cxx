// SPDX-License-Identifier: BSD-3-Clause
// Lights as a user writes them, bright enough to saturate (issue 11's dense scene): 800
// inverse-square lights, attenuation (1, 0, 8), no radius, over the test scene, at
// intensity 1 and scaled down to 1/4, 1/8 and 1/200 (IntensityScale). Their far parts add
// up to many times full brightness at intensity 1, so the far field's moments cannot tell
// on many fragments whether a channel saturates; those fragments sum the far parts
// exactly (FarFieldTolerance), and stop once every channel saturates. Checks that
//  - the scene is the hard case: at intensity 1 most channels of the brute-force image
//    saturate, at 1/200 almost none;
//  - at every scale, every pixel is within its derived bound of brute force, with zero
//    false negatives and no NaN pixel (CheckClusteredFrame). Measured: at 1/8 the exact
//    sums run on many fragments (109 lights evaluated per pixel against 12 at 1/200), and
//    the error reaches 5 steps there, inside a stated bound of up to 63.
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"

#include <cstdio>
#include <string>

namespace
{
int Status = EXIT_SUCCESS;

void Check(bool ok, const char* what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok)
  {
    Status = EXIT_FAILURE;
  }
}

/// Mean lights evaluated per pixel of geometry (DEBUG_EVALUATED_COUNT).
double MeanEvaluated(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  rw->Render();
  const double mean = pass->GetMeanLightsEvaluatedPerPixel();
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  rw->Render();
  return mean;
}

/// Share of channels at full brightness in the brute-force image.
double SaturatedShare(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
  rw->Render();
  const std::vector<float> brute = ClusteredLightingTest::CapturePixels(rw);
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
  rw->Render();
  std::size_t saturated = 0;
  for (float v : brute)
  {
    saturated += v >= 254.5f / 255.0f ? 1 : 0;
  }
  return brute.empty() ? 0.0 : static_cast<double>(saturated) / brute.size();
}
}

int TestClusteredLightingSaturation(int, char*[])
{
  const int n = 800;
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 320, 240);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingScenes::LightParameters params;
  params.Intensity = 1.0;
  params.Quadratic = 8.0;
  const double lo[3] = { -3, -0.9, -3 }, hi[3] = { 3, 1.8, 3 };
  ClusteredLightingScenes::MakeLights(
    lights, n, ClusteredLightingScenes::Layout::Uniform, lo, hi, params, 5);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  rw->Render();

  Check(pass->GetNumberOfFarFieldLights() == n, "every light is split (none has a radius)");
  for (double scale : { 1.0, 0.25, 0.125, 1.0 / 200.0 })
  {
    lights->SetIntensityScale(scale);
    rw->Render();
    const double saturated = SaturatedShare(pass, rw);
    const std::string what = "intensity scale " + std::to_string(scale);
    std::printf("%s: brute force saturates %.1f%% of channels\n", what.c_str(), 100.0 * saturated);
    if (scale == 1.0)
    {
      Check(saturated > 0.5, "intensity 1 saturates most channels (the case under test)");
    }
    else if (scale < 0.01)
    {
      Check(saturated < 0.01, "intensity 1/200 saturates almost nothing");
    }
    Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, what.c_str()) == 0,
      (what + ": within the derived bound of brute force, zero false negatives, finite").c_str());
    std::printf(
      "%s: lights evaluated per pixel %.1f of %d\n", what.c_str(), MeanEvaluated(pass, rw), n);
  }
  return Status;
}
