// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFarFieldBudget.h
 * @brief GL-free choice of the far field's resolution for an error budget.
 *
 * An error budget (vtkClusteredLightingPass::ErrorBudgetInSteps) states the largest error
 * a user accepts. Two approximations spend it (ShareErrorBudget: half each when both are
 * present): the tails of culled lights (explicit radii, or every light with the far field
 * off: ChooseBudgetCutoff picks their cutoff) and the far field of split lights, whose error has a
 * stated bound (ComputeFarFieldErrorBound) that depends on the far field's resolution: a finer grid
 * interpolates the far light better and groups its lights more finely. On the benchmark's
 * bunny with 4,096 lights the bound's summary over probe points is 1.72 steps at 4,096
 * nodes, 0.889 at 16,384, 0.694 at 32,768 and 0.511 at 131,072, while a build (every frame
 * for moving lights) costs 3.9, 7.4, 19.9 and 44.4 ms (docs/far-field.md).
 *
 * What a resolution costs:
 *  - its build, every time the lights move, grows with the nodes (and the memory, 48 or
 *    112 bytes per node);
 *  - its frame: a grid's cell sets the smallest near radius (FarFieldOptions::
 *    CellsPerRadius cells), so a coarse grid can force larger near radii and more near
 *    lights evaluated per fragment (FarFieldPlan::NearLightsPerPoint, which never grows
 *    with the resolution).
 * The frame comes first: the resolutions whose near field costs more than the finest
 * one's (by more than FarFieldBudgetNearTolerance) are not taken. Among the others, the
 * coarsest whose bound meets the budget is: each resolution, coarsest first, is planned,
 * its light tree built and its bound summarized over probe points
 * (SummarizeFarFieldErrorBound: the largest bound for a white diffuse surface at up to 256
 * points of the grid's interior, 6 normals each), until one meets the budget. When none
 * does, the one with the smallest summary is taken and the choice says so (the pass
 * warns): what remains is the order-2 moments' own uncertainty, which the resolution does
 * not move (at 65,536 lights on the bunny, 8.1 steps at 32,768 and 262,144 nodes alike).
 *
 * The cutoff of split lights (ChooseFarFieldCutoffAndResolution). A larger cutoff shortens
 * the near radii the cutoff sets (not those the near field's budget cuts) and hands the
 * rest of each light to the far field, whose bound grows with it: on the benchmark's bunny
 * with 4,096 lights 1/256 takes 0.73 near lights per point instead of 4.84 at 1/1024, at
 * 2.96 steps (4,096 nodes) instead of 1.24 (the CPU study), and a budget of 4 steps that
 * takes it renders in 0.85 times the time of 1 step, at max 1 step. The split lights'
 * cutoff (LightPreparationOptions::FarFieldCutoff) is their own: the culled lights' tails
 * choose theirs with their share (ChooseBudgetCutoff), and the split lights' is loosened
 * with the far field's share from the pass's ContributionCutoff by factors of
 * FarFieldBudgetCutoffStep up to FarFieldBudgetLoosestCutoff, each step taken while some
 * resolution meets the share and stopping at the first that none meets; a step is kept
 * only when it evaluates fewer near lights per point (by more than
 * FarFieldBudgetNearTolerance) than the choice so far. (When one cutoff served both kinds,
 * the split lights beside spot lights took the one the spot lights' tails asked for: with
 * 200 spot lights among 2,000 lights as users write them, a budget of 16 steps evaluated
 * 100 lights per pixel instead of 82, docs/far-field.md.)
 * Loosened cutoffs use grids no finer than FarFieldOptions::TargetNodes (the pass's
 * FarFieldResolution): a loose cutoff that only a finer grid meets would make every frame
 * of moving lights rebuild that grid (262,144 nodes: 131 to 206 ms on llvmpipe, against
 * 20 to 47 at the default 32,768), which the near field's rule does not see.
 *
 * The summary is not a supremum over every pixel: a pixel's bound depends on its position,
 * normal and material (the GL tests check each pixel against it). It is what the pass
 * reports (ComputeFarFieldErrorBound) and the budget is held to.
 *
 * Cost: one plan per resolution (milliseconds), then a tree and a summary per resolution
 * tried (0.1 to 0.25 s each at 4,096 lights on 2 threads, about 0.7 s at 65,536), for each
 * cutoff tried (a loosened one tries at most the resolutions up to TargetNodes). The pass
 * chooses when the budget, the far field's options, its region or the number of lights
 * change, not when lights move or change brightness: the budget is met when the choice
 * is made, and the pass's ComputeFarFieldErrorBound gives the bound of the current build.
 */
#ifndef vtkClusteredLightingFarFieldBudget_h
#define vtkClusteredLightingFarFieldBudget_h

#include "vtkClusteredLightingFarFieldBound.h" // for SummarizeFarFieldErrorBound

#include <algorithm> // for std::any_of, std::min_element
#include <cstdint>   // for std::int64_t
#include <vector>    // for std::vector

namespace vtkClusteredLighting
{

/// How an error budget is shared (ShareErrorBudget), as fractions of full brightness.
struct ErrorBudgetShares
{
  double CutTails = 0.0; ///< for the culled lights' tails (ChooseBudgetCutoff)
  /// for the far field's stated bound (ChooseFarFieldCutoffAndResolution: the split
  /// lights' cutoff and the resolution)
  double FarField = 0.0;
};

/**
 * The shares of `budget` (a fraction of full brightness) for the two approximations that
 * spend it. Their errors add at a pixel, so when there are both culled lights (explicit
 * radii; every light with the far field off) and lights the far field splits
 * (IsFarFieldLight, spot lights included), each gets half; otherwise the one present gets
 * all of it.
 */
inline ErrorBudgetShares ShareErrorBudget(
  const std::vector<PreparedLight>& lights, double budget, bool farField)
{
  const bool anySplit = farField && std::any_of(lights.begin(), lights.end(), &IsFarFieldLight);
  const bool anyCulled = !farField ||
    std::any_of(
      lights.begin(), lights.end(), [](const PreparedLight& l) { return !IsFarFieldLight(l); });
  const double share = anySplit && anyCulled ? 0.5 * budget : budget;
  ErrorBudgetShares shares;
  shares.CutTails = share;
  shares.FarField = anySplit ? share : 0.0;
  return shares;
}

/// The coarsest and finest resolutions (grid nodes) an error budget chooses from, in
/// powers of two: one eighth to eight times FarFieldOptions' default.
constexpr std::int64_t FarFieldBudgetCoarsestNodes = 4096;
constexpr std::int64_t FarFieldBudgetFinestNodes = 262144;
/// A resolution is not taken when its near lights per point exceed the cheapest (the
/// finest's) by more than this fraction (the frame would pay for the cheaper build).
constexpr double FarFieldBudgetNearTolerance = 0.05;

/// The cutoffs an error budget may loosen split lights to: the pass's, then this factor
/// larger at each step, up to FarFieldBudgetLoosestCutoff.
constexpr double FarFieldBudgetCutoffStep = 4.0;
constexpr double FarFieldBudgetLoosestCutoff = 1.0 / 16.0;

/// The resolutions an error budget chooses from, coarsest first, none finer than `finest`
/// (but at least the coarsest).
inline std::vector<std::int64_t> GetFarFieldBudgetResolutions(
  std::int64_t finest = FarFieldBudgetFinestNodes)
{
  std::vector<std::int64_t> nodes;
  for (std::int64_t n = FarFieldBudgetCoarsestNodes; n <= FarFieldBudgetFinestNodes; n *= 2)
  {
    if (n <= finest || nodes.empty())
    {
      nodes.push_back(n);
    }
  }
  return nodes;
}

/// What ChooseFarFieldResolution chose.
struct FarFieldResolutionChoice
{
  std::int64_t Nodes = 0;          ///< FarFieldOptions::TargetNodes to use
  double Bound = 0.0;              ///< its bound's summary (8-bit steps); 0: no far field
  bool Met = true;                 ///< Bound <= the budget
  int Summaries = 0;               ///< resolutions whose bound was summarized
  double NearLightsPerPoint = 0.0; ///< its plan's FarFieldPlan::NearLightsPerPoint
};

/**
 * The coarsest resolution of GetFarFieldBudgetResolutions whose near field costs no more
 * than the finest one's (FarFieldBudgetNearTolerance) and whose bound's summary is at most
 * `budgetInSteps`; see the file description. `options` are the far field's other options
 * (its TargetNodes is ignored), `lights` the prepared lights before PlanFarField (they are
 * not changed), `lo`, `hi` and `anchor` the region as PlanFarField takes them.
 * `summarize(const FarFieldBuildInputs&)` returns the FarFieldBoundSummary of a build
 * (SummarizeFarFieldErrorBound, or the same over threads). Without a far field at any
 * resolution (disabled, no split light, or every light fits whole) it returns the
 * coarsest, bound 0, met, with no summary. `finestNodes` limits the resolutions tried
 * (GetFarFieldBudgetResolutions).
 */
template <typename Summarize>
FarFieldResolutionChoice ChooseFarFieldResolution(const std::vector<PreparedLight>& lights,
  const glm::dvec3& lo, const glm::dvec3& hi, FarFieldOptions options, const glm::dvec3& anchor,
  double budgetInSteps, Summarize&& summarize, std::int64_t finestNodes = FarFieldBudgetFinestNodes)
{
  const std::vector<std::int64_t> ladder = GetFarFieldBudgetResolutions(finestNodes);
  FarFieldResolutionChoice choice;
  choice.Nodes = ladder.front();
  // The near field's cost at each resolution (plans only).
  std::vector<double> near(ladder.size(), 0.0);
  for (std::size_t i = 0; i < ladder.size(); ++i)
  {
    std::vector<PreparedLight> planned = lights;
    options.TargetNodes = ladder[i];
    const FarFieldPlan plan = PlanFarField(planned, lo, hi, options, anchor);
    if (!plan.Active)
    {
      // The same at every resolution: every split light fits whole, or none is split.
      choice.NearLightsPerPoint = plan.NearLightsPerPoint;
      return choice;
    }
    near[i] = plan.NearLightsPerPoint;
  }
  const double cheapestNear = *std::min_element(near.begin(), near.end());
  choice.Met = false;
  for (std::size_t i = 0; i < ladder.size(); ++i)
  {
    if (near[i] > cheapestNear * (1.0 + FarFieldBudgetNearTolerance))
    {
      continue;
    }
    std::vector<PreparedLight> planned = lights;
    options.TargetNodes = ladder[i];
    const FarFieldPlan plan = PlanFarField(planned, lo, hi, options, anchor);
    const std::vector<double> radii = GetFarFieldNearRadii(planned);
    const FarFieldLightTree tree = BuildFarFieldLightTree(planned, radii);
    const FarFieldBuildInputs in{ &plan.Grid, &planned, &radii, &tree, plan.Grouping,
      plan.Order4Diffuse, plan.SpecularBins };
    const double bound = summarize(in).Max;
    if (++choice.Summaries == 1 || bound < choice.Bound)
    {
      choice.Nodes = ladder[i];
      choice.Bound = bound;
      choice.NearLightsPerPoint = near[i];
    }
    if (bound <= budgetInSteps)
    {
      choice.Met = true;
      return choice;
    }
  }
  return choice;
}

/// What ChooseFarFieldCutoffAndResolution chose.
struct FarFieldBudgetChoice
{
  double Cutoff = 0.0; ///< the cutoff split lights take (ContributionCutoff or larger)
  FarFieldResolutionChoice Resolution; ///< the resolution at that cutoff
  int CutoffsTried = 0;                ///< cutoffs whose resolutions were tried
};

/**
 * The error budget's choice of the split lights' cutoff and the far field's resolution
 * (see the file description): at `cutoff` (the pass's ContributionCutoff)
 * ChooseFarFieldResolution over every resolution; then, when that choice meets the
 * budget with a far field, cutoffs larger by
 * FarFieldBudgetCutoffStep up to FarFieldBudgetLoosestCutoff, each with the resolutions up
 * to `options.TargetNodes`, until one meets the budget at none of them. A looser cutoff is
 * taken when it meets the budget and its near lights per point are below the choice so
 * far's by more than FarFieldBudgetNearTolerance (a cutoff that buys no time is passed
 * over, not taken). `prepare(double cutoff)` returns the prepared lights with the split
 * lights at that cutoff (before PlanFarField); `summarize` as for ChooseFarFieldResolution.
 */
template <typename Prepare, typename Summarize>
FarFieldBudgetChoice ChooseFarFieldCutoffAndResolution(Prepare&& prepare, double cutoff,
  const glm::dvec3& lo, const glm::dvec3& hi, const FarFieldOptions& options,
  const glm::dvec3& anchor, double budgetInSteps, Summarize&& summarize)
{
  FarFieldBudgetChoice choice;
  choice.Cutoff = cutoff;
  choice.Resolution =
    ChooseFarFieldResolution(prepare(cutoff), lo, hi, options, anchor, budgetInSteps, summarize);
  choice.CutoffsTried = 1;
  if (!choice.Resolution.Met || choice.Resolution.Summaries == 0)
  {
    return choice;
  }
  for (double c = cutoff * FarFieldBudgetCutoffStep;
       c <= FarFieldBudgetLoosestCutoff * (1.0 + 1e-12); c *= FarFieldBudgetCutoffStep)
  {
    const FarFieldResolutionChoice r = ChooseFarFieldResolution(
      prepare(c), lo, hi, options, anchor, budgetInSteps, summarize, options.TargetNodes);
    ++choice.CutoffsTried;
    if (!r.Met)
    {
      break;
    }
    if (r.NearLightsPerPoint <
      choice.Resolution.NearLightsPerPoint * (1.0 - FarFieldBudgetNearTolerance))
    {
      choice.Cutoff = c;
      choice.Resolution = r;
    }
  }
  return choice;
}

/// ChooseFarFieldResolution with the serial summary (SummarizeFarFieldErrorBound).
inline FarFieldResolutionChoice ChooseFarFieldResolution(const std::vector<PreparedLight>& lights,
  const glm::dvec3& lo, const glm::dvec3& hi, const FarFieldOptions& options,
  const glm::dvec3& anchor, double budgetInSteps)
{
  return ChooseFarFieldResolution(lights, lo, hi, options, anchor, budgetInSteps,
    [](const FarFieldBuildInputs& in) { return SummarizeFarFieldErrorBound(in); });
}

} // namespace vtkClusteredLighting

#endif
