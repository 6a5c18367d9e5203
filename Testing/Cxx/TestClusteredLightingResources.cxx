// SPDX-License-Identifier: BSD-3-Clause
// GL resource lifetime of vtkClusteredLightingPass in one window. Checks that
//  - ReleaseGraphicsResources frees every GL object the pass made: its own count
//    (GetNumberOfGLObjects) goes to 0, each name it reported is no longer a GL object,
//    and, independently of the pass's bookkeeping, a census of every live texture,
//    buffer, framebuffer and vertex-array name in the context (asked of GL, name by
//    name) is exactly what it was before the pass first rendered;
//  - the pass renders the same image again after a release, with zero false negatives
//    and within the derived tolerance of brute force, and keeps doing so over repeated
//    release / reallocate cycles (grid and light-count changes) without any GL object
//    surviving a release;
//  - removing the renderer from the window, and deleting the pass while the window lives,
//    free the pass's objects too;
//  - no GL error, and no warning or error from the pass.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingScenes.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkCamera.h"
#include "vtkLight.h"

#include <cstdio>

using ClusteredLightingTest::Check;
using ClusteredLightingTest::CheckSameGLObjects;

namespace
{
}

int TestClusteredLightingResources(int, char*[])
{
  using namespace ClusteredLightingTest;
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  SetUpTestScene(renWin, ren, 160, 120);
  vtkNew<vtkClusteredLightSet> lights;
  MakeTestLights(lights, 300, 0.9, 11);
  for (int i = 0; i < 3; ++i)
  {
    vtkNew<vtkLight> l;
    l->SetLightTypeToSceneLight();
    l->SetPositional(true);
    l->SetConeAngle(180.0);
    l->SetPosition(-2.0 + 2.0 * i, 0.5, 2.0);
    l->SetAttenuationValues(1.0, 0.0, 2.0);
    ren->AddLight(l);
  }

  vtkSmartPointer<vtkClusteredLightingPass> pass = vtkSmartPointer<vtkClusteredLightingPass>::New();
  pass->AddLightSet(lights);
  pass->FarFieldSpecularBinsOn(); // its texture counts too
  // A small near-field budget gives these lights a far field, so that its textures are
  // part of every census below.
  pass->SetNearFieldBudget(1.0);
  vtkNew<MessageCollector> messages;
  messages->Watch(pass);

  // Baseline: every GL object of the window and the scene, before the pass exists there.
  renWin->Render();
  const GLNames before = TakeGLNameCensus(renWin);
  std::printf("GL objects before the pass: %zu\n", before.size());

  // 1. First render with the pass.
  ren->SetPass(pass);
  renWin->Render();
  const GLNames own = PassGLNames(pass);
  Check(pass->GetNumberOfClusteredLights() == 303, "303 clustered lights");
  // LightData, LightView, Quads (texture + buffer each), list, master, FBO, VAO, and the
  // far field's moment textures (the scene's lights are inverse-square), the cluster
  // depths and rectangles (depth-aware clusters are on by default), and the copy of the prepass's
  // depths for the next frame (ReuseDepthPrepass, on by default).
  // The sphere's specular (power 20) takes the far specular's bins (on here).
  const int per = GLObjectsPerRenderer(pass);
  Check(pass->GetFarFieldSpecularBinsUsed() &&
      per ==
        AssignmentGLObjects + FarFieldGLObjects + FarSpecularBinsGLObjects + DepthAwareGLObjects +
          SavedDepthGLObjects,
    "the lights have a far field with the specular's bins, the clusters are depth-aware, the "
    "prepass's depths are kept");
  Check(pass->GetNumberOfGLObjects() == per && own.size() == static_cast<std::size_t>(per),
    "the pass holds " + std::to_string(per) + " GL objects: count " +
      std::to_string(pass->GetNumberOfGLObjects()) + ", names " + Describe(own));
  bool allLive = true;
  for (const auto& n : own)
  {
    allLive = allLive && n.second <= CensusMaxName && IsLiveGLName(n.first, n.second);
  }
  Check(allLive, "every name the pass reports is a live GL object");
  CheckSameGLObjects(TakeGLNameCensus(renWin), Union(before, own),
    "after the first render, GL holds exactly the objects from before plus the pass's");
  const std::vector<float> first = CapturePixels(renWin);

  // 2. Release: nothing of the pass survives, according to GL itself.
  pass->ReleaseGraphicsResources(renWin);
  Check(pass->GetNumberOfGLObjects() == 0, "GetNumberOfGLObjects() is 0 after the release");
  renWin->MakeCurrent();
  bool anyLive = false;
  for (const auto& n : own)
  {
    anyLive = anyLive || IsLiveGLName(n.first, n.second);
  }
  Check(!anyLive, "no name the pass reported is a GL object after the release");
  CheckSameGLObjects(
    TakeGLNameCensus(renWin), before, "after the release, GL holds what it did before the pass");

  // 3. Works again: same image, exact assignment, brute-force bound.
  renWin->Render();
  Check(pass->GetNumberOfGLObjects() == per, "as many GL objects again after rendering");
  const ImageComparison again = CompareImages(first, CapturePixels(renWin));
  PrintComparison("after release vs before", again);
  Check(again.MaxAbsError == 0.0, "the image after the release is identical");
  const auto assignment = CheckAssignment(pass, ren, "after release");
  Check(assignment.FalseNegatives == 0 && assignment.MasterMismatches == 0,
    "no false negative after the release");
  Check(CheckAgainstBruteForce(pass, renWin, ren, 1.4, "after release").Violations == 0,
    "clustered within the derived tolerance of brute force after the release");

  // 4. Release / reallocate cycles: grid and light-count changes reallocate the list and
  //    master textures and the light buffers; no object may outlive its replacement.
  const int grids[5][3] = { { 8, 4, 8 }, { 32, 16, 32 }, { 1, 1, 1 }, { 64, 32, 16 },
    { 32, 16, 32 } };
  for (int cycle = 0; cycle < 5; ++cycle)
  {
    pass->SetTilesX(grids[cycle][0]);
    pass->SetTilesY(grids[cycle][1]);
    pass->SetSlices(grids[cycle][2]);
    lights->SetNumberOfLights(cycle % 2 ? 300 : 1100);
    renWin->Render();
    pass->SetSlices(grids[cycle][2] + 3);
    lights->SetNumberOfLights(cycle % 2 ? 40 : 700);
    renWin->Render();
    const auto cmp = CheckAssignment(pass, ren, "cycle");
    Check(cmp.FalseNegatives == 0 && cmp.MasterMismatches == 0,
      "cycle " + std::to_string(cycle) + ": no false negative");
    pass->ReleaseGraphicsResources(renWin);
    Check(pass->GetNumberOfGLObjects() == 0, "cycle " + std::to_string(cycle) + ": count 0");
    CheckSameGLObjects(TakeGLNameCensus(renWin), before,
      "cycle " + std::to_string(cycle) + ": GL holds what it did before the pass");
  }
  pass->SetTilesX(32);
  pass->SetTilesY(16);
  pass->SetSlices(32);
  MakeTestLights(lights, 300, 0.9, 11);
  renWin->Render();
  Check(CompareImages(first, CapturePixels(renWin)).MaxAbsError == 0.0,
    "the original settings give the original image again");

  // 5. Removing the renderer from the window releases the pass's objects with it.
  renWin->RemoveRenderer(ren);
  Check(pass->GetNumberOfGLObjects() == 0, "removing the renderer releases the pass's objects");
  renWin->AddRenderer(ren);
  renWin->Render();
  Check(pass->GetNumberOfGLObjects() == per, "the pass works again once the renderer is back");
  Check(CompareImages(first, CapturePixels(renWin)).MaxAbsError == 0.0,
    "same image once the renderer is back");

  // 6. Deleting the pass while the window lives frees its objects too.
  ren->SetPass(nullptr);
  renWin->Render(); // stock rendering: the scene's own objects stay
  const GLNames withPass = TakeGLNameCensus(renWin);
  const GLNames passNames = PassGLNames(pass);
  Check(passNames.size() == static_cast<std::size_t>(per),
    "the pass still holds its objects before it is deleted");
  pass = nullptr;
  CheckSameGLObjects(TakeGLNameCensus(renWin), Minus(withPass, passNames),
    "deleting the pass frees exactly its GL objects");

  std::string firstError;
  const int errors = CountGLErrors(renWin, &firstError);
  Check(errors == 0, "no GL error (" + std::to_string(errors) + ", first " + firstError + ")");
  for (const std::string& m : messages->Warnings)
  {
    std::printf("warning: %s\n", m.c_str());
  }
  Check(
    messages->Errors.empty() && messages->Warnings.empty(), "no warning or error from the pass");
  return CheckStatus();
}
