// SPDX-License-Identifier: BSD-3-Clause
// Lights as a user writes them, bright enough to saturate (issue 11's dense scene): 800
// inverse-square lights, attenuation (1, 0, 8), no radius, over the test scene, at
// intensity 1 and scaled down to 1/4, 1/8 and 1/200 (IntensityScale). Their far parts add
// up to many times full brightness at intensity 1, so the far field's moments cannot tell
// on many fragments whether a channel saturates; those fragments sum the far parts
// exactly (FarFieldTolerance), and stop once every channel saturates. Checks that
//  - the scene is the hard case: at intensity 1 most channels of the brute-force image
//    saturate, at 1/200 almost none;
//  - at every scale, every pixel is within its derived bound of brute force, with zero
//    false negatives and no NaN pixel (CheckClusteredFrame). Measured: at 1/8 the exact
//    sums run on many fragments (110 lights evaluated per pixel against 8 at 1/200), and
//    the error reaches 5 steps there, inside a stated bound of up to 58;
//  - at every scale, the image is within what the README states for very bright far
//    fields (at most 5 steps, RMSE under one step): the derived bound alone, up to 458
//    steps at intensity 1, could not catch a regression;
//  - with more lights than FarFieldExactSumLimit the exact sums are off (fewer lights
//    evaluated per pixel) and every pixel is still within its derived bound;
//  - with more lights than FarSumSingleLightLimit (16 far parts per loop iteration
//    instead of one) the exact sums still run and keep the image within 5 steps.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkImageData.h"
#include "vtkProperty.h"
#include "vtkTexture.h"
#include "vtkToneMappingPass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
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

/// Mean lights evaluated per pixel of geometry (DEBUG_EVALUATED_COUNT).
double MeanEvaluated(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  rw->Render();
  const double mean = pass->GetMeanLightsEvaluatedPerPixel();
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  rw->Render();
  return mean;
}

/// Share of channels at full brightness in the brute-force image.
double SaturatedShare(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  const std::vector<float> brute = ClusteredLightingTest::CaptureBruteForce(pass, rw);
  std::size_t saturated = 0;
  for (float v : brute)
  {
    saturated += v >= 254.5f / 255.0f ? 1 : 0;
  }
  return brute.empty() ? 0.0 : static_cast<double>(saturated) / brute.size();
}
}

int TestClusteredLightingSaturation(int, char*[])
{
  const int n = 800;
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 320, 240);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, n, 1.0, 5);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  rw->Render();

  Check(pass->GetNumberOfFarFieldLights() == n, "every light is split (none has a radius)");
  for (double scale : { 1.0, 0.25, 0.125, 1.0 / 200.0 })
  {
    lights->SetIntensityScale(scale);
    rw->Render();
    const double saturated = SaturatedShare(pass, rw);
    const std::string what = "intensity scale " + std::to_string(scale);
    std::printf("%s: brute force saturates %.1f%% of channels\n", what.c_str(), 100.0 * saturated);
    if (scale == 1.0)
    {
      Check(saturated > 0.5, "intensity 1 saturates most channels (the case under test)");
    }
    else if (scale < 0.01)
    {
      Check(saturated < 0.01, "intensity 1/200 saturates almost nothing");
    }
    ClusteredLightingTest::BruteForceCheck comparison;
    Check(ClusteredLightingTest::CheckClusteredFrame(
            pass, rw, ren, 1.4, what.c_str(), 0, &comparison) == 0,
      (what + ": within the derived bound of brute force, zero false negatives, finite").c_str());
    // The derived bound is loose here (up to 458 steps at intensity 1: the far field's
    // moments bound bright sums poorly), too loose to catch a regression. The README's
    // statement for very bright far fields is the stricter check: at most 5 steps, RMSE
    // under one step (measured: 0, 5, 5 and 1 steps; RMSE at most 0.62 steps, at 1/8).
    Check(255.0 * comparison.Image.MaxAbsError <= 5.0 + 1e-3 && 255.0 * comparison.Image.RMSE < 1.0,
      (what + ": at most 5 steps from brute force, RMSE under one step").c_str());
    const double evaluated = MeanEvaluated(pass, rw);
    std::printf("%s: lights evaluated per pixel %.1f of %d\n", what.c_str(), evaluated, n);
    if (scale == 0.125)
    {
      // FarFieldExactSumLimit: with more lights than it the exact sums are off (fewer
      // lights evaluated), and the image stays inside the stated bound; at exactly as many
      // lights they are on.
      const int limit = pass->GetFarFieldExactSumLimit();
      pass->SetFarFieldExactSumLimit(n);
      Check(MeanEvaluated(pass, rw) == evaluated, "as many lights as the limit: exact sums on");
      pass->SetFarFieldExactSumLimit(n - 1);
      const double without = MeanEvaluated(pass, rw);
      std::printf(
        "%s, exact sum limit %d: lights evaluated per pixel %.1f\n", what.c_str(), n - 1, without);
      Check(without < 0.5 * evaluated, "more lights than the limit: no exact far sums");
      Check(ClusteredLightingTest::CheckClusteredFrame(
              pass, rw, ren, 1.4, (what + ", above the exact sum limit").c_str()) == 0,
        "above the exact sum limit: within the derived bound of brute force");
      pass->SetFarFieldExactSumLimit(limit);

      // FarFieldExactSumsOnBackFaces. The floor is a back face here (vtkPlaneSource's
      // normal, Point1 x Point2, points down, away from the camera; VTK lights it from
      // above all the same): by default only the ball's front takes the sums, and the
      // floor keeps the moments' estimate, inside its stated bound (checked above). Asked
      // to, the floor takes them too: more lights evaluated, and the same statement holds.
      pass->SetFarFieldExactSumsOnBackFaces(true);
      const double withBackFaces = MeanEvaluated(pass, rw);
      std::printf("%s, exact sums on back faces too: lights evaluated per pixel %.1f\n",
        what.c_str(), withBackFaces);
      Check(withBackFaces > evaluated + 5.0, "back faces take the exact sums only when asked to");
      ClusteredLightingTest::BruteForceCheck backFaces;
      Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4,
              (what + ", exact sums on back faces").c_str(), 0, &backFaces) == 0,
        "exact sums on back faces: within the derived bound of brute force");
      Check(255.0 * backFaces.Image.MaxAbsError <= 5.0 + 1e-3 && 255.0 * backFaces.Image.RMSE < 1.0,
        "exact sums on back faces: at most 5 steps from brute force, RMSE under one step");
      pass->SetFarFieldExactSumsOnBackFaces(false);

      // A translucent ball's back faces show through its front, so its draw sums on both
      // sides whatever the option says: the same image with it on and off (the floor, an
      // opaque back face, hidden meanwhile).
      {
        vtkActor* floor = vtkActor::SafeDownCast(ren->GetActors()->GetItemAsObject(0));
        vtkActor* ball = vtkActor::SafeDownCast(ren->GetActors()->GetItemAsObject(1));
        floor->VisibilityOff();
        ball->GetProperty()->SetOpacity(0.3);
        ren->SetUseDepthPeeling(1);
        rw->Render();
        const std::vector<float> off = ClusteredLightingTest::CapturePixels(rw);
        pass->SetFarFieldExactSumsOnBackFaces(true);
        rw->Render();
        const std::vector<float> on = ClusteredLightingTest::CapturePixels(rw);
        pass->SetFarFieldExactSumsOnBackFaces(false);
        // (Images of different or zero size compare as 1e30 apart.)
        const double largest = ClusteredLightingTest::CompareImages(off, on).MaxAbsError;
        std::printf("%s, translucent ball: option on against off, max difference %.2f steps\n",
          what.c_str(), 255.0 * largest);
        Check(largest == 0.0,
          "a translucent ball sums on its back faces whatever FarFieldExactSumsOnBackFaces says");
        ball->GetProperty()->SetOpacity(1.0);
        ren->SetUseDepthPeeling(0);
        floor->VisibilityOn();
      }
    }
  }

  // Past FarSumSingleLightLimit (16,384) lights the exact sums take 16 lights per loop
  // iteration (FAR_SUM_BLOCKS), below it one. 20,000 such lights, each 1/25 of the 800's
  // intensity, at the scale where the sums run on many fragments, the sums allowed
  // (FarFieldExactSumLimit): the same checks as above, and the sums must run.
  {
    const int many = 20000;
    const int limit = pass->GetFarFieldExactSumLimit();
    ClusteredLightingTest::MakeUserLights(lights, many, 1.0, 5);
    lights->SetIntensityScale(0.125 * n / many);
    pass->SetFarFieldExactSumLimit(many);
    rw->Render();
    ClusteredLightingTest::BruteForceCheck comparison;
    Check(ClusteredLightingTest::CheckClusteredFrame(
            pass, rw, ren, 1.4, "20,000 lights, exact sums", 0, &comparison) == 0,
      "20,000 lights, 16 far parts per iteration: within the derived bound of brute force");
    Check(255.0 * comparison.Image.MaxAbsError <= 5.0 + 1e-3 && 255.0 * comparison.Image.RMSE < 1.0,
      "20,000 lights, 16 far parts per iteration: at most 5 steps from brute force, RMSE under "
      "one step");
    const double with = MeanEvaluated(pass, rw);
    pass->SetFarFieldExactSumLimit(many - 1);
    const double without = MeanEvaluated(pass, rw);
    std::printf("20,000 lights: lights evaluated per pixel %.1f with the exact sums, %.1f "
                "without\n",
      with, without);
    Check(with > 2.0 * without + 1.0, "20,000 lights: the exact sums run");
    pass->SetFarFieldExactSumLimit(limit);
    ClusteredLightingTest::MakeUserLights(lights, n, 1.0, 5);
  }

  // VTK's default specular power is 1. Below power 2 a Phong lobe can exceed R^T T R (the
  // far light's sum of g t^2), so the far field must not clamp the lobe to it there. The
  // stated bound is loose here (mean 13 steps), so it does not see that clamp; the share
  // of pixels off by more than one step does: 33.4% with it, 3.2% without (measured).
  {
    vtkActorCollection* actors = ren->GetActors();
    actors->InitTraversal();
    std::vector<std::pair<double, double>> saved; // specular, power
    while (vtkActor* a = actors->GetNextActor())
    {
      saved.emplace_back(a->GetProperty()->GetSpecular(), a->GetProperty()->GetSpecularPower());
      a->GetProperty()->SetSpecular(0.4);
      a->GetProperty()->SetSpecularPower(1.0);
    }
    lights->SetIntensityScale(0.05);
    rw->Render();
    Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "specular power 1") == 0,
      "specular power 1: within the derived bound of brute force");
    const ClusteredLightingTest::BruteForceCheck c =
      ClusteredLightingTest::CheckAgainstBruteForce(pass, rw, ren, 1.4, "specular power 1");
    Check(c.Image.FractionOverOneStep < 0.1,
      "specular power 1: fewer than 10% of the pixels off by more than one step");
    actors->InitTraversal();
    std::size_t k = 0;
    while (vtkActor* a = actors->GetNextActor())
    {
      a->GetProperty()->SetSpecular(saved[k].first);
      a->GetProperty()->SetSpecularPower(saved[k].second);
      ++k;
    }
  }

  // Where the colour goes on after the lighting, a fragment saturated by its lights so far
  // is not final, and the pass must not stop there. The same lights with an explicit
  // radius of 1.2 and windowed falloff have no tail and no far part, so brute force and
  // clustered shading agree to rounding and each pixel's tolerance is tight; at intensity 1
  // they light the floor to many times full brightness, so stopping at 1 would show.
  for (vtkIdType i = 0; i < n; ++i)
  {
    lights->SetRadius(i, 1.2);
  }
  pass->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED);
  lights->SetIntensityScale(1.0);
  rw->Render();
  Check(pass->GetNumberOfFarFieldLights() == 0, "explicit radii: no light is split");
  const double saturated = SaturatedShare(pass, rw);
  std::printf("explicit radii: brute force saturates %.1f%% of channels\n", 100.0 * saturated);
  Check(saturated > 0.3, "explicit radii at intensity 1 saturate many channels");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "explicit radii") == 0,
    "explicit radii: within rounding of brute force, zero false negatives, finite");
  std::printf(
    "explicit radii: lights evaluated per pixel %.1f of %d\n", MeanEvaluated(pass, rw), n);
  // 1. A texture multiplies the lit colour (VTK: gl_FragData[0] * tcolor): a dark floor
  // texture (40/255) brings the sum back below 1.
  {
    vtkActor* floor = vtkActor::SafeDownCast(ren->GetActors()->GetItemAsObject(0));
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
    std::fill(texels, texels + 4 * 4 * 3, static_cast<unsigned char>(40));
    vtkNew<vtkTexture> texture;
    texture->SetInputData(image);
    floor->SetTexture(texture);
    rw->Render();
    Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "textured floor") == 0,
      "a textured floor: within rounding of brute force");
    floor->SetTexture(nullptr);
  }
  // 2. Translucent fragments are blended by their opacity after the shader (depth
  // peeling here): a translucent ball over the bright floor.
  {
    vtkActor* ball = vtkActor::SafeDownCast(ren->GetActors()->GetItemAsObject(1));
    ball->GetProperty()->SetOpacity(0.3);
    ren->SetUseDepthPeeling(1);
    rw->Render();
    Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "translucent ball") == 0,
      "a translucent ball (depth peeling): within rounding of brute force");
    ball->GetProperty()->SetOpacity(1.0);
    ren->SetUseDepthPeeling(0);
  }
  // 3. A float render target: vtkToneMappingPass (Reinhard) around the pass keeps values
  // above 1 and maps them below. Its curve, with VTK's gamma around it,
  // x / (1 + x^2.2)^(1/2.2), has slope at most 1, so each pixel's tolerance from the plain
  // render (rounding here) holds after it.
  {
    std::vector<double> tolerances;
    ClusteredLightingTest::CheckAgainstBruteForce(
      pass, rw, ren, 1.4, "tolerances for the tone-mapped check", 0, &tolerances);
    vtkNew<vtkToneMappingPass> toneMapping;
    toneMapping->SetToneMappingType(vtkToneMappingPass::Reinhard);
    toneMapping->SetDelegatePass(pass);
    ren->SetPass(toneMapping);
    rw->Render();
    const std::vector<float> clustered = ClusteredLightingTest::CapturePixels(rw);
    const std::vector<float> brute = ClusteredLightingTest::CaptureBruteForce(pass, rw);
    ren->SetPass(pass);
    toneMapping->ReleaseGraphicsResources(rw);
    std::size_t violations = 0, unsaturated = 0;
    double maxError = 0.0;
    for (std::size_t i = 0; i < tolerances.size() && 3 * i + 2 < brute.size(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double error = std::abs(double(clustered[3 * i + c]) - double(brute[3 * i + c]));
        maxError = std::max(maxError, error);
        violations += error > tolerances[i] ? 1 : 0;
        unsaturated += brute[3 * i + c] < 254.5f / 255.0f ? 1 : 0;
      }
    }
    std::printf("tone mapped: max error %.2f steps, %zu channels over their tolerance, %.1f%% "
                "of channels below full brightness\n",
      255.0 * maxError, violations, 100.0 * unsaturated / (3.0 * tolerances.size()));
    Check(unsaturated > 2 * tolerances.size(), "tone mapping brings most channels below 1");
    Check(violations == 0, "tone mapped: within rounding of brute force");
  }
  return Status;
}
