// SPDX-License-Identifier: BSD-3-Clause
// More lights than a shader loop may iterate on llvmpipe: Mesa's software renderer ends
// every fragment shader after 65,535 loop iterations in all (LP_MAX_TGSI_LOOP_ITERATIONS,
// one counter shared by every loop of the shader), silently. A loop over lights one by
// one then drops the lights past the count. The loops over every light (brute force, the
// exact far sums) take 16 lights per iteration; a cluster's walk takes one, and the pass
// reports a list too long for it (docs/guide.md, "Limits").
//
// Checks:
//  - 100,000 lights at one position, each 1/100,000 of one light's intensity, shade like
//    that one light in brute force, within float rounding (1 step); before the change
//    brute force showed 65,535 of them (59 steps off);
//  - 60,000 such lights with an explicit radius that holds the whole scene and the
//    smallest cutoff, so that every cluster lists all of them, shade like one light in
//    clustered shading (the walk within the limit);
//  - the evaluated-lights count (DEBUG_EVALUATED_COUNT) saturates at 65,535; its 16-bit
//    encoding wrapped past that;
//  - no message below the limit; past it one warning on llvmpipe that names the limit,
//    none on other drivers: 1,100,000 lights in brute force, and 100,000 lights that
//    every cluster lists (before, the walk left a third of them out, 66 steps off,
//    silently).
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
  vtkNew<MessageCollector> messages;
  // A pass on the lights with a small grid, its messages collected. Each light alone is
  // far below the default cutoff; at 1e-9 the explicit radius is where the ranged lights
  // end.
  auto usePass = [&](vtkClusteredLightingPass* p)
  {
    p->AddLightSet(lights);
    p->SetTilesX(4);
    p->SetTilesY(3);
    p->SetSlices(4);
    p->SetContributionCutoff(1e-9);
    messages->Clear();
    messages->Watch(p);
    ren->SetPass(p);
  };
  // On llvmpipe exactly one warning that contains `needle`; none on other drivers.
  const std::string renderer = [&]()
  {
    renWin->Render(); // a context to ask
    return std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  }();
  auto checkOneWarning = [&](const char* needle, const std::string& what)
  {
    if (renderer.find("llvmpipe") == std::string::npos)
    {
      Check(messages->Warnings.empty(), "no loop-limit warning on " + renderer);
      return;
    }
    std::printf(
      "%s\n", messages->Warnings.empty() ? "(no warning)" : messages->Warnings[0].c_str());
    Check(messages->Warnings.size() == 1 && messages->Warnings[0].find(needle) != std::string::npos,
      what);
  };
  vtkNew<vtkClusteredLightingPass> pass;
  usePass(pass);
  for (const bool ranged : { false, true })
  {
    // Brute force: 100,000 lights, 6,250 iterations of 16. Clustered with the explicit
    // radius: 60,000 lights in every cluster's list, a walk of 63,868 iterations at most
    // (ComputeWalkIterations), within the limit.
    const int many = ranged ? 60000 : 100000;
    const std::string what = std::string(ranged ? "explicit radius 40, " : "no radius, ") +
      std::to_string(many) + " lights";
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
    Check(lit > 0.3, what + ": the one light lights the scene");
    const ImageComparison b = CompareImages(brute, one);
    PrintComparison((what + ": brute force vs one light").c_str(), b);
    Check(b.MaxAbsError <= 1.0 / 255.0 + 1e-6, what + ": brute force shades like one light");
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
      std::printf("%s: evaluated count shown %ld\n", what.c_str(), shown);
      Check(shown == 65535, "the evaluated count saturates at 65,535");
    }
    else
    {
      const ImageComparison c = CompareImages(clustered, one);
      PrintComparison((what + ": clustered vs one light").c_str(), c);
      Check(c.MaxAbsError <= 1.0 / 255.0 + 1e-6, what + ": clustered shades like one light");
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
  checkOneWarning("1100000 lights: llvmpipe ends a fragment shader after 65,535",
    "1,100,000 lights in brute force on llvmpipe: one warning naming the limit");

  // A walk past the limit: 100,000 lights that every cluster lists (a new pass: the first
  // one reports the limit once while it lasts).
  vtkNew<vtkClusteredLightingPass> walkPass;
  usePass(walkPass);
  MakeColocatedLights(lights, 100000, 0.7, true);
  renWin->Render();
  checkOneWarning("a cluster lists up to 100000 lights",
    "100,000 lights in every cluster on llvmpipe: one warning naming the walk");
  return CheckStatus();
}
