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

// What lists per cluster can do at best (MeasureClusterCullingFloor): a wall facing the
// camera, one slice, small lights each well inside one tile. Every pixel of a light's tile
// walks it (the floor), only its disk's pixels are reached: the floor is the tiles' share
// of the pixels, exactly, and finer tiles lower it in proportion.
TEST(Reference, CullingFloorIsTheLightsOfEachClusterReachingSomeFragment)
{
  const int size = 64;
  const double nearVC = 1.0, farVC = 10.0, wall = 5.0;
  const glm::dmat4 P = Perspective(40.0, 1.0, nearVC, farVC);
  const std::vector<float> depth(
    static_cast<std::size_t>(size) * size, static_cast<float>(WindowDepthFromViewDepth(wall, P)));
  const DepthImage image{ depth.data(), size, size };
  // Lights on the wall at pixel centres well inside 16 x 16 pixel tiles (and 8 x 8 ones),
  // each reaching 2.5 pixels around it.
  const double pixel = 2.0 * wall * std::tan(20.0 * 3.14159265358979323846 / 180.0) / size;
  std::vector<ReferenceLight> lights;
  for (const glm::ivec2 at : { glm::ivec2(4, 4), glm::ivec2(20, 44), glm::ivec2(52, 12) })
  {
    const glm::dvec3 c =
      UnprojectAtDepth(2.0 * (at.x + 0.5) / size - 1.0, 2.0 * (at.y + 0.5) / size - 1.0, wall, P);
    lights.push_back({ c, 2.5 * pixel });
  }
  // A spot light whose cone points away from the wall reaches no pixel, so it raises the
  // cells' count but not the floor.
  const glm::dvec3 spot = UnprojectAtDepth(0.3, -0.3, wall - 0.5 * pixel, P);
  lights.push_back({ spot, 3.0 * pixel, glm::dvec3(0.0, 0.0, 1.0), std::cos(0.3) });
  for (const int tiles : { 4, 8 })
  {
    const ClusterGridParams g = ClusteredLightingTest::MakeGrid(
      tiles, tiles, 1, size, size, nearVC, farVC, SlicingScheme::Exponential);
    const ReferenceAssignment ref = ComputeReferenceAssignment(lights, g, P, nearVC, farVC);
    const ClusterCullingFloor f = MeasureClusterCullingFloor(image, P, g, lights, ref);
    ASSERT_EQ(f.Pixels, depth.size());
    const double tilePixels = static_cast<double>(size / tiles) * (size / tiles);
    EXPECT_DOUBLE_EQ(f.Floor, 3.0 * tilePixels / depth.size()) << tiles << " tiles";
    // Each point light reaches the pixels within 2.5 pixels of its own: 21 of them.
    EXPECT_DOUBLE_EQ(f.Reaching, 3.0 * 21.0 / depth.size()) << tiles << " tiles";
    // The reference's cells hold the spot light too (its ball reaches the wall's slab).
    EXPECT_GT(f.Cells, f.Floor) << tiles << " tiles";
  }
  // Nothing to measure without a matching reference.
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(4, 4, 1, size, size, nearVC, farVC, SlicingScheme::Exponential);
  EXPECT_EQ(MeasureClusterCullingFloor(image, P, g, lights, ReferenceAssignment()).Pixels, 0u);
}
