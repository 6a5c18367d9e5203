// SPDX-License-Identifier: BSD-3-Clause
/**
 * A far specular from directional bins (ClusteredLightingFarFieldStudy --specular-bins):
 * a design measured on the CPU, not the product's.
 *
 * The order-2 (and order-4) moments hold the far light's angular shape too coarsely for a
 * Phong lobe of power 20, whose half-width is about 15 degrees: its Legendre series does
 * not converge by order 8 (docs/far-field.md, "What more angular resolution would buy").
 * A narrow lobe samples the far light's radiance near one direction, so the far light is
 * kept instead per direction bin: the sphere of directions is cut into K cells (the
 * directions nearest each of K axes), and every node holds, per bin and channel, the
 * order-1 moments of the far light whose direction falls in it, S_b = sum g and
 * V_b = sum g u (4 numbers; linear in the lights, so they interpolate trilinearly as the
 * moments do). At a fragment each bin is taken as a von Mises-Fisher distribution of its
 * light, mean direction V_b / |V_b|, concentration kappa from |V_b| / S_b (Banerjee's
 * estimate), and the Phong lobe as a spherical Gaussian exp(lambda (R.u - 1)) with
 * lambda = n + 1 (the same integral over the sphere for large n). Their product integrates
 * in closed form:
 *
 *   E[exp(lambda (R.u - 1))] = exp(-lambda) kappa sinh(m) / (sinh(kappa) m),
 *   m = |kappa mu + lambda R|,
 *
 * and VTK's lit side (N.u > 0) is taken as the share of that product's mass in front of
 * the surface (a normal approximation along N). The estimate is clamped into the order-2
 * interval of the moments, which holds the truth whatever the estimate.
 */
#ifndef SpecularBinsStudy_h
#define SpecularBinsStudy_h

#include "vtkClusteredLightingFarField.h"

#include <glm/gtx/component_wise.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace ClusteredLightingBenchmark
{
/// The axes of K bins: 6 (the cube's faces), 14 (and its corners), 26 (and its edges),
/// otherwise K points of a Fibonacci spiral.
inline std::vector<glm::dvec3> MakeSpecularBinAxes(int count)
{
  std::vector<glm::dvec3> axes;
  if (count == 6 || count == 14 || count == 26)
  {
    for (int x = -1; x <= 1; ++x)
    {
      for (int y = -1; y <= 1; ++y)
      {
        for (int z = -1; z <= 1; ++z)
        {
          const int nonzero = (x != 0) + (y != 0) + (z != 0);
          if (nonzero == 1 || (nonzero == 3 && count >= 14) || (nonzero == 2 && count == 26))
          {
            axes.push_back(glm::normalize(glm::dvec3(x, y, z)));
          }
        }
      }
    }
    return axes;
  }
  const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    axes.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return axes;
}

/// Nearest-axis lookup by a cube map of directions (6 x Size^2 texels).
struct SpecularBinTable
{
  static constexpr int Size = 128;
  std::vector<glm::dvec3> Axes;
  std::vector<std::uint16_t> Bin;

  static int Texel(const glm::dvec3& u)
  {
    const glm::dvec3 a = glm::abs(u);
    int face, s, t;
    double x, y, m;
    if (a.x >= a.y && a.x >= a.z)
    {
      face = u.x > 0 ? 0 : 1;
      m = a.x;
      x = u.y;
      y = u.z;
    }
    else if (a.y >= a.z)
    {
      face = u.y > 0 ? 2 : 3;
      m = a.y;
      x = u.x;
      y = u.z;
    }
    else
    {
      face = u.z > 0 ? 4 : 5;
      m = a.z;
      x = u.x;
      y = u.y;
    }
    s = std::min(Size - 1, static_cast<int>((x / m * 0.5 + 0.5) * Size));
    t = std::min(Size - 1, static_cast<int>((y / m * 0.5 + 0.5) * Size));
    return (face * Size + t) * Size + s;
  }

  explicit SpecularBinTable(int count)
    : Axes(MakeSpecularBinAxes(count))
    , Bin(static_cast<std::size_t>(6 * Size * Size))
  {
    for (int face = 0; face < 6; ++face)
    {
      for (int t = 0; t < Size; ++t)
      {
        for (int s = 0; s < Size; ++s)
        {
          const double x = (s + 0.5) / Size * 2.0 - 1.0, y = (t + 0.5) / Size * 2.0 - 1.0;
          const double sign = face % 2 == 0 ? 1.0 : -1.0;
          const glm::dvec3 u =
            glm::normalize(face < 2 ? glm::dvec3(sign, x, y)
                                    : (face < 4 ? glm::dvec3(x, sign, y) : glm::dvec3(x, y, sign)));
          std::size_t best = 0;
          if (count == 26)
          {
            // The product's cells: each component's sign where it exceeds tan(22.5 deg)
            // of the largest, else 0 (3 x 3 cells per face of the cube).
            const double m = glm::compMax(glm::abs(u)) * std::tan(glm::pi<double>() / 8.0);
            const glm::dvec3 digit(u.x > m ? 1 : (u.x < -m ? -1 : 0),
              u.y > m ? 1 : (u.y < -m ? -1 : 0), u.z > m ? 1 : (u.z < -m ? -1 : 0));
            const glm::dvec3 axis = glm::normalize(digit);
            for (std::size_t b = 0; b < this->Axes.size(); ++b)
            {
              best = glm::dot(axis, this->Axes[b]) > 1.0 - 1e-9 ? b : best;
            }
          }
          else
          {
            for (std::size_t b = 1; b < this->Axes.size(); ++b)
            {
              best = glm::dot(u, this->Axes[b]) > glm::dot(u, this->Axes[best]) ? b : best;
            }
          }
          this->Bin[static_cast<std::size_t>((face * Size + t) * Size + s)] =
            static_cast<std::uint16_t>(best);
        }
      }
    }
  }

  std::size_t Count() const { return this->Axes.size(); }
  std::size_t Of(const glm::dvec3& u) const
  {
    return this->Bin[static_cast<std::size_t>(Texel(u))];
  }
};

/// Floats per bin: S and V per channel.
constexpr std::size_t SpecularBinFloats = 12;

/// Adds a far part g (colour c) from unit direction u into bins (Count() x 12).
inline void AddToSpecularBins(
  const SpecularBinTable& table, const glm::dvec3& c, double g, const glm::dvec3& u, double* bins)
{
  double* b = bins + table.Of(u) * SpecularBinFloats;
  for (int ch = 0; ch < 3; ++ch)
  {
    b[4 * ch] += c[ch] * g;
    b[4 * ch + 1] += c[ch] * g * u.x;
    b[4 * ch + 2] += c[ch] * g * u.y;
    b[4 * ch + 3] += c[ch] * g * u.z;
  }
}

/// The bins' Phong far specular of one bin's (S, V) (see the header comment).
inline double EvaluateSpecularBin(
  double S, const glm::dvec3& V, const glm::dvec3& N, const glm::dvec3& R, double n)
{
  if (!(S > 0.0))
  {
    return 0.0;
  }
  const double len = glm::length(V);
  const double rho = std::min(len / S, 0.999);
  const glm::dvec3 mu = len > 0.0 ? V / len : R;
  const double kappa = rho * (3.0 - rho * rho) / (1.0 - rho * rho);
  const double lambda = n + 1.0;
  const glm::dvec3 w = kappa * mu + lambda * R;
  const double m = glm::length(w);
  const double kappaTerm = kappa > 1e-8 ? kappa / -std::expm1(-2.0 * kappa) : 0.5;
  const double mTerm = -std::expm1(-2.0 * m) / m;
  const double e = std::exp(m - kappa - lambda) * kappaTerm * mTerm;
  // The lit side: the share of the product's mass with N.u > 0.
  const glm::dvec3 a = w / m;
  const double na = glm::dot(N, a);
  const double sd = std::sqrt(std::max(1.0 - na * na, 1.0 / m) / m);
  const double lit = 0.5 * std::erfc(-na / (sd * std::sqrt(2.0)));
  return S * e * lit;
}

/// As EvaluateSpecularBins, with one direction per bin for all channels: the channels'
/// sums of S and V give the direction and concentration, each channel its own S.
inline glm::dvec3 EvaluateSpecularBinsSharedDirection(const SpecularBinTable& table,
  const double* bins, const glm::dvec3& N, const glm::dvec3& R, double n)
{
  glm::dvec3 out(0.0);
  for (std::size_t b = 0; b < table.Count(); ++b)
  {
    const double* q = bins + b * SpecularBinFloats;
    const double S = q[0] + q[4] + q[8];
    const glm::dvec3 V(q[1] + q[5] + q[9], q[2] + q[6] + q[10], q[3] + q[7] + q[11]);
    const double unit = S > 0.0 ? EvaluateSpecularBin(1.0, V / S, N, R, n) : 0.0;
    out += unit * glm::dvec3(q[0], q[4], q[8]);
  }
  return out;
}

/// The far specular per channel from bins (Count() x 12), unclamped.
inline glm::dvec3 EvaluateSpecularBins(const SpecularBinTable& table, const double* bins,
  const glm::dvec3& N, const glm::dvec3& R, double n)
{
  glm::dvec3 out(0.0);
  for (std::size_t b = 0; b < table.Count(); ++b)
  {
    const double* q = bins + b * SpecularBinFloats;
    for (int ch = 0; ch < 3; ++ch)
    {
      out[ch] += EvaluateSpecularBin(
        q[4 * ch], glm::dvec3(q[4 * ch + 1], q[4 * ch + 2], q[4 * ch + 3]), N, R, n);
    }
  }
  return out;
}
}

#endif
