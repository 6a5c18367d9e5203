// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingClosedSurface.h
 * @brief When an opaque surface's back faces cannot show: a closed, consistently oriented
 *        mesh wholly beyond the near plane.
 *
 * On llvmpipe a hidden fragment costs about what a visible one does: with the depth
 * prepass it fails the depth test, but the fragment shader still runs for it, masked
 * (docs/depth.md, "What hidden fragments still cost on llvmpipe"). The back faces of a
 * closed surface are such fragments, and only not drawing them (GL's face culling) spares
 * their work. The pass culls them itself (its option `AutomaticBackfaceCulling`) where it
 * can prove that no back face of the mesh can be seen, so the image is unchanged (but
 * where a back face tied a front face in depth, at a silhouette or against another mesh,
 * and won: the front face shows there now):
 *
 * - **Closed and consistently oriented** (ComputeSurfaceClosure). With the points as
 *   numbered, or if that fails with points of equal coordinates as one vertex (a mesh
 *   whose normals were split at sharp edges repeats them): every directed edge (a, b) of
 *   a polygon occurs once, and its reverse (b, a) once, in another polygon, so every edge
 *   bounds exactly two polygons, which run along it in opposite directions. Each
 *   connected component then bounds a solid, and its polygons' normals (right-hand rule)
 *   all point out of it or all into it: the sign of its signed volume (the divergence
 *   theorem over the polygons' fan triangles) says which. The surface counts as oriented
 *   only if every component's sign is the same (a hollow shell's inner surface faces the
 *   other way: not culled). A mesh that folds through itself (locally inverted polygons)
 *   cannot be told apart from a sound one by these tests; where its fold showed a back
 *   face, culling hides it.
 * - **Wholly beyond the near plane** (IsBoxBeyondNearPlane). Every corner of the mesh's
 *   bounding box, taken to clip coordinates, has w > 0 and lies beyond the near plane
 *   (z > -w, with a margin). Then the near plane does not cut the solid and the eye (for a
 *   perspective camera) is outside it. A ray from the eye (or from the near plane, for a
 *   parallel camera) that reaches a point where it leaves the solid (a back face) entered
 *   it first, nearer, through a front face of the same mesh, which hides the back face.
 *   Coverage is watertight on shared edges, so the front face covers every sample the
 *   back face would.
 * - **Which face to cull** (ChooseCulledFace). GL's front faces are those wound counter-
 *   clockwise in window coordinates. With the polygons' normals pointing out, the faces
 *   that face the eye are wound counter-clockwise when the map from model to clip
 *   coordinates has a negative determinant (every OpenGL projection does: VTK's camera
 *   included), clockwise when an actor mirrors the mesh (a negative scale) or a projection
 *   is mirrored. So the culled face is GL's back face when orientation * det < 0, its
 *   front face when > 0, none when either is 0.
 *
 * The pass decides per actor and per frame (vtkClusteredLightingBackfaceCulling): only
 * opaque surfaces drawn as surfaces by a plain polydata mapper, with no clipping planes,
 * textures or face culling of their own, and of polygons only (a triangle strip alternates
 * its winding).
 */
#ifndef vtkClusteredLightingClosedSurface_h
#define vtkClusteredLightingClosedSurface_h

#include <algorithm> // for std::max
#include <cmath>     // for std::abs
#include <cstdint>   // for std::int64_t
#include <glm/glm.hpp>
#include <vector> // for std::vector

namespace vtkClusteredLighting
{

/// What ComputeSurfaceClosure found.
struct SurfaceClosure
{
  /// Every edge bounds two polygons, which run along it in opposite directions.
  bool Closed = false;
  /// +1: the normals point out of the solid; -1: in; 0: not closed, or no one orientation.
  int Orientation = 0;
  /// Why the surface is not closed ("closed" when it is).
  const char* Reason = "no polygons";
};

namespace Detail
{
/// Sorts `keys` in place, least significant 11 bits first (a radix sort whose 2,048
/// buckets stay in cache: the edges of a mesh of a million triangles in tens of ms).
inline void RadixSort(std::vector<std::uint64_t>& keys)
{
  constexpr int Bits = 11;
  constexpr std::uint64_t Mask = (1u << Bits) - 1;
  std::vector<std::uint64_t> buffer(keys.size());
  std::uint64_t all = 0;
  for (std::uint64_t k : keys)
  {
    all |= k;
  }
  for (int shift = 0; shift < 64 && (all >> shift) != 0; shift += Bits)
  {
    std::size_t count[Mask + 2] = {};
    for (std::uint64_t k : keys)
    {
      ++count[((k >> shift) & Mask) + 1];
    }
    for (std::size_t d = 1; d < Mask + 2; ++d)
    {
      count[d] += count[d - 1];
    }
    for (std::uint64_t k : keys)
    {
      buffer[count[(k >> shift) & Mask]++] = k;
    }
    keys.swap(buffer);
  }
}

/// Numbers the points so that points with equal coordinates share a number (a sort of
/// the points); returns how many numbers there are.
inline std::uint32_t MergePoints(
  const double* points, std::size_t n, std::vector<std::uint32_t>& vertexOf)
{
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    order[i] = static_cast<std::uint32_t>(i);
  }
  std::sort(order.begin(), order.end(),
    [points](std::uint32_t a, std::uint32_t b)
    {
      const double* pa = points + 3 * static_cast<std::size_t>(a);
      const double* pb = points + 3 * static_cast<std::size_t>(b);
      return pa[0] != pb[0] ? pa[0] < pb[0] : pa[1] != pb[1] ? pa[1] < pb[1] : pa[2] < pb[2];
    });
  vertexOf.assign(n, 0);
  std::uint32_t last = 0;
  for (std::size_t k = 1; k < n; ++k)
  {
    const double* p = points + 3 * static_cast<std::size_t>(order[k]);
    const double* q = points + 3 * static_cast<std::size_t>(order[k - 1]);
    last += p[0] == q[0] && p[1] == q[1] && p[2] == q[2] ? 0 : 1;
    vertexOf[order[k]] = last;
  }
  return n == 0 ? 0 : last + 1;
}

/// ComputeSurfaceClosure over the vertices `vertexOf` numbers the points with; `lo`, `hi`
/// the points' box.
inline SurfaceClosure ComputeClosureOfVertices(const double* points, std::int64_t numberOfPoints,
  const std::int64_t* offsets, const std::int64_t* connectivity, std::int64_t numberOfPolygons,
  const std::vector<std::uint32_t>& vertexOf, std::uint32_t vertices, const glm::dvec3& lo,
  const glm::dvec3& hi)
{
  SurfaceClosure result;
  auto point = [points](std::int64_t id)
  { return glm::dvec3(points[3 * id], points[3 * id + 1], points[3 * id + 2]); };

  // The directed edges, each as (min, max, direction) in one key; components of vertices.
  std::vector<std::uint64_t> edges;
  edges.reserve(static_cast<std::size_t>(offsets[numberOfPolygons] - offsets[0]));
  std::vector<std::uint32_t> parent(vertices);
  for (std::uint32_t v = 0; v < vertices; ++v)
  {
    parent[v] = v;
  }
  auto root = [&parent](std::uint32_t v)
  {
    while (parent[v] != v)
    {
      v = parent[v] = parent[parent[v]];
    }
    return v;
  };
  std::vector<std::uint32_t> polygon;
  for (std::int64_t c = 0; c < numberOfPolygons; ++c)
  {
    const std::int64_t begin = offsets[c], end = offsets[c + 1];
    if (end - begin < 3)
    {
      result.Reason = "a polygon has fewer than 3 vertices";
      return result;
    }
    polygon.clear();
    for (std::int64_t k = begin; k < end; ++k)
    {
      const std::int64_t id = connectivity[k];
      if (id < 0 || id >= numberOfPoints)
      {
        result.Reason = "a polygon refers to a point that does not exist";
        return result;
      }
      const std::uint32_t v = vertexOf[static_cast<std::size_t>(id)];
      if (std::find(polygon.begin(), polygon.end(), v) != polygon.end())
      {
        result.Reason = "a polygon repeats a vertex";
        return result;
      }
      polygon.push_back(v);
    }
    const std::uint32_t first = root(polygon[0]);
    for (std::size_t k = 0; k < polygon.size(); ++k)
    {
      parent[root(polygon[k])] = first;
      const std::uint64_t a = polygon[k], b = polygon[(k + 1) % polygon.size()];
      const std::uint64_t key = (std::min(a, b) << 32) | std::max(a, b);
      edges.push_back((key << 1) | (a < b ? 0 : 1));
    }
  }
  // Sorted, each edge must come as exactly two entries: one each way.
  RadixSort(edges);
  for (std::size_t e = 0; e < edges.size(); e += 2)
  {
    const std::uint64_t key = edges[e] >> 1;
    if (e + 1 == edges.size() || (edges[e + 1] >> 1) != key)
    {
      result.Reason = "an edge bounds only one polygon";
      return result;
    }
    if (e + 2 < edges.size() && (edges[e + 2] >> 1) == key)
    {
      result.Reason = "an edge bounds more than two polygons";
      return result;
    }
    if (edges[e] == edges[e + 1])
    {
      result.Reason = "two polygons run along an edge the same way";
      return result;
    }
  }
  result.Closed = true;
  result.Reason = "closed";

  // Each component's signed volume (six times it, the polygons' fan triangles about the
  // box's centre). The orientation holds only if every component's is clearly the same:
  // outward components only ever add to the winding number of a point (its count of
  // components around it), so a ray from outside meets a front face before any back face.
  const glm::dvec3 centre = 0.5 * (lo + hi);
  std::vector<double> volume6(vertices, 0.0);
  std::vector<char> component(vertices, 0);
  for (std::int64_t c = 0; c < numberOfPolygons; ++c)
  {
    const std::int64_t begin = offsets[c], end = offsets[c + 1];
    const glm::dvec3 p0 = point(connectivity[begin]) - centre;
    double sum = 0.0;
    for (std::int64_t k = begin + 1; k + 1 < end; ++k)
    {
      sum += glm::dot(
        p0, glm::cross(point(connectivity[k]) - centre, point(connectivity[k + 1]) - centre));
    }
    const std::uint32_t r = root(vertexOf[static_cast<std::size_t>(connectivity[begin])]);
    volume6[r] += sum;
    component[r] = 1;
  }
  const glm::dvec3 size = hi - lo;
  const double box6 = 6.0 * size.x * size.y * size.z;
  if (!(box6 > 0.0) || !std::isfinite(box6))
  {
    return result; // flat: no volume to be outside of
  }
  int orientation = 0;
  for (std::uint32_t v = 0; v < vertices; ++v)
  {
    if (!component[v])
    {
      continue; // not the root of a component of polygons
    }
    // Far above the sum's rounding (relative to the whole box: a tiny component counts
    // only if it is clearly not flat).
    const int sign = volume6[v] > 1e-9 * box6 ? 1 : volume6[v] < -1e-9 * box6 ? -1 : 0;
    if (sign == 0 || (orientation != 0 && sign != orientation))
    {
      return result; // closed, but no one orientation
    }
    orientation = sign;
  }
  result.Orientation = orientation;
  return result;
}
}

/**
 * Whether the polygons (VTK 9's cell array layout: polygon i has the point ids
 * connectivity[offsets[i]] .. connectivity[offsets[i + 1] - 1]) over `points` (x, y, z
 * for each of numberOfPoints) bound a solid, and which way their normals point. Points
 * with equal coordinates are merged. Not closed: no polygons, a polygon of fewer than 3
 * vertices or one that repeats a vertex, an edge that bounds one polygon, or more than
 * two, or two running along it the same way, or a non-finite coordinate. A closed surface
 * has Orientation 0 unless the signed volume of each of its components (polygons joined
 * by shared vertices) is clearly away from 0 (relative to the bounding box's) and all
 * have the same sign.
 *
 * The points are tried as they are numbered first: a surface closed by its point ids is
 * closed (its components may touch, each still bounds a solid), and only if it is not are
 * equal points merged and the test made again. Cost: a radix sort of the directed edges,
 * and for the second try a sort of the points (about 0.1 s and 0.3 s for a million
 * triangles on one core); the pass computes it once per modification of a polydata.
 */
inline SurfaceClosure ComputeSurfaceClosure(const double* points, std::int64_t numberOfPoints,
  const std::int64_t* offsets, const std::int64_t* connectivity, std::int64_t numberOfPolygons)
{
  SurfaceClosure result;
  if (numberOfPolygons <= 0 || numberOfPoints <= 0 || numberOfPoints >= (std::int64_t(1) << 31))
  {
    return result;
  }
  const std::size_t n = static_cast<std::size_t>(numberOfPoints);
  glm::dvec3 lo(points[0], points[1], points[2]), hi = lo;
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    {
      result.Reason = "a point has a non-finite coordinate";
      return result;
    }
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  std::vector<std::uint32_t> vertexOf(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    vertexOf[i] = static_cast<std::uint32_t>(i);
  }
  result = Detail::ComputeClosureOfVertices(points, numberOfPoints, offsets, connectivity,
    numberOfPolygons, vertexOf, static_cast<std::uint32_t>(n), lo, hi);
  if (result.Closed)
  {
    return result;
  }
  const std::uint32_t vertices = Detail::MergePoints(points, n, vertexOf);
  return vertices == n ? result
                       : Detail::ComputeClosureOfVertices(points, numberOfPoints, offsets,
                           connectivity, numberOfPolygons, vertexOf, vertices, lo, hi);
}

/**
 * Whether every corner of the box `bounds` (xmin, xmax, ymin, ymax, zmin, zmax, model
 * coordinates) lies beyond the near plane of `clipFromModel` (column vectors, GLM's
 * convention): w > 0 and z > -w + 1e-6 w for each. False for an empty or non-finite box.
 */
inline bool IsBoxBeyondNearPlane(const glm::dmat4& clipFromModel, const double bounds[6])
{
  if (!(bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5]))
  {
    return false;
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 p(
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)], 1.0);
    const glm::dvec4 clip = clipFromModel * p;
    if (!(clip.w > 0.0) || !(clip.z > -clip.w + 1e-6 * clip.w) || !std::isfinite(clip.z))
    {
      return false;
    }
  }
  return true;
}

/// Which of GL's faces hides nothing: +1 its back face, -1 its front face (glCullFace
/// GL_BACK, GL_FRONT), 0 none; `determinant` that of the map from model to clip
/// coordinates.
inline int ChooseCulledFace(int orientation, double determinant)
{
  if (orientation == 0 || !(std::abs(determinant) > 0.0) || !std::isfinite(determinant))
  {
    return 0;
  }
  return (orientation > 0) == (determinant < 0.0) ? 1 : -1;
}

} // namespace vtkClusteredLighting

#endif
// VTK-HeaderTest-Exclude: vtkClusteredLightingClosedSurface.h
