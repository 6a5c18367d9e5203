// SPDX-License-Identifier: BSD-3-Clause
// Regression image (a): a small scene lit by 4 point lights and 1 spot light. Rendered by
// stock VTK and with vtkClusteredLightingPass; the two must match within the cutoff
// (checked pixel by pixel), and the pass's image must match the committed baseline.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkSphereSource.h"

int TestClusteredLightingMatchesStock(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(400, 300);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.1, 0.1, 0.12);
  renWin->AddRenderer(ren);

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4, -1, -4);
  plane->SetPoint1(4, -1, -4);
  plane->SetPoint2(-4, -1, 4);
  plane->SetResolution(64, 64);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> floor;
  floor->SetMapper(planeMapper);
  floor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  ren->AddActor(floor);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(sphereMapper);
  ball->SetScale(1.6);
  ball->GetProperty()->SetColor(0.8, 0.6, 0.4);
  ball->GetProperty()->SetSpecular(0.5);
  ball->GetProperty()->SetSpecularPower(30);
  ren->AddActor(ball);

  const double positions[4][3] = { { -2, 0.5, 1 }, { 2, 0.2, 1.5 }, { 0, 1.5, -2 },
    { 1.5, -0.5, 2.5 } };
  const double colors[4][3] = { { 1, 0.3, 0.3 }, { 0.3, 1, 0.3 }, { 0.3, 0.4, 1 }, { 1, 1, 0.5 } };
  for (int i = 0; i < 4; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetPositional(true);
    light->SetConeAngle(180);
    light->SetPosition(positions[i][0], positions[i][1], positions[i][2]);
    light->SetColor(colors[i][0], colors[i][1], colors[i][2]);
    light->SetAttenuationValues(0.2, 0.3, 0.4);
    light->SetLightTypeToSceneLight();
    ren->AddLight(light);
  }
  vtkNew<vtkLight> spot;
  spot->SetPositional(true);
  spot->SetPosition(0, 3.5, 1.5);
  spot->SetFocalPoint(0.3, -1, 0.5);
  spot->SetConeAngle(25);
  spot->SetExponent(2);
  spot->SetAttenuationValues(0.5, 0.0, 0.1);
  spot->SetColor(1, 1, 1);
  spot->SetIntensity(1.5);
  spot->SetLightTypeToSceneLight();
  ren->AddLight(spot);

  ren->GetActiveCamera()->SetPosition(0, 3, 9);
  ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();

  vtkNew<vtkClusteredLightingPass> pass;
  std::vector<float> stock, clustered;
  ClusteredLightingTest::RenderStockThenClustered(renWin, ren, pass, stock, clustered);

  int status = EXIT_SUCCESS;
  if (pass->GetNumberOfClusteredLights() != 5 || pass->GetNumberOfSpotLights() != 1)
  {
    std::printf("expected 5 clustered lights (1 spot), got %d (%d)\n",
      pass->GetNumberOfClusteredLights(), pass->GetNumberOfSpotLights());
    status = EXIT_FAILURE;
  }
  const auto cmp = ClusteredLightingTest::CompareImages(stock, clustered);
  ClusteredLightingTest::PrintComparison("clustered vs stock", cmp);
  // Each light is cut where it falls below 1/1024: at most 5 such tails per pixel,
  // times Diffuse + Specular <= 1.5, plus one step of 8-bit rounding.
  if (cmp.MaxAbsError > 5 * 1.5 / 1024.0 + 1.0 / 255.0)
  {
    std::printf("clustered image differs from stock VTK beyond the cutoff tolerance\n");
    status = EXIT_FAILURE;
  }
  const auto assignment = ClusteredLightingTest::CheckAssignment(pass, ren, "assignment");
  if (assignment.FalseNegatives != 0 || assignment.MasterMismatches != 0)
  {
    status = EXIT_FAILURE;
  }

  return ClusteredLightingTest::FinishImageTest(argc, argv, renWin, status);
}
