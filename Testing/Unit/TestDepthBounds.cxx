// SPDX-License-Identifier: BSD-3-Clause
// Depth-aware clusters (vtkClusteredLightingDepthBounds.h): every fragment's exact view
// depth lies inside the interval of the cluster the shader puts it in, for depth images
// synthesized the way a 24-bit depth buffer stores them (quantized, with VTK's coincident
// offsets), at scene scales from 1e-3 to 1e6, perspective and parallel; and the intervals
// are tight (they could fail: a test that everything is non-empty would pass trivially).
#include "TestUtilities.h"
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingDepthBounds.h"
#include "vtkClusteredLightingReference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{
struct Synthetic
{
  std::vector<float> Depth;       ///< window depth as a 24-bit buffer holds it
  std::vector<double> ExactDepth; ///< exact view depth of each pixel's fragment (0: none)
  int Width = 0, Height = 0;
  DepthImage Image() const { return { this->Depth.data(), this->Width, this->Height }; }
};

/// A floor plane tilted away from the camera and a sphere in front of it, at `scale`.
/// View space: eye at the origin looking down -z. `offset` is a coincident-topology
/// cOffset added to the stored window depth (as VTK's shader does).
Synthetic Render(
  const glm::dmat4& P, int width, int height, double scale, double offset = 0.0, bool sphere = true)
{
  Synthetic out;
  out.Width = width;
  out.Height = height;
  out.Depth.assign(static_cast<std::size_t>(width) * height, 1.0f);
  out.ExactDepth.assign(out.Depth.size(), 0.0);
  const glm::dmat4 inv = glm::inverse(P);
  const glm::dvec3 centre(0.1 * scale, -0.2 * scale, -5.0 * scale);
  const double radius = 1.2 * scale;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double nx = 2.0 * (x + 0.5) / width - 1.0;
      const double ny = 2.0 * (y + 0.5) / height - 1.0;
      glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0);
      glm::dvec4 b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 o = glm::dvec3(a) / a.w;
      const glm::dvec3 d = glm::normalize(glm::dvec3(b) / b.w - o);
      double t = std::numeric_limits<double>::infinity();
      // Floor: y = -1.5 scale - 0.1 (z + 5 scale), seen from above.
      const glm::dvec3 n = glm::normalize(glm::dvec3(0.0, 1.0, 0.1));
      const double pd = glm::dot(n, glm::dvec3(0.0, -1.5 * scale, -5.0 * scale));
      const double den = glm::dot(n, d);
      if (std::abs(den) > 1e-12)
      {
        const double tp = (pd - glm::dot(n, o)) / den;
        if (tp > 0.0)
        {
          t = tp;
        }
      }
      if (sphere)
      {
        const glm::dvec3 oc = o - centre;
        const double bq = glm::dot(oc, d);
        const double c = glm::dot(oc, oc) - radius * radius;
        const double disc = bq * bq - c;
        if (disc >= 0.0)
        {
          const double ts = -bq - std::sqrt(disc);
          if (ts > 0.0)
          {
            t = std::min(t, ts);
          }
        }
      }
      if (!std::isfinite(t))
      {
        continue;
      }
      const double depth = -(o + t * d).z;
      const double w = WindowDepthFromViewDepth(depth, P) + offset / 65000.0;
      if (!(w > 0.0 && w < 1.0))
      {
        continue; // clipped
      }
      const std::size_t p = static_cast<std::size_t>(y) * width + x;
      out.Depth[p] = static_cast<float>(std::round(w * 16777216.0) / 16777216.0);
      out.ExactDepth[p] = depth;
    }
  }
  return out;
}

/// Calls f(x, y, exact view depth) for every pixel that shows a fragment.
template <typename F>
void ForEachFragment(const Synthetic& s, F f)
{
  for (int y = 0; y < s.Height; ++y)
  {
    for (int x = 0; x < s.Width; ++x)
    {
      const double d = s.ExactDepth[static_cast<std::size_t>(y) * s.Width + x];
      if (d != 0.0)
      {
        f(x, y, d);
      }
    }
  }
}

/// Whether window position (px, py) of an image w x h lies in the NDC rectangle of
/// cluster (tx, ty, slice).
bool InRect(const ClusterDepthBounds& b, const ClusterGridParams& g, int tx, int ty, int slice,
  double px, double py, int w, int h)
{
  double rect[4];
  const double nx = 2.0 * px / w - 1.0, ny = 2.0 * py / h - 1.0;
  return b.GetRect(tx, ty, slice, g.TilesX, rect) && nx >= rect[0] && nx <= rect[2] &&
    ny >= rect[1] && ny <= rect[3];
}

/// Whether the rectangle of cluster (tx, ty, s) holds its whole tile, or the part of it
/// inside NDC rectangle `part` (x0, y0, x1, y1).
bool CoversTile(const ClusterDepthBounds& b, const ClusterGridParams& g, int tx, int ty, int s,
  const double* part = nullptr)
{
  double rect[4];
  const double inf = std::numeric_limits<double>::infinity();
  const double whole[4] = { -inf, -inf, inf, inf };
  part = part ? part : whole;
  return b.GetRect(tx, ty, s, g.TilesX, rect) &&
    rect[0] <= std::max(2.0 * tx / g.TilesX - 1.0, part[0]) &&
    rect[1] <= std::max(2.0 * ty / g.TilesY - 1.0, part[1]) &&
    rect[2] >= std::min(2.0 * (tx + 1) / g.TilesX - 1.0, part[2]) &&
    rect[3] >= std::min(2.0 * (ty + 1) / g.TilesY - 1.0, part[3]);
}

/// Mean over the non-empty clusters of the part of its tile its rectangle covers.
double MeanRectAreaInTile(const ClusterDepthBounds& b, const ClusterGridParams& g)
{
  double sum = 0.0;
  int n = 0;
  for (int s = 0; s < g.Slices; ++s)
  {
    for (int ty = 0; ty < g.TilesY; ++ty)
    {
      for (int tx = 0; tx < g.TilesX; ++tx)
      {
        double lo = 0.0, hi = 0.0, rect[4];
        if (!b.GetInterval(tx, ty, s, g.TilesX, lo, hi))
        {
          continue;
        }
        EXPECT_TRUE(b.GetRect(tx, ty, s, g.TilesX, rect));
        const double w = 2.0 / g.TilesX, h = 2.0 / g.TilesY;
        const double x0 = std::max(rect[0], tx * w - 1.0),
                     x1 = std::min(rect[2], (tx + 1) * w - 1.0);
        const double y0 = std::max(rect[1], ty * h - 1.0),
                     y1 = std::min(rect[3], (ty + 1) * h - 1.0);
        sum += std::max(x1 - x0, 0.0) * std::max(y1 - y0, 0.0) / (w * h);
        ++n;
      }
    }
  }
  return n ? sum / n : 0.0;
}

/// Checks that each fragment's exact depth is inside the interval of its cluster, and its
/// pixel's centre inside the cluster's rectangle, for the slice the shader could compute
/// in float (the exact one and its neighbours within 1e-6).
int CountMisses(const Synthetic& s, const ClusterDepthBounds& b, const ClusterGridParams& g)
{
  int misses = 0;
  ForEachFragment(s,
    [&](int x, int y, double d)
    {
      const int tx = ComputeTileIndex(x + 0.5, s.Width, g.TilesX);
      const int ty = ComputeTileIndex(y + 0.5, s.Height, g.TilesY);
      for (double f : { 1.0 - 1e-6, 1.0, 1.0 + 1e-6 })
      {
        const int slice = ComputeSliceIndex(d * f, g);
        double lo = 0.0, hi = 0.0;
        if (!b.GetInterval(tx, ty, slice, g.TilesX, lo, hi) || d < lo || d > hi ||
          !InRect(b, g, tx, ty, slice, x + 0.5, y + 0.5, s.Width, s.Height))
        {
          ++misses;
        }
      }
    });
  return misses;
}

/// Fragments positioned off their pixel's centre, by up to `reach` pixels on each axis
/// (a line's fragment takes the position of a point of the line, a point's its centre):
/// counts the pixels whose exact depth (or that position) is outside the cluster of a
/// tile the shader could find from such a position (sampled on a 5 x 5 grid of offsets).
int CountMissesOffCentre(
  const Synthetic& s, const ClusterDepthBounds& b, const ClusterGridParams& g, double reach)
{
  int misses = 0;
  ForEachFragment(s,
    [&](int x, int y, double d)
    {
      const int slice = ComputeSliceIndex(d, g);
      bool missed = false;
      for (int i = -2; i <= 2 && !missed; ++i)
      {
        for (int j = -2; j <= 2 && !missed; ++j)
        {
          const double px = x + 0.5 + 0.5 * i * reach, py = y + 0.5 + 0.5 * j * reach;
          const int tx = ComputeTileIndex(px, s.Width, g.TilesX);
          const int ty = ComputeTileIndex(py, s.Height, g.TilesY);
          double lo = 0.0, hi = 0.0;
          missed = !b.GetInterval(tx, ty, slice, g.TilesX, lo, hi) || d < lo || d > hi ||
            !InRect(b, g, tx, ty, slice, px, py, s.Width, s.Height);
        }
      }
      misses += missed ? 1 : 0;
    });
  return misses;
}
}

TEST(DepthBounds, WindowAndViewDepthsAreInverse)
{
  for (bool parallel : { false, true })
  {
    const glm::dmat4 P = parallel ? ClusteredLightingTest::Parallel(3.0, 4.0 / 3.0, 0.1, 100.0)
                                  : ClusteredLightingTest::Perspective(30.0, 4.0 / 3.0, 0.1, 100.0);
    EXPECT_TRUE(HasDepthOnlyClipZ(P));
    for (double d : { 0.1, 0.5, 3.0, 42.0, 100.0 })
    {
      const double w = WindowDepthFromViewDepth(d, P);
      EXPECT_GE(w, -1e-12);
      EXPECT_LE(w, 1.0 + 1e-12);
      EXPECT_NEAR(ViewDepthFromWindowDepth(w, P), d, 1e-9 * d);
    }
  }
}

TEST(DepthBounds, EveryFragmentIsInsideItsClusterAtEveryScale)
{
  for (double scale : { 1e-3, 1.0, 1e6 })
  {
    for (bool parallel : { false, true })
    {
      const double nearVC = 0.5 * scale, farVC = 40.0 * scale;
      const glm::dmat4 P = parallel
        ? ClusteredLightingTest::Parallel(4.0 * scale, 4.0 / 3.0, nearVC, farVC)
        : ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, nearVC, farVC);
      const Synthetic s = Render(P, 160, 120, scale);
      ClusterGridParams g = ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, nearVC, farVC,
        parallel ? SlicingScheme::Linear : SlicingScheme::Exponential);
      const VisibleRange range = MeasureVisibleRange(s.Image(), P);
      ASSERT_TRUE(range.Visible);
      ChooseSlicingRange(true, range.Nearest, range.Deepest, g);
      EXPECT_GE(g.GetSlicingNear(), g.NearVC);
      EXPECT_LE(g.GetSlicingFar(), g.FarVC);
      const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, DepthBoundsOptions());
      ASSERT_TRUE(b.Valid);
      EXPECT_EQ(CountMisses(s, b, g), 0) << "scale " << scale << (parallel ? " parallel" : "");
      // Tight: most clusters hold no fragment (a floor and a sphere are thin sheets).
      const double fraction = double(b.NonEmptyClusters) / (b.LoHi.size() / 2);
      EXPECT_LT(fraction, 0.35) << "scale " << scale;
      EXPECT_GT(fraction, 0.0);
      // And a non-empty cluster's rectangle is a part of its tile: the slices cut the
      // tilted floor and the sphere into bands (0.32 of a tile on average in perspective,
      // 0.25 in parallel projection, at every scale).
      const double area = MeanRectAreaInTile(b, g);
      EXPECT_LT(area, 0.5) << "scale " << scale << (parallel ? " parallel" : "");
      EXPECT_GT(area, 0.0);
    }
  }
}

namespace
{
/// The bounds pixel by pixel, as the header's documentation defines them (the reference
/// for its runs of pixels and its slices found from window-depth thresholds): each pixel
/// of window depths [w, wMax] holds view depths [lowest(w), highest(wMax)] and grows
/// every cluster of its tiles and of the slices those depths touch with them and its
/// rectangle; a background pixel grows the last slice of its tiles with everything from
/// the far plane's depth (less the margins) on, and the whole plane. Opaque geometry only.
ClusterDepthBounds BoundsPixelByPixel(const DepthImage& image, const glm::dmat4& P,
  const ClusterGridParams& g, const DepthBoundsOptions& o)
{
  ClusterDepthBounds out;
  InitializeClusterDepthBounds(g, out);
  const double nearest = g.NearVC, deepest = g.GetMaxFragmentDepth();
  auto toView = [&](double w)
  {
    if (w <= 0.0 || w >= 1.0)
    {
      return w <= 0.0 ? nearest : deepest;
    }
    const double d = ViewDepthFromWindowDepth(w, P);
    return d > 0.0 ? std::min(d, deepest) : nearest;
  };
  auto grow = [&](int tx, int ty, int s, const float interval[2], const float rect[4])
  {
    const std::size_t t = out.Texel(tx, ty, s, g.TilesX);
    out.LoHi[2 * t] = std::min(out.LoHi[2 * t], interval[0]);
    out.LoHi[2 * t + 1] = std::max(out.LoHi[2 * t + 1], interval[1]);
    for (int k = 0; k < 4; ++k)
    {
      float& r = out.Rects[4 * t + k];
      r = k < 2 ? std::min(r, rect[k]) : std::max(r, rect[k]);
    }
  };
  const float whole[4] = { -std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
    std::numeric_limits<float>::max(), std::numeric_limits<float>::max() };
  const float far[2] = { static_cast<float>(
                           toView(1.0 - o.WindowMargin) * (1.0 - o.RelativeMargin)),
    static_cast<float>(deepest) };
  auto slice = [&](double d)
  {
    int s = 0;
    while (s < g.Slices - 1 && d >= ComputeSliceBoundary(s + 1, g))
    {
      ++s;
    }
    return s;
  };
  const auto columns = Detail::ComputePixelTiles(image.Width, g.TilesX, o.TileSlack, o.PixelSlack);
  const auto rows = Detail::ComputePixelTiles(image.Height, g.TilesY, o.TileSlack, o.PixelSlack);
  const auto xs = Detail::ComputePixelExtents(image.Width, g.TilesX, o.TileSlack, o.PixelSlack);
  const auto ys = Detail::ComputePixelExtents(image.Height, g.TilesY, o.TileSlack, o.PixelSlack);
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * image.Width + x;
      const double w = image.Depth[p];
      if (!(w < 1.0))
      {
        for (int ty = rows[y].Lo; ty <= rows[y].Hi; ++ty)
        {
          for (int tx = columns[x].Lo; tx <= columns[x].Hi; ++tx)
          {
            grow(tx, ty, g.Slices - 1, far, whole);
          }
        }
        continue;
      }
      const double wMax = image.DepthMax ? image.DepthMax[p] : w;
      const double lo = toView(w - o.WindowMargin) * (1.0 - o.RelativeMargin);
      const double hi = std::min(toView(wMax + o.WindowMargin) * (1.0 + o.RelativeMargin), deepest);
      const float interval[2] = { static_cast<float>(lo) * (1.0f - 1e-6f),
        static_cast<float>(hi) * (1.0f + 1e-6f) };
      const float rect[4] = { xs[2 * x], ys[2 * y], xs[2 * x + 1], ys[2 * y + 1] };
      for (int s = slice(lo); s <= slice(hi); ++s)
      {
        for (int ty = rows[y].Lo; ty <= rows[y].Hi; ++ty)
        {
          for (int tx = columns[x].Lo; tx <= columns[x].Hi; ++tx)
          {
            grow(tx, ty, s, interval, rect);
          }
        }
      }
    }
  }
  return out;
}
}

TEST(DepthBounds, RunsOfPixelsGiveTheBoundsOfEachPixel)
{
  // The CPU pass over the depths takes the pixels of a line in runs (the same tiles and
  // slices) and finds slices from window-depth thresholds, without a division per pixel:
  // the same bounds, float for float, as pixel by pixel; perspective and parallel, scales
  // 1e-3 to 1e6, coincident offsets, a pixel slack (pixels in several tiles) and pixel
  // ranges as a multisampled framebuffer records them.
  int compared = 0;
  for (const bool perspective : { true, false })
  {
    for (const double scale : { 1e-3, 1.0, 1e6 })
    {
      const glm::dmat4 P = perspective
        ? ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5 * scale, 40.0 * scale)
        : ClusteredLightingTest::Parallel(3.0 * scale, 4.0 / 3.0, 0.5 * scale, 40.0 * scale);
      ClusterGridParams g = ClusteredLightingTest::MakeGrid(
        16, 8, 32, 160, 120, 0.5 * scale, 40.0 * scale, SlicingScheme::Exponential);
      const Synthetic s = Render(P, 160, 120, scale, 3.0);
      std::vector<float> wider(s.Depth);
      for (std::size_t p = 0; p < wider.size(); ++p)
      {
        wider[p] = s.Depth[p] < 1.0f ? std::min(s.Depth[p] + 1e-3f * (p % 7), 1.0f) : 1.0f;
      }
      for (const bool multisampled : { false, true })
      {
        for (const double slack : { 0.0, 6.0 })
        {
          DepthImage image = s.Image();
          image.DepthMax = multisampled ? wider.data() : nullptr;
          DepthBoundsOptions o;
          o.WindowMargin = ComputeWindowMargin(3.0);
          o.PixelSlack = slack;
          const VisibleRange range = MeasureVisibleRange(image, P);
          ChooseSlicingRange(range.Visible, range.Nearest, range.Deepest, g);
          ClusterDepthBounds b;
          InitializeClusterDepthBounds(g, b);
          ComputeClusterDepthBoundsRows(image, P, g, o, 0, g.TilesY, b);
          const ClusterDepthBounds expected = BoundsPixelByPixel(image, P, g, o);
          ASSERT_EQ(b.LoHi.size(), expected.LoHi.size());
          for (std::size_t i = 0; i < b.LoHi.size(); ++i)
          {
            ASSERT_EQ(b.LoHi[i], expected.LoHi[i]) << "interval value " << i;
          }
          for (std::size_t i = 0; i < b.Rects.size(); ++i)
          {
            ASSERT_EQ(b.Rects[i], expected.Rects[i]) << "rectangle value " << i;
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 24);
}

TEST(DepthBounds, CoincidentOffsetsAreCoveredByTheMargin)
{
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  for (double offset : { -8.0, -4.0, 2.0 })
  {
    const Synthetic s = Render(P, 160, 120, 1.0, offset);
    DepthBoundsOptions options;
    options.WindowMargin = ComputeWindowMargin(offset);
    const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, options);
    EXPECT_EQ(CountMisses(s, b, g), 0) << "cOffset " << offset;
    // Without the offset in the margin, fragments fall outside: the margin matters.
    const ClusterDepthBounds tight =
      ComputeClusterDepthBounds(s.Image(), P, g, DepthBoundsOptions());
    EXPECT_GT(CountMisses(s, tight, g), 0) << "cOffset " << offset;
  }
}

// A multisampled framebuffer (vtkClusteredLightingSampleDepths): a pixel's fragments have
// any window depth from Depth to DepthMax (at an edge, the pixel-centre depth of a
// primitive extrapolated along its plane). Here each pixel's range is that of its 3x3
// neighbourhood: every depth in it lies in the pixel's cluster, and without DepthMax the
// deepest ones do not (the range matters).
TEST(DepthBounds, MultisampledPixelRangesAreInsideTheirClusters)
{
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const Synthetic s = Render(P, 160, 120, 1.0);
  std::vector<float> lo(s.Depth.size(), 1.0f), hi(s.Depth.size(), 1.0f);
  for (int y = 0; y < s.Height; ++y)
  {
    for (int x = 0; x < s.Width; ++x)
    {
      float a = 1.0f, b = 0.0f;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const int u = std::clamp(x + dx, 0, s.Width - 1);
          const int v = std::clamp(y + dy, 0, s.Height - 1);
          const float w = s.Depth[static_cast<std::size_t>(v) * s.Width + u];
          if (w < 1.0f)
          {
            a = std::min(a, w);
            b = std::max(b, w);
          }
        }
      }
      const std::size_t p = static_cast<std::size_t>(y) * s.Width + x;
      lo[p] = a <= b ? a : 1.0f;
      hi[p] = a <= b ? b : 1.0f;
    }
  }
  DepthImage image{ lo.data(), s.Width, s.Height, hi.data() };
  const VisibleRange range = MeasureVisibleRange(image, P);
  ASSERT_TRUE(range.Visible);
  ChooseSlicingRange(true, range.Nearest, range.Deepest, g);
  const ClusterDepthBounds b = ComputeClusterDepthBounds(image, P, g, DepthBoundsOptions());
  image.DepthMax = nullptr;
  const ClusterDepthBounds nearestOnly = ComputeClusterDepthBounds(image, P, g, {});
  int misses = 0, missesWithout = 0, edges = 0;
  for (int y = 0; y < s.Height; ++y)
  {
    for (int x = 0; x < s.Width; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * s.Width + x;
      if (!(lo[p] < 1.0f))
      {
        continue;
      }
      edges += hi[p] - lo[p] > 1e-3f ? 1 : 0;
      const int tx = ComputeTileIndex(x + 0.5, s.Width, g.TilesX);
      const int ty = ComputeTileIndex(y + 0.5, s.Height, g.TilesY);
      for (double t : { 0.0, 0.5, 1.0 })
      {
        const double w = lo[p] + t * (double(hi[p]) - lo[p]);
        const double d = ViewDepthFromWindowDepth(w, P);
        const int slice = ComputeSliceIndex(d, g);
        double a = 0.0, c = 0.0;
        misses += (!b.GetInterval(tx, ty, slice, g.TilesX, a, c) || d < a || d > c) ? 1 : 0;
        missesWithout +=
          (!nearestOnly.GetInterval(tx, ty, slice, g.TilesX, a, c) || d < a || d > c) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(edges, 100); // the sphere's outline and the floor's horizon
  EXPECT_EQ(misses, 0);
  EXPECT_GT(missesWithout, 0);
  // The visible range reaches the deepest fragment, not only the deepest nearest one.
  float deepest = 0.0f;
  for (float w : hi)
  {
    deepest = w < 1.0f ? std::max(deepest, w) : deepest;
  }
  EXPECT_DOUBLE_EQ(range.Deepest, ViewDepthFromWindowDepth(deepest, P));
}

TEST(DepthBounds, LinesAndPointsAreInsideTheClustersOfTheirPositions)
{
  // Tiles of 10 x 15 pixels; lines 1 and 6 pixels wide, and points of 25 pixels, wider
  // than a tile (a pixel then counts in up to 3 tiles per axis).
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const Synthetic s = Render(P, 160, 120, 1.0);
  const VisibleRange range = MeasureVisibleRange(s.Image(), P);
  ASSERT_TRUE(range.Visible);
  ChooseSlicingRange(true, range.Nearest, range.Deepest, g);
  const ClusterDepthBounds centred = ComputeClusterDepthBounds(s.Image(), P, g, {});
  for (double width : { 1.0, 6.0, 25.0 })
  {
    DepthBoundsOptions options;
    options.PixelSlack = 0.5 * width + 1.0; // as vtkClusteredLightingDepthPrepass sets it
    const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, options);
    EXPECT_EQ(CountMissesOffCentre(s, b, g, options.PixelSlack * (1.0 - 1e-9)), 0)
      << "width " << width;
    // Centred fragments stay inside too, and the clusters stay mostly empty.
    EXPECT_EQ(CountMisses(s, b, g), 0) << "width " << width;
    EXPECT_LT(double(b.NonEmptyClusters) / (b.LoHi.size() / 2), 0.5) << "width " << width;
    EXPECT_GE(b.NonEmptyClusters, centred.NonEmptyClusters);
    // Without the slack, fragments half a pixel off their centre miss (the check can fail).
    EXPECT_GT(CountMissesOffCentre(s, centred, g, 0.5 * width), 0) << "width " << width;
  }
}

TEST(DepthBounds, AnyPixelSlackGivesTilesOfTheGrid)
{
  // Huge, infinite and NaN slacks (a line width nobody bounded) reach every tile; none
  // leaves the grid (and none overflows the cast to int, which UBSan would report).
  for (double slack : { 0.0, 0.4, 7.0, 1e30, std::numeric_limits<double>::infinity(),
         std::numeric_limits<double>::quiet_NaN(), -3.0 })
  {
    const std::vector<Detail::PixelTiles> tiles = Detail::ComputePixelTiles(160, 16, 1e-3, slack);
    for (int p = 0; p < 160; ++p)
    {
      const Detail::PixelTiles& t = tiles[static_cast<std::size_t>(p)];
      ASSERT_LE(0, t.Lo) << slack;
      ASSERT_LE(t.Lo, p / 10) << slack; // the pixel's own tile (10 pixels each) is in
      ASSERT_LE(p / 10, t.Hi) << slack;
      ASSERT_LT(t.Hi, 16) << slack;
      if (!(slack < 1e6))
      {
        ASSERT_EQ(t.Lo, 0) << slack;
        ASSERT_EQ(t.Hi, 15) << slack;
      }
      if (slack <= 0.0)
      {
        ASSERT_LE(t.Hi - t.Lo, 1) << slack; // at most a neighbour within 1e-3 tile
      }
    }
  }
}

TEST(DepthBounds, BackgroundKeepsTheFarPlaneInTheLastSlice)
{
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const std::vector<float> empty(160 * 120, 1.0f);
  const ClusterDepthBounds b = ComputeClusterDepthBounds({ empty.data(), 160, 120 }, P, g, {});
  ASSERT_TRUE(b.Valid);
  EXPECT_EQ(b.VisiblePixels, 0u);
  for (int ty = 0; ty < g.TilesY; ++ty)
  {
    for (int tx = 0; tx < g.TilesX; ++tx)
    {
      double lo = 0.0, hi = 0.0;
      ASSERT_TRUE(b.GetInterval(tx, ty, g.Slices - 1, g.TilesX, lo, hi));
      EXPECT_GE(hi, g.FarVC);
      EXPECT_TRUE(CoversTile(b, g, tx, ty, g.Slices - 1));      // anywhere in the tile
      EXPECT_FALSE(b.GetInterval(tx, ty, 0, g.TilesX, lo, hi)); // nothing nearer
    }
  }
}

namespace
{
/// Whether tile (tx, ty)'s clusters hold every depth from the near plane to `d` (sampled
/// at 4 points), where a translucent fragment in front of an opaque surface at `d` may be,
/// anywhere in the tile (or in its part inside NDC rectangle `part`).
bool HoldsEverythingInFront(const ClusterDepthBounds& b, const ClusterGridParams& g, int tx, int ty,
  double d, const double* part = nullptr)
{
  for (double t : { 0.0, 0.3, 0.9, 1.0 })
  {
    const double z = g.NearVC + t * (d - g.NearVC);
    double lo = 0.0, hi = 0.0;
    const int s = ComputeSliceIndex(z, g);
    if (!b.GetInterval(tx, ty, s, g.TilesX, lo, hi) || lo > z || hi < z * (1.0 - 1e-6) ||
      !CoversTile(b, g, tx, ty, s, part))
    {
      return false;
    }
  }
  return true;
}
}

TEST(DepthBounds, TranslucentGeometryKeepsEverythingInFrontOfTheOpaque)
{
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const Synthetic s = Render(P, 160, 120, 1.0);
  DepthBoundsOptions options;
  options.Translucent = true;
  const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, options);
  // A translucent fragment anywhere between the near plane and a pixel's opaque depth.
  for (int y = 0; y < s.Height; y += 7)
  {
    for (int x = 0; x < s.Width; x += 5)
    {
      double d = s.ExactDepth[static_cast<std::size_t>(y) * s.Width + x];
      d = d == 0.0 ? g.FarVC : d;
      const int tx = ComputeTileIndex(x + 0.5, s.Width, g.TilesX);
      const int ty = ComputeTileIndex(y + 0.5, s.Height, g.TilesY);
      ASSERT_TRUE(HoldsEverythingInFront(b, g, tx, ty, d)) << "pixel " << x << ", " << y;
    }
  }
}

TEST(DepthBounds, TranslucentRectanglesKeepTheirTilesAndCutTheOthers)
{
  // A translucent prop whose screen rectangle covers part of the view: its tiles (and the
  // tiles within a pixel of it) keep every depth from the near plane to the opaque depth
  // (to the far plane in a multisampled framebuffer), the other tiles are cut to the
  // opaque depths as without translucent geometry.
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const Synthetic s = Render(P, 160, 120, 1.0);
  DepthBoundsOptions options;
  options.Translucent = true;
  // Tiles of 10 x 15 pixels. x from pixel 41.5 to 82.5: tiles 4 to 8; y from 31.5 to
  // 59.9: tiles 2 to 3, and 4 (within a pixel of 59.9).
  options.TranslucentRects.push_back(
    glm::dvec4(41.5 / 80.0 - 1.0, 31.5 / 60.0 - 1.0, 82.5 / 80.0 - 1.0, 59.9 / 60.0 - 1.0));
  // Where a translucent fragment may be: the rectangle grown by a pixel (a multisampled
  // fragment's centre lies up to 0.71 pixel off its primitive). Its clusters' rectangles
  // hold that part of their tiles, and only that part at its edge tiles.
  const glm::dvec4& r = options.TranslucentRects[0];
  const double part[4] = { r.x - 1.0 / 80.0, r.y - 1.0 / 60.0, r.z + 1.0 / 80.0, r.w + 1.0 / 60.0 };
  const ClusterDepthBounds opaque = ComputeClusterDepthBounds(s.Image(), P, g, {});
  for (const bool multisampled : { false, true })
  {
    DepthImage image = s.Image();
    image.DepthMax = multisampled ? s.Depth.data() : nullptr;
    const ClusterDepthBounds b = ComputeClusterDepthBounds(image, P, g, options);
    int kept = 0, cut = 0;
    for (int ty = 0; ty < g.TilesY; ++ty)
    {
      for (int tx = 0; tx < g.TilesX; ++tx)
      {
        const bool inside = tx >= 4 && tx <= 8 && ty >= 2 && ty <= 4;
        // Every pixel of the tile: from the near plane to its opaque depth (multisampled:
        // to the far plane) inside the tile's clusters, or the tile as without
        // translucent geometry.
        for (int y = ty * 15; inside && y < (ty + 1) * 15; ++y)
        {
          for (int x = tx * 10; x < (tx + 1) * 10; ++x)
          {
            double d = s.ExactDepth[static_cast<std::size_t>(y) * s.Width + x];
            d = d == 0.0 || multisampled ? g.GetMaxFragmentDepth() : d;
            ASSERT_TRUE(HoldsEverythingInFront(b, g, tx, ty, d, part))
              << "tile " << tx << ", " << ty << ", pixel " << x << ", " << y;
          }
        }
        for (int slice = 0; slice < g.Slices; ++slice)
        {
          double lo = 0.0, hi = 0.0, lo0 = 0.0, hi0 = 0.0;
          const bool has = b.GetInterval(tx, ty, slice, g.TilesX, lo, hi);
          const bool had = opaque.GetInterval(tx, ty, slice, g.TilesX, lo0, hi0);
          if (!inside)
          {
            ASSERT_EQ(has, had) << "tile " << tx << ", " << ty << ", slice " << slice;
            if (has)
            {
              EXPECT_EQ(lo, lo0);
              EXPECT_EQ(hi, hi0);
            }
          }
          kept += inside && has ? 1 : 0;
          cut += !inside && !has ? 1 : 0;
        }
      }
    }
    // Multisampled, the rectangle's 15 tiles keep all their 32 slices.
    if (multisampled)
    {
      EXPECT_EQ(kept, 15 * g.Slices);
    }
    EXPECT_GT(cut, 0);
    // In front of the opaque surface only translucent fragments may be: tile (8, 2)'s
    // first cluster ends where the rectangle does (pixel 83.5, with its grow and the tile
    // slack), not at the tile's edge (pixel 90).
    double rect[4];
    ASSERT_TRUE(b.GetRect(8, 2, 0, g.TilesX, rect));
    EXPECT_GE(rect[2], part[2]);
    EXPECT_LT(rect[2], 84.0 / 80.0 - 1.0);
    EXPECT_LE(rect[0], 2.0 * 8 / g.TilesX - 1.0);
  }
  // A rectangle that is not a number, or reaches past the viewport, gives tiles of the
  // grid (no out-of-range index); one wholly outside the viewport gives none.
  for (const glm::dvec4& r : { glm::dvec4(std::nan(""), 0.0, 0.5, std::nan("")),
         glm::dvec4(-1e300, -1e300, 1e300, 1e300), glm::dvec4(2.0, 2.0, 3.0, 3.0) })
  {
    DepthBoundsOptions o;
    o.Translucent = true;
    o.TranslucentRects = { r };
    const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, o);
    ASSERT_TRUE(b.Valid);
    EXPECT_EQ(b.NonEmptyClusters == opaque.NonEmptyClusters, r.x == 2.0);
  }
  // A rectangle 2 pixels off the right edge: no tile, unless lines or points 8 pixels
  // wide may be drawn (PixelSlack 5: a wide line's fragments carry its centre line's
  // position, which the shader clamps to the edge tile).
  for (const double slack : { 0.0, 5.0 })
  {
    DepthBoundsOptions o;
    o.Translucent = true;
    o.PixelSlack = slack;
    o.TranslucentRects = { glm::dvec4(1.0 + 4.0 / 160.0, -0.5, 1.1, 0.5) };
    const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, o);
    DepthBoundsOptions plain;
    plain.PixelSlack = slack;
    const ClusterDepthBounds without = ComputeClusterDepthBounds(s.Image(), P, g, plain);
    EXPECT_EQ(b.NonEmptyClusters == without.NonEmptyClusters, slack == 0.0);
    double lo = 0.0, hi = 0.0;
    EXPECT_EQ(b.GetInterval(g.TilesX - 1, g.TilesY / 2, 0, g.TilesX, lo, hi), slack > 0.0);
  }
}

TEST(DepthBounds, TranslucentBoxesKeepOnlyTheirDepths)
{
  // Single-sampled, a translucent fragment lies on its primitive, inside its prop's box:
  // a tile its rectangle covers keeps only the clusters the box's depths reach (cut to
  // the opaque depth), not everything from the near plane. Points sampled in each box
  // (in front of the opaque surface at their pixel) must lie inside the interval and
  // rectangle of the cluster the shader finds for them.
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const Synthetic s = Render(P, 160, 120, 1.0);
  const glm::dmat4 wcvc(1.0); // world = view: the eye at the origin, looking down -z
  // A pane in front of the sphere, a thick box over the floor, a box reaching behind the
  // camera (the whole viewport, to its deepest corner) and one wholly behind it (none).
  const std::vector<std::array<double, 6>> boxes = { { -0.9, -0.1, -0.6, 0.4, -3.3, -3.2 },
    { 0.3, 1.6, -1.4, -0.6, -8.0, -6.0 }, { -0.5, 0.5, -0.3, 0.3, -2.0, 0.6 },
    { -1.0, 1.0, -1.0, 1.0, 0.2, 3.0 } };
  DepthBoundsOptions withDepths;
  withDepths.Translucent = true;
  for (const auto& box : boxes)
  {
    glm::dvec4 rect;
    glm::dvec2 depths;
    const bool front = ProjectBoxToViewport(box.data(), wcvc, P, rect, &depths);
    EXPECT_EQ(front, box[5] < 0.0);
    withDepths.TranslucentRects.push_back(rect);
    withDepths.TranslucentDepths.push_back(depths);
  }
  DepthBoundsOptions withoutDepths = withDepths;
  withoutDepths.TranslucentDepths.clear();
  const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, withDepths);
  const ClusterDepthBounds wide = ComputeClusterDepthBounds(s.Image(), P, g, withoutDepths);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int points = 0, misses = 0;
  for (const auto& box : boxes)
  {
    for (int k = 0; k < 4000; ++k)
    {
      // Corners and faces too: the extremes of the box's depths.
      auto pick = [&](int a)
      {
        const double t = k < 8 ? ((k >> a) & 1) : (k % 3 == a ? std::round(u(rng)) : u(rng));
        return box[2 * a] + t * (box[2 * a + 1] - box[2 * a]);
      };
      const glm::dvec4 p(pick(0), pick(1), pick(2), 1.0);
      const double d = -p.z;
      const glm::dvec4 c = P * p;
      if (!(d > g.NearVC) || std::abs(c.x / c.w) >= 1.0 || std::abs(c.y / c.w) >= 1.0)
      {
        continue; // clipped
      }
      const double px = (0.5 * c.x / c.w + 0.5) * s.Width, py = (0.5 * c.y / c.w + 0.5) * s.Height;
      const double opaque =
        s.ExactDepth[static_cast<std::size_t>(py) * s.Width + static_cast<std::size_t>(px)];
      if (opaque != 0.0 && d > opaque)
      {
        continue; // behind the opaque surface: depth-tested away
      }
      ++points;
      const int tx = ComputeTileIndex(px, s.Width, g.TilesX);
      const int ty = ComputeTileIndex(py, s.Height, g.TilesY);
      for (double f : { 1.0 - 1e-6, 1.0, 1.0 + 1e-6 })
      {
        const int slice = ComputeSliceIndex(d * f, g);
        double lo = 0.0, hi = 0.0;
        if (!b.GetInterval(tx, ty, slice, g.TilesX, lo, hi) || d < lo || d > hi ||
          !InRect(b, g, tx, ty, slice, px, py, s.Width, s.Height))
        {
          ++misses;
        }
      }
    }
  }
  EXPECT_GT(points, 5000);
  EXPECT_EQ(misses, 0);
  // Tighter than from the near plane: the pane's tiles keep nothing between the box
  // reaching behind the camera (to depth 2) and the pane (from 3.2); everything they kept
  // before is a superset.
  int kept = 0, keptWide = 0;
  for (int slice = 0; slice < g.Slices; ++slice)
  {
    for (int ty = 0; ty < g.TilesY; ++ty)
    {
      for (int tx = 0; tx < g.TilesX; ++tx)
      {
        double lo = 0.0, hi = 0.0, lo0 = 0.0, hi0 = 0.0;
        const bool has = b.GetInterval(tx, ty, slice, g.TilesX, lo, hi);
        const bool had = wide.GetInterval(tx, ty, slice, g.TilesX, lo0, hi0);
        ASSERT_TRUE(!has || (had && lo0 <= lo && hi <= hi0));
        kept += has ? 1 : 0;
        keptWide += had ? 1 : 0;
        if (ComputeSliceBoundary(slice, g) > 2.1 && ComputeSliceBoundary(slice + 1, g) < 3.1)
        {
          EXPECT_FALSE(has && lo < 3.1 && hi > 2.1)
            << "tile " << tx << ", " << ty << ", slice " << slice;
        }
      }
    }
  }
  EXPECT_LT(kept, keptWide * 3 / 4);
  // Multisampled, the boxes' depths are not used: every depth to the far plane.
  DepthImage image = s.Image();
  image.DepthMax = s.Depth.data();
  EXPECT_TRUE(ComputeClusterDepthBounds(image, P, g, withDepths) ==
    ComputeClusterDepthBounds(image, P, g, withoutDepths));
  // A box wholly behind the camera adds nothing: the bounds are the opaque ones.
  DepthBoundsOptions behind;
  behind.Translucent = true;
  behind.TranslucentRects = { withDepths.TranslucentRects[3] };
  behind.TranslucentDepths = { withDepths.TranslucentDepths[3] };
  EXPECT_TRUE(ComputeClusterDepthBounds(s.Image(), P, g, behind) ==
    ComputeClusterDepthBounds(s.Image(), P, g, {}));
}

TEST(DepthBounds, BoxesProjectToRectanglesHoldingEveryPoint)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const glm::dmat4 wcvc =
    glm::lookAt(glm::dvec3(3.0, 2.0, 9.0), glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0));
  for (const glm::dmat4& P : { ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0),
         ClusteredLightingTest::Parallel(3.0, 4.0 / 3.0, 0.5, 40.0) })
  {
    for (int i = 0; i < 200; ++i)
    {
      double box[6];
      for (int a = 0; a < 3; ++a)
      {
        const double c = -3.0 + 6.0 * u(rng), h = 2.0 * u(rng); // in front of the camera
        box[2 * a] = c - h;
        box[2 * a + 1] = c + h;
      }
      glm::dvec4 rect;
      glm::dvec2 depths;
      ASSERT_TRUE(ProjectBoxToViewport(box, wcvc, P, rect, &depths));
      for (int k = 0; k < 50; ++k)
      {
        const glm::dvec4 p(box[0] + u(rng) * (box[1] - box[0]), box[2] + u(rng) * (box[3] - box[2]),
          box[4] + u(rng) * (box[5] - box[4]), 1.0);
        const glm::dvec4 c = P * wcvc * p;
        const double d = -(wcvc * p).z;
        EXPECT_GT(d, depths.x);
        EXPECT_LT(d, depths.y);
        EXPECT_GE(c.x / c.w, rect.x - 1e-12);
        EXPECT_LE(c.x / c.w, rect.z + 1e-12);
        EXPECT_GE(c.y / c.w, rect.y - 1e-12);
        EXPECT_LE(c.y / c.w, rect.w + 1e-12);
      }
    }
  }
  // A box reaching behind the camera, an invalid box, one that is not a number: the whole
  // viewport, and false.
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  const double behind[6] = { -1.0, 1.0, -1.0, 1.0, 5.0, 12.0 };
  const double invalid[6] = { 1.0, -1.0, 0.0, 1.0, 0.0, 1.0 };
  const double nan[6] = { std::nan(""), 1.0, 0.0, 1.0, 0.0, 1.0 };
  for (const double* box : { behind, invalid, nan })
  {
    glm::dvec4 rect(0.0);
    glm::dvec2 depths(0.0);
    EXPECT_FALSE(ProjectBoxToViewport(box, wcvc, P, rect, &depths));
    EXPECT_EQ(rect, glm::dvec4(-1.0, -1.0, 1.0, 1.0));
    // The box behind keeps its depths (those of its corners, widened by a hair); the
    // others every depth.
    if (box == behind)
    {
      double lo = 1e300, hi = -1e300, farthest = 0.0;
      for (int i = 0; i < 8; ++i)
      {
        const glm::dvec4 v =
          wcvc * glm::dvec4(box[i & 1], box[2 + ((i >> 1) & 1)], box[4 + (i >> 2)], 1.0);
        lo = std::min(lo, -v.z);
        hi = std::max(hi, -v.z);
        farthest = std::max(farthest, glm::length(glm::dvec3(v)));
      }
      ASSERT_LT(lo, 0.0); // it does reach behind the camera
      EXPECT_NEAR(depths.x, lo - 1e-5 * farthest, 1e-12);
      EXPECT_NEAR(depths.y, hi + 1e-5 * farthest, 1e-12);
    }
    else
    {
      EXPECT_EQ(depths,
        glm::dvec2(-std::numeric_limits<double>::max(), std::numeric_limits<double>::max()));
    }
  }
}

TEST(DepthBounds, SlicingRangeStaysInsideTheCameraRange)
{
  ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  ChooseSlicingRange(true, 3.0, 9.0, g);
  EXPECT_NEAR(g.GetSlicingNear(), 2.97, 1e-12);
  EXPECT_NEAR(g.GetSlicingFar(), 9.09, 1e-12);
  // Slice 0 still holds everything down to the camera's near plane, the last slice
  // everything up to the far plane.
  EXPECT_EQ(ComputeSliceIndex(0.5, g), 0);
  EXPECT_EQ(ComputeSliceIndex(39.0, g), g.Slices - 1);
  EXPECT_NEAR(ComputeSliceBoundary(0, g), 2.97, 1e-12);
  // A flat view (one depth) still gets a valid range; nothing visible keeps the camera's.
  ChooseSlicingRange(true, 5.0, 5.0, g);
  EXPECT_GT(g.GetSlicingFar(), g.GetSlicingNear());
  ChooseSlicingRange(false, 0.0, 0.0, g);
  EXPECT_EQ(g.GetSlicingNear(), g.NearVC);
  EXPECT_EQ(g.GetSlicingFar(), g.FarVC);
  // A visible range beyond the camera range is clamped to it.
  ChooseSlicingRange(true, 0.1, 100.0, g);
  EXPECT_GE(g.GetSlicingNear(), g.NearVC);
  EXPECT_LE(g.GetSlicingFar(), g.FarVC);
}

TEST(DepthBounds, AnObliqueProjectionIsNotUsed)
{
  glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, 0.5, 40.0);
  P[0][2] = 0.1; // clip z depends on view x
  EXPECT_FALSE(HasDepthOnlyClipZ(P));
  const ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, 0.5, 40.0, SlicingScheme::Exponential);
  const std::vector<float> depth(160 * 120, 0.5f);
  EXPECT_FALSE(ComputeClusterDepthBounds({ depth.data(), 160, 120 }, P, g, {}).Valid);
}

// The CPU side of depth-aware clusters: list-pass quads shrunk to the clusters a light's
// depth extent reaches (ShrinkToReachableClusters) lose no cluster that the reference
// (the cell cut to the recorded depths, exact sphere-cell distance) says the light
// reaches; they do draw fewer clusters; and the quads computed in chunks, as the assigner
// does over its threads, are the same quads in the same order.
TEST(DepthBounds, QuadsShrinkToTheClustersALightCanReach)
{
  const double nearVC = 0.5, farVC = 40.0;
  const glm::dmat4 P = ClusteredLightingTest::Perspective(40.0, 4.0 / 3.0, nearVC, farVC);
  const Synthetic s = Render(P, 160, 120, 1.0);
  ClusterGridParams g =
    ClusteredLightingTest::MakeGrid(16, 8, 32, 160, 120, nearVC, farVC, SlicingScheme::Exponential);
  const VisibleRange range = MeasureVisibleRange(s.Image(), P);
  ASSERT_TRUE(range.Visible);
  ChooseSlicingRange(true, range.Nearest, range.Deepest, g);
  const ClusterDepthBounds b = ComputeClusterDepthBounds(s.Image(), P, g, DepthBoundsOptions());
  ASSERT_TRUE(b.Valid);

  ViewParameters v; // world = view
  v.VCDC = P;
  v.Grid = g;
  std::mt19937 random(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<PreparedLight> lights;
  for (int i = 0; i < 600; ++i)
  {
    PreparedLight l{};
    l.PositionWC = glm::dvec3(-4.0 + 8.0 * unit(random), -3.0 + 5.0 * unit(random),
      -12.0 + 11.8 * unit(random)); // some straddle the near plane
    l.Radius = 0.05 + 1.5 * unit(random);
    l.Color = glm::dvec3(1.0);
    l.Attenuation = glm::dvec3(0.0, 0.0, 1.0);
    l.CosCone = -2.0;
    l.ExplicitRadius = std::numeric_limits<double>::infinity();
    lights.push_back(l);
  }
  const ViewData whole = ComputeViewData(lights, v);
  const ViewData cut = ComputeViewData(lights, v, &b);
  EXPECT_LT(cut.NumberOfQuads, whole.NumberOfQuads);
  EXPECT_LT(cut.ClusterCoverage, 0.5 * whole.ClusterCoverage);
  EXPECT_EQ(cut.LightView, whole.LightView);

  // (light, slice) -> shrunk rectangle.
  std::map<std::pair<int, int>, std::array<int, 4>> rects;
  for (int q = 0; q < cut.NumberOfQuads; ++q)
  {
    const float* f = &cut.Quads[static_cast<std::size_t>(q) * FloatsPerQuad];
    rects[{ static_cast<int>(f[5]), static_cast<int>(f[4]) }] = { static_cast<int>(f[0]),
      static_cast<int>(f[1]), static_cast<int>(f[2]), static_cast<int>(f[3]) };
  }
  int reached = 0, missed = 0;
  std::vector<SliceTileRange> ranges;
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    ranges.clear();
    ComputeSliceTileRanges(lights[i].PositionWC, lights[i].Radius, P, g, ranges);
    for (const SliceTileRange& r : ranges)
    {
      for (int ty = r.TileMin[1]; ty <= r.TileMax[1]; ++ty)
      {
        for (int tx = r.TileMin[0]; tx <= r.TileMax[0]; ++tx)
        {
          const ClusterCell cell = ComputeClusterCell(tx, ty, r.Slice, g, P, nearVC, farVC, &b);
          if (cell.Empty || DistanceToCell(lights[i].PositionWC, cell) > lights[i].Radius)
          {
            continue;
          }
          ++reached;
          const auto it = rects.find({ static_cast<int>(i), r.Slice });
          const bool covered = it != rects.end() && tx >= it->second[0] && ty >= it->second[1] &&
            tx <= it->second[2] && ty <= it->second[3];
          missed += covered ? 0 : 1;
        }
      }
    }
  }
  EXPECT_GT(reached, 1000);
  EXPECT_EQ(missed, 0);

  // In chunks of 7 lights, joined in order: the same records and quads.
  ViewData joined;
  joined.LightView.resize(lights.size() * FloatsPerLightRecord);
  for (std::size_t begin = 0; begin < lights.size(); begin += 7)
  {
    ViewData part;
    ComputeViewDataRange(
      lights, v, &b, begin, std::min(begin + 7, lights.size()), joined.LightView.data(), part);
    AppendViewData(joined, part);
  }
  EXPECT_EQ(joined.Quads, cut.Quads);
  EXPECT_EQ(joined.LightView, cut.LightView);
  EXPECT_EQ(joined.NumberOfQuads, cut.NumberOfQuads);
  EXPECT_EQ(joined.NumberOfAssignedLights, cut.NumberOfAssignedLights);
}
