// SPDX-License-Identifier: BSD-3-Clause
// Sanitizer builds only (scripts/check-machine.sh): leaks a vtkClusteredLightingPass on
// purpose after rendering with it, and the check passes only if LeakSanitizer reports that
// leak with its allocation in vtkClusteredLightingPass::New. This shows that the run's
// options, the suppressions file (lsan.supp) and the driver pin cannot hide a leak of
// our own code, even one whose stack goes through VTK and Mesa.
#include "vtkActor.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

int main()
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(64, 48);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  renWin->AddRenderer(ren);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ren->AddActor(actor);
  vtkNew<vtkClusteredLightSet> lights;
  for (int i = 0; i < 40; ++i)
  {
    const vtkIdType id = lights->AddLight(0.1 * i - 2.0, 0.0, 1.0);
    lights->SetAttenuation(id, 1.0, 0.0, 4.0);
  }

  vtkClusteredLightingPass* leaked = vtkClusteredLightingPass::New();
  leaked->AddLightSet(lights);
  ren->SetPass(leaked);
  renWin->Render();
  ren->SetPass(nullptr);
  // Deliberately no leaked->Delete().
  return leaked->GetNumberOfClusteredLights() == 40 ? 0 : 1;
}
