// SPDX-License-Identifier: BSD-3-Clause
// Light counts and limits:
//  - 16,384 lights render correctly: zero false negatives against the CPU reference, and
//    clustered vs brute force within the derived cutoff tolerance, no NaN pixel;
//  - the documented maximum (GetMaximumNumberOfLights for the context's
//    GL_MAX_TEXTURE_SIZE) is what the pass enforces: past it on a grid too fine for the
//    light count, the pass renders every light on a smaller grid that holds them (one
//    warning naming the limit and the grid chosen; the frame passes the same checks);
//    only when no grid holds them (a tiny MaximumTextureSize) does it report an error
//    naming the limit, with no crash and no light silently dropped from a rendered frame;
//    going back to a valid grid renders them again.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"

#include <random>

int TestClusteredLightingLimits(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(200, 150);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  renWin->AddRenderer(ren);
  ClusteredLightingTest::AddFloor(ren, 5);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.2);
  sphere->SetCenter(0, 0, 1.0);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  ren->AddActor(sphereActor);

  const int n = 16384;
  vtkNew<vtkClusteredLightSet> lights;
  lights->SetNumberOfLights(n);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < n; ++i)
  {
    lights->SetPosition(i, -5 + 10 * U(rng), -5 + 10 * U(rng), 0.05 + 2.5 * U(rng));
    lights->SetColor(i, U(rng), U(rng), U(rng));
    lights->SetIntensity(i, 0.5);
    lights->SetAttenuation(i, 1.0, 0.0, 3000.0);
  }
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  ren->GetActiveCamera()->SetPosition(0, -9, 7);
  ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();
  renWin->Render();

  int status = EXIT_SUCCESS;
  const int maxTexture =
    vtkTextureObject::GetMaximumTextureSize(vtkOpenGLRenderWindow::SafeDownCast(renWin));
  const vtkTypeInt64 maxLights = vtkClusteredLightingPass::GetMaximumNumberOfLights(
    pass->GetTilesX(), pass->GetTilesY(), pass->GetSlices(), maxTexture);
  std::printf("GL_MAX_TEXTURE_SIZE %d: the default %dx%dx%d grid holds %lld lights\n", maxTexture,
    pass->GetTilesX(), pass->GetTilesY(), pass->GetSlices(), static_cast<long long>(maxLights));
  std::printf("%d lights: list %.1f MiB, master %.2f MiB, light records %.2f MiB\n",
    pass->GetNumberOfClusteredLights(), pass->GetListTextureBytes() / 1048576.0,
    pass->GetMasterTextureBytes() / 1048576.0, pass->GetLightBufferBytes() / 1048576.0);
  if (pass->GetNumberOfClusteredLights() != n || pass->GetNumberOfAssignedLights() == 0)
  {
    status = EXIT_FAILURE;
  }
  if (ClusteredLightingTest::CheckClusteredFrame(pass, renWin, ren, 1.0, "16384 lights") != 0)
  {
    status = EXIT_FAILURE;
  }

  // A grid that cannot hold 16,384 lights: 256 x 256 tiles x 64 slices. Every light is
  // still rendered, on a smaller grid, and the user is told once.
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  pass->SetTilesX(256);
  pass->SetTilesY(256);
  pass->SetSlices(64);
  const vtkTypeInt64 fineMax =
    vtkClusteredLightingPass::GetMaximumNumberOfLights(256, 256, 64, maxTexture);
  renWin->Render();
  renWin->Render(); // reported once, not every frame
  const std::string warning = messages->Warnings.empty() ? "" : messages->Warnings[0];
  const int* used = pass->GetClusterGridInUse();
  std::printf("warned %zu time(s), %zu error(s): %s\n", messages->Warnings.size(),
    messages->Errors.size(), warning.c_str());
  std::printf("grid in use: %dx%dx%d\n", used[0], used[1], used[2]);
  const std::string expected = "holds at most " + std::to_string(fineMax) + " lights";
  const std::string chosen = "rendered on a " + std::to_string(used[0]) + "x" +
    std::to_string(used[1]) + "x" + std::to_string(used[2]) + " grid";
  if (messages->Warnings.size() != 1 || !messages->Errors.empty() ||
    warning.find(expected) == std::string::npos || warning.find(chosen) == std::string::npos ||
    warning.find("16384 lights") == std::string::npos)
  {
    std::printf(
      "expected one warning containing \"%s\" and \"%s\"\n", expected.c_str(), chosen.c_str());
    status = EXIT_FAILURE;
  }
  if (used[0] > 256 || used[1] > 256 || used[2] > 64 ||
    used[0] * used[1] * used[2] >= 256 * 256 * 64 ||
    vtkClusteredLightingPass::GetMaximumNumberOfLights(used[0], used[1], used[2], maxTexture) < n)
  {
    std::printf("the grid in use must be smaller than 256x256x64 and hold %d lights\n", n);
    status = EXIT_FAILURE;
  }
  if (pass->GetNumberOfAssignedLights() == 0 ||
    ClusteredLightingTest::CheckClusteredFrame(pass, renWin, ren, 1.0, "past the grid's limit") !=
      0)
  {
    status = EXIT_FAILURE;
  }

  // No grid holds them: 16,384 lights with textures of at most 16 texels a side (a 1x1x1
  // grid then holds 16 x min(16, 32) x 32 = 8,192). An error naming the limit, nothing lit
  // by halves.
  messages->Clear();
  pass->SetMaximumTextureSize(16);
  renWin->Render();
  renWin->Render();
  const std::string error = messages->Errors.empty() ? "" : messages->Errors[0];
  std::printf("error reported %zu time(s): %s\n", messages->Errors.size(), error.c_str());
  if (messages->Errors.size() != 1 ||
    error.find("no cluster grid holds 16384 lights") == std::string::npos ||
    error.find("1x1x1 grid holds at most 8192") == std::string::npos ||
    pass->GetNumberOfAssignedLights() != 0)
  {
    std::printf("expected one error naming the 8192-light limit, and no light assigned\n");
    status = EXIT_FAILURE;
  }
  pass->SetMaximumTextureSize(0);

  // Back to a valid grid: the lights render again and the assignment is exact.
  pass->SetTilesX(32);
  pass->SetTilesY(16);
  pass->SetSlices(32);
  renWin->Render();
  if (pass->GetNumberOfAssignedLights() == 0 ||
    ClusteredLightingTest::CheckAssignment(pass, ren, "after recovery").FalseNegatives != 0)
  {
    status = EXIT_FAILURE;
  }
  return status;
}
