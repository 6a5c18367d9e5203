// SPDX-License-Identifier: BSD-3-Clause
// Bad input: NaN or Inf position, color or intensity; negative intensity or radius;
// attenuation that is negative, non-finite or all zero (1/(a0+a1 d+a2 d^2) infinite or
// negative); spots without a direction or with a NaN cone; a vtkLight at NaN. Each gets a
// warning naming the light, is skipped, and every other light is unaffected (the image
// equals the one rendered with only the valid lights, exactly); nothing crashes, no pixel
// is NaN; warnings are given once per change, not every frame. A NaN option of the pass is
// set back to its default with a warning naming it.
#include "ClusteredLightingHardCase.h"
#include "vtkClusteredLightingMessages.h"

#include "vtkLight.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace ClusteredLightingTest;

int TestClusteredLightingBadInput(int, char*[])
{
  int failures = 0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  SetUpRoomWindow(renWin, ren);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0.3, 0.2, 3.0);
  cam->SetFocalPoint(0, 0, -2);
  cam->SetViewAngle(60);
  cam->SetClippingRange(0.5, 9.0);

  // 12 valid lights, then one bad light per kind.
  const double visible[3] = { 0.0, 0.0, -2.75 };
  vtkNew<vtkClusteredLightSet> valid;
  MakeRoomLights(valid, 12, 2.5, 41, 3.5, visible);
  vtkNew<vtkClusteredLightSet> mixed;
  MakeRoomLights(mixed, 12, 2.5, 41, 3.5, visible);
  struct Bad
  {
    const char* What;
    void (*Apply)(vtkClusteredLightSet*, vtkIdType);
  };
  static const double kNan = nan, kInf = inf;
  const Bad bad[] = {
    { "NaN position", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetPosition(i, kNan, 0, 0); } },
    { "Inf position", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetPosition(i, 0, kInf, 0); } },
    { "NaN color", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetColor(i, 1, kNan, 1); } },
    { "Inf color", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetColor(i, kInf, 1, 1); } },
    { "negative color", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetColor(i, -1, 1, 1); } },
    { "NaN intensity", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetIntensity(i, kNan); } },
    { "Inf intensity", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetIntensity(i, kInf); } },
    { "negative intensity", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetIntensity(i, -2); } },
    { "negative radius", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetRadius(i, -1); } },
    { "NaN radius", [](vtkClusteredLightSet* s, vtkIdType i) { s->SetRadius(i, kNan); } },
    { "zero attenuation (infinite everywhere)",
      [](vtkClusteredLightSet* s, vtkIdType i) { s->SetAttenuation(i, 0, 0, 0); } },
    { "negative attenuation (infinite at d = 1)",
      [](vtkClusteredLightSet* s, vtkIdType i) { s->SetAttenuation(i, 1, -1, 0); } },
    { "NaN attenuation",
      [](vtkClusteredLightSet* s, vtkIdType i) { s->SetAttenuation(i, 1, 0, kNan); } },
    { "spot without direction",
      [](vtkClusteredLightSet* s, vtkIdType i) { s->SetSpot(i, 0, 0, 0, 30, 1); } },
    { "spot with NaN cone",
      [](vtkClusteredLightSet* s, vtkIdType i) { s->SetSpot(i, 0, 0, -1, kNan, 1); } },
  };
  const int numberOfBad = static_cast<int>(sizeof(bad) / sizeof(bad[0]));
  for (int k = 0; k < numberOfBad; ++k)
  {
    const double p[3] = { 0.5, 0.5, -1.0 };
    const vtkIdType id = mixed->AddLight(p[0], p[1], p[2]);
    SetLight(mixed, id, p, 2.0);
    bad[k].Apply(mixed, id);
  }

  vtkNew<vtkClusteredLightingPass> pass;
  vtkNew<MessageCollector> messages;
  messages->Watch(pass);
  pass->AddLightSet(valid);
  ren->SetPass(pass);
  renWin->Render();
  const std::vector<float> reference = CapturePixels(renWin);
  failures += messages->Warnings.empty() ? 0 : 1;

  pass->RemoveAllLightSets();
  pass->AddLightSet(mixed);
  renWin->Render();
  const std::vector<float> withBad = CapturePixels(renWin);
  std::printf("%zu warnings for %d bad lights; %d clustered, %d rejected\n",
    messages->Warnings.size(), numberOfBad, pass->GetNumberOfClusteredLights(),
    pass->GetNumberOfRejectedLights());
  // The first DefaultMaximumProblemsPerSource bad lights are named one by one, the rest
  // summarized in one line (vtkClusteredLightingMessages.h).
  const int shown =
    std::min(numberOfBad, static_cast<int>(vtkClusteredLighting::DefaultMaximumProblemsPerSource));
  for (int k = 0; k < shown; ++k)
  {
    const std::string name = "light " + std::to_string(12 + k) + ":";
    bool named = false;
    for (const std::string& w : messages->Warnings)
    {
      named =
        named || (w.find(name) != std::string::npos && w.find("skipped") != std::string::npos);
    }
    std::printf("[%s] %s: warning names the light\n", named ? "PASS" : "FAIL", bad[k].What);
    failures += named ? 0 : 1;
  }
  const std::string summary =
    "... and " + std::to_string(numberOfBad - shown) + " more problems in vtkClusteredLightSet";
  const std::string range =
    "(lights " + std::to_string(12 + shown) + " to " + std::to_string(11 + numberOfBad) + ")";
  bool summarized = false;
  for (const std::string& w : messages->Warnings)
  {
    summarized =
      summarized || (w.find(summary) != std::string::npos && w.find(range) != std::string::npos);
  }
  std::printf("[%s] the other %d bad lights in one line: %s ... %s\n", summarized ? "PASS" : "FAIL",
    numberOfBad - shown, summary.c_str(), range.c_str());
  failures += summarized ? 0 : 1;
  const bool counted = static_cast<int>(messages->Warnings.size()) == shown + 1 &&
    pass->GetNumberOfClusteredLights() == 12 && pass->GetNumberOfRejectedLights() == numberOfBad;
  std::printf("[%s] %d warnings for %d bad lights, the 12 valid lights kept\n",
    counted ? "PASS" : "FAIL", shown + 1, numberOfBad);
  failures += counted ? 0 : 1;
  const auto same = CompareImages(reference, withBad);
  std::printf("[%s] valid lights unaffected: image identical (max difference %.4f)\n",
    same.MaxAbsError == 0.0 ? "PASS" : "FAIL", same.MaxAbsError);
  failures += same.MaxAbsError == 0.0 ? 0 : 1;
  failures += RunHardCase(pass, renWin, ren, "mixed valid and bad lights");
  const std::size_t warningsAfter = messages->Warnings.size();
  renWin->Render();
  renWin->Render();
  std::printf("[%s] no repeated warnings on unchanged frames\n",
    messages->Warnings.size() == warningsAfter ? "PASS" : "FAIL");
  failures += messages->Warnings.size() == warningsAfter ? 0 : 1;

  // A vtkLight of the renderer at NaN.
  messages->Clear();
  vtkNew<vtkLight> broken;
  broken->SetPositional(true);
  broken->SetPosition(nan, 0, 0);
  ren->AddLight(broken);
  renWin->Render();
  const bool vtkLightNamed = messages->Warnings.size() == 1 &&
    messages->Warnings[0].find("vtkLight") != std::string::npos &&
    messages->Warnings[0].find("not finite") != std::string::npos;
  std::printf("[%s] vtkLight at NaN: %s\n", vtkLightNamed ? "PASS" : "FAIL",
    messages->Warnings.empty() ? "(no warning)" : messages->Warnings[0].c_str());
  failures += vtkLightNamed ? 0 : 1;
  failures += CountNonFinitePixels(pass, renWin) == 0 ? 0 : 1;

  // NaN options: vtkSetClampMacro stores NaN as given (its comparisons are false). The
  // next frame sets each back to its default with one warning naming it, and renders as
  // with the default; SetErrorBudgetInSteps(NaN) is refused when called.
  renWin->Render();
  const std::vector<float> before = CapturePixels(renWin);
  vtkNew<vtkClusteredLightingPass> fresh;
  struct NaNOption
  {
    const char* Name;
    void (*Set)(vtkClusteredLightingPass*, double);
    double (*Get)(vtkClusteredLightingPass*);
  };
  const NaNOption nanOptions[] = {
    { "ContributionCutoff",
      [](vtkClusteredLightingPass* p, double v) { p->SetContributionCutoff(v); },
      [](vtkClusteredLightingPass* p) { return p->GetContributionCutoff(); } },
    { "FarFieldCutoff", [](vtkClusteredLightingPass* p, double v) { p->SetFarFieldCutoff(v); },
      [](vtkClusteredLightingPass* p) { return p->GetFarFieldCutoff(); } },
    { "ErrorBudget", [](vtkClusteredLightingPass* p, double v) { p->SetErrorBudget(v); },
      [](vtkClusteredLightingPass* p) { return p->GetErrorBudget(); } },
    { "FarFieldCellsPerRadius",
      [](vtkClusteredLightingPass* p, double v) { p->SetFarFieldCellsPerRadius(v); },
      [](vtkClusteredLightingPass* p) { return p->GetFarFieldCellsPerRadius(); } },
    { "FarFieldTolerance",
      [](vtkClusteredLightingPass* p, double v) { p->SetFarFieldTolerance(v); },
      [](vtkClusteredLightingPass* p) { return p->GetFarFieldTolerance(); } },
    { "FarFieldGrouping", [](vtkClusteredLightingPass* p, double v) { p->SetFarFieldGrouping(v); },
      [](vtkClusteredLightingPass* p) { return p->GetFarFieldGrouping(); } },
    { "NearFieldBudget", [](vtkClusteredLightingPass* p, double v) { p->SetNearFieldBudget(v); },
      [](vtkClusteredLightingPass* p) { return p->GetNearFieldBudget(); } },
    { "HeatMapMaximum", [](vtkClusteredLightingPass* p, double v) { p->SetHeatMapMaximum(v); },
      [](vtkClusteredLightingPass* p) { return p->GetHeatMapMaximum(); } },
  };
  for (const NaNOption& o : nanOptions)
  {
    messages->Clear();
    o.Set(pass, nan);
    renWin->Render();
    const bool named = messages->Warnings.size() == 1 &&
      messages->Warnings[0].find(o.Name) != std::string::npos &&
      messages->Warnings[0].find("NaN") != std::string::npos;
    const bool reset = o.Get(pass) == o.Get(fresh);
    const bool same = CapturePixels(renWin) == before;
    std::printf("[%s] %s NaN: %s; %s %g (default %g); image %s\n",
      named && reset && same ? "PASS" : "FAIL", o.Name,
      messages->Warnings.empty() ? "(no warning)" : messages->Warnings[0].c_str(), o.Name,
      o.Get(pass), o.Get(fresh), same ? "unchanged" : "changed");
    failures += named && reset && same ? 0 : 1;
    renWin->Render(); // once: no warning in the next frame
    failures += messages->Warnings.size() == 1 ? 0 : 1;
  }
  messages->Clear();
  pass->SetErrorBudgetInSteps(4.0);
  pass->SetErrorBudgetInSteps(nan);
  const bool refused = messages->Warnings.size() == 1 &&
    messages->Warnings[0].find("NaN") != std::string::npos &&
    std::abs(pass->GetErrorBudgetInSteps() - 4.0) < 1e-12;
  std::printf("[%s] SetErrorBudgetInSteps(NaN) refused, the budget stays %g steps\n",
    refused ? "PASS" : "FAIL", pass->GetErrorBudgetInSteps());
  failures += refused ? 0 : 1;
  pass->SetErrorBudgetInSteps(0.0);
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
