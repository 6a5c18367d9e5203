// SPDX-License-Identifier: BSD-3-Clause
// The far field of lights that share a colour (FarFieldSharedColor): one channel in 3
// textures times the colour, instead of three channels in 7. Lights as users write them
// (inverse-square, attenuation (1, 0, 8), no radius) over the test scene. Checks that
//  - white lights (VTK's default colour) take the one-channel path, with 3/7 of the
//    texture memory, and their image is the three-channel path's bit for bit (white: the
//    three channels' sums are the same numbers);
//  - lights of one tint at different intensities take it too, and their image is the
//    three-channel path's to within one step (the channels' sums differ by float
//    rounding);
//  - both are within the stated bound of brute force, with zero false negatives and no
//    NaN pixel (CheckClusteredFrame);
//  - one light of another hue brings back three channels (a spot light without a radius
//    too: the far field holds it); a light that the far field does not hold (an explicit
//    radius) may have any colour;
//  - switching paths back and forth gives the first image again (textures released and
//    made again);
//  - the pass's ComputeFarFieldErrorBound(), whose probes run on several threads, is the
//    core's serial SummarizeFarFieldErrorBound over the same build, bit for bit.
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

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

/// Largest difference between two images, in 8-bit steps.
double MaxSteps(const std::vector<float>& a, const std::vector<float>& b)
{
  double m = a.size() == b.size() ? 0.0 : 1e9;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    m = std::max(m, 255.0 * std::abs(double(a[i]) - double(b[i])));
  }
  return m;
}

/// Share of the two images' channel values that differ.
double DifferingShare(const std::vector<float>& a, const std::vector<float>& b)
{
  std::size_t n = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    n += a[i] != b[i] ? 1 : 0;
  }
  return a.empty() ? 0.0 : static_cast<double>(n) / a.size();
}

/// Renders with FarFieldSharedColor on and off; returns both images.
void RenderBothPaths(vtkClusteredLightingPass* pass, vtkRenderWindow* rw, std::vector<float>& one,
  std::vector<float>& three, bool& usedOn, bool& usedOff, vtkTypeUInt64& bytesOn,
  vtkTypeUInt64& bytesOff)
{
  pass->FarFieldSharedColorOn();
  rw->Render();
  one = ClusteredLightingTest::CapturePixels(rw);
  usedOn = pass->GetFarFieldSharedColorUsed();
  bytesOn = pass->GetFarFieldTextureBytes();
  pass->FarFieldSharedColorOff();
  rw->Render();
  three = ClusteredLightingTest::CapturePixels(rw);
  usedOff = pass->GetFarFieldSharedColorUsed();
  bytesOff = pass->GetFarFieldTextureBytes();
  pass->FarFieldSharedColorOn();
  rw->Render();
}
}

int TestClusteredLightingSharedColor(int, char*[])
{
  const int n = 600;
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 320, 240);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, n, 0.02, 11);
  for (vtkIdType i = 0; i < n; ++i)
  {
    lights->SetColor(i, 1.0, 1.0, 1.0);
  }
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  // With the far specular's bins (off by default): one channel of them must give the
  // same image as three.
  pass->FarFieldSpecularBinsOn();
  ren->SetPass(pass);
  rw->Render();
  Check(pass->GetNumberOfFarFieldLights() == n, "every light is split (none has a radius)");

  // 1. White lights.
  std::vector<float> one, three;
  bool usedOn = false, usedOff = true;
  vtkTypeUInt64 bytesOn = 0, bytesOff = 0;
  RenderBothPaths(pass, rw, one, three, usedOn, usedOff, bytesOn, bytesOff);
  std::printf("white: far-field bytes %llu (one channel) and %llu (three), images differ by "
              "%.2f steps\n",
    static_cast<unsigned long long>(bytesOn), static_cast<unsigned long long>(bytesOff),
    MaxSteps(one, three));
  Check(usedOn && !usedOff, "white lights: one channel with the option on, three with it off");
  // Beside the moments, both hold the far specular's table (LobeTableBytes), and for the
  // sphere's specular (power 20) its bins: 26 slabs of the grid with one channel, 52 with
  // three (FarFieldSpecularBins).
  const vtkTypeUInt64 table = vtkClusteredLighting::LobeTableBytes;
  Check(pass->GetFarFieldSpecularBinsUsed(), "the sphere's specular takes the far specular's bins");
  Check(bytesOn > table && (bytesOn - table) * (14 + 52) == (bytesOff - table) * (5 + 26),
    "white lights: 5 moment textures and 26 bin slabs instead of 14 and 52");
  Check(MaxSteps(one, three) == 0.0, "white lights: the same image bit for bit");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "white lights") == 0,
    "white lights: within the stated bound of brute force, zero false negatives, finite");

  // The stated bound's summary: threaded in the pass, serial in the core.
  {
    const vtkClusteredLightingAssignmentSnapshot frame =
      vtkClusteredLightingInspector(pass).GetFrame(ren);
    const ClusteredLightingTest::SnapshotFarField farField(frame);
    const double serial = vtkClusteredLighting::SummarizeFarFieldErrorBound(farField.Inputs).Max;
    const double threaded = pass->ComputeFarFieldErrorBound();
    std::printf(
      "far-field bound over the probes: %.17g steps (pass), %.17g (core)\n", threaded, serial);
    Check(threaded == serial && serial > 0.0,
      "ComputeFarFieldErrorBound: the core's serial summary of the same build, bit for bit");
  }

  // 2. One tint, intensities from 0.005 to 0.04.
  for (vtkIdType i = 0; i < n; ++i)
  {
    lights->SetColor(i, 1.0, 0.8, 0.55);
    lights->SetIntensity(i, 0.005 + 0.035 * static_cast<double>(i % 7) / 6.0);
  }
  RenderBothPaths(pass, rw, one, three, usedOn, usedOff, bytesOn, bytesOff);
  std::printf("tinted: images differ by %.2f steps in %.4f%% of the values\n", MaxSteps(one, three),
    100.0 * DifferingShare(one, three));
  Check(usedOn && !usedOff, "one tint: one channel");
  Check(MaxSteps(one, three) <= 1.001 && DifferingShare(one, three) < 1e-3,
    "one tint: within one step of three channels, in fewer than 0.1% of the values");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "one tint") == 0,
    "one tint: within the stated bound of brute force, zero false negatives, finite");

  // 3. Lights the far field does not hold may differ: a red light and a blue spot light,
  // each with an explicit radius (cut there, never in the far field). Without its radius
  // the spot light is split like the others (since 2026-11-30), and its hue is another.
  lights->SetColor(0, 1.0, 0.0, 0.0);
  lights->SetRadius(0, 1.0);
  lights->SetColor(1, 0.0, 0.0, 1.0);
  lights->SetSpot(1, 0.0, -1.0, 0.0, 40.0, 1.0);
  rw->Render();
  Check(!pass->GetFarFieldSharedColorUsed() && pass->GetNumberOfFarFieldLights() == n - 1,
    "a blue spot light without a radius: split, three channels");
  lights->SetRadius(1, 1.0);
  rw->Render();
  Check(pass->GetFarFieldSharedColorUsed() && pass->GetNumberOfFarFieldLights() == n - 2,
    "a red light and a blue spot with radii: still one channel for the other lights");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "other colours near") == 0,
    "other colours near: within the stated bound of brute force");

  // 4. One far-field light of another hue: three channels again, then back.
  lights->SetColor(2, 0.2, 1.0, 0.2);
  rw->Render();
  const std::vector<float> mixed = ClusteredLightingTest::CapturePixels(rw);
  Check(!pass->GetFarFieldSharedColorUsed(), "one green far-field light: three channels");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "one other hue") == 0,
    "one other hue: within the stated bound of brute force");
  lights->SetColor(2, 1.0, 0.8, 0.55);
  rw->Render();
  const std::vector<float> back = ClusteredLightingTest::CapturePixels(rw);
  Check(pass->GetFarFieldSharedColorUsed(), "the tint again: one channel again");
  lights->SetColor(2, 0.2, 1.0, 0.2);
  rw->Render();
  Check(MaxSteps(mixed, ClusteredLightingTest::CapturePixels(rw)) == 0.0,
    "three channels again: the same image as before (textures made again)");
  lights->SetColor(2, 1.0, 0.8, 0.55);
  rw->Render();
  Check(MaxSteps(back, ClusteredLightingTest::CapturePixels(rw)) == 0.0,
    "one channel again: the same image as before");
  return Status;
}
