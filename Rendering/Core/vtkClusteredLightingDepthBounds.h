// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingDepthBounds.h
 * @brief GL-free depth-aware clusters: the depths each cluster really holds.
 *
 * A cluster (tx, ty, s) of the frustum grid (vtkClusteredLightingGrid.h) is a box of
 * the view volume, but the fragments the shading pass puts in it lie on the visible
 * surfaces only: a thin sheet inside the box, or nothing at all. After a depth prepass
 * (opaque geometry, depth only) the pass reads the window depth of its viewport back and
 * this header turns it into, per cluster, the interval of view depths [lo, hi] that its
 * fragments can have (Olsson, Billeter and Assarsson, "Clustered Deferred and Forward
 * Shading", HPG 2012: clusters from the actual samples). The list pass then tests each
 * light against the cluster's cell cut to that interval, and drops empty clusters.
 *
 * Each cluster also records the screen rectangle its fragments cover (Rects, in the
 * viewport's normalized device coordinates: the pixels it holds, each as its whole square
 * grown by the same slack that made it count in the tile), so a cluster that the surface
 * crosses in a corner or a band of its tile (a receding wall cut by the slices, an
 * object's silhouette) is tested as that part of its tile only: the tight bounds of
 * Olsson et al. in x and y as well as in depth.
 *
 * Conservative by construction: every fragment the shading pass shades in cluster c has
 * a view depth inside c's interval and a projected position inside c's rectangle.
 *  - A pixel's window depth w is read as the interval [w - m, w + m]: m covers the
 *    depth buffer's quantization (24 bits) and VTK's coincident-topology offsets (the
 *    mappers write gl_FragDepth = gl_FragCoord.z + cOffset / 65000; the pass reads the
 *    largest |cOffset| of the prepass), then it is mapped to view depth (the map is
 *    monotonic) and widened by a relative RelativeMargin for float interpolation.
 *  - The shader finds a fragment's tile from its own projected position (the
 *    interpolated vertexVC) and its slice in float: a pixel within TileSlack of a tile
 *    edge counts in both tiles, and an interval is added to every slice it touches after
 *    the relative widening.
 *  - A line's or a point's fragment has the position of a point of the line (or the
 *    point's centre), not of its pixel's centre: up to half the line's width or the
 *    point's size away (llvmpipe evaluates a thin line's attributes at the pixel's column
 *    or row on the line; VTK's wide lines are quads and its points squares whose
 *    fragments all carry the centre line's or centre's attributes; multisampling adds
 *    coverage at a pixel's corner). Its depth is that point's too. So a pixel also counts
 *    in every tile within PixelSlack pixels of its centre (the pass sets half the widest
 *    line or point of the frame's props plus a pixel); otherwise the wireframe sphere of
 *    TestClusteredLightingDepthAware shaded pixels at tile edges with no light at all.
 *  - A multisampled framebuffer shades a fragment at the pixel centre, whose depth may
 *    match none of the samples' (an edge extrapolates the primitive's plane): the prepass
 *    records each pixel's range of fragment depths (vtkClusteredLightingSampleDepths), and
 *    the pixel counts as [Depth - m, DepthMax + m].
 *  - A pixel left at the cleared depth 1 may still hold a fragment exactly on the far
 *    plane: its tile's last slice includes [depth(1 - m), GetMaxFragmentDepth()].
 *  - Translucent geometry is not in the opaque depth buffer. With Translucent set, a
 *    tile where a translucent fragment may be (every tile, or those within a pixel of
 *    TranslucentRects: the screen rectangles of the translucent props' boxes) holds every
 *    depth from the camera's near plane to the tile's deepest opaque depth (or the far
 *    plane where the tile shows background): translucent fragments are depth-tested
 *    against the opaque ones, so none lies deeper. Single-sampled, a translucent
 *    fragment is shaded at a point of its primitive, inside its prop's box, so where every
 *    rectangle of a tile comes with its box's depths (TranslucentDepths) the tile holds
 *    only the depths of those boxes (each apart), cut to the same deepest opaque depth. In a
 *    multisampled framebuffer such a tile holds every depth to the far plane: a
 *    translucent fragment is shaded at its pixel's centre, whose depth may lie behind
 *    every opaque sample of the pixel (and outside its box: the primitive's plane is
 *    extrapolated).
 *
 * The visible range (MeasureVisibleRange: the nearest and deepest opaque pixels) sets
 * the slicing range (ChooseSlicingRange): slices where the geometry is. Slicing is
 * only a matter of speed: slice 0 still starts at the camera's near plane and the last
 * still ends at the far plane.
 *
 * The window-to-view map needs VTK's usual projection form, where clip z and w depend
 * on view z only; for any other form (or no usable pixels) the bounds are not Valid
 * and the pass uses the whole cells.
 */
#ifndef vtkClusteredLightingDepthBounds_h
#define vtkClusteredLightingDepthBounds_h

#include "vtkClusteredLightingGrid.h"

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::floor
#include <cstddef>   // for std::size_t
#include <cstdint>   // for std::uint32_t
#include <cstring>   // for std::memcpy
#include <glm/glm.hpp>
#include <limits> // for std::numeric_limits
#include <vector> // for std::vector

namespace vtkClusteredLighting
{

/// Margins of the depth readback.
struct DepthBoundsOptions
{
  /// Window-depth margin: quantization plus the largest coincident offset seen.
  double WindowMargin = 1.0 / 4194304.0; // 2^-22: four steps of a 24-bit depth buffer
  double RelativeMargin = 1e-5;          ///< relative widening of each view-depth interval
  double TileSlack = 1e-3;               ///< in tiles: pixels this close to an edge count twice
  /// In pixels: how far from its pixel's centre a fragment's position may lie (lines and
  /// points); a pixel counts in every tile this close.
  double PixelSlack = 0.0;
  bool Translucent = false; ///< translucent geometry is shaded too
  /// Where translucent fragments may be: rectangles (x0, y0, x1, y1) in the viewport's
  /// normalized device coordinates (ProjectBoxToViewport). Empty: anywhere.
  std::vector<glm::dvec4> TranslucentRects;
  /// The view depths (nearest, deepest) of each rectangle's box, widened for float
  /// error (ProjectBoxToViewport). Used single-sampled only, and only when there is one
  /// per rectangle; otherwise a translucent tile holds every depth from the near plane.
  std::vector<glm::dvec2> TranslucentDepths;
};

/**
 * The relative widening of a box's view depths in ProjectBoxToViewport: a fragment's
 * view position comes from float transforms and interpolation, off by a few float steps
 * (about 1e-7) of the coordinates involved, far below this share of the largest distance
 * from the camera to a corner.
 */
constexpr double BoxDepthRelativeMargin = 1e-5;

/**
 * The screen rectangle of a world box (x0, x1, y0, y1, z0, z1) in the normalized device
 * coordinates of the view `wcvc`, `vcdc`: the bounds of its projected corners, which
 * hold the projection of every point of the box when every corner lies in front of the
 * camera. With `depths`, also the view depths (nearest, deepest) of the corners, which
 * hold every point's (view depth is affine in the point), widened by
 * BoxDepthRelativeMargin of the largest distance from the camera to a corner. False
 * (rect: the whole viewport) when a corner does not lie in front of the camera, or the
 * box is not valid; the depths are those of the box still where it is valid and finite
 * (a box reaching behind the camera has them too), otherwise every depth.
 */
inline bool ProjectBoxToViewport(const double box[6], const glm::dmat4& wcvc,
  const glm::dmat4& vcdc, glm::dvec4& rect, glm::dvec2* depths = nullptr)
{
  const double huge = std::numeric_limits<double>::max();
  rect = glm::dvec4(-1.0, -1.0, 1.0, 1.0);
  if (depths)
  {
    *depths = glm::dvec2(-huge, huge);
  }
  if (!(box[0] <= box[1] && box[2] <= box[3] && box[4] <= box[5]))
  {
    return false;
  }
  // The depths hold for a box reaching behind the camera too: every corner is taken
  // before the rectangle is refused.
  glm::dvec2 depth(huge, -huge);
  double farthest = 0.0;
  glm::dvec4 out(huge, huge, -huge, -huge);
  bool inFront = true;
  const glm::dmat4 wcdc = vcdc * wcvc;
  for (int i = 0; i < 8; ++i)
  {
    const glm::dvec4 p(box[i & 1], box[2 + ((i >> 1) & 1)], box[4 + (i >> 2)], 1.0);
    const glm::dvec3 v = glm::dvec3(wcvc * p);
    depth.x = std::min(depth.x, -v.z);
    depth.y = std::max(depth.y, -v.z);
    farthest = std::max(farthest, glm::length(v));
    const glm::dvec4 c = wcdc * p;
    // In front of the camera: positive clip w (perspective), or any point (parallel).
    // (No division by a w that is not positive.)
    if (!(c.w > 0.0) || !std::isfinite(c.x / c.w) || !std::isfinite(c.y / c.w))
    {
      inFront = false;
      continue;
    }
    out.x = std::min(out.x, c.x / c.w);
    out.y = std::min(out.y, c.y / c.w);
    out.z = std::max(out.z, c.x / c.w);
    out.w = std::max(out.w, c.y / c.w);
  }
  if (depths && std::isfinite(farthest))
  {
    const double margin = BoxDepthRelativeMargin * farthest;
    *depths = glm::dvec2(depth.x - margin, depth.y + margin);
  }
  if (!inFront)
  {
    return false;
  }
  rect = out;
  return true;
}

/// The largest |cOffset| of VTK's coincident topology as a window-depth margin.
inline double ComputeWindowMargin(double maxAbsCoincidentOffset)
{
  return 1.0 / 4194304.0 + std::abs(maxAbsCoincidentOffset) / 65000.0;
}

/// True when clip z and w depend on view z only (VTK's perspective and parallel forms).
inline bool HasDepthOnlyClipZ(const glm::dmat4& vcdc)
{
  // column-major: vcdc[column][row]
  return vcdc[0][2] == 0.0 && vcdc[1][2] == 0.0 && vcdc[0][3] == 0.0 && vcdc[1][3] == 0.0;
}

/// View depth (-z in VC) of window depth w (glDepthRange 0..1) under `vcdc`.
inline double ViewDepthFromWindowDepth(double w, const glm::dmat4& vcdc)
{
  const double ndc = 2.0 * w - 1.0;
  const double a = vcdc[2][2], b = vcdc[3][2], c = vcdc[2][3], d = vcdc[3][3];
  // ndc = (a z + b) / (c z + d)  =>  z = (b - ndc d) / (ndc c - a)
  return -(b - ndc * d) / (ndc * c - a);
}

/// Window depth of a view depth (the inverse of ViewDepthFromWindowDepth).
inline double WindowDepthFromViewDepth(double depth, const glm::dmat4& vcdc)
{
  const double z = -depth;
  const double ndc = (vcdc[2][2] * z + vcdc[3][2]) / (vcdc[2][3] * z + vcdc[3][3]);
  return 0.5 * ndc + 0.5;
}

/// A renderer viewport's window depths, row-major from the bottom row.
struct DepthImage
{
  const float* Depth = nullptr;
  int Width = 0;
  int Height = 0;
  /// With a multisampled framebuffer, a pixel's fragments have window depths from
  /// Depth[p] to DepthMax[p] (vtkClusteredLightingSampleDepths); null: exactly Depth[p].
  const float* DepthMax = nullptr;
};

/// Per-cluster view-depth intervals; texel (s * X + tx, ty) of a (X * Z) x Y image.
struct ClusterDepthBounds
{
  bool Valid = false;
  int Width = 0;           ///< TilesX * Slices
  int Height = 0;          ///< TilesY
  std::vector<float> LoHi; ///< 2 floats per texel; an empty cluster has lo > hi
  /// 4 floats per texel: the NDC rectangle (x0, y0, x1, y1) of the cluster's fragments
  /// (x0 > x1 when empty; the whole plane where any fragment of the tile may count).
  std::vector<float> Rects;
  double VisibleNear = 0.0; ///< nearest opaque depth (0 when none is visible)
  double VisibleFar = 0.0;  ///< deepest opaque depth
  std::size_t VisiblePixels = 0;
  std::size_t NonEmptyClusters = 0;

  bool operator==(const ClusterDepthBounds& o) const
  {
    return this->Valid == o.Valid && this->Width == o.Width && this->Height == o.Height &&
      this->LoHi == o.LoHi && this->Rects == o.Rects;
  }
  bool operator!=(const ClusterDepthBounds& o) const { return !(*this == o); }

  /// Texel of cluster (tx, ty, s) in the (X * Z) x Y image.
  std::size_t Texel(int tx, int ty, int s, int tilesX) const
  {
    return static_cast<std::size_t>(ty) * this->Width + static_cast<std::size_t>(s) * tilesX + tx;
  }

  /// Interval of cluster (tx, ty, s): false when it holds no fragment.
  bool GetInterval(int tx, int ty, int s, int tilesX, double& lo, double& hi) const
  {
    const std::size_t t = this->Texel(tx, ty, s, tilesX);
    lo = this->LoHi[2 * t];
    hi = this->LoHi[2 * t + 1];
    return lo <= hi;
  }

  /// NDC rectangle (x0, y0, x1, y1) of cluster (tx, ty, s): false when it holds no
  /// fragment (or has no rectangles).
  bool GetRect(int tx, int ty, int s, int tilesX, double rect[4]) const
  {
    const std::size_t t = this->Texel(tx, ty, s, tilesX);
    rect[0] = rect[1] = 1.0;
    rect[2] = rect[3] = -1.0;
    if (4 * t + 3 >= this->Rects.size())
    {
      return false;
    }
    for (int i = 0; i < 4; ++i)
    {
      rect[i] = this->Rects[4 * t + i];
    }
    return rect[0] <= rect[2] && rect[1] <= rect[3];
  }
};

/// What of an image shows opaque geometry: its nearest and deepest view depths and its
/// pixel count (background excluded).
struct VisibleRange
{
  bool Visible = false; ///< some pixel shows geometry and the projection is usable
  double Nearest = 0.0;
  double Deepest = 0.0;
  std::size_t Pixels = 0;
};

/// One pass over the image.
inline VisibleRange MeasureVisibleRange(const DepthImage& image, const glm::dmat4& vcdc)
{
  VisibleRange range;
  float wMin = 2.0f, wMax = -1.0f;
  const std::size_t n = static_cast<std::size_t>(image.Width) * image.Height;
  for (std::size_t p = 0; p < n; ++p)
  {
    const float w = image.Depth[p];
    if (w < 1.0f)
    {
      const float deepest = image.DepthMax ? image.DepthMax[p] : w;
      wMin = std::min(wMin, w);
      wMax = std::max(wMax, deepest < 1.0f ? deepest : w);
      ++range.Pixels;
    }
  }
  if (!(wMin <= wMax) || !HasDepthOnlyClipZ(vcdc))
  {
    return range;
  }
  range.Nearest = ViewDepthFromWindowDepth(wMin, vcdc);
  range.Deepest = ViewDepthFromWindowDepth(wMax, vcdc);
  range.Visible = range.Nearest > 0.0 && range.Deepest >= range.Nearest;
  return range;
}

/**
 * Slices where the geometry is: the slicing range becomes the visible range (grown by 1%,
 * kept inside the camera range and at least 1e-3 of its near depth thick). Without a
 * visible range the camera's range stays.
 */
inline void ChooseSlicingRange(
  bool visible, double nearest, double deepest, ClusterGridParams& grid)
{
  grid.SlicingNearVC = 0.0;
  grid.SlicingFarVC = 0.0;
  if (!visible)
  {
    return;
  }
  const double n = std::max(grid.NearVC, nearest * 0.99);
  double f = std::min(grid.FarVC, deepest * 1.01);
  f = std::max(f, n * 1.001);
  if (n >= grid.FarVC || !(f > n))
  {
    return;
  }
  grid.SlicingNearVC = n;
  grid.SlicingFarVC = f;
}

namespace Detail
{
/// The tiles a pixel counts in: Lo to Hi, inclusive.
struct PixelTiles
{
  int Lo = 0;
  int Hi = 0;
};

/// For each of `pixels` pixels along one axis, the tiles within `slack` tiles plus
/// `pixelSlack` pixels of its centre.
inline std::vector<PixelTiles> ComputePixelTiles(
  int pixels, int tiles, double slack, double pixelSlack)
{
  std::vector<PixelTiles> out(static_cast<std::size_t>(pixels));
  const double tilesPerPixel = static_cast<double>(tiles) / pixels;
  // A slack that is not a number reaches every tile (the conservative choice).
  const double reach =
    slack + (pixelSlack > 0.0 || std::isnan(pixelSlack) ? pixelSlack : 0.0) * tilesPerPixel;
  for (int p = 0; p < pixels; ++p)
  {
    // Clamped as doubles before the cast: a huge or NaN reach gives the first and the
    // last tile.
    const double u = (p + 0.5) * tilesPerPixel;
    const double lo = std::floor(u - reach);
    const double hi = std::floor(u + reach);
    out[p].Lo = lo > 0.0 ? (lo < tiles - 1 ? static_cast<int>(lo) : tiles - 1) : 0;
    out[p].Hi = hi < tiles - 1 ? (hi > 0.0 ? static_cast<int>(hi) : 0) : tiles - 1;
  }
  return out;
}
} // namespace Detail

/**
 * Per-cluster depth intervals of one image for `grid` (its slicing range already chosen).
 * Rows [rowBegin, rowEnd) of tiles only, so that callers may split the work; call
 * InitializeClusterDepthBounds first and FinishClusterDepthBounds after.
 */
inline void InitializeClusterDepthBounds(const ClusterGridParams& grid, ClusterDepthBounds& out)
{
  out.Width = grid.TilesX * grid.Slices;
  out.Height = grid.TilesY;
  out.LoHi.assign(2 * static_cast<std::size_t>(out.Width) * out.Height, 0.0f);
  for (std::size_t t = 0; t < out.LoHi.size(); t += 2)
  {
    out.LoHi[t] = std::numeric_limits<float>::max();
    out.LoHi[t + 1] = -std::numeric_limits<float>::max();
  }
  out.Rects.assign(4 * static_cast<std::size_t>(out.Width) * out.Height, 0.0f);
  for (std::size_t t = 0; t < out.Rects.size(); t += 4)
  {
    out.Rects[t] = out.Rects[t + 1] = std::numeric_limits<float>::max();
    out.Rects[t + 2] = out.Rects[t + 3] = -std::numeric_limits<float>::max();
  }
}

namespace Detail
{
/**
 * For each of `pixels` pixels along one axis, the NDC interval (lo, hi) its fragments'
 * projected positions lie in: its square, grown by the reach that counts it in a tile
 * (`slack` tiles plus `pixelSlack` pixels, as ComputePixelTiles), rounded outward to
 * float. Never narrower than what made the pixel count in a tile, so the interval meets
 * every tile the pixel counts in. A reach that is not finite gives the whole line.
 */
inline std::vector<float> ComputePixelExtents(
  int pixels, int tiles, double slack, double pixelSlack)
{
  std::vector<float> out(2 * static_cast<std::size_t>(pixels));
  const double reach =
    0.5 + slack * pixels / tiles + (pixelSlack > 0.0 || std::isnan(pixelSlack) ? pixelSlack : 0.0);
  const float inf = std::numeric_limits<float>::max();
  for (int p = 0; p < pixels; ++p)
  {
    if (!std::isfinite(reach))
    {
      out[2 * static_cast<std::size_t>(p)] = -inf;
      out[2 * static_cast<std::size_t>(p) + 1] = inf;
      continue;
    }
    const double lo = 2.0 * (p + 0.5 - reach) / pixels - 1.0;
    const double hi = 2.0 * (p + 0.5 + reach) / pixels - 1.0;
    out[2 * static_cast<std::size_t>(p)] = std::nextafter(static_cast<float>(lo), -inf);
    out[2 * static_cast<std::size_t>(p) + 1] = std::nextafter(static_cast<float>(hi), inf);
  }
  return out;
}
} // namespace Detail

/**
 * Grows the clusters of tile rows [tileRowBegin, tileRowEnd) of `out` (initialized by
 * InitializeClusterDepthBounds, the slicing range chosen) with the pixels of `image` that
 * count in them, then adds the translucent and background terms of those tiles. Rows are
 * independent: the assigner splits them over threads. A pixel's interval and slices only
 * grow with its window depths, so the slices come from window-depth thresholds found
 * once, and the pixels of a line that share tiles and slices grow them once, with the
 * least and greatest window depths of the run: the same bounds, float for float, as pixel
 * by pixel (`Core.DepthBounds.RunsOfPixelsGiveTheBoundsOfEachPixel`), in half the time.
 */
inline void ComputeClusterDepthBoundsRows(const DepthImage& image, const glm::dmat4& vcdc,
  const ClusterGridParams& grid, const DepthBoundsOptions& options, int tileRowBegin,
  int tileRowEnd, ClusterDepthBounds& out)
{
  const int X = grid.TilesX, Z = grid.Slices;
  const std::vector<Detail::PixelTiles> columns =
    Detail::ComputePixelTiles(image.Width, X, options.TileSlack, options.PixelSlack);
  const std::vector<Detail::PixelTiles> rows =
    Detail::ComputePixelTiles(image.Height, grid.TilesY, options.TileSlack, options.PixelSlack);
  std::vector<double> boundary(static_cast<std::size_t>(Z) + 1);
  for (int k = 0; k <= Z; ++k)
  {
    boundary[k] = ComputeSliceBoundary(k, grid);
  }
  const double nearest = grid.NearVC;
  const double deepest = grid.GetMaxFragmentDepth();
  const double m = options.WindowMargin;
  const double rel = options.RelativeMargin;
  auto toView = [&](double w)
  {
    if (w <= 0.0)
    {
      return nearest;
    }
    if (w >= 1.0)
    {
      return deepest;
    }
    const double d = ViewDepthFromWindowDepth(w, vcdc);
    return d > 0.0 ? std::min(d, deepest) : nearest;
  };
  // The slice s with edges[s] <= v < edges[s + 1] (clamped), from a cached guess: edges
  // are the slice boundaries for a view depth, or thresholds for a window depth (below).
  auto sliceAt = [&](const auto& edges, auto v, int guess)
  {
    int s = guess;
    while (s > 0 && v < edges[s])
    {
      --s;
    }
    while (s < Z - 1 && v >= edges[s + 1])
    {
      ++s;
    }
    return s;
  };
  // A pixel of window depths [w, wMax] holds view depths [lowest(w), highest(wMax)]; both
  // grow with the window depth.
  auto lowest = [&](double w) { return toView(w - m) * (1.0 - rel); };
  auto highest = [&](double w) { return std::min(toView(w + m) * (1.0 + rel), deepest); };
  // So a pixel's slices change at fixed window depths: the least float w whose lowest (or
  // highest) reaches boundary k, found once per frame by bisection over the floats of
  // [0, 1] (2 when none does); pixels then find their slices without a division.
  auto firstReaching = [&](const auto& f, double b)
  {
    std::uint32_t lo = 0, hi = 0x3F800000u; // the bits of 0.0f and 1.0f: ordered as floats
    auto value = [](std::uint32_t u)
    {
      float v;
      std::memcpy(&v, &u, sizeof v);
      return v;
    };
    if (!(f(value(hi)) >= b))
    {
      return 2.0f;
    }
    while (lo < hi)
    {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (f(value(mid)) >= b)
      {
        hi = mid;
      }
      else
      {
        lo = mid + 1;
      }
    }
    return value(lo);
  };
  std::vector<float> lowThreshold(static_cast<std::size_t>(Z) + 1, 0.0f);
  std::vector<float> highThreshold(static_cast<std::size_t>(Z) + 1, 0.0f);
  for (int k = 1; k < Z; ++k)
  {
    lowThreshold[k] = firstReaching(lowest, boundary[k]);
    highThreshold[k] = firstReaching(highest, boundary[k]);
  }
  auto texel = [&](int tx, int ty, int s) { return out.Texel(tx, ty, s, X); };
  // Each pixel's NDC extent on both axes (ComputePixelExtents); a tile that may hold a
  // fragment on the far plane anywhere, or a translucent one of unknown props, takes the
  // whole plane, one under a translucent prop's box the box's rectangle.
  const std::vector<float> columnExtents =
    Detail::ComputePixelExtents(image.Width, X, options.TileSlack, options.PixelSlack);
  const std::vector<float> rowExtents =
    Detail::ComputePixelExtents(image.Height, grid.TilesY, options.TileSlack, options.PixelSlack);
  const float inf = std::numeric_limits<float>::max();
  const float wholePlane[4] = { -inf, -inf, inf, inf };
  auto grow = [&](std::size_t t, const float interval[2], const float rect[4])
  {
    float* b = &out.LoHi[2 * t];
    b[0] = std::min(b[0], interval[0]);
    b[1] = std::max(b[1], interval[1]);
    float* r = &out.Rects[4 * t];
    r[0] = std::min(r[0], rect[0]);
    r[1] = std::min(r[1], rect[1]);
    r[2] = std::max(r[2], rect[2]);
    r[3] = std::max(r[3], rect[3]);
  };
  std::vector<float> tileDeepest(static_cast<std::size_t>(X));
  std::vector<char> tileBackground(static_cast<std::size_t>(X));
  // Tiles where a translucent fragment may be: those of the rectangles, grown by a pixel
  // (a multisampled fragment's centre lies up to 0.71 pixel outside its primitive), the
  // pixel slack (a wide line's fragments carry its centre line's position, which may lie
  // off screen) and the tile slack; every tile without rectangles.
  const bool everywhere = options.Translucent && options.TranslucentRects.empty();
  // Each translucent rectangle as tiles (x0, x1, y0, y1) and the view depths its
  // fragments may have: its box's single-sampled, else from the near plane (every tile
  // and depth without rectangles).
  struct TranslucentRegion
  {
    int Tiles[4];
    double Lo, Hi;
    float Rect[4];
  };
  std::vector<TranslucentRegion> translucentRegions;
  if (everywhere)
  {
    translucentRegions.push_back({ { 0, X - 1, 0, grid.TilesY - 1 }, nearest, deepest,
      { wholePlane[0], wholePlane[1], wholePlane[2], wholePlane[3] } });
  }
  // A rectangle's edge as a float rounded outward (not a number or past float's range:
  // the whole plane on that side).
  auto outwardLo = [inf](double v) {
    return v > -inf ? std::nextafter(static_cast<float>(std::min(v, double{ inf })), -inf) : -inf;
  };
  auto outwardHi = [inf](double v)
  { return v < inf ? std::nextafter(static_cast<float>(std::max(v, -double{ inf })), inf) : inf; };
  const bool boxDepths =
    !image.DepthMax && options.TranslucentDepths.size() == options.TranslucentRects.size();
  const double growPixels = 1.0 +
    (std::isnan(options.PixelSlack) ? std::numeric_limits<double>::max()
                                    : std::max(0.0, options.PixelSlack));
  for (std::size_t i = 0; i < options.TranslucentRects.size(); ++i)
  {
    const glm::dvec4& r = options.TranslucentRects[i];
    const double gx = growPixels / image.Width * X + options.TileSlack;
    const double gy = growPixels / image.Height * grid.TilesY + options.TileSlack;
    // NDC to tiles (as doubles, clamped before the cast: a huge or NaN corner gives an
    // edge tile, the conservative choice).
    auto tileRange = [](double lo, double hi, double grow, int tiles, int& t0, int& t1)
    {
      const double a = std::floor((0.5 * lo + 0.5) * tiles - grow);
      const double b = std::floor((0.5 * hi + 0.5) * tiles + grow);
      t0 = a > 0.0 ? (a < tiles - 1 ? static_cast<int>(a) : tiles - 1) : 0;
      t1 = b < tiles - 1 ? (b > 0.0 ? static_cast<int>(b) : 0) : tiles - 1;
      return !(b < 0.0 || a > tiles - 1);
    };
    TranslucentRegion region;
    if (tileRange(r.x, r.z, gx, X, region.Tiles[0], region.Tiles[1]) &&
      tileRange(r.y, r.w, gy, grid.TilesY, region.Tiles[2], region.Tiles[3]))
    {
      // Not-a-number depths give the whole range.
      const glm::dvec2 d = boxDepths ? options.TranslucentDepths[i] : glm::dvec2(nearest, deepest);
      region.Lo = d.x >= nearest ? d.x : nearest;
      region.Hi = d.y <= deepest ? d.y : deepest;
      // Its clusters' rectangles: the box's, grown as its tiles were (a fragment's
      // position lies in the box's projection, or within the grow of it).
      region.Rect[0] = outwardLo(r.x - 2.0 * gx / X);
      region.Rect[1] = outwardLo(r.y - 2.0 * gy / grid.TilesY);
      region.Rect[2] = outwardHi(r.z + 2.0 * gx / X);
      region.Rect[3] = outwardHi(r.w + 2.0 * gy / grid.TilesY);
      if (region.Lo <= region.Hi)
      {
        translucentRegions.push_back(region);
      }
    }
  }
  for (int ty = tileRowBegin; ty < tileRowEnd; ++ty)
  {
    std::fill(tileDeepest.begin(), tileDeepest.end(), 0.0f);
    std::fill(tileBackground.begin(), tileBackground.end(), 0);
    for (int y = 0; y < image.Height; ++y)
    {
      if (ty < rows[y].Lo || ty > rows[y].Hi)
      {
        continue;
      }
      const float* line = image.Depth + static_cast<std::size_t>(y) * image.Width;
      const float* lineMax =
        image.DepthMax ? image.DepthMax + static_cast<std::size_t>(y) * image.Width : line;
      int guess = 0;
      // Consecutive pixels of the line in the same tiles and slices form a run: its
      // interval (from its least and greatest window depths) and its rectangle (the union
      // of its pixels') grow those clusters once, the same bounds as pixel by pixel.
      struct Run
      {
        int Lo = 0, Hi = -1, S0 = 0, S1 = 0;
        float W0 = 0.0f, W1 = 0.0f, Rect[4];
      } run;
      const std::size_t ey = 2 * static_cast<std::size_t>(y);
      auto flush = [&]()
      {
        if (run.Lo > run.Hi)
        {
          return;
        }
        const float interval[2] = { static_cast<float>(lowest(run.W0)) * (1.0f - 1e-6f),
          static_cast<float>(highest(run.W1)) * (1.0f + 1e-6f) };
        // With translucent geometry anywhere, every tile keeps every depth in front of
        // its deepest opaque one (below): only that depth counts.
        for (int tx = run.Lo; tx <= run.Hi; ++tx)
        {
          tileDeepest[tx] = std::max(tileDeepest[tx], interval[1]);
          for (int s = run.S0; s <= run.S1 && !everywhere; ++s)
          {
            grow(texel(tx, ty, s), interval, run.Rect);
          }
        }
        run.Hi = run.Lo - 1;
      };
      for (int x = 0; x < image.Width; ++x)
      {
        const float w = line[x];
        const Detail::PixelTiles& c = columns[x];
        if (!(w < 1.0f))
        {
          flush();
          std::fill(tileBackground.begin() + c.Lo, tileBackground.begin() + c.Hi + 1, 1);
          continue;
        }
        const float wMax = lineMax[x];
        const int s0 = sliceAt(lowThreshold, w, guess);
        const int s1 = sliceAt(highThreshold, wMax, s0);
        guess = s0;
        const std::size_t ex = 2 * static_cast<std::size_t>(x);
        if (run.Lo <= run.Hi && c.Lo == run.Lo && c.Hi == run.Hi && s0 == run.S0 && s1 == run.S1)
        {
          run.W0 = std::min(run.W0, w);
          run.W1 = std::max(run.W1, wMax);
          run.Rect[0] = std::min(run.Rect[0], columnExtents[ex]);
          run.Rect[2] = std::max(run.Rect[2], columnExtents[ex + 1]);
          continue;
        }
        flush();
        run.Lo = c.Lo;
        run.Hi = c.Hi;
        run.S0 = s0;
        run.S1 = s1;
        run.W0 = w;
        run.W1 = wMax;
        run.Rect[0] = columnExtents[ex];
        run.Rect[1] = rowExtents[ey];
        run.Rect[2] = columnExtents[ex + 1];
        run.Rect[3] = rowExtents[ey + 1];
      }
      flush();
    }
    const float farLo = static_cast<float>(toView(1.0 - m) * (1.0 - rel));
    for (int tx = 0; tx < X; ++tx)
    {
      for (const TranslucentRegion& region : translucentRegions)
      {
        if (tx < region.Tiles[0] || tx > region.Tiles[1] || ty < region.Tiles[2] ||
          ty > region.Tiles[3])
        {
          continue;
        }
        // The depths its translucent fragments may have, to the deepest opaque depth (or
        // the far plane, where the tile shows background or the framebuffer is
        // multisampled).
        const bool toFar = tileBackground[tx] || image.DepthMax;
        const float interval[2] = { static_cast<float>(region.Lo) * (1.0f - 1e-6f),
          std::min(static_cast<float>(region.Hi) * (1.0f + 1e-6f),
            toFar ? static_cast<float>(deepest) : tileDeepest[tx]) };
        if (interval[1] > 0.0f && interval[0] <= interval[1])
        {
          const int s0 = sliceAt(boundary, static_cast<double>(interval[0]), 0);
          const int s1 = sliceAt(boundary, static_cast<double>(interval[1]), s0);
          for (int s = s0; s <= s1; ++s)
          {
            grow(texel(tx, ty, s), interval, region.Rect);
          }
        }
      }
      if (tileBackground[tx])
      {
        const float interval[2] = { farLo, static_cast<float>(deepest) };
        grow(texel(tx, ty, Z - 1), interval, wholePlane);
      }
    }
  }
}

/// Counts the non-empty clusters and records the visible range.
inline void FinishClusterDepthBounds(const VisibleRange& range, ClusterDepthBounds& out)
{
  out.NonEmptyClusters = 0;
  for (std::size_t t = 0; t < out.LoHi.size(); t += 2)
  {
    out.NonEmptyClusters += out.LoHi[t] <= out.LoHi[t + 1] ? 1 : 0;
  }
  out.VisiblePixels = range.Pixels;
  out.VisibleNear = range.Visible ? range.Nearest : 0.0;
  out.VisibleFar = range.Visible ? range.Deepest : 0.0;
  out.Valid = true;
}

/// All of the above in one call (single-threaded).
inline ClusterDepthBounds ComputeClusterDepthBounds(const DepthImage& image, const glm::dmat4& vcdc,
  const ClusterGridParams& grid, const DepthBoundsOptions& options)
{
  ClusterDepthBounds out;
  if (!HasDepthOnlyClipZ(vcdc) || image.Width < 1 || image.Height < 1 || !image.Depth)
  {
    return out;
  }
  const VisibleRange range = MeasureVisibleRange(image, vcdc);
  InitializeClusterDepthBounds(grid, out);
  ComputeClusterDepthBoundsRows(image, vcdc, grid, options, 0, grid.TilesY, out);
  FinishClusterDepthBounds(range, out);
  return out;
}

} // namespace vtkClusteredLighting

#endif
