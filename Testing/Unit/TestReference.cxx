// SPDX-License-Identifier: BSD-3-Clause
// The double-precision reference assigner, and the GL-free half of "zero false
// negatives": every (cluster, light) pair the reference finds lies inside the cluster
// range that the pass computes from its sphere bounds.
#include "TestUtilities.h"
#include "vtkClusteredLightingReference.h"

#include <gtest/gtest.h>

#include <random>

using namespace vtkClusteredLighting;
using ClusteredLightingTest::Parallel;
using ClusteredLightingTest::Perspective;

namespace
{
ClusterGridParams SmallGrid(double nearVC, double farVC, SlicingScheme scheme)
{
  return ClusteredLightingTest::MakeGrid(12, 8, 16, 640, 480, nearVC, farVC, scheme);
}
}

TEST(Reference, DistanceToCellMatchesDenseSampling)
{
  const glm::dmat4 P = Perspective(50.0, 1.33, 0.5, 40.0, 0.2, 0.0);
  const ClusterGridParams g = SmallGrid(0.5, 40.0, SlicingScheme::Exponential);
  const ClusterCell cell = ComputeClusterCell(5, 3, 9, g, P, 0.5, 40.0);
  ASSERT_FALSE(cell.Empty);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-8.0, 8.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    const glm::dvec3 p(U(rng), U(rng), -std::abs(U(rng)) - 1.0);
    const double d = DistanceToCell(p, cell);
    // Sample the cell densely (trilinear in corners; faces are planar).
    double best = 1e300;
    const int n = 24;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= n; ++k)
        {
          const double a = double(i) / n, b = double(j) / n, c = double(k) / n;
          glm::dvec3 q(0.0);
          for (int v = 0; v < 8; ++v)
          {
            const double w = ((v & 1) ? a : 1 - a) * ((v & 2) ? b : 1 - b) * ((v & 4) ? c : 1 - c);
            q += w * cell.Corners[v];
          }
          best = std::min(best, glm::length(p - q));
        }
    EXPECT_LE(d, best + 1e-9); // exact distance is never larger than a sampled one
    EXPECT_GE(d, best - 0.08); // and close to it (sampling resolution)
  }
}

TEST(Reference, EveryReferencePairIsInsideTheConservativeClusterRange)
{
  struct Case
  {
    const char* Name;
    glm::dmat4 P;
    double Near, Far;
    SlicingScheme Scheme;
  };
  const Case cases[] = {
    { "perspective", Perspective(60.0, 1.33, 0.2, 50.0), 0.2, 50.0, SlicingScheme::Exponential },
    { "off-axis", Perspective(45.0, 1.33, 0.2, 50.0, 0.7, -0.3), 0.2, 50.0,
      SlicingScheme::Exponential },
    { "wide", Perspective(150.0, 1.33, 0.05, 20.0), 0.05, 20.0, SlicingScheme::Exponential },
    { "parallel", Parallel(6.0, 1.33, 0.5, 50.0), 0.5, 50.0, SlicingScheme::Linear },
  };
  std::mt19937 rng(2024);
  for (const Case& c : cases)
  {
    const ClusterGridParams g = SmallGrid(c.Near, c.Far, c.Scheme);
    std::vector<ReferenceLight> lights;
    std::uniform_real_distribution<double> X(-10.0, 10.0), Z(-30.0, 3.0), R(0.01, 4.0);
    for (int i = 0; i < 200; ++i)
    {
      lights.push_back({ glm::dvec3(X(rng), X(rng) * 0.7, Z(rng)), R(rng) });
    }
    lights.push_back({ glm::dvec3(0.1, 0.0, 0.2), 1.0 });     // camera inside
    lights.push_back({ glm::dvec3(0.0, 0.0, -c.Near), 0.5 }); // centred on the near plane
    lights.push_back({ glm::dvec3(0.0, 0.0, -c.Far), 2.0 });  // straddles the far plane
    lights.push_back({ glm::dvec3(0.0, 0.0, 2.0), 2.5 });     // centre behind the camera
    const ReferenceAssignment ref = ComputeReferenceAssignment(lights, g, c.P, c.Near, c.Far);
    std::uint64_t pairs = 0, covered = 0;
    for (int i = 0; i < static_cast<int>(lights.size()); ++i)
    {
      const SphereScreenBounds b =
        ComputeSphereScreenBounds(lights[i].CenterVC, lights[i].Radius, c.P, c.Near, c.Far);
      const ClusterRange cr = ComputeClusterRange(b, g);
      for (int ty = 0; ty < g.TilesY; ++ty)
        for (int tx = 0; tx < g.TilesX; ++tx)
          for (int s = 0; s < g.Slices; ++s)
          {
            const bool inRange = !cr.IsEmpty() && tx >= cr.TileMin[0] && tx <= cr.TileMax[0] &&
              ty >= cr.TileMin[1] && ty <= cr.TileMax[1] && s >= cr.SliceMin && s <= cr.SliceMax;
            if (ref.Contains(ComputeClusterId(tx, ty, s, g), i))
            {
              ++pairs;
              ASSERT_TRUE(inRange)
                << c.Name << ": light " << i << " cluster (" << tx << "," << ty << "," << s << ")";
            }
            covered += inRange;
          }
    }
    EXPECT_GT(pairs, 1000u) << c.Name;
    // Report culling tightness of the rectangle x slice-range assignment.
    std::cout << "[ reference ] " << c.Name << ": " << pairs << " true pairs, " << covered
              << " assigned, false-positive rate " << (covered - pairs) / double(covered) << "\n";
  }
}

TEST(Reference, CompareCountsFalseNegativesAndMasterMismatches)
{
  ClusterTextureLayout L;
  ClusterGridParams g = SmallGrid(0.5, 50.0, SlicingScheme::Exponential);
  g.TilesX = 2;
  g.TilesY = 2;
  g.Slices = 2;
  ASSERT_TRUE(ComputeLayout(2, 2, 2, 40, 16384, L));
  ReferenceAssignment ref;
  ref.Batches = L.Batches;
  ref.Words.assign(8 * L.Batches, 0u);
  ref.Words[ComputeClusterId(1, 0, 1, g) * L.Batches + 1] = 0x5u; // lights 32 and 34
  std::vector<std::uint32_t> list(L.ListWidth * L.ListHeight, 0u),
    master(L.MasterWidth * L.MasterHeight, 0u);
  const TexelCoord t = L.ListTexel(1, 0, 1, 1);
  list[t.Y * L.ListWidth + t.X] = 0x6u; // light 33 (false positive), 34; 32 missing
  AssignmentComparison cmp = CompareWithReference(ref, list, master, L, g);
  EXPECT_EQ(cmp.FalseNegatives, 1u);
  EXPECT_EQ(cmp.FalsePositives, 1u);
  EXPECT_EQ(cmp.MasterMismatches, 1u); // master bit missing for a non-empty texel
  EXPECT_NE(cmp.FirstFalseNegative.find("light 32"), std::string::npos);
  const TexelCoord m = L.MasterTexel(1, 0, 1, 0);
  master[m.Y * L.MasterWidth + m.X] = 1u << 1;
  EXPECT_EQ(CompareWithReference(ref, list, master, L, g).MasterMismatches, 0u);
}
