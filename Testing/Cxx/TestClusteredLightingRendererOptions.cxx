// SPDX-License-Identifier: BSD-3-Clause
// Renderer options that only the renderer's own render applies (UseFXAA, UseShadows,
// UseSSAO, UseHiddenLineRemoval: vtkOpenGLRenderer's UpdateGeometry and
// DeviceRenderOpaqueGeometry). VTK's render steps, the pass's delegate, skip them, as they
// do under any render pass; until 2026-11-28 the pass dropped them without a word. Checks,
// on the test scene lit by the renderer's headlight (which the pass leaves to VTK, so its
// image equals stock VTK's):
//  - FXAA changes stock VTK's image here (the check below can fail);
//  - under the pass, UseFXAA is not applied and one warning says so, names the option and
//    the fix (a vtkOpenGLFXAAPass around the pass), however many frames follow;
//  - that fix gives stock VTK's FXAA image, bit for bit, with no warning;
//  - UseShadows gives one warning of its own, and another when it is asked for again after
//    being turned off.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightingPass.h"
#include "vtkOpenGLFXAAPass.h"

#include <cstdio>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

std::vector<float> Frame(vtkRenderWindow* rw, int frames = 1)
{
  for (int i = 0; i < frames; ++i)
  {
    rw->Render();
  }
  return ClusteredLightingTest::CapturePixels(rw);
}

double MaxDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  return ClusteredLightingTest::CompareImages(a, b).MaxAbsError;
}
}

int TestClusteredLightingRendererOptions(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 200, 150, 8);

  // Stock VTK, with and without FXAA.
  const std::vector<float> stockPlain = Frame(rw);
  ren->UseFXAAOn();
  const std::vector<float> stockFxaa = Frame(rw);
  Check(MaxDifference(stockFxaa, stockPlain) > 0.0, "FXAA changes stock VTK's image here");

  // Under the pass: not applied, said once.
  vtkNew<vtkClusteredLightingPass> pass;
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  ren->SetPass(pass);
  const std::vector<float> passFxaa = Frame(rw, 3);
  Check(MaxDifference(passFxaa, stockPlain) == 0.0,
    "under the pass UseFXAA is not applied (the image is stock VTK's without it)");
  Check(messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("UseFXAA") != std::string::npos &&
      messages->Warnings[0].find("vtkOpenGLFXAAPass") != std::string::npos,
    "one warning in 3 frames names UseFXAA and the fix");
  if (!messages->Warnings.empty())
  {
    std::printf("the warning: %s\n", messages->Warnings[0].c_str());
  }

  // The fix: a vtkOpenGLFXAAPass around the pass gives stock VTK's FXAA.
  ren->UseFXAAOff();
  vtkNew<vtkOpenGLFXAAPass> fxaa;
  fxaa->SetDelegatePass(pass);
  ren->SetPass(fxaa);
  const std::vector<float> wrapped = Frame(rw, 2);
  Check(MaxDifference(wrapped, stockFxaa) == 0.0,
    "a vtkOpenGLFXAAPass around the pass: stock VTK's FXAA image, bit for bit");
  Check(messages->Warnings.size() == 1, "no warning without the option");

  // Shadows: a warning of their own, and again when asked for again.
  ren->SetPass(pass);
  ren->UseShadowsOn();
  Frame(rw, 2);
  Check(messages->Warnings.size() == 2 &&
      messages->Warnings[1].find("UseShadows") != std::string::npos &&
      messages->Warnings[1].find("vtkOpenGLFXAAPass") == std::string::npos,
    "UseShadows: one warning that names it");
  ren->UseShadowsOff();
  Frame(rw);
  ren->UseShadowsOn();
  Frame(rw);
  Check(messages->Warnings.size() == 3, "asked for again: said again");
  ren->UseShadowsOff();
  Frame(rw);
  Check(messages->Errors.empty(), "no error");
  fxaa->ReleaseGraphicsResources(rw);
  pass->ReleaseGraphicsResources(rw);
  return ClusteredLightingTest::CheckStatus();
}
