// SPDX-License-Identifier: BSD-3-Clause
// A still frame must not redo work, and a moving camera must not rebuild shaders:
//  - 100 frames with a moving camera (and VTK's automatic clipping-range reset): no mapper
//    shader rebuild and no new program after the first frame; the lights are reassigned
//    every frame but their records are not re-uploaded;
//  - still frames of an unchanged scene skip light assignment entirely;
//  - changing one light re-uploads the light records once, without a shader rebuild;
//  - lights outside the view frustum cost nothing in the list pass (no quad is drawn);
//  - resizing the window reassigns; a new shader variant (first spot light) rebuilds once.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <random>

namespace
{
int Expect(bool condition, const char* what)
{
  std::printf("%s %s\n", condition ? "ok:  " : "FAIL:", what);
  return condition ? 0 : 1;
}
}

int TestClusteredLightingSkipWork(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(160, 120);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  renWin->AddRenderer(ren);
  vtkMapper* planeMapper = ClusteredLightingTest::AddFloor(ren, 4)->GetMapper();
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 1);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<ClusteredLightingTest::ShaderRecorder> programs;
  sphereMapper->AddObserver(vtkCommand::UpdateShaderEvent, programs);
  planeMapper->AddObserver(vtkCommand::UpdateShaderEvent, programs);
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetSpecular(0.4);
  ren->AddActor(sphereActor);

  vtkNew<vtkClusteredLightSet> lights;
  lights->SetNumberOfLights(500);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 500; ++i)
  {
    lights->SetPosition(i, -4 + 8 * U(rng), -4 + 8 * U(rng), 0.1 + 2 * U(rng));
    lights->SetAttenuation(i, 1.0, 0.0, 2000.0);
  }
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetPosition(0, -8, 6);
  camera->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();
  renWin->Render();

  int failures = 0;
  const int builds = pass->GetNumberOfShaderBuilds();
  const std::size_t programCount = programs->Programs.size();
  const int uploads = pass->GetNumberOfLightUploads();
  const int assignments = pass->GetNumberOfAssignmentUpdates();
  std::printf("first frame: %d shader builds, %zu programs, %d light uploads, %d assignments\n",
    builds, programCount, uploads, assignments);

  for (int f = 0; f < 100; ++f)
  {
    camera->Azimuth(3.6);
    camera->Elevation(0.2);
    ren->ResetCameraClippingRange();
    renWin->Render();
  }
  std::printf("after 100 moving frames: %d shader builds, %zu programs, %d light uploads, "
              "%d assignments\n",
    pass->GetNumberOfShaderBuilds(), programs->Programs.size(), pass->GetNumberOfLightUploads(),
    pass->GetNumberOfAssignmentUpdates());
  failures += Expect(pass->GetNumberOfShaderBuilds() == builds, "no shader rebuild in 100 frames");
  failures += Expect(programs->Programs.size() == programCount, "no new shader program");
  failures += Expect(pass->GetNumberOfLightUploads() == uploads, "light records not re-uploaded");
  failures += Expect(pass->GetNumberOfAssignmentUpdates() == assignments + 100,
    "lights reassigned once per moving frame");

  const int before = pass->GetNumberOfAssignmentUpdates();
  for (int f = 0; f < 10; ++f)
  {
    renWin->Render();
    failures +=
      f == 0 ? Expect(!pass->GetLastAssignmentUpdated(), "still frame skips assignment") : 0;
  }
  failures +=
    Expect(pass->GetNumberOfAssignmentUpdates() == before, "10 still frames: no assignment");

  lights->SetPosition(3, 0.5, 0.5, 0.5);
  renWin->Render();
  failures += Expect(pass->GetNumberOfLightUploads() == uploads + 1, "moved light: one upload");
  failures += Expect(pass->GetNumberOfAssignmentUpdates() == before + 1, "and one assignment");
  failures += Expect(pass->GetNumberOfShaderBuilds() == builds, "and no shader rebuild");

  // Lights behind the camera cost nothing in the list pass. With a far field the near radii
  // of all lights depend on how many there are (NearFieldBudget), so this part compares
  // list passes with the far field off, where each light's radius is its own.
  pass->FarFieldOff();
  renWin->Render();
  const int quads = vtkClusteredLightingInspector(pass).GetFrame(ren).NumberOfQuads;
  const int assigned = pass->GetNumberOfAssignedLights();
  const double* eye = camera->GetPosition();
  const double* dir = camera->GetDirectionOfProjection();
  const vtkIdType first = lights->GetNumberOfLights();
  for (int i = 0; i < 1000; ++i)
  {
    const double back = 3.0 + 5.0 * U(rng);
    const vtkIdType id = lights->AddLight(eye[0] - back * dir[0] + U(rng) - 0.5,
      eye[1] - back * dir[1] + U(rng) - 0.5, eye[2] - back * dir[2] + U(rng) - 0.5);
    lights->SetAttenuation(id, 1.0, 0.0, 2000.0); // radius 0.7, well behind the camera
  }
  renWin->Render();
  std::printf("with 1000 lights behind the camera: %d clustered, %d assigned (was %d), %d quads "
              "(was %d)\n",
    pass->GetNumberOfClusteredLights(), pass->GetNumberOfAssignedLights(), assigned,
    vtkClusteredLightingInspector(pass).GetFrame(ren).NumberOfQuads, quads);
  failures += Expect(pass->GetNumberOfClusteredLights() == static_cast<int>(first) + 1000,
    "the lights behind the camera are clustered (kept)");
  failures += Expect(pass->GetNumberOfAssignedLights() == assigned &&
      vtkClusteredLightingInspector(pass).GetFrame(ren).NumberOfQuads == quads,
    "but draw nothing in the list pass");
  failures += Expect(
    ClusteredLightingTest::CheckAssignment(pass, ren, "with hidden lights").FalseNegatives == 0,
    "assignment still complete");

  // Resize: reassign. New variant: rebuild once, then stable.
  const int beforeResize = pass->GetNumberOfAssignmentUpdates();
  renWin->SetSize(200, 100);
  renWin->Render();
  failures += Expect(pass->GetNumberOfAssignmentUpdates() == beforeResize + 1, "resize reassigns");
  const int buildsBeforeSpot = pass->GetNumberOfShaderBuilds();
  lights->SetSpot(0, 0, 0, -1, 30, 1);
  renWin->Render();
  const int buildsWithSpot = pass->GetNumberOfShaderBuilds();
  renWin->Render();
  camera->Azimuth(10);
  renWin->Render();
  failures += Expect(buildsWithSpot > buildsBeforeSpot, "first spot light rebuilds the shaders");
  failures += Expect(pass->GetNumberOfShaderBuilds() == buildsWithSpot, "once");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
