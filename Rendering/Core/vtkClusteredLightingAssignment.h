// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingAssignment.h
 * @brief GL-free per-view step: light records in view coordinates and list-pass quads.
 *
 * Data flow of one frame (CPU in double precision, GPU in float):
 *
 *   PreparedLight[]  --PackLightData-->   clLightData  (2 RGBA32F texels / light,
 *   (world coords,                         uploaded when lights change)
 *    Morton order)   --ComputeViewData--> clLightView  (2 RGBA32F texels / light,
 *                                          uploaded when the view changes:
 *                                          (centre VC, culling radius),
 *                                          (spot axis VC, explicit radius))
 *                                       + clQuads      (2 RGBA32F texels per (light, slice))
 *
 *   clQuads --list pass (instanced quads, logic-op OR)--> list texture (R32UI)
 *   list    --master pass (full screen)----------------> master texture (R32UI)
 *   fragment: cluster -> master bits -> list bits -> clLightData/clLightView -> shade
 *
 * Positions are transformed to view coordinates in double precision, so scenes far from
 * the origin keep their precision (the float records are relative to the eye).
 */
#ifndef vtkClusteredLightingAssignment_h
#define vtkClusteredLightingAssignment_h

#include "vtkClusteredLightingDepthBounds.h"
#include "vtkClusteredLightingLayout.h"
#include "vtkClusteredLightingLights.h"
#include "vtkClusteredLightingSphereBounds.h"
#include "vtkClusteredLightingSpotBounds.h"

#include <cmath> // for std::isfinite
#include <glm/glm.hpp>
#include <vector> // for std::vector

namespace vtkClusteredLighting
{

/// Floats per light in clLightData / clLightView, and per (light, slice) quad in clQuads:
///   (tileMinX, tileMinY, tileMaxX, tileMaxY), (slice, light index, cone, 0), where cone is
///   a spot light's cos(cone angle) when the list pass tests its cone (-2: no cone test).
constexpr int FloatsPerLightRecord = 8;
constexpr int FloatsPerQuad = 8;

/// Radius used in the shader for always-on lights (comparisons with +inf are avoided).
constexpr float AlwaysOnRadius = 1e30f;

/// A radius as the shaders get it: radii from AlwaysOnRadius up (infinite ones included)
/// become AlwaysOnRadius, so no float overflows to Inf.
inline float ToShaderRadius(double r)
{
  return r >= static_cast<double>(AlwaysOnRadius) ? AlwaysOnRadius : static_cast<float>(r);
}

/// How light spheres are bounded on screen.
enum class BoundsMethod
{
  Tangent = 0,        ///< exact, conservative (default)
  CenterDepthQuad = 1 ///< non-conservative; for benchmark comparisons only
};

struct ViewParameters
{
  glm::dmat4 WCVC = glm::dmat4(1.0); ///< world -> view (VTK's model-view matrix)
  glm::dmat4 VCDC = glm::dmat4(1.0); ///< view -> clip (VTK's projection matrix)
  ClusterGridParams Grid;            ///< includes the clustering near/far (camera planes)
  BoundsMethod Bounds = BoundsMethod::Tangent;
  ClusterRangePadding Padding;
  /// Spot lights are assigned only to the clusters their cones may reach (the sector's
  /// bounding sphere here, the cone per cluster in the list pass;
  /// vtkClusteredLightingSpotBounds.h).
  bool SpotConeCulling = true;
};

struct ViewData
{
  std::vector<float> LightView; ///< FloatsPerLightRecord per light
  std::vector<float> Quads;     ///< FloatsPerQuad per (light, slice)
  int NumberOfQuads = 0;
  int NumberOfAssignedLights = 0; ///< lights with at least one quad
  int NumberOfCulled = 0;         ///< lights with a radius that miss the view frustum
  /// (light, cluster) pairs of the tile rectangles before per-cluster culling (with
  /// depth-aware clusters, only the non-empty clusters the light's depth extent overlaps):
  /// divided by the number of (non-empty) clusters, the lights an average cluster holds.
  double ClusterCoverage = 0.0;
};

/// clLightData: (color * intensity, exponent), (a0, a1, a2, cos(cone) or -2). A negative
/// exponent slot marks a light split into a near and a far part (PreparedLight::FarField):
/// its near part is windowed at its radius, and a spot light's exponent e is stored as
/// -1 - e (exponents are >= 0; a point light's is unused and stored as 1).
inline std::vector<float> PackLightData(const std::vector<PreparedLight>& lights)
{
  std::vector<float> out(lights.size() * FloatsPerLightRecord);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    const PreparedLight& l = lights[i];
    float* o = &out[i * FloatsPerLightRecord];
    o[0] = static_cast<float>(l.Color.x);
    o[1] = static_cast<float>(l.Color.y);
    o[2] = static_cast<float>(l.Color.z);
    o[3] = static_cast<float>(l.FarField ? -1.0 - l.Exponent : l.Exponent);
    o[4] = static_cast<float>(l.Attenuation.x);
    o[5] = static_cast<float>(l.Attenuation.y);
    o[6] = static_cast<float>(l.Attenuation.z);
    o[7] = static_cast<float>(l.CosCone);
  }
  return out;
}

/// World -> view for directions: spot axes transform like vtkTransform::TransformNormal
/// (inverse transpose), as VTK's own lights do.
inline glm::dmat3 ComputeAxisMatrix(const glm::dmat4& wcvc)
{
  return glm::transpose(glm::inverse(glm::dmat3(wcvc)));
}

/// A light's unit spot axis in view coordinates (`axisMatrix`: ComputeAxisMatrix); 0 for a
/// point light or an axis that vanishes.
inline glm::dvec3 ComputeSpotAxisVC(const glm::dmat3& axisMatrix, const PreparedLight& l)
{
  if (!l.IsSpot())
  {
    return glm::dvec3(0.0);
  }
  const glm::dvec3 dir = axisMatrix * l.DirectionWC;
  const double len = glm::length(dir);
  return len > 0.0 ? dir / len : glm::dvec3(0.0);
}

/// Whether the view assigns light l by its cone (SpotConeCulling; `axisVC` from
/// ComputeSpotAxisVC): the list pass tests it, and the CPU reference must too.
inline bool IsAssignedByCone(bool spotConeCulling, const PreparedLight& l, const glm::dvec3& axisVC)
{
  return spotConeCulling && l.IsSpot() && glm::length(axisVC) > 0.5;
}

/**
 * Depth-aware clusters on the CPU, before the list pass: shrinks a (light, slice) tile
 * rectangle to the clusters the light's depth extent [d - r, d + r] (d = -c.z) can reach,
 * i.e. non-empty clusters whose recorded interval [lo, hi] it overlaps. Returns how many
 * clusters of the rectangle are such (0: the quad is dropped). The margin is at least the list
 * shader's box margin (1e-4 (z1 + |c|) + 1e-6, with z1 <= hi), and the shader cuts each cell to
 * [max(slice near, lo), min(slice far, hi)], so every cluster left out here is one the
 * shader would reject too: the lists are the same, the list pass draws fewer texels. (For
 * a spot light, c and radius are its sector's sphere, ComputeSpotSectorSphere: a cluster
 * left out is one the sector cannot reach.)
 */
inline int ShrinkToReachableClusters(const ClusterDepthBounds& depths, int tilesX,
  const glm::dvec3& c, double radius, SliceTileRange& r)
{
  int reachable = 0;
  const double d = -c.z;
  const double length = glm::length(c);
  int lo[2] = { r.TileMax[0] + 1, r.TileMax[1] + 1 };
  int hi[2] = { r.TileMin[0] - 1, r.TileMin[1] - 1 };
  for (int ty = r.TileMin[1]; ty <= r.TileMax[1]; ++ty)
  {
    for (int tx = r.TileMin[0]; tx <= r.TileMax[0]; ++tx)
    {
      double zLo = 0.0, zHi = 0.0;
      if (!depths.GetInterval(tx, ty, r.Slice, tilesX, zLo, zHi))
      {
        continue; // no fragment in this cluster
      }
      const double reach = radius + 2e-4 * (std::abs(zHi) + length + radius) + 2e-6;
      if (zLo > d + reach || zHi < d - reach)
      {
        continue;
      }
      ++reachable;
      lo[0] = std::min(lo[0], tx);
      lo[1] = std::min(lo[1], ty);
      hi[0] = std::max(hi[0], tx);
      hi[1] = std::max(hi[1], ty);
    }
  }
  if (reachable > 0)
  {
    r.TileMin[0] = lo[0];
    r.TileMin[1] = lo[1];
    r.TileMax[0] = hi[0];
    r.TileMax[1] = hi[1];
  }
  return reachable;
}

/**
 * View records (into `lightView`, FloatsPerLightRecord per light, for every light) and
 * list-pass quads (appended to `out`) for lights [begin, end) of the current view. Lights whose
 * radius is 0, or whose sphere misses the frustum, get no quad (they cost nothing in the list
 * pass). With depth-aware clusters (`depths` valid and of the view's grid) each quad is
 * shrunk to the clusters the light can reach (ShrinkToReachableClusters). Ranges are
 * independent: the assigner computes them in parallel and joins them in order.
 */
inline void ComputeViewDataRange(const std::vector<PreparedLight>& lights, const ViewParameters& v,
  const ClusterDepthBounds* depths, std::size_t begin, std::size_t end, float* lightView,
  ViewData& out)
{
  const bool depthAware = depths && depths->Valid &&
    depths->Width == v.Grid.TilesX * v.Grid.Slices && depths->Height == v.Grid.TilesY;
  const glm::dmat3 axisMatrix = ComputeAxisMatrix(v.WCVC);
  std::vector<SliceTileRange> ranges;
  for (std::size_t i = begin; i < end; ++i)
  {
    const PreparedLight& l = lights[i];
    const glm::dvec3 c = glm::dvec3(v.WCVC * glm::dvec4(l.PositionWC, 1.0));
    const glm::dvec3 dir = ComputeSpotAxisVC(axisMatrix, l);
    float* o = lightView + i * FloatsPerLightRecord;
    o[0] = static_cast<float>(c.x);
    o[1] = static_cast<float>(c.y);
    o[2] = static_cast<float>(c.z);
    o[3] = ToShaderRadius(l.Radius);
    o[4] = static_cast<float>(dir.x);
    o[5] = static_cast<float>(dir.y);
    o[6] = static_cast<float>(dir.z);
    // The light model's own range (an explicit radius), AlwaysOnRadius when it has none.
    o[7] = ToShaderRadius(l.ExplicitRadius);
    if (!(l.Radius > 0.0))
    {
      continue;
    }
    // A spot light's cone: its sector's sphere bounds the rectangles when it is smaller
    // than the light's, and the list pass tests the cone per cluster.
    const bool cone = IsAssignedByCone(v.SpotConeCulling, l, dir);
    glm::dvec3 centre = c;
    double radius = l.Radius;
    if (cone && std::isfinite(l.Radius))
    {
      const SpotSectorSphere sector = ComputeSpotSectorSphere(c, dir, l.CosCone, l.Radius);
      if (sector.Radius < radius)
      {
        centre = sector.Centre;
        radius = sector.Radius;
      }
    }
    const float coneRecord = cone ? static_cast<float>(l.CosCone) : -2.0f;
    ranges.clear();
    if (ComputeSliceTileRanges(centre, radius, v.VCDC, v.Grid, ranges,
          v.Bounds == BoundsMethod::CenterDepthQuad, v.Padding) == 0)
    {
      ++out.NumberOfCulled;
      continue;
    }
    int quads = 0;
    for (SliceTileRange& r : ranges)
    {
      const int reachable =
        depthAware ? ShrinkToReachableClusters(*depths, v.Grid.TilesX, centre, radius, r) : -1;
      if (reachable == 0)
      {
        continue;
      }
      ++quads;
      const float q[FloatsPerQuad] = { static_cast<float>(r.TileMin[0]),
        static_cast<float>(r.TileMin[1]), static_cast<float>(r.TileMax[0]),
        static_cast<float>(r.TileMax[1]), static_cast<float>(r.Slice), static_cast<float>(i),
        coneRecord, 0.0f };
      out.Quads.insert(out.Quads.end(), q, q + FloatsPerQuad);
      out.ClusterCoverage += reachable > 0 ? static_cast<double>(reachable)
                                           : static_cast<double>(r.TileMax[0] - r.TileMin[0] + 1) *
          static_cast<double>(r.TileMax[1] - r.TileMin[1] + 1);
    }
    out.NumberOfQuads += quads;
    out.NumberOfAssignedLights += quads > 0 ? 1 : 0;
  }
}

/// Joins `part` (a later range of the same view) to `out`.
inline void AppendViewData(ViewData& out, const ViewData& part)
{
  out.Quads.insert(out.Quads.end(), part.Quads.begin(), part.Quads.end());
  out.NumberOfQuads += part.NumberOfQuads;
  out.NumberOfAssignedLights += part.NumberOfAssignedLights;
  out.NumberOfCulled += part.NumberOfCulled;
  out.ClusterCoverage += part.ClusterCoverage;
}

/**
 * The most lights one cluster's list can hold after this view's list pass: the largest
 * number of quads of one slice whose tile rectangles share a tile (the list pass's
 * per-cluster culling only removes lights from that). A difference array per slice over
 * the tiles, then its prefix sums: O(quads + tiles x slices).
 */
inline int ComputeMostLightsInACluster(
  const std::vector<float>& quads, int tilesX, int tilesY, int slices)
{
  if (tilesX <= 0 || tilesY <= 0 || slices <= 0)
  {
    return 0;
  }
  const std::size_t w = static_cast<std::size_t>(tilesX) + 1;
  const std::size_t plane = w * (static_cast<std::size_t>(tilesY) + 1);
  std::vector<int> diff(plane * static_cast<std::size_t>(slices), 0);
  for (std::size_t q = 0; q + FloatsPerQuad <= quads.size(); q += FloatsPerQuad)
  {
    const int x0 = std::max(0, static_cast<int>(quads[q]));
    const int y0 = std::max(0, static_cast<int>(quads[q + 1]));
    const int x1 = std::min(tilesX - 1, static_cast<int>(quads[q + 2]));
    const int y1 = std::min(tilesY - 1, static_cast<int>(quads[q + 3]));
    const int s = static_cast<int>(quads[q + 4]);
    if (s < 0 || s >= slices || x0 > x1 || y0 > y1)
    {
      continue;
    }
    int* d = &diff[plane * static_cast<std::size_t>(s)];
    d[y0 * w + x0] += 1;
    d[y0 * w + x1 + 1] -= 1;
    d[(y1 + 1) * w + x0] -= 1;
    d[(y1 + 1) * w + x1 + 1] += 1;
  }
  int most = 0;
  for (int s = 0; s < slices; ++s)
  {
    int* d = &diff[plane * static_cast<std::size_t>(s)];
    for (int y = 0; y < tilesY; ++y)
    {
      for (int x = 0; x < tilesX; ++x)
      {
        const std::size_t i = y * w + x;
        d[i] +=
          (x > 0 ? d[i - 1] : 0) + (y > 0 ? d[i - w] : 0) - (x > 0 && y > 0 ? d[i - w - 1] : 0);
        most = std::max(most, d[i]);
      }
    }
  }
  return most;
}

/**
 * Mesa's llvmpipe ends a fragment shader after ShaderLoopLimit loop iterations in all (one
 * counter shared by every loop; GPU drivers have none). ComputeWalkIterations bounds the
 * iterations of a cluster's walk (vtkClusteredLightingShadingImpl.glsl) that lists `listed`
 * of `lights` lights: one per master texel, one per non-empty batch of 32 (at most
 * min(listed, batches)) and one per light; plus one per loop entered, in case the driver
 * counts the exit too. ComputeEveryLightIterations is brute force's loop over every
 * light, 16 lights per iteration. ComputeFarSumIterations is the exact far sums' loop,
 * which takes ComputeFarPartsPerIteration lights per iteration: one up to
 * FarSumSingleLightLimit lights, where a fragment whose cluster lists every light and
 * sums every far part stays within the limit, and 16 above. One is cheaper on llvmpipe,
 * which runs a first iteration of the loop for every group of fragments, masked, even
 * where no fragment needs the sums (vtkClusteredLightingShadingDec.glsl).
 */
constexpr long long ShaderLoopLimit = 65535;

inline long long ComputeWalkIterations(long long listed, long long lights, int masterTexels)
{
  const long long n = std::max(listed, 0LL);
  const long long batches = std::min(n, (std::max(lights, 0LL) + 31) / 32);
  const long long master = std::max(masterTexels, 0);
  return 2 * master + 2 * batches + n;
}

inline long long ComputeEveryLightIterations(long long lights)
{
  return (std::max(lights, 0LL) + 15) / 16;
}

constexpr long long FarSumSingleLightLimit = 16384;

inline int ComputeFarPartsPerIteration(long long lights)
{
  return lights <= FarSumSingleLightLimit ? 1 : 16;
}

inline long long ComputeFarSumIterations(long long lights)
{
  const long long perIteration = ComputeFarPartsPerIteration(lights);
  return (std::max(lights, 0LL) + perIteration - 1) / perIteration;
}

/// ComputeViewDataRange over every light, in one thread.
inline ViewData ComputeViewData(const std::vector<PreparedLight>& lights, const ViewParameters& v,
  const ClusterDepthBounds* depths = nullptr)
{
  ViewData out;
  out.LightView.resize(lights.size() * FloatsPerLightRecord);
  out.Quads.reserve(lights.size() * FloatsPerQuad);
  ComputeViewDataRange(lights, v, depths, 0, lights.size(), out.LightView.data(), out);
  return out;
}

/**
 * Uniforms of the list pass (vtkClusteredLightingListFS.glsl), packed from the view:
 * per-cluster culling unprojects tile edges with the rows (P00, P02, P03), (P11, P12, P13)
 * and (P32, P33) of the projection, which needs VTK's usual projection form
 * (P01 = P10 = P30 = P31 = 0); for any other form culling falls back to whole ranges.
 */
struct ListPassParameters
{
  bool CullClusters = true;
  float ProjectionX[3] = { 1, 0, 0 }; ///< P00, P02, P03
  float ProjectionY[3] = { 1, 0, 0 }; ///< P11, P12, P13
  float ProjectionW[2] = { -1, 0 };   ///< P32, P33
  float Slicing[4] = { 0, 0, 0, 0 };  ///< ComputeSliceShaderParameters
  float DepthRange[2] = { 0, 1 };     ///< camera near depth, deepest fragment depth
  /// Depth-aware clusters (vtkClusteredLightingDepthBounds.h): each cluster's cell is cut
  /// to the depths its fragments have; nullptr or not Valid: whole cells.
  const ClusterDepthBounds* DepthBounds = nullptr;
};

inline ListPassParameters ComputeListPassParameters(const ViewParameters& view,
  bool perClusterCulling, const ClusterDepthBounds* depthBounds = nullptr)
{
  ListPassParameters p;
  const glm::dmat4& P = view.VCDC; // column-major: P[column][row]
  const bool usualForm = P[1][0] == 0.0 && P[0][1] == 0.0 && P[0][3] == 0.0 && P[1][3] == 0.0;
  const bool depthAware = depthBounds && depthBounds->Valid && usualForm &&
    depthBounds->Width == view.Grid.TilesX * view.Grid.Slices &&
    depthBounds->Height == view.Grid.TilesY;
  p.DepthBounds = depthAware ? depthBounds : nullptr;
  // The depth-aware test is the per-cluster test on cut cells.
  p.CullClusters = (perClusterCulling || depthAware) && usualForm;
  p.ProjectionX[0] = static_cast<float>(P[0][0]);
  p.ProjectionX[1] = static_cast<float>(P[2][0]);
  p.ProjectionX[2] = static_cast<float>(P[3][0]);
  p.ProjectionY[0] = static_cast<float>(P[1][1]);
  p.ProjectionY[1] = static_cast<float>(P[2][1]);
  p.ProjectionY[2] = static_cast<float>(P[3][1]);
  p.ProjectionW[0] = static_cast<float>(P[2][3]);
  p.ProjectionW[1] = static_cast<float>(P[3][3]);
  double slicing[4];
  ComputeSliceShaderParameters(view.Grid, slicing);
  for (int k = 0; k < 4; ++k)
  {
    p.Slicing[k] = static_cast<float>(slicing[k]);
  }
  p.DepthRange[0] = static_cast<float>(view.Grid.NearVC);
  p.DepthRange[1] = static_cast<float>(view.Grid.GetMaxFragmentDepth());
  return p;
}

/**
 * Uniforms of the shading code (vtkClusteredLightingShadingDec.glsl) for one assignment:
 * clGrid = (tiles x, tiles y, slices, batch rows), clProjection (VC -> clip, column-major,
 * the matrix the mappers use), clSlicing (ComputeSliceShaderParameters).
 */
struct ShadingParameters
{
  int Grid[4] = { 1, 1, 1, 1 };
  float Projection[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  float Slicing[4] = { 0, 0, 0, 0 };
};

inline ShadingParameters ComputeShadingParameters(
  const ViewParameters& view, const ClusterTextureLayout& layout)
{
  ShadingParameters s;
  s.Grid[0] = view.Grid.TilesX;
  s.Grid[1] = view.Grid.TilesY;
  s.Grid[2] = view.Grid.Slices;
  s.Grid[3] = std::max(layout.BatchRows, 1);
  for (int i = 0; i < 16; ++i)
  {
    s.Projection[i] = static_cast<float>((&view.VCDC[0][0])[i]);
  }
  double slicing[4];
  ComputeSliceShaderParameters(view.Grid, slicing);
  for (int k = 0; k < 4; ++k)
  {
    s.Slicing[k] = static_cast<float>(slicing[k]);
  }
  return s;
}

} // namespace vtkClusteredLighting

#endif
