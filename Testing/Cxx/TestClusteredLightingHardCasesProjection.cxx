// SPDX-License-Identifier: BSD-3-Clause
// Hard cases of projections and viewports, each checked by RunHardCase (zero false
// negatives, brute force within the derived bound, no NaN/Inf, something lit):
//  parallel projection; off-axis projection (SetWindowCenter); both eyes of stereo
//  rendering; a renderer in a sub-rectangle of the window; two renderers in one window
//  sharing one pass; far/near ratios of 1.5, 1e4 and 1e6, and VTK's automatic clipping-range
//  reset every frame while the camera moves; a scene around (1e6, 1e6, 1e6).
#include "ClusteredLightingHardCase.h"

using namespace ClusteredLightingTest;

namespace
{
void DefaultCamera(vtkCamera* cam, const double offset[3] = nullptr)
{
  const double o[3] = { offset ? offset[0] : 0.0, offset ? offset[1] : 0.0,
    offset ? offset[2] : 0.0 };
  cam->SetParallelProjection(0);
  cam->SetWindowCenter(0, 0);
  cam->SetPosition(o[0] + 0.3, o[1] + 0.2, o[2] + 3.0);
  cam->SetFocalPoint(o[0], o[1], o[2] - 2.0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(60);
  cam->SetClippingRange(0.5, 9.0);
}
}

int TestClusteredLightingHardCasesProjection(int, char*[])
{
  int failures = 0;
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  SetUpRoomWindow(renWin, ren);
  vtkNew<vtkClusteredLightSet> lights;
  MakeRoomLights(lights, 300, 2.0, 17);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkCamera* cam = ren->GetActiveCamera();
  DefaultCamera(cam);
  failures += RunHardCase(pass, renWin, ren, "perspective (reference case)");

  cam->SetParallelProjection(1);
  cam->SetParallelScale(3.0);
  failures += RunHardCase(pass, renWin, ren, "parallel projection");
  DefaultCamera(cam);

  cam->SetWindowCenter(0.6, -0.4);
  failures += RunHardCase(pass, renWin, ren, "off-axis projection (SetWindowCenter)");
  DefaultCamera(cam);

  renWin->StereoCapableWindowOn();
  renWin->StereoRenderOn();
  cam->SetEyeAngle(6.0); // also marks the camera modified, so VTK recomputes its matrices
  renWin->SetStereoTypeToLeft();
  failures += RunHardCase(pass, renWin, ren, "stereo, left eye");
  const std::vector<float> leftEye = CapturePixels(renWin);
  const glm::dmat4 leftView = vtkClusteredLightingInspector(pass).GetFrame(ren).VCDC;

  renWin->SetStereoTypeToRight();
  failures += RunHardCase(pass, renWin, ren, "stereo, right eye");
  const std::vector<float> rightEye = CapturePixels(renWin);

  const double imageDifference = CompareImages(leftEye, rightEye).MaxAbsError;
  const double shear =
    std::abs(leftView[2][0] - vtkClusteredLightingInspector(pass).GetFrame(ren).VCDC[2][0]);
  std::printf(
    "eyes: image difference %.3f, projection shear difference %.4f\n", imageDifference, shear);
  // Different views: a projection shear, and images that differ beyond 8-bit rounding.
  const bool eyesDiffer = imageDifference > 2.0 / 255.0 && shear > 1e-3;
  std::printf("[%s] the two eyes are different views\n", eyesDiffer ? "PASS" : "FAIL");
  failures += eyesDiffer ? 0 : 1;
  renWin->StereoRenderOff();
  DefaultCamera(cam);

  ren->SetViewport(0.15, 0.2, 0.85, 0.9);
  failures += RunHardCase(pass, renWin, ren, "renderer in a sub-rectangle");

  // Two renderers, one pass.
  ren->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkRenderer> ren2;
  ren2->AutomaticLightCreationOff();
  ren2->SetViewport(0.5, 0.0, 1.0, 1.0);
  AddRoom(ren2);
  ren2->SetPass(pass);
  DefaultCamera(ren2->GetActiveCamera());
  ren2->GetActiveCamera()->Azimuth(35);
  renWin->AddRenderer(ren2);
  failures += RunHardCase(pass, renWin, ren, "two renderers sharing a pass: left");
  failures += RunHardCase(pass, renWin, ren2, "two renderers sharing a pass: right");
  renWin->RemoveRenderer(ren2);
  ren->SetViewport(0.0, 0.0, 1.0, 1.0);

  // Clipping ranges.
  cam->SetClippingRange(5.0, 7.5); // far / near = 1.5
  failures += RunHardCase(pass, renWin, ren, "far/near = 1.5");
  cam->SetClippingRange(8e-4, 8.2); // ~1e4
  failures += RunHardCase(pass, renWin, ren, "far/near = 1e4");
  cam->SetClippingRange(8.2e-6, 8.2); // 1e6
  failures += RunHardCase(pass, renWin, ren, "far/near = 1e6");
  for (int f = 0; f < 3; ++f)
  {
    cam->Azimuth(25);
    cam->Elevation(-10);
    cam->OrthogonalizeViewUp();
    ren->ResetCameraClippingRange();
    failures += RunHardCase(
      pass, renWin, ren, "automatic clipping range, moving camera, frame " + std::to_string(f));
  }
  DefaultCamera(cam);

  // The same scene around (1e6, 1e6, 1e6).
  vtkNew<vtkRenderer> far;
  far->AutomaticLightCreationOff();
  const double offset[3] = { 1e6, 1e6, 1e6 };
  AddRoom(far, 10.0, offset);
  vtkNew<vtkClusteredLightSet> farLights;
  MakeRoomLights(farLights, 300, 2.0, 17, 10.0, offset);
  vtkNew<vtkClusteredLightingPass> farPass;
  farPass->AddLightSet(farLights);
  far->SetPass(farPass);
  DefaultCamera(far->GetActiveCamera(), offset);
  renWin->RemoveRenderer(ren);
  renWin->AddRenderer(far);
  failures += RunHardCase(farPass, renWin, far, "scene around (1e6, 1e6, 1e6)");
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
