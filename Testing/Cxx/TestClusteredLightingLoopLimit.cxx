// SPDX-License-Identifier: BSD-3-Clause
// More lights than a shader loop may iterate on llvmpipe: Mesa's software renderer ends
// every fragment shader after 65,535 loop iterations in all (LP_MAX_TGSI_LOOP_ITERATIONS,
// one counter shared by every loop of the shader), silently. A loop over lights one by
// one (brute force, the exact far sums, a cluster's walk) then drops the lights past the
// count. The shader takes 16 lights per iteration in the loops over every light and 4 in
// the walk (docs/guide.md, "Limits").
//
// Checks:
//  - 100,000 lights at one position, each 1/100,000 of one light's intensity, shade like
//    that one light, in brute force and clustered (with an explicit radius that holds the
//    whole scene and the smallest cutoff, so that every cluster lists every light: the
//    walk's loop), within float rounding (1 step). Before the fix brute force showed
//    65,535/100,000 of it (59 steps off), clustered 66 steps off;
//  - the evaluated-lights count (DEBUG_EVALUATED_COUNT) saturates at 65,535; its 16-bit
//    encoding wrapped past that;
//  - no message below the limit; past it one warning on llvmpipe that names the limit,
//    none on other drivers: 1,100,000 lights in brute force, and 250,000 lights that
//    every cluster lists.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtk_glew.h" // for glGetString

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
void MakeColocatedLights(vtkClusteredLightSet* lights, int n, double total, bool ranged)
{
  lights->SetNumberOfLights(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    lights->SetPosition(i, 0.4, 2.4, 1.2);
    lights->SetColor(i, 1.0, 0.9, 0.8);
    lights->SetIntensity(i, total / n);
    lights->SetAttenuation(i, 1.0, 0.0, 0.05);
    if (ranged)
    {
      lights->SetRadius(i, 40.0);
    }
  }
}
}

int TestClusteredLightingLoopLimit(int, char*[])
{
  using namespace ClusteredLightingTest;
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  SetUpTestScene(renWin, ren, 64, 48, 12);
  vtkNew<vtkClusteredLightSet> lights;
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  pass->SetTilesX(4);
  pass->SetTilesY(3);
  pass->SetSlices(4);
  // Each light alone is far below the default cutoff; at 1e-9 the explicit radius is
  // where the ranged lights end.
  pass->SetContributionCutoff(1e-9);
  ren->SetPass(pass);

  vtkNew<MessageCollector> messages;
  messages->Watch(pass);
  const int many = 100000;
  for (const bool ranged : { false, true })
  {
    const char* what = ranged ? "explicit radius 40" : "no radius";
    MakeColocatedLights(lights, 1, 0.7, ranged);
    const std::vector<float> one = CaptureBruteForce(pass, renWin);
    MakeColocatedLights(lights, many, 0.7, ranged);
    const std::vector<float> brute = CaptureBruteForce(pass, renWin);
    const std::vector<float> clustered = CapturePixels(renWin);
    double lit = 0.0;
    for (float v : one)
    {
      lit = std::max(lit, static_cast<double>(v));
    }
    Check(lit > 0.3, std::string(what) + ": the one light lights the scene");
    const ImageComparison b = CompareImages(brute, one);
    PrintComparison((std::string(what) + ": brute force, 100,000 lights vs one").c_str(), b);
    Check(b.MaxAbsError <= 1.0 / 255.0 + 1e-6,
      std::string(what) + ": brute force with 100,000 lights shades like one");
    if (!ranged)
    {
      // The count of evaluated lights saturates at 65,535 (16 bits), it does not wrap.
      pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
      pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
      renWin->Render();
      const std::vector<float> counts = CapturePixels(renWin);
      pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
      pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
      const long shown = std::lround(counts[0] * 255.0) + 256 * std::lround(counts[1] * 255.0);
      std::printf("brute force, 100,000 lights: evaluated count shown %ld\n", shown);
      Check(shown == 65535, "the evaluated count saturates at 65,535");
    }
    if (ranged)
    {
      // Every cluster lists all 100,000: the walk's loop.
      const ImageComparison c = CompareImages(clustered, one);
      PrintComparison((std::string(what) + ": clustered, 100,000 lights vs one").c_str(), c);
      Check(c.MaxAbsError <= 1.0 / 255.0 + 1e-6,
        std::string(what) + ": clustered with 100,000 lights shades like one");
    }
  }
  Check(messages->Warnings.empty() && messages->Errors.empty(),
    "no message below the limit (" + std::to_string(messages->Warnings.size()) + " warnings)");

  // Past what 65,535 iterations of 16 lights reach, brute force on llvmpipe says so, once
  // (a 16x12 window: 1,100,000 lights per pixel, 68,750 iterations of 16).
  renWin->SetSize(16, 12);
  MakeColocatedLights(lights, 1100000, 0.7, false);
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
  renWin->Render();
  renWin->Render();
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer.find("llvmpipe") != std::string::npos)
  {
    const bool named = messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("1100000 lights: llvmpipe ends a fragment shader after 65,535") !=
        std::string::npos;
    std::printf(
      "%s\n", messages->Warnings.empty() ? "(no warning)" : messages->Warnings[0].c_str());
    Check(named, "1,100,000 lights in brute force on llvmpipe: one warning naming the limit");
  }
  else
  {
    Check(messages->Warnings.empty(), "no loop-limit warning on " + renderer);
  }

  // A walk past the limit: 250,000 lights that every cluster lists (a new pass: the first
  // one reports the limit once while it lasts).
  vtkNew<vtkClusteredLightingPass> walkPass;
  walkPass->AddLightSet(lights);
  walkPass->SetTilesX(4);
  walkPass->SetTilesY(3);
  walkPass->SetSlices(4);
  walkPass->SetContributionCutoff(1e-9);
  messages->Clear();
  messages->Watch(walkPass);
  ren->SetPass(walkPass);
  MakeColocatedLights(lights, 250000, 0.7, true);
  renWin->Render();
  if (renderer.find("llvmpipe") != std::string::npos)
  {
    const bool named = messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("a cluster lists up to 250000 lights") != std::string::npos;
    std::printf(
      "%s\n", messages->Warnings.empty() ? "(no warning)" : messages->Warnings[0].c_str());
    Check(named, "250,000 lights in every cluster on llvmpipe: one warning naming the walk");
  }
  return CheckStatus();
}
