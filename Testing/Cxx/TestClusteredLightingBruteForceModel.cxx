// SPDX-License-Identifier: BSD-3-Clause
// Brute force is the reference for every light model: it evaluates each light with the
// same model clustered shading uses (explicit radius, windowed falloff, spot cone) and
// differs only in not culling.
//
// Lights with an explicit radius smaller than their cutoff radius have no cut tail: the
// radius is part of the light, so clustered shading must equal brute force to float
// rounding at every pixel, for hard-cut and windowed falloff, point and spot lights, and
// for a mix with lights that have no radius (which brute force evaluates everywhere).
// Each case also checks that the lights show (not black) and do not saturate the image
// (what a brute force that ignored the radius did: 8,192 such lights rendered white).
#include "ClusteredLightingTestUtilities.h"

#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"

#include <cstdio>
#include <random>

namespace
{
/// n lights over the test scene with an explicit radius well inside their cutoff radius
/// (intensity 0.2, attenuation (1, 0, 8): the cutoff radius is about 5).
void MakeRangedLights(vtkClusteredLightSet* lights, int n, bool spots, bool someUnranged)
{
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  lights->SetNumberOfLights(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    lights->SetPosition(i, -3 + 6 * U(rng), -0.9 + 2.4 * U(rng), -3 + 6 * U(rng));
    lights->SetColor(i, 0.4 + 0.6 * U(rng), 0.4 + 0.6 * U(rng), 0.4 + 0.6 * U(rng));
    lights->SetIntensity(i, 0.2);
    lights->SetAttenuation(i, 1.0, 0.0, 8.0);
    if (someUnranged && i % 64 == 0)
    {
      lights->SetIntensity(i, 0.02); // no radius: evaluated everywhere by both modes
      lights->SetAttenuation(i, 1.0, 0.0, 40.0);
      lights->UnsetRadius(i);
    }
    else
    {
      lights->SetRadius(i, 0.25 + 0.35 * U(rng));
    }
    if (spots && i % 3 == 0)
    {
      lights->SetSpot(i, U(rng) - 0.5, -1.0, U(rng) - 0.5, 20.0 + 50.0 * U(rng), 2.0);
    }
  }
}
}

int TestClusteredLightingBruteForceModel(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  ClusteredLightingTest::SetUpTestScene(renWin, ren, 200, 150);
  vtkNew<vtkClusteredLightSet> lights;
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);

  struct Case
  {
    const char* Name;
    int Falloff;
    bool Spots, Unranged;
  };
  const Case cases[] = {
    { "hard cut", vtkClusteredLightingPass::FALLOFF_HARD_CUT, false, false },
    { "windowed", vtkClusteredLightingPass::FALLOFF_WINDOWED, false, false },
    { "windowed spots", vtkClusteredLightingPass::FALLOFF_WINDOWED, true, false },
    { "hard-cut spots and lights without a radius", vtkClusteredLightingPass::FALLOFF_HARD_CUT,
      true, true },
  };
  int failures = 0;
  for (const Case& c : cases)
  {
    MakeRangedLights(lights, 8192, c.Spots, c.Unranged);
    pass->SetFalloff(c.Falloff);
    pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
    renWin->Render();
    const std::vector<float> brute = ClusteredLightingTest::CapturePixels(renWin);
    pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
    renWin->Render();
    const std::vector<float> clustered = ClusteredLightingTest::CapturePixels(renWin);
    const auto cmp = ClusteredLightingTest::CompareImages(brute, clustered);
    ClusteredLightingTest::PrintComparison(c.Name, cmp);
    std::size_t saturated = 0, lit = 0;
    for (std::size_t p = 0; p + 2 < brute.size(); p += 3)
    {
      saturated += (brute[p] > 0.995f && brute[p + 1] > 0.995f && brute[p + 2] > 0.995f) ? 1 : 0;
      lit += (brute[p] + brute[p + 1] + brute[p + 2] > 0.3f) ? 1 : 0;
    }
    const std::size_t pixels = brute.size() / 3;
    std::printf("%s: brute force %.1f%% saturated, %.1f%% lit\n", c.Name,
      100.0 * saturated / pixels, 100.0 * lit / pixels);
    // Every light ends at its own radius, before its cutoff: nothing is cut, so the two
    // modes differ by float rounding only (the unranged lights' tails, at most 1/1024
    // each, do not reach a step here).
    if (cmp.MaxAbsError > 1.0 / 255.0 + 1e-6)
    {
      std::printf("%s: clustered differs from brute force\n", c.Name);
      ++failures;
    }
    if (saturated > pixels / 20 || lit < pixels / 8)
    {
      std::printf("%s: brute force is not the light model (saturated or dark)\n", c.Name);
      ++failures;
    }
    if (ClusteredLightingTest::CheckClusteredFrame(pass, renWin, ren, 1.4, c.Name) != 0)
    {
      ++failures;
    }
  }
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
