// SPDX-License-Identifier: BSD-3-Clause
// An existing app with many vtkLights gains without code changes: 300 positional
// vtkLights (point and spot) in the renderer, plus a headlight and a directional light.
// Checks that
//  - the pass clusters exactly the 300 positional lights, and VTK's own per-light shader
//    code is generated only for the 2 others (stock VTK 9.1 needs minutes to compile
//    hundreds of lights and cannot link about 1,090);
//  - the renderer's light collection is intact and in order after each render;
//  - clustered matches brute force within the derived cutoff tolerance, and the assignment
//    has zero false negatives;
//  - the headlight and the directional light still light the scene when the positional
//    lights are switched off (stock behaviour), and a light switched off is not clustered.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <random>

int TestClusteredLightingRendererLights(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(300, 240);
  renWin->SetMultiSamples(0);
  vtkNew<vtkOpenGLRenderer> ren;
  renWin->AddRenderer(ren);

  ClusteredLightingTest::AddFloor(ren, 3, 8);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetCenter(0, 0, 0.5);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(40);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetSpecular(0.5);
  sphereActor->GetProperty()->SetSpecularPower(30);
  ren->AddActor(sphereActor);

  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.15);
  ren->AddLight(headlight);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(1, 1, 3);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(0.1);
  ren->AddLight(sun);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<vtkSmartPointer<vtkLight>> positional;
  for (int i = 0; i < 300; ++i)
  {
    vtkNew<vtkLight> l;
    l->SetLightTypeToSceneLight();
    l->SetPositional(true);
    l->SetPosition(-3 + 6 * U(rng), -3 + 6 * U(rng), 0.1 + 1.5 * U(rng));
    l->SetColor(0.4 + 0.6 * U(rng), 0.4 + 0.6 * U(rng), 0.4 + 0.6 * U(rng));
    l->SetAttenuationValues(1.0, 0.0, 600.0);
    if (i % 5 == 0)
    {
      l->SetFocalPoint(l->GetPosition()[0], l->GetPosition()[1], 0.0);
      l->SetConeAngle(35.0);
      l->SetExponent(2.0);
    }
    else
    {
      l->SetConeAngle(180.0);
    }
    ren->AddLight(l);
    positional.emplace_back(l);
  }
  vtkNew<vtkLight> off;
  off->SetPositional(true);
  off->SwitchOff();
  ren->AddLight(off);

  std::vector<vtkLight*> order;
  {
    vtkCollectionSimpleIterator it;
    vtkLight* l;
    for (ren->GetLights()->InitTraversal(it); (l = ren->GetLights()->GetNextLight(it));)
    {
      order.push_back(l);
    }
  }

  vtkNew<vtkClusteredLightingPass> pass;
  ren->SetPass(pass);
  ren->GetActiveCamera()->SetPosition(0, -6, 5);
  ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();
  renWin->Render();

  int status = EXIT_SUCCESS;
  std::printf("clustered %d lights (%d spots); VTK's own lighting code for %d lights "
              "(complexity %d)\n",
    pass->GetNumberOfClusteredLights(), pass->GetNumberOfSpotLights(), ren->GetLightingCount(),
    ren->GetLightingComplexity());
  if (pass->GetNumberOfClusteredLights() != 300 || pass->GetNumberOfSpotLights() != 60)
  {
    status = EXIT_FAILURE;
  }
  if (ren->GetLightingCount() != 2)
  {
    std::printf("VTK generated lighting code for %d lights, expected 2\n", ren->GetLightingCount());
    status = EXIT_FAILURE;
  }
  auto checkOrder = [&]()
  {
    std::vector<vtkLight*> now;
    vtkCollectionSimpleIterator it;
    vtkLight* l;
    for (ren->GetLights()->InitTraversal(it); (l = ren->GetLights()->GetNextLight(it));)
    {
      now.push_back(l);
    }
    if (now != order)
    {
      std::printf("the renderer's light collection changed\n");
      status = EXIT_FAILURE;
    }
  };
  checkOrder();
  if (ClusteredLightingTest::CheckClusteredFrame(pass, renWin, ren, 1.5, "renderer lights") != 0)
  {
    status = EXIT_FAILURE;
  }
  checkOrder();

  // Positional lights off: the headlight and the directional light alone, as in stock VTK.
  for (auto& l : positional)
  {
    l->SwitchOff();
  }
  renWin->Render();
  const std::vector<float> withPass = ClusteredLightingTest::CapturePixels(renWin);
  if (pass->GetNumberOfClusteredLights() != 0)
  {
    std::printf("switched-off lights were clustered\n");
    status = EXIT_FAILURE;
  }
  ren->SetPass(nullptr);
  renWin->Render();
  const std::vector<float> stock = ClusteredLightingTest::CapturePixels(renWin);
  const auto cmp = ClusteredLightingTest::CompareImages(withPass, stock);
  ClusteredLightingTest::PrintComparison("headlight + directional, pass vs stock", cmp);
  if (cmp.MaxAbsError > 1.5 / 255.0)
  {
    status = EXIT_FAILURE;
  }
  checkOrder();
  return status;
}
