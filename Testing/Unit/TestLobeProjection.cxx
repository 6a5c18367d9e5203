// SPDX-License-Identifier: BSD-3-Clause
// The far field's Phong specular (vtkClusteredLightingLobeProjection.h, ApplyFarLobe):
// the lit-side lobe's order-2 projection, its table, and the blend with the zonal lobe,
// against sums over lights computed light by light.
#include "vtkClusteredLightingFarField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{
/// VTK's lit-side Phong lobe for unit vectors N, R and direction L toward a light.
double LitLobe(const glm::dvec3& N, const glm::dvec3& R, const glm::dvec3& L, double n)
{
  const double t = glm::dot(R, L);
  return glm::dot(N, L) > 0.0 && t > 0.0 ? std::pow(t, n) : 0.0;
}

/// The coefficients by brute force: the projection's integrals on a theta x phi grid over
/// the whole sphere (no closed form in phi), in the frame R = z, N in the x-z plane.
LobeProjection ProjectOnGrid(double c, double n, int rows = 1200)
{
  const double pi = glm::pi<double>();
  const glm::dvec3 R(0, 0, 1), N(std::sqrt(std::max(0.0, 1.0 - c * c)), 0, c);
  double G0 = 0, G1x = 0, G1z = 0, Gxx = 0, Gyy = 0, Gzz = 0, Gxz = 0;
  const int cols = 2 * rows;
  for (int i = 0; i < rows; ++i)
  {
    const double theta = (i + 0.5) * pi / rows;
    for (int j = 0; j < cols; ++j)
    {
      const double phi = (j + 0.5) * 2.0 * pi / cols;
      const glm::dvec3 L(
        std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const double g = LitLobe(N, R, L, n) * std::sin(theta) * (pi / rows) * (2.0 * pi / cols);
      G0 += g;
      G1x += g * L.x;
      G1z += g * L.z;
      Gxx += g * L.x * L.x;
      Gyy += g * L.y * L.y;
      Gzz += g * L.z * L.z;
      Gxz += g * L.x * L.z;
    }
  }
  LobeProjection q;
  q.S = G0 / (4.0 * pi) + 5.0 / (8.0 * pi) * (3.0 * Gyy - G0);
  q.XV = 3.0 / (4.0 * pi) * G1x;
  q.RV = 3.0 / (4.0 * pi) * G1z;
  q.XX = 15.0 / (8.0 * pi) * (Gxx - Gyy);
  q.RR = 15.0 / (8.0 * pi) * (Gzz - Gyy);
  q.XR = 15.0 / (4.0 * pi) * Gxz;
  return q;
}

double Largest(const LobeProjection& a, const LobeProjection& b)
{
  return std::max({ std::abs(a.S - b.S), std::abs(a.XV - b.XV), std::abs(a.RV - b.RV),
    std::abs(a.XX - b.XX), std::abs(a.RR - b.RR), std::abs(a.XR - b.XR) });
}

/// One channel's moments (S, V, T) of lights with weights w from unit directions L.
std::vector<double> Moments(const std::vector<double>& w, const std::vector<glm::dvec3>& L)
{
  std::vector<double> m(FarFieldMomentsPerChannel, 0.0);
  for (std::size_t i = 0; i < w.size(); ++i)
  {
    const glm::dvec3& u = L[i];
    const double v[FarFieldMomentsPerChannel] = { 1.0, u.x, u.y, u.z, u.x * u.x, u.y * u.y,
      u.x * u.y, u.x * u.z, u.y * u.z };
    for (int k = 0; k < FarFieldMomentsPerChannel; ++k)
    {
      m[static_cast<std::size_t>(k)] += w[i] * v[k];
    }
  }
  return m;
}
}

TEST(LobeProjection, TheHemisphereIntegralsAgreeWithAGridOverTheSphere)
{
  // The closed forms in phi (the lit arc) against plain quadrature over the sphere, at
  // cosines where the arc is whole, empty or cut, and powers from 0 to 128.
  for (const double c : { -0.9, -0.3, 0.0, 0.4, 0.95 })
  {
    for (const double n : { 0.0, 1.0, 2.5, 20.0 })
    {
      const LobeProjection q = ComputeLobeProjection(c, { n }).front();
      const LobeProjection grid = ProjectOnGrid(c, n);
      EXPECT_LT(Largest(q, grid), 2e-3) << "c " << c << ", power " << n;
    }
  }
}

TEST(LobeProjection, IsTheZonalLobeWhereTheNormalIsTheMirroredViewAndZeroOpposite)
{
  for (const double n : { 0.5, 1.0, 3.0, 20.0, 128.0 })
  {
    // N = R: every light in the lobe is in front, g is the zonal lobe, whose projection
    // is its Legendre expansion: k0 + k1 t + k2 (3 t^2 - 1) / 2.
    const glm::dvec3 k = ComputeLobeKernel(n);
    const LobeProjection q = ComputeLobeProjection(1.0, { n }).front();
    EXPECT_NEAR(q.S, k.x - 0.5 * k.z, 1e-4 * k.x) << n;
    EXPECT_NEAR(q.RV, k.y, 1e-4 * k.x) << n;
    EXPECT_NEAR(q.RR, 1.5 * k.z, 1e-4 * k.x) << n;
    EXPECT_NEAR(q.XV, 0.0, 1e-12);
    EXPECT_NEAR(q.XX, 0.0, 1e-12);
    EXPECT_NEAR(q.XR, 0.0, 1e-12);
    // N = -R: no light is both in front and in the lobe.
    const LobeProjection none = ComputeLobeProjection(-1.0, { n }).front();
    EXPECT_EQ(Largest(none, LobeProjection()), 0.0) << n;
  }
}

TEST(LobeProjection, TheTableIsTheCoefficientsAtItsNodesAndCloseBetweenThem)
{
  // At a node: the coefficients in float. Between nodes: bilinear interpolation, within
  // a small part of the lobe's integral (k_S + k_RR / 3 is its mean over the sphere).
  for (int i = 0; i < LobeTableCosines; i += 8)
  {
    for (int j = 0; j < LobeTablePowers; j += 4)
    {
      const double c = -1.0 + 2.0 * i / (LobeTableCosines - 1);
      const double n = GetLobeTablePower(j);
      const LobeProjection q = ComputeLobeProjection(c, { n }).front();
      EXPECT_LT(Largest(LookupLobeProjection(c, n), q), 1e-6) << c << " " << n;
    }
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 300; ++k)
  {
    const double c = -1.0 + 2.0 * U(rng);
    const double n = 128.0 * U(rng) * U(rng);
    const LobeProjection q = ComputeLobeProjection(c, { n }).front();
    const LobeProjection zonal = ComputeLobeProjection(1.0, { n }).front();
    const double scale = zonal.S + zonal.RR / 3.0;
    worst = std::max(worst, Largest(LookupLobeProjection(c, n), q) / scale);
  }
  std::printf(
    "table against direct coefficients: largest difference %.4f of the lobe's mean\n", worst);
  EXPECT_LT(worst, 0.05);
  // Out of range: the powers clamp to [0, 128], the cosines to [-1, 1].
  EXPECT_EQ(Largest(LookupLobeProjection(0.3, 500.0), LookupLobeProjection(0.3, 128.0)), 0.0);
  EXPECT_EQ(Largest(LookupLobeProjection(1.5, 4.0), LookupLobeProjection(1.0, 4.0)), 0.0);
}

TEST(LobeProjection, TheBlendFollowsTheLightBehindTheSurface)
{
  // Lights on two sides of a surface point: all in front, a third behind, all behind.
  // The far specular ApplyFarLobe gives against the lit-side sum light by light: the
  // zonal lobe counts the lights behind (too bright at low powers), the blend does not.
  std::mt19937 rng(9);
  std::normal_distribution<double> G(0.0, 1.0);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const glm::dvec3 N(0, 0, 1);
  double zonalWorst = 0.0, blendWorst = 0.0;
  for (const double behind : { 0.0, 0.33 })
  {
    for (int trial = 0; trial < 60; ++trial)
    {
      std::vector<double> w;
      std::vector<glm::dvec3> L;
      for (int i = 0; i < 400; ++i)
      {
        glm::dvec3 u = glm::normalize(glm::dvec3(G(rng), G(rng), G(rng)));
        u.z = (U(rng) < behind ? -1.0 : 1.0) * std::abs(u.z);
        L.push_back(u);
        w.push_back(0.5 + U(rng));
      }
      const std::vector<double> m = Moments(w, L);
      // A view 10 to 80 degrees from the normal.
      const double a = glm::radians(10.0 + 70.0 * U(rng)), b = 6.283 * U(rng);
      const glm::dvec3 V(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a));
      const glm::dvec3 R = 2.0 * glm::dot(N, V) * N - V;
      for (const double n : { 1.0, 2.0 })
      {
        double truth = 0.0, total = 0.0;
        for (std::size_t i = 0; i < w.size(); ++i)
        {
          truth += w[i] * LitLobe(N, R, L[i], n);
          total += w[i];
        }
        double lower = 0.0, upper = 0.0;
        const double blended = ApplyFarLobe(m.data(), N, R, n, &lower, &upper);
        const double zonal = ApplyMomentKernel(m.data(), ComputeLobeKernel(n), R, true, n);
        EXPECT_GE(truth, lower - 1e-9 * total);
        EXPECT_LE(truth, upper + 1e-9 * total);
        EXPECT_GE(blended, lower);
        EXPECT_LE(blended, upper);
        if (behind == 0.0)
        {
          // Every light in front: the blend is the zonal estimate itself.
          EXPECT_NEAR(blended, zonal, 1e-12 * total);
        }
        zonalWorst = std::max(zonalWorst, std::abs(zonal - truth) / total);
        blendWorst = std::max(blendWorst, std::abs(blended - truth) / total);
      }
    }
  }
  std::printf("lights a third behind: largest error per unit of light %.4f zonal, %.4f blended\n",
    zonalWorst, blendWorst);
  EXPECT_LT(blendWorst, 0.5 * zonalWorst);
  // The blend weight: 0 without light behind (N^T T N <= V.N), 1 from a tenth of it.
  EXPECT_EQ(ComputeLobeBlend(1.0, 0.8, 0.7), 0.0);
  EXPECT_EQ(ComputeLobeBlend(0.0, 0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(ComputeLobeBlend(1.0, 0.6, 0.7), 0.05 / (0.1 * 1.05));
  EXPECT_EQ(ComputeLobeBlend(1.0, -0.5, 0.7), 1.0);
}
