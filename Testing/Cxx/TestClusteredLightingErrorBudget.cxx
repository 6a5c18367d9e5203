// SPDX-License-Identifier: BSD-3-Clause
// The error budget chooses the far field's resolution (ErrorBudgetInSteps,
// vtkClusteredLightingFarFieldBudget.h). Lights as users write them (inverse-square,
// attenuation (1, 0, 8), no radius) over the test scene. Checks that
//  - without a budget the far field uses FarFieldResolution and no choice is made;
//  - a loose budget (16 steps) takes a grid no finer than the default and a looser cutoff
//    for the split lights than ContributionCutoff (shorter near radii, more of each light
//    in the far field; GetEffectiveFarFieldCutoff), its bound as the pass reports it
//    (ComputeFarFieldErrorBound) is within the budget, and the image is within the stated
//    bound of brute force at every pixel, with zero false negatives (CheckClusteredFrame):
//    the coarse far field is shaded right;
//  - moving a light keeps the choice, cutoff included (no new choice); adding one makes a
//    new one;
//  - a tight budget takes a finer grid than the loose one and meets it, or says it does
//    not; a budget below every resolution's bound warns once, names the option, is
//    reported by GetFarFieldErrorBudgetMet and PrintSelf, and its frame is still within
//    the stated bound of brute force;
//  - a budget of 0 gives FarFieldResolution back, the culled lights ContributionCutoff and
//    the split lights FarFieldCutoff (default 1/256), whose frame is within the stated
//    bound of brute force at every pixel; FarFieldCutoff 0 gives the split lights
//    ContributionCutoff, and FarField off gives it to every light;
//  - culled lights (an explicit radius beyond their cutoff radius: a tail the far field
//    does not hold) among split lights get their cutoff for half of the budget
//    (GetEffectiveCutoff), and the split lights theirs and the far field's resolution as
//    alone at half the budget: each kind spends its own share with its own cutoff (one
//    cutoff for both made the split lights take the culled lights'); that frame is within
//    the stated bound of brute force at every pixel, and its largest error within the
//    budget (for the scene's materials): the culled lights' tails are sampled where the
//    geometry is;
//  - spot lights are split as well (since 2026-11-30: their tails go to the far field,
//    cones included), so beside the split lights nothing is culled: the far field takes
//    the whole budget, and a frame at 8 steps is within the stated bound of brute force
//    at every pixel (the cones' edges in the far field included) and within the budget.
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"

#include <cstdio>
#include <sstream>
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

void Report(vtkClusteredLightingPass* pass, const char* what)
{
  std::printf("%s: budget %g steps, cutoff %g (split lights %g), far field %d nodes (%dx%dx%d), "
              "bound %.4f steps, %s, %d choices\n",
    what, pass->GetErrorBudgetInSteps(), pass->GetEffectiveCutoff(),
    pass->GetEffectiveFarFieldCutoff(), pass->GetFarFieldResolutionInUse(),
    pass->GetFarFieldDimensions()[0], pass->GetFarFieldDimensions()[1],
    pass->GetFarFieldDimensions()[2], pass->ComputeFarFieldErrorBound(),
    pass->GetFarFieldErrorBudgetMet() ? "met" : "not met",
    pass->GetNumberOfFarFieldResolutionChoices());
}
}

int TestClusteredLightingErrorBudget(int, char*[])
{
  const int n = 600;
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 320, 240);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, n, 0.02, 11);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);

  // 1. No budget: the pass's FarFieldResolution.
  rw->Render();
  Report(pass, "no budget");
  Check(pass->GetNumberOfFarFieldLights() == n, "every light is split (none has a radius)");
  Check(pass->GetFarFieldResolutionInUse() == pass->GetFarFieldResolution() &&
      pass->GetNumberOfFarFieldResolutionChoices() == 0 && pass->GetFarFieldErrorBudgetMet(),
    "no budget: FarFieldResolution, no choice");
  const double defaultBound = pass->ComputeFarFieldErrorBound();

  // 2. A loose budget: a coarse far field, within its bound of brute force.
  pass->SetErrorBudgetInSteps(16.0);
  rw->Render();
  Report(pass, "16 steps");
  const int loose = pass->GetFarFieldResolutionInUse();
  Check(pass->GetNumberOfFarFieldResolutionChoices() == 1, "16 steps: one choice");
  Check(loose > 0 && loose <= pass->GetFarFieldResolution(), "16 steps: no finer than the default");
  const double looseCutoff = pass->GetEffectiveFarFieldCutoff();
  Check(looseCutoff > pass->GetContributionCutoff(),
    "16 steps: a looser cutoff for the split lights than ContributionCutoff");
  Check(pass->GetEffectiveCutoff() == pass->GetContributionCutoff(),
    "16 steps: no culled light, their cutoff stays ContributionCutoff");
  Check(pass->GetFarFieldErrorBudgetMet() && pass->ComputeFarFieldErrorBound() <= 16.0,
    "16 steps: met, the reported bound within it");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "16 steps") == 0,
    "16 steps: within the stated bound of brute force, zero false negatives, finite");

  // 3. Moving lights keep the choice; another light makes a new one.
  lights->SetPosition(5, 0.3, 1.2, -0.4);
  rw->Render();
  lights->SetPosition(6, -1.0, 0.5, 0.8);
  rw->Render();
  Check(pass->GetNumberOfFarFieldResolutionChoices() == 1 &&
      pass->GetFarFieldResolutionInUse() == loose &&
      pass->GetEffectiveFarFieldCutoff() == looseCutoff,
    "moved lights: the same choice (resolution and cutoff), not made again");
  auto addUserLight = [&lights](double x, double y, double z)
  {
    const vtkIdType i = lights->AddLight(x, y, z);
    lights->SetAttenuation(i, 1.0, 0.0, 8.0);
    lights->SetIntensity(i, 0.02);
  };
  addUserLight(0.5, 0.2, 0.5);
  rw->Render();
  Check(pass->GetNumberOfFarFieldResolutionChoices() == 2, "one more light: a new choice");

  // 4. A tight budget: below the default resolution's bound.
  const double tight = 0.9 * defaultBound;
  pass->SetErrorBudgetInSteps(tight);
  rw->Render();
  Report(pass, "tight");
  const int fine = pass->GetFarFieldResolutionInUse();
  Check(fine > loose, "tight budget: a finer grid than the loose one");
  Check(pass->GetFarFieldErrorBudgetMet() == (pass->ComputeFarFieldErrorBound() <= tight),
    "tight budget: met exactly when the reported bound is within it");
  Check(messages->Warnings.size() == (pass->GetFarFieldErrorBudgetMet() ? 0u : 1u),
    "tight budget: a warning only if it is not met");
  messages->Clear();

  // 5. A budget no resolution meets.
  pass->SetErrorBudgetInSteps(0.01);
  rw->Render();
  Report(pass, "0.01 steps");
  Check(!pass->GetFarFieldErrorBudgetMet() && pass->ComputeFarFieldErrorBound() > 0.01,
    "0.01 steps: not met, and reported so");
  Check(messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("ErrorBudgetInSteps 0.01") != std::string::npos &&
      messages->Warnings[0].find("NearFieldBudget") != std::string::npos,
    "0.01 steps: one warning naming the budget and NearFieldBudget");
  lights->SetPosition(7, 0.0, 1.0, 0.0);
  rw->Render();
  addUserLight(-0.5, 0.2, 0.5);
  rw->Render();
  Check(messages->Warnings.size() == 1, "the same budget, lights changed: no second warning");
  std::ostringstream printed;
  pass->PrintSelf(printed, vtkIndent());
  Check(printed.str().find("(error budget not met)") != std::string::npos,
    "PrintSelf says the budget is not met");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "0.01 steps") == 0,
    "0.01 steps: still within the stated bound of brute force");

  // 6. No budget again: FarFieldResolution, the culled lights' ContributionCutoff and the
  // split lights' FarFieldCutoff (default 1/256), within the stated bound of brute force;
  // FarFieldCutoff 0 gives the split lights ContributionCutoff, and FarField off splits
  // nothing (every light takes ContributionCutoff).
  pass->SetErrorBudgetInSteps(0.0);
  rw->Render();
  Report(pass, "no budget");
  Check(pass->GetFarFieldResolutionInUse() == pass->GetFarFieldResolution() &&
      pass->GetFarFieldErrorBudgetMet() &&
      pass->GetEffectiveCutoff() == pass->GetContributionCutoff() &&
      pass->GetFarFieldCutoff() == 1.0 / 256.0 &&
      pass->GetEffectiveFarFieldCutoff() == pass->GetFarFieldCutoff(),
    "budget 0: FarFieldResolution, ContributionCutoff and FarFieldCutoff (1/256) again");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "FarFieldCutoff 1/256") == 0,
    "the split lights' default cutoff: within the stated bound of brute force");
  pass->SetFarFieldCutoff(0.0);
  rw->Render();
  Check(pass->GetEffectiveFarFieldCutoff() == pass->GetContributionCutoff(),
    "FarFieldCutoff 0: the split lights take ContributionCutoff");
  pass->SetFarFieldCutoff(1.0 / 256.0);
  pass->SetFarField(false);
  rw->Render();
  Check(pass->GetEffectiveFarFieldCutoff() == pass->GetContributionCutoff() &&
      pass->GetEffectiveCutoff() == pass->GetContributionCutoff(),
    "FarField off: every light takes ContributionCutoff");
  pass->SetFarField(true);

  // The split lights alone at 4 steps, for 7.
  pass->SetErrorBudgetInSteps(4.0);
  rw->Render();
  Report(pass, "4 steps");
  const double splitCutoff4 = pass->GetEffectiveFarFieldCutoff();
  const int splitNodes4 = pass->GetFarFieldResolutionInUse();

  // 7. Culled lights (an explicit radius past their cutoff radius) among the split lights:
  // each kind's cutoff is chosen for half of the budget, the same as for that kind alone at
  // half the budget.
  auto addCulled = [](vtkClusteredLightSet* set)
  {
    for (int k = 0; k < 64; ++k)
    {
      const vtkIdType i = set->AddLight(-2.8 + 0.8 * (k % 8), 1.2, -2.8 + 0.8 * (k / 8));
      set->SetAttenuation(i, 1.0, 0.0, 1.0);
      set->SetIntensity(i, 0.3);
      set->SetRadius(i, 50.0);
    }
  };
  addCulled(lights);
  pass->SetErrorBudgetInSteps(8.0);
  rw->Render();
  Report(pass, "8 steps, culled lights among the split lights");
  const double mixed = pass->GetEffectiveCutoff();
  Check(pass->GetEffectiveFarFieldCutoff() == splitCutoff4 &&
      pass->GetFarFieldResolutionInUse() == splitNodes4,
    "with culled lights beside them, the split lights' cutoff and the far field's resolution "
    "are those of the split lights alone at half the budget");
  ClusteredLightingTest::BruteForceCheck mixedCheck;
  Check(ClusteredLightingTest::CheckClusteredFrame(
          pass, rw, ren, 1.4, "8 steps, mixed", 0, &mixedCheck) == 0,
    "8 steps with culled lights: within the stated bound of brute force, zero false negatives");
  // The budget is stated for a white material (Diffuse + Specular <= 1); the scene's reach
  // 1.4 (CheckClusteredFrame's material factor), and the images are rounded to 8 bits.
  std::printf(
    "8 steps with culled lights: largest error %.2f steps\n", 255.0 * mixedCheck.MaxError);
  Check(255.0 * mixedCheck.MaxError <= 1.4 * 8.0 + 1.0,
    "8 steps with culled lights: the image within the budget of brute force (their tails "
    "held where the geometry is)");
  vtkNew<vtkClusteredLightSet> culledAlone;
  addCulled(culledAlone);
  pass->RemoveLightSet(lights);
  pass->AddLightSet(culledAlone);
  rw->Render();
  const double alone8 = pass->GetEffectiveCutoff();
  pass->SetErrorBudgetInSteps(4.0);
  rw->Render();
  const double alone4 = pass->GetEffectiveCutoff();
  std::printf("culled lights' cutoff: %g among split lights at 8 steps, %g alone at 8, %g alone "
              "at 4\n",
    mixed, alone8, alone4);
  Check(alone8 != alone4, "the culled lights alone: their cutoff depends on the budget");
  Check(mixed == alone4,
    "with split lights beside them, the culled lights' cutoff is chosen for half the budget");

  // 8. Spot lights as users write them (no radius) among the split lights: split too, so
  // nothing is culled and the far field, cones and all, is held to the whole budget.
  pass->RemoveLightSet(culledAlone);
  pass->AddLightSet(lights);
  for (vtkIdType i = n + 1; i < lights->GetNumberOfLights(); ++i)
  {
    lights->UnsetRadius(i);
    lights->SetSpot(i, 0.0, -1.0, 0.0, 60.0, 1.0);
  }
  pass->SetErrorBudgetInSteps(8.0);
  rw->Render();
  Report(pass, "8 steps, spot lights among the split lights");
  Check(pass->GetNumberOfFarFieldLights() == lights->GetNumberOfLights(),
    "spot lights without a radius are split like the others");
  Check(pass->GetEffectiveCutoff() == pass->GetContributionCutoff(),
    "spot lights split: no culled light, their cutoff stays ContributionCutoff");
  ClusteredLightingTest::BruteForceCheck spotCheck;
  Check(ClusteredLightingTest::CheckClusteredFrame(
          pass, rw, ren, 1.4, "8 steps, spot lights", 0, &spotCheck) == 0,
    "8 steps with spot lights: within the stated bound of brute force, zero false negatives");
  std::printf("8 steps with spot lights: largest error %.2f steps\n", 255.0 * spotCheck.MaxError);
  Check(255.0 * spotCheck.MaxError <= 1.4 * 8.0 + 1.0,
    "8 steps with spot lights: the image within the budget of brute force");
  return Status;
}
