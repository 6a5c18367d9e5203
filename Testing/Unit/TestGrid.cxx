// SPDX-License-Identifier: BSD-3-Clause
#include "TestUtilities.h"
#include "vtkClusteredLightingGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace vtkClusteredLighting;

namespace
{
ClusterGridParams MakeGrid(SlicingScheme scheme, double nearVC = 0.5, double farVC = 500.0)
{
  return ClusteredLightingTest::MakeGrid(32, 16, 32, 1024, 768, nearVC, farVC, scheme);
}
}

TEST(ClusterGrid, SliceIndexIsMonotonicInDepth)
{
  for (auto scheme : { SlicingScheme::Exponential, SlicingScheme::Linear })
  {
    const ClusterGridParams g = MakeGrid(scheme);
    int last = ComputeSliceIndex(-10.0, g);
    for (double z = -10.0; z < 2000.0; z = z * 1.001 + 0.0137)
    {
      const int s = ComputeSliceIndex(z, g);
      EXPECT_GE(s, last) << "depth " << z;
      last = s;
    }
    EXPECT_EQ(last, g.Slices - 1);
  }
}

TEST(ClusterGrid, SliceIndexIsClampedAndDefinedForNonPositiveDepths)
{
  for (auto scheme : { SlicingScheme::Exponential, SlicingScheme::Linear })
  {
    const ClusterGridParams g = MakeGrid(scheme);
    const double inf = std::numeric_limits<double>::infinity();
    for (double z : { -inf, -1e30, -1.0, 0.0, 1e-300, 0.25, 0.5 })
    {
      EXPECT_EQ(ComputeSliceIndex(z, g), 0) << "depth " << z;
    }
    for (double z : { 500.0, 501.0, 1e30, inf })
    {
      EXPECT_EQ(ComputeSliceIndex(z, g), g.Slices - 1) << "depth " << z;
    }
    EXPECT_EQ(ComputeSliceIndex(std::nan(""), g), 0);
  }
}

TEST(ClusterGrid, SliceBoundariesMapExactlyToTheirSlice)
{
  for (auto scheme : { SlicingScheme::Exponential, SlicingScheme::Linear })
  {
    for (double ratio : { 1.0001, 10.0, 1e4, 1e6, 1e10 })
    {
      const ClusterGridParams g = MakeGrid(scheme, 0.01, 0.01 * ratio);
      for (int k = 0; k < g.Slices; ++k)
      {
        const double zk = ComputeSliceBoundary(k, g);
        EXPECT_EQ(ComputeSliceIndex(zk, g), k) << "ratio " << ratio << " k " << k;
        if (k > 0)
        {
          EXPECT_EQ(ComputeSliceIndex(std::nextafter(zk, 0.0), g), k - 1)
            << "ratio " << ratio << " k " << k;
        }
      }
    }
  }
}

TEST(ClusterGrid, ExponentialSlicesGrowGeometrically)
{
  const ClusterGridParams g = MakeGrid(SlicingScheme::Exponential, 1.0, 102.4);
  const double growth = ComputeSliceBoundary(2, g) / ComputeSliceBoundary(1, g);
  for (int k = 1; k < g.Slices; ++k)
  {
    EXPECT_NEAR(ComputeSliceBoundary(k + 1, g) / ComputeSliceBoundary(k, g), growth, 1e-12);
  }
  EXPECT_NEAR(growth, std::pow(102.4, 1.0 / 32.0), 1e-12);
}

TEST(ClusterGrid, ShaderParametersReproduceSliceCoordinate)
{
  for (auto scheme : { SlicingScheme::Exponential, SlicingScheme::Linear })
  {
    const ClusterGridParams g = MakeGrid(scheme);
    double p[4];
    ComputeSliceShaderParameters(g, p);
    for (double z : { 0.6, 1.0, 7.5, 99.0, 499.0 })
    {
      const double gpu =
        p[3] == 0.0 ? std::log(z * p[0]) * p[1] : (z - p[2]) * p[1]; // the GLSL formula
      EXPECT_NEAR(gpu, ComputeSliceCoordinate(z, g), 1e-9);
    }
  }
}

TEST(ClusterGrid, TileIndexIsClamped)
{
  EXPECT_EQ(ComputeTileIndex(0.5, 1024, 32), 0);
  EXPECT_EQ(ComputeTileIndex(31.5, 1024, 32), 0);
  EXPECT_EQ(ComputeTileIndex(32.5, 1024, 32), 1);
  EXPECT_EQ(ComputeTileIndex(1023.5, 1024, 32), 31);
  EXPECT_EQ(ComputeTileIndex(5000.0, 1024, 32), 31);
  EXPECT_EQ(ComputeTileIndex(-3.0, 1024, 32), 0);
  EXPECT_EQ(ComputeTileIndex(0.5, 1, 32), 16); // 1-pixel viewport: pixel centre
}

TEST(ClusterGrid, SanitizeDepthRangeAlwaysGivesAValidRange)
{
  const double nan = std::nan("");
  for (double n : { nan, -1.0, 0.0, 1e-9, 2.0 })
  {
    for (double f : { nan, -1.0, 0.0, 1.0, 1e9 })
    {
      double a = n, b = f;
      SanitizeDepthRange(a, b);
      EXPECT_GT(a, 0.0);
      EXPECT_GT(b, a);
      EXPECT_TRUE(std::isfinite(a) && std::isfinite(b));
    }
  }
}
