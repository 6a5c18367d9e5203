// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFarSpecularBins.h
 * @brief GL-free far specular from directional bins: the far light per direction cell.
 *
 * Why. The far field's moments (vtkClusteredLightingFarField.h) give the far diffuse to
 * order 4, but a Phong lobe of power 20 falls to half its peak 15 degrees from its axis,
 * and its Legendre series does not converge by order 8: with 65,536 lights the order-2
 * lobe left 90 of 60,000 channel values more than 2 steps off, all of them where the far
 * specular was (docs/far-field.md, "A far specular from directional bins"). A narrow lobe
 * reads the far light near one direction, so for it the far light is kept per direction.
 *
 * Bins. The sphere of directions is cut into 26 cells: a unit direction u falls in the
 * cell of the digits (sx, sy, sz), each component's sign where it exceeds tan(22.5 deg)
 * times the largest component's magnitude, else 0 (the cube's faces, edges and corners;
 * each face of the cube cut 3 x 3; ComputeFarSpecularBin, mirrored by the build). Every
 * grid node holds, per bin, the far light whose direction from the node falls in the bin:
 * its sum per channel, S_c = sum g c_c, and its direction sum over the channels,
 * V = sum g (c_r + c_g + c_b) u (FarSpecularBinFloats = 6 numbers; with a shared colour,
 * one channel's S and V: 4). Both are linear in the lights, so they interpolate
 * trilinearly between nodes as the moments do.
 *
 * Shading (EvaluateFarSpecularBins, mirrored by clFarSpecularBins in the shader). Each bin
 * is taken as a von Mises-Fisher distribution of its light, mean direction mu = V / |V|,
 * concentration kappa from rho = |V| / (S_r + S_g + S_b) by Banerjee's estimate
 * rho (3 - rho^2) / (1 - rho^2), and the Phong lobe max(0, R.u)^n as the spherical
 * Gaussian exp(lambda (R.u - 1)), lambda = n + 1 (the same integral over the sphere for a
 * large n). Their product integrates in closed form:
 *
 *   E[exp(lambda (R.u - 1))] = exp(m - kappa - lambda) kappa (1 - exp(-2m))
 *                              / (m (1 - exp(-2 kappa))),   m = |kappa mu + lambda R|,
 *
 * and VTK's lit side (N.u > 0: no specular from a light behind the surface) is taken as
 * the share of the product's mass in front of the surface, the product being about a vMF
 * of axis a = (kappa mu + lambda R) / m and concentration m: N.u about normal with mean
 * N.a and variance max(1 - (N.a)^2, 1 / m) / m, its share above 0 that of the normal
 * distribution (ComputeNormalShare). A channel's estimate
 * is the sum over bins of S_c times that factor, clamped into the interval the moments
 * prove (ApplyMomentKernel's for the lobe), which holds the truth whatever the estimate.
 *
 * Only for powers of at least FarSpecularBinsLeastPower: the spherical Gaussian is a poor
 * Phong lobe at low powers, where the moments' lobe converges and serves
 * (vtkClusteredLightingLobeProjection.h).
 *
 * Bins out of reach. Every direction of a cell lies within FarSpecularBinCellRadius
 * (30.4 degrees, at the cell's corners) of its axis. A bin is read only where some direction
 * of its cell can matter (IsFarSpecularBinInReach, the shader reads only those):
 *  - in reach of the lobe: max(0, R.u)^n <= exp(n (R.u - 1)) falls below
 *    FarSpecularBinLobeFloor (1/4096) of the light beyond an angle theta_n from R
 *    (GetFarSpecularBinReach), so a cell whose axis is farther than theta_n plus the cell's
 *    radius from R holds no light the lobe lets through by more than that share;
 *  - in front of the surface: a cell whose axis is more than 90 degrees plus its radius from
 *    N holds only lights behind it, whose specular VTK leaves 0.
 * On average 10.7 of the 26 bins are read at power 20, 16.3 at 8 and 4.8 at 128 (over
 * random views, Core.FarSpecularBins.BinsOutOfReachHoldNoLightTheLobeLetsThrough). What a
 * skipped bin's lights add, seen from the nodes, is at most 1/4096 of their light
 * times Ks; the estimate is then clamped as before, and the stated bound's term
 * (vtkClusteredLightingFarFieldBound.h) is for this estimate, skipped bins and all.
 */
#ifndef vtkClusteredLightingFarSpecularBins_h
#define vtkClusteredLightingFarSpecularBins_h

#include <algorithm> // for std::max
#include <array>     // for std::array
#include <cmath>     // for std::exp, std::acos
#include <cstddef>   // for std::size_t, std::ptrdiff_t
#include <glm/glm.hpp>
#include <vector> // for std::vector

namespace vtkClusteredLighting
{
/// Direction bins of the far specular, and the numbers each holds per node: S per channel
/// (3), then V (3).
constexpr int FarSpecularBins = 26;
constexpr int FarSpecularBinFloats = 6;
constexpr int FarSpecularFloatsPerNode = FarSpecularBins * FarSpecularBinFloats;
/// tan(22.5 degrees): where a component's digit changes (see the file description).
constexpr double FarSpecularBinEdge = 0.41421356237309503;
/// The least specular power the bins serve (see the file description).
constexpr double FarSpecularBinsLeastPower = 8.0;
/// cos of a cell's angular radius: the least cosine between a direction of a cell and its
/// axis, 1 / sqrt(1 + 2 tan^2(22.5 deg)) at the corners of a face's cell (30.4 degrees).
constexpr double FarSpecularBinCellRadius = 0.86285620946101682;
/// The share of a bin's light below which its lobe leaves it out (see the file
/// description).
constexpr double FarSpecularBinLobeFloor = 1.0 / 4096.0;

/// The bin (0 to 25) of direction (x, y, z), any length but 0. Branch-free, for the build's
/// vectorized loops.
template <typename T>
inline int ComputeFarSpecularBin(T x, T y, T z)
{
  const T m =
    std::max(std::max(std::abs(x), std::abs(y)), std::abs(z)) * static_cast<T>(FarSpecularBinEdge);
  const int dx = (x > m) - (x < -m), dy = (y > m) - (y < -m), dz = (z > m) - (z < -m);
  const int i = 9 * (dx + 1) + 3 * (dy + 1) + (dz + 1);
  return i - (i > 13 ? 1 : 0);
}

/// The unit axis of bin b (its digits, normalized).
inline glm::dvec3 GetFarSpecularBinAxis(int b)
{
  const int i = b + (b >= 13 ? 1 : 0);
  return glm::normalize(glm::dvec3(i / 9 - 1, (i / 3) % 3 - 1, i % 3 - 1));
}

/// The standard normal distribution's share below x, Phi(x) = erfc(-x / sqrt(2)) / 2, by
/// Abramowitz and Stegun's 7.1.26 (absolute error below 1.5e-7; GLSL has no erfc).
inline double ComputeNormalShare(double x)
{
  const double z = std::abs(x) / std::sqrt(2.0);
  const double t = 1.0 / (1.0 + 0.3275911 * z);
  const double poly = t *
    (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  const double tail = 0.5 * poly * std::exp(-z * z); // the share beyond |x|
  return x >= 0.0 ? 1.0 - tail : tail;
}

/**
 * The least cosine between R and a bin's axis for which the bin is read at power n: the
 * cosine of theta_n + the cell's radius, where exp(n (cos theta_n - 1)) =
 * FarSpecularBinLobeFloor (-1: every bin, where that angle passes 180 degrees). Mirrored by
 * clFarSpecularBinReach.
 */
inline double GetFarSpecularBinReach(double n)
{
  const double c = 1.0 + std::log(FarSpecularBinLobeFloor) / std::max(n, 1e-6);
  const double angle =
    std::acos(std::max(-1.0, std::min(1.0, c))) + std::acos(FarSpecularBinCellRadius);
  return angle >= 3.14159265358979 ? -1.0 : std::cos(angle);
}

/// Whether bin b is read at unit normal N and mirrored view R (see the file description):
/// its axis within the lobe's reach of R (`reach`, GetFarSpecularBinReach) and some of its
/// cell in front of the surface. Mirrored by the shader's mask of bins.
inline bool IsFarSpecularBinInReach(int b, const glm::dvec3& N, const glm::dvec3& R, double reach)
{
  const glm::dvec3 a = GetFarSpecularBinAxis(b);
  const double sc = std::sqrt(1.0 - FarSpecularBinCellRadius * FarSpecularBinCellRadius);
  return glm::dot(R, a) >= reach && glm::dot(N, a) >= -sc;
}

/**
 * The far specular of one bin per unit of its light S: its light S (all channels summed)
 * and direction sum V, at unit normal N, unit mirrored view R and power n (see the file
 * description). 0 where the bin is empty.
 */
inline double EvaluateFarSpecularBinLobe(
  double S, const glm::dvec3& V, const glm::dvec3& N, const glm::dvec3& R, double n)
{
  if (!(S > 0.0))
  {
    return 0.0;
  }
  const double len = glm::length(V);
  const double rho = std::min(len / S, 0.9999);
  const glm::dvec3 mu = len > 0.0 ? V / len : R;
  const double kappa = rho * (3.0 - rho * rho) / (1.0 - rho * rho);
  const double lambda = n + 1.0;
  const glm::dvec3 w = kappa * mu + lambda * R;
  const double m = glm::length(w);
  const double kappaTerm =
    kappa > 1e-3 ? kappa / (1.0 - std::exp(-2.0 * kappa)) : 0.5 + 0.5 * kappa;
  const double mTerm = m > 1e-3 ? (1.0 - std::exp(-2.0 * m)) / m : 2.0 - 2.0 * m;
  const double e = std::exp(m - kappa - lambda) * kappaTerm * mTerm;
  const double na = m > 1e-3 ? glm::dot(N, w) / m : 0.0;
  const double sd = std::sqrt(std::max(1.0 - na * na, 1.0 / std::max(m, 1e-3)) / std::max(m, 1e-3));
  return e * ComputeNormalShare(na / sd);
}

/**
 * The bins' far specular per channel, unclamped: bins holds FarSpecularFloatsPerNode
 * numbers (FarSpecularBins x (S_r, S_g, S_b, V)); only the bins in reach
 * (IsFarSpecularBinInReach) are read.
 */
inline glm::dvec3 EvaluateFarSpecularBins(
  const double* bins, const glm::dvec3& N, const glm::dvec3& R, double n)
{
  glm::dvec3 out(0.0);
  const double reach = GetFarSpecularBinReach(n);
  for (int b = 0; b < FarSpecularBins; ++b)
  {
    if (!IsFarSpecularBinInReach(b, N, R, reach))
    {
      continue;
    }
    const double* q = bins + static_cast<std::ptrdiff_t>(b) * FarSpecularBinFloats;
    const glm::dvec3 S(q[0], q[1], q[2]);
    out += S * EvaluateFarSpecularBinLobe(S.x + S.y + S.z, glm::dvec3(q[3], q[4], q[5]), N, R, n);
  }
  return out;
}

/// Adds a far part g of colour c from unit direction u into bins (FarSpecularFloatsPerNode,
/// double, or float as the build stores them), its direction sum shortened by
/// `concentration` (a group's: GetFarSpecularGroupSpread).
template <typename T>
inline void AddToFarSpecularBins(
  const glm::dvec3& c, double g, const glm::dvec3& u, T* bins, double concentration = 1.0)
{
  T* q =
    bins + static_cast<std::ptrdiff_t>(ComputeFarSpecularBin(u.x, u.y, u.z)) * FarSpecularBinFloats;
  const double sum = g * (c.x + c.y + c.z) * concentration;
  q[0] += static_cast<T>(g * c.x);
  q[1] += static_cast<T>(g * c.y);
  q[2] += static_cast<T>(g * c.z);
  q[3] += static_cast<T>(sum * u.x);
  q[4] += static_cast<T>(sum * u.y);
  q[5] += static_cast<T>(sum * u.z);
}
/**
 * The texture of the bins: one RGBA32F 3D texture of the grid's size but along `axis`
 * (the grid's shallowest, GetFarSpecularBinAxis) GetFarSpecularBinSlabs(oneChannel) times
 * as many texels, the slabs stacked along it: slab s holds node (i, j, k) at (s Dx + i, j,
 * k) for axis 0, (i, s Dy + j, k) for 1, (i, j, s Dz + k) for 2. Three channels: two slabs
 * per bin, (S_r, S_g, S_b, 0) then (Vx, Vy, Vz, 0); a shared colour (`channel` 0 to 2):
 * one, (S_channel, Vx, Vy, Vz). The shader interpolates within a slab (its coordinate
 * along the axis clamped to the slab's texel centres, so the filter never mixes two slabs).
 */
inline int GetFarSpecularBinSlabs(bool oneChannel)
{
  return oneChannel ? FarSpecularBins : 2 * FarSpecularBins;
}

/// The axis the slabs are stacked along: the grid's shallowest (the texture's size along it
/// is the slabs times its nodes).
inline int GetFarSpecularBinAxis(const std::array<int, 3>& dims)
{
  return dims[0] <= dims[1] && dims[0] <= dims[2] ? 0 : (dims[1] <= dims[2] ? 1 : 2);
}

/// Packs nodes [n0, n1) (node index i + Dx (j + Dy k), grid dims `dims`) of `bins`
/// (FarSpecularFloatsPerNode per node, as the build sums them) into `texels` (4 floats per texel,
/// slabs stacked along `axis`, GetFarSpecularBinSlabs times the nodes in all). `channel` -1: three
/// channels.
inline void PackFarSpecularBinTexels(const std::vector<float>& bins, int channel,
  const std::array<int, 3>& dims, int axis, std::size_t n0, std::size_t n1,
  std::vector<float>& texels)
{
  const std::size_t dx = static_cast<std::size_t>(dims[0]), dy = static_cast<std::size_t>(dims[1]);
  // Texel (x, y, z) of the stacked texture, its size along `axis` times the slabs.
  const std::size_t slabs = static_cast<std::size_t>(GetFarSpecularBinSlabs(channel >= 0));
  const std::size_t tx = axis == 0 ? dx * slabs : dx, ty = axis == 1 ? dy * slabs : dy;
  auto texel = [&](std::size_t slab, std::size_t n)
  {
    std::size_t c[3] = { n % dx, (n / dx) % dy, n / (dx * dy) };
    c[axis] += slab * static_cast<std::size_t>(dims[static_cast<std::size_t>(axis)]);
    return 4 * (c[0] + tx * (c[1] + ty * c[2]));
  };
  for (std::size_t n = n0; n < n1; ++n)
  {
    for (int b = 0; b < FarSpecularBins; ++b)
    {
      const float* q =
        &bins[n * FarSpecularFloatsPerNode + static_cast<std::size_t>(b) * FarSpecularBinFloats];
      if (channel >= 0)
      {
        float* t = &texels[texel(static_cast<std::size_t>(b), n)];
        t[0] = q[channel];
        t[1] = q[3];
        t[2] = q[4];
        t[3] = q[5];
      }
      else
      {
        float* s = &texels[texel(2 * static_cast<std::size_t>(b), n)];
        float* v = &texels[texel(2 * static_cast<std::size_t>(b) + 1, n)];
        for (int c = 0; c < 3; ++c)
        {
          s[c] = q[c];
          v[c] = q[3 + c];
        }
        s[3] = v[3] = 0.0f;
      }
    }
  }
}
} // namespace vtkClusteredLighting

#endif
