// SPDX-License-Identifier: BSD-3-Clause
// The far field on PBR actors. VTK's PBR terms hold each light's own Fresnel and a GGX
// specular lobe, which the far field's order-2 moments cannot represent; before this test
// the far field added only a Lambert diffuse there, so a metallic actor lit by lights as
// users write them (inverse-square, no radius) lost every far light (90 steps darker than
// brute force on Examples/Python/user_lights.py with --pbr 1). Now each PBR fragment
// brackets its far light from the moments (ComputePbrFarInterval) and sums the far parts
// exactly with VTK's own terms where the bracket is wider than FarFieldTolerance. Checks,
// for a dielectric, a half-metal and a metal, rough and smoother:
//  - FarFieldTolerance 0 (every far part summed exactly): the image is brute force's to
//    within rounding;
//  - the default tolerance (2/255): within the tolerance plus rounding of brute force (the
//    bracket is computed from interpolated moments, whose own error is the grid's);
//  - no NaN pixel, and the frame uses the far field (every light is split);
//  - FarFieldExactSumLimit (Phong fragments only) leaves PBR's exact sums on;
//  - the pass says once, in a warning, that PBR actors sum their far light exactly and
//    what to do for speed (and not while the actors are Phong).
#include "ClusteredLightingTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkProperty.h"

#include <cstdio>
#include <string>
#include <vector>

namespace
{
int Status = EXIT_SUCCESS;

void Check(bool ok, const char* what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok)
  {
    Status = EXIT_FAILURE;
  }
}

/// Every actor of `ren` PBR with the given metallic factor and roughness.
void SetPbr(vtkRenderer* ren, double metallic, double roughness)
{
  vtkActorCollection* actors = ren->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->GetProperty()->SetInterpolationToPBR();
    a->GetProperty()->SetMetallic(metallic);
    a->GetProperty()->SetRoughness(roughness);
  }
}

/// The warnings that say PBR actors sum their far light exactly, with the fixes.
std::size_t CountPbrWarnings(const std::vector<std::string>& warnings)
{
  std::size_t n = 0;
  for (const std::string& w : warnings)
  {
    n += w.find("A PBR actor is lit by the far field") != std::string::npos &&
        w.find("SetFarFieldTolerance(1)") != std::string::npos &&
        w.find("SetFalloffToWindowed()") != std::string::npos
      ? 1
      : 0;
  }
  return n;
}

/// The clustered frame against brute force, in 8-bit steps.
ClusteredLightingTest::ImageComparison CompareWithBruteForce(
  vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  rw->Render();
  const std::vector<float> clustered = ClusteredLightingTest::CapturePixels(rw);
  const std::vector<float> brute = ClusteredLightingTest::CaptureBruteForce(pass, rw);
  return ClusteredLightingTest::CompareImages(clustered, brute);
}
}

int TestClusteredLightingPBRFarField(int, char*[])
{
  const int n = 600;
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 240, 180);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, n, 0.02, 11);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  rw->Render();
  Check(CountPbrWarnings(messages->Warnings) == 0, "Phong actors: no warning about PBR");

  const double rounding = 1.5 / 255.0;
  const struct
  {
    double Metallic, Roughness;
  } materials[] = { { 0.0, 0.6 }, { 0.5, 0.45 }, { 1.0, 0.6 }, { 1.0, 0.3 } };
  for (const auto& m : materials)
  {
    SetPbr(ren, m.Metallic, m.Roughness);
    char what[160];
    pass->SetFarFieldTolerance(0.0);
    rw->Render();
    std::snprintf(what, sizeof(what), "metallic %.2f, roughness %.2f", m.Metallic, m.Roughness);
    Check(pass->GetNumberOfFarFieldLights() == n, "every light is split (none has a radius)");
    const auto exact = CompareWithBruteForce(pass, rw);
    std::printf("%s, tolerance 0: max %.2f steps, RMSE %.3f\n", what, 255.0 * exact.MaxAbsError,
      255.0 * exact.RMSE);
    Check(exact.MaxAbsError <= rounding, "tolerance 0: brute force's image to within rounding");

    pass->SetFarFieldTolerance(2.0 / 255.0);
    const auto bounded = CompareWithBruteForce(pass, rw);
    std::printf("%s, tolerance 2/255: max %.2f steps, RMSE %.3f\n", what,
      255.0 * bounded.MaxAbsError, 255.0 * bounded.RMSE);
    Check(bounded.MaxAbsError <= 2.0 / 255.0 + rounding,
      "default tolerance: within the tolerance and rounding of brute force");
    Check(ClusteredLightingTest::CountNonFinitePixels(pass, rw) == 0, "no NaN pixel");
  }
  // PBR actors take the exact sums whatever FarFieldExactSumLimit says (their far light
  // has no stated bound without them; the metal above is up to 35 steps off without).
  pass->SetFarFieldExactSumLimit(0);
  const auto limited = CompareWithBruteForce(pass, rw);
  std::printf("exact sum limit 0: max %.2f steps\n", 255.0 * limited.MaxAbsError);
  Check(limited.MaxAbsError <= 2.0 / 255.0 + rounding,
    "exact sum limit 0: PBR still within the tolerance and rounding of brute force");
  const std::size_t said = CountPbrWarnings(messages->Warnings);
  std::printf(
    "%zu warnings, %zu of them about PBR and the far field\n", messages->Warnings.size(), said);
  Check(said == 1, "one warning: PBR actors sum their far light exactly, with what to do");
  return Status;
}
