// SPDX-License-Identifier: BSD-3-Clause
// Lit lines and points under lights as users write them (inverse-square, no radius, so
// every light has a far field). VTK shades a line or point fragment with a normal the
// mapper makes up when the data has none (a line's: perpendicular to the line, in the
// plane of the line and the view direction; a point's: towards the camera), at the
// position of the line or point, not of the pixel. Checks, against brute force, that
// every pixel of
//  - a wireframe sphere (point normals), a polyline helix without normals 5 px wide, and
//    points 7 px wide without normals over the test scene's floor,
// is within its derived bound (cut tails + the far field's stated bound at the pixel's
// position and normal), with zero false negatives and no NaN pixel (CheckClusteredFrame),
// with the depth prepass and depth-aware clusters on (the default) and off.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkCellArray.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

/// A helix of one polyline around the test scene's sphere (no normals), and a ring of
/// vertices (no normals) on the floor.
vtkSmartPointer<vtkPolyData> MakeHelix(bool vertices)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  const int n = vertices ? 64 : 400;
  for (int i = 0; i < n; ++i)
  {
    const double t = static_cast<double>(i) / (n - 1);
    const double angle = (vertices ? 1.0 : 5.0) * 2.0 * vtkMath::Pi() * t;
    const double radius = vertices ? 2.4 : 2.0;
    points->InsertNextPoint(
      radius * std::cos(angle), vertices ? -0.95 : -0.9 + 2.4 * t, radius * std::sin(angle));
  }
  if (vertices)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      cells->InsertNextCell(1, &i);
    }
  }
  else
  {
    cells->InsertNextCell(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      cells->InsertCellPoint(i);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  if (vertices)
  {
    polyData->SetVerts(cells);
  }
  else
  {
    polyData->SetLines(cells);
  }
  return polyData;
}
}

int TestClusteredLightingLitLines(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 320, 240);
  vtkActorCollection* actors = ren->GetActors();
  actors->InitTraversal();
  actors->GetNextActor(); // the floor
  vtkActor* ball = actors->GetNextActor();
  ball->GetProperty()->SetRepresentationToWireframe();
  for (bool vertices : { false, true })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(MakeHelix(vertices));
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.4, 0.45, 0.5);
    actor->GetProperty()->SetSpecular(0.4);
    actor->GetProperty()->SetSpecularPower(20);
    actor->GetProperty()->SetLineWidth(5);
    actor->GetProperty()->SetPointSize(7);
    ren->AddActor(actor);
  }
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, 1000, 0.05, 3);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  pass->AutomaticDepthPrepassOff(); // both modes, each in every frame
  ren->SetPass(pass);
  rw->Render();
  Check(pass->GetNumberOfFarFieldLights() == 1000, "every light has a far field (no radius)");
  // Errors hide in saturated channels: the scene is lit below full brightness.
  std::size_t saturated = 0;
  const std::vector<float> brute = ClusteredLightingTest::CaptureBruteForce(pass, rw);
  for (float v : brute)
  {
    saturated += v >= 254.5f / 255.0f ? 1 : 0;
  }
  std::printf("brute force saturates %.2f%% of channels\n", 100.0 * saturated / brute.size());
  Check(saturated < brute.size() / 100, "under 1% of the channels saturate");

  for (bool depthAware : { true, false })
  {
    pass->SetDepthPrepass(depthAware);
    pass->SetDepthAwareClusters(depthAware);
    rw->Render();
    const std::string what = depthAware ? "lines and points, prepass and depth-aware clusters"
                                        : "lines and points, both off";
    ClusteredLightingTest::BruteForceCheck comparison;
    Check(ClusteredLightingTest::CheckClusteredFrame(
            pass, rw, ren, 1.4, what.c_str(), 0, &comparison) == 0,
      what + ": within the derived bound of brute force, zero false negatives, finite");
  }
  return ClusteredLightingTest::CheckStatus();
}
