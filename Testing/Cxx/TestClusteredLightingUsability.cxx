// SPDX-License-Identifier: BSD-3-Clause
// What a new user trips on (issue 14), each checked so that it would fail without the fix:
//  - enumerated options: SetShadingMode(7) is an error naming the accepted values and
//    keeps the mode (VTK's clamping setter silently made it brute force); SetXToY and
//    GetXAsString for every enumerated option; PrintSelf prints names, the advanced and
//    diagnostic groups and the rejected and always-on counts;
//  - the renamed options keep their old names working (Cutoff, ErrorBudget) and the
//    error budget in 8-bit steps equals the old fraction times 255;
//  - clustering that cannot help: 100 lights that never fall off (far field off) are
//    shaded by the plain loop, giving exactly the brute-force image, with one warning
//    naming the cause and the fix; 10 such lights take the plain loop without a warning;
//    200 inverse-square lights without a radius (far field off) get one warning that
//    clustering culls little, and none with the far field on;
//  - lights evaluated per pixel: a DEBUG_EVALUATED_COUNT frame's statistics equal the
//    counts decoded independently from the window's pixels and depth; the heat map scales
//    to the data (its hottest colour is the measured maximum, and appears in the image).
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace
{
int Failed = 0;

void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  Failed += ok ? 0 : 1;
}

/// A VTK message without its "Warning: In file, line N\nclass (address): " prefix (so
/// that the log holds no "ERROR:" of an expected error).
std::string Text(const std::vector<std::string>& messages)
{
  if (messages.empty())
  {
    return std::string();
  }
  const std::string& m = messages[0];
  const std::size_t colon = m.find("): ");
  return colon == std::string::npos ? m : m.substr(colon + 3);
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

/// Lights over AddTestScene: a 10 x n/10 grid of positions at height 1.2.
void MakeLights(vtkClusteredLightSet* lights, int n, double a0, double a2, double intensity)
{
  lights->SetNumberOfLights(n);
  for (int i = 0; i < n; ++i)
  {
    const double x = -2.7 + 5.4 * ((i % 10) + 0.5) / 10.0;
    const double z = -2.7 + 5.4 * ((i / 10) + 0.5) / ((n + 9) / 10);
    lights->SetPosition(i, x, 1.2, z);
    lights->SetColor(
      i, 0.5 + 0.5 * (i % 3 == 0), 0.5 + 0.5 * (i % 3 == 1), 0.5 + 0.5 * (i % 3 == 2));
    lights->SetIntensity(i, intensity);
    lights->SetAttenuation(i, a0, 0.0, a2);
  }
}

void CheckEnumeratedOptions(vtkClusteredLightingPass* pass)
{
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  pass->SetShadingMode(7);
  const std::string error = Text(messages->Errors);
  Check(messages->Errors.size() == 1 && Contains(error, "SetShadingMode(7): not a shading mode") &&
      Contains(error, "0 (Clustered) or 1 (BruteForce)") && Contains(error, "Kept Clustered"),
    "SetShadingMode(7) is an error naming the accepted values: " + error);
  Check(pass->GetShadingMode() == vtkClusteredLightingPass::SHADING_CLUSTERED,
    "SetShadingMode(7) keeps the mode");
  pass->SetDebugView(-1);
  pass->SetFalloff(2);
  pass->SetSlicingScheme(3);
  pass->SetBoundsMethod(9);
  Check(messages->Errors.size() == 5 && pass->GetDebugView() == 0 && pass->GetFalloff() == 0 &&
      pass->GetSlicingScheme() == 0 && pass->GetBoundsMethod() == 0,
    "every enumerated setter rejects a value out of range and keeps its own");
  messages->Clear();

  pass->SetShadingModeToBruteForce();
  pass->SetFalloffToWindowed();
  pass->SetSlicingSchemeToLinear();
  pass->SetDebugViewToHeatMap();
  pass->SetBoundsMethodToCenterDepthQuad();
  Check(std::string(pass->GetShadingModeAsString()) == "BruteForce" &&
      std::string(pass->GetFalloffAsString()) == "Windowed" &&
      std::string(pass->GetSlicingSchemeAsString()) == "Linear" &&
      std::string(pass->GetDebugViewAsString()) == "HeatMap" &&
      std::string(pass->GetBoundsMethodAsString()) == "CenterDepthQuad",
    "SetXToY sets what GetXAsString names");
  std::ostringstream os;
  pass->Print(os);
  const std::string printed = os.str();
  Check(Contains(printed, "ShadingMode: BruteForce") && Contains(printed, "Falloff: Windowed") &&
      Contains(printed, "SlicingScheme: Linear") && Contains(printed, "DebugView: HeatMap") &&
      Contains(printed, "BoundsMethod: CenterDepthQuad") && Contains(printed, "Advanced:") &&
      Contains(printed, "Diagnostic:") && Contains(printed, "NumberOfRejectedLights:") &&
      Contains(printed, "NumberOfAlwaysOnLights:"),
    "PrintSelf prints names, the option groups and the rejected and always-on counts");
  pass->SetShadingModeToClustered();
  pass->SetFalloffToHardCut();
  pass->SetSlicingSchemeToAuto();
  pass->SetDebugViewToNone();
  pass->SetBoundsMethodToTangent();
  Check(messages->Errors.empty() && messages->Warnings.empty(), "valid values give no message");

  // Renamed options: the old names still work, on the same value.
  pass->SetCutoff(1.0 / 64.0);
  Check(pass->GetContributionCutoff() == 1.0 / 64.0, "SetCutoff sets ContributionCutoff");
  pass->SetContributionCutoff(1.0 / 1024.0);
  Check(pass->GetCutoff() == 1.0 / 1024.0, "GetCutoff reads ContributionCutoff");
  pass->SetErrorBudgetInSteps(4.0);
  Check(std::abs(pass->GetErrorBudget() - 4.0 / 255.0) < 1e-15,
    "ErrorBudgetInSteps 4 is ErrorBudget 4/255");
  pass->SetErrorBudget(2.0 / 255.0);
  Check(
    std::abs(pass->GetErrorBudgetInSteps() - 2.0) < 1e-12, "ErrorBudget 2/255 reads as 2 steps");
  pass->SetErrorBudget(0.0);
}

/// The window's pixels decoded as DEBUG_EVALUATED_COUNT (R + 256 G) where depth < 1.
void DecodeCounts(vtkRenderWindow* rw, double& mean, int& maximum, vtkIdType& pixels)
{
  const int* size = rw->GetSize();
  vtkNew<vtkUnsignedCharArray> rgb;
  rw->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, rgb);
  vtkNew<vtkFloatArray> depth;
  rw->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth);
  double sum = 0.0;
  maximum = 0;
  pixels = 0;
  for (vtkIdType i = 0; i < depth->GetNumberOfValues(); ++i)
  {
    if (depth->GetValue(i) < 1.0f)
    {
      const int evaluated = rgb->GetValue(3 * i) + 256 * rgb->GetValue(3 * i + 1);
      sum += evaluated;
      maximum = std::max(maximum, evaluated);
      ++pixels;
    }
  }
  mean = pixels > 0 ? sum / static_cast<double>(pixels) : 0.0;
}
}

int TestClusteredLightingUsability(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  ClusteredLightingTest::SetUpTestScene(rw, ren, 240, 180);
  vtkNew<vtkClusteredLightingPass> pass;
  ren->SetPass(pass);
  CheckEnumeratedOptions(pass);

  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  vtkNew<vtkClusteredLightSet> lights;
  pass->AddLightSet(lights);

  // 100 lights that never fall off, far field off: the plain loop, exactly brute force.
  MakeLights(lights, 100, 1.0, 0.0, 0.006);
  pass->FarFieldOff();
  rw->Render();
  rw->Render();
  const std::vector<float> bypassed = ClusteredLightingTest::CapturePixels(rw);
  const std::string warning = Text(messages->Warnings);
  Check(pass->GetClusteringBypassed(), "100 always-on lights take the plain loop");
  Check(messages->Warnings.size() == 1 && Contains(warning, "all 100 reach every cluster") &&
      Contains(warning, "never fall off") && Contains(warning, "FarFieldOn"),
    "one warning names the cause and the fix: " + warning);
  pass->SetShadingModeToBruteForce();
  rw->Render();
  const std::vector<float> brute = ClusteredLightingTest::CapturePixels(rw);
  const ClusteredLightingTest::ImageComparison same =
    ClusteredLightingTest::CompareImages(bypassed, brute);
  ClusteredLightingTest::PrintComparison("plain loop vs brute force", same);
  Check(same.MaxAbsError == 0.0, "the plain loop gives exactly the brute-force image");
  pass->SetShadingModeToClustered();
  pass->FarFieldOn();
  rw->Render();
  Check(!pass->GetClusteringBypassed() && pass->GetNumberOfFarFieldLights() == 100,
    "with the far field on, the 100 lights are split and clustered");

  // 10 such lights (an ordinary scene of a few vtkLights): the plain loop, no warning.
  messages->Clear();
  MakeLights(lights, 10, 1.0, 0.0, 0.05);
  rw->Render();
  Check(pass->GetClusteringBypassed() && messages->Warnings.empty(),
    "10 always-on lights take the plain loop without a warning");

  // 200 inverse-square lights without a radius, far field off: clustering culls little.
  messages->Clear();
  MakeLights(lights, 200, 0.0, 1.0, 0.02);
  pass->FarFieldOff();
  rw->Render();
  rw->Render();
  const std::string little = Text(messages->Warnings);
  std::printf("far field off: %.1f lights per cluster of 200\n", pass->GetMeanLightsPerCluster());
  Check(messages->Warnings.size() == 1 && Contains(little, "Clustering culls little") &&
      Contains(little, "of the 200 lights") && Contains(little, "FarFieldOn") &&
      pass->GetMeanLightsPerCluster() >= 100.0 && !pass->GetClusteringBypassed(),
    "one warning that clustering culls little: " + little);
  messages->Clear();
  pass->FarFieldOn();
  rw->Render();
  std::printf("far field on: %.1f lights per cluster of 200\n", pass->GetMeanLightsPerCluster());
  Check(messages->Warnings.empty() && pass->GetMeanLightsPerCluster() < 100.0,
    "with the far field on, no warning");

  // Lights evaluated per pixel, counted by a DEBUG_EVALUATED_COUNT frame.
  pass->SetDebugViewToEvaluatedCount();
  rw->Render();
  double mean = 0.0;
  int maximum = 0;
  vtkIdType pixels = 0;
  DecodeCounts(rw, mean, maximum, pixels);
  std::printf("evaluated per pixel: pass %.3f (max %d, %lld pixels), decoded %.3f (max %d, %lld "
              "pixels)\n",
    pass->GetMeanLightsEvaluatedPerPixel(), pass->GetMaximumLightsEvaluatedPerPixel(),
    static_cast<long long>(pass->GetNumberOfCountedPixels()), mean, maximum,
    static_cast<long long>(pixels));
  Check(pixels > 1000 && maximum > 0 && pass->GetNumberOfCountedPixels() == pixels &&
      pass->GetMaximumLightsEvaluatedPerPixel() == maximum &&
      std::abs(pass->GetMeanLightsEvaluatedPerPixel() - mean) < 1e-9,
    "the pass's per-pixel statistics equal the counts decoded from the window");

  // The heat map scales to the data: the measured maximum is its hottest colour.
  pass->SetDebugViewToHeatMap();
  rw->Render();
  const std::vector<float> heat = ClusteredLightingTest::CapturePixels(rw);
  std::size_t hottest = 0;
  for (std::size_t i = 0; i + 2 < heat.size(); i += 3)
  {
    // clHeatColor(1) = (0.5, 0, 0); anything hotter would be clamped to it.
    hottest +=
      std::abs(heat[i] - 0.5f) < 1.5f / 255.0f && heat[i + 1] == 0.0f && heat[i + 2] == 0.0f;
  }
  std::printf(
    "heat map scale %.1f, %zu pixels at the hottest colour\n", pass->GetHeatMapScale(), hottest);
  Check(pass->GetHeatMapScale() == static_cast<double>(maximum) &&
      pass->GetMaximumLightsEvaluatedPerPixel() == maximum && hottest > 0 &&
      hottest < static_cast<std::size_t>(pixels) / 2,
    "the heat map's hottest colour is the measured maximum, shown where it is reached");
  pass->SetHeatMapMaximum(4.0);
  rw->Render();
  Check(pass->GetHeatMapScale() == 4.0, "an explicit HeatMapMaximum is the scale");
  pass->SetDebugViewToNone();
  return Failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
