// SPDX-License-Identifier: BSD-3-Clause
// Simulate only the effects a scene calls for. Reads the fragment shader each mapper
// really compiled (vtkCommand::UpdateShaderEvent) and checks that the injected code holds
// only the paths that actor and light set need, and that each variant's image matches the
// brute-force reference:
//  - point-only lights: no spot-cone code; specular code only for the actor with
//    Specular > 0; no clustered code at all for the unlit actor (LightingOff);
//  - point + spot lights: cone code appears;
//  - PBR actor: the PBR path (VTK's PBR terms), checked against brute force and stock VTK;
//  - master texels per cluster fixed at compile time; debug code absent unless enabled.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkLight.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <cctype>
#include <random>

namespace
{
struct Actor
{
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkNew<vtkActor> Prop;
  vtkNew<ClusteredLightingTest::ShaderRecorder> Shader;
};

void MakeSphere(Actor& a, vtkRenderer* ren, double x, double radius = 0.7)
{
  vtkNew<vtkSphereSource> s;
  s->SetCenter(x, 0, radius);
  s->SetRadius(radius);
  s->SetThetaResolution(48);
  s->SetPhiResolution(48);
  a.Mapper->SetInputConnection(s->GetOutputPort());
  a.Prop->SetMapper(a.Mapper);
  a.Mapper->AddObserver(vtkCommand::UpdateShaderEvent, a.Shader);
  ren->AddActor(a.Prop);
}

void MakeFloor(Actor& a, vtkRenderer* ren)
{
  vtkNew<vtkPlaneSource> p;
  p->SetOrigin(-4, -3, 0);
  p->SetPoint1(4, -3, 0);
  p->SetPoint2(-4, 3, 0);
  a.Mapper->SetInputConnection(p->GetOutputPort());
  a.Prop->SetMapper(a.Mapper);
  a.Mapper->AddObserver(vtkCommand::UpdateShaderEvent, a.Shader);
  ren->AddActor(a.Prop);
}

bool Has(const std::string& source, const char* text)
{
  return source.find(text) != std::string::npos;
}

/// Any identifier of the clustered code (they all start with "cl" + capital letter)?
bool HasClusteredIdentifier(const std::string& source)
{
  for (std::size_t i = 0; i + 2 < source.size(); ++i)
  {
    const bool wordStart =
      i == 0 || !(std::isalnum(static_cast<unsigned char>(source[i - 1])) || source[i - 1] == '_');
    if (wordStart && source[i] == 'c' && source[i + 1] == 'l' &&
      std::isupper(static_cast<unsigned char>(source[i + 2])))
    {
      return true;
    }
  }
  return false;
}

int Expect(bool condition, const char* what)
{
  std::printf("%s %s\n", condition ? "ok:  " : "FAIL:", what);
  return condition ? 0 : 1;
}
}

int TestClusteredLightingVariants(int, char*[])
{
  int failures = 0;
  // One window for both parts, each with its own renderer: destroying a window and
  // creating another reopens the X display, which fails on a server that resets when its
  // last client leaves (scripts/with-display.sh starts Xvfb with -noreset; see
  // Display.ReopenAfterLastClient). One window keeps this test independent of that.
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(320, 200);
  renWin->SetMultiSamples(0);
  // ---------------------------------------------------------------- Phong variants
  {
    vtkNew<vtkRenderer> ren;
    ren->AutomaticLightCreationOff();
    renWin->AddRenderer(ren);
    Actor shiny, matte, unlit, floor;
    MakeSphere(shiny, ren, -2.0);
    shiny.Prop->GetProperty()->SetSpecular(0.6);
    shiny.Prop->GetProperty()->SetSpecularPower(25);
    MakeSphere(matte, ren, 0.0);
    matte.Prop->GetProperty()->SetSpecular(0.0);
    MakeSphere(unlit, ren, 2.0);
    unlit.Prop->GetProperty()->LightingOff();
    unlit.Prop->GetProperty()->SetColor(0.2, 0.3, 0.4);
    MakeFloor(floor, ren);

    vtkNew<vtkClusteredLightSet> points, spots;
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    points->SetNumberOfLights(600);
    for (int i = 0; i < 600; ++i)
    {
      points->SetPosition(i, -4 + 8 * U(rng), -3 + 6 * U(rng), 0.05 + 1.8 * U(rng));
      points->SetColor(i, 0.3 + 0.7 * U(rng), 0.3 + 0.7 * U(rng), 0.3 + 0.7 * U(rng));
      points->SetAttenuation(i, 1.0, 0.0, 1500.0);
    }
    spots->SetNumberOfLights(80);
    for (int i = 0; i < 80; ++i)
    {
      spots->SetPosition(i, -4 + 8 * U(rng), -3 + 6 * U(rng), 1.5 + U(rng));
      spots->SetSpot(i, 0.3 * (U(rng) - 0.5), 0.3 * (U(rng) - 0.5), -1.0, 20 + 20 * U(rng), 2.0);
      spots->SetIntensity(i, 2.0);
      spots->SetAttenuation(i, 1.0, 0.0, 400.0);
    }
    vtkNew<vtkClusteredLightingPass> pass;
    pass->AddLightSet(points);
    ren->SetPass(pass);
    ren->GetActiveCamera()->SetPosition(0, -7, 4);
    ren->GetActiveCamera()->SetFocalPoint(0, 0, 0.5);
    ren->ResetCameraClippingRange();
    renWin->Render();

    std::printf("-- point lights only\n");
    failures += Expect(
      Has(shiny.Shader->LastFragmentSource, "clShadeLight"), "specular actor has clustered code");
    failures += Expect(Has(shiny.Shader->LastFragmentSource, "reflect(L, N)"),
      "specular actor has the specular term");
    failures += Expect(Has(matte.Shader->LastFragmentSource, "clShadeLight") &&
        !Has(matte.Shader->LastFragmentSource, "reflect(L, N)"),
      "actor with Specular 0 has no specular term");
    failures += Expect(
      !Has(shiny.Shader->LastFragmentSource, "coneDot"), "no spot-cone code without spot lights");
    failures += Expect(!unlit.Shader->LastFragmentSource.empty() &&
        !HasClusteredIdentifier(unlit.Shader->LastFragmentSource) &&
        HasClusteredIdentifier(matte.Shader->LastFragmentSource),
      "unlit actor has no clustered code at all");
    failures += Expect(Has(shiny.Shader->LastFragmentSource, "const int clMasterTexels = 1;"),
      "master texels per cluster is a compile-time constant");
    failures += Expect(!Has(shiny.Shader->LastFragmentSource, "clHeatColor") &&
        !Has(shiny.Shader->LastFragmentSource, "clEvaluated"),
      "no debug code when no debug view is enabled");
    // (The far field's exact fallback also loops over clLightCount, for far parts only.)
    failures += Expect(!Has(shiny.Shader->LastFragmentSource, "clLight < clLightCount"),
      "no brute-force loop in clustered mode");
    const auto pointOnly =
      ClusteredLightingTest::CheckAgainstBruteForce(pass, renWin, ren, 1.6, "point-only");
    failures += Expect(pointOnly.Violations == 0, "point-only image within the cutoff bound");
    failures +=
      Expect(ClusteredLightingTest::CheckAssignment(pass, ren, "point-only").FalseNegatives == 0,
        "point-only assignment complete");

    std::printf("-- point and spot lights\n");
    pass->AddLightSet(spots);
    renWin->Render();
    failures += Expect(
      Has(shiny.Shader->LastFragmentSource, "coneDot"), "spot-cone code once spot lights exist");
    failures += Expect(pass->GetNumberOfSpotLights() == 80, "80 spot lights clustered");
    const auto withSpots =
      ClusteredLightingTest::CheckAgainstBruteForce(pass, renWin, ren, 1.6, "point+spot");
    failures += Expect(withSpots.Violations == 0, "point+spot image within the cutoff bound");
    failures +=
      Expect(ClusteredLightingTest::CheckAssignment(pass, ren, "point+spot").FalseNegatives == 0,
        "point+spot assignment complete");

    std::printf("-- debug view compiled in only when enabled\n");
    pass->SetDebugView(vtkClusteredLightingPass::DEBUG_HEAT_MAP);
    renWin->Render();
    failures +=
      Expect(Has(shiny.Shader->LastFragmentSource, "clHeatColor"), "heat map code present");
    pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
    renWin->Render();
    failures += Expect(!Has(shiny.Shader->LastFragmentSource, "clHeatColor"), "and gone again");
    renWin->RemoveRenderer(ren); // releases the pass's and the mappers' GL resources
  }

  // ---------------------------------------------------------------- PBR variant
  {
    vtkNew<vtkRenderer> ren;
    ren->AutomaticLightCreationOff();
    renWin->AddRenderer(ren);
    Actor ball, floor;
    MakeSphere(ball, ren, 0.0, 1.0);
    ball.Prop->GetProperty()->SetInterpolationToPBR();
    ball.Prop->GetProperty()->SetRoughness(0.45);
    ball.Prop->GetProperty()->SetMetallic(0.3);
    ball.Prop->GetProperty()->SetColor(0.9, 0.7, 0.5);
    MakeFloor(floor, ren);
    floor.Prop->GetProperty()->SetInterpolationToPBR();
    floor.Prop->GetProperty()->SetRoughness(0.8);
    // Four point lights and a spot as vtkLights (stock VTK can render these too).
    const double pos[5][3] = { { -2, -1, 1.5 }, { 2, -1.5, 1 }, { 0, 2, 2 }, { 1, -2.5, 0.4 },
      { 0, -1, 3.5 } };
    for (int i = 0; i < 5; ++i)
    {
      vtkNew<vtkLight> l;
      l->SetLightTypeToSceneLight();
      l->SetPositional(true);
      l->SetPosition(pos[i]);
      l->SetFocalPoint(0, 0, 0);
      l->SetConeAngle(i == 4 ? 30.0 : 180.0);
      l->SetColor(0.5 + 0.1 * i, 0.9 - 0.1 * i, 0.7);
      l->SetIntensity(4.0);
      l->SetAttenuationValues(1.0, 0.0, 0.002); // reaches the whole scene at the cutoff
      ren->AddLight(l);
    }
    ren->GetActiveCamera()->SetPosition(0, -7, 4);
    ren->GetActiveCamera()->SetFocalPoint(0, 0, 0.5);
    ren->ResetCameraClippingRange();
    vtkNew<vtkClusteredLightingPass> pass;
    std::vector<float> stock, clustered;
    ClusteredLightingTest::RenderStockThenClustered(renWin, ren, pass, stock, clustered);
    std::printf("-- PBR\n");
    failures += Expect(Has(ball.Shader->LastFragmentSource, "Lo += clLo") &&
        Has(ball.Shader->LastFragmentSource, "SpecularIsotropic(NdH, NdV, NdL, HdL"),
      "PBR actor has the clustered PBR path");
    failures += Expect(!Has(ball.Shader->LastFragmentSource, "vec3 clDiffuse =") &&
        !Has(ball.Shader->LastFragmentSource, "clDiffuse * diffuseColor"),
      "and no Phong path");
    const auto vsStock = ClusteredLightingTest::CompareImages(stock, clustered);
    ClusteredLightingTest::PrintComparison("PBR clustered vs stock VTK", vsStock);
    failures += Expect(vsStock.MaxAbsError <= 1.5 / 255.0, "PBR matches stock VTK");
    // Every light reaches the whole scene, so there is no cut tail: brute force must agree
    // to rounding.
    const auto vsBrute =
      ClusteredLightingTest::CheckAgainstBruteForce(pass, renWin, ren, 0.0, "PBR");
    failures += Expect(vsBrute.Violations == 0, "PBR matches brute force");
    failures +=
      Expect(ClusteredLightingTest::CountNonFinitePixels(pass, renWin) == 0, "PBR finite");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
