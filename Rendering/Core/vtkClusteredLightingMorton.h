// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingMorton.h
 * @brief 30-bit 3D Morton (Z-order) codes used to sort lights before upload.
 *
 * Lights close in space get close indices, so they share 32-light batches: more list
 * texels stay zero, fewer master bits are set and the shading loop fetches fewer texels.
 * Positions are quantized to 10 bits per axis inside the bounding box of the lights.
 * Only finite coordinates are quantized (callers reject non-finite lights first); the
 * quantizer clamps, so no float-to-integer conversion is ever out of range (no UB).
 */
#ifndef vtkClusteredLightingMorton_h
#define vtkClusteredLightingMorton_h

#include <algorithm> // for std::sort
#include <cmath>     // for std::floor
#include <cstdint>   // for uint32_t
#include <glm/glm.hpp>
#include <limits>  // for std::numeric_limits
#include <numeric> // for std::iota
#include <vector>  // for std::vector

namespace vtkClusteredLighting
{

/// Spreads the low 10 bits of v so that bit i moves to bit 3i.
inline std::uint32_t SpreadBits10(std::uint32_t v)
{
  v &= 0x3FFu;
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

/// Inverse of SpreadBits10.
inline std::uint32_t CompactBits10(std::uint32_t v)
{
  v &= 0x09249249u;
  v = (v | (v >> 2)) & 0x030C30C3u;
  v = (v | (v >> 4)) & 0x0300F00Fu;
  v = (v | (v >> 8)) & 0x030000FFu;
  v = (v | (v >> 16)) & 0x3FFu;
  return v;
}

/// 30-bit Morton code of three 10-bit integers (x in the lowest bit).
inline std::uint32_t MortonCode3D(std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
  return SpreadBits10(x) | (SpreadBits10(y) << 1) | (SpreadBits10(z) << 2);
}

/// Quantizes t in [lo, hi] to [0, 1023], clamping (NaN maps to 0).
inline std::uint32_t QuantizeMorton10(double t, double lo, double hi)
{
  const double extent = hi - lo;
  const double u = extent > 0.0 ? (t - lo) / extent : 0.0;
  if (!(u > 0.0))
  {
    return 0u;
  }
  if (u >= 1.0)
  {
    return 1023u;
  }
  return static_cast<std::uint32_t>(std::floor(u * 1023.0 + 0.5));
}

/**
 * Permutation that sorts points by Morton code within their bounding box. group[i]
 * (optional, same size) sorts first: lower groups come first (the pass puts always-on
 * lights first so they pack into the first batches, and spot lights last, see
 * PrepareLights). Ties keep input order, so
 * the result is deterministic.
 */
inline std::vector<std::uint32_t> ComputeMortonOrder(
  const std::vector<glm::dvec3>& points, const std::vector<std::uint8_t>* group = nullptr)
{
  const std::size_t n = points.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  if (n == 0)
  {
    return order;
  }
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const auto& p : points)
  {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
    {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  std::vector<std::uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::dvec3& p = points[i];
    const std::uint64_t code = MortonCode3D(QuantizeMorton10(p.x, lo.x, hi.x),
      QuantizeMorton10(p.y, lo.y, hi.y), QuantizeMorton10(p.z, lo.z, hi.z));
    const std::uint64_t g = group ? (*group)[i] : 0u;
    keys[i] = (g << 32) | code;
  }
  std::stable_sort(order.begin(), order.end(),
    [&keys](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  return order;
}

} // namespace vtkClusteredLighting

#endif
