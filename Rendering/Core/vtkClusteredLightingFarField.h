// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFarField.h
 * @brief GL-free far field: what the near radius cuts off, added back with a stated bound.
 *
 * Every light contributes everywhere; only how it is evaluated changes with distance.
 * Each light j (colour C_j = color * intensity, VTK attenuation A_j(d)) is split smoothly
 * at its near radius r_j:
 *
 *   near part   C_j A_j(d) W(d / r_j)          evaluated exactly, light by light, through
 *                                              the clusters (the list/master walk)
 *   far part    C_j A_j(d) (1 - W(d / r_j))    summed over all lights on a world-space grid
 *
 * with the window W(x) = clamp(1 - x^4, 0, 1)^2 (1 near the light, 0 at and beyond r_j,
 * the windowed falloff the clustered path already evaluates). The far part is smooth
 * everywhere and vanishes near the light, so the sum of all far parts interpolates well.
 *
 * Angular representation. The far light arriving at a point comes from many directions;
 * at each grid node it is kept as the moments of its direction distribution, per colour
 * channel (18 numbers each, 54 per node):
 *
 *   S = sum g_j        V = sum g_j L_j        T = sum g_j L_j L_j^T   (trace T = S)
 *   F = sum g_j L_j (x) L_j (x) L_j (x) L_j                           (its traces are T)
 *
 * where g_j is light j's far part at the node and L_j the unit vector from the node to the
 * light. S, V and T are spherical harmonics of order 2 in another basis, F adds the
 * fourth-order band (9 numbers: its traces are T). Diffuse irradiance for a normal N is
 * the clamped-cosine kernel applied to them (Legendre coefficients of max(0, t): 1/4,
 * 1/2, 5/16, 0, -3/32; Ramamoorthi and Hanrahan 2001), since 2026-12-06 to order 4
 * (ApplyFarDiffuse; FarFieldOptions::Order4Diffuse):
 *
 *   E(N) = S/4 + (V.N)/2 + (5/16) (3 N^T T N - S) / 2 - (3/32) (35 F(N) - 30 N^T T N + 3 S) / 8
 *
 * with F(N) = sum g_j (N.L_j)^4; order 2 stops before the last term, whose pointwise error
 * (from -0.040 to +0.094 per unit g) the fourth order cuts to -0.031 to +0.059, and for
 * light from many directions far more: the study at 65,536 lights found the diffuse's
 * mean error 5 times smaller, docs/far-field.md).
 *
 * and Phong specular, sum g_j max(0, L_j.R)^n over the lights in front of the surface
 * (N.L_j > 0) for the reflected view direction R, the Legendre coefficients of the whole
 * lobe (ComputeLobeKernel) where the far light is in front of the surface, and the order-2
 * projection of the lit-side lobe where a share of it comes from behind (ApplyFarLobe,
 * since 2026-12-06: the whole lobe alone was too bright at low powers). A node's
 * moments are interpolated trilinearly to the shaded point, then the kernels are applied.
 *
 * What the far field holds. Lights without an explicit radius (VTK's inverse-square and
 * other attenuations, and always-on lights, attenuation (1, 0, 0)) are split at their near
 * radius. Lights with an explicit radius are left out: the radius ends the light, nothing
 * is cut. Spot lights are split too, with their spot factor in both parts, but at their
 * cutoff radius: the far field holds only the tail the cutoff used to drop. Their far part
 * has the cone's hard edge, which trilinear interpolation spreads over a cell; the stated
 * bound counts that spot light by spot light (each is a source of its own in the build,
 * never grouped), and keeping the near radius at the cutoff keeps what spreads as faint
 * as the tail (since 2026-11-30; before, spot tails were dropped).
 *
 * Error. Three sources: the angular truncation (order 2 of the kernel: the pointwise
 * error of the diffuse kernel lies in [-0.040, +0.094] per unit g, far less when the far
 * light comes from many directions), the trilinear interpolation between nodes (it grows
 * as (h / r)^2 for grid spacing h and near radius r), and the aggregation of far groups of
 * lights in the build (vtkClusteredLightingFarFieldTree.h). Their stated bound, computed
 * per shaded point, is in vtkClusteredLightingFarFieldBound.h; the tests check it per
 * pixel against brute force.
 *
 * Units: world coordinates. Everything here is double precision on the CPU; the GPU gets
 * the node moments as floats.
 */
#ifndef vtkClusteredLightingFarField_h
#define vtkClusteredLightingFarField_h

#include "vtkClusteredLightingFarSpecularBins.h"
#include "vtkClusteredLightingLights.h"
#include "vtkClusteredLightingLobeProjection.h"

#include <algorithm> // for std::max, std::any_of
#include <array>     // for std::array
#include <cmath>     // for std::floor
#include <cstdint>   // for std::int64_t
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp> // for glm::pi
#include <iterator>              // for std::back_inserter
#include <limits>                // for std::numeric_limits
#include <vector>                // for std::vector

namespace vtkClusteredLighting
{

/// Moments of the far light at one node for one colour channel: the order-2 moments S, V
/// (3) and T as (Txx, Tyy, Txy, Txz, Tyz) with Tzz = S - Txx - Tyy (the first
/// FarFieldOrder2Moments), then the fourth moments F_abc = sum g ux^a uy^b uz^c (a + b + c
/// = 4) with c <= 1, as (F400, F310, F220, F130, F040, F301, F211, F121, F031); the other
/// six follow from T, since F summed over a repeated pair of axes is T
/// (ComputeFourthMomentForm).
constexpr int FarFieldOrder2Moments = 9;
constexpr int FarFieldMomentsPerChannel = 18;
constexpr int FarFieldFloatsPerNode = 3 * FarFieldMomentsPerChannel;

/// The fourth-order terms (F400 to F031, the last 9 of FarFieldMomentsPerChannel) one
/// light of far part g from unit direction u adds to a channel's moments, into f[0] to
/// f[8]. ComputeFarMomentTerms' t[9] on, and the group spread's fourth moments
/// (ComputeGroupSpreadTerms) use the same expressions.
inline void ComputeFarFourthMomentTerms(double g, const glm::dvec3& u, double* f)
{
  const double gx = g * u.x, gy = g * u.y;
  const double gxx = gx * u.x, gyy = gy * u.y, gxy = gx * u.y;
  f[0] = gxx * u.x * u.x;
  f[1] = gxx * u.x * u.y;
  f[2] = gxx * u.y * u.y;
  f[3] = gxy * u.y * u.y;
  f[4] = gyy * u.y * u.y;
  f[5] = gxx * u.x * u.z;
  f[6] = gxx * u.y * u.z;
  f[7] = gyy * u.x * u.z;
  f[8] = gyy * u.y * u.z;
}

/// The terms one light of far part g from unit direction u adds to a channel's moments
/// (FarFieldMomentsPerChannel, in their order). Mirrors Detail::ComputeFarFieldTerms.
inline void ComputeFarMomentTerms(
  double g, const glm::dvec3& u, double (&t)[FarFieldMomentsPerChannel])
{
  const double gx = g * u.x, gy = g * u.y;
  t[0] = g;
  t[1] = gx;
  t[2] = gy;
  t[3] = g * u.z;
  t[4] = gx * u.x;
  t[5] = gy * u.y;
  t[6] = gx * u.y;
  t[7] = gx * u.z;
  t[8] = gy * u.z;
  ComputeFarFourthMomentTerms(g, u, t + FarFieldOrder2Moments);
}

/// The window of the near/far split, W(x) = clamp(1 - x^4, 0, 1)^2.
inline double EvaluateSplitWindow(double x)
{
  const double x2 = x * x;
  const double w = std::min(1.0, std::max(0.0, 1.0 - x2 * x2));
  return w * w;
}

/// The far part of a light of peak contribution c (colour x attenuation at d) at distance
/// d, for near radius r: c (1 - W(d / r)). An infinite near radius keeps everything near.
inline double EvaluateFarPart(double c, double d, double nearRadius)
{
  if (std::isinf(nearRadius))
  {
    return 0.0;
  }
  if (!(nearRadius > 0.0))
  {
    return c;
  }
  return c * (1.0 - EvaluateSplitWindow(d / nearRadius));
}

/// Whether a light's far part goes to the far field (see the file description): every
/// light without an explicit radius, spot lights included.
inline bool IsFarFieldLight(const PreparedLight& l)
{
  return std::isinf(l.ExplicitRadius);
}

/// A spot light the far field splits: it keeps its cutoff radius as its near radius
/// (PlanFarField never caps it, nor counts it in the near field's budget), is never grouped
/// with other lights in the build (vtkClusteredLightingFarFieldTree.h), and its far part
/// holds its spot factor (ComputeFarContribution).
inline bool IsFarFieldSpot(const PreparedLight& l)
{
  return IsFarFieldLight(l) && l.IsSpot();
}

/// A far-field light whose near radius PlanFarField chooses (not a spot light).
inline bool IsFarFieldPointLight(const PreparedLight& l)
{
  return IsFarFieldLight(l) && !l.IsSpot();
}

/**
 * The cutoff an error budget asks for (vtkClusteredLightingPass::ErrorBudget). The budget
 * bounds the cut tails. With the far field on, a light it splits has no cut tail: its far
 * part is added back, within the far field's own stated bound (ComputeFarFieldErrorBound).
 * So only the lights that are culled (lights with an explicit radius; every light with the
 * far field off; since 2026-11-30 spot lights are split too) choose the cutoff, with
 * ChooseCutoffForErrorBudget over their tails at ComputeErrorBudgetSamples (with [regionLo,
 * regionHi], the box of the geometry to shade, when valid); with none, `cutoff` (the pass's
 * ContributionCutoff) is kept. Lowering the cutoff of split lights would only move work from the
 * far field to the near field.
 */
inline double ChooseBudgetCutoff(const std::vector<PreparedLight>& lights, double budget,
  bool farField, double cutoff, bool windowed = false, const glm::dvec3& regionLo = glm::dvec3(1.0),
  const glm::dvec3& regionHi = glm::dvec3(-1.0))
{
  if (!farField)
  {
    return ChooseCutoffForErrorBudget(
      lights, budget, ComputeErrorBudgetSamples(lights, regionLo, regionHi), windowed);
  }
  std::vector<PreparedLight> culled;
  std::copy_if(lights.begin(), lights.end(), std::back_inserter(culled),
    [](const PreparedLight& l) { return !IsFarFieldLight(l); });
  if (culled.empty())
  {
    return cutoff;
  }
  return ChooseCutoffForErrorBudget(
    culled, budget, ComputeErrorBudgetSamples(culled, regionLo, regionHi), windowed);
}

/// A regular grid of nodes over an axis-aligned box.
struct FarFieldGrid
{
  glm::dvec3 Origin = glm::dvec3(0.0); ///< world position of node (0, 0, 0)
  double Spacing = 1.0;                ///< h, the same on every axis
  std::array<int, 3> Dims = { { 0, 0, 0 } };

  std::int64_t GetNumberOfNodes() const
  {
    return static_cast<std::int64_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2];
  }
  glm::dvec3 NodePosition(int i, int j, int k) const
  {
    return this->Origin + this->Spacing * glm::dvec3(i, j, k);
  }
  std::int64_t NodeIndex(int i, int j, int k) const
  {
    return (static_cast<std::int64_t>(k) * this->Dims[1] + j) * this->Dims[0] + i;
  }
};

/// Options of the far field (vtkClusteredLightingPass's FarField* options).
struct FarFieldOptions
{
  bool Enabled = true;
  double CellsPerRadius = 2.0;      ///< grid cells per near radius (accuracy of the grid)
  std::int64_t TargetNodes = 32768; ///< nodes over the region (the grid's resolution)
  double Grouping = 1.0;     ///< light-tree aggregation: extent / distance below it (0: exact)
  bool Order4Diffuse = true; ///< the diffuse kernel to order 4 (ApplyFarDiffuse), else 2
  /// The Phong far specular of powers from FarSpecularBinsLeastPower on from directional
  /// bins (vtkClusteredLightingFarSpecularBins.h), else from the moments alone.
  bool SpecularBins = false;
  double NearBudget = 8.0; ///< lights per point the near field may evaluate, on average
  bool SharedColor = true; ///< one channel when the far lights share a colour (see below)
  /// Far light packed lights may put between the grid's nodes before their near radii
  /// are raised (RaiseUnresolvedNearRadii), in the units of the cutoff (1 is white on a
  /// white diffuse surface): 16 8-bit steps.
  double LumpTolerance = 16.0 / 255.0;
};

/// Lights per point that are shaded exactly, with no far field, when they all fit whole
/// (a handful of vtkLights reaching everywhere, as stock VTK shades them); the near budget
/// when it is larger. See PlanFarField.
constexpr double FarFieldExactLightsPerPoint = 16.0;

/// What PlanFarField decided.
struct FarFieldPlan
{
  bool Active = false; ///< some light has a far part
  FarFieldGrid Grid;
  double NearRadiusCap = std::numeric_limits<double>::infinity(); ///< see PlanFarField
  std::size_t NumberOfFarFieldLights = 0;
  double Grouping = 1.0;           ///< FarFieldOptions::Grouping
  bool Order4Diffuse = true;       ///< FarFieldOptions::Order4Diffuse
  bool SpecularBins = false;       ///< FarFieldOptions::SpecularBins
  double NearLightsPerPoint = 0.0; ///< estimated mean near lights per point of the region
  /// Near radii raised by RaiseBrightNearRadii and RaiseUnresolvedNearRadii, and of those
  /// the packed lights' (RaiseUnresolvedNearRadii).
  std::size_t NumberOfRaisedNearRadii = 0;
  std::size_t NumberOfPackedNearRadii = 0;
  /// The colour every far-field light shares (FindFarFieldSharedColor), largest component
  /// 1; (0, 0, 0) when they differ or FarFieldOptions::SharedColor is off.
  glm::dvec3 SharedColor = glm::dvec3(0.0);
};

/**
 * The colour the far-field lights (PreparedLight::FarField) share, if they do. Each
 * light's far moments are its Color (colour x intensity) times terms of its position and
 * attenuation alone, and a group of the light tree sums its lights' colours. So when every
 * far-field light's Color is a multiple of one colour c, every channel's moments at every
 * node are c's component times the moments of the channel where c is largest: the far
 * field is exactly one channel and a colour (3 texture reads per shaded fragment instead
 * of 7; the shading code multiplies by the colour). White vtkLights, VTK's default, are the
 * common case. Returns c scaled so its largest component is 1, or (0, 0, 0) when the
 * lights' hues differ (a component off by more than 1e-6 relative to the largest: a
 * float's precision is 6e-8, so a shared colour read from float data still counts) or no
 * far-field light has a colour. Black lights add nothing and share any colour.
 */
inline glm::dvec3 FindFarFieldSharedColor(const std::vector<PreparedLight>& lights)
{
  glm::dvec3 shared(0.0);
  for (const PreparedLight& l : lights)
  {
    const double largest = std::max(l.Color.x, std::max(l.Color.y, l.Color.z));
    if (!l.FarField || !(largest > 0.0))
    {
      continue;
    }
    const glm::dvec3 c = l.Color / largest;
    if (shared == glm::dvec3(0.0))
    {
      shared = c;
    }
    else if (std::abs(c.x - shared.x) > 1e-6 || std::abs(c.y - shared.y) > 1e-6 ||
      std::abs(c.z - shared.z) > 1e-6)
    {
      return glm::dvec3(0.0);
    }
  }
  return shared;
}

/// The channel where a shared colour (FindFarFieldSharedColor) is 1; 0 when there is none.
inline int GetSharedColorChannel(const glm::dvec3& shared)
{
  return shared.x >= shared.y && shared.x >= shared.z ? 0 : (shared.y >= shared.z ? 1 : 2);
}

/**
 * The far field's region is the box of the geometry to be shaded, grown by this fraction of
 * its size on every side when it is adopted (so that geometry moving a little does not
 * rebuild the far field; vtkClusteredLightingAssigner keeps it until the geometry leaves
 * it or shrinks to half of it).
 */
constexpr double FarFieldRegionMargin = 0.05;

/**
 * A grid of at most maxNodes nodes with spacing at most `spacing` covering the box [lo,
 * hi] (grown by at least one node on every side, so trilinear interpolation never reads
 * outside), with node planes through `anchor` (clamped into the box).
 *
 * Why an anchor: a surface with every far light on one side of it (a floor under the
 * lights) is where V.N peaks, and trilinear interpolation between a node plane below it and
 * one above shades it darker than exact (docs/far-field.md). The pass anchors the grid at
 * the geometry's lower corner, so a floor at the bottom of the scene lies on a node plane.
 * If the box needs more nodes than maxNodes, the spacing grows until it fits (the caller
 * then uses larger near radii, see ComputeNearRadiusFloor).
 */
inline FarFieldGrid ComputeFarFieldGrid(const glm::dvec3& lo, const glm::dvec3& hi, double spacing,
  std::int64_t maxNodes, const glm::dvec3& anchor)
{
  FarFieldGrid g;
  const glm::dvec3 a = glm::clamp(anchor, lo, glm::max(lo, hi));
  const glm::dvec3 below = glm::max(a - lo, glm::dvec3(0.0));
  const glm::dvec3 above = glm::max(hi - a, glm::dvec3(0.0));
  double h = spacing > 0.0 ? spacing : 1.0;
  std::array<int, 3> nodesBelow = { { 0, 0, 0 } };
  for (int attempt = 0; attempt < 64; ++attempt)
  {
    for (int i = 0; i < 3; ++i)
    {
      nodesBelow[i] = static_cast<int>(std::ceil(below[i] / h)) + 1;
      g.Dims[i] = nodesBelow[i] + static_cast<int>(std::ceil(above[i] / h)) + 2;
    }
    if (g.GetNumberOfNodes() <= maxNodes)
    {
      break;
    }
    h *=
      std::cbrt(static_cast<double>(g.GetNumberOfNodes()) / static_cast<double>(maxNodes)) * 1.0001;
  }
  g.Spacing = h;
  g.Origin = a - h * glm::dvec3(nodesBelow[0], nodesBelow[1], nodesBelow[2]);
  return g;
}

namespace Detail
{
/// A light's level at its radius: its peak channel times its attenuation there (for a
/// split light, the peak of its far part).
inline double GetLevelAtRadius(const PreparedLight& l)
{
  return l.GetPeak() * EvaluateAttenuation(l.Radius, l.Attenuation);
}

/// GetLevelAtRadius for split lights that fall off; -1 for the others.
inline double GetNearRadiusLevel(const PreparedLight& l)
{
  return l.FarField && IsFarFieldPointLight(l) && std::isfinite(l.Radius) &&
      (l.Attenuation.y > 0.0 || l.Attenuation.z > 0.0)
    ? GetLevelAtRadius(l)
    : -1.0;
}
} // namespace Detail

/// The limits RaiseUnresolvedNearRadii works with.
struct NearRadiusLimits
{
  double Smallest = 0.0;  ///< the near radius the grid resolves (CellsPerRadius x h)
  double Tolerance = 0.0; ///< FarFieldOptions::LumpTolerance
  double Most = std::numeric_limits<double>::infinity(); ///< ComputeBrightLevelLimit
};

/**
 * Near radii the grid cannot resolve, where lights are packed. A far part
 * g_j = C_j A_j(d) (1 - W(d / r_j)) with r_j below CellsPerRadius * h (`Smallest`) has its
 * peak, about L_j = max channel of C_j A_j(r_j), within a cell of the light. Lights spread
 * over the region are sampled by the nodes as a whole (the sum of their far parts is
 * smooth where the lights are as dense as around them), but lights packed into a cell or
 * two (a clump, or a small cloud of lights under a grid stretched over a large floor: 500
 * lights in a ball of radius 3 under a grid of spacing 12) put their far light between
 * the nodes, which miss it: tens of steps darker than exact, while the stated bound's
 * summary, taken at probes spread over the whole region, may not see it.
 *
 * So, for each such light, the levels of the lights in the 2 x 2 x 2 cells nearest it
 * (within a cell on every axis) are compared with what the nodes would see if those
 * lights were spread like the ones in the 4 x 4 x 4 cells around them (an eighth of
 * theirs): where the block holds more than `Tolerance` (16 steps by default) above that,
 * and more than four times it, every light of the block is raised to `Smallest`, or
 * further: the block's lights count as one light that many times as bright, which keeps
 * its near part out to where that light falls to `Most` (ComputeBrightLevelLimit; 500
 * lights at one point are one bright light). Uniform layouts (the ratio stays near 1
 * however dense they are) and clouds wider than a few cells are left as they are: their
 * errors stay inside the stated bound (docs/far-field.md). The levels and counts go into
 * summed-area tables over the grid's cells and three more on every side (lights more
 * than 1.5 cells outside the grid are left as they are); grids of more than 2^23 such
 * cells (above about 8 million nodes) are not looked at. Returns the number of lights
 * raised.
 */
inline std::size_t RaiseUnresolvedNearRadii(
  std::vector<PreparedLight>& lights, const FarFieldGrid& grid, const NearRadiusLimits& limits)
{
  const double h = grid.Spacing;
  // Cells of spacing h from the grid's origin, three beyond it on every side. Their levels
  // (sum of L_k) and light counts are kept as sums over boxes from the corner (a
  // summed-area table, one plane of zeros first), so that any block's sum is 8 reads.
  const std::array<std::int64_t, 3> n = { { grid.Dims[0] + 6, grid.Dims[1] + 6,
    grid.Dims[2] + 6 } };
  const std::array<std::int64_t, 3> t = { { n[0] + 1, n[1] + 1, n[2] + 1 } };
  if (!(h > 0.0) || !(limits.Tolerance > 0.0) || t[0] * t[1] * t[2] > (std::int64_t(1) << 23))
  {
    return 0;
  }
  auto unresolved = [&limits](const PreparedLight& l)
  { return l.FarField && IsFarFieldPointLight(l) && l.Radius < limits.Smallest; };
  auto position = [&](const PreparedLight& l) { return (l.PositionWC - grid.Origin) / h + 3.0; };
  // Lights at least 1.5 cells inside the table's faces: every block around them (the
  // 4 x 4 x 4 cells from floor(q - 0.5) - 1) is inside the table.
  auto inside = [&n](const glm::dvec3& q)
  {
    return q.x >= 1.5 && q.y >= 1.5 && q.z >= 1.5 && q.x < static_cast<double>(n[0]) - 1.5 &&
      q.y < static_cast<double>(n[1]) - 1.5 && q.z < static_cast<double>(n[2]) - 1.5;
  };
  auto at = [&t](std::int64_t i, std::int64_t j, std::int64_t k)
  { return static_cast<std::size_t>((k * t[1] + j) * t[0] + i); };
  const std::size_t size = static_cast<std::size_t>(t[0] * t[1] * t[2]);
  // The tables of a grid of up to 2^20 cells (16 MiB) are kept from call to call on each
  // thread: a light update then writes memory it already has instead of mapping new
  // pages (a few ms at 4,096 lights on a virtual machine, more than the work itself).
  struct Tables
  {
    std::vector<double> Level;
    std::vector<std::uint32_t> Count, ClumpOf;
  };
  thread_local Tables kept;
  Tables fresh;
  Tables& tables = size <= (std::size_t(1) << 20) ? kept : fresh;
  tables.Level.assign(size, 0.0);
  tables.Count.assign(size, 0);
  tables.ClumpOf.assign(size, 0);
  std::vector<double>& level = tables.Level;
  std::vector<std::uint32_t>& count = tables.Count;
  std::vector<std::uint32_t>& clumpOf = tables.ClumpOf;
  bool any = false;
  for (const PreparedLight& l : lights)
  {
    const glm::dvec3 q = position(l);
    if (unresolved(l) && inside(q))
    {
      const std::size_t c = at(static_cast<std::int64_t>(q.x) + 1,
        static_cast<std::int64_t>(q.y) + 1, static_cast<std::int64_t>(q.z) + 1);
      level[c] += Detail::GetLevelAtRadius(l);
      ++count[c];
      any = true;
    }
  }
  if (!any)
  {
    return 0;
  }
  for (std::int64_t k = 0; k < t[2]; ++k)
  {
    for (std::int64_t j = 0; j < t[1]; ++j)
    {
      for (std::int64_t i = 1; i < t[0]; ++i)
      {
        level[at(i, j, k)] += level[at(i - 1, j, k)];
        count[at(i, j, k)] += count[at(i - 1, j, k)];
      }
    }
  }
  for (std::int64_t k = 0; k < t[2]; ++k)
  {
    for (std::int64_t j = 1; j < t[1]; ++j)
    {
      for (std::int64_t i = 0; i < t[0]; ++i)
      {
        level[at(i, j, k)] += level[at(i, j - 1, k)];
        count[at(i, j, k)] += count[at(i, j - 1, k)];
      }
    }
  }
  for (std::int64_t k = 1; k < t[2]; ++k)
  {
    for (std::int64_t j = 0; j < t[1]; ++j)
    {
      for (std::int64_t i = 0; i < t[0]; ++i)
      {
        level[at(i, j, k)] += level[at(i, j, k - 1)];
        count[at(i, j, k)] += count[at(i, j, k - 1)];
      }
    }
  }
  // The sums over cells [i0, i1) x [j0, j1) x [k0, k1).
  auto box = [&](const auto& sums, std::int64_t i0, std::int64_t j0, std::int64_t k0,
               std::int64_t i1, std::int64_t j1, std::int64_t k1)
  {
    return sums[at(i1, j1, k1)] - sums[at(i0, j1, k1)] - sums[at(i1, j0, k1)] -
      sums[at(i1, j1, k0)] + sums[at(i0, j0, k1)] + sums[at(i0, j1, k0)] + sums[at(i1, j0, k0)] -
      sums[at(i0, j0, k0)];
  };
  // A light is in a clump where the 2 x 2 x 2 cells nearest it (within a cell of it on
  // every axis) hold more than the tolerance above what the nodes would see if their
  // lights were spread like those of the 4 x 4 x 4 cells around them (an eighth of
  // those), and four times that. Every light of such a block is raised (a clump wider
  // than a cell is not split into a raised half and a kept half), each block's lights
  // counted as one light that many times as bright.
  for (const PreparedLight& l : lights)
  {
    const glm::dvec3 q = position(l);
    if (!unresolved(l) || !inside(q))
    {
      continue;
    }
    const glm::dvec3 corner = glm::floor(q - 0.5);
    const std::int64_t i0 = static_cast<std::int64_t>(corner.x),
                       j0 = static_cast<std::int64_t>(corner.y),
                       k0 = static_cast<std::int64_t>(corner.z);
    const double inner = box(level, i0, j0, k0, i0 + 2, j0 + 2, k0 + 2);
    const double spread = box(level, i0 - 1, j0 - 1, k0 - 1, i0 + 3, j0 + 3, k0 + 3) / 8.0;
    if (inner - spread > limits.Tolerance && inner > 4.0 * spread)
    {
      const std::uint32_t clump = box(count, i0, j0, k0, i0 + 2, j0 + 2, k0 + 2);
      for (std::int64_t k = k0; k <= k0 + 1; ++k)
      {
        for (std::int64_t j = j0; j <= j0 + 1; ++j)
        {
          for (std::int64_t i = i0; i <= i0 + 1; ++i)
          {
            std::uint32_t& c = clumpOf[at(i, j, k)];
            c = std::max(c, clump);
          }
        }
      }
    }
  }
  std::size_t raised = 0;
  for (PreparedLight& l : lights)
  {
    const glm::dvec3 q = position(l);
    if (!unresolved(l) || !inside(q))
    {
      continue;
    }
    const std::uint32_t clump = clumpOf[at(static_cast<std::int64_t>(q.x),
      static_cast<std::int64_t>(q.y), static_cast<std::int64_t>(q.z))];
    if (clump > 0)
    {
      // Each light of the clump keeps its near part out to where the clump is no brighter
      // than `Most` (ComputeBrightLevelLimit).
      const double r = ComputeInfluenceRadius(
        l.GetPeak(), l.Attenuation, limits.Most / static_cast<double>(clump));
      l.Radius = std::max(limits.Smallest, std::isfinite(r) ? r : limits.Smallest);
      ++raised;
    }
  }
  return raised;
}

/// The level no split light (or clump of lights) should keep at its near radius: 4 times
/// the median level of the split lights that fall off (Detail::GetNearRadiusLevel), at
/// least 4 8-bit steps. Infinite when no light falls off.
inline double ComputeBrightLevelLimit(const std::vector<PreparedLight>& lights)
{
  std::vector<double> levels;
  for (const PreparedLight& l : lights)
  {
    const double level = Detail::GetNearRadiusLevel(l);
    if (level >= 0.0)
    {
      levels.push_back(level);
    }
  }
  if (levels.empty())
  {
    return std::numeric_limits<double>::infinity();
  }
  auto middle = levels.begin() + static_cast<std::ptrdiff_t>(levels.size() / 2);
  std::nth_element(levels.begin(), middle, levels.end());
  return std::max(4.0 * *middle, 4.0 / 255.0);
}

/**
 * Near radii of lights far brighter than the rest. When the near field's budget cuts the
 * near radii to R (PlanFarField), a light many times brighter than the others keeps a far
 * part that is still bright at R: its level there, L_j = max channel of C_j A_j(r_j), is
 * what the grid interpolates, and the interpolation's error is a share of it (about a
 * fifth at two cells). One light of intensity 1,000 among 500 of 0.05 was shaded 219
 * steps off near its sphere (inside the stated bound, which said 4,159 steps). So every
 * split light that falls off and whose level at its near radius is above `most`
 * (ComputeBrightLevelLimit: 4 times the median level, at least 4 8-bit steps)
 * gets the radius where it falls to `most`: a few bright lights among many are shaded
 * exactly up to where they are no more than 4 times as bright as the median light.
 * Lights of one brightness keep R (colours alone put none above 4 times the median: a
 * light's level is its largest channel), so the budget holds for them; each raised light
 * adds at most one light per point. Returns the number of lights raised.
 */
inline std::size_t RaiseBrightNearRadii(std::vector<PreparedLight>& lights, double most)
{
  std::size_t raised = 0;
  for (PreparedLight& l : lights)
  {
    if (Detail::GetNearRadiusLevel(l) > most)
    {
      const double r = ComputeInfluenceRadius(l.GetPeak(), l.Attenuation, most);
      if (r > l.Radius)
      {
        l.Radius = r;
        ++raised;
      }
    }
  }
  return raised;
}

/**
 * Decides the far field for a set of prepared lights and a region (the world box of the
 * geometry to be shaded). The grid comes first: its spacing h gives `TargetNodes` nodes
 * over the region (each axis counted at least 1/16 of the longest, so that flat regions
 * keep a sensible spacing). Then every far-field point light (IsFarFieldPointLight: no
 * explicit radius, not a spot) gets its near radius:
 *
 *   r_j = min(cutoff radius_j, max(CellsPerRadius * h, R))
 *
 * CellsPerRadius * h is the smallest near radius the grid resolves (the study,
 * docs/far-field.md, found the error flat once h <= r / 2). R shares out the near field's
 * budget: the largest radius for which the lights' near spheres hold, on average over the
 * region, at most NearBudget lights per point (sum_j 4/3 pi r_j^3 <= NearBudget x region
 * volume, a light counting at most the region's volume). When all lights fit whole within
 * NearBudget, every one keeps its cutoff radius and the far field holds only the tails
 * past it (none for a light whose sphere holds the whole region). Lights whose spheres
 * all hold the whole region keep their radii, with no far field at all, within the larger
 * exact budget E = max(NearBudget, FarFieldExactLightsPerPoint): up to 16 vtkLights
 * reaching everywhere are shaded as stock VTK shades them. Otherwise a few bright lights
 * among many keep theirs, highlights included, while thousands get the grid's radius and
 * leave their tails to the far field. Always-on lights have no cutoff radius: while a
 * sphere that shares out E holds at least half of the region, every light gets
 * max(CellsPerRadius * h, R_E) (R chosen for E: a few dozen vtkLights stay exact at most
 * points); otherwise they get CellsPerRadius * h (their near spheres then buy little
 * accuracy, see the code) and R is chosen for NearBudget among the others. Lights below
 * the cutoff everywhere (radius 0) go to the far field whole. Their
 * PreparedLight::Radius (the culling radius) becomes the near radius and
 * PreparedLight::FarField is set. Spot lights (IsFarFieldSpot) keep their cutoff radius
 * whatever the budget and are not counted in it (their near field costs what it did when
 * their tails were dropped); each whose sphere does not hold the whole region is split
 * there. Does nothing when disabled, when no light qualifies or when every qualifying
 * light's sphere holds the whole region within the budget. The grid
 * has node planes through `anchor` (ComputeFarFieldGrid; the pass gives the geometry's
 * lower corner, the overload without one the region's).
 */
inline FarFieldPlan PlanFarField(std::vector<PreparedLight>& lights, glm::dvec3 lo, glm::dvec3 hi,
  const FarFieldOptions& options, glm::dvec3 anchor)
{
  FarFieldPlan plan;
  for (const PreparedLight& l : lights)
  {
    plan.NumberOfFarFieldLights += IsFarFieldLight(l) ? 1 : 0;
  }
  if (!options.Enabled || plan.NumberOfFarFieldLights == 0)
  {
    plan.NumberOfFarFieldLights = 0;
    return plan;
  }
  if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) || !std::isfinite(lo.x + lo.y + lo.z) ||
    !std::isfinite(hi.x + hi.y + hi.z))
  {
    // No usable region: the lights' own box.
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = -lo;
    for (const PreparedLight& l : lights)
    {
      lo = glm::min(lo, l.PositionWC);
      hi = glm::max(hi, l.PositionWC);
    }
    anchor = lo;
  }
  const glm::dvec3 size = hi - lo;
  const double longest = std::max(size.x, std::max(size.y, size.z));
  if (!(longest > 0.0) || !std::isfinite(longest))
  {
    plan.NumberOfFarFieldLights = 0;
    return plan;
  }
  const glm::dvec3 counted = glm::max(size, glm::dvec3(longest / 16.0));
  const std::int64_t target = std::max<std::int64_t>(options.TargetNodes, 64);
  const double h = std::cbrt(counted.x * counted.y * counted.z / static_cast<double>(target));
  plan.Grid = ComputeFarFieldGrid(lo, hi, h, 8 * target, anchor);
  const double smallest = std::max(options.CellsPerRadius, 1.0) * plan.Grid.Spacing;
  plan.Grouping = std::max(options.Grouping, 0.0);
  plan.Order4Diffuse = options.Order4Diffuse;
  plan.SpecularBins = options.SpecularBins;
  plan.Active = true;

  // The near field's budget: sum_j min(rc_j, max(smallest, R))^3 <= budget, R by bisection
  // (the sum grows with R). One light counts at most the region's volume (a sphere larger
  // than the region covers each of its points once). When every light fits whole (at most
  // NearBudget lights reaching everywhere, or more with short radii) there is no far field:
  // exact shading costs no more than the budget.
  const double volume = counted.x * counted.y * counted.z;
  const double unit = volume / (4.0 / 3.0 * glm::pi<double>());
  const double budget = std::max(options.NearBudget, 0.0) * unit;
  const double exactBudget = std::max(options.NearBudget, FarFieldExactLightsPerPoint) * unit;
  const double diagonal = glm::length(size);
  auto cubes = [&](double R)
  {
    double sum = 0.0;
    for (const PreparedLight& l : lights)
    {
      if (IsFarFieldPointLight(l))
      {
        const double r = std::min(l.Radius, std::max(smallest, R));
        sum += std::min(r * r * r, unit);
      }
    }
    return sum;
  };
  const double whole = cubes(std::numeric_limits<double>::infinity());
  auto fillBudget = [&](double most)
  {
    double fill = smallest;
    if (cubes(smallest) < most)
    {
      double a = smallest, b = diagonal;
      for (int i = 0; i < 50; ++i)
      {
        const double m = 0.5 * (a + b);
        (cubes(m) <= most ? a : b) = m;
      }
      fill = a;
    }
    return fill;
  };
  // Within the exact budget, lights that all hold the whole region (a handful of
  // vtkLights) need no far field at all: they keep their radii, within NearBudget so do
  // lights with shorter ones.
  auto holdsRegion = [&](const PreparedLight& l)
  {
    const glm::dvec3 corner = glm::max(glm::abs(lo - l.PositionWC), glm::abs(hi - l.PositionWC));
    return l.Radius >= glm::length(corner);
  };
  const bool allHoldTheRegion = std::all_of(lights.begin(), lights.end(),
    [&](const PreparedLight& l) { return !IsFarFieldPointLight(l) || holdsRegion(l); });
  if (whole <= budget || (whole <= exactBudget && allHoldTheRegion))
  {
    // Every light keeps its cutoff radius; the far field holds only the tails past it, of
    // the lights whose sphere does not hold the whole region.
    plan.NumberOfFarFieldLights = 0;
    plan.NearRadiusCap = std::numeric_limits<double>::infinity();
    plan.NearLightsPerPoint = whole / unit;
    for (PreparedLight& l : lights)
    {
      if (IsFarFieldLight(l))
      {
        if (!holdsRegion(l))
        {
          l.FarField = true;
          ++plan.NumberOfFarFieldLights;
        }
      }
    }
    if (plan.NumberOfFarFieldLights == 0)
    {
      FarFieldPlan none;
      none.NearLightsPerPoint = plan.NearLightsPerPoint;
      return none;
    }
    // Every split light keeps its cutoff radius: none is brighter than the rest there.
    plan.NumberOfPackedNearRadii = RaiseUnresolvedNearRadii(lights, plan.Grid,
      NearRadiusLimits{ smallest, options.LumpTolerance, ComputeBrightLevelLimit(lights) });
    plan.NumberOfRaisedNearRadii = plan.NumberOfPackedNearRadii;
    plan.SharedColor = options.SharedColor ? FindFarFieldSharedColor(lights) : glm::dvec3(0.0);
    return plan;
  }
  // Lights that fall off: their far parts are the tails the far field adds back within
  // its bound, so the near field needs no more than NearBudget per point (8: the same
  // images as 16 on the benchmark's scenes, 25% faster on Examples/Python/user_lights.py,
  // docs/far-field.md).
  double R = fillBudget(budget);
  // An always-on light (no falloff) is not brighter near its position: its far part is
  // off by the moments' angular truncation wherever the far field holds it, and a near
  // sphere only makes the points inside it exact. While spheres sharing out the exact
  // budget hold at least half of the region, every light keeps such a sphere (a few
  // dozen vtkLights stay exact at most points). Otherwise that is a small share of the
  // error for most of the budget (300 always-on lights, near budget 16 -> 1: RMSE 1.0 ->
  // 1.05 steps, 411 -> 288 ms), so they keep the smallest radius and the budget goes to
  // the lights that fall off.
  auto alwaysOn = [](const PreparedLight& l)
  { return IsFarFieldPointLight(l) && std::isinf(l.Radius); };
  if (std::any_of(lights.begin(), lights.end(), alwaysOn))
  {
    const double exactR = fillBudget(exactBudget);
    const double cap = std::max(smallest, exactR);
    if (std::min(cap * cap * cap, unit) < 0.5 * unit)
    {
      for (PreparedLight& l : lights)
      {
        l.Radius = alwaysOn(l) ? smallest : l.Radius;
      }
      R = fillBudget(budget);
    }
    else
    {
      R = exactR;
    }
  }
  plan.NearRadiusCap = std::max(smallest, R);
  plan.NearLightsPerPoint = cubes(R) / unit;
  plan.NumberOfFarFieldLights = 0;
  for (PreparedLight& l : lights)
  {
    if (IsFarFieldPointLight(l))
    {
      l.Radius = std::min(l.Radius, plan.NearRadiusCap);
      l.FarField = true;
    }
    else if (IsFarFieldSpot(l))
    {
      l.FarField = !holdsRegion(l);
    }
    plan.NumberOfFarFieldLights += l.FarField ? 1 : 0;
  }
  const double most = ComputeBrightLevelLimit(lights);
  const std::size_t bright = RaiseBrightNearRadii(lights, most);
  plan.NumberOfPackedNearRadii = RaiseUnresolvedNearRadii(
    lights, plan.Grid, NearRadiusLimits{ smallest, options.LumpTolerance, most });
  plan.NumberOfRaisedNearRadii = bright + plan.NumberOfPackedNearRadii;
  plan.SharedColor = options.SharedColor ? FindFarFieldSharedColor(lights) : glm::dvec3(0.0);
  return plan;
}

/// PlanFarField with node planes through the region's lower corner.
inline FarFieldPlan PlanFarField(
  std::vector<PreparedLight>& lights, glm::dvec3 lo, glm::dvec3 hi, const FarFieldOptions& options)
{
  return PlanFarField(lights, lo, hi, options, lo);
}

/// Near radii of the lights for the far-field builders: the culling radius of far-field
/// lights, infinity (no far part) for the others.
inline std::vector<double> GetFarFieldNearRadii(const std::vector<PreparedLight>& lights)
{
  std::vector<double> r(lights.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    if (lights[i].FarField)
    {
      r[i] = lights[i].Radius;
    }
  }
  return r;
}

/// The far moments of one light of channel colours c (3) seen from a node: adds g L L^T etc.
inline void AccumulateFarMoments(
  const glm::dvec3& color, double far, const glm::dvec3& toLight, double* m)
{
  // toLight is unit; far is the far part per unit colour.
  double t[FarFieldMomentsPerChannel];
  ComputeFarMomentTerms(far, toLight, t);
  for (int c = 0; c < 3; ++c)
  {
    double* o = m + static_cast<std::ptrdiff_t>(c) * FarFieldMomentsPerChannel;
    for (int q = 0; q < FarFieldMomentsPerChannel; ++q)
    {
      o[q] += color[c] * t[q];
    }
  }
}

/// The far part of light l at point p (a spot light's with VTK's spot factor at p,
/// EvaluateSpotFactor without slack: 0 outside the cone), its unit direction from p, and
/// whether it has one. The far-field build sums spot lights with this very function, so
/// that the stated bound sees at each node what the build stored.
inline bool ComputeFarContribution(
  const PreparedLight& l, double nearRadius, const glm::dvec3& p, double& far, glm::dvec3& toLight)
{
  const glm::dvec3 v = l.PositionWC - p;
  const double d = glm::length(v);
  far = 0.0;
  if (!(d > 0.0))
  {
    return false;
  }
  toLight = v / d;
  // A spot light's cosine from its axis to p is that of -toLight, as EvaluateSpotFactor
  // takes it.
  const double spot =
    l.IsSpot() ? EvaluateSpotFactorAtCosine(-glm::dot(toLight, l.DirectionWC), l, 0.0) : 1.0;
  if (!(spot > 0.0))
  {
    return false;
  }
  far = spot * EvaluateFarPart(EvaluateAttenuation(d, l.Attenuation), d, nearRadius);
  return far > 0.0;
}

/**
 * The exact far moments at point p: every light's far part (nearRadii[i] is light i's near
 * radius, inf: no far part) added into m (FarFieldFloatsPerNode doubles, channel-major).
 */
inline void AddFarMomentsAt(const glm::dvec3& p, const std::vector<PreparedLight>& lights,
  const std::vector<double>& nearRadii, double* m)
{
  for (std::size_t l = 0; l < lights.size(); ++l)
  {
    double far;
    glm::dvec3 toLight;
    if (ComputeFarContribution(lights[l], nearRadii[l], p, far, toLight))
    {
      AccumulateFarMoments(lights[l].Color, far, toLight, m);
    }
  }
}

/**
 * Exact node moments: every light's far part summed at every node (O(nodes x lights),
 * AddFarMomentsAt at each node). Returns FarFieldFloatsPerNode doubles per node (the 27
 * moments, channel-major), node index order (FarFieldGrid::NodeIndex). The reference for
 * the tree build (vtkClusteredLightingFarFieldTree.h).
 */
inline std::vector<double> ComputeFarFieldMomentsExact(const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii)
{
  std::vector<double> m(
    static_cast<std::size_t>(grid.GetNumberOfNodes()) * FarFieldFloatsPerNode, 0.0);
  for (int k = 0; k < grid.Dims[2]; ++k)
  {
    for (int j = 0; j < grid.Dims[1]; ++j)
    {
      for (int i = 0; i < grid.Dims[0]; ++i)
      {
        AddFarMomentsAt(grid.NodePosition(i, j, k), lights, nearRadii,
          &m[static_cast<std::size_t>(grid.NodeIndex(i, j, k)) * FarFieldFloatsPerNode]);
      }
    }
  }
  return m;
}

/// Trilinear interpolation of node values (`floats` per node, double or float) at p
/// (clamped to the grid), as the shader's texture reads do, into out[0, floats).
template <typename T>
inline void InterpolateNodeValues(const FarFieldGrid& grid, const std::vector<T>& values,
  std::size_t floats, const glm::dvec3& p, double* out)
{
  std::fill(out, out + floats, 0.0);
  const glm::dvec3 u = (p - grid.Origin) / grid.Spacing;
  int base[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double c = std::min(std::max(u[a], 0.0), static_cast<double>(grid.Dims[a] - 1));
    base[a] = std::min(static_cast<int>(std::floor(c)), std::max(grid.Dims[a] - 2, 0));
    t[a] = c - base[a];
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
    if (w == 0.0)
    {
      continue;
    }
    const int ii = std::min(base[0] + di, grid.Dims[0] - 1);
    const int jj = std::min(base[1] + dj, grid.Dims[1] - 1);
    const int kk = std::min(base[2] + dk, grid.Dims[2] - 1);
    const T* m = &values[static_cast<std::size_t>(grid.NodeIndex(ii, jj, kk)) * floats];
    for (std::size_t q = 0; q < floats; ++q)
    {
      out[q] += w * m[q];
    }
  }
}

/// The node moments (FarFieldFloatsPerNode each) interpolated at p (InterpolateNodeValues).
inline std::array<double, FarFieldFloatsPerNode> InterpolateFarMoments(
  const FarFieldGrid& grid, const std::vector<double>& values, const glm::dvec3& p)
{
  std::array<double, FarFieldFloatsPerNode> out{};
  InterpolateNodeValues(grid, values, out.size(), p, out.data());
  return out;
}

/// The far specular's bins (FarSpecularFloatsPerNode per node) interpolated at p.
inline std::array<double, FarSpecularFloatsPerNode> InterpolateFarSpecularBins(
  const FarFieldGrid& grid, const std::vector<float>& bins, const glm::dvec3& p)
{
  std::array<double, FarSpecularFloatsPerNode> out{};
  InterpolateNodeValues(grid, bins, out.size(), p, out.data());
  return out;
}

/// Legendre coefficients (k0, k1, k2) of max(0, t)^n, n >= 0: max(0,t)^n ~ k0 + k1 t + k2 P2(t).
inline glm::dvec3 ComputeLobeKernel(double n)
{
  return glm::dvec3(0.5 / (n + 1.0), 1.5 / (n + 2.0), 2.5 * (1.5 / (n + 3.0) - 0.5 / (n + 1.0)));
}

/// Which upper end a Phong lobe of power n has (ApplyMomentKernel; the stated bound and the
/// shader's clApplyFarKernel take the same): t^n <= t^2 on [0, 1] from n = 2 on, t^n <= t
/// from n = 1 on, t^n <= 1 below.
enum class LobeUpperEnd
{
  SecondMoment, ///< min(D^T T D, ComputeLobeQuadraticUpper, the diffuse upper ends)
  Diffuse,      ///< the diffuse upper ends
  Total         ///< S
};
inline LobeUpperEnd GetLobeUpperEnd(double n)
{
  return n >= 2.0 ? LobeUpperEnd::SecondMoment
                  : (n >= 1.0 ? LobeUpperEnd::Diffuse : LobeUpperEnd::Total);
}

/**
 * The least upper end of a Phong lobe of power n >= 2 that the quadratics
 * q_c(t) = ((t - c) / (1 - c))^2, -1 <= c <= 0, give from one channel's S, V.D and
 * D^T T D. Each lies above max(0, t)^n on [-1, 1] (on [0, 1], (t - c) / (1 - c) >= t, so
 * q_c >= t^2 >= t^n; below 0 it is a square), so sum g q_c = (D^T T D - 2 c V.D + c^2 S) /
 * (1 - c)^2 bounds the lobe's sum. c = 0 gives D^T T D, c = -1 gives (S + 2 V.D +
 * D^T T D) / 4 (an upper end of the clamped cosine too); the best c between them is
 * (V.D - D^T T D) / (S - V.D), where the bound is Cantelli's inequality. It is much lower
 * than D^T T D where the far light comes from behind the mirrored view (all of it from
 * t = -1/2: 0 instead of S / 4).
 */
inline double ComputeLobeQuadraticUpper(double S, double VD, double DTD)
{
  const double c = S - VD > 0.0 ? std::min(std::max((VD - DTD) / (S - VD), -1.0), 0.0) : 0.0;
  return (DTD - 2.0 * c * VD + c * c * S) / ((1.0 - c) * (1.0 - c));
}

/**
 * How far ComputeLobeQuadraticUpper can move when S, V.D and D^T T D move by at most dS,
 * dV and dD (the stated bound's clamp term). The least of a family moves by at most the
 * most any member moves: with s = -c in [0, 1], (dD + 2 s dV + s^2 dS) / (1 + s)^2, whose
 * largest value is at s = 0, s = 1 or its one critical point, s = (dD - dV) / (dS - dV).
 */
inline double ComputeLobeQuadraticUpperShift(double dS, double dV, double dD)
{
  auto member = [&](double t)
  { return (dD + 2.0 * t * dV + t * t * dS) / ((1.0 + t) * (1.0 + t)); };
  double shift = std::max(member(0.0), member(1.0));
  if (dS != dV)
  {
    const double t = (dD - dV) / (dS - dV);
    shift = t > 0.0 && t < 1.0 ? std::max(shift, member(t)) : shift;
  }
  return shift;
}

/**
 * Applies a kernel (k0, k1, k2) in direction D to one channel's moments, and clamps the
 * result into the interval the moments prove the true value lies in. For the clamped
 * cosine (diffuse) E = sum g max(0, t), t = D.u, with S, V.D and D^T T D the sums of g,
 * g t and g t^2, every quadratic below max(0, t) on [-1, 1] gives a lower bound and every
 * one above it an upper bound:
 *   E >= max(0, V.D, (V.D + D^T T D) / 2)          (0, t and (t + t^2) / 2 lie below)
 *   E <= (S + 2 V.D + D^T T D) / 4                 ((1 + t)^2 / 4 lies above)
 *   E <= (V.D + sqrt(S D^T T D)) / 2               (max(0, t) = (t + |t|) / 2 and
 *                                                  sum g |t| <= sqrt(sum g sum g t^2))
 * and for a Phong lobe of power n, 0 <= sum g max(0, t)^n <= U with U = min(D^T T D,
 * ComputeLobeQuadraticUpper, the diffuse upper bounds) for n >= 2 (t^n <= t^2 on [0, 1];
 * ComputeLobeQuadraticUpper since 2026-12-05), the diffuse upper bounds for
 * 1 <= n < 2 (t^n <= t), and S for n < 1 (t^n <= 1; D^T T D is no bound below n = 2: at
 * n = 1.2 a lobe can hold 20% more). Clamping an estimate into an interval that holds the truth
 * never increases its error; it removes the order-2 kernel's ringing where it matters most: a
 * surface facing away from most of the far light gets no phantom light (the kernel's
 * value at t = -1 is 1/16). `lower` and `upper` receive the interval
 * (ComputeMomentInterval, from S, V.D and D^T T D alone).
 */
inline void ComputeMomentInterval(
  double S, double VD, double DTD, bool lobe, double power, double& lower, double& upper)
{
  upper = std::min(0.5 * (VD + std::sqrt(std::max(S * DTD, 0.0))), 0.25 * (S + 2.0 * VD + DTD));
  lower = std::max(std::max(VD, 0.0), 0.5 * (VD + DTD));
  if (lobe)
  {
    const LobeUpperEnd end = GetLobeUpperEnd(power);
    upper = end == LobeUpperEnd::SecondMoment
      ? std::min(upper, std::min(DTD, ComputeLobeQuadraticUpper(S, VD, DTD)))
      : (end == LobeUpperEnd::Diffuse ? upper : S);
    lower = 0.0;
  }
  upper = std::max(upper, lower);
}

/// An estimate from one direction's contractions of a channel's moments, S, V.D and
/// D^T T D, clamped into ComputeMomentInterval's interval, which `lowerOut` and
/// `upperOut` receive (ApplyKernelToContractions, ApplyFarDiffuse).
inline double ClampIntoMomentInterval(double estimate, double S, double VD, double DTD, bool lobe,
  double power, double* lowerOut, double* upperOut)
{
  double lower = 0.0, upper = 0.0;
  ComputeMomentInterval(S, VD, DTD, lobe, power, lower, upper);
  if (lowerOut)
  {
    *lowerOut = lower;
  }
  if (upperOut)
  {
    *upperOut = upper;
  }
  return std::min(std::max(estimate, lower), upper);
}

/// ApplyMomentKernel from one direction's contractions: the kernel's estimate, clamped
/// (ClampIntoMomentInterval). Mirrors clApplyFarKernel (whose callers contract each
/// direction once and share it: the normal's for the diffuse and the lobe's blend).
inline double ApplyKernelToContractions(const glm::dvec3& k, double S, double VD, double DTD,
  bool lobe, double power, double* lowerOut = nullptr, double* upperOut = nullptr)
{
  return ClampIntoMomentInterval(
    k.x * S + k.y * VD + k.z * 0.5 * (3.0 * DTD - S), S, VD, DTD, lobe, power, lowerOut, upperOut);
}

/// One channel's moments m (FarFieldMomentsPerChannel) contracted with direction D: V.D
/// and D^T T D (Tzz = S - Txx - Tyy).
inline void ContractMoments(const double* m, const glm::dvec3& D, double& VD, double& DTD)
{
  const double Tzz = m[0] - m[4] - m[5];
  VD = m[1] * D.x + m[2] * D.y + m[3] * D.z;
  DTD = m[4] * D.x * D.x + m[5] * D.y * D.y + Tzz * D.z * D.z +
    2.0 * (m[6] * D.x * D.y + m[7] * D.x * D.z + m[8] * D.y * D.z);
}

inline double ApplyMomentKernel(const double* m, const glm::dvec3& k, const glm::dvec3& D,
  bool lobe = false, double power = 1.0, double* lowerOut = nullptr, double* upperOut = nullptr)
{
  double VD = 0.0, DTD = 0.0;
  ContractMoments(m, D, VD, DTD);
  return ApplyKernelToContractions(k, m[0], VD, DTD, lobe, power, lowerOut, upperOut);
}

/**
 * F(D) = sum g (D.u)^4 from one channel's moments m (FarFieldMomentsPerChannel): F's 15
 * components, the six not stored taken from T (F_ab summed with a repeated pair is T_ab:
 * F_xxzz = Txx - F_xxxx - F_xxyy, and so on), each times its multinomial count. Mirrors
 * clFourthMomentForm.
 */
inline double ComputeFourthMomentForm(const double* m, const glm::dvec3& D)
{
  const double* F = m + FarFieldOrder2Moments;
  const double xxzz = m[4] - F[0] - F[2], xyzz = m[6] - F[1] - F[3], yyzz = m[5] - F[2] - F[4];
  const double xzzz = m[7] - F[5] - F[7], yzzz = m[8] - F[6] - F[8];
  const double zzzz = (m[0] - m[4] - m[5]) - xxzz - yyzz;
  const double x = D.x, y = D.y, z = D.z;
  const double x2 = x * x, y2 = y * y, z2 = z * z;
  return x2 * x2 * F[0] + 4.0 * x2 * x * y * F[1] + 6.0 * x2 * y2 * F[2] + 4.0 * x * y2 * y * F[3] +
    y2 * y2 * F[4] + 4.0 * x2 * x * z * F[5] + 12.0 * x2 * y * z * F[6] + 12.0 * x * y2 * z * F[7] +
    4.0 * y2 * y * z * F[8] + 6.0 * x2 * z2 * xxzz + 12.0 * x * y * z2 * xyzz +
    6.0 * y2 * z2 * yyzz + 4.0 * x * z2 * z * xzzz + 4.0 * y * z2 * z * yzzz + z2 * z2 * zzzz;
}

/// The clamped cosine's fourth Legendre coefficient: max(0, t) = 1/4 + t/2 + (5/16) P2(t)
/// - (3/32) P4(t) + (terms of order 6 and up), P4(t) = (35 t^4 - 30 t^2 + 3) / 8.
constexpr double FarDiffuseK4 = -3.0 / 32.0;

/// The far diffuse kernel of one light from cosine t = N.u, as the estimate takes it: the
/// clamped cosine's Legendre series to order 4, or to order 2 (the stated bound's angular
/// term, light by light).
inline double EvaluateFarDiffuseKernel(double t, bool order4)
{
  const double t2 = t * t;
  const double q2 = 0.25 + 0.5 * t + 0.3125 * 0.5 * (3.0 * t2 - 1.0);
  return order4 ? q2 + FarDiffuseK4 * (35.0 * t2 * t2 - 30.0 * t2 + 3.0) / 8.0 : q2;
}

/// The far diffuse estimate before its clamp, from one channel's moments m, the normal N
/// and its contractions V.N and N^T T N: linear in the moments (the stated bound applies it
/// to moment differences too).
inline double EstimateFarDiffuse(
  const double* m, const glm::dvec3& N, double VN, double NTN, bool order4)
{
  const double S = m[0];
  const double q2 = 0.25 * S + 0.5 * VN + 0.3125 * 0.5 * (3.0 * NTN - S);
  return order4
    ? q2 + FarDiffuseK4 * (35.0 * ComputeFourthMomentForm(m, N) - 30.0 * NTN + 3.0 * S) / 8.0
    : q2;
}

/**
 * The far diffuse of one channel's moments m for unit normal N: EstimateFarDiffuse (order
 * 4 or 2) clamped into the interval the order-2 moments prove the true value lies in
 * (ComputeMomentInterval, which `lowerOut` and `upperOut` receive). The clamp keeps the
 * order-4 estimate inside the same stated interval, so the bound's clamp term holds for
 * either order. Mirrors the shader's far diffuse (clFarDiffuse).
 */
inline double ApplyFarDiffuse(const double* m, const glm::dvec3& N, bool order4 = true,
  double* lowerOut = nullptr, double* upperOut = nullptr)
{
  double VN = 0.0, NTN = 0.0;
  ContractMoments(m, N, VN, NTN);
  return ClampIntoMomentInterval(
    EstimateFarDiffuse(m, N, VN, NTN, order4), m[0], VN, NTN, false, 1.0, lowerOut, upperOut);
}

/**
 * Texture units a fragment shader needs for the order-4 far diffuse beside VTK's own: the
 * lights' 4 (data, view, master, list), 14 moment textures and the specular table (19), and
 * room for the 8 or so a VTK mapper may bind (colour and actor textures, a PBR material's
 * maps and its environment's 3). OpenGL 4.5 guarantees 16 (GL_MAX_TEXTURE_IMAGE_UNITS);
 * llvmpipe and desktop GPUs have 32. With fewer the far diffuse is of order 2 (7 moment
 * textures): ChooseFarDiffuseOrder4.
 */
constexpr int FarFieldOrder4TextureUnits = 28;
inline bool ChooseFarDiffuseOrder4(bool asked, int fragmentTextureUnits)
{
  return asked && fragmentTextureUnits >= FarFieldOrder4TextureUnits;
}

/// Texture units a fragment shader needs with the far specular's bins (one texture more,
/// vtkClusteredLightingFarSpecularBins.h), at either order of the far diffuse (order 2
/// reads 7 moment textures fewer).
inline int GetFarSpecularBinsTextureUnits(bool order4)
{
  return (order4 ? FarFieldOrder4TextureUnits : FarFieldOrder4TextureUnits - 7) + 1;
}
inline bool ChooseFarSpecularBins(bool asked, int fragmentTextureUnits, bool order4)
{
  return asked && fragmentTextureUnits >= GetFarSpecularBinsTextureUnits(order4);
}

/// Diffuse far irradiance (per unit colour, per channel) for normal N (ApplyFarDiffuse).
inline glm::dvec3 EvaluateFarDiffuse(
  const std::array<double, FarFieldFloatsPerNode>& m, const glm::dvec3& N, bool order4 = true)
{
  return glm::dvec3(ApplyFarDiffuse(&m[0], N, order4),
    ApplyFarDiffuse(&m[FarFieldMomentsPerChannel], N, order4),
    ApplyFarDiffuse(&m[std::size_t{ 2 } * FarFieldMomentsPerChannel], N, order4));
}

/**
 * How much of the lit-side lobe's projection ApplyFarLobe takes (the rest from the zonal
 * lobe): the far light behind the surface, cosine-weighted, B = sum g max(0, -N.L), as a
 * share of D + B (D the diffuse estimate, the light in front), over LobeBlendShare, at
 * most 1. B is taken at the least the moments allow, max(0, -V.N, (N^T T N - V.N) / 2)
 * (ApplyMomentKernel's lower end for -N), which is exactly 0 wherever every far light is
 * in front (there t^2 <= t). The zonal lobe is the better order-2 estimate there (a floor
 * under the lights: the projection of the lit-side lobe, cut at the horizon, fits its lit
 * side worse), the projection wherever a tenth of the light or more comes from behind (a
 * sphere among the lights); docs/far-field.md, "Low specular powers".
 */
constexpr double LobeBlendShare = 0.1;
inline double ComputeLobeBlend(double D, double VN, double NN)
{
  const double back = std::max(std::max(-VN, 0.0), 0.5 * (NN - VN));
  const double total = D + back;
  return total > 0.0 ? std::min(back / (LobeBlendShare * total), 1.0) : 0.0;
}

/**
 * Phong far specular of one channel's moments m for unit normal N, mirrored view R and
 * power n: VTK's lobe on the lit side. The zonal lobe's estimate (ApplyMomentKernel, clamped
 * into the lobe's interval, which `lower` and `upper` receive) moved toward the lit-side
 * lobe's order-2 projection (vtkClusteredLightingLobeProjection.h, the table's
 * coefficients) by ComputeLobeBlend, and clamped again: the result lies between the two
 * clamped estimates, so its error is at most the larger of theirs (which the stated bound
 * takes). Mirrors clApplyFarLobe.
 */
inline double ApplyFarLobe(const double* m, const glm::dvec3& N, const glm::dvec3& R, double n,
  double* lowerOut = nullptr, double* upperOut = nullptr, bool order4 = true)
{
  double lower = 0.0, upper = 0.0;
  const double zonal = ApplyMomentKernel(m, ComputeLobeKernel(n), R, true, n, &lower, &upper);
  double c = 0.0;
  const glm::dvec3 X = ComputeLobeAxis(N, R, c);
  const double projected = ApplyLobeProjectionToMoments(m, LookupLobeProjection(c, n), X, R);
  const double D = ApplyFarDiffuse(m, N, order4);
  const double a =
    ComputeLobeBlend(D, m[1] * N.x + m[2] * N.y + m[3] * N.z, ComputeMomentForm(m, N, N));
  const double estimate = zonal + a * (projected - zonal);
  if (lowerOut)
  {
    *lowerOut = lower;
  }
  if (upperOut)
  {
    *upperOut = upper;
  }
  return std::min(std::max(estimate, lower), upper);
}

/**
 * Phong far specular (per channel) for unit normal N, mirrored view R and power n. With
 * `bins` (FarSpecularFloatsPerNode at the point, vtkClusteredLightingFarSpecularBins.h) and
 * a power of at least FarSpecularBinsLeastPower, the bins' estimate clamped into the
 * lobe's interval instead of ApplyFarLobe's (mirrors the shader's FAR_SPECULAR_BINS).
 */
inline glm::dvec3 EvaluateFarSpecular(const std::array<double, FarFieldFloatsPerNode>& m,
  const glm::dvec3& N, const glm::dvec3& R, double n, bool order4 = true,
  const double* bins = nullptr)
{
  glm::dvec3 out, lower, upper;
  for (int c = 0; c < 3; ++c)
  {
    out[c] = ApplyFarLobe(&m[static_cast<std::size_t>(c) * FarFieldMomentsPerChannel], N, R, n,
      &lower[c], &upper[c], order4);
  }
  if (bins && n >= FarSpecularBinsLeastPower)
  {
    out = glm::clamp(EvaluateFarSpecularBins(bins, N, R, n), lower, upper);
  }
  return out;
}

/**
 * PBR (VTK's isotropic terms, vtkPBRFunctions.glsl). A PBR fragment's far light is the sum
 * over far lights of g (diffuse + specular) N.L, whose diffuse holds each light's own
 * Fresnel F(H.L) and whose specular is a GGX lobe about the half vector. Neither is a
 * function of one direction's cosine, so the shading code brackets the sum from the
 * moments instead (ComputePbrFarInterval, mirrored in vtkClusteredLightingShadingImpl.glsl):
 *   - Fresnel: F(H.L) = F0 + (F90 - F0) (1 - H.L)^5 lies between F0 and F90, so the
 *     diffuse lies between (1 - m)(1 - max(F0, F90)) albedo / pi and
 *     (1 - m)(1 - min(F0, F90)) albedo / pi times N.L, whose sum the clamped cosine's
 *     interval brackets (ApplyMomentKernel), plus 1e-5 S for VTK's N.L >= 1e-5;
 *   - specular times N.L is at least 0 and at most ComputePbrSpecularBound times g.
 * Where that interval is wider than FarFieldTolerance, the fragment sums its far parts
 * exactly with VTK's own terms (EvaluatePbrTerms), otherwise an estimate inside it stands.
 */
struct PbrMaterial
{
  glm::dvec3 Albedo{ 1.0 };
  double Roughness = 0.5;
  double Metallic = 0.0;
  glm::dvec3 F0{ 0.04 };
  glm::dvec3 F90{ 1.0 };
};

/// Mirrors clPbrTerms: VTK's PBR (diffuse + specular) * N.L for the unit direction L from
/// the fragment to the light, unit normal N and view V (NdV = clamp(N.V, 1e-5, 1)).
inline glm::dvec3 EvaluatePbrTerms(
  const glm::dvec3& L, const glm::dvec3& N, const glm::dvec3& V, double NdV, const PbrMaterial& m)
{
  const glm::dvec3 H = glm::normalize(V + L);
  const double NdL = std::min(std::max(glm::dot(N, L), 1e-5), 1.0);
  const double NdH = std::min(std::max(glm::dot(N, H), 1e-5), 1.0);
  const double HdL = std::min(std::max(glm::dot(H, L), 1e-5), 1.0);
  const double pi = glm::pi<double>();
  const double a = m.Roughness * m.Roughness; // D_GGX
  const double a4 = a * a;
  const double d = (NdH * a4 - NdH) * NdH + 1.0;
  const double D = a4 / (pi * d * d);
  const double a2 = m.Roughness * m.Roughness; // V_SmithCorrelated
  const double ggxV = NdL * std::sqrt(a2 + NdV * (NdV - a2 * NdV));
  const double ggxL = NdV * std::sqrt(a2 + NdL * (NdL - a2 * NdL));
  const double Vis = 0.5 / (ggxV + ggxL);
  const glm::dvec3 F = m.F0 + (m.F90 - m.F0) * std::pow(1.0 - HdL, 5.0);
  const glm::dvec3 spec = (D * Vis) * F;
  const glm::dvec3 diff = (1.0 - m.Metallic) * (glm::dvec3(1.0) - F) * m.Albedo / pi;
  return (diff + spec) * NdL;
}

/**
 * Mirrors clPbrSpecularBound: an upper end of VTK's isotropic specular times N.L over every
 * light direction, per channel. D_GGX = a^4 / (pi d^2) with d = 1 - N.H^2 (1 - a^4) >= a^4,
 * so D <= 1 / (pi a^4) (a the roughness); V_SmithCorrelated times N.L is at most
 * 0.5 / sqrt(a^2 + NdV^2 (1 - a^2)) (the denominator's second term dropped); F <= max(F0,
 * F90). Loose for smooth materials (their lobe is narrower than any order-2 moment can
 * tell), which then sum their far parts exactly.
 */
inline glm::dvec3 ComputePbrSpecularBound(
  double NdV, double roughness, const glm::dvec3& F0, const glm::dvec3& F90)
{
  const double pi = glm::pi<double>();
  const double a2 = roughness * roughness;
  const double dMax = 1.0 / (pi * std::max(a2 * a2, 1e-12));
  const double vMax = 0.5 / std::sqrt(std::max(a2 + NdV * NdV * (1.0 - a2), 1e-12));
  return dMax * vMax * glm::max(F0, F90);
}

/**
 * Mirrors the PBR far interval of the shading code for one channel c of the moments m
 * (FarFieldMomentsPerChannel doubles): the sum over far lights of g EvaluatePbrTerms lies in
 * [lower, upper] (see PbrMaterial).
 */
inline void ComputePbrFarInterval(const double* m, int c, const glm::dvec3& N, double NdV,
  const PbrMaterial& mat, double& lower, double& upper)
{
  const double pi = glm::pi<double>();
  double dLow = 0.0, dHigh = 0.0;
  ApplyMomentKernel(m, ComputeLobeKernel(1.0), N, false, 1.0, &dLow, &dHigh);
  const double lambert = (1.0 - mat.Metallic) * mat.Albedo[c] / pi;
  const double fMin = std::min(mat.F0[c], mat.F90[c]);
  const double fMax = std::max(mat.F0[c], mat.F90[c]);
  const double S = m[0];
  lower = lambert * std::max(1.0 - fMax, 0.0) * dLow;
  upper = lambert * std::max(1.0 - fMin, 0.0) * (dHigh + 1e-5 * S) +
    ComputePbrSpecularBound(NdV, mat.Roughness, mat.F0, mat.F90)[c] * S;
}

/**
 * The node moments as the shading code reads them: 14 RGBA32F 3D textures of the grid's
 * dimensions, texel (i, j, k) of texture q holding floats 4q..4q+3 in moment-major order
 * (moment m of channel c at 3 m + c: S, Vx, Vy, Vz, Txx, Tyy, Txy, Txz, Tyz, then the 9 of
 * F, each as RGB; the last 2 floats are 0). The order-2 moments fill the first 7 (the 28th
 * float is F400's red), which are all an order-2 far field reads. `out` holds 14 arrays of
 * 4 floats per node, node index order; nodes [n0, n1) are packed (ranges can be packed in
 * parallel).
 */
constexpr int FarFieldTextures = (3 * FarFieldMomentsPerChannel + 3) / 4;
/// The textures an order-2 far field reads (the first 27 floats), three channels or one.
constexpr int FarFieldOrder2Textures = (3 * FarFieldOrder2Moments + 3) / 4;
constexpr int FarFieldOrder2SharedColorTextures = (FarFieldOrder2Moments + 3) / 4;
inline void PackFarFieldTexels(const std::vector<double>& moments, std::size_t n0, std::size_t n1,
  std::array<std::vector<float>, FarFieldTextures>& out)
{
  for (std::size_t n = n0; n < n1; ++n)
  {
    const double* m = &moments[n * FarFieldFloatsPerNode];
    for (int moment = 0; moment < FarFieldMomentsPerChannel; ++moment)
    {
      for (int c = 0; c < 3; ++c)
      {
        const int q = 3 * moment + c;
        out[static_cast<std::size_t>(q / 4)][4 * n + static_cast<std::size_t>(q % 4)] =
          static_cast<float>(m[c * FarFieldMomentsPerChannel + moment]);
      }
    }
    for (int q = 3 * FarFieldMomentsPerChannel; q < 4 * FarFieldTextures; ++q)
    {
      out[static_cast<std::size_t>(q / 4)][4 * n + static_cast<std::size_t>(q % 4)] = 0.0f;
    }
  }
}

/**
 * The node moments of one channel (`channel`, 0 to 2) for a far field whose lights share a
 * colour (FindFarFieldSharedColor): 5 RGBA32F 3D textures, texel (i, j, k) of texture 0
 * holding (S, Vx, Vy, Vz), of texture 1 (Txx, Tyy, Txy, Txz), of texture 2 (Tyz, F400,
 * F310, F220), of texture 3 (F130, F040, F301, F211), of texture 4 (F121, F031, 0, 0).
 * `out` holds (at least) 5 arrays of 4 floats per node; nodes [n0, n1) are packed.
 */
constexpr int FarFieldSharedColorTextures = (FarFieldMomentsPerChannel + 3) / 4;
inline void PackFarFieldTexelsOneChannel(const std::vector<double>& moments, int channel,
  std::size_t n0, std::size_t n1, std::array<std::vector<float>, FarFieldTextures>& out)
{
  for (std::size_t n = n0; n < n1; ++n)
  {
    const double* m = &moments[n * FarFieldFloatsPerNode +
      static_cast<std::size_t>(channel) * FarFieldMomentsPerChannel];
    for (int moment = 0; moment < FarFieldMomentsPerChannel; ++moment)
    {
      out[static_cast<std::size_t>(moment / 4)][4 * n + static_cast<std::size_t>(moment % 4)] =
        static_cast<float>(m[moment]);
    }
    for (int q = FarFieldMomentsPerChannel; q < 4 * FarFieldSharedColorTextures; ++q)
    {
      out[static_cast<std::size_t>(q / 4)][4 * n + static_cast<std::size_t>(q % 4)] = 0.0f;
    }
  }
}

/**
 * VC -> far-field texture coordinates (column-major 4x4): the world position of a point
 * in view coordinates, then its place in the grid with node (i, j, k) at the centre of
 * texel (i, j, k). Composed in double precision (the eye-relative part stays exact).
 */
inline glm::dmat4 ComputeFarFieldTextureFromVC(const FarFieldGrid& g, const glm::dmat4& wcvc)
{
  glm::dmat4 gridFromWC(1.0);
  for (int a = 0; a < 3; ++a)
  {
    const double scale = 1.0 / (g.Spacing * g.Dims[a]);
    gridFromWC[a][a] = scale;
    gridFromWC[3][a] = -g.Origin[a] * scale + 0.5 / g.Dims[a];
  }
  return gridFromWC * glm::inverse(wcvc);
}

} // namespace vtkClusteredLighting

#endif
