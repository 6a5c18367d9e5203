// SPDX-License-Identifier: BSD-3-Clause
// Hard cases of window sizes and light counts, each checked by RunHardCase (zero false
// negatives, brute force within the derived bound, no NaN/Inf, something lit):
//  window resized between frames; a 1x1 window; very wide and very tall windows;
//  light counts 0, 1, 31, 32, 33, 1023, 1024, 1025 (batch and master-texel boundaries),
//  and exactly the maximum a grid holds (with a texture-size cap so that the maximum is
//  small enough to check against brute force), then one more light: every light still
//  rendered on a smaller grid, one warning naming the limit, and the grid recovers.
#include "ClusteredLightingHardCase.h"

using namespace ClusteredLightingTest;

int TestClusteredLightingHardCasesCounts(int, char*[])
{
  int failures = 0;
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  SetUpRoomWindow(renWin, ren);
  // Lights in the part of the room the camera sees (around the central sphere), so that
  // every count case lights something.
  const double visible[3] = { 0.0, 0.0, -2.75 };
  const double visibleSize = 3.5;
  vtkNew<vtkClusteredLightSet> lights;
  MakeRoomLights(lights, 400, 2.0, 23, visibleSize, visible);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0.3, 0.2, 3.0);
  cam->SetFocalPoint(0, 0, -2);
  cam->SetViewAngle(60);
  cam->SetClippingRange(0.5, 9.0);

  failures += RunHardCase(pass, renWin, ren, "160x120 before resize");
  renWin->SetSize(211, 97);
  failures += RunHardCase(pass, renWin, ren, "resized to 211x97 between frames");
  renWin->SetSize(1, 1);
  failures += RunHardCase(pass, renWin, ren, "1x1 window", 0);
  renWin->SetSize(1200, 6);
  failures += RunHardCase(pass, renWin, ren, "very wide window 1200x6");
  renWin->SetSize(6, 900);
  failures += RunHardCase(pass, renWin, ren, "very tall window 6x900");
  renWin->SetSize(160, 120);

  for (int n : { 0, 1, 31, 32, 33, 1023, 1024, 1025 })
  {
    MakeRoomLights(lights, n, n > 100 ? 1.2 : 3.0, 29, visibleSize, visible);
    failures += RunHardCase(pass, renWin, ren, std::to_string(n) + " lights", n > 0 ? 1 : 0);
    if (pass->GetNumberOfClusteredLights() != n)
    {
      std::printf(
        "FAIL: %d lights clustered, expected %d\n", pass->GetNumberOfClusteredLights(), n);
      ++failures;
    }
  }

  // The maximum: an 8x4x8 grid with textures of at most 256 texels a side holds
  // 32 * floor(256 / 4) * floor(256 / (8 * 8)) = 8192 lights.
  pass->SetTilesX(8);
  pass->SetTilesY(4);
  pass->SetSlices(8);
  pass->SetMaximumTextureSize(256);
  const vtkTypeInt64 maxLights = vtkClusteredLightingPass::GetMaximumNumberOfLights(8, 4, 8, 256);
  MakeRoomLights(lights, static_cast<int>(maxLights), 0.8, 31, visibleSize, visible);
  failures +=
    RunHardCase(pass, renWin, ren, "the maximum: " + std::to_string(maxLights) + " lights");
  // One light more: every light is still rendered, on a smaller grid that holds them,
  // with one warning naming the limit; the frame passes the same checks.
  vtkNew<MessageCollector> messages;
  messages->Watch(pass);
  MakeRoomLights(lights, static_cast<int>(maxLights) + 1, 0.8, 31, visibleSize, visible);
  renWin->Render();
  renWin->Render(); // reported once, not every frame
  const int* used = pass->GetClusterGridInUse();
  const bool reported = messages->Errors.empty() && messages->Warnings.size() == 1 &&
    messages->Warnings[0].find("holds at most " + std::to_string(maxLights)) != std::string::npos &&
    used[0] * used[1] * used[2] < 8 * 4 * 8 &&
    pass->GetNumberOfClusteredLights() == static_cast<int>(maxLights) + 1;
  std::printf("[%s] maximum + 1 lights: %zu warning(s), %zu error(s), grid %dx%dx%d, %s\n",
    reported ? "PASS" : "FAIL", messages->Warnings.size(), messages->Errors.size(), used[0],
    used[1], used[2],
    messages->Warnings.empty() ? "(no warning)" : messages->Warnings.back().c_str());
  failures += reported ? 0 : 1;
  // (RunHardCase's reference frame has one light, which fits: the episode ends and the
  // warning comes again after it, as it should.)
  failures += RunHardCase(pass, renWin, ren, "maximum + 1 lights, on a smaller grid");
  MakeRoomLights(lights, static_cast<int>(maxLights), 0.8, 31, visibleSize, visible);
  failures += RunHardCase(pass, renWin, ren, "back to the maximum");
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
