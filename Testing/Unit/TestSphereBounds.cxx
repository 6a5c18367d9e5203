// SPDX-License-Identifier: BSD-3-Clause
// Conservativeness of the sphere bounds: every point of the visible part of a light
// sphere (dense sampling of its surface and of its near/far clip disks) must project
// inside the NDC rectangle and land in the cluster range.
#include "TestUtilities.h"
#include "vtkClusteredLightingSphereBounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vtkClusteredLighting;
using ClusteredLightingTest::Parallel;
using ClusteredLightingTest::Perspective;

namespace
{
struct Sample
{
  glm::dvec3 P;
};

/// Points of sphere(c, r) clipped to [near, far]: surface samples plus clip-disk samples.
std::vector<glm::dvec3> SampleClippedSphere(
  const glm::dvec3& c, double r, double nearVC, double farVC, int n = 6000)
{
  std::vector<glm::dvec3> pts;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double y = 1.0 - 2.0 * (i + 0.5) / n;
    const double rad = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double th = golden * i;
    const glm::dvec3 p = c + r * glm::dvec3(std::cos(th) * rad, y, std::sin(th) * rad);
    if (-p.z >= nearVC && -p.z <= farVC)
    {
      pts.push_back(p);
    }
  }
  for (double plane : { nearVC, farVC })
  {
    const double dz = -c.z - plane;
    const double rho2 = r * r - dz * dz;
    if (rho2 <= 0.0)
    {
      continue;
    }
    const double rho = std::sqrt(rho2);
    for (int i = 0; i < 720; ++i)
    {
      const double a = 2.0 * 3.14159265358979323846 * i / 720.0;
      for (double f : { 1.0, 0.5 })
      {
        pts.emplace_back(c.x + f * rho * std::cos(a), c.y + f * rho * std::sin(a), -plane);
      }
    }
  }
  return pts;
}

glm::dvec2 ProjectNDC(const glm::dmat4& P, const glm::dvec3& p)
{
  const glm::dvec4 clip = P * glm::dvec4(p, 1.0);
  return glm::dvec2(clip) / clip.w;
}

struct Camera
{
  const char* Name;
  glm::dmat4 P;
  double Near, Far;
};

std::vector<Camera> MakeCameras()
{
  std::vector<Camera> cams;
  cams.push_back({ "persp30", Perspective(30.0, 1.0, 0.1, 100.0), 0.1, 100.0 });
  cams.push_back({ "persp90wide", Perspective(90.0, 1.7, 1.0, 100.0), 1.0, 100.0 });
  cams.push_back({ "persp170", Perspective(170.0, 1.0, 0.5, 50.0), 0.5, 50.0 });
  cams.push_back({ "offaxis", Perspective(60.0, 1.33, 0.3, 80.0, 0.6, -0.4), 0.3, 80.0 });
  cams.push_back({ "offaxis-strong", Perspective(40.0, 0.5, 0.2, 30.0, -1.5, 1.2), 0.2, 30.0 });
  cams.push_back({ "parallel", Parallel(5.0, 1.33, 0.5, 60.0), 0.5, 60.0 });
  return cams;
}

std::vector<std::pair<glm::dvec3, double>> MakeLights()
{
  std::vector<std::pair<glm::dvec3, double>> lights;
  for (double r : { 0.05, 0.7, 3.0 })
  {
    for (double dOverR : { -2.0, -0.5, 0.0, 0.3, 1.0, 1.2, 2.0, 5.0, 100.0 })
    {
      for (const glm::dvec2& off : { glm::dvec2(0.0), glm::dvec2(0.7, 0.0), glm::dvec2(0.0, -0.9),
             glm::dvec2(3.0, 2.0), glm::dvec2(-8.0, 0.5), glm::dvec2(30.0, -30.0) })
      {
        const double d = dOverR * r + 0.1 * (off.x != 0.0);
        lights.push_back({ glm::dvec3(off.x * r, off.y * r, -d), r });
      }
    }
  }
  return lights;
}
}

TEST(SphereBounds, ContainSampledClippedSphereForAllProjections)
{
  int checkedPoints = 0, visibleLights = 0;
  for (const Camera& cam : MakeCameras())
  {
    for (const auto& [c, r] : MakeLights())
    {
      const SphereScreenBounds b = ComputeSphereScreenBounds(c, r, cam.P, cam.Near, cam.Far);
      ASSERT_TRUE(std::isfinite(b.NDCMin.x) && std::isfinite(b.NDCMax.x) &&
        std::isfinite(b.NDCMin.y) && std::isfinite(b.NDCMax.y));
      for (const glm::dvec3& p : SampleClippedSphere(c, r, cam.Near, cam.Far))
      {
        const glm::dvec2 ndc = ProjectNDC(cam.P, p);
        if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0)
        {
          continue; // off screen: only the clamped part matters
        }
        ++checkedPoints;
        ASSERT_TRUE(b.Visible) << cam.Name << " c=(" << c.x << "," << c.y << "," << c.z
                               << ") r=" << r;
        const double tol = 1e-9;
        ASSERT_GE(ndc.x, b.NDCMin.x - tol) << cam.Name << " c.z=" << c.z << " r=" << r;
        ASSERT_LE(ndc.x, b.NDCMax.x + tol) << cam.Name << " c.z=" << c.z << " r=" << r;
        ASSERT_GE(ndc.y, b.NDCMin.y - tol) << cam.Name << " c.z=" << c.z << " r=" << r;
        ASSERT_LE(ndc.y, b.NDCMax.y + tol) << cam.Name << " c.z=" << c.z << " r=" << r;
        const double depth = -p.z;
        ASSERT_GE(depth, b.DepthMin - 1e-9);
        ASSERT_LE(depth, b.DepthMax + 1e-9);
      }
      visibleLights += b.Visible;
    }
  }
  EXPECT_GT(checkedPoints, 100000);
  EXPECT_GT(visibleLights, 200);
}

TEST(SphereBounds, AreTightForSpheresInFrontOfTheCamera)
{
  // Fully visible spheres: the bounds should touch the sampled silhouette.
  const glm::dmat4 P = Perspective(60.0, 1.0, 0.1, 100.0, 0.2, 0.1);
  for (const glm::dvec3& c : { glm::dvec3(0, 0, -10), glm::dvec3(2, -1, -6),
         glm::dvec3(-1, 1.5, -4), glm::dvec3(0, 0, -2.5) })
  {
    const double r = 1.0;
    const SphereScreenBounds b = ComputeSphereScreenBounds(c, r, P, 0.1, 100.0);
    ASSERT_TRUE(b.Visible);
    glm::dvec2 lo(1e9), hi(-1e9);
    for (const glm::dvec3& p : SampleClippedSphere(c, r, 0.1, 100.0, 200000))
    {
      const glm::dvec2 ndc = ProjectNDC(P, p);
      lo = glm::min(lo, ndc);
      hi = glm::max(hi, ndc);
    }
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    for (int a = 0; a < 2; ++a)
    {
      if (b.NDCMin[a] > -1.0)
      {
        EXPECT_NEAR(b.NDCMin[a], lo[a], 2e-3 * extent);
      }
      if (b.NDCMax[a] < 1.0)
      {
        EXPECT_NEAR(b.NDCMax[a], hi[a], 2e-3 * extent);
      }
    }
  }
}

TEST(SphereBounds, ExactOnAxisHalfAngleMatchesClosedForm)
{
  // On the optical axis the true half extent is tan(asin(r/d)) (technique note §3.1).
  const glm::dmat4 P = Perspective(90.0, 1.0, 0.01, 1000.0); // P00 = 1
  for (double d : { 1.2, 2.0, 4.0, 10.0 })
  {
    const SphereScreenBounds b =
      ComputeSphereScreenBounds(glm::dvec3(0, 0, -d), 1.0, P, 0.01, 1000.0);
    EXPECT_NEAR(b.NDCMax.x, std::min(1.0, std::tan(std::asin(1.0 / d))), 1e-12) << "d=" << d;
    EXPECT_NEAR(b.NDCMin.x, -std::min(1.0, std::tan(std::asin(1.0 / d))), 1e-12);
  }
}

TEST(SphereBounds, CenterDepthQuadUnderCoversNearbySpheres)
{
  // Documents why the centre-depth quad is not used: at d = 1.2 r it covers only
  // sqrt(1 - (r/d)^2) = 55% of the true half extent.
  const glm::dmat4 P = Perspective(120.0, 1.0, 0.01, 1000.0);
  const glm::dvec3 c(0, 0, -1.2);
  const SphereScreenBounds exact = ComputeSphereScreenBounds(c, 1.0, P, 0.01, 1000.0);
  const SphereScreenBounds quad = ComputeCenterDepthQuadBounds(c, 1.0, P, 0.01, 1000.0);
  EXPECT_NEAR(quad.NDCMax.x / exact.NDCMax.x, std::sqrt(1.0 - 1.0 / 1.44), 1e-9);
  EXPECT_LT(quad.NDCMax.x, exact.NDCMax.x);
}

TEST(SphereBounds, NoNaNForDegenerateInput)
{
  const glm::dmat4 P = Perspective(60.0, 1.0, 0.1, 100.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& c : { glm::dvec3(0.0), glm::dvec3(0, 0, 0.1), glm::dvec3(0, 0, -0.1),
         glm::dvec3(1e6, 0, -1e6), glm::dvec3(0, 0, -1e12) })
  {
    for (double r : { 0.0, 1e-12, 0.1, 1.0, 1e9, inf })
    {
      const SphereScreenBounds b = ComputeSphereScreenBounds(c, r, P, 0.1, 100.0);
      EXPECT_FALSE(std::isnan(b.NDCMin.x) || std::isnan(b.NDCMax.x) || std::isnan(b.NDCMin.y) ||
        std::isnan(b.NDCMax.y) || std::isnan(b.DepthMin) || std::isnan(b.DepthMax));
    }
  }
  // Camera inside the sphere covers the whole screen and starts at the near slice.
  const SphereScreenBounds inside =
    ComputeSphereScreenBounds(glm::dvec3(0.2, 0, 0.3), 2.0, P, 0.1, 100.0);
  EXPECT_TRUE(inside.Visible);
  EXPECT_DOUBLE_EQ(inside.NDCMin.x, -1.0);
  EXPECT_DOUBLE_EQ(inside.NDCMax.y, 1.0);
  EXPECT_DOUBLE_EQ(inside.DepthMin, 0.1);
  // Entirely behind the camera, or beyond the far plane: not visible.
  EXPECT_FALSE(ComputeSphereScreenBounds(glm::dvec3(0, 0, 5), 1.0, P, 0.1, 100.0).Visible);
  EXPECT_FALSE(ComputeSphereScreenBounds(glm::dvec3(0, 0, -200), 1.0, P, 0.1, 100.0).Visible);
  // Negative and NaN radius are rejected, not propagated.
  EXPECT_FALSE(ComputeSphereScreenBounds(glm::dvec3(0, 0, -5), -1.0, P, 0.1, 100.0).Visible);
  EXPECT_FALSE(
    ComputeSphereScreenBounds(glm::dvec3(0, 0, -5), std::nan(""), P, 0.1, 100.0).Visible);
}

TEST(SphereBounds, ClusterRangeContainsClusterOfEverySample)
{
  for (const Camera& cam : MakeCameras())
  {
    const ClusterGridParams g =
      ClusteredLightingTest::MakeGrid(16, 9, 24, 800, 450, cam.Near, cam.Far,
        cam.Name == std::string("parallel") ? SlicingScheme::Linear : SlicingScheme::Exponential);
    for (const auto& [c, r] : MakeLights())
    {
      const SphereScreenBounds b = ComputeSphereScreenBounds(c, r, cam.P, cam.Near, cam.Far);
      const ClusterRange cr = ComputeClusterRange(b, g);
      for (const glm::dvec3& p : SampleClippedSphere(c, r, cam.Near, cam.Far, 1500))
      {
        const glm::dvec2 ndc = ProjectNDC(cam.P, p);
        if (std::abs(ndc.x) >= 1.0 || std::abs(ndc.y) >= 1.0)
        {
          continue;
        }
        const int tx =
          ComputeTileIndex(0.5 * (ndc.x + 1.0) * g.ViewportWidth, g.ViewportWidth, g.TilesX);
        const int ty =
          ComputeTileIndex(0.5 * (ndc.y + 1.0) * g.ViewportHeight, g.ViewportHeight, g.TilesY);
        const int s = ComputeSliceIndex(-p.z, g);
        ASSERT_FALSE(cr.IsEmpty());
        ASSERT_TRUE(tx >= cr.TileMin[0] && tx <= cr.TileMax[0]) << cam.Name;
        ASSERT_TRUE(ty >= cr.TileMin[1] && ty <= cr.TileMax[1]) << cam.Name;
        ASSERT_TRUE(s >= cr.SliceMin && s <= cr.SliceMax) << cam.Name << " s=" << s;
      }
    }
  }
}
