// SPDX-License-Identifier: BSD-3-Clause
// The error budget's choices for the far field (vtkClusteredLightingFarFieldBudget.h):
// the budget is shared between cut tails and the far field only when both are present;
// the resolution chosen is the coarsest whose stated bound (summarized independently
// here, build by build) meets the budget, never one whose near field costs more than the
// finest one's; an unreachable budget takes the smallest bound and says it is not met;
// lights that need no far field need no choice.
#include "vtkClusteredLightingFarFieldBudget.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{

/// n inverse-square lights without radius (as users write them), uniform in [lo, hi],
/// white at `intensity`, attenuation (1, 0, quadratic).
std::vector<PreparedLight> MakeUniformLights(
  int n, const glm::dvec3& lo, const glm::dvec3& hi, double intensity, double quadratic)
{
  std::vector<LightSource> sources(static_cast<std::size_t>(n));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (LightSource& s : sources)
  {
    s.PositionWC = lo + glm::dvec3(U(rng), U(rng), U(rng)) * (hi - lo);
    s.Color = glm::dvec3(1.0);
    s.Intensity = intensity;
    s.Attenuation = glm::dvec3(1.0, 0.0, quadratic);
  }
  return PrepareLights(sources, LightPreparationOptions{ 1.0 / 1024.0, false }).Lights;
}

/// What one resolution gives, computed here from scratch: its plan's near lights per point
/// and its bound's summary (the core's serial SummarizeFarFieldErrorBound).
struct Rung
{
  std::int64_t Nodes = 0;
  double Near = 0.0;
  double Bound = 0.0;
};

std::vector<Rung> MeasureLadder(const std::vector<PreparedLight>& lights, const glm::dvec3& lo,
  const glm::dvec3& hi, FarFieldOptions options)
{
  std::vector<Rung> rungs;
  for (std::int64_t nodes = 4096; nodes <= 262144; nodes *= 2)
  {
    std::vector<PreparedLight> planned = lights;
    options.TargetNodes = nodes;
    const FarFieldPlan plan = PlanFarField(planned, lo, hi, options, lo);
    EXPECT_TRUE(plan.Active);
    const std::vector<double> radii = GetFarFieldNearRadii(planned);
    const FarFieldLightTree tree = BuildFarFieldLightTree(planned, radii);
    const FarFieldBuildInputs in{ &plan.Grid, &planned, &radii, &tree, plan.Grouping };
    rungs.push_back(Rung{ nodes, plan.NearLightsPerPoint, SummarizeFarFieldErrorBound(in).Max });
  }
  return rungs;
}

/// Whether a rung may be chosen: its near field costs no more than the cheapest's.
bool Eligible(const std::vector<Rung>& rungs, std::size_t i)
{
  double cheapest = rungs[0].Near;
  for (const Rung& r : rungs)
  {
    cheapest = std::min(cheapest, r.Near);
  }
  return rungs[i].Near <= (1.0 + FarFieldBudgetNearTolerance) * cheapest;
}

/// The scene of most tests: 1,500 lights as users write them (intensity 0.02, attenuation
/// (1, 0, 8)) in a 10 x 4 x 10 box; the near field's budget cuts their radii, and at the
/// coarsest grid its smallest radius (2 cells) costs more near lights.
struct Scene
{
  glm::dvec3 Lo{ -5.0, 0.0, -5.0 }, Hi{ 5.0, 4.0, 5.0 };
  std::vector<PreparedLight> Lights;
  Scene() { this->Lights = MakeUniformLights(1500, this->Lo, this->Hi, 0.02, 8.0); }
};

} // namespace

TEST(FarFieldBudget, SharedOnlyWhenTailsAndTheFarFieldAreBothPresent)
{
  const Scene scene;
  const double budget = 4.0 / 255.0;
  ErrorBudgetShares s = ShareErrorBudget(scene.Lights, budget, true);
  EXPECT_EQ(s.CutTails, budget);
  EXPECT_EQ(s.FarField, budget) << "only split lights: the far field gets all of it";
  s = ShareErrorBudget(scene.Lights, budget, false);
  EXPECT_EQ(s.CutTails, budget);
  EXPECT_EQ(s.FarField, 0.0) << "far field off: every light is culled";
  std::vector<PreparedLight> mixed = scene.Lights;
  mixed[3].CosCone = 0.5; // a spot light is culled, never split
  ASSERT_FALSE(IsFarFieldLight(mixed[3]));
  s = ShareErrorBudget(mixed, budget, true);
  EXPECT_EQ(s.CutTails, 0.5 * budget);
  EXPECT_EQ(s.FarField, 0.5 * budget) << "both present: their errors add, half each";
  std::vector<PreparedLight> culled(1, mixed[3]);
  s = ShareErrorBudget(culled, budget, true);
  EXPECT_EQ(s.CutTails, budget);
  EXPECT_EQ(s.FarField, 0.0);
}

TEST(FarFieldBudget, ChoosesTheCoarsestResolutionWhoseBoundMeetsTheBudget)
{
  const Scene scene;
  const FarFieldOptions options;
  const std::vector<Rung> rungs = MeasureLadder(scene.Lights, scene.Lo, scene.Hi, options);
  ASSERT_EQ(rungs.size(), GetFarFieldBudgetResolutions().size());
  for (const Rung& r : rungs)
  {
    std::printf("%7lld nodes: near lights per point %.3f, bound %.4f steps\n",
      static_cast<long long>(r.Nodes), r.Near, r.Bound);
  }
  // The coarsest grid would cost near lights; the bound falls with the resolution (not
  // strictly at every rung: a grid's node planes meet the lights differently).
  EXPECT_FALSE(Eligible(rungs, 0));
  EXPECT_TRUE(Eligible(rungs, rungs.size() - 1));
  EXPECT_GT(rungs[1].Bound, 1.5 * rungs.back().Bound);

  // Every budget between the rungs' bounds, and on them: the coarsest rung that meets it.
  std::vector<double> budgets;
  for (const Rung& r : rungs)
  {
    budgets.push_back(r.Bound);
    budgets.push_back(r.Bound * 0.99);
  }
  budgets.push_back(1e9);
  for (double budget : budgets)
  {
    std::size_t expected = rungs.size(), tried = 0;
    for (std::size_t i = 0; i < rungs.size() && expected == rungs.size(); ++i)
    {
      if (Eligible(rungs, i))
      {
        ++tried;
        expected = rungs[i].Bound <= budget ? i : expected;
      }
    }
    const FarFieldResolutionChoice c =
      ChooseFarFieldResolution(scene.Lights, scene.Lo, scene.Hi, options, scene.Lo, budget);
    if (expected == rungs.size())
    {
      EXPECT_FALSE(c.Met) << "budget " << budget;
      continue;
    }
    EXPECT_TRUE(c.Met) << "budget " << budget;
    EXPECT_EQ(c.Nodes, rungs[expected].Nodes) << "budget " << budget;
    EXPECT_EQ(c.Bound, rungs[expected].Bound) << "the summary of that build, bit for bit";
    EXPECT_LE(c.Bound, budget);
    EXPECT_EQ(c.Summaries, static_cast<int>(tried)) << "stops at the first that meets it";
  }
}

TEST(FarFieldBudget, AnUnreachableBudgetTakesTheSmallestBoundAndSaysSo)
{
  const Scene scene;
  const FarFieldOptions options;
  const std::vector<Rung> rungs = MeasureLadder(scene.Lights, scene.Lo, scene.Hi, options);
  std::size_t smallest = rungs.size() - 1;
  int eligible = 0;
  for (std::size_t i = 0; i < rungs.size(); ++i)
  {
    if (Eligible(rungs, i))
    {
      ++eligible;
      smallest = rungs[i].Bound < rungs[smallest].Bound ? i : smallest;
    }
  }
  const double budget = 0.5 * rungs[smallest].Bound;
  const FarFieldResolutionChoice c =
    ChooseFarFieldResolution(scene.Lights, scene.Lo, scene.Hi, options, scene.Lo, budget);
  EXPECT_FALSE(c.Met);
  EXPECT_EQ(c.Nodes, rungs[smallest].Nodes);
  EXPECT_EQ(c.Bound, rungs[smallest].Bound);
  EXPECT_EQ(c.Summaries, eligible) << "every resolution whose near field is the cheapest";
}

TEST(FarFieldBudget, CoarseGridsThatCostNearLightsAreNotTaken)
{
  // Bright lights: the near field's budget cuts every radius to R, and a coarse grid's
  // smallest near radius (CellsPerRadius cells) is larger than R, so it would evaluate
  // more near lights per point at every frame to save build time.
  const glm::dvec3 lo(-5.0, 0.0, -5.0), hi(5.0, 4.0, 5.0);
  const std::vector<PreparedLight> lights = MakeUniformLights(4000, lo, hi, 1.0, 1.0);
  FarFieldOptions options;
  options.CellsPerRadius = 4.0;
  const std::vector<Rung> rungs = MeasureLadder(lights, lo, hi, options);
  const double cheapest = rungs.back().Near;
  ASSERT_GT(rungs.front().Near, (1.0 + FarFieldBudgetNearTolerance) * cheapest)
    << "the scene must make the coarsest grid cost near lights";
  std::size_t first = 0;
  while (rungs[first].Near > (1.0 + FarFieldBudgetNearTolerance) * cheapest)
  {
    ++first;
  }
  ASSERT_LT(first, rungs.size());
  // A budget every rung meets: the coarsest rung whose near field is the cheapest.
  const FarFieldResolutionChoice c = ChooseFarFieldResolution(lights, lo, hi, options, lo, 1e9);
  EXPECT_TRUE(c.Met);
  EXPECT_EQ(c.Nodes, rungs[first].Nodes);
  EXPECT_LE(c.NearLightsPerPoint, (1.0 + FarFieldBudgetNearTolerance) * cheapest);
  EXPECT_EQ(c.Summaries, 1);
}

TEST(FarFieldBudget, LightsThatNeedNoFarFieldNeedNoChoice)
{
  const glm::dvec3 lo(-5.0, 0.0, -5.0), hi(5.0, 4.0, 5.0);
  // A handful of bright lights reaching everywhere: shaded exactly, no far field.
  const std::vector<PreparedLight> few = MakeUniformLights(4, lo, hi, 1.0, 0.0);
  FarFieldResolutionChoice c = ChooseFarFieldResolution(few, lo, hi, FarFieldOptions(), lo, 0.1);
  EXPECT_TRUE(c.Met);
  EXPECT_EQ(c.Bound, 0.0);
  EXPECT_EQ(c.Summaries, 0);
  // The far field off.
  FarFieldOptions off;
  off.Enabled = false;
  c = ChooseFarFieldResolution(Scene().Lights, lo, hi, off, lo, 0.1);
  EXPECT_TRUE(c.Met);
  EXPECT_EQ(c.Summaries, 0);
}
