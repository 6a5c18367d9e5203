// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file FarBlocksStudy.h
 * @brief A design measured and not adopted (ClusteredLightingFarFieldStudy --blocks): the far
 *        field's exact sums to a tolerance from bounds of blocks of 32 lights.
 *
 * Where the far field's moments leave a fragment too uncertain (FarFieldTolerance), the
 * shading code sums the far parts of every light exactly. The idea measured here: lights are
 * stored in Morton order, so 32 consecutive lights lie close together, and seen from a point
 * such a block's far parts are bounded by one interval (a one-level light cut, after
 * Lightcuts, Walter et al., SIGGRAPH 2005):
 *  - distance: every light of the block lies in a sphere (centre c, radius rho), so its
 *    distance d lies in [max(|c - P| - rho, 0), |c - P| + rho];
 *  - attenuation times (1 - W(d / r)): VTK's 1 / (a0 + a1 d + a2 d^2) falls with d and with
 *    every coefficient, (1 - W) rises with d and falls with the near radius r, so the
 *    block's least and largest coefficients and near radii bound every light's far part;
 *  - direction: the cosine between a unit direction D (the normal, or the mirrored view)
 *    and any direction from P into the sphere lies in [cos(alpha + theta), cos(alpha -
 *    theta)], alpha the angle to the centre, theta the sphere's half angle;
 *  - colour: the block's summed colour x intensity multiplies both ends.
 * The sum (SumFarPartsByBlocks) makes two passes: every block's interval, its width in
 * colour units binned by powers of 2 of the tolerance; then the narrowest bins whose widths
 * add up to at most the tolerance take their midpoints and the other blocks are summed
 * light by light. The result is within half the tolerance of the exact sum, per channel.
 *
 * Why it was not adopted: the widths are first order in rho / |c - P|, and the tolerance
 * (2/255) is a small fraction of the far light at a point, so almost every block is
 * summed light by light (docs/far-field.md, "Exact sums by blocks of 32 lights").
 */
#ifndef FarBlocksStudy_h
#define FarBlocksStudy_h

#include "vtkClusteredLightingFarField.h" // for ComputeFarContribution
#include "vtkClusteredLightingLights.h"   // for PreparedLight

#include <algorithm> // for std::min, std::max
#include <array>     // for std::array
#include <cmath>     // for std::sqrt, std::pow, std::log2, std::floor
#include <glm/glm.hpp>
#include <limits> // for std::numeric_limits
#include <vector> // for std::vector

namespace ClusteredLightingStudy
{
using namespace vtkClusteredLighting;

constexpr int LightsPerFarBlock = 32;
/// Width bins of the first pass: bin k holds widths in [2^(k-12), 2^(k-11)) tolerances
/// (bin 0 everything narrower, bin 15 everything wider).
constexpr int FarBlockBins = 16;

/// One block of LightsPerFarBlock consecutive lights (upload order), its far-field lights
/// only (spot lights and lights with an explicit radius have no far part).
struct FarBlock
{
  glm::dvec3 Center{ 0.0 }; ///< bounding sphere of the lights' positions
  double Radius = 0.0;
  glm::dvec3 Color{ 0.0 }; ///< sum of colour x intensity
  double NearRadiusMin = 1.0;
  double NearRadiusMax = 1.0;
  glm::dvec3 AttenuationMin{ 0.0 }; ///< least (a0, a1, a2) over the lights, each on its own
  glm::dvec3 AttenuationMax{ 0.0 }; ///< largest
  int Count = 0;                    ///< far-field lights in the block (0: empty)
};

/// Blocks of the lights in their stored order (world coordinates).
inline std::vector<FarBlock> ComputeFarBlocks(const std::vector<PreparedLight>& lights)
{
  const std::size_t n = lights.size();
  std::vector<FarBlock> blocks((n + LightsPerFarBlock - 1) / LightsPerFarBlock);
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    FarBlock& k = blocks[b];
    const std::size_t first = b * LightsPerFarBlock;
    const std::size_t last = std::min(first + LightsPerFarBlock, n);
    glm::dvec3 lo(inf), hi(-inf);
    double rMin = inf, rMax = 0.0;
    glm::dvec3 aMin(inf), aMax(0.0);
    for (std::size_t i = first; i < last; ++i)
    {
      const PreparedLight& l = lights[i];
      if (!l.FarField)
      {
        continue;
      }
      ++k.Count;
      lo = glm::min(lo, l.PositionWC);
      hi = glm::max(hi, l.PositionWC);
      k.Color += l.Color;
      rMin = std::min(rMin, l.Radius);
      rMax = std::max(rMax, l.Radius);
      aMin = glm::min(aMin, l.Attenuation);
      aMax = glm::max(aMax, l.Attenuation);
    }
    if (k.Count == 0)
    {
      continue;
    }
    k.Center = 0.5 * (lo + hi);
    for (std::size_t i = first; i < last; ++i)
    {
      if (lights[i].FarField)
      {
        k.Radius = std::max(k.Radius, glm::length(lights[i].PositionWC - k.Center));
      }
    }
    k.Radius *= 1.0 + 1e-9; // rounding
    k.NearRadiusMin = rMin;
    k.NearRadiusMax = rMax;
    k.AttenuationMin = aMin;
    k.AttenuationMax = aMax;
  }
  return blocks;
}

/// The least and largest cosine between the unit direction D and the directions from a
/// point into a sphere whose centre is `toC` away (|toC| = dc) and whose radius is rho.
inline glm::dvec2 ComputeConeCosineRange(
  const glm::dvec3& D, const glm::dvec3& toC, double dc, double rho)
{
  if (!(dc > rho))
  {
    return glm::dvec2(-1.0, 1.0);
  }
  const double s = rho / dc; // sin(theta)
  const double cs = std::sqrt(std::max(1.0 - s * s, 0.0));
  const double ca = std::min(std::max(glm::dot(D, toC) / dc, -1.0), 1.0); // cos(alpha)
  const double sa = std::sqrt(std::max(1.0 - ca * ca, 0.0));
  const double hi = ca >= cs ? 1.0 : ca * cs + sa * s;   // alpha <= theta: 1
  const double lo = -ca >= cs ? -1.0 : ca * cs - sa * s; // alpha + theta >= pi: -1
  return glm::dvec2(lo, hi);
}

/// The least and largest far part per unit colour of any light of the block at a distance
/// in [dMin, dMax] (VTK's attenuation times 1 - W(d / r)).
inline glm::dvec2 ComputeFarBlockAttenuationRange(const FarBlock& b, double dMin, double dMax)
{
  const glm::dvec3& a = b.AttenuationMin;
  const glm::dvec3& A = b.AttenuationMax;
  const double hi = (1.0 - EvaluateSplitWindow(dMax / b.NearRadiusMin)) /
    std::max(a.x + a.y * dMin + a.z * dMin * dMin, 1e-30);
  const double lo = (1.0 - EvaluateSplitWindow(dMin / b.NearRadiusMax)) /
    std::max(A.x + A.y * dMax + A.z * dMax * dMax, 1e-30);
  return glm::dvec2(lo, hi);
}

/// A block's far parts at a Phong fragment, per unit of the block's colour: diffuse
/// [x, y] and specular [z, w] (specular is 0 without `specular`).
inline glm::dvec4 ComputeFarBlockPhongInterval(const FarBlock& b, const glm::dvec3& P,
  const glm::dvec3& N, const glm::dvec3& R, double power, bool specular = true)
{
  const glm::dvec3 toC = b.Center - P;
  const double dc = glm::length(toC);
  const glm::dvec2 g =
    ComputeFarBlockAttenuationRange(b, std::max(dc - b.Radius, 0.0), dc + b.Radius);
  const glm::dvec2 cn = ComputeConeCosineRange(N, toC, dc, b.Radius);
  glm::dvec4 out(std::max(cn.x, 0.0) * g.x, std::max(cn.y, 0.0) * g.y, 0.0, 0.0);
  if (specular)
  {
    const glm::dvec2 cr = ComputeConeCosineRange(R, toC, dc, b.Radius);
    out.z = cn.x > 0.0 && cr.x > 0.0 ? std::pow(cr.x, power) * g.x : 0.0;
    out.w = cn.y > 0.0 && cr.y > 0.0 ? std::pow(cr.y, power) * g.y : 0.0;
  }
  return out;
}

/// The bin of a width w > 0 for tolerance tau (FarBlockBins).
inline int GetFarBlockBin(double w, double tau)
{
  const double k = std::floor(std::log2(w / tau)) + 12.0;
  return static_cast<int>(std::min(std::max(k, 0.0), static_cast<double>(FarBlockBins - 1)));
}

/// The number t of bins, from the narrowest up, whose widths add up to at most tau. Blocks
/// of bins below t take their midpoints.
inline int ChooseFarBlockThreshold(const std::array<double, FarBlockBins>& bins, double tau)
{
  double taken = 0.0;
  int t = 0;
  while (t < FarBlockBins && taken + bins[static_cast<std::size_t>(t)] <= tau)
  {
    taken += bins[static_cast<std::size_t>(t)];
    ++t;
  }
  return t;
}

/// What SumFarPartsByBlocks did.
struct FarBlockSumStatistics
{
  int BlocksVisited = 0; ///< non-empty block intervals computed, both passes
  int LightsSummed = 0;  ///< lights of refined blocks, each summed exactly
};

/// Adds light l's far part at a Phong point to the diffuse d and (with `specular`) the
/// specular sp, per unit material; false when the light has none there.
inline bool AddFarPartPhong(const PreparedLight& l, const glm::dvec3& P, const glm::dvec3& N,
  const glm::dvec3& R, double power, bool specular, glm::dvec3& d, glm::dvec3& sp)
{
  double far = 0.0;
  glm::dvec3 toLight(0.0);
  if (!l.FarField || !ComputeFarContribution(l, l.Radius, P, far, toLight))
  {
    return false;
  }
  const double nl = glm::dot(N, toLight);
  if (nl > 0.0)
  {
    d += far * nl * l.Color;
    const double rl = glm::dot(R, toLight);
    sp += specular && rl > 0.0 ? far * std::pow(rl, power) * l.Color : glm::dvec3(0.0);
  }
  return true;
}

/**
 * The far parts of `lights` at a Phong point (world coordinates), summed to within tau / 2
 * per channel in colour units, kd and ks being the material's diffuse and specular colours:
 * diffuse and specular per unit material, as the shading code adds them.
 */
inline void SumFarPartsByBlocks(const std::vector<PreparedLight>& lights,
  const std::vector<FarBlock>& blocks, const glm::dvec3& P, const glm::dvec3& N,
  const glm::dvec3& V, double power, const glm::dvec3& kd, const glm::dvec3& ks, double tau,
  glm::dvec3& diffuse, glm::dvec3& specular, FarBlockSumStatistics* stats = nullptr)
{
  FarBlockSumStatistics s;
  const glm::dvec3 R = 2.0 * glm::dot(N, V) * N - V;
  const bool spec = ks != glm::dvec3(0.0);
  // A block's interval (diffuse [x, y], specular [z, w] per unit colour) and its width in
  // colour units, the largest over the channels.
  const auto interval = [&](const FarBlock& b, double& width)
  {
    ++s.BlocksVisited;
    const glm::dvec4 i = ComputeFarBlockPhongInterval(b, P, N, R, power, spec);
    const glm::dvec3 w = ((i.y - i.x) * kd + (i.w - i.z) * ks) * b.Color;
    width = std::max(std::max(w.x, w.y), w.z);
    return i;
  };
  // Pass 1: every block's midpoint, its width binned.
  std::array<double, FarBlockBins> bins{};
  glm::dvec3 midD(0.0), midS(0.0);
  double total = 0.0;
  for (const FarBlock& b : blocks)
  {
    if (b.Color == glm::dvec3(0.0))
    {
      continue;
    }
    double width = 0.0;
    const glm::dvec4 i = interval(b, width);
    midD += 0.5 * (i.x + i.y) * b.Color;
    midS += 0.5 * (i.z + i.w) * b.Color;
    if (width > 0.0)
    {
      bins[static_cast<std::size_t>(GetFarBlockBin(width, tau))] += width;
      total += width;
    }
  }
  diffuse = midD;
  specular = midS;
  if (total > tau)
  {
    // Pass 2: the blocks of the bins past the threshold, light by light.
    const int t = ChooseFarBlockThreshold(bins, tau);
    diffuse = specular = glm::dvec3(0.0);
    for (std::size_t k = 0; k < blocks.size(); ++k)
    {
      const FarBlock& b = blocks[k];
      if (b.Color == glm::dvec3(0.0))
      {
        continue;
      }
      double width = 0.0;
      const glm::dvec4 i = interval(b, width);
      if (!(width > 0.0) || GetFarBlockBin(width, tau) < t)
      {
        diffuse += 0.5 * (i.x + i.y) * b.Color;
        specular += 0.5 * (i.z + i.w) * b.Color;
        continue;
      }
      const std::size_t last = std::min((k + 1) * LightsPerFarBlock, lights.size());
      for (std::size_t j = k * LightsPerFarBlock; j < last; ++j)
      {
        s.LightsSummed += AddFarPartPhong(lights[j], P, N, R, power, spec, diffuse, specular);
      }
    }
  }
  if (stats)
  {
    *stats = s;
  }
}

/// The exact far parts of `lights` at a Phong point (world coordinates), diffuse and
/// specular per unit material: the reference of SumFarPartsByBlocks.
inline void SumFarPartsExactly(const std::vector<PreparedLight>& lights, const glm::dvec3& P,
  const glm::dvec3& N, const glm::dvec3& V, double power, glm::dvec3& diffuse, glm::dvec3& specular)
{
  const glm::dvec3 R = 2.0 * glm::dot(N, V) * N - V;
  diffuse = specular = glm::dvec3(0.0);
  for (const PreparedLight& l : lights)
  {
    AddFarPartPhong(l, P, N, R, power, true, diffuse, specular);
  }
}

} // namespace ClusteredLightingStudy

#endif
