// SPDX-License-Identifier: BSD-3-Clause
// AutomaticDepthPrepass (on by default): the pass times frames with and without the depth
// prepass and keeps the faster (vtkClusteredLightingPrepassChoice.h). Which side wins
// depends on the device and its load, so this test does not ask which; it checks that
//  - a trial runs where it should: 3 frames as configured (shader compilation), then 4
//    frames with the prepass and 4 without, as the pass reports per frame
//    (GetDepthPrepassUsed), and one completed trial with a positive, finite time ratio;
//  - the frames after it follow the rule: no prepass exactly when the trial measured the
//    frames without it more than 5% faster;
//  - every frame gives the same image: bit for bit with lights that have an explicit
//    radius and windowed falloff, within one step with lights as users write them
//    (inverse-square, no radius, far field), and within the stated bound of brute force;
//  - a moving camera and props that leave the frame (frustum culling) do not restart the
//    trial; a changed scene (twice the lights, a changed option) starts over with the
//    prepass;
//  - AutomaticDepthPrepassOff renders the prepass in every frame and runs no trial.
#include "ClusteredLightingGLTestUtilities.h" // for Check
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
using ClusteredLightingTest::Check;

/// n frames of the unchanged scene: whether each drew the prepass, and its image.
struct Frames
{
  std::vector<bool> Prepass;
  std::vector<std::vector<float>> Images;
};

Frames RenderFrames(vtkRenderWindow* rw, vtkClusteredLightingPass* pass, int n)
{
  Frames out;
  for (int f = 0; f < n; ++f)
  {
    rw->Render();
    out.Prepass.push_back(pass->GetDepthPrepassUsed());
    out.Images.push_back(ClusteredLightingTest::CapturePixels(rw));
  }
  return out;
}

std::string Pattern(const std::vector<bool>& prepass)
{
  std::string s;
  for (bool p : prepass)
  {
    s += p ? 'P' : '-';
  }
  return s;
}

/// A trial of the unchanged scene: 3 frames with the prepass, 4 with, 4 without; then
/// `after` frames that follow the trial's choice. Returns the frames; checks the pattern,
/// the trial count and ratio, and that the frames after it follow the rule.
Frames CheckTrial(vtkRenderWindow* rw, vtkClusteredLightingPass* pass, const std::string& what)
{
  const Frames frames = RenderFrames(rw, pass, 3 + 8 + 2);
  const double ratio = pass->GetDepthPrepassTrialRatio();
  const bool keep = !(ratio > 1.0 / 0.95);
  const std::string expected = std::string("PPPPPPP----") + (keep ? "PP" : "--");
  std::printf("%s: frames %s (P: prepass), with / without %.3f\n", what.c_str(),
    Pattern(frames.Prepass).c_str(), ratio);
  Check(Pattern(frames.Prepass) == expected,
    what + ": 3 settle frames, 4 with and 4 without the prepass, then the choice");
  Check(pass->GetNumberOfDepthPrepassTrials() == 1, what + ": one trial completed");
  Check(ratio > 0.0 && std::isfinite(ratio), what + ": a positive, finite time ratio");
  return frames;
}
}

int TestClusteredLightingAutomaticPrepass(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 300, 200);
  vtkNew<vtkClusteredLightingPass> pass;
  Check(pass->GetAutomaticDepthPrepass(), "AutomaticDepthPrepass is on by default");
  pass->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeTestLights(lights, 600, 0.6, 11);
  for (vtkIdType i = 0; i < lights->GetNumberOfLights(); ++i)
  {
    lights->SetRadius(i, 0.6);
  }
  pass->AddLightSet(lights);
  ren->SetPass(pass);

  // 1. Lights with an explicit radius and windowed falloff: both modes, the same image.
  Frames frames = CheckTrial(rw, pass, "windowed lights");
  bool same = true;
  for (const auto& image : frames.Images)
  {
    same = same && image == frames.Images.front();
  }
  Check(same, "windowed lights: every frame's image is the first's, bit for bit");

  // 2. Lights as users write them (inverse-square, no radius: near parts and far field).
  // The pass's options and light sets change, so a new trial starts.
  pass->SetFalloff(vtkClusteredLightingPass::FALLOFF_HARD_CUT);
  vtkNew<vtkClusteredLightSet> userLights;
  ClusteredLightingTest::MakeUserLights(userLights, 600, 0.02, 12);
  pass->RemoveAllLightSets();
  pass->AddLightSet(userLights);
  frames = CheckTrial(rw, pass, "inverse-square lights");
  double worst = 0.0;
  for (const auto& image : frames.Images)
  {
    worst = std::max(worst,
      ClusteredLightingTest::CompareImages(image, frames.Images.front()).MaxAbsError * 255.0);
  }
  std::printf("inverse-square lights: largest difference from the first frame %.2f steps\n", worst);
  Check(worst <= 1.0 + 1e-6, "inverse-square lights: every frame within one step of the first");
  Check(pass->GetNumberOfFarFieldLights() > 0, "inverse-square lights: the far field is used");
  Check(
    ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "inverse-square lights") == 0,
    "inverse-square lights: within the stated bound of brute force, no false negative");

  // 3. A moving camera and a prop that leaves the frame and comes back (as frustum
  // culling makes it) are the same scene: the trial runs through them.
  vtkNew<vtkSphereSource> small;
  small->SetCenter(2.0, 0.0, 2.0);
  small->SetRadius(0.2);
  vtkNew<vtkPolyDataMapper> smallMapper;
  smallMapper->SetInputConnection(small->GetOutputPort());
  vtkNew<vtkActor> extra;
  extra->SetMapper(smallMapper);
  ren->AddActor(extra);
  for (int f = 0; f < 3 + 8; ++f)
  {
    extra->SetVisibility(f % 2);
    ren->GetActiveCamera()->Azimuth(1.0);
    ren->ResetCameraClippingRange();
    rw->Render();
  }
  Check(pass->GetNumberOfDepthPrepassTrials() == 1,
    "moving camera, a prop hidden every other frame: one trial completed in 11 frames");
  // Measuring the pass's parts (as a benchmark does after its timed frames) changes
  // nothing drawn, so it is the same scene: the trial and its choice stay.
  const std::string chosen = Pattern(RenderFrames(rw, pass, 2).Prepass);
  pass->MeasureTimingsOn();
  frames = RenderFrames(rw, pass, 2);
  pass->MeasureTimingsOff();
  std::printf("after the trial: %s, with MeasureTimings: %s\n", chosen.c_str(),
    Pattern(frames.Prepass).c_str());
  Check(pass->GetNumberOfDepthPrepassTrials() == 1 && (chosen == "PP" || chosen == "--") &&
      Pattern(frames.Prepass) == chosen,
    "MeasureTimings on: still one trial, and its choice in every frame");

  // 4. Twice the lights: a new scene, which starts with the prepass and no trial.
  ClusteredLightingTest::MakeUserLights(userLights, 1200, 0.01, 13);
  frames = RenderFrames(rw, pass, 3);
  Check(Pattern(frames.Prepass) == "PPP" && pass->GetNumberOfDepthPrepassTrials() == 0 &&
      pass->GetDepthPrepassTrialRatio() == 0.0,
    "twice the lights: 3 frames with the prepass, no trial yet");

  // 5. Off: the prepass in every frame, no trial.
  pass->AutomaticDepthPrepassOff();
  frames = RenderFrames(rw, pass, 3 + 8 + 2);
  Check(
    Pattern(frames.Prepass) == std::string(13, 'P') && pass->GetNumberOfDepthPrepassTrials() == 0,
    "AutomaticDepthPrepassOff: the prepass in every frame, no trial");
  return ClusteredLightingTest::CheckStatus();
}
