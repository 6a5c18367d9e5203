// SPDX-License-Identifier: BSD-3-Clause
// Morton codes, bit packing and texture layouts.
#include "vtkClusteredLightingLayout.h"
#include "vtkClusteredLightingMorton.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <set>

using namespace vtkClusteredLighting;

TEST(Morton, SpreadAndCompactRoundTrip)
{
  for (std::uint32_t v = 0; v < 1024; ++v)
  {
    EXPECT_EQ(CompactBits10(SpreadBits10(v)), v);
    EXPECT_EQ(SpreadBits10(v) & ~0x09249249u, 0u);
  }
}

TEST(Morton, CodeIsABijectionOn10BitTriples)
{
  std::set<std::uint32_t> codes;
  for (std::uint32_t x = 0; x < 1024; x += 37)
  {
    for (std::uint32_t y = 0; y < 1024; y += 41)
    {
      for (std::uint32_t z = 0; z < 1024; z += 43)
      {
        const std::uint32_t m = MortonCode3D(x, y, z);
        EXPECT_LT(m, 1u << 30);
        EXPECT_EQ(CompactBits10(m), x);
        EXPECT_EQ(CompactBits10(m >> 1), y);
        EXPECT_EQ(CompactBits10(m >> 2), z);
        codes.insert(m);
      }
    }
  }
  EXPECT_EQ(codes.size(), 28u * 25u * 24u);
}

TEST(Morton, OrderIsAPermutationAndGroupsNearbyPoints)
{
  // Shuffled points of an 8x8x8 lattice: after sorting, each aligned run of 8 lights
  // (a Morton octant) spans a single 2x2x2 cell.
  std::vector<glm::dvec3> pts;
  for (int i = 0; i < 512; ++i)
  {
    const int j = (i * 197) % 512;
    pts.emplace_back(j % 8, (j / 8) % 8, j / 64);
  }
  const std::vector<std::uint32_t> order = ComputeMortonOrder(pts);
  std::set<std::uint32_t> unique(order.begin(), order.end());
  ASSERT_EQ(unique.size(), pts.size());
  for (std::size_t k = 0; k < order.size(); k += 8)
  {
    glm::dvec3 lo(1e9), hi(-1e9);
    for (std::size_t m = k; m < k + 8; ++m)
    {
      lo = glm::min(lo, pts[order[m]]);
      hi = glm::max(hi, pts[order[m]]);
    }
    EXPECT_LE(hi.x - lo.x, 1.0);
    EXPECT_LE(hi.y - lo.y, 1.0);
    EXPECT_LE(hi.z - lo.z, 1.0);
  }
}

TEST(Morton, QuantizerHasNoOutOfRangeConversion)
{
  const double inf = std::numeric_limits<double>::infinity();
  for (double t : { -inf, -1e300, -1.0, 0.0, 0.5, 1.0, 2.0, 1e300, inf, std::nan("") })
  {
    const std::uint32_t q = QuantizeMorton10(t, 0.0, 1.0);
    EXPECT_LE(q, 1023u);
  }
  EXPECT_EQ(QuantizeMorton10(5.0, 5.0, 5.0), 0u); // empty extent
}

TEST(BitPacking, LightBatchBitRoundTrip)
{
  for (int i = 0; i < 70000; i += 7)
  {
    EXPECT_EQ(LightOfBatchBit(BatchOfLight(i), BitOfLight(i)), i);
    EXPECT_LT(BitOfLight(i), 32);
    const int b = BatchOfLight(i);
    EXPECT_EQ(MasterTexelOfBatch(b) * 32 + MasterBitOfBatch(b), b);
  }
}

TEST(Layout, ListTexelsAreUniqueAndInside)
{
  for (int n : { 1, 31, 32, 33, 1024, 1025, 2016 })
  {
    ClusterTextureLayout L;
    // A small max texture size forces several block columns.
    ASSERT_TRUE(ComputeLayout(4, 3, 5, n, 64, L)) << n;
    std::set<std::pair<int, int>> seen;
    for (int b = 0; b < L.Batches; ++b)
    {
      for (int ty = 0; ty < 3; ++ty)
      {
        for (int tx = 0; tx < 4; ++tx)
        {
          for (int s = 0; s < 5; ++s)
          {
            const TexelCoord t = L.ListTexel(tx, ty, s, b);
            ASSERT_GE(t.X, 0);
            ASSERT_LT(t.X, L.ListWidth);
            ASSERT_GE(t.Y, 0);
            ASSERT_LT(t.Y, L.ListHeight);
            ASSERT_TRUE(seen.insert({ t.X, t.Y }).second);
            EXPECT_EQ((t.X % (4 * 5)) / 4, s); // slice-major inside a block
            EXPECT_EQ(t.X % 4, tx);
          }
        }
      }
    }
    EXPECT_EQ(ComputeMaximumNumberOfLights(4, 3, 5, 64), 2016);
    EXPECT_LE(L.ListWidth, 64);
    EXPECT_LE(L.ListHeight, 64);
    EXPECT_EQ(L.MasterTexelsPerCluster, (L.Batches + 31) / 32);
  }
}

TEST(Layout, DefaultGridMemoryMatchesFormula)
{
  ClusterTextureLayout L;
  ASSERT_TRUE(ComputeLayout(32, 16, 32, 4096, 16384, L));
  EXPECT_EQ(L.GetListBytes(), 32ull * 16 * 32 * 4096 / 8); // 8 MiB
  EXPECT_EQ(L.BatchColumns, 1);
  ASSERT_TRUE(ComputeLayout(32, 16, 32, 65536, 16384, L));
  EXPECT_EQ(L.GetListBytes(), 128ull << 20);
  EXPECT_EQ(L.ListHeight, 16384);
  ASSERT_TRUE(ComputeLayout(32, 16, 32, 65537, 16384, L));
  EXPECT_EQ(L.Batches, 2049);
  EXPECT_EQ(L.BatchColumns, 3); // wraps into more block columns instead of failing
  EXPECT_LE(L.ListHeight, 16384);
}

TEST(Layout, LimitIsReportedNotTruncated)
{
  const std::int64_t maxN = ComputeMaximumNumberOfLights(32, 16, 32, 16384);
  EXPECT_EQ(maxN, 524288);
  ClusterTextureLayout L;
  std::string error;
  EXPECT_TRUE(ComputeLayout(32, 16, 32, static_cast<int>(maxN), 16384, L, &error));
  EXPECT_FALSE(ComputeLayout(32, 16, 32, static_cast<int>(maxN) + 1, 16384, L, &error));
  EXPECT_NE(error.find("at most 524288"), std::string::npos) << error;
  EXPECT_FALSE(ComputeLayout(1024, 16, 32, 10, 16384, L, &error)); // X*Z too wide
}

TEST(Layout, PastTheLimitASmallerGridHoldsTheLights)
{
  // The case: 1,000,200 lights on the default grid at 16,384 texels.
  int x = 32, y = 16, z = 32;
  ASSERT_TRUE(ChooseGridForLights(x, y, z, 1000200, 16384));
  EXPECT_GE(ComputeMaximumNumberOfLights(x, y, z, 16384), 1000200);
  EXPECT_LT(x * y * z, 32 * 16 * 32);
  // Halving one dimension is enough here, and the chosen grid is one of those.
  EXPECT_EQ(x * y * z * 2, 32 * 16 * 32) << x << "x" << y << "x" << z;
  ClusterTextureLayout L;
  EXPECT_TRUE(ComputeLayout(x, y, z, 1000200, 16384, L));

  // A grid that already holds the lights is kept.
  x = 32, y = 16, z = 32;
  EXPECT_TRUE(ChooseGridForLights(x, y, z, 524288, 16384));
  EXPECT_EQ(x, 32);
  EXPECT_EQ(y, 16);
  EXPECT_EQ(z, 32);

  // Every grid the search returns holds the lights, for many grids, counts and texture
  // sizes; none is returned larger than asked on any axis; when it fails, 1x1x1 does not
  // hold them either.
  for (int maxTexture : { 16, 256, 1024, 16384 })
  {
    for (std::int64_t n : { 1, 33, 5000, 70000, 1000200, 20000000 })
    {
      for (const auto& asked : { std::array<int, 3>{ 32, 16, 32 },
             std::array<int, 3>{ 256, 256, 64 }, std::array<int, 3>{ 7, 3, 100 } })
      {
        int gx = asked[0], gy = asked[1], gz = asked[2];
        const bool ok = ChooseGridForLights(gx, gy, gz, n, maxTexture);
        if (ok)
        {
          EXPECT_GE(ComputeMaximumNumberOfLights(gx, gy, gz, maxTexture), n);
          EXPECT_TRUE(gx <= asked[0] && gy <= asked[1] && gz <= asked[2]);
          EXPECT_TRUE(gx >= 1 && gy >= 1 && gz >= 1);
          EXPECT_TRUE(ComputeLayout(gx, gy, gz, static_cast<int>(n), maxTexture, L));
        }
        else
        {
          EXPECT_LT(ComputeMaximumNumberOfLights(1, 1, 1, maxTexture), n);
          EXPECT_EQ(gx * gy * gz, 1);
        }
      }
    }
  }
}
