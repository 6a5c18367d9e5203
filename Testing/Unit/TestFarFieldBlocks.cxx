// SPDX-License-Identifier: BSD-3-Clause
// The far field's blocks that surfaces read (vtkClusteredLightingFarFieldBlocks.h): every
// node a point's trilinear read takes lies in a marked layer of a marked block, for points
// inside, on the edge of and far outside the grid; a floor on a node plane marks two
// layers of one row of blocks; a build of the marked layers writes exactly the values a
// whole build writes there (spot lights and the specular's bins included) and leaves
// every other node alone; a later build adds only what is missing. In a multisampled
// framebuffer, the marks of the prepass's recorded depths hold every node that a fragment
// shaded at its pixel's centre, at any depth its pixel's fragments have, reads (at scales
// from 1e-3 to 1e6, perspective and parallel), and a record that cannot say marks nothing.
#include "TestUtilities.h"
#include "vtkClusteredLightingFarFieldBlocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{

/// A grid that does not start at the origin, of uneven dimensions (partial blocks).
FarFieldGrid MakeGrid()
{
  FarFieldGrid g;
  g.Origin = glm::dvec3(-3.25, 10.5, 1e3);
  g.Spacing = 0.37;
  g.Dims = { { 13, 9, 18 } };
  return g;
}

/// The block of node (i, j, k) and the node's bit in the block's mask.
std::size_t BlockOf(const FarFieldGrid& g, int i, int j, int k)
{
  const std::array<int, 3> b = GetFarFieldBlocks(g);
  return static_cast<std::size_t>(
    ((k / FarFieldBlockSize) * b[1] + j / FarFieldBlockSize) * b[0] + i / FarFieldBlockSize);
}

/// Whether node (i, j, k) is set in `masks` (one mask of nodes per block).
bool IsMarked(const FarFieldGrid& g, const std::vector<std::uint64_t>& masks, int i, int j, int k)
{
  const int bit =
    GetFarFieldBlockBit(i % FarFieldBlockSize, j % FarFieldBlockSize, k % FarFieldBlockSize);
  return (masks[BlockOf(g, i, j, k)] >> bit) & 1u;
}

/// Calls f(i, j, k) for every node of the grid.
template <typename F>
void ForEachNode(const FarFieldGrid& g, F f)
{
  for (int k = 0; k < g.Dims[2]; ++k)
  {
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        f(i, j, k);
      }
    }
  }
}

/// The nodes a texture read at world point p takes (linear filter, clamped to edge).
std::vector<glm::ivec3> NodesRead(const FarFieldGrid& g, const glm::dvec3& p)
{
  std::array<std::array<int, 2>, 3> n;
  for (int a = 0; a < 3; ++a)
  {
    const double c = (p[a] - g.Origin[a]) / g.Spacing;
    const double last = g.Dims[static_cast<std::size_t>(a)] - 1;
    const double f = std::floor(c);
    n[static_cast<std::size_t>(a)] = { { static_cast<int>(std::min(std::max(f, 0.0), last)),
      static_cast<int>(std::min(std::max(f + 1.0, 0.0), last)) } };
  }
  std::vector<glm::ivec3> nodes;
  for (int c = 0; c < 8; ++c)
  {
    nodes.emplace_back(n[0][c & 1], n[1][(c >> 1) & 1], n[2][(c >> 2) & 1]);
  }
  return nodes;
}

} // namespace

TEST(FarFieldBlocks, EveryNodeAPointReadsIsMarked)
{
  const FarFieldGrid g = MakeGrid();
  const glm::dvec3 lo = g.Origin, hi = g.NodePosition(g.Dims[0] - 1, g.Dims[1] - 1, g.Dims[2] - 1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-0.3, 1.3); // beyond the grid on every side too
  for (int trial = 0; trial < 2000; ++trial)
  {
    const glm::dvec3 a = lo + glm::dvec3(U(rng), U(rng), U(rng)) * (hi - lo);
    const glm::dvec3 size = (trial % 3 == 0 ? 0.0 : 0.2) * glm::dvec3(U(rng), U(rng), U(rng));
    const glm::dvec3 boxLo = a, boxHi = a + glm::abs(size) * (hi - lo);
    std::vector<std::uint64_t> needed(static_cast<std::size_t>(GetNumberOfFarFieldBlocks(g)), 0);
    MarkFarFieldBlocks(g, boxLo, boxHi, needed);
    for (int s = 0; s < 20; ++s)
    {
      std::uniform_real_distribution<double> V(0.0, 1.0);
      const glm::dvec3 p = boxLo + glm::dvec3(V(rng), V(rng), V(rng)) * (boxHi - boxLo);
      for (const glm::ivec3& n : NodesRead(g, p))
      {
        ASSERT_TRUE(IsMarked(g, needed, n.x, n.y, n.z))
          << "trial " << trial << ": node " << n.x << " " << n.y << " " << n.z;
      }
    }
    // Points exactly on node planes read the next node with weight 0: still marked.
    const glm::dvec3 onNode =
      g.NodePosition(trial % g.Dims[0], trial % g.Dims[1], trial % g.Dims[2]);
    std::vector<std::uint64_t> one(needed.size(), 0);
    MarkFarFieldBlocks(g, onNode, onNode, one);
    for (const glm::ivec3& n : NodesRead(g, onNode))
    {
      ASSERT_TRUE(IsMarked(g, one, n.x, n.y, n.z));
    }
  }
}

TEST(FarFieldBlocks, AFloorOnANodePlaneIsSummedInTwoLayers)
{
  const FarFieldGrid g = MakeGrid();
  const std::array<int, 3> blocks = GetFarFieldBlocks(g);
  const glm::dvec3 last = g.NodePosition(g.Dims[0] - 1, g.Dims[1] - 1, g.Dims[2] - 1);
  // A floor across z (on the bottom node plane) and one across y (y up, as VTK's cameras).
  for (int up : { 2, 1 })
  {
    std::vector<std::uint64_t> needed(static_cast<std::size_t>(GetNumberOfFarFieldBlocks(g)), 0);
    glm::dvec3 a = g.Origin - glm::dvec3(1.0), b = last + glm::dvec3(1.0);
    a[up] = b[up] = g.Origin[up];
    const std::int64_t added = MarkFarFieldBlocks(g, a, b, needed);
    const int across = blocks[0] * blocks[up == 2 ? 1 : 2];
    EXPECT_EQ(added, across) << "up axis " << up;
    ForEachNode(g,
      [&](int i, int j, int k)
      {
        const int height = up == 2 ? k : j;
        ASSERT_EQ(IsMarked(g, needed, i, j, k), height <= 1)
          << "up axis " << up << ", node " << i << " " << j << " " << k;
      });
    const FarFieldBlockList list = GetFarFieldBlocksToBuild(needed, {});
    ASSERT_EQ(static_cast<std::int64_t>(list.Blocks.size()), added);
    for (std::size_t q = 0; q < list.Blocks.size(); ++q)
    {
      // Two layers across the floor; a block at the grid's end with fewer nodes along
      // another axis (13 = 3 x 4 + 1 along x) may be taken along that one.
      int first, last;
      GetFarFieldLayerRange(list.Layers[q], first, last);
      EXPECT_LE(last - first + 1, 2);
      const std::int64_t b = list.Blocks[q];
      const bool full = b % blocks[0] < blocks[0] - 1 &&
        (b / blocks[0]) % blocks[1] < blocks[1] - 1 && b / (blocks[0] * blocks[1]) < blocks[2] - 1;
      if (full)
      {
        EXPECT_EQ(list.Axis[q], up);
        EXPECT_EQ(list.Layers[q], 0x3);
      }
    }
    // A second floor one cell up marks one more layer, no new block; the next build sums
    // that layer only.
    const std::vector<std::uint64_t> before = needed;
    glm::dvec3 step(0.0);
    step[up] = g.Spacing;
    EXPECT_EQ(MarkFarFieldBlocks(g, a + step, b + step, needed), 0);
    const FarFieldBlockList more = GetFarFieldBlocksToBuild(needed, before);
    ASSERT_EQ(static_cast<std::int64_t>(more.Blocks.size()), added);
    EXPECT_EQ(more.Axis[0], up);
    EXPECT_EQ(more.Layers[0], 0x4);
    EXPECT_TRUE(GetFarFieldBlocksToBuild(needed, needed).Blocks.empty());
  }
}

TEST(FarFieldBlocks, NotANumberAndFarAwayAreClamped)
{
  const FarFieldGrid g = MakeGrid();
  const std::size_t count = static_cast<std::size_t>(GetNumberOfFarFieldBlocks(g));
  const double nan = std::nan("");
  // x not a number: every node along x; y and z: the clamped point's (node 0 of each).
  std::vector<std::uint64_t> row(count, 0);
  MarkFarFieldBlocks(g, glm::dvec3(nan, 0.0, 0.0), glm::dvec3(nan, 0.0, 0.0), row);
  ForEachNode(
    g, [&](int i, int j, int k) { ASSERT_EQ(IsMarked(g, row, i, j, k), j == 0 && k == 0); });
  std::vector<std::uint64_t> all(count, 0);
  MarkFarFieldBlocks(g, glm::dvec3(nan), glm::dvec3(nan), all);
  ForEachNode(g, [&](int i, int j, int k) { ASSERT_TRUE(IsMarked(g, all, i, j, k)); });
  // Far outside (1e300): clamped into the grid (the last node), no overflow.
  std::vector<std::uint64_t> far(count, 0);
  EXPECT_EQ(MarkFarFieldBlocks(g, glm::dvec3(1e300), glm::dvec3(1e300), far), 1);
  ForEachNode(g,
    [&](int i, int j, int k)
    {
      ASSERT_EQ(
        IsMarked(g, far, i, j, k), i == g.Dims[0] - 1 && j == g.Dims[1] - 1 && k == g.Dims[2] - 1);
    });
}

TEST(FarFieldBlocks, ABuildOfTheMarkedLayersIsTheWholeBuildThere)
{
  // Inverse-square lights, every fifth a spot light, over a grid of partial blocks.
  std::vector<LightSource> sources(400);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (std::size_t i = 0; i < sources.size(); ++i)
  {
    LightSource& s = sources[i];
    s.PositionWC = glm::dvec3(4.0 * U(rng), 3.0 * U(rng), 2.0 * U(rng));
    s.Color = glm::dvec3(0.3 + 0.7 * U(rng), 0.3 + 0.7 * U(rng), 0.3 + 0.7 * U(rng));
    s.Attenuation = glm::dvec3(0.0, 0.0, 1.0);
    if (i % 5 == 0)
    {
      s.ConeAngle = 20.0 + 50.0 * U(rng);
      s.Exponent = std::floor(10.0 * U(rng)) + (i % 10 == 0 ? 0.5 : 0.0);
      s.DirectionWC = glm::normalize(glm::dvec3(U(rng) - 0.5, U(rng) - 0.5, -1.0));
    }
  }
  std::vector<PreparedLight> lights =
    PrepareLights(sources, LightPreparationOptions{ 1.0 / 1024.0, false }).Lights;
  FarFieldOptions options;
  options.TargetNodes = 6000;
  options.SpecularBins = true;
  const FarFieldPlan plan =
    PlanFarField(lights, glm::dvec3(0.0), glm::dvec3(4.0, 3.0, 2.0), options);
  ASSERT_TRUE(plan.Active);
  const FarFieldGrid& g = plan.Grid;
  const std::vector<double> radii = GetFarFieldNearRadii(lights);
  const FarFieldLightTree tree = BuildFarFieldLightTree(lights, radii);
  const std::size_t nodes = static_cast<std::size_t>(g.GetNumberOfNodes());
  // Both builds in the copy the product runs: the same operations per node, so the same
  // bits, whichever nodes a block sums.
  const FarFieldBuildCopy copy = GetFarFieldBuildCopyForThisCPU();
  std::vector<double> whole(nodes * FarFieldFloatsPerNode, 0.0);
  std::vector<float> wholeBins(nodes * FarSpecularFloatsPerNode, 0.0f);
  ComputeFarFieldMomentsWith(copy, g, lights, radii, tree, 1.0, 0, GetNumberOfFarFieldBlocks(g),
    whole, -1, true, &wholeBins);

  // Surfaces: a floor on the bottom node plane and a small box in the middle.
  std::vector<std::uint64_t> needed(static_cast<std::size_t>(GetNumberOfFarFieldBlocks(g)), 0);
  MarkFarFieldBlocks(g, glm::dvec3(0.0, 0.0, g.Origin.z), glm::dvec3(4.0, 3.0, g.Origin.z), needed);
  MarkFarFieldBlocks(g, glm::dvec3(1.9, 1.4, 0.9), glm::dvec3(2.1, 1.6, 1.1), needed);
  const double sentinel = 12345.0;
  std::vector<double> part(whole.size(), sentinel);
  std::vector<float> partBins(wholeBins.size(), 7.0f);
  const FarFieldBlockList list = GetFarFieldBlocksToBuild(needed, {});
  ASSERT_LT(list.Blocks.size(), needed.size());
  ComputeFarFieldMomentsWith(copy, g, lights, radii, tree, 1.0, 0,
    static_cast<std::int64_t>(list.Blocks.size()), part, -1, true, &partBins, &list);
  // What the build summed: each listed block's layers from the lowest to the highest.
  std::vector<std::uint64_t> summed(needed.size(), 0);
  for (std::size_t q = 0; q < list.Blocks.size(); ++q)
  {
    int first, last;
    GetFarFieldLayerRange(list.Layers[q], first, last);
    summed[static_cast<std::size_t>(list.Blocks[q])] =
      GetFarFieldLayerMask(list.Axis[q], first, last);
  }
  std::size_t marked = 0;
  ForEachNode(g,
    [&](int i, int j, int k)
    {
      const std::size_t n = static_cast<std::size_t>(g.NodeIndex(i, j, k));
      const bool in = IsMarked(g, summed, i, j, k);
      ASSERT_TRUE(in || !IsMarked(g, needed, i, j, k)) << "a marked node not summed";
      marked += IsMarked(g, needed, i, j, k) ? 1 : 0;
      for (int m = 0; m < FarFieldFloatsPerNode; ++m)
      {
        const double w = whole[n * FarFieldFloatsPerNode + static_cast<std::size_t>(m)];
        const double p = part[n * FarFieldFloatsPerNode + static_cast<std::size_t>(m)];
        ASSERT_EQ(p, in ? w : sentinel) << "node " << i << " " << j << " " << k << " moment " << m;
      }
      for (int m = 0; m < FarSpecularFloatsPerNode; ++m)
      {
        const float w = wholeBins[n * FarSpecularFloatsPerNode + static_cast<std::size_t>(m)];
        const float p = partBins[n * FarSpecularFloatsPerNode + static_cast<std::size_t>(m)];
        ASSERT_EQ(p, in ? w : 7.0f) << "node " << i << " " << j << " " << k << " bin float " << m;
      }
    });
  EXPECT_GT(marked, 0u);
  EXPECT_LT(marked, nodes / 2);

  // A later build of more surfaces sums only what is missing.
  std::vector<std::uint64_t> more = needed;
  MarkFarFieldBlocks(g, glm::dvec3(0.0, 0.0, 1.9), glm::dvec3(0.1, 0.1, 1.95), more);
  const FarFieldBlockList extra = GetFarFieldBlocksToBuild(more, needed);
  ASSERT_FALSE(extra.Blocks.empty());
  for (std::size_t q = 0; q < extra.Blocks.size(); ++q)
  {
    const std::size_t b = static_cast<std::size_t>(extra.Blocks[q]);
    int first, last;
    GetFarFieldLayerRange(extra.Layers[q], first, last);
    const std::uint64_t missing = more[b] & ~needed[b];
    EXPECT_NE(missing, 0u);
    EXPECT_EQ(GetFarFieldLayerMask(extra.Axis[q], first, last) & missing, missing);
  }
  EXPECT_TRUE(GetFarFieldBlocksToBuild(more, more).Blocks.empty());
}

namespace
{
/// A multisampled view of a ball on a floor (world z up) from a camera above and in
/// front, `scale` sized, far from the origin: per pixel the window depth of the nearest
/// hit at its centre (24-bit), as Depth; as the range of depths a multisampled prepass
/// records (vtkClusteredLightingSampleDepths), [Depth, DepthMax] spans the depths of the
/// pixel and its 8 neighbours (primitives of the neighbours extrapolated to this centre,
/// which at the ball's silhouette reach the floor behind it). Background pixels read 1.
struct MultisampledView
{
  int Width = 96, Height = 72;
  glm::dmat4 WCVC, VCDC;
  std::vector<float> Depth, DepthMax;
  vtkClusteredLighting::DepthImage Image() const
  {
    return { this->Depth.data(), this->Width, this->Height, this->DepthMax.data() };
  }
  /// The world point of pixel (x, y)'s centre at window depth w.
  glm::dvec3 WorldPoint(int x, int y, double w) const
  {
    const glm::dvec4 ndc(2.0 * (x + 0.5) / this->Width - 1.0, 2.0 * (y + 0.5) / this->Height - 1.0,
      2.0 * w - 1.0, 1.0);
    const glm::dvec4 vc = glm::inverse(this->VCDC) * ndc;
    const glm::dvec4 wc = glm::inverse(this->WCVC) * (vc / vc.w);
    return glm::dvec3(wc) / wc.w;
  }
};

MultisampledView RenderBallOnFloor(bool parallel, double scale, const glm::dvec3& offset)
{
  MultisampledView v;
  const glm::dvec3 centre = offset + scale * glm::dvec3(0.0, 0.0, 1.0);
  const double radius = scale;
  const glm::dvec3 eye = offset + scale * glm::dvec3(0.5, -6.0, 3.5);
  v.WCVC = glm::lookAt(eye, centre, glm::dvec3(0.0, 0.0, 1.0));
  const double nearVC = 2.0 * scale, farVC = 20.0 * scale;
  v.VCDC = parallel ? ClusteredLightingTest::Parallel(2.5 * scale, 4.0 / 3.0, nearVC, farVC)
                    : ClusteredLightingTest::Perspective(35.0, 4.0 / 3.0, nearVC, farVC);
  const glm::dmat4 inv = glm::inverse(v.VCDC * v.WCVC);
  std::vector<float> depth(static_cast<std::size_t>(v.Width) * v.Height, 1.0f);
  for (int y = 0; y < v.Height; ++y)
  {
    for (int x = 0; x < v.Width; ++x)
    {
      const double nx = 2.0 * (x + 0.5) / v.Width - 1.0, ny = 2.0 * (y + 0.5) / v.Height - 1.0;
      const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0);
      const glm::dvec4 b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 o = glm::dvec3(a) / a.w, e = glm::dvec3(b) / b.w;
      const glm::dvec3 d = e - o; // t in [0, 1] spans near to far
      double t = 2.0;
      if (d.z < 0.0)
      {
        t = std::min(t, (offset.z - o.z) / d.z); // the floor
      }
      const glm::dvec3 oc = o - centre;
      const double qa = glm::dot(d, d), qb = glm::dot(oc, d),
                   qc = glm::dot(oc, oc) - radius * radius;
      const double disc = qb * qb - qa * qc;
      if (disc >= 0.0)
      {
        const double ts = (-qb - std::sqrt(disc)) / qa;
        t = ts > 0.0 ? std::min(t, ts) : t;
      }
      if (t > 1.0)
      {
        continue;
      }
      const glm::dvec4 clip = v.VCDC * v.WCVC * glm::dvec4(o + t * d, 1.0);
      const double w = 0.5 * clip.z / clip.w + 0.5;
      depth[static_cast<std::size_t>(y) * v.Width + x] =
        static_cast<float>(std::round(w * 16777216.0) / 16777216.0);
    }
  }
  v.Depth.assign(depth.size(), 1.0f);
  v.DepthMax.assign(depth.size(), 1.0f);
  for (int y = 0; y < v.Height; ++y)
  {
    for (int x = 0; x < v.Width; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * v.Width + x;
      if (depth[p] >= 1.0f)
      {
        continue; // no fragment here
      }
      float lo = depth[p], hi = depth[p];
      for (int j = std::max(y - 1, 0); j <= std::min(y + 1, v.Height - 1); ++j)
      {
        for (int i = std::max(x - 1, 0); i <= std::min(x + 1, v.Width - 1); ++i)
        {
          const float n = depth[static_cast<std::size_t>(j) * v.Width + i];
          lo = n < 1.0f ? std::min(lo, n) : lo;
          hi = n < 1.0f ? std::max(hi, n) : hi;
        }
      }
      v.Depth[p] = lo;
      v.DepthMax[p] = hi;
    }
  }
  return v;
}
} // namespace

TEST(FarFieldBlocks, RecordedPixelsMarkEveryNodeAMultisampledFragmentReads)
{
  for (double scale : { 1e-3, 1.0, 1e6 })
  {
    for (bool parallel : { false, true })
    {
      const glm::dvec3 offset = scale * glm::dvec3(30.0, -12.0, 4.0);
      const MultisampledView v = RenderBallOnFloor(parallel, scale, offset);
      // The far field's grid over the floor's middle and the ball, 0.25 of the ball's
      // radius per cell (as the pass's grids: a few cells per light radius).
      FarFieldGrid g;
      g.Origin = offset + scale * glm::dvec3(-4.0, -4.0, 0.0);
      g.Spacing = 0.25 * scale;
      g.Dims = { { 33, 33, 13 } };
      // Squares of 8 pixels (the pass's), of 5 (partial squares at the image's edges) and
      // single pixels.
      for (int piece : { 8, 5, 1 })
      {
        std::vector<std::uint64_t> needed(
          static_cast<std::size_t>(GetNumberOfFarFieldBlocks(g)), 0);
        std::int64_t added = 0;
        ASSERT_TRUE(MarkFarFieldBlocksOfPixels(
          g, v.Image(), v.WCVC, v.VCDC, DepthBoundsOptions().WindowMargin, piece, needed, &added));
        const std::int64_t marked =
          std::count_if(needed.begin(), needed.end(), [](std::uint64_t m) { return m != 0; });
        EXPECT_EQ(added, marked);
        // Every fragment, at any depth its pixel's fragments have: every node it reads.
        int misses = 0, fragments = 0;
        for (int y = 0; y < v.Height; ++y)
        {
          for (int x = 0; x < v.Width; ++x)
          {
            const std::size_t p = static_cast<std::size_t>(y) * v.Width + x;
            if (v.Depth[p] >= 1.0f)
            {
              continue;
            }
            for (double f : { 0.0, 0.25, 0.5, 0.75, 1.0 })
            {
              const double w = v.Depth[p] + f * (double(v.DepthMax[p]) - v.Depth[p]);
              ++fragments;
              for (const glm::ivec3& n : NodesRead(g, v.WorldPoint(x, y, w)))
              {
                misses += IsMarked(g, needed, n.x, n.y, n.z) ? 0 : 1;
              }
            }
          }
        }
        const std::string what = "scale " + std::to_string(scale) +
          (parallel ? " parallel" : " perspective") + ", squares of " + std::to_string(piece);
        EXPECT_GT(fragments, 1000) << what;
        EXPECT_EQ(misses, 0) << what;
        // And a part of the grid: the pieces of the frustum lie around the surfaces (an
        // assertion that could fail: marking everything would pass the one above).
        EXPECT_GT(marked, 0) << what;
        EXPECT_LT(marked, static_cast<std::int64_t>(needed.size()) * 3 / 4) << what;
        std::cout << what << ": " << marked << " of " << needed.size() << " blocks marked\n";
      }
    }
  }
}

TEST(FarFieldBlocks, RecordedPixelsThatCannotSayMarkNothing)
{
  const MultisampledView v = RenderBallOnFloor(false, 1.0, glm::dvec3(0.0));
  FarFieldGrid g;
  g.Origin = glm::dvec3(-4.0, -4.0, 0.0);
  g.Spacing = 0.25;
  g.Dims = { { 33, 33, 13 } };
  const std::vector<std::uint64_t> none(static_cast<std::size_t>(GetNumberOfFarFieldBlocks(g)), 0);
  const double margin = DepthBoundsOptions().WindowMargin;
  std::vector<std::uint64_t> needed = none;
  // Single-sampled (no DepthMax): nothing says where the fragments off surfaces are.
  DepthImage single = v.Image();
  single.DepthMax = nullptr;
  EXPECT_FALSE(MarkFarFieldBlocksOfPixels(g, single, v.WCVC, v.VCDC, margin, 8, needed));
  EXPECT_EQ(needed, none);
  // A projection that cannot be inverted.
  EXPECT_FALSE(
    MarkFarFieldBlocksOfPixels(g, v.Image(), v.WCVC, glm::dmat4(0.0), margin, 8, needed));
  EXPECT_EQ(needed, none);
  // A margin that takes the deepest corners past infinity, behind the camera.
  EXPECT_FALSE(MarkFarFieldBlocksOfPixels(g, v.Image(), v.WCVC, v.VCDC, 10.0, 8, needed));
  EXPECT_EQ(needed, none);
  // A fragment shaded past the far plane (a primitive's plane extrapolated to a pixel's
  // centre) records a depth above 1: marked, as every other one.
  std::vector<float> past(v.Depth.size(), 1.0f);
  std::vector<float> pastMax(v.Depth.size(), 1.0f);
  const std::size_t corner = static_cast<std::size_t>(v.Height / 2) * v.Width + v.Width / 2;
  past[corner] = pastMax[corner] = 1.00001f;
  const DepthImage beyond{ past.data(), v.Width, v.Height, pastMax.data() };
  EXPECT_TRUE(MarkFarFieldBlocksOfPixels(g, beyond, v.WCVC, v.VCDC, margin, 8, needed));
  int unmarked = 0;
  for (const glm::ivec3& n : NodesRead(g, v.WorldPoint(v.Width / 2, v.Height / 2, 1.00001)))
  {
    unmarked += IsMarked(g, needed, n.x, n.y, n.z) ? 0 : 1;
  }
  EXPECT_EQ(unmarked, 0);
  EXPECT_NE(needed, none);
  needed = none;
  // Only background (the cleared depth 1): nothing recorded, nothing marked.
  const std::vector<float> cleared(v.Depth.size(), 1.0f);
  const DepthImage background{ cleared.data(), v.Width, v.Height, cleared.data() };
  EXPECT_TRUE(MarkFarFieldBlocksOfPixels(g, background, v.WCVC, v.VCDC, margin, 8, needed));
  EXPECT_EQ(needed, none);
  EXPECT_TRUE(MarkFarFieldBlocksOfPixels(g, v.Image(), v.WCVC, v.VCDC, margin, 8, needed));
  EXPECT_NE(needed, none);
}
