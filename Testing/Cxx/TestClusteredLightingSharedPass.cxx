// SPDX-License-Identifier: BSD-3-Clause
// One vtkClusteredLightingPass shared by two render windows, and by two renderers of one
// window. Checks that
//  - each renderer's image is identical to the same scene rendered with a pass of its own,
//    and has zero false negatives and stays within the derived tolerance of brute force,
//    while lights move between the renders of the two windows;
//  - releasing the pass for one window frees exactly that window's GL objects, in that
//    window's context, while another window's context is current: the other window's GL
//    objects are untouched (asked of GL, name by name) and both still render correctly;
//  - a renderer deleted while its window lives does not disturb the other window's
//    rendering (its state is dropped without switching GL contexts under the render);
//  - destroying a window releases the pass's objects for it;
//  - no GL error, and no warning or error from the passes.
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
vtkSmartPointer<vtkRenderer> MakeRenderer(const double eye[3], double light)
{
  vtkSmartPointer<vtkRenderer> ren = vtkSmartPointer<vtkRenderer>::New();
  ren->SetBackground(0.05, 0.05, 0.08);
  ClusteredLightingTest::AddTestScene(ren);
  ren->GetActiveCamera()->SetPosition(eye[0], eye[1], eye[2]);
  ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  ren->ResetCameraClippingRange();
  // Two renderer lights of its own (clustered by the pass along with the shared set).
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkLight> l;
    l->SetLightTypeToSceneLight();
    l->SetPositional(true);
    l->SetConeAngle(i == 0 ? 180.0 : 40.0);
    l->SetPosition(light + 1.5 * i, 1.0, 1.5);
    l->SetFocalPoint(light, -1.0, 0.0);
    l->SetAttenuationValues(1.0, 0.0, 1.5);
    ren->AddLight(l);
  }
  return ren;
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(int w, int h)
{
  vtkSmartPointer<vtkRenderWindow> win = vtkSmartPointer<vtkRenderWindow>::New();
  win->SetSize(w, h);
  win->SetMultiSamples(0);
  return win;
}

/// Checks one renderer rendered by `pass`: assignment and brute-force bound.
void CheckRenderer(
  vtkClusteredLightingPass* pass, vtkRenderWindow* win, vtkRenderer* ren, const std::string& name)
{
  win->Render();
  const auto cmp = ClusteredLightingTest::CheckAssignment(pass, ren, name.c_str());
  Check(cmp.FalseNegatives == 0 && cmp.MasterMismatches == 0, name + ": no false negative");
  Check(
    ClusteredLightingTest::CheckAgainstBruteForce(pass, win, ren, 1.4, name.c_str()).Violations ==
      0,
    name + ": within the derived tolerance of brute force");
}

/// Renders `ren` of `win` with a fresh pass of its own (same light set) and returns the image.
std::vector<float> RenderWithOwnPass(
  vtkRenderWindow* win, vtkRenderer* ren, vtkClusteredLightSet* lights, vtkRenderPass* restore)
{
  vtkNew<vtkClusteredLightingPass> own;
  own->AddLightSet(lights);
  ren->SetPass(own);
  win->Render();
  std::vector<float> image = ClusteredLightingTest::CapturePixels(win);
  ren->SetPass(restore);
  return image;
}
}

int TestClusteredLightingSharedPass(int, char*[])
{
  using namespace ClusteredLightingTest;
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeTestLights(lights, 200, 0.9, 5);
  vtkNew<vtkClusteredLightingPass> shared;
  shared->AddLightSet(lights);
  vtkNew<MessageCollector> messages;
  messages->Watch(shared);

  const double eyeA[3] = { 0.5, 2.5, 7.0 }, eyeB[3] = { -4.0, 3.0, 4.0 };
  vtkSmartPointer<vtkRenderWindow> winA = MakeWindow(128, 96), winB = MakeWindow(112, 84);
  vtkSmartPointer<vtkRenderer> renA = MakeRenderer(eyeA, -1.0), renB = MakeRenderer(eyeB, 1.0);
  winA->AddRenderer(renA);
  winB->AddRenderer(renB);
  renA->SetPass(shared);
  renB->SetPass(shared);

  // 1. Two windows, lights moving between their renders.
  for (int frame = 0; frame < 4; ++frame)
  {
    for (vtkIdType i = frame; i < lights->GetNumberOfLights(); i += 7)
    {
      double p[3];
      lights->GetPosition(i, p);
      lights->SetPosition(i, p[0] + 0.1, p[1], p[2] - 0.05);
    }
    winA->Render();
    winB->Render();
  }
  Check(shared->GetNumberOfClusteredLights() == 202, "202 clustered lights per renderer");
  const int per = GLObjectsPerRenderer(shared);
  Check(shared->GetNumberOfGLObjects() == 2 * per, "the same GL objects for each renderer");
  const std::vector<float> imageA = CapturePixels(winA), imageB = CapturePixels(winB);
  CheckRenderer(shared, winA, renA, "window A, shared pass");
  CheckRenderer(shared, winB, renB, "window B, shared pass");
  const ImageComparison ownA = CompareImages(imageA, RenderWithOwnPass(winA, renA, lights, shared));
  const ImageComparison ownB = CompareImages(imageB, RenderWithOwnPass(winB, renB, lights, shared));
  PrintComparison("window A: shared pass vs own pass", ownA);
  PrintComparison("window B: shared pass vs own pass", ownB);
  Check(ownA.MaxAbsError == 0.0 && ownB.MaxAbsError == 0.0,
    "each window's image is identical to the one of a pass of its own");

  // 2. Two renderers of one window (side by side) sharing the pass.
  {
    vtkSmartPointer<vtkRenderWindow> winC = MakeWindow(200, 90);
    vtkSmartPointer<vtkRenderer> left = MakeRenderer(eyeA, 0.0), right = MakeRenderer(eyeB, 0.5);
    left->SetViewport(0.0, 0.0, 0.5, 1.0);
    right->SetViewport(0.5, 0.0, 1.0, 1.0);
    winC->AddRenderer(left);
    winC->AddRenderer(right);
    left->SetPass(shared);
    right->SetPass(shared);
    winC->Render();
    const std::vector<float> both = CapturePixels(winC);
    CheckRenderer(shared, winC, left, "window C left, shared pass");
    CheckRenderer(shared, winC, right, "window C right, shared pass");
    vtkNew<vtkClusteredLightingPass> ownLeft, ownRight;
    ownLeft->AddLightSet(lights);
    ownRight->AddLightSet(lights);
    left->SetPass(ownLeft);
    right->SetPass(ownRight);
    winC->Render();
    const ImageComparison own = CompareImages(both, CapturePixels(winC));
    PrintComparison("window C (two renderers): shared pass vs own passes", own);
    Check(own.MaxAbsError == 0.0, "two renderers sharing a pass render as with their own");
    Check(shared->GetNumberOfGLObjects() == 4 * per, "the same GL objects for each of 4 renderers");
  }
  Check(shared->GetNumberOfGLObjects() == 2 * per, "window C's objects went with it");

  // 3. Releasing window B's objects while window A's context is current.
  shared->ReleaseGraphicsResources(nullptr);
  Check(shared->GetNumberOfGLObjects() == 0, "release for all windows: 0 GL objects");
  // VTK's mappers keep a reference to the passes that last rendered them, so the own
  // passes above live (with their GL objects) until the mappers render again.
  winA->Render();
  winB->Render();
  shared->ReleaseGraphicsResources(nullptr);
  const GLNames baseB = TakeGLNameCensus(winB);
  winA->Render();
  const GLNames censusA = TakeGLNameCensus(winA);
  winB->Render();
  const GLNames censusB = TakeGLNameCensus(winB);
  Check(shared->GetNumberOfGLObjects() == 2 * per,
    "both renderers' GL objects after rendering both windows");
  winA->MakeCurrent();
  shared->ReleaseGraphicsResources(winB);
  Check(shared->GetNumberOfGLObjects() == per, "release for window B: window A's objects remain");
  CheckSameGLObjects(
    TakeGLNameCensus(winA), censusA, "window A's GL objects are untouched by window B's release");
  CheckSameGLObjects(
    TakeGLNameCensus(winB), baseB, "window B holds no GL object of the pass after its release");
  winA->Render();
  winB->Render();
  Check(CompareImages(imageA, CapturePixels(winA)).MaxAbsError == 0.0 &&
      CompareImages(imageB, CapturePixels(winB)).MaxAbsError == 0.0,
    "both windows render the same images after window B's release");
  // Re-created objects get new names: compare counts.
  Check(TakeGLNameCensus(winB).size() == censusB.size(),
    "window B holds as many GL objects as before its release");

  // 4. Renderer B deleted while window B lives; window A renders a new view.
  winB->RemoveRenderer(renB);
  renB = nullptr;
  Check(shared->GetNumberOfGLObjects() == per, "removing renderer B released its objects");
  renA->GetActiveCamera()->Azimuth(25.0);
  renA->ResetCameraClippingRange();
  winA->Render();
  const std::vector<float> turned = CapturePixels(winA);
  const ImageComparison turnedOwn =
    CompareImages(turned, RenderWithOwnPass(winA, renA, lights, shared));
  PrintComparison("window A after renderer B was deleted: shared vs own pass", turnedOwn);
  Check(turnedOwn.MaxAbsError == 0.0, "window A renders correctly after renderer B was deleted");
  winA->Render();

  // 5. Destroying window A releases the pass's objects for it.
  std::string first;
  const int errorsA = CountGLErrors(winA, &first);
  Check(errorsA == 0, "no GL error in window A (" + std::to_string(errorsA) + " " + first + ")");
  const int errorsB = CountGLErrors(winB, &first);
  Check(errorsB == 0, "no GL error in window B (" + std::to_string(errorsB) + " " + first + ")");
  winA = nullptr;
  Check(shared->GetNumberOfGLObjects() == 0, "destroying window A released its objects");
  Check(
    messages->Errors.empty() && messages->Warnings.empty(), "no warning or error from the pass");
  return CheckStatus();
}
