// SPDX-License-Identifier: BSD-3-Clause
// Packing of the list-pass and shading uniforms from a view (GL-free core).
#include "TestUtilities.h"
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingReference.h"

#include <gtest/gtest.h>

#include <random>

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
