// SPDX-License-Identifier: BSD-3-Clause
// Influence radius, validation and light preparation.
#include "vtkClusteredLightingLights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace vtkClusteredLighting;

TEST(LightRadius, ContributionAtRadiusEqualsCutoff)
{
  const double cutoff = 1.0 / 1024.0;
  for (const glm::dvec3& att : { glm::dvec3(1, 0, 1), glm::dvec3(0.5, 0.2, 0.05),
         glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 1e-6), glm::dvec3(0, 0, 3) })
  {
    for (double peak : { 0.01, 1.0, 5.0, 1000.0 })
    {
      const double r = ComputeInfluenceRadius(peak, att, cutoff);
      ASSERT_TRUE(std::isfinite(r));
      if (r > 0.0)
      {
        EXPECT_NEAR(peak * EvaluateAttenuation(r, att), cutoff, 1e-9 * cutoff)
          << "att " << att.x << "," << att.y << "," << att.z << " peak " << peak;
        // Just inside the radius the light is above the cutoff, just outside below.
        EXPECT_GT(peak * EvaluateAttenuation(r * (1 - 1e-6), att), cutoff);
        EXPECT_LT(peak * EvaluateAttenuation(r * (1 + 1e-6), att), cutoff);
      }
    }
  }
}

TEST(LightRadius, VTKDefaultAttenuationIsAlwaysOn)
{
  EXPECT_TRUE(std::isinf(ComputeInfluenceRadius(1.0, glm::dvec3(1, 0, 0), 1.0 / 1024.0)));
}

TEST(LightRadius, LightBelowCutoffEverywhereHasZeroRadius)
{
  EXPECT_EQ(ComputeInfluenceRadius(1e-4, glm::dvec3(1, 0, 1), 1.0 / 1024.0), 0.0);
  EXPECT_EQ(ComputeInfluenceRadius(0.0, glm::dvec3(1, 0, 1), 1.0 / 1024.0), 0.0);
  EXPECT_EQ(ComputeInfluenceRadius(2.0, glm::dvec3(4096, 0, 0), 1.0 / 1024.0), 0.0);
}

TEST(LightRadius, StableForTinyQuadraticTerm)
{
  // a2 -> 0 must converge to the linear solution (K - a0) / a1 without cancellation.
  const double cutoff = 1e-3;
  const double linear = ComputeInfluenceRadius(1.0, glm::dvec3(1, 0.5, 0), cutoff);
  EXPECT_NEAR(linear, (1000.0 - 1.0) / 0.5, 1e-9);
  const double tiny = ComputeInfluenceRadius(1.0, glm::dvec3(1, 0.5, 1e-18), cutoff);
  EXPECT_NEAR(tiny, linear, 1e-6 * linear);
}

TEST(LightRadius, MonotonicInCutoff)
{
  double last = std::numeric_limits<double>::infinity();
  for (double cutoff = 1.0 / 4096.0; cutoff <= 1.0 / 16.0; cutoff *= 2.0)
  {
    const double r = ComputeInfluenceRadius(1.0, glm::dvec3(1, 0.1, 0.5), cutoff);
    EXPECT_LT(r, last);
    last = r;
  }
}

TEST(LightValidation, BadInputIsNamedAndSkipped)
{
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  std::vector<LightSource> lights(12);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    lights[i].PositionWC = glm::dvec3(double(i), 0, 0);
    lights[i].Attenuation = glm::dvec3(1, 0, 1);
  }
  lights[1].PositionWC.y = nan;
  lights[2].Color = glm::dvec3(inf, 0, 0);
  lights[3].Intensity = nan;
  lights[4].Intensity = -1.0;
  lights[5].HasRadius = true;
  lights[5].Radius = -2.0;
  lights[6].Attenuation = glm::dvec3(0, 0, 0);  // 1/0: infinite everywhere
  lights[7].Attenuation = glm::dvec3(1, -1, 0); // reaches 1/0 at d = 1
  lights[8].ConeAngle = 30.0;
  lights[8].DirectionWC = glm::dvec3(0.0); // spot without direction
  lights[9].Color = glm::dvec3(-1, 1, 1);
  lights[10].HasRadius = true;
  lights[10].Radius = inf;
  const PreparedLights p = PrepareLights(lights, LightPreparationOptions());
  ASSERT_EQ(p.Problems.size(), 10u);
  EXPECT_EQ(p.Lights.size(), 2u);
  for (const std::string& msg : p.Problems)
  {
    EXPECT_NE(msg.find("light "), std::string::npos) << msg;
    EXPECT_NE(msg.find("skipped"), std::string::npos) << msg;
  }
  EXPECT_NE(p.Problems[0].find("light 1:"), std::string::npos);
  EXPECT_NE(p.Problems[5].find("attenuation"), std::string::npos);
  // The two valid lights are intact.
  for (const PreparedLight& l : p.Lights)
  {
    EXPECT_TRUE(l.SourceIndex == 0 || l.SourceIndex == 11);
    EXPECT_GT(l.Radius, 0.0);
    EXPECT_TRUE(std::isfinite(l.Radius));
  }
}

// Found by a hostile-input sweep (2026-12-06): a position past the floats' range was
// taken in (and broke the far field of every other light), a negative cone angle made an
// empty cone (VTK lights |angle|), and a tiny but valid spot direction was called zero.
TEST(LightValidation, PositionsConeAnglesAndDirectionsAtTheEdges)
{
  std::vector<LightSource> lights(8);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    lights[i].PositionWC = glm::dvec3(double(i), 0, 0);
    lights[i].Attenuation = glm::dvec3(1, 0, 1);
    lights[i].DirectionWC = glm::dvec3(0, -1, 0);
  }
  // +Inf is 90 degrees or more: a point light, as VTK makes it; -Inf is no cone at all.
  lights[0].ConeAngle = std::numeric_limits<double>::infinity();
  lights[7].ConeAngle = -std::numeric_limits<double>::infinity();
  lights[1].PositionWC.x = 3.5e38; // a double, but Inf as a float
  lights[2].PositionWC.z = -1e300;
  lights[3].ConeAngle = -30.0; // lit as 30 degrees, as VTK lights it
  lights[4].ConeAngle = -90.0; // VTK's shading of it is undefined: skipped
  lights[5].ConeAngle = 30.0;
  lights[5].DirectionWC = glm::dvec3(0, -1e-300, 0); // a direction, not zero
  lights[6].PositionWC.y = 3e38;                     // still a float
  const PreparedLights p = PrepareLights(lights, LightPreparationOptions());
  ASSERT_EQ(p.Problems.size(), 4u);
  EXPECT_NE(p.Problems[0].find("light 1: position"), std::string::npos) << p.Problems[0];
  EXPECT_NE(p.Problems[0].find("32-bit"), std::string::npos) << p.Problems[0];
  EXPECT_NE(p.Problems[1].find("light 2: position"), std::string::npos) << p.Problems[1];
  EXPECT_NE(p.Problems[2].find("light 4: spot cone angle -90"), std::string::npos) << p.Problems[2];
  EXPECT_NE(p.Problems[3].find("light 7: spot cone angle -inf"), std::string::npos)
    << p.Problems[3];
  ASSERT_EQ(p.Lights.size(), 4u);
  for (const PreparedLight& l : p.Lights)
  {
    if (l.SourceIndex == 0)
    {
      EXPECT_FALSE(l.IsSpot());
    }
    if (l.SourceIndex == 3)
    {
      EXPECT_NEAR(l.CosCone, std::cos(glm::radians(30.0)), 1e-12);
    }
    if (l.SourceIndex == 5)
    {
      EXPECT_NEAR(l.DirectionWC.y, -1.0, 1e-12);
    }
  }
  EXPECT_EQ(p.NumberOfSpots, 2u);
}

TEST(LightPreparation, AlwaysOnLightsComeFirstAndEveryValidLightIsKept)
{
  std::vector<LightSource> lights(100);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    lights[i].PositionWC =
      glm::dvec3(std::sin(i * 1.3) * 10, std::cos(i * 0.7) * 10, double(i % 7));
    lights[i].Attenuation = (i % 10 == 3) ? glm::dvec3(1, 0, 0) : glm::dvec3(1, 0, 0.2);
    lights[i].Intensity = (i % 10 == 4) ? 0.0 : 1.0;
  }
  const PreparedLights p = PrepareLights(lights, LightPreparationOptions());
  ASSERT_EQ(p.Lights.size(), lights.size());
  EXPECT_EQ(p.NumberOfAlwaysOn, 10u);
  EXPECT_EQ(p.NumberOfBelowCutoff, 10u); // intensity 0
  for (std::size_t i = 0; i < 10; ++i)
  {
    EXPECT_TRUE(std::isinf(p.Lights[i].Radius));
  }
  std::vector<bool> seen(lights.size(), false);
  for (const PreparedLight& l : p.Lights)
  {
    ASSERT_LT(l.SourceIndex, lights.size());
    EXPECT_FALSE(seen[l.SourceIndex]);
    seen[l.SourceIndex] = true;
  }
}

// Spot lights come after every point light in Morton order (the shader walks the lights
// below FirstSpot without the spot code); without it the input order stays and FirstSpot
// is the first spot light wherever it is; with no spot light FirstSpot is the count.
TEST(LightPreparation, SpotLightsComeLastAndFirstSpotFindsThem)
{
  std::vector<LightSource> lights(90);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    lights[i].PositionWC = glm::dvec3(std::sin(i * 1.7) * 10, std::cos(i * 0.3) * 10, 0.0);
    lights[i].Attenuation = (i % 9 == 2) ? glm::dvec3(1, 0, 0) : glm::dvec3(1, 0, 0.2);
    lights[i].ConeAngle = (i % 4 == 1) ? 30.0 : 180.0;
    lights[i].DirectionWC = glm::dvec3(0, 0, -1);
  }
  const PreparedLights morton = PrepareLights(lights, LightPreparationOptions());
  ASSERT_EQ(morton.Lights.size(), lights.size());
  EXPECT_EQ(morton.NumberOfSpots, 23u);
  EXPECT_EQ(morton.FirstSpot, lights.size() - 23u);
  for (std::size_t i = 0; i < morton.Lights.size(); ++i)
  {
    EXPECT_EQ(morton.Lights[i].IsSpot(), i >= morton.FirstSpot) << i;
  }
  // Always-on lights first among the spot lights too (sources 2 and 11 ... are always-on).
  EXPECT_TRUE(std::isinf(morton.Lights[morton.FirstSpot].Radius));
  const PreparedLights input = PrepareLights(lights, LightPreparationOptions{ 1e-3, false });
  EXPECT_EQ(input.FirstSpot, 1u);
  lights.resize(1);
  EXPECT_EQ(PrepareLights(lights, LightPreparationOptions()).FirstSpot, 1u);
}

TEST(LightPreparation, SpotParametersFollowVTKConventions)
{
  LightSource spot;
  spot.ConeAngle = 30.0; // half angle in degrees, as vtkLight
  spot.DirectionWC = glm::dvec3(0, 0, -5);
  spot.Attenuation = glm::dvec3(1, 0, 1);
  LightSource wide = spot;
  wide.ConeAngle = 90.0; // >= 90 is not a spot in VTK
  const PreparedLights p = PrepareLights({ spot, wide }, LightPreparationOptions{ 1e-3, false });
  ASSERT_EQ(p.Lights.size(), 2u);
  EXPECT_NEAR(p.Lights[0].CosCone, std::cos(30.0 * 3.14159265358979323846 / 180.0), 1e-15);
  EXPECT_NEAR(glm::length(p.Lights[0].DirectionWC), 1.0, 1e-15);
  EXPECT_EQ(p.Lights[1].CosCone, -2.0);
  EXPECT_EQ(p.NumberOfSpots, 1u);
}

TEST(LightPreparation, ExplicitRadiusCapsDerivedRadius)
{
  LightSource l;
  l.Attenuation = glm::dvec3(1, 0, 1);
  l.HasRadius = true;
  l.Radius = 2.0;
  EXPECT_DOUBLE_EQ(PrepareLights({ l }, LightPreparationOptions()).Lights[0].Radius, 2.0);
  l.Radius = 1e6; // larger than what the cutoff needs: the derived radius wins
  const double derived = ComputeInfluenceRadius(1.0, l.Attenuation, 1.0 / 1024.0);
  EXPECT_DOUBLE_EQ(PrepareLights({ l }, LightPreparationOptions()).Lights[0].Radius, derived);
  l.Radius = 0.0; // explicit zero radius: valid, reaches nothing
  EXPECT_EQ(PrepareLights({ l }, LightPreparationOptions()).Lights[0].Radius, 0.0);
}

TEST(LightPreparation, FarFieldCutoffSetsOnlyTheRadiiOfLightsAFarFieldMaySplit)
{
  LightSource point; // inverse-square, no radius: a far field may split it
  point.Attenuation = glm::dvec3(1, 0, 1);
  LightSource spot = point;
  spot.ConeAngle = 30.0;
  LightSource capped = point;
  capped.HasRadius = true;
  capped.Radius = 1e6; // larger than either cutoff needs: the cutoff sets its radius
  LightPreparationOptions options{ 1.0 / 1024.0, false };
  const double tight = ComputeInfluenceRadius(1.0, point.Attenuation, options.Cutoff);
  const double loose = ComputeInfluenceRadius(1.0, point.Attenuation, 1.0 / 64.0);
  ASSERT_GT(tight, loose);
  options.FarFieldCutoff = 1.0 / 64.0;
  const PreparedLights p = PrepareLights({ point, spot, capped }, options);
  ASSERT_EQ(p.Lights.size(), 3u);
  EXPECT_DOUBLE_EQ(p.Lights[0].Radius, loose) << "a splittable light takes FarFieldCutoff";
  EXPECT_DOUBLE_EQ(p.Lights[1].Radius, loose) << "so does a spot light (split since 2026-11-30)";
  EXPECT_DOUBLE_EQ(p.Lights[2].Radius, tight) << "a light with an explicit radius keeps Cutoff";
  options.FarFieldCutoff = 0.0; // unset: Cutoff for every light
  for (const PreparedLight& l : PrepareLights({ point, spot, capped }, options).Lights)
  {
    EXPECT_DOUBLE_EQ(l.Radius, tight);
  }
}

TEST(ErrorBudget, TailShrinksAsTheCutoffShrinks)
{
  std::vector<LightSource> lights(200);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    lights[i].PositionWC = glm::dvec3(std::sin(i * 1.7) * 4, std::cos(i * 0.9) * 4, double(i % 5));
    lights[i].Attenuation = glm::dvec3(1, 0.1, 2.0);
  }
  const PreparedLights p = PrepareLights(lights, LightPreparationOptions());
  const glm::dvec3 point(0.3, 0.2, 1.0);
  double last = std::numeric_limits<double>::infinity();
  for (double cutoff = 1.0 / 16.0; cutoff > 1e-6; cutoff /= 2.0)
  {
    const double tail = ComputeTailAtCutoff(point, p.Lights, cutoff, false);
    EXPECT_LE(tail, last);
    last = tail;
  }
}

TEST(ErrorBudget, ChosenCutoffMeetsTheBudgetAndIsTight)
{
  std::vector<LightSource> lights(300);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    lights[i].PositionWC =
      glm::dvec3(std::sin(i * 2.3) * 5, std::cos(i * 1.1) * 5, std::sin(i * 0.37) * 2);
    lights[i].Color = glm::dvec3(1.0, 0.5, 0.25);
    lights[i].Attenuation = glm::dvec3(1, 0, 8.0);
  }
  const PreparedLights p = PrepareLights(lights, LightPreparationOptions());
  const std::vector<glm::dvec3> samples = ComputeErrorBudgetSamples(p.Lights);
  EXPECT_EQ(samples.size(), 216u + 64u);
  for (double budget : { 1.0 / 255.0, 4.0 / 255.0, 0.05 })
  {
    const double cutoff = ChooseCutoffForErrorBudget(p.Lights, budget, samples);
    double worst = 0.0, worstLarger = 0.0;
    for (const glm::dvec3& s : samples)
    {
      worst = std::max(worst, ComputeTailAtCutoff(s, p.Lights, cutoff, false));
      worstLarger = std::max(worstLarger, ComputeTailAtCutoff(s, p.Lights, cutoff * 1.05, false));
    }
    EXPECT_LE(worst, budget) << "budget " << budget;
    EXPECT_GT(worstLarger, budget) << "budget " << budget; // no larger cutoff would do
  }
  // A budget every cutoff meets gives the largest cutoff.
  EXPECT_DOUBLE_EQ(ChooseCutoffForErrorBudget(p.Lights, 1e6, samples), 1.0 / 16.0);
}

TEST(ErrorBudget, ASpotLightsTailReachesOnlyThePointsInsideItsCone)
{
  LightSource spot;
  spot.Attenuation = glm::dvec3(1, 0, 1);
  spot.DirectionWC = glm::dvec3(0, -2, 0);
  spot.ConeAngle = 30.0;
  spot.Exponent = 2.0;
  LightSource point = spot;
  point.ConeAngle = 180.0;
  const LightPreparationOptions options{ 1.0 / 16.0, false };
  const PreparedLight s = PrepareLights({ spot }, options).Lights[0];
  const PreparedLight q = PrepareLights({ point }, options).Lights[0];
  const double pi = 3.14159265358979323846;
  auto at = [](double degrees, double d)
  {
    const double a = degrees * 3.14159265358979323846 / 180.0;
    return glm::dvec3(d * std::sin(a), -d * std::cos(a), 0.0); // degrees from the axis
  };
  const double d = 5.0; // beyond both radii at 1/16
  ASSERT_LT(s.Radius, d);
  const double full = ComputeTailAtCutoff(at(0.0, d), { q }, options.Cutoff, false);
  ASSERT_GT(full, 0.0);
  EXPECT_NEAR(ComputeTailAtCutoff(at(0.0, d), { s }, options.Cutoff, false), full, 1e-5 * full)
    << "on the axis the spot factor is 1";
  const double c20 = std::cos(20.0 * pi / 180.0);
  EXPECT_NEAR(
    ComputeTailAtCutoff(at(20.0, d), { s }, options.Cutoff, false), full * c20 * c20, 1e-5 * full)
    << "inside the cone: pow(cos, exponent)";
  EXPECT_EQ(ComputeTailAtCutoff(at(45.0, d), { s }, options.Cutoff, false), 0.0)
    << "outside the cone: no tail";
  EXPECT_EQ(ComputeTailAtCutoff(at(180.0, d), { s }, options.Cutoff, false), 0.0);
  EXPECT_NEAR(ComputeTailAtCutoff(at(45.0, d), { q }, options.Cutoff, false), full, 1e-12)
    << "a point light's tail reaches every direction";

  // So spot lights need a looser cutoff for the same budget than the same lights as point
  // lights (here 200 spot lights of 60 degrees pointing down in a ball, 1.11 times looser:
  // below the ball most of them shine on the same points).
  std::vector<LightSource> spots(200), points(200);
  for (std::size_t i = 0; i < spots.size(); ++i)
  {
    spots[i] = spot;
    spots[i].ConeAngle = 60.0;
    spots[i].Exponent = 1.0;
    spots[i].Attenuation = glm::dvec3(1, 0, 8);
    spots[i].PositionWC =
      glm::dvec3(std::sin(i * 2.3) * 3, std::cos(i * 1.1) * 3, std::sin(i * 0.37) * 3);
    points[i] = spots[i];
    points[i].ConeAngle = 180.0;
  }
  const PreparedLights ps = PrepareLights(spots, LightPreparationOptions());
  const PreparedLights pp = PrepareLights(points, LightPreparationOptions());
  const std::vector<glm::dvec3> samples = ComputeErrorBudgetSamples(pp.Lights);
  const double spotCutoff = ChooseCutoffForErrorBudget(ps.Lights, 4.0 / 255.0, samples);
  const double pointCutoff = ChooseCutoffForErrorBudget(pp.Lights, 4.0 / 255.0, samples);
  EXPECT_GT(spotCutoff, 1.05 * pointCutoff);
  for (const glm::dvec3& x : samples)
  {
    EXPECT_LE(ComputeTailAtCutoff(x, ps.Lights, spotCutoff, false), 4.0 / 255.0);
  }
}

TEST(LightModel, ExplicitRadiusEndsTheLightAndWindowsThere)
{
  LightSource s;
  s.Attenuation = glm::dvec3(1, 0, 2);
  PreparedLights p = PrepareLights({ s }, LightPreparationOptions());
  const PreparedLight unranged = p.Lights[0];
  s.HasRadius = true;
  s.Radius = 0.5;
  p = PrepareLights({ s }, LightPreparationOptions());
  const PreparedLight ranged = p.Lights[0];
  EXPECT_EQ(p.NumberOfExplicitRadius, 1u);
  for (double d : { 0.0, 0.2, 0.49, 0.5, 0.7, 3.0 })
  {
    const double c = EvaluateAttenuation(d, s.Attenuation);
    EXPECT_EQ(EvaluateLightModel(c, d, unranged, false), c) << d;
    EXPECT_EQ(EvaluateLightModel(c, d, unranged, true), c) << d; // no range: no window
    EXPECT_EQ(EvaluateLightModel(c, d, ranged, false), d < 0.5 ? c : 0.0) << d;
    EXPECT_DOUBLE_EQ(
      EvaluateLightModel(c, d, ranged, true), d < 0.5 ? c * EvaluateFalloffWindow(d, 0.5) : 0.0)
      << d;
  }
}

TEST(LightModel, TailBoundCountsOnlyWhatTheCutoffRemovesFromTheModel)
{
  LightSource s;
  s.Attenuation = glm::dvec3(1, 0, 2);
  s.HasRadius = true;
  const glm::dvec3 center(0.0);
  const LightPreparationOptions coarse{ 1.0 / 8.0, false }; // cutoff radius ~1.87
  // An explicit radius inside the cutoff radius: culled where the model ends, no tail.
  s.Radius = 1.0;
  PreparedLights p = PrepareLights({ s }, coarse);
  ASSERT_DOUBLE_EQ(p.Lights[0].Radius, 1.0);
  for (double d : { 0.5, 0.999, 1.0, 1.5, 5.0 })
  {
    for (bool windowed : { false, true })
    {
      EXPECT_EQ(ComputeCutoffTailBound(glm::dvec3(d, 0, 0), p.Lights, { center }, windowed).x, 0.0)
        << d;
    }
  }
  // An explicit radius beyond it: the tail is the model between the two radii, nothing
  // beyond the explicit radius.
  s.Radius = 3.0;
  p = PrepareLights({ s }, coarse);
  const double r = p.Lights[0].Radius;
  ASSERT_LT(r, 3.0);
  EXPECT_EQ(ComputeCutoffTailBound(glm::dvec3(0.5 * r, 0, 0), p.Lights, { center }).x, 0.0);
  const double mid = 0.5 * (r + 3.0);
  EXPECT_DOUBLE_EQ(ComputeCutoffTailBound(glm::dvec3(mid, 0, 0), p.Lights, { center }).x,
    EvaluateAttenuation(mid, s.Attenuation));
  EXPECT_EQ(ComputeCutoffTailBound(glm::dvec3(3.5, 0, 0), p.Lights, { center }).x, 0.0);
}
