// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingGrid.h
 * @brief GL-free cluster grid: screen tiles and depth slices.
 *
 * The view frustum of one renderer is cut into TilesX x TilesY screen tiles and
 * Slices depth slices. A fragment belongs to cluster (tx, ty, s):
 *
 *   tx = floor((fragCoord.x - viewportOrigin.x) * TilesX / viewportWidth)   clamped to [0, X-1]
 *   ty = floor((fragCoord.y - viewportOrigin.y) * TilesY / viewportHeight)  clamped to [0, Y-1]
 *   s  = ComputeSliceIndex(depth)                                            clamped to [0, Z-1]
 *
 * where depth = -z of the fragment in view coordinates (VC: eye at the origin looking
 * down -z). Fragments exist between the camera's near and far depths NearVC and FarVC.
 * Depth slicing runs between the slicing depths n = GetSlicingNear() and
 * f = GetSlicingFar(): the camera's range by default, or the range of depths actually
 * visible (SlicingNearVC, SlicingFarVC: the pass measures them in a depth prepass):
 *
 *   Exponential:  s = floor(Z * ln(depth / n) / ln(f / n))
 *   Linear:       s = floor(Z * (depth - n) / (f - n))
 *
 * Both are clamped to [0, Z-1] and monotonic in depth. A depth at or below n
 * (including 0 and negative depths: a light that reaches the camera or straddles the
 * near plane) maps to slice 0 without evaluating a logarithm of a non-positive number;
 * depths beyond f land in the last slice. So slice 0 always starts at the camera's NearVC
 * and the last slice always ends at GetMaxFragmentDepth(), whatever the slicing range. Slice k
 * spans [ComputeSliceBoundary(k), ComputeSliceBoundary(k+1)) and ComputeSliceIndex of a boundary
 * returns exactly k (pinned by unit tests).
 *
 * The GLSL function clComputeSliceIndex mirrors ComputeSliceIndex with the values of
 * ComputeSliceShaderParameters.
 */
#ifndef vtkClusteredLightingGrid_h
#define vtkClusteredLightingGrid_h

#include <algorithm> // for std::clamp
#include <cmath>     // for std::log
#include <limits>    // for std::numeric_limits

namespace vtkClusteredLighting
{

/// How depth is cut into slices.
enum class SlicingScheme
{
  Exponential = 0, ///< slices grow geometrically with depth (good for perspective)
  Linear = 1       ///< equal depth slices (good for parallel projection)
};

/// Screen-tile and depth-slice counts of one renderer's cluster grid.
struct ClusterGridParams
{
  int TilesX = 32;
  int TilesY = 16;
  int Slices = 32;
  int ViewportWidth = 1;  ///< pixels
  int ViewportHeight = 1; ///< pixels
  double NearVC = 0.1;    ///< clustering near depth (> 0)
  double FarVC = 1000.0;  ///< clustering far depth (> NearVC)
  /// Slicing range; 0 (the default) slices the camera range [NearVC, FarVC].
  double SlicingNearVC = 0.0;
  double SlicingFarVC = 0.0;
  SlicingScheme Scheme = SlicingScheme::Exponential;

  double GetSlicingNear() const
  {
    return this->SlicingNearVC > 0.0 ? this->SlicingNearVC : this->NearVC;
  }
  double GetSlicingFar() const
  {
    return this->SlicingFarVC > this->GetSlicingNear() ? this->SlicingFarVC : this->FarVC;
  }

  int GetNumberOfClusters() const { return this->TilesX * this->TilesY * this->Slices; }

  /**
   * Deepest view depth a fragment can have. GL clips at the far plane in float: with
   * P22 + 1 = -2 n / (f - n) the far plane moves by about 2^-24 * f / (2 n) relative, so
   * at far/near = 1e6 fragments survive a few percent beyond FarVC. The last slice and
   * the assignment extend to this depth (8x that error) so no such fragment misses a light.
   */
  double GetMaxFragmentDepth() const
  {
    const double floatEpsilon = 1.0 / 16777216.0;
    return this->FarVC * (1.0 + 4.0 * floatEpsilon * (this->FarVC / this->NearVC)) + 1e-12;
  }
};

/// Sanitize near/far so that slicing is always well defined (NearVC > 0, FarVC > NearVC).
/// The shaders get near, far and 1/near as 32-bit floats, so the range is also clamped to
/// [2/FLT_MAX, FLT_MAX]: 1/near and far stay finite there (a wider range cannot be
/// rendered in float anyway), and far = 2 near cannot overflow.
inline void SanitizeDepthRange(double& nearVC, double& farVC)
{
  const double floatMax = static_cast<double>(std::numeric_limits<float>::max());
  if (!(nearVC > 0.0) || !std::isfinite(nearVC))
  {
    nearVC = 1e-6;
  }
  nearVC = std::clamp(nearVC, 2.0 / floatMax, 0.5 * floatMax);
  if (!(farVC > nearVC) || !std::isfinite(farVC))
  {
    farVC = nearVC * 2.0;
  }
  farVC = std::min(farVC, floatMax);
}

/// Continuous slice coordinate (before flooring and clamping). Monotonic in depth.
inline double ComputeSliceCoordinate(double depthVC, const ClusterGridParams& grid)
{
  const double z = static_cast<double>(grid.Slices);
  const double n = grid.GetSlicingNear(), f = grid.GetSlicingFar();
  if (grid.Scheme == SlicingScheme::Linear)
  {
    return z * (depthVC - n) / (f - n);
  }
  if (!(depthVC > n))
  {
    return 0.0; // no log of a non-positive (or tiny) number: near slice
  }
  return z * std::log(depthVC / n) / std::log(f / n);
}

/// Depth where slice k begins (k in [0, Slices]). For assignment, slice 0 also holds
/// every depth below the slicing near depth and the last slice every depth beyond the
/// slicing far depth.
inline double ComputeSliceBoundary(int k, const ClusterGridParams& grid)
{
  const double t = static_cast<double>(k) / static_cast<double>(grid.Slices);
  const double n = grid.GetSlicingNear(), f = grid.GetSlicingFar();
  if (grid.Scheme == SlicingScheme::Linear)
  {
    return n + t * (f - n);
  }
  return n * std::pow(f / n, t);
}

/// Slice index of a view depth, clamped to [0, Slices-1]. NaN maps to slice 0.
/// Consistent with ComputeSliceBoundary: boundary(s) <= depth < boundary(s+1).
inline int ComputeSliceIndex(double depthVC, const ClusterGridParams& grid)
{
  const int last = grid.Slices - 1;
  const double c = std::floor(ComputeSliceCoordinate(depthVC, grid));
  int s = 0;
  if (c > 0.0)
  {
    s = c >= static_cast<double>(last) ? last : static_cast<int>(c);
  }
  else if (!(c == c))
  {
    return 0; // NaN depth
  }
  // log/pow rounding can put a depth one slice off right at a boundary: fix up.
  if (s > 0 && depthVC < ComputeSliceBoundary(s, grid))
  {
    --s;
  }
  else if (s < last && depthVC >= ComputeSliceBoundary(s + 1, grid))
  {
    ++s;
  }
  return s;
}

/// Tile index along one axis for a pixel-centre coordinate relative to the viewport
/// origin (e.g. 0.5 for the first pixel), clamped to [0, tiles-1].
inline int ComputeTileIndex(double pixelCoord, int viewportSize, int tiles)
{
  const double t = std::floor(pixelCoord * static_cast<double>(tiles) / viewportSize);
  if (!(t > 0.0))
  {
    return 0;
  }
  return t >= tiles - 1 ? tiles - 1 : static_cast<int>(t);
}

/// Linear cluster id used by CPU-side tables: ((ty * X) + tx) * Z + s.
inline int ComputeClusterId(int tx, int ty, int s, const ClusterGridParams& grid)
{
  return (ty * grid.TilesX + tx) * grid.Slices + s;
}

/**
 * Uniform values for the GLSL mirror clComputeSliceIndex(depth):
 *   exponential: s = floor(log(depth * P[0]) * P[1])   (depth <= n -> 0)
 *   linear:      s = floor((depth - P[2]) * P[1])
 * P[3] is 0 for exponential and 1 for linear. The values are uploaded as 32-bit floats:
 * they are clamped to the finite float range, so that a degenerate range (far/near
 * rounding to 1, or a linear range thinner than float precision) gives a huge but finite
 * factor instead of Inf (Inf times 0 is NaN in the shader).
 */
inline void ComputeSliceShaderParameters(const ClusterGridParams& grid, double p[4])
{
  const double floatMax = static_cast<double>(std::numeric_limits<float>::max());
  const double n = grid.GetSlicingNear(), f = grid.GetSlicingFar();
  p[0] = 1.0 / n;
  p[1] =
    grid.Scheme == SlicingScheme::Linear ? grid.Slices / (f - n) : grid.Slices / std::log(f / n);
  p[2] = n;
  p[3] = grid.Scheme == SlicingScheme::Linear ? 1.0 : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    p[k] = std::isnan(p[k]) ? 0.0 : std::clamp(p[k], -floatMax, floatMax);
  }
}

} // namespace vtkClusteredLighting

#endif
