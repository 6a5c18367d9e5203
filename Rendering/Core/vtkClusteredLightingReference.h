// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingReference.h
 * @brief Double-precision CPU reference assignment and comparison with GPU textures.
 *
 * The reference decides, for every cluster cell and every light, whether the light's
 * sphere reaches into the cell: distance(centre, cell) < radius. This is exactly the
 * condition under which the light contributes above the cutoff somewhere in the cell
 * (the radius is where the contribution equals the cutoff). It does not use the
 * tangent-bound code of the pass: each cell is built by unprojecting its NDC corners
 * at its two depth boundaries, which gives a convex hexahedron with planar faces (the
 * points with constant ndc_x form a plane), and the point-to-polyhedron distance is
 * computed exactly (inside test against the six face planes, else the distance to the
 * nearest face polygon).
 *
 * Cell (tx, ty, s) spans NDC x in [2 tx/X - 1, 2 (tx+1)/X - 1] (same for y), and depth
 * [max(boundary(s), near), min(boundary(s+1), far)]: only fragments between the camera
 * planes exist, slice 0 starts at the near plane and the last slice ends at `far`. Pass
 * ClusterGridParams::GetMaxFragmentDepth() as `far`: GL's float clipping lets fragments
 * exist slightly beyond the far plane at large far/near ratios.
 *
 * Depth-aware clusters (vtkClusteredLightingDepthBounds.h): each cell's depth range is
 * further cut to the cluster's recorded interval, and a cluster without one is empty.
 *
 * Spot lights whose cones the pass culls (ReferenceLight::CosCone > -1.5): a cell must
 * also come within the radius of the sector's bounding sphere (ComputeSpotSectorSphere)
 * and its bounding box's ball must meet the cone (SpotConeMayReachBall): the tests of
 * vtkClusteredLightingSpotBounds.h in double precision, on the exact cell, each holding
 * every point the light can reach (the core tests check that by sampling), so the GPU's
 * float tests, with their margins, must keep every cell kept here.
 *
 * For speed, each light is first tested only against the cells that its clipped
 * axis-aligned box can touch: the projection of a box in front of the eye lies in the
 * convex hull of its projected corners, so that prefilter is conservative too (and
 * independent of the pass's bounds code), with one extra tile and slice of slack.
 */
#ifndef vtkClusteredLightingReference_h
#define vtkClusteredLightingReference_h

#include "vtkClusteredLightingDepthBounds.h"
#include "vtkClusteredLightingLayout.h"
#include "vtkClusteredLightingSphereBounds.h"
#include "vtkClusteredLightingSpotBounds.h"

#include <array>   // for std::array
#include <cstdint> // for uint32_t
#include <glm/glm.hpp>
#include <limits>  // for std::numeric_limits
#include <sstream> // for std::ostringstream
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace vtkClusteredLighting
{

struct ReferenceLight
{
  glm::dvec3 CenterVC;
  double Radius;                       ///< may be +inf (always on) or 0 (never reaches anything)
  glm::dvec3 AxisVC = glm::dvec3(0.0); ///< a spot light's unit axis, when CosCone > -1.5
  double CosCone = -2.0; ///< cos(cone angle) of a spot light whose cone is culled, else -2
};

/// Geometry of one cluster cell: eight corners, index ix + 2 iy + 4 iz, and the ball
/// about their axis-aligned box (the list pass tests spot cones against it).
struct ClusterCell
{
  std::array<glm::dvec3, 8> Corners;
  glm::dvec3 BallCentre = glm::dvec3(0.0);
  double BallRadius = 0.0;
  bool Empty = true;
};

/// Point on the ray of NDC (x, y) at view depth `depth` (requires W.x = W.y = 0).
inline glm::dvec3 UnprojectAtDepth(double ndcX, double ndcY, double depth, const glm::dmat4& vcdc)
{
  const glm::dvec4 A = GetMatrixRow(vcdc, 0), B = GetMatrixRow(vcdc, 1), W = GetMatrixRow(vcdc, 3);
  const double pz = -depth;
  const double w = W.z * pz + W.w;
  const double r0 = ndcX * w - A.z * pz - A.w;
  const double r1 = ndcY * w - B.z * pz - B.w;
  const double det = A.x * B.y - A.y * B.x;
  return glm::dvec3((r0 * B.y - A.y * r1) / det, (A.x * r1 - r0 * B.x) / det, pz);
}

/// Cell of cluster (tx, ty, s); with depth-aware bounds, cut to the cluster's depths.
inline ClusterCell ComputeClusterCell(int tx, int ty, int s, const ClusterGridParams& grid,
  const glm::dmat4& vcdc, double nearVC, double farVC, const ClusterDepthBounds* depths = nullptr)
{
  ClusterCell cell;
  double z0 = s == 0 ? nearVC : std::max(ComputeSliceBoundary(s, grid), nearVC);
  double z1 = s == grid.Slices - 1 ? farVC : std::min(ComputeSliceBoundary(s + 1, grid), farVC);
  double x[2] = { 2.0 * tx / grid.TilesX - 1.0, 2.0 * (tx + 1) / grid.TilesX - 1.0 };
  double y[2] = { 2.0 * ty / grid.TilesY - 1.0, 2.0 * (ty + 1) / grid.TilesY - 1.0 };
  if (depths && depths->Valid)
  {
    double lo = 0.0, hi = 0.0;
    if (!depths->GetInterval(tx, ty, s, grid.TilesX, lo, hi))
    {
      return cell;
    }
    z0 = std::max(z0, lo);
    z1 = std::min(z1, hi);
    // The tile cut to the rectangle its fragments cover (as the list pass does).
    double rect[4];
    if (depths->GetRect(tx, ty, s, grid.TilesX, rect))
    {
      x[0] = std::max(x[0], rect[0]);
      y[0] = std::max(y[0], rect[1]);
      x[1] = std::max(std::min(x[1], rect[2]), x[0]);
      y[1] = std::max(std::min(y[1], rect[3]), y[0]);
    }
  }
  if (!(z1 > z0))
  {
    return cell;
  }
  cell.Empty = false;
  const double z[2] = { z0, z1 };
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (int i = 0; i < 8; ++i)
  {
    cell.Corners[i] = UnprojectAtDepth(x[i & 1], y[(i >> 1) & 1], z[i >> 2], vcdc);
    lo = glm::min(lo, cell.Corners[i]);
    hi = glm::max(hi, cell.Corners[i]);
  }
  cell.BallCentre = 0.5 * (lo + hi);
  cell.BallRadius = 0.5 * glm::length(hi - lo);
  return cell;
}

namespace Detail
{
inline double DistanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  double t = len2 > 0.0 ? glm::dot(p - a, ab) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return glm::length(p - (a + t * ab));
}
} // namespace Detail

/// Exact Euclidean distance from p to the (convex) cell; 0 when p is inside.
inline double DistanceToCell(const glm::dvec3& p, const ClusterCell& cell)
{
  static const int faces[6][4] = { { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 },
    { 0, 1, 3, 2 }, { 4, 5, 7, 6 } };
  glm::dvec3 centroid(0.0);
  for (const auto& c : cell.Corners)
  {
    centroid += c;
  }
  centroid /= 8.0;
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : faces)
  {
    const glm::dvec3* q[4] = { &cell.Corners[f[0]], &cell.Corners[f[1]], &cell.Corners[f[2]],
      &cell.Corners[f[3]] };
    // Newell normal (robust for slightly non-planar or degenerate quads).
    glm::dvec3 n(0.0);
    for (int i = 0; i < 4; ++i)
    {
      const glm::dvec3& a = *q[i];
      const glm::dvec3& b = *q[(i + 1) & 3];
      n.x += (a.y - b.y) * (a.z + b.z);
      n.y += (a.z - b.z) * (a.x + b.x);
      n.z += (a.x - b.x) * (a.y + b.y);
    }
    const double nlen = glm::length(n);
    if (!(nlen > 0.0))
    {
      continue;
    }
    n /= nlen;
    glm::dvec3 fc = 0.25 * (*q[0] + *q[1] + *q[2] + *q[3]);
    if (glm::dot(n, fc - centroid) < 0.0)
    {
      n = -n; // outward
    }
    const double sd = glm::dot(p - fc, n);
    if (sd > 0.0)
    {
      inside = false;
    }
    // Closest point on the face polygon.
    const glm::dvec3 proj = p - sd * n;
    bool inPoly = true;
    double edgeBest = std::numeric_limits<double>::infinity();
    // Orientation of the polygon around n.
    double orient = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      orient += glm::dot(glm::cross(*q[(i + 1) & 3] - *q[i], fc - *q[i]), n);
    }
    for (int i = 0; i < 4; ++i)
    {
      const glm::dvec3& a = *q[i];
      const glm::dvec3& b = *q[(i + 1) & 3];
      const double side = glm::dot(glm::cross(b - a, proj - a), n);
      if ((orient >= 0.0 && side < 0.0) || (orient < 0.0 && side > 0.0))
      {
        inPoly = false;
      }
      edgeBest = std::min(edgeBest, Detail::DistanceToSegment(p, a, b));
    }
    best = std::min(best, inPoly ? std::abs(sd) : edgeBest);
  }
  return inside ? 0.0 : best;
}

/**
 * Reference bitmask table: Words[clusterId * Batches + b] has bit j set iff light
 * 32 b + j reaches cluster clusterId = ComputeClusterId(tx, ty, s).
 */
struct ReferenceAssignment
{
  int Batches = 0;
  std::vector<std::uint32_t> Words;

  bool Contains(int clusterId, int light) const
  {
    return (this->Words[static_cast<std::size_t>(clusterId) * this->Batches + (light >> 5)] >>
             (light & 31)) &
      1u;
  }
};

inline ReferenceAssignment ComputeReferenceAssignment(const std::vector<ReferenceLight>& lights,
  const ClusterGridParams& grid, const glm::dmat4& vcdc, double nearVC, double farVC,
  const ClusterDepthBounds* depths = nullptr)
{
  ReferenceAssignment ref;
  const int n = static_cast<int>(lights.size());
  ref.Batches = (n + 31) / 32;
  const int clusters = grid.GetNumberOfClusters();
  ref.Words.assign(static_cast<std::size_t>(clusters) * ref.Batches, 0u);
  std::vector<ClusterCell> cells(static_cast<std::size_t>(clusters));
  for (int ty = 0; ty < grid.TilesY; ++ty)
  {
    for (int tx = 0; tx < grid.TilesX; ++tx)
    {
      for (int s = 0; s < grid.Slices; ++s)
      {
        cells[ComputeClusterId(tx, ty, s, grid)] =
          ComputeClusterCell(tx, ty, s, grid, vcdc, nearVC, farVC, depths);
      }
    }
  }

  for (int i = 0; i < n; ++i)
  {
    const ReferenceLight& l = lights[i];
    if (!(l.Radius > 0.0))
    {
      continue;
    }
    int t0[2] = { 0, 0 }, t1[2] = { grid.TilesX - 1, grid.TilesY - 1 };
    int s0 = 0, s1 = grid.Slices - 1;
    if (std::isfinite(l.Radius))
    {
      const double d = -l.CenterVC.z;
      const double zmin = std::max(d - l.Radius, nearVC);
      const double zmax = std::min(d + l.Radius, farVC);
      if (zmin > zmax)
      {
        continue;
      }
      double lo[2] = { std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity() };
      double hi[2] = { -lo[0], -lo[1] };
      for (int c = 0; c < 8; ++c)
      {
        const glm::dvec4 p(l.CenterVC.x + ((c & 1) ? l.Radius : -l.Radius),
          l.CenterVC.y + ((c & 2) ? l.Radius : -l.Radius), -((c & 4) ? zmax : zmin), 1.0);
        const glm::dvec4 clip = vcdc * p;
        for (int a = 0; a < 2; ++a)
        {
          const double ndc = clip[a] / clip.w;
          lo[a] = std::min(lo[a], ndc);
          hi[a] = std::max(hi[a], ndc);
        }
      }
      const int tiles[2] = { grid.TilesX, grid.TilesY };
      bool visible = true;
      for (int a = 0; a < 2; ++a)
      {
        if (hi[a] < -1.0 || lo[a] > 1.0)
        {
          visible = false;
          break;
        }
        const double u0 = std::floor(0.5 * (lo[a] + 1.0) * tiles[a]) - 1.0;
        const double u1 = std::floor(0.5 * (hi[a] + 1.0) * tiles[a]) + 1.0;
        t0[a] = static_cast<int>(std::max(0.0, std::min<double>(u0, tiles[a] - 1)));
        t1[a] = static_cast<int>(std::max(0.0, std::min<double>(u1, tiles[a] - 1)));
      }
      if (!visible)
      {
        continue;
      }
      s0 = std::max(ComputeSliceIndex(zmin, grid) - 1, 0);
      s1 = std::min(ComputeSliceIndex(zmax, grid) + 1, grid.Slices - 1);
    }
    const bool spot = l.CosCone > -1.5;
    const SpotSectorSphere sector = spot && std::isfinite(l.Radius)
      ? ComputeSpotSectorSphere(l.CenterVC, l.AxisVC, l.CosCone, l.Radius)
      : SpotSectorSphere{ l.CenterVC, l.Radius };
    for (int ty = t0[1]; ty <= t1[1]; ++ty)
    {
      for (int tx = t0[0]; tx <= t1[0]; ++tx)
      {
        for (int s = s0; s <= s1; ++s)
        {
          const int id = ComputeClusterId(tx, ty, s, grid);
          const ClusterCell& cell = cells[id];
          if (cell.Empty)
          {
            continue;
          }
          if (spot &&
            (!SpotConeMayReachBall(
               l.CenterVC, l.AxisVC, l.CosCone, cell.BallCentre, cell.BallRadius) ||
              (std::isfinite(sector.Radius) &&
                !(DistanceToCell(sector.Centre, cell) < sector.Radius))))
          {
            continue;
          }
          if (std::isinf(l.Radius) || DistanceToCell(l.CenterVC, cell) < l.Radius)
          {
            ref.Words[static_cast<std::size_t>(id) * ref.Batches + (i >> 5)] |= 1u << (i & 31);
          }
        }
      }
    }
  }
  return ref;
}

/// Result of comparing GPU list/master textures with the reference.
struct AssignmentComparison
{
  std::uint64_t ReferencePairs = 0;   ///< (cluster, light) pairs in the reference
  std::uint64_t GPUPairs = 0;         ///< pairs set in the GPU list texture
  std::uint64_t FalseNegatives = 0;   ///< in the reference, missing on the GPU
  std::uint64_t FalsePositives = 0;   ///< on the GPU, not in the reference
  std::uint64_t MasterMismatches = 0; ///< master bit != (list texel != 0)
  std::string FirstFalseNegative;     ///< description of the first miss, if any

  double GetFalsePositiveRate() const
  {
    return this->GPUPairs
      ? static_cast<double>(this->FalsePositives) / static_cast<double>(this->GPUPairs)
      : 0.0;
  }
};

inline int PopCount32(std::uint32_t v)
{
  int c = 0;
  for (; v; v &= v - 1)
  {
    ++c;
  }
  return c;
}

/**
 * Compares read-back textures (row-major, row 0 = texel row 0) with the reference.
 * list has layout.ListWidth * layout.ListHeight texels, master MasterWidth * MasterHeight.
 */
inline AssignmentComparison CompareWithReference(const ReferenceAssignment& ref,
  const std::vector<std::uint32_t>& list, const std::vector<std::uint32_t>& master,
  const ClusterTextureLayout& layout, const ClusterGridParams& grid)
{
  AssignmentComparison cmp;
  for (int ty = 0; ty < grid.TilesY; ++ty)
  {
    for (int tx = 0; tx < grid.TilesX; ++tx)
    {
      for (int s = 0; s < grid.Slices; ++s)
      {
        const int id = ComputeClusterId(tx, ty, s, grid);
        for (int b = 0; b < layout.Batches; ++b)
        {
          const TexelCoord t = layout.ListTexel(tx, ty, s, b);
          const std::uint32_t gpu = list[static_cast<std::size_t>(t.Y) * layout.ListWidth + t.X];
          const std::uint32_t want = ref.Words[static_cast<std::size_t>(id) * ref.Batches + b];
          cmp.ReferencePairs += PopCount32(want);
          cmp.GPUPairs += PopCount32(gpu);
          const std::uint32_t missing = want & ~gpu;
          cmp.FalseNegatives += PopCount32(missing);
          cmp.FalsePositives += PopCount32(gpu & ~want);
          if (missing && cmp.FirstFalseNegative.empty())
          {
            int bit = 0;
            while (!((missing >> bit) & 1u))
            {
              ++bit;
            }
            std::ostringstream os;
            os << "light " << LightOfBatchBit(b, bit) << " missing from cluster (" << tx << ", "
               << ty << ", " << s << ")";
            cmp.FirstFalseNegative = os.str();
          }
          const TexelCoord m = layout.MasterTexel(tx, ty, s, MasterTexelOfBatch(b));
          const std::uint32_t mword =
            master[static_cast<std::size_t>(m.Y) * layout.MasterWidth + m.X];
          const bool masterBit = (mword >> MasterBitOfBatch(b)) & 1u;
          if (masterBit != (gpu != 0u))
          {
            ++cmp.MasterMismatches;
          }
        }
      }
    }
  }
  return cmp;
}

/**
 * What lists of lights per cluster can do at best, on one depth image (issue 12's
 * culling ratio: lights evaluated per pixel against those that reach it). Per pixel that
 * shows geometry, its fragment is taken at the pixel's centre and its view depth (the
 * cluster the shader finds there): the lights that reach it (distance below the radius,
 * inside a culled cone), the lights of its cluster in `ref` (cell culling in double
 * precision, which the GPU's float box tests approach), and the lights that reach some
 * fragment of its cluster. A list can hold no fewer lights than that last set and miss no
 * fragment: no culling of whole clusters, however exact, walks fewer per pixel (Floor).
 * Only finer clusters lower it. Lights are tested only in their clusters of `ref`, which
 * holds every light that reaches a fragment of the cluster (the reference is conservative).
 */
struct ClusterCullingFloor
{
  std::size_t Pixels = 0; ///< pixels that show geometry
  double Reaching = 0.0;  ///< mean lights reaching a pixel's fragment
  double Floor = 0.0;     ///< mean lights reaching some fragment of the pixel's cluster
  double Cells = 0.0;     ///< mean lights of the pixel's cluster in the reference
};

inline ClusterCullingFloor MeasureClusterCullingFloor(const DepthImage& image,
  const glm::dmat4& vcdc, const ClusterGridParams& grid, const std::vector<ReferenceLight>& lights,
  const ReferenceAssignment& ref)
{
  ClusterCullingFloor out;
  const std::size_t batches = static_cast<std::size_t>(ref.Batches);
  if (!image.Depth || image.Width < 1 || image.Height < 1 || !HasDepthOnlyClipZ(vcdc) ||
    batches != (lights.size() + 31) / 32 ||
    ref.Words.size() != static_cast<std::size_t>(grid.GetNumberOfClusters()) * batches)
  {
    return out;
  }
  std::vector<std::uint32_t> reached(ref.Words.size(), 0u);
  std::vector<int> pixelCluster(static_cast<std::size_t>(image.Width) * image.Height, -1);
  double reaching = 0.0, cells = 0.0;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * image.Width + x;
      const double w = image.Depth[p];
      if (!(w < 1.0))
      {
        continue;
      }
      const double depth = ViewDepthFromWindowDepth(w, vcdc);
      const glm::dvec3 P = UnprojectAtDepth(
        2.0 * (x + 0.5) / image.Width - 1.0, 2.0 * (y + 0.5) / image.Height - 1.0, depth, vcdc);
      const int id = ComputeClusterId(ComputeTileIndex(x + 0.5, image.Width, grid.TilesX),
        ComputeTileIndex(y + 0.5, image.Height, grid.TilesY), ComputeSliceIndex(depth, grid), grid);
      pixelCluster[p] = id;
      ++out.Pixels;
      const std::uint32_t* words = &ref.Words[static_cast<std::size_t>(id) * batches];
      std::uint32_t* hit = &reached[static_cast<std::size_t>(id) * batches];
      for (std::size_t b = 0; b < batches; ++b)
      {
        cells += PopCount32(words[b]);
        for (std::uint32_t bits = words[b]; bits; bits &= bits - 1u)
        {
          int bit = 0;
          while (!((bits >> bit) & 1u))
          {
            ++bit;
          }
          const ReferenceLight& l = lights[32 * b + static_cast<std::size_t>(bit)];
          const glm::dvec3 toP = P - l.CenterVC;
          const double d = glm::length(toP);
          bool reaches = std::isinf(l.Radius) || d < l.Radius;
          if (reaches && l.CosCone > -1.5 && d > 0.0)
          {
            reaches = glm::dot(toP / d, l.AxisVC) >= l.CosCone;
          }
          if (reaches)
          {
            reaching += 1.0;
            hit[b] |= 1u << bit;
          }
        }
      }
    }
  }
  // Each cluster's count once, then summed over its pixels.
  std::vector<int> clusterFloor(static_cast<std::size_t>(grid.GetNumberOfClusters()), 0);
  for (std::size_t id = 0; id < clusterFloor.size(); ++id)
  {
    for (std::size_t b = 0; b < batches; ++b)
    {
      clusterFloor[id] += PopCount32(reached[id * batches + b]);
    }
  }
  double floor = 0.0;
  for (int id : pixelCluster)
  {
    floor += id >= 0 ? clusterFloor[static_cast<std::size_t>(id)] : 0;
  }
  if (out.Pixels > 0)
  {
    const double n = static_cast<double>(out.Pixels);
    out.Reaching = reaching / n;
    out.Floor = floor / n;
    out.Cells = cells / n;
  }
  return out;
}

} // namespace vtkClusteredLighting

#endif
