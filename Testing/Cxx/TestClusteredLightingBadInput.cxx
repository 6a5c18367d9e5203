// SPDX-License-Identifier: BSD-3-Clause
// Bad input: NaN or Inf position, color or intensity; negative intensity or radius;
// attenuation that is negative, non-finite or all zero (1/(a0+a1 d+a2 d^2) infinite or
// negative); spots without a direction or with a NaN cone; a vtkLight at NaN. Each gets a
// warning naming the light, is skipped, and every other light is unaffected (the image
// equals the one rendered with only the valid lights, exactly); nothing crashes, no pixel
// is NaN; warnings are given once per change, not every frame.
#include "ClusteredLightingHardCase.h"
#include "vtkClusteredLightingMessages.h"

#include "vtkLight.h"

#include <algorithm>
#include <limits>

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
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
