// SPDX-License-Identifier: BSD-3-Clause
// Regression image (b): 4,096 point lights over the Stanford bunny (69,666 triangles) on a
// floor, with VTK's attenuation and the pass's default accuracy. Checks, for this frame:
//  - zero false negatives of the GPU list/master textures against the double-precision
//    CPU reference (false-positive rate reported);
//  - clustered vs brute force at every pixel within the tolerance derived from the
//    cutoff (sum of the cut tails at the pixel's surface point, computed on the CPU);
//  - no NaN/Inf pixel;
//  - the image against the committed baseline.
#include "ClusteredLightingScenes.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkCamera.h"
#include "vtkRegressionTestImage.h"

int TestClusteredLightingManyLights(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> bunny = ClusteredLightingScenes::LoadBunny(0);
  if (!bunny)
  {
    std::printf("bunny mesh missing: %s\n", ClusteredLightingScenes::BunnyPath().c_str());
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(400, 300);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.02, 0.02, 0.03);
  ren->AutomaticLightCreationOff();
  renWin->AddRenderer(ren);
  ClusteredLightingScenes::AddBunnyScene(ren, bunny);

  // Lights hover 0.005 to 0.05 above the surfaces: each makes a small, bright spot.
  // VTK attenuation (1, 0, k) with k such that the influence radius at the default
  // cutoff is 0.4.
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingScenes::LightParameters params;
  params.Intensity = 2.0;
  params.TargetRadius = 0.4;
  ClusteredLightingScenes::MakeSurfaceLights(lights, 4096, bunny, 0.005, 0.05, params, 7);

  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  ren->GetActiveCamera()->SetPosition(0.0, 1.6, 4.6);
  ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  ren->GetActiveCamera()->SetViewAngle(40.0);
  ren->ResetCameraClippingRange();
  renWin->Render();

  int status = EXIT_SUCCESS;
  if (pass->GetNumberOfClusteredLights() != 4096)
  {
    std::printf("expected 4096 clustered lights, got %d\n", pass->GetNumberOfClusteredLights());
    status = EXIT_FAILURE;
  }
  // Bunny: Diffuse 1 + Specular 0.3; floor: Diffuse 1.
  if (ClusteredLightingTest::CheckClusteredFrame(pass, renWin, ren, 1.3, "4096 lights") != 0)
  {
    status = EXIT_FAILURE;
  }

  renWin->Render();
  return ClusteredLightingTest::FinishImageTest(argc, argv, renWin, status);
}
