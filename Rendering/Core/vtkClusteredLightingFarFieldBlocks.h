// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFarFieldBlocks.h
 * @brief GL-free choice of the far field's blocks that shaded surfaces can read.
 *
 * The far field's grid (vtkClusteredLightingFarField.h) fills the box of the visible
 * geometry, but the shading reads it only at surface points: a fragment at world point p
 * interpolates the 8 nodes of the cell holding p (node coordinate c = (p - Origin) / h,
 * nodes floor(c) and floor(c) + 1 per axis, clamped to the grid, as the textures' linear
 * filter clamped to edge reads them). A floor and a bunny touch a small part of the box's
 * volume, so the build (vtkClusteredLightingFarFieldTree.h, blocks of 4 x 4 x 4 nodes)
 * need only sum the blocks holding nodes that some surface point can read: where the
 * lights move every frame, that is the whole rebuild's cost.
 *
 * Surfaces come as world boxes (a box per cell of a mesh, or a prop's bounds where its
 * geometry is not known cell by cell); MarkFarFieldBlocks marks every node that a point of
 * the box may read, with FarFieldBlockPad cells of slack on every side against the
 * shader's single-precision coordinates, as bits of a 64-bit mask per block. Points
 * outside the grid read its edge nodes (the clamp), so a box is clamped to the grid, never
 * dropped. A build (GetFarFieldBlocksToBuild) takes each block's marked nodes that are
 * not built yet in layers of 4 x 4 nodes along the axis that needs the fewest: a floor
 * on a node plane (where the grid puts the bottom of the geometry, ComputeFarFieldGrid)
 * reads 2 of the 4 layers across it in each block it crosses, and the sums skip the
 * other 2.
 *
 * Blocks not marked are not summed: what the textures hold there is stale or zero, finite,
 * and never read by a surface inside a marked box. Nothing so far depends on the camera:
 * a moving camera marks the same blocks. But only single-sampled fragments lie on their
 * surfaces: a multisampled one that covers part of its pixel is shaded at the pixel's
 * centre, on its primitive's plane extrapolated, possibly cells away from every box. For
 * those the pass adds the view's marks (MarkFarFieldBlocksOfPixels): the multisampled depth
 * prepass records, per pixel, the range of window depths its fragments are shaded at
 * (vtkClusteredLightingSampleDepths, for the depth-aware clusters), so every such
 * fragment lies in a known piece of the view frustum, whose world box is marked too.
 * These marks follow the camera; a camera move that reaches new nodes sums only those (a
 * build adds only what is missing). Without that record (depth-aware clusters off, or a
 * framebuffer it cannot be made for), or with translucent geometry in the frame (the
 * record holds the opaque fragments only), the pass marks every block in a multisampled
 * framebuffer (vtkClusteredLightingPass, FarFieldSkipEmptyBlocks).
 */
#ifndef vtkClusteredLightingFarFieldBlocks_h
#define vtkClusteredLightingFarFieldBlocks_h

#include "vtkClusteredLightingDepthBounds.h"  // for DepthImage
#include "vtkClusteredLightingFarFieldTree.h" // for FarFieldBlockSize, GetFarFieldBlocks

#include <algorithm> // for std::min, std::max
#include <array>     // for std::array
#include <cmath>     // for std::floor, std::abs, std::isfinite
#include <cstdint>   // for std::int64_t
#include <glm/glm.hpp>
#include <limits> // for std::numeric_limits
#include <vector> // for std::vector

namespace vtkClusteredLighting
{

/// Cells of slack MarkFarFieldBlocks gives a box on every side (the shader's texture
/// coordinates are single precision: far below a tenth of a cell).
constexpr double FarFieldBlockPad = 0.1;

/// The node range [first, last] along `axis` that points with world coordinates in
/// [lo, hi] may read, clamped to the grid.
inline std::array<int, 2> GetFarFieldNodeRange(
  const FarFieldGrid& grid, int axis, double lo, double hi)
{
  const int last = grid.Dims[static_cast<std::size_t>(axis)] - 1;
  const double c0 = (lo - grid.Origin[axis]) / grid.Spacing - FarFieldBlockPad;
  const double c1 = (hi - grid.Origin[axis]) / grid.Spacing + FarFieldBlockPad;
  // Clamped as doubles first: a box far outside the grid stays in int range.
  const double f0 = std::min(std::max(std::floor(c0), 0.0), static_cast<double>(last));
  const double f1 = std::min(std::max(std::floor(c1) + 1.0, 0.0), static_cast<double>(last));
  return { { static_cast<int>(f0), static_cast<int>(f1) } };
}

/**
 * Marks in `needed` (one 64-bit mask per block, GetNumberOfFarFieldBlocks, block index x
 * fastest; bit GetFarFieldBlockBit for each node) the nodes that a point of the world box
 * [lo, hi] may read. A box with a coordinate that is not a number marks every node along
 * that axis (nothing can be said of where it is). Returns the number of blocks that had
 * no mark before.
 */
inline std::int64_t MarkFarFieldBlocks(const FarFieldGrid& grid, const glm::dvec3& lo,
  const glm::dvec3& hi, std::vector<std::uint64_t>& needed)
{
  const std::array<int, 3> blocks = GetFarFieldBlocks(grid);
  std::array<std::array<int, 2>, 3> nodes;
  for (int a = 0; a < 3; ++a)
  {
    nodes[static_cast<std::size_t>(a)] = !(lo[a] == lo[a]) || !(hi[a] == hi[a])
      ? std::array<int, 2>{ { 0, grid.Dims[static_cast<std::size_t>(a)] - 1 } }
      : GetFarFieldNodeRange(grid, a, lo[a], hi[a]);
  }
  // The nodes of a block that the box's range along one axis holds, as offsets' bits.
  auto offsets = [&](int a, int block)
  {
    const int first = block * FarFieldBlockSize;
    unsigned bits = 0;
    for (int d = 0; d < FarFieldBlockSize; ++d)
    {
      const int node = first + d;
      bits |= (node >= nodes[static_cast<std::size_t>(a)][0] &&
                node <= nodes[static_cast<std::size_t>(a)][1])
        ? 1u << d
        : 0u;
    }
    return bits;
  };
  std::int64_t added = 0;
  for (int k = nodes[2][0] / FarFieldBlockSize; k <= nodes[2][1] / FarFieldBlockSize; ++k)
  {
    const unsigned bk = offsets(2, k);
    for (int j = nodes[1][0] / FarFieldBlockSize; j <= nodes[1][1] / FarFieldBlockSize; ++j)
    {
      const unsigned bj = offsets(1, j);
      for (int i = nodes[0][0] / FarFieldBlockSize; i <= nodes[0][1] / FarFieldBlockSize; ++i)
      {
        const unsigned bi = offsets(0, i);
        std::uint64_t mask = 0;
        for (int dk = 0; dk < FarFieldBlockSize; ++dk)
        {
          for (int dj = 0; dj < FarFieldBlockSize; ++dj)
          {
            for (int di = 0; di < FarFieldBlockSize; ++di)
            {
              const bool in = ((bk >> dk) & (bj >> dj) & (bi >> di) & 1u) != 0;
              mask |= in ? std::uint64_t{ 1 } << GetFarFieldBlockBit(di, dj, dk) : 0;
            }
          }
        }
        std::uint64_t& b = needed[static_cast<std::size_t>(
          (static_cast<std::int64_t>(k) * blocks[1] + j) * blocks[0] + i)];
        added += b ? 0 : 1;
        b |= mask;
      }
    }
  }
  return added;
}

/// Every node of a block (the mask of nodes when nothing is known of the surfaces).
constexpr std::uint64_t FarFieldAllNodes = ~std::uint64_t{ 0 };

/**
 * Marks in `needed` the nodes that a fragment shaded at its pixel's centre may read, from
 * a multisampled depth prepass's record of the window depths each pixel's fragments have
 * (`image`: [Depth, DepthMax] per pixel, vtkClusteredLightingSampleDepths; see the file's
 * description). The pixels go in squares of `piece` x `piece`: their fragments' window
 * positions lie in the box of the square's pixel centres and of its least and greatest
 * depths, widened by `windowMargin` (the depth buffer's quantization and VTK's coincident
 * offsets, DepthBoundsOptions::WindowMargin). The inverse of the projection and view maps
 * that box to the convex hull of its 8 corners' images (a projective map whose denominator
 * is positive at the corners, so on the whole box), and the world box of those corners is
 * marked. A pixel at the cleared depths (1, 1) (no fragment recorded) marks nothing: a
 * fragment exactly on the far plane records the same, and is not marked (one whose centre
 * lies past the far plane records a depth above 1, and is). `added`, if given, grows
 * by the number of blocks that had no mark before. Returns false and marks nothing when it
 * cannot say: no image or no DepthMax, a projection that cannot be inverted, a corner that
 * maps to infinity or behind the camera.
 */
inline bool MarkFarFieldBlocksOfPixels(const FarFieldGrid& grid, const DepthImage& image,
  const glm::dmat4& wcvc, const glm::dmat4& vcdc, double windowMargin, int piece,
  std::vector<std::uint64_t>& needed, std::int64_t* added = nullptr)
{
  if (!image.Depth || !image.DepthMax || image.Width < 1 || image.Height < 1 || piece < 1 ||
    !(windowMargin >= 0.0))
  {
    return false;
  }
  const glm::dmat4 worldFromNdc = glm::inverse(vcdc * wcvc);
  const double* m = &worldFromNdc[0][0];
  for (int i = 0; i < 16; ++i)
  {
    if (!std::isfinite(m[i]))
    {
      return false;
    }
  }
  std::vector<glm::dvec3> boxes;
  for (int y0 = 0; y0 < image.Height; y0 += piece)
  {
    const int y1 = std::min(y0 + piece, image.Height) - 1;
    for (int x0 = 0; x0 < image.Width; x0 += piece)
    {
      const int x1 = std::min(x0 + piece, image.Width) - 1;
      float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
      bool any = false;
      for (int y = y0; y <= y1; ++y)
      {
        const std::size_t row = static_cast<std::size_t>(y) * image.Width;
        for (int x = x0; x <= x1; ++x)
        {
          // The cleared depth, (1, 1), records no fragment; a fragment extrapolated past
          // the far plane records a depth above 1 and counts.
          const float w = image.Depth[row + x], wMax = image.DepthMax[row + x];
          if (w != 1.0f || wMax != 1.0f)
          {
            lo = std::min(lo, w);
            hi = std::max(hi, std::max(w, wMax));
            any = true;
          }
        }
      }
      if (!any)
      {
        continue; // no fragment recorded
      }
      glm::dvec3 boxLo(std::numeric_limits<double>::infinity());
      glm::dvec3 boxHi(-std::numeric_limits<double>::infinity());
      for (int c = 0; c < 8; ++c)
      {
        const double px = ((c & 1) ? x1 : x0) + 0.5, py = ((c & 2) ? y1 : y0) + 0.5;
        const double w = (c & 4) ? hi + windowMargin : lo - windowMargin;
        const glm::dvec4 q = worldFromNdc *
          glm::dvec4(
            2.0 * px / image.Width - 1.0, 2.0 * py / image.Height - 1.0, 2.0 * w - 1.0, 1.0);
        if (!(q.w > 0.0) || !std::isfinite(q.x + q.y + q.z + q.w))
        {
          return false;
        }
        const glm::dvec3 p = glm::dvec3(q) / q.w;
        boxLo = glm::min(boxLo, p);
        boxHi = glm::max(boxHi, p);
      }
      if (!std::isfinite(boxLo.x + boxLo.y + boxLo.z + boxHi.x + boxHi.y + boxHi.z))
      {
        return false;
      }
      boxes.push_back(boxLo);
      boxes.push_back(boxHi);
    }
  }
  std::int64_t count = 0;
  for (std::size_t i = 0; i + 1 < boxes.size(); i += 2)
  {
    count += MarkFarFieldBlocks(grid, boxes[i], boxes[i + 1], needed);
  }
  if (added)
  {
    *added += count;
  }
  return true;
}

/// The nodes of a block in layers [first, last] along `axis`, as a mask.
inline std::uint64_t GetFarFieldLayerMask(int axis, int first, int last)
{
  std::uint64_t mask = 0;
  for (int n = first * FarFieldLayerNodes; n < (last + 1) * FarFieldLayerNodes; ++n)
  {
    const glm::ivec3 d = GetFarFieldBlockNode(n, axis);
    mask |= std::uint64_t{ 1 } << GetFarFieldBlockBit(d.x, d.y, d.z);
  }
  return mask;
}

/**
 * What a build sums: each block with nodes marked in `needed` and not in `built` (built
 * may be shorter: nothing built there), in increasing order, taken in layers along the
 * axis whose layers from the lowest to the highest holding such a node are fewest (z on
 * a tie, the order nodes are stored in), with those layers.
 */
inline FarFieldBlockList GetFarFieldBlocksToBuild(
  const std::vector<std::uint64_t>& needed, const std::vector<std::uint64_t>& built)
{
  FarFieldBlockList list;
  for (std::size_t b = 0; b < needed.size(); ++b)
  {
    const std::uint64_t missing = needed[b] & ~(b < built.size() ? built[b] : 0u);
    if (!missing)
    {
      continue;
    }
    // Each axis's layers that hold a missing node.
    unsigned layers[3] = { 0, 0, 0 };
    for (int n = 0; n < FarFieldBlockNodes; ++n)
    {
      if ((missing >> n) & 1u)
      {
        layers[0] |= 1u << (n % FarFieldBlockSize);
        layers[1] |= 1u << ((n / FarFieldBlockSize) % FarFieldBlockSize);
        layers[2] |= 1u << (n / FarFieldLayerNodes);
      }
    }
    int axis = 2, span = FarFieldBlockSize + 1;
    for (int a = 2; a >= 0; --a)
    {
      int first, last;
      GetFarFieldLayerRange(layers[a], first, last);
      if (last - first + 1 < span)
      {
        span = last - first + 1;
        axis = a;
      }
    }
    list.Blocks.push_back(static_cast<std::int64_t>(b));
    list.Axis.push_back(static_cast<unsigned char>(axis));
    list.Layers.push_back(static_cast<unsigned char>(layers[axis]));
  }
  return list;
}

} // namespace vtkClusteredLighting

#endif
