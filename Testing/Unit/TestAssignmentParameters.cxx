// SPDX-License-Identifier: BSD-3-Clause
// Packing of the list-pass and shading uniforms from a view (GL-free core).
#include "TestUtilities.h"
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingReference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{
ViewParameters MakeView(const glm::dmat4& vcdc)
{
  ViewParameters v;
  v.VCDC = vcdc;
  v.Grid.NearVC = 0.5;
  v.Grid.FarVC = 80.0;
  v.Grid.TilesX = 24;
  v.Grid.TilesY = 12;
  v.Grid.Slices = 20;
  return v;
}

/// CPU mirror of clUnproject (vtkClusteredLightingListFS.glsl) for one axis.
double Unproject(const float row[3], const float w[2], double ndc, double depth)
{
  const double z = -depth;
  const double clipW = w[0] * z + w[1];
  return (ndc * clipW - row[1] * z - row[2]) / row[0];
}
}

TEST(ListPassParameters, UnprojectionMatchesTheReferenceCellGeometry)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ndc(-1.0, 1.0), depth(0.5, 80.0);
  const glm::dmat4 projections[] = { ClusteredLightingTest::Perspective(40, 1.5, 0.5, 80),
    ClusteredLightingTest::Perspective(70, 0.7, 0.5, 80, 0.4, -0.3),
    ClusteredLightingTest::Parallel(3.0, 1.3, 0.5, 80) };
  for (const glm::dmat4& P : projections)
  {
    const ListPassParameters p = ComputeListPassParameters(MakeView(P), true);
    EXPECT_TRUE(p.CullClusters);
    for (int i = 0; i < 200; ++i)
    {
      const double x = ndc(rng), y = ndc(rng), d = depth(rng);
      const glm::dvec3 ref = UnprojectAtDepth(x, y, d, P);
      const double scale = 1.0 + std::abs(ref.x) + std::abs(ref.y);
      EXPECT_NEAR(Unproject(p.ProjectionX, p.ProjectionW, x, d), ref.x, 1e-5 * scale);
      EXPECT_NEAR(Unproject(p.ProjectionY, p.ProjectionW, y, d), ref.y, 1e-5 * scale);
    }
  }
}

TEST(ListPassParameters, CullingNeedsVTKsProjectionForm)
{
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40, 1.5, 0.5, 80);
  EXPECT_FALSE(ComputeListPassParameters(MakeView(P), false).CullClusters);
  glm::dmat4 skewed = P;
  skewed[1][0] = 0.2; // P01: x depends on y
  EXPECT_FALSE(ComputeListPassParameters(MakeView(skewed), true).CullClusters);
  glm::dmat4 tilted = P;
  tilted[0][3] = 0.1; // P30: w depends on x
  EXPECT_FALSE(ComputeListPassParameters(MakeView(tilted), true).CullClusters);
}

TEST(ListPassParameters, DepthRangeAndSlicingFollowTheGrid)
{
  ViewParameters v = MakeView(ClusteredLightingTest::Perspective(40, 1.5, 0.5, 80));
  for (SlicingScheme scheme : { SlicingScheme::Exponential, SlicingScheme::Linear })
  {
    v.Grid.Scheme = scheme;
    const ListPassParameters p = ComputeListPassParameters(v, true);
    double slicing[4];
    ComputeSliceShaderParameters(v.Grid, slicing);
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_FLOAT_EQ(p.Slicing[k], static_cast<float>(slicing[k]));
    }
    EXPECT_FLOAT_EQ(p.DepthRange[0], 0.5f);
    EXPECT_FLOAT_EQ(p.DepthRange[1], static_cast<float>(v.Grid.GetMaxFragmentDepth()));
    EXPECT_GE(p.DepthRange[1], 80.0f);
  }
}

TEST(ShadingParameters, GridProjectionAndSlicingAreTheAssignmentsOwn)
{
  const ViewParameters v =
    MakeView(ClusteredLightingTest::Perspective(55, 1.2, 0.5, 80, 0.25, 0.1));
  ClusterTextureLayout layout;
  ASSERT_TRUE(ComputeLayout(v.Grid.TilesX, v.Grid.TilesY, v.Grid.Slices, 5000, 4096, layout));
  const ShadingParameters s = ComputeShadingParameters(v, layout);
  EXPECT_EQ(s.Grid[0], 24);
  EXPECT_EQ(s.Grid[1], 12);
  EXPECT_EQ(s.Grid[2], 20);
  EXPECT_EQ(s.Grid[3], layout.BatchRows);
  // Column-major, as glUniformMatrix4fv without transpose expects.
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      EXPECT_FLOAT_EQ(s.Projection[4 * c + r], static_cast<float>(v.VCDC[c][r]));
    }
  }
  double slicing[4];
  ComputeSliceShaderParameters(v.Grid, slicing);
  for (int k = 0; k < 4; ++k)
  {
    EXPECT_FLOAT_EQ(s.Slicing[k], static_cast<float>(slicing[k]));
  }
  // Brute force has no layout: the batch rows stay a valid divisor.
  EXPECT_EQ(ComputeShadingParameters(v, ClusterTextureLayout()).Grid[3], 1);
}

// The most lights in one cluster, from the list pass's quads: against counting every
// cluster directly, for random quads on a small grid.
TEST(ShaderLoopLimit, MostLightsInAClusterCountsTheQuadsOverEachCluster)
{
  const int tilesX = 7, tilesY = 5, slices = 3;
  EXPECT_EQ(ComputeMostLightsInACluster({}, tilesX, tilesY, slices), 0);
  std::mt19937 rng(5);
  for (int round = 0; round < 50; ++round)
  {
    std::vector<float> quads;
    std::vector<int> count(static_cast<std::size_t>(tilesX * tilesY * slices), 0);
    const int n = 1 + static_cast<int>(rng() % 60);
    for (int q = 0; q < n; ++q)
    {
      const int x0 = static_cast<int>(rng() % tilesX), y0 = static_cast<int>(rng() % tilesY);
      const int x1 = x0 + static_cast<int>(rng() % (tilesX - x0));
      const int y1 = y0 + static_cast<int>(rng() % (tilesY - y0));
      const int s = static_cast<int>(rng() % slices);
      const float quad[FloatsPerQuad] = { static_cast<float>(x0), static_cast<float>(y0),
        static_cast<float>(x1), static_cast<float>(y1), static_cast<float>(s),
        static_cast<float>(q), 0.0f, 0.0f };
      quads.insert(quads.end(), quad, quad + FloatsPerQuad);
      for (int y = y0; y <= y1; ++y)
      {
        for (int x = x0; x <= x1; ++x)
        {
          ++count[static_cast<std::size_t>((s * tilesY + y) * tilesX + x)];
        }
      }
    }
    EXPECT_EQ(ComputeMostLightsInACluster(quads, tilesX, tilesY, slices),
      *std::max_element(count.begin(), count.end()))
      << "round " << round;
  }
}

// The bound of a walk's loop iterations holds for any list: the shader's loops counted
// for random lists (one iteration per master texel, per non-empty batch and per light),
// and the numbers the docs give.
TEST(ShaderLoopLimit, WalkIterationsBoundTheShadersLoops)
{
  std::mt19937 rng(9);
  for (int round = 0; round < 200; ++round)
  {
    const long long lights = 1 + static_cast<long long>(rng() % 200000);
    const long long batches = (lights + 31) / 32;
    const int master = static_cast<int>((batches + 31) / 32);
    // A random list: each light with a probability from very sparse to all.
    const double p = std::pow(10.0, -4.0 * (rng() % 1000) / 1000.0);
    std::bernoulli_distribution listed(p);
    std::vector<int> perBatch(static_cast<std::size_t>(batches), 0);
    long long n = 0;
    for (long long i = 0; i < lights; ++i)
    {
      if (listed(rng))
      {
        ++perBatch[static_cast<std::size_t>(i / 32)];
        ++n;
      }
    }
    long long actual = master;
    for (int k : perBatch)
    {
      actual += k > 0 ? 1 + k : 0;
    }
    EXPECT_GE(ComputeWalkIterations(n, lights, master), actual) << lights << " lights, " << n;
  }
  // Every light listed: within the limit up to 60,000 lights, past it at 65,000.
  auto all = [](long long lights)
  {
    const long long batches = (lights + 31) / 32;
    return ComputeWalkIterations(lights, lights, static_cast<int>((batches + 31) / 32));
  };
  EXPECT_LE(all(60000), ShaderLoopLimit);
  EXPECT_GT(all(65000), ShaderLoopLimit);
  EXPECT_LE(ComputeEveryLightIterations(16 * ShaderLoopLimit), ShaderLoopLimit);
  EXPECT_GT(ComputeEveryLightIterations(16 * ShaderLoopLimit + 1), ShaderLoopLimit);
}

// The exact far sums take one light per iteration where that cannot pass the limit, even
// for a fragment whose cluster lists every light and that sums every far part, and 16
// above, as far as brute force.
TEST(ShaderLoopLimit, FarSumsTakeOneLightPerIterationWhileTheWalkAndSumsFit)
{
  using namespace vtkClusteredLighting;
  EXPECT_EQ(ComputeFarPartsPerIteration(0), 1);
  EXPECT_EQ(ComputeFarPartsPerIteration(FarSumSingleLightLimit), 1);
  EXPECT_EQ(ComputeFarPartsPerIteration(FarSumSingleLightLimit + 1), 16);
  EXPECT_EQ(ComputeFarSumIterations(4096), 4096);
  EXPECT_EQ(
    ComputeFarSumIterations(FarSumSingleLightLimit + 1), (FarSumSingleLightLimit + 16) / 16);
  for (long long lights : { 1LL, 4096LL, FarSumSingleLightLimit, FarSumSingleLightLimit + 1,
         60000LL, 16 * ShaderLoopLimit })
  {
    const long long batches = (lights + 31) / 32;
    const int master = static_cast<int>((batches + 31) / 32);
    if (lights <= FarSumSingleLightLimit + 1)
    {
      EXPECT_LE(ComputeWalkIterations(lights, lights, master) + ComputeFarSumIterations(lights),
        ShaderLoopLimit)
        << lights;
    }
    EXPECT_LE(ComputeFarSumIterations(lights), ShaderLoopLimit) << lights;
  }
  // One light per iteration up to twice the limit would not fit.
  const long long twice = 2 * FarSumSingleLightLimit;
  EXPECT_GT(ComputeWalkIterations(twice, twice, static_cast<int>((twice / 32 + 31) / 32)) + twice,
    ShaderLoopLimit);
}
