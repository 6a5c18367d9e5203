// SPDX-License-Identifier: BSD-3-Clause
// Drop-in fidelity: setting the pass must not change how VTK's own lights look.
//
// The lights the pass leaves to VTK (headlight, light kit, directional and camera lights)
// must be shaded exactly as stock VTK shades them without the pass, for Phong and PBR
// actors, whatever else the renderer holds. VTK picks its lighting code from the whole
// light collection (vtkOpenGLRenderer::UpdateLights): with a positional light anywhere it
// generates its full code (complexity 3), whose headlight specular is reflect()-based
// Phong, where a lone headlight gets pow(N.z, power) (complexity 1); PBR directional lights
// differ between complexities 2 and 3 too. The pass hides the clustered lights from VTK, so
// it must keep the complexity VTK would have picked.
//
// Each case is compared with stock VTK itself (no pass), not with brute force. The
// clustered lights have zero intensity, so that only VTK's own lights show and the images
// must agree to float rounding: at most one 8-bit step. Cases: VTK lights {headlight,
// light kit, headlight + directional scene light, camera light} x clustered lights {16
// positional vtkLights of the renderer, a vtkClusteredLightSet}, on Phong actors with
// Specular 0.3 and power 20 and on a PBR actor.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <cstdio>
#include <functional>
#include <string>

namespace
{
void AddSphere(vtkRenderer* ren, double x, bool pbr)
{
  vtkNew<vtkSphereSource> s;
  s->SetCenter(x, 0.0, 0.0);
  s->SetRadius(0.9);
  s->SetThetaResolution(64);
  s->SetPhiResolution(64);
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputConnection(s->GetOutputPort());
  vtkNew<vtkActor> a;
  a->SetMapper(m);
  vtkProperty* p = a->GetProperty();
  p->SetColor(0.9, 0.75, 0.6);
  if (pbr)
  {
    p->SetInterpolationToPBR();
    p->SetRoughness(0.35);
    p->SetMetallic(0.2);
  }
  else
  {
    p->SetSpecular(0.3);
    p->SetSpecularPower(20);
  }
  ren->AddActor(a);
}

/// The stock lights of a case, added to the renderer.
struct StockCase
{
  const char* Name;
  std::function<void(vtkRenderer*)> Add;
};

void AddHeadlight(vtkRenderer* ren)
{
  vtkNew<vtkLight> h;
  h->SetLightTypeToHeadlight();
  ren->AddLight(h);
}
}

int TestClusteredLightingStockLights(int, char*[])
{
  const StockCase stockCases[] = {
    { "headlight", AddHeadlight },
    { "light kit",
      [](vtkRenderer* ren)
      {
        vtkNew<vtkLightKit> kit;
        kit->AddLightsToRenderer(ren);
      } },
    { "headlight + directional",
      [](vtkRenderer* ren)
      {
        AddHeadlight(ren);
        vtkNew<vtkLight> d;
        d->SetLightTypeToSceneLight();
        d->SetPosition(2.0, 4.0, 3.0);
        d->SetFocalPoint(0.0, 0.0, 0.0);
        d->SetColor(0.9, 0.8, 1.0);
        ren->AddLight(d);
      } },
    { "camera light",
      [](vtkRenderer* ren)
      {
        vtkNew<vtkLight> c;
        c->SetLightTypeToCameraLight();
        c->SetPosition(0.5, 0.5, 1.0);
        c->SetFocalPoint(0.0, 0.0, 0.0);
        ren->AddLight(c);
      } },
  };
  int failures = 0;
  for (const StockCase& stockCase : stockCases)
  {
    for (bool rendererLights : { true, false })
    {
      vtkNew<vtkRenderWindow> renWin;
      renWin->SetSize(240, 120);
      renWin->SetMultiSamples(0);
      vtkNew<vtkRenderer> ren;
      ren->SetBackground(0.05, 0.05, 0.08);
      ren->AutomaticLightCreationOff();
      renWin->AddRenderer(ren);
      AddSphere(ren, -1.0, false);
      AddSphere(ren, 1.0, true);
      ren->GetActiveCamera()->SetPosition(0.0, 1.0, 5.5);
      ren->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
      ren->ResetCameraClippingRange();
      stockCase.Add(ren);

      // Clustered lights that add nothing: zero intensity.
      vtkNew<vtkClusteredLightingPass> pass;
      vtkNew<vtkClusteredLightSet> set;
      for (int i = 0; i < 16; ++i)
      {
        const double x = -3.0 + 0.4 * i, y = 1.5, z = 1.0 + 0.1 * i;
        if (rendererLights)
        {
          vtkNew<vtkLight> l;
          l->SetLightTypeToSceneLight();
          l->SetPositional(true);
          l->SetConeAngle(180.0);
          l->SetPosition(x, y, z);
          l->SetIntensity(0.0);
          l->SetAttenuationValues(1.0, 0.0, 1.0);
          ren->AddLight(l);
        }
        else
        {
          const vtkIdType id = set->AddLight(x, y, z);
          set->SetIntensity(id, 0.0);
          set->SetAttenuation(id, 1.0, 0.0, 1.0);
        }
      }
      pass->AddLightSet(set);

      std::vector<float> stock, clustered;
      ClusteredLightingTest::RenderStockThenClustered(renWin, ren, pass, stock, clustered);
      const std::string what = std::string(stockCase.Name) +
        (rendererLights ? " + 16 positional vtkLights" : " + a light set");
      const auto cmp = ClusteredLightingTest::CompareImages(stock, clustered);
      ClusteredLightingTest::PrintComparison(what.c_str(), cmp);
      std::size_t lit = 0;
      for (float v : stock)
      {
        lit += v > 0.1f ? 1 : 0;
      }
      if (pass->GetNumberOfClusteredLights() != 16 || lit < 1000)
      {
        std::printf("%s: %d clustered lights, %zu lit channels (expected 16 and a lit scene)\n",
          what.c_str(), pass->GetNumberOfClusteredLights(), lit);
        ++failures;
      }
      // Float rounding only (VTK sums the same lights' terms in another order).
      if (cmp.MaxAbsError > 1.0 / 255.0 + 1e-6)
      {
        std::printf("%s: VTK's own lights look different with the pass set\n", what.c_str());
        ++failures;
      }
    }
  }
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
