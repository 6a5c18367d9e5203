// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingSphereBounds.h
 * @brief Conservative screen and depth bounds of a light sphere, and its cluster range.
 *
 * A light of radius r centred at c (view coordinates, VC) can only light fragments
 * inside the clipped body  S = sphere(c, r) ∩ { near <= depth <= far },  depth = -z.
 * ComputeSphereScreenBounds returns the exact NDC rectangle of the projection of S
 * under the actual VC->clip matrix P (VTK's GetProjectionTransformMatrix(aspect,-1,1)),
 * for perspective, off-axis (P[2][0], P[2][1] != 0, e.g. SetWindowCenter, stereo) and
 * parallel projections alike.
 *
 * Derivation, per screen axis a (row A = P row a, row W = P row 3, with W.x = W.y = 0 as
 * for every VTK camera):
 *  - The points with ndc_a = k form the plane (A - k W) . (p, 1) = 0.
 *  - ndc_a restricted to S is extremal either where such a plane is tangent to the
 *    sphere (tangent point inside the depth slab), or on the circle where the sphere
 *    meets the near (or far) plane. There are no other critical points: on the flat
 *    near/far disks ndc_a is linear.
 *  - Tangency: (alpha - k beta)^2 = r^2 |A.xyz - k W.xyz|^2 with alpha = A.(c,1),
 *    beta = W.(c,1): a quadratic in k. It is homogeneous in (alpha, beta, r), so it is
 *    solved after scaling them to O(1) (no cancellation for far-away lights).
 *  - Near circle: centre (c.x, c.y, -near), radius sqrt(r^2 - (d - near)^2); its ndc_a
 *    extremes are (A.(q,1) +- rho |A.xy|) / W.(q,1).
 * The range on each axis is [min, max] over the valid candidates. When the eye is
 * inside the sphere there is no tangent plane through it and the near circle alone
 * bounds S; no division by a non-positive w ever happens, so there is no NaN for
 * d <= r, d = 0 or d < 0. This is the math of Mara & McGuire 2013 ("2D Polyhedral
 * Bounds of a Clipped, Perspective-Projected 3D Sphere") in plane form.
 *
 * ComputeClusterRange then snaps outward to whole tiles after widening by a small
 * padding (a fraction of a pixel in NDC and a relative epsilon in depth) that covers
 * the float rounding of the GPU's tile and slice computations.
 *
 * ComputeSliceTileRanges refines this per depth slice: the same exact bounds, with the
 * slice's (padded) depth slab as near and far planes, give the tile rectangle of the
 * sphere's cross-section in that slice. The list pass draws one quad per (light, slice).
 *
 * ComputeCenterDepthQuadBounds is the NON-conservative "centre-depth quad" used by
 * several public implementations (cl2 up to 546d164, Babylon.js, CIS 565). It exists
 * only so that the benchmark can measure what it gets wrong.
 */
#ifndef vtkClusteredLightingSphereBounds_h
#define vtkClusteredLightingSphereBounds_h

#include "vtkClusteredLightingGrid.h"

#include <algorithm> // for std::min
#include <cmath>     // for std::sqrt
#include <glm/glm.hpp>
#include <limits> // for std::numeric_limits
#include <vector> // for std::vector

namespace vtkClusteredLighting
{

/// NDC rectangle and depth range of the part of a light sphere that can be visible.
struct SphereScreenBounds
{
  bool Visible = false;
  glm::dvec2 NDCMin = glm::dvec2(-1.0); ///< clamped to [-1, 1]
  glm::dvec2 NDCMax = glm::dvec2(1.0);
  double DepthMin = 0.0; ///< depth range of the sphere clipped to [near, far]
  double DepthMax = 0.0;
};

/// Inclusive cluster index ranges covered by one light.
struct ClusterRange
{
  int TileMin[2] = { 0, 0 };
  int TileMax[2] = { -1, -1 };
  int SliceMin = 0;
  int SliceMax = -1;
  bool IsEmpty() const
  {
    return this->TileMax[0] < this->TileMin[0] || this->TileMax[1] < this->TileMin[1] ||
      this->SliceMax < this->SliceMin;
  }
};

/// Row r of a glm (column-major) matrix.
inline glm::dvec4 GetMatrixRow(const glm::dmat4& m, int r)
{
  return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]);
}

namespace Detail
{
struct CandidateRange
{
  double Lo = std::numeric_limits<double>::infinity();
  double Hi = -std::numeric_limits<double>::infinity();
  void Add(double v)
  {
    if (std::isfinite(v))
    {
      this->Lo = std::min(this->Lo, v);
      this->Hi = std::max(this->Hi, v);
    }
  }
  bool IsValid() const { return this->Lo <= this->Hi; }
};

/// Adds the ndc values of the tangent planes whose tangent point lies in the slab.
inline void AddTangentCandidates(const glm::dvec4& A, const glm::dvec4& W, const glm::dvec3& c,
  double r, double nearVC, double farVC, CandidateRange& range)
{
  const glm::dvec3 a3(A), w3(W);
  double alpha = glm::dot(a3, c) + A.w;
  double beta = glm::dot(w3, c) + W.w;
  // Scale (alpha, beta, r) to O(1); the tangency equation is homogeneous in them.
  const double scale = std::max(std::max(std::abs(alpha), std::abs(beta)), r);
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    return;
  }
  alpha /= scale;
  beta /= scale;
  const double rs = r / scale;
  const double qa = beta * beta - rs * rs * glm::dot(w3, w3);
  const double qb = -2.0 * (alpha * beta - rs * rs * glm::dot(a3, w3));
  const double qc = alpha * alpha - rs * rs * glm::dot(a3, a3);

  double roots[2];
  int nroots = 0;
  const double qmax = std::max(std::max(std::abs(qa), std::abs(qb)), std::abs(qc));
  if (std::abs(qa) <= 1e-14 * qmax)
  {
    if (std::abs(qb) > 0.0)
    {
      roots[nroots++] = -qc / qb; // one tangent plane, the other is at infinity
    }
  }
  else
  {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0)
    {
      return; // no plane of the family touches the sphere (eye inside, in this axis)
    }
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (qb + (qb >= 0.0 ? sq : -sq));
    roots[nroots++] = q / qa;
    if (q != 0.0)
    {
      roots[nroots++] = qc / q;
    }
  }

  // Generous slab test: including a candidate slightly outside only widens the range.
  const double tol = 1e-9 * (std::abs(nearVC) + std::abs(farVC) + r);
  for (int i = 0; i < nroots; ++i)
  {
    const double k = roots[i];
    const glm::dvec3 n = a3 - k * w3;
    const double e = A.w - k * W.w;
    const double nn = glm::dot(n, n);
    if (!(nn > 0.0) || !std::isfinite(k))
    {
      continue;
    }
    const glm::dvec3 p = c - ((glm::dot(n, c) + e) / nn) * n;
    const double depth = -p.z;
    const double w = glm::dot(w3, p) + W.w;
    if (w > 0.0 && depth >= nearVC - tol && depth <= farVC + tol)
    {
      range.Add(k);
    }
  }
}

/// Adds the ndc extremes of the circle where the sphere meets the plane depth = planeVC.
inline void AddPlaneCircleCandidates(const glm::dvec4& A, const glm::dvec4& W, const glm::dvec3& c,
  double r, double planeVC, CandidateRange& range)
{
  const double dz = -c.z - planeVC;
  const double rho2 = r * r - dz * dz;
  if (!(rho2 >= 0.0))
  {
    return;
  }
  const double rho = std::sqrt(rho2);
  const glm::dvec4 q(c.x, c.y, -planeVC, 1.0);
  const double wq = glm::dot(W, q);
  if (!(wq > 0.0))
  {
    return;
  }
  const double center = glm::dot(A, q);
  const double spread = rho * std::sqrt(A.x * A.x + A.y * A.y);
  range.Add((center - spread) / wq);
  range.Add((center + spread) / wq);
}
} // namespace Detail

/**
 * Exact NDC bounds of sphere(centerVC, radius) clipped to nearVC <= depth <= farVC under
 * the VC->clip matrix vcdc. An infinite radius covers the whole screen and depth range.
 */
inline SphereScreenBounds ComputeSphereScreenBounds(
  const glm::dvec3& centerVC, double radius, const glm::dmat4& vcdc, double nearVC, double farVC)
{
  SphereScreenBounds b;
  const double d = -centerVC.z;
  if (std::isinf(radius))
  {
    b.Visible = radius > 0.0;
    b.DepthMin = nearVC;
    b.DepthMax = farVC;
    return b;
  }
  if (!(radius >= 0.0) || std::isnan(d) || d + radius < nearVC || d - radius > farVC)
  {
    // Invalid (a NaN depth comes from a degenerate view matrix; the shader skips such a
    // light too), entirely in front of the near plane or beyond the far plane.
    return b;
  }
  b.DepthMin = std::max(d - radius, nearVC);
  b.DepthMax = std::min(d + radius, farVC);

  const glm::dvec4 W = GetMatrixRow(vcdc, 3);
  const bool generalW = W.x != 0.0 || W.y != 0.0;
  for (int axis = 0; axis < 2; ++axis)
  {
    Detail::CandidateRange range;
    if (!generalW)
    {
      const glm::dvec4 A = GetMatrixRow(vcdc, axis);
      Detail::AddTangentCandidates(A, W, centerVC, radius, nearVC, farVC, range);
      if (d - radius < nearVC)
      {
        Detail::AddPlaneCircleCandidates(A, W, centerVC, radius, nearVC, range);
      }
      if (d + radius > farVC)
      {
        Detail::AddPlaneCircleCandidates(A, W, centerVC, radius, farVC, range);
      }
    }
    if (!range.IsValid())
    {
      // Unsupported projection form or degenerate numbers: cover the whole axis.
      range.Lo = -1.0;
      range.Hi = 1.0;
    }
    if (range.Hi < -1.0 || range.Lo > 1.0)
    {
      b.Visible = false;
      return b;
    }
    b.NDCMin[axis] = std::max(range.Lo, -1.0);
    b.NDCMax[axis] = std::min(range.Hi, 1.0);
  }
  b.Visible = true;
  return b;
}

/**
 * The non-conservative centre-depth quad (projects c +- r at the centre depth). For
 * benchmark comparisons only; guarded so that it never produces NaN (d <= near covers
 * the screen).
 */
inline SphereScreenBounds ComputeCenterDepthQuadBounds(
  const glm::dvec3& centerVC, double radius, const glm::dmat4& vcdc, double nearVC, double farVC)
{
  SphereScreenBounds b;
  const double d = -centerVC.z;
  if (std::isinf(radius)) // as ComputeSphereScreenBounds (d -+ radius would be NaN for d = Inf)
  {
    b.Visible = radius > 0.0;
    b.DepthMin = nearVC;
    b.DepthMax = farVC;
    return b;
  }
  if (!(radius >= 0.0) || std::isnan(d) || d + radius < nearVC || d - radius > farVC)
  {
    return b;
  }
  b.Visible = true;
  b.DepthMin = std::max(d - radius, nearVC);
  b.DepthMax = std::min(d + radius, farVC);
  if (d <= nearVC)
  {
    return b;
  }
  for (int axis = 0; axis < 2; ++axis)
  {
    glm::dvec4 lo(centerVC, 1.0), hi(centerVC, 1.0);
    lo[axis] -= radius;
    hi[axis] += radius;
    const glm::dvec4 clo = vcdc * lo, chi = vcdc * hi;
    const double a = clo[axis] / clo.w, c = chi[axis] / chi.w;
    if (!std::isfinite(a) || !std::isfinite(c))
    {
      continue; // degenerate projection: keep the whole axis (NDCMin/NDCMax are -1/1)
    }
    const double mn = std::min(a, c), mx = std::max(a, c);
    if (mx < -1.0 || mn > 1.0)
    {
      b.Visible = false;
      return b;
    }
    b.NDCMin[axis] = std::max(mn, -1.0);
    b.NDCMax[axis] = std::min(mx, 1.0);
  }
  return b;
}

/**
 * Padding that covers the GPU's float rounding: NDC widening of padPixels pixels and a
 * relative depth widening. Defaults are far above float error (1/64 px and 1e-5).
 */
struct ClusterRangePadding
{
  double Pixels = 1.0 / 64.0;
  double RelativeDepth = 1e-5;
};

/// Snaps bounds outward to whole tiles and slices of the grid (inclusive ranges).
inline ClusterRange ComputeClusterRange(const SphereScreenBounds& b, const ClusterGridParams& grid,
  const ClusterRangePadding& pad = ClusterRangePadding())
{
  ClusterRange cr;
  if (!b.Visible)
  {
    return cr;
  }
  const int tiles[2] = { grid.TilesX, grid.TilesY };
  const int size[2] = { grid.ViewportWidth, grid.ViewportHeight };
  for (int axis = 0; axis < 2; ++axis)
  {
    const double padNDC = 2.0 * pad.Pixels / std::max(size[axis], 1) + 1e-9;
    const double u0 = 0.5 * (b.NDCMin[axis] - padNDC + 1.0);
    const double u1 = 0.5 * (b.NDCMax[axis] + padNDC + 1.0);
    const double t0 = std::floor(u0 * tiles[axis]);
    const double t1 = std::floor(u1 * tiles[axis]);
    cr.TileMin[axis] = t0 > 0.0 ? static_cast<int>(std::min<double>(t0, tiles[axis] - 1)) : 0;
    cr.TileMax[axis] = t1 > 0.0 ? static_cast<int>(std::min<double>(t1, tiles[axis] - 1)) : 0;
  }
  const double z0 = b.DepthMin - pad.RelativeDepth * std::abs(b.DepthMin);
  const double z1 = b.DepthMax + pad.RelativeDepth * std::abs(b.DepthMax);
  cr.SliceMin = ComputeSliceIndex(z0, grid);
  cr.SliceMax = ComputeSliceIndex(z1, grid);
  return cr;
}

/// Tiles of one depth slice that a light can reach (inclusive).
struct SliceTileRange
{
  int Slice = 0;
  int TileMin[2] = { 0, 0 };
  int TileMax[2] = { -1, -1 };
};

/// Depth slab [z0, z1] holding every fragment the GPU may put in slice s (padded).
inline void ComputePaddedSliceSlab(
  int s, const ClusterGridParams& grid, const ClusterRangePadding& pad, double& z0, double& z1)
{
  z0 = s == 0 ? grid.NearVC : ComputeSliceBoundary(s, grid);
  z1 = s == grid.Slices - 1 ? grid.GetMaxFragmentDepth() : ComputeSliceBoundary(s + 1, grid);
  z0 -= pad.RelativeDepth * std::abs(z0);
  z1 += pad.RelativeDepth * std::abs(z1);
}

/**
 * Appends the per-slice tile rectangles of sphere(centerVC, radius) to out; returns how
 * many were appended (0: the light reaches no cluster). With centerDepthQuad, every slice
 * of the range gets the (non-conservative) centre-depth rectangle, as in cl2.
 */
inline int ComputeSliceTileRanges(const glm::dvec3& centerVC, double radius, const glm::dmat4& vcdc,
  const ClusterGridParams& grid, std::vector<SliceTileRange>& out, bool centerDepthQuad = false,
  const ClusterRangePadding& pad = ClusterRangePadding())
{
  const double deepest = grid.GetMaxFragmentDepth();
  const SphereScreenBounds whole = centerDepthQuad
    ? ComputeCenterDepthQuadBounds(centerVC, radius, vcdc, grid.NearVC, deepest)
    : ComputeSphereScreenBounds(centerVC, radius, vcdc, grid.NearVC, deepest);
  const ClusterRange range = ComputeClusterRange(whole, grid, pad);
  if (range.IsEmpty())
  {
    return 0;
  }
  int added = 0;
  for (int s = range.SliceMin; s <= range.SliceMax; ++s)
  {
    SliceTileRange r;
    r.Slice = s;
    ClusterRange tiles = range;
    if (!centerDepthQuad && std::isfinite(radius))
    {
      double z0, z1;
      ComputePaddedSliceSlab(s, grid, pad, z0, z1);
      tiles =
        ComputeClusterRange(ComputeSphereScreenBounds(centerVC, radius, vcdc, z0, z1), grid, pad);
      if (tiles.IsEmpty())
      {
        continue;
      }
    }
    for (int a = 0; a < 2; ++a)
    {
      r.TileMin[a] = tiles.TileMin[a];
      r.TileMax[a] = tiles.TileMax[a];
    }
    out.push_back(r);
    ++added;
  }
  return added;
}

} // namespace vtkClusteredLighting

#endif
