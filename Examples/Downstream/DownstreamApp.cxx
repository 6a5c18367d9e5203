// SPDX-License-Identifier: BSD-3-Clause
// The smallest application of an installed ClusteredLighting: a sphere on a floor lit by
// 12 point lights fed from a VTK pipeline (a vtkPointSource), rendered offscreen once.
// Exits with failure unless the window is an OpenGL one (vtk_module_autoinit worked) and
// the pass clustered every light. Built by scripts/check-install.sh.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlaneSource.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdio>
#include <cstdlib>

namespace
{
void AddActor(vtkRenderer* ren, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ren->AddActor(actor);
}
}

int main()
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(160, 120);
  renWin->SetOffScreenRendering(1);
  vtkNew<vtkRenderer> ren;
  renWin->AddRenderer(ren);
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-2, -2, 0);
  floor->SetPoint1(2, -2, 0);
  floor->SetPoint2(-2, 2, 0);
  AddActor(ren, floor);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 0.5);
  sphere->SetRadius(0.5);
  AddActor(ren, sphere);

  const int numberOfLights = 12;
  vtkNew<vtkPointSource> points;
  points->SetNumberOfPoints(numberOfLights);
  points->SetCenter(0, 0, 0.6);
  points->SetRadius(1.5);
  vtkNew<vtkClusteredLightSet> lights;
  lights->SetInputConnection(points->GetOutputPort());
  lights->SetDefaultAttenuation(1.0, 0.0, 10.0); // no arrays: every light gets the defaults

  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  ren->GetActiveCamera()->SetPosition(0, -4, 4);
  ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();
  renWin->Render();

  const bool opengl = vtkOpenGLRenderWindow::SafeDownCast(renWin) != nullptr;
  std::printf("%s: %d of %d lights clustered, %d assigned\n", renWin->GetClassName(),
    pass->GetNumberOfClusteredLights(), numberOfLights, pass->GetNumberOfAssignedLights());
  if (!opengl || pass->GetNumberOfClusteredLights() != numberOfLights ||
    pass->GetNumberOfAssignedLights() == 0)
  {
    std::fprintf(stderr, "downstream check failed\n");
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
