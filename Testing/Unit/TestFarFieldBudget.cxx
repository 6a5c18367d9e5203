// SPDX-License-Identifier: BSD-3-Clause
// The error budget's choices for the far field (vtkClusteredLightingFarFieldBudget.h):
// the budget is shared between cut tails and the far field only when both are present;
// the resolution chosen is the coarsest whose stated bound (summarized independently
// here, build by build) meets the budget, never one whose near field costs more than the
// finest one's; an unreachable budget takes the smallest bound and says it is not met;
// lights that need no far field need no choice; with only split lights the budget
// loosens their cutoff while a grid no finer than the option's meets it, and only where
// that evaluates fewer near lights.
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
/// white at `intensity`, attenuation (1, 0, quadratic), prepared at `cutoff`.
std::vector<PreparedLight> MakeUniformLights(int n, const glm::dvec3& lo, const glm::dvec3& hi,
  double intensity, double quadratic, double cutoff = 1.0 / 1024.0)
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
  return PrepareLights(sources, LightPreparationOptions{ cutoff, false }).Lights;
}

/// The serial summary, as ChooseFarFieldResolution's own overload takes it.
FarFieldBoundSummary Summarize(const FarFieldBuildInputs& in)
{
  return SummarizeFarFieldErrorBound(in);
}

/// Faint lights whose near radii the cutoff sets (not the near field's budget): 600 of
/// intensity 0.05, attenuation (1, 0, 8), in a 10 x 4 x 10 box, prepared at any cutoff.
struct FaintScene
{
  glm::dvec3 Lo{ -5.0, 0.0, -5.0 }, Hi{ 5.0, 4.0, 5.0 };
  std::vector<PreparedLight> At(double cutoff) const
  {
    return MakeUniformLights(600, this->Lo, this->Hi, 0.05, 8.0, cutoff);
  }
  FarFieldBudgetChoice Choose(double budget, const FarFieldOptions& options) const
  {
    return ChooseFarFieldCutoffAndResolution([this](double c) { return this->At(c); }, 1.0 / 1024.0,
      this->Lo, this->Hi, options, this->Lo, budget, &Summarize);
  }
};

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
    const FarFieldBuildInputs in{ &plan.Grid, &planned, &radii, &tree, plan.Grouping,
      plan.Order4Diffuse };
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
  mixed[3].ExplicitRadius = 50.0; // a light with an explicit radius is culled, never split
  ASSERT_FALSE(IsFarFieldLight(mixed[3]));
  std::vector<PreparedLight> spot = scene.Lights;
  spot[3].CosCone = 0.5; // a spot light is split (since 2026-11-30)
  ASSERT_TRUE(IsFarFieldLight(spot[3]));
  s = ShareErrorBudget(spot, budget, true);
  EXPECT_EQ(s.FarField, budget) << "a spot light among split lights: still all split";
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

TEST(FarFieldBudget, LoosensTheSplitLightsCutoffWhileAGridNoFinerThanTheOptionMeetsIt)
{
  const FaintScene scene;
  FarFieldOptions options;
  options.TargetNodes = 8192; // loosened cutoffs try 4,096 and 8,192 nodes only
  const double user = 1.0 / 1024.0;
  const FarFieldResolutionChoice atUser = ChooseFarFieldResolution(
    scene.At(user), scene.Lo, scene.Hi, options, scene.Lo, 1e9, &Summarize);
  ASSERT_TRUE(atUser.Met);
  ASSERT_GT(atUser.Summaries, 0) << "the scene must have a far field";

  // A budget every cutoff meets: the loosest step that still cuts near lights.
  FarFieldBudgetChoice c = scene.Choose(1e9, options);
  std::printf("any budget: cutoff 1/%g, %lld nodes, bound %.3f steps, near lights per point "
              "%.3f (%.3f at 1/1024), %d cutoffs tried\n",
    1.0 / c.Cutoff, static_cast<long long>(c.Resolution.Nodes), c.Resolution.Bound,
    c.Resolution.NearLightsPerPoint, atUser.NearLightsPerPoint, c.CutoffsTried);
  EXPECT_GT(c.Cutoff, user);
  EXPECT_LE(c.Cutoff, FarFieldBudgetLoosestCutoff);
  EXPECT_EQ(c.CutoffsTried, 4) << "1/1024, 1/256, 1/64, 1/16: none fails";
  EXPECT_LE(c.Resolution.Nodes, options.TargetNodes);
  EXPECT_LT(c.Resolution.NearLightsPerPoint,
    (1.0 - FarFieldBudgetNearTolerance) * atUser.NearLightsPerPoint);

  // The bound of each step's choice (grids up to 8,192 nodes), computed here.
  std::vector<double> cutoffs, bounds, near;
  for (double cutoff = user; cutoff <= FarFieldBudgetLoosestCutoff * 1.000001; cutoff *= 4.0)
  {
    const FarFieldResolutionChoice r = ChooseFarFieldResolution(scene.At(cutoff), scene.Lo,
      scene.Hi, options, scene.Lo, 1e9, &Summarize, options.TargetNodes);
    cutoffs.push_back(cutoff);
    bounds.push_back(r.Bound);
    near.push_back(r.NearLightsPerPoint);
    std::printf("  1/%g: coarsest bound %.3f steps, near lights per point %.3f\n", 1.0 / cutoff,
      r.Bound, r.NearLightsPerPoint);
  }
  ASSERT_EQ(cutoffs.size(), 4u);
  // The scene's shape: at 1/1024 and 1/256 the near field's budget sets the radii (the
  // same near lights and bound), from 1/64 on the cutoff does.
  ASSERT_EQ(near[1], near[0]);
  ASSERT_EQ(bounds[1], bounds[0]);
  ASSERT_LT(near[2], (1.0 - FarFieldBudgetNearTolerance) * near[0]);
  ASSERT_LT(bounds[0], bounds[2]) << "a looser cutoff hands more light to the far field";
  ASSERT_LT(bounds[2], bounds[3]);

  // A budget between 1/64's and 1/16's bounds: 1/64, and the search stops at 1/16.
  const double between = 0.5 * (bounds[2] + bounds[3]);
  c = scene.Choose(between, options);
  EXPECT_EQ(c.Cutoff, cutoffs[2]);
  EXPECT_TRUE(c.Resolution.Met);
  EXPECT_LE(c.Resolution.Bound, between);
  EXPECT_LE(c.Resolution.Nodes, options.TargetNodes);
  EXPECT_EQ(c.CutoffsTried, 4);
  const FarFieldResolutionChoice again = ChooseFarFieldResolution(scene.At(cutoffs[2]), scene.Lo,
    scene.Hi, options, scene.Lo, between, &Summarize, options.TargetNodes);
  EXPECT_EQ(c.Resolution.Nodes, again.Nodes);
  EXPECT_EQ(c.Resolution.Bound, again.Bound) << "that cutoff's own choice, bit for bit";

  // A budget that 1/256 meets and 1/64 does not: 1/256 buys no near light, so it is passed
  // over, and the pass's cutoff stays (with every resolution).
  c = scene.Choose(0.5 * (bounds[0] + bounds[2]), options);
  EXPECT_EQ(c.Cutoff, user);
  EXPECT_EQ(c.CutoffsTried, 3);
  EXPECT_TRUE(c.Resolution.Met);
}

TEST(FarFieldBudget, TheCutoffStaysWhereThePassCutoffDoesNotMeetTheBudget)
{
  const FaintScene scene;
  const FarFieldOptions options;
  // A budget the pass's cutoff does not meet: no looser one is tried.
  const FarFieldBudgetChoice unmet = scene.Choose(1e-6, options);
  EXPECT_EQ(unmet.Cutoff, 1.0 / 1024.0);
  EXPECT_EQ(unmet.CutoffsTried, 1);
  EXPECT_FALSE(unmet.Resolution.Met);
}
