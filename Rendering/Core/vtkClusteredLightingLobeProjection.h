// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingLobeProjection.h
 * @brief GL-free: the far field's Phong specular kernel, VTK's lobe on the lit side only.
 *
 * VTK's Phong specular of a positional light at a surface point with unit normal N and
 * mirrored view R = 2 (N.V) N - V is max(0, R.L)^n, and 0 where the light is behind the
 * surface (N.L <= 0: `sign(df)` in vtkOpenGLPolyDataMapper's shader). The far field holds
 * the order-2 moments of the far light's directions (S, V, T: vtkClusteredLightingFarField.h),
 * so what it can give is the sum over far lights of an order-2 polynomial of L: the best
 * one (least squares over the sphere) is the order-2 spherical-harmonic projection of
 *
 *   g(L) = H(N.L) max(0, R.L)^n.
 *
 * A zonal lobe about R (its Legendre coefficients, ComputeLobeKernel) drops H(N.L), which
 * is harmless for narrow lobes but not for broad ones: at n = 1 (VTK's default power) the
 * lobe is the hemisphere about R, up to half of which lies behind the surface where R is
 * far from N, and the far specular came out too bright by up to 19 8-bit steps in
 * Examples/Python/user_lights.py (docs/far-field.md, "Low specular powers").
 *
 * The projection. With G0 = int g, G1 = int g L, G2 = int g L L^T over the sphere, the
 * addition theorem gives the projection
 *
 *   q(L) = G0 / (4 pi) + (3 / (4 pi)) G1.L + (5 / (8 pi)) (3 L^T G2 L - G0),
 *
 * and summed over the far lights with weights w: sum w q(L) is linear in S, V and T. In the
 * frame of R (z) and X = (N - c R) / |N - c R| (x, c = N.R = N.V, so N = s X + c R with
 * s = sqrt(1 - c^2)), g is even in y, so G1 and G2 have no y terms, and with y^2 = 1 - x^2 - r^2
 * (x = X.L, r = R.L):
 *
 *   q(L) = k_S + k_XV x + k_RV r + k_XX x^2 + k_RR r^2 + k_XR x r,
 *   sum w q(L) = k_S S + k_XV V.X + k_RV V.R + k_XX X^T T X + k_RR R^T T R + k_XR X^T T R.
 *
 * The six coefficients depend on c and n only. They are integrals over the hemisphere
 * R.L > 0 (t = R.L = cos(theta)): for each theta the lit side N.L > 0 is the arc
 * |phi| < phi0 with cos(phi0) = -c t / (s sqrt(1 - t^2)), whose integrals in phi are
 * closed forms, so each coefficient is a one-dimensional integral in theta (midpoint rule,
 * ComputeLobeProjection). Where N = R (c = 1) g is the zonal lobe and the coefficients are
 * its Legendre ones; where N = -R (c = -1) g is 0.
 *
 * The table. The shader cannot integrate per fragment, so the coefficients are tabulated
 * once per process (GetLobeProjectionTable: 65 cosines c in [-1, 1] by 33 powers n in
 * [0, 128], VTK's range of vtkProperty::SpecularPower, evenly spaced in log2(1 + n)) and
 * interpolated bilinearly, in the shader from one RGBA32F 2D texture read texel by texel
 * (clLobeProjection in vtkClusteredLightingShadingDec.glsl) and here
 * (LookupLobeProjection), so both use the same coefficients.
 *
 * Its use (ApplyFarLobe, vtkClusteredLightingFarField.h). The projection fits g over the
 * whole sphere, and g's cut at the horizon costs accuracy on its lit side: where every far
 * light is in front of the surface (a floor under the lights) the zonal lobe is the better
 * estimate (the projection there: 31% of a floor's pixels more than a step too dark at
 * power 1). So the zonal estimate is moved toward the projection by the share of far light
 * behind the surface, from the diffuse estimate (ComputeLobeBlend), and clamped into the
 * interval the moments prove for the lobe (ApplyMomentKernel). The stated bound
 * (vtkClusteredLightingFarFieldBound.h) measures both estimates against the lit-side truth
 * and takes the larger where the blend is neither surely 0 nor surely 1, so the table's
 * interpolation is inside it too.
 */
#ifndef vtkClusteredLightingLobeProjection_h
#define vtkClusteredLightingLobeProjection_h

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::acos, std::log2
#include <cstddef>   // for std::ptrdiff_t
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp> // for glm::pi
#include <vector>                // for std::vector

namespace vtkClusteredLighting
{

/// The lobe projection's coefficients (see the file description).
struct LobeProjection
{
  double S = 0.0, XV = 0.0, RV = 0.0, XX = 0.0, RR = 0.0, XR = 0.0;
};

/// The table's size: cosines c = N.V in [-1, 1] (columns), powers in [0, LobeTableMaxPower]
/// evenly spaced in log2(1 + n) (rows).
constexpr int LobeTableCosines = 65;
constexpr int LobeTablePowers = 33;
constexpr double LobeTableMaxPower = 128.0;

/// The table's row coordinate of power n (clamped to [0, LobeTableMaxPower]).
inline double GetLobeTablePowerCoordinate(double n)
{
  const double p = std::min(std::max(n, 0.0), LobeTableMaxPower);
  return std::log2(1.0 + p) / std::log2(1.0 + LobeTableMaxPower) * (LobeTablePowers - 1);
}

/// Power of table row `row` (the inverse of GetLobeTablePowerCoordinate).
inline double GetLobeTablePower(int row)
{
  return std::exp2(
           std::log2(1.0 + LobeTableMaxPower) * static_cast<double>(row) / (LobeTablePowers - 1)) -
    1.0;
}

/**
 * The coefficients of VTK's lit-side Phong lobe of powers `powers` for N.R = c (see the file
 * description), by the midpoint rule over theta in (0, pi/2) with `steps` intervals: the
 * integrand is smooth in theta except where the lit arc starts or stops being whole or
 * empty, and for the largest power (128) about 160 of the default 2,048 intervals span the
 * lobe.
 */
inline std::vector<LobeProjection> ComputeLobeProjection(
  double c, const std::vector<double>& powers, int steps = 2048)
{
  const double pi = glm::pi<double>();
  c = std::min(std::max(c, -1.0), 1.0);
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  struct Sums
  {
    double G0 = 0, G1x = 0, G1z = 0, Gxx = 0, Gyy = 0, Gzz = 0, Gxz = 0;
  };
  std::vector<Sums> sums(powers.size());
  const double h = 0.5 * pi / steps;
  for (int i = 0; i < steps; ++i)
  {
    const double theta = (i + 0.5) * h;
    const double t = std::cos(theta), r = std::sin(theta);
    // The lit arc |phi| < phi0: N.L = s r cos(phi) + c t > 0.
    double phi0;
    if (s * r <= 0.0)
    {
      phi0 = c * t > 0.0 ? pi : 0.0;
    }
    else
    {
      phi0 = std::acos(std::min(std::max(-c * t / (s * r), -1.0), 1.0));
    }
    if (phi0 <= 0.0)
    {
      continue;
    }
    const double sp = std::sin(phi0), cp = std::cos(phi0);
    const double logT = std::log(t);
    for (std::size_t k = 0; k < powers.size(); ++k)
    {
      // t^n dt with dt = sin(theta) d theta (0^0 = 1, as VTK's pow for n = 0 where R.L > 0).
      const double w = (powers[k] == 0.0 ? 1.0 : std::exp(powers[k] * logT)) * r * h;
      Sums& g = sums[k];
      g.G0 += w * 2.0 * phi0;
      g.G1x += w * r * 2.0 * sp;
      g.G1z += w * t * 2.0 * phi0;
      g.Gxx += w * r * r * (phi0 + sp * cp);
      g.Gyy += w * r * r * (phi0 - sp * cp);
      g.Gzz += w * t * t * 2.0 * phi0;
      g.Gxz += w * r * t * 2.0 * sp;
    }
  }
  std::vector<LobeProjection> out(powers.size());
  for (std::size_t k = 0; k < powers.size(); ++k)
  {
    const Sums& g = sums[k];
    LobeProjection& q = out[k];
    q.S = g.G0 / (4.0 * pi) + 5.0 / (8.0 * pi) * (3.0 * g.Gyy - g.G0);
    q.XV = 3.0 / (4.0 * pi) * g.G1x;
    q.RV = 3.0 / (4.0 * pi) * g.G1z;
    q.XX = 15.0 / (8.0 * pi) * (g.Gxx - g.Gyy);
    q.RR = 15.0 / (8.0 * pi) * (g.Gzz - g.Gyy);
    q.XR = 15.0 / (4.0 * pi) * g.Gxz;
  }
  return out;
}

/**
 * The table as the shader reads it: one RGBA32F 2D texture of LobeTableCosines columns by
 * 2 LobeTablePowers rows. Column i is the cosine c = -1 + 2 i / (LobeTableCosines - 1);
 * row j < LobeTablePowers holds (k_S, k_XV, k_RV, k_XX) for power GetLobeTablePower(j),
 * row LobeTablePowers + j (k_RR, k_XR, 0, 0) for the same power. Computed once per process
 * (about 65 x 2,048 x 33 exponentials).
 */
constexpr int LobeTableRows = 2 * LobeTablePowers;
constexpr std::size_t LobeTableBytes =
  std::size_t{ 16 } * static_cast<std::size_t>(LobeTableCosines) * LobeTableRows;
struct LobeProjectionTable
{
  std::vector<float> Texels; ///< 4 floats per texel, row by row
};

inline const LobeProjectionTable& GetLobeProjectionTable()
{
  static const LobeProjectionTable table = []()
  {
    LobeProjectionTable t;
    t.Texels.assign(LobeTableBytes / sizeof(float), 0.0f);
    std::vector<double> powers(LobeTablePowers);
    for (int j = 0; j < LobeTablePowers; ++j)
    {
      powers[static_cast<std::size_t>(j)] = GetLobeTablePower(j);
    }
    for (int i = 0; i < LobeTableCosines; ++i)
    {
      const double c = -1.0 + 2.0 * i / (LobeTableCosines - 1);
      const std::vector<LobeProjection> q = ComputeLobeProjection(c, powers);
      for (int j = 0; j < LobeTablePowers; ++j)
      {
        const LobeProjection& k = q[static_cast<std::size_t>(j)];
        const std::size_t first = 4 * (static_cast<std::size_t>(j) * LobeTableCosines + i);
        const std::size_t second =
          4 * (static_cast<std::size_t>(j + LobeTablePowers) * LobeTableCosines + i);
        t.Texels[first] = static_cast<float>(k.S);
        t.Texels[first + 1] = static_cast<float>(k.XV);
        t.Texels[first + 2] = static_cast<float>(k.RV);
        t.Texels[first + 3] = static_cast<float>(k.XX);
        t.Texels[second] = static_cast<float>(k.RR);
        t.Texels[second + 1] = static_cast<float>(k.XR);
      }
    }
    return t;
  }();
  return table;
}

/// The coefficients for N.R = c and power n, interpolated bilinearly in the table as the
/// shader does (clLobeProjection).
inline LobeProjection LookupLobeProjection(double c, double n)
{
  const std::vector<float>& t = GetLobeProjectionTable().Texels;
  const double fc =
    std::min(std::max((c + 1.0) * 0.5 * (LobeTableCosines - 1), 0.0), LobeTableCosines - 1.0);
  const double fp = GetLobeTablePowerCoordinate(n);
  const int i = std::min(static_cast<int>(fc), LobeTableCosines - 2);
  const int j = std::min(static_cast<int>(fp), LobeTablePowers - 2);
  const double a = fc - i, b = fp - j;
  double v[6] = {};
  for (int corner = 0; corner < 4; ++corner)
  {
    const int di = corner & 1, dj = corner >> 1;
    const double w = (di ? a : 1.0 - a) * (dj ? b : 1.0 - b);
    const std::size_t first = 4 * (static_cast<std::size_t>(j + dj) * LobeTableCosines + i + di);
    const std::size_t second =
      4 * (static_cast<std::size_t>(j + dj + LobeTablePowers) * LobeTableCosines + i + di);
    for (int q = 0; q < 4; ++q)
    {
      v[q] += w * t[first + static_cast<std::size_t>(q)];
    }
    v[4] += w * t[second];
    v[5] += w * t[second + 1];
  }
  return { v[0], v[1], v[2], v[3], v[4], v[5] };
}

/// The projection's axis X for unit normal N and mirrored view R (0 where N = +-R, where the
/// coefficients of X's terms vanish), and c = N.R.
inline glm::dvec3 ComputeLobeAxis(const glm::dvec3& N, const glm::dvec3& R, double& c)
{
  c = glm::dot(N, R);
  const glm::dvec3 w = N - c * R;
  const double length = glm::length(w);
  return length > 1e-12 ? w / length : glm::dvec3(0.0);
}

/// The projection q(L) for a unit direction L toward a light (per unit weight).
inline double EvaluateLobeProjection(
  const LobeProjection& k, const glm::dvec3& X, const glm::dvec3& R, const glm::dvec3& L)
{
  const double x = glm::dot(X, L), r = glm::dot(R, L);
  return k.S + k.XV * x + k.RV * r + k.XX * x * x + k.RR * r * r + k.XR * x * r;
}

/// A^T T B for one channel's moments m (S, Vx, Vy, Vz, Txx, Tyy, Txy, Txz, Tyz; Tzz = S -
/// Txx - Tyy). Mirrors clMomentForm.
inline double ComputeMomentForm(const double* m, const glm::dvec3& A, const glm::dvec3& B)
{
  return m[4] * A.x * B.x + m[5] * A.y * B.y + (m[0] - m[4] - m[5]) * A.z * B.z +
    m[6] * (A.x * B.y + A.y * B.x) + m[7] * (A.x * B.z + A.z * B.x) +
    m[8] * (A.y * B.z + A.z * B.y);
}

/// The projection summed over one channel's moments m (as ComputeMomentForm's).
inline double ApplyLobeProjectionToMoments(
  const double* m, const LobeProjection& k, const glm::dvec3& X, const glm::dvec3& R)
{
  const glm::dvec3 V(m[1], m[2], m[3]);
  return k.S * m[0] + k.XV * glm::dot(V, X) + k.RV * glm::dot(V, R) +
    k.XX * ComputeMomentForm(m, X, X) + k.RR * ComputeMomentForm(m, R, R) +
    k.XR * ComputeMomentForm(m, X, R);
}
} // namespace vtkClusteredLighting

#endif
