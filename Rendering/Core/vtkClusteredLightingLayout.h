// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingLayout.h
 * @brief Texel layouts of the list and master textures, bit packing and memory.
 *
 * Light i (in upload order) lives in batch b = i >> 5 at bit i & 31.
 *
 * List texture, R32UI, one 32-light bitmask per (cluster, batch). Each batch is a block
 * of (X*Z) x Y texels, slice-major: slice s is the X x Y rectangle starting at column
 * s*X, so the clusters of one slice over a tile rectangle form one texel rectangle and
 * the list pass draws one quad per (light, slice) with no discarded fragments. (cl2 puts
 * the Z slices of a tile next to each other instead, and discards the slices a light
 * misses; measured here that made the list pass rasterize 5-20x more fragments.)
 * Blocks stack vertically (BatchRows of them per column, as in cl2) and, when
 * Y * batches would exceed the maximum texture size, wrap into further columns:
 *
 *        <------- X*Z ------->  <------- X*Z ------->
 *       +---------------------+---------------------+  ^
 *       | batch 0             | batch R             |  | Y
 *       +---------------------+---------------------+  v
 *       | batch 1             | batch R+1           |
 *       |   ...               |   ...               |
 *       | batch R-1           |                     |
 *       +---------------------+---------------------+
 *
 *   texel(tx, ty, s, b) = ((b / R) * X*Z + s*X + tx,  (b % R) * Y + ty),   R = BatchRows
 *
 * Master texture, R32UI, M = ceil(B / 32) texels per cluster, stacked inside the tile
 * row; bit (b & 31) of texel m = b >> 5 is set iff list texel (cluster, b) is non-zero:
 *
 *   master(tx, ty, s, m) = (s*X + tx, ty*M + m)
 *
 * Memory: the list texture takes 4 bytes per (cluster, batch), i.e. X*Y*Z*ceil(N/32)*4
 * bytes (X*Y*Z*N/8 when N is a multiple of 32), plus unused blocks of a partly filled
 * last column. Limits: every dimension must be <= GL_MAX_TEXTURE_SIZE; ComputeLayout
 * reports when the grid cannot hold N lights instead of dropping any.
 */
#ifndef vtkClusteredLightingLayout_h
#define vtkClusteredLightingLayout_h

#include "vtkClusteredLightingGrid.h"

#include <algorithm> // for std::min
#include <cstdint>   // for std::int64_t
#include <sstream>   // for std::ostringstream
#include <string>    // for std::string

namespace vtkClusteredLighting
{

constexpr int LightsPerBatch = 32;   ///< bits of one R32UI list texel
constexpr int BatchesPerMaster = 32; ///< bits of one R32UI master texel

inline int BatchOfLight(int i)
{
  return i >> 5;
}
inline int BitOfLight(int i)
{
  return i & 31;
}
inline int LightOfBatchBit(int b, int bit)
{
  return b * LightsPerBatch + bit;
}
inline int MasterTexelOfBatch(int b)
{
  return b >> 5;
}
inline int MasterBitOfBatch(int b)
{
  return b & 31;
}

struct TexelCoord
{
  int X = 0;
  int Y = 0;
};

struct ClusterTextureLayout
{
  int TilesX = 0, TilesY = 0, Slices = 0;
  int NumberOfLights = 0;
  int Batches = 0;      ///< B = ceil(N / 32)
  int BatchRows = 0;    ///< R: batch blocks per column
  int BatchColumns = 0; ///< ceil(B / R)
  int ListWidth = 0, ListHeight = 0;
  int MasterTexelsPerCluster = 0; ///< M = ceil(B / 32)
  int MasterWidth = 0, MasterHeight = 0;

  TexelCoord ListTexel(int tx, int ty, int s, int b) const
  {
    TexelCoord t;
    t.X = (b / this->BatchRows) * this->TilesX * this->Slices + s * this->TilesX + tx;
    t.Y = (b % this->BatchRows) * this->TilesY + ty;
    return t;
  }
  TexelCoord MasterTexel(int tx, int ty, int s, int m) const
  {
    TexelCoord t;
    t.X = s * this->TilesX + tx;
    t.Y = ty * this->MasterTexelsPerCluster + m;
    return t;
  }
  std::uint64_t GetListBytes() const
  {
    return static_cast<std::uint64_t>(this->ListWidth) * this->ListHeight * 4u;
  }
  std::uint64_t GetMasterBytes() const
  {
    return static_cast<std::uint64_t>(this->MasterWidth) * this->MasterHeight * 4u;
  }
};

/// Largest light count a grid can hold with textures of at most maxTextureSize texels.
inline std::int64_t ComputeMaximumNumberOfLights(
  int tilesX, int tilesY, int slices, int maxTextureSize)
{
  if (tilesX <= 0 || tilesY <= 0 || slices <= 0 || maxTextureSize <= 0)
  {
    return 0;
  }
  const std::int64_t rows = maxTextureSize / tilesY;
  const std::int64_t cols = maxTextureSize / (static_cast<std::int64_t>(tilesX) * slices);
  // list: rows * cols batches; master: Y * M <= max  ->  M <= rows, i.e. 32 * rows batches.
  // min(rows * cols, 32 * rows) = rows * min(cols, 32): no 64-bit overflow (rows * cols
  // * 32 overflowed for a 1x1x1 grid and maxTextureSize near INT_MAX).
  return rows * std::min<std::int64_t>(cols, BatchesPerMaster) * LightsPerBatch;
}

/**
 * Layout for n lights on the grid. Returns false with a message when the textures
 * would exceed maxTextureSize (the caller reports it; no light is silently dropped).
 */
inline bool ComputeLayout(int tilesX, int tilesY, int slices, int n, int maxTextureSize,
  ClusterTextureLayout& layout, std::string* error = nullptr)
{
  layout = ClusterTextureLayout();
  layout.TilesX = tilesX;
  layout.TilesY = tilesY;
  layout.Slices = slices;
  layout.NumberOfLights = n;
  if (tilesX <= 0 || tilesY <= 0 || slices <= 0 || n < 0)
  {
    if (error)
    {
      *error = "invalid grid or light count";
    }
    return false;
  }
  // In 64 bits: n + 31 overflows an int for n near INT_MAX.
  layout.Batches =
    static_cast<int>((static_cast<std::int64_t>(n) + LightsPerBatch - 1) / LightsPerBatch);
  layout.MasterTexelsPerCluster = (layout.Batches + BatchesPerMaster - 1) / BatchesPerMaster;
  const std::int64_t rowWidth = static_cast<std::int64_t>(tilesX) * slices;
  const std::int64_t maxRows = maxTextureSize / tilesY;
  const std::int64_t maxN = ComputeMaximumNumberOfLights(tilesX, tilesY, slices, maxTextureSize);
  if (rowWidth > maxTextureSize || maxRows < 1 || n > maxN)
  {
    if (error)
    {
      std::ostringstream os;
      os << "a " << tilesX << "x" << tilesY << "x" << slices << " cluster grid holds at most "
         << maxN << " lights with textures of at most " << maxTextureSize
         << " texels a side (requested " << n << "); use fewer tiles or slices";
      *error = os.str();
    }
    return false;
  }
  const int batches = std::max(layout.Batches, 1);
  layout.BatchRows = static_cast<int>(std::min<std::int64_t>(batches, maxRows));
  layout.BatchColumns = (batches + layout.BatchRows - 1) / layout.BatchRows;
  // Balance the columns so the last one is not nearly empty.
  layout.BatchRows = (batches + layout.BatchColumns - 1) / layout.BatchColumns;
  layout.ListWidth = static_cast<int>(rowWidth * layout.BatchColumns);
  layout.ListHeight = layout.BatchRows * tilesY;
  layout.MasterWidth = static_cast<int>(rowWidth);
  layout.MasterHeight = tilesY * std::max(layout.MasterTexelsPerCluster, 1);
  return true;
}

/**
 * The grid to use for n lights when tilesX x tilesY x slices cannot hold them: halves
 * one dimension at a time (the one whose halving holds the most lights; on a tie the
 * largest) until the grid holds n lights. Returns false, with the grid at 1 x 1 x 1,
 * when no grid does. A grid that already holds n lights is returned unchanged.
 */
inline bool ChooseGridForLights(
  int& tilesX, int& tilesY, int& slices, std::int64_t n, int maxTextureSize)
{
  int* dims[3] = { &tilesX, &slices, &tilesY };
  while (ComputeMaximumNumberOfLights(tilesX, tilesY, slices, maxTextureSize) < n ||
    static_cast<std::int64_t>(tilesX) * slices > maxTextureSize || tilesY > maxTextureSize)
  {
    int best = -1;
    std::int64_t bestCapacity = -1;
    for (int d = 0; d < 3; ++d)
    {
      if (*dims[d] <= 1)
      {
        continue;
      }
      const int kept = *dims[d];
      *dims[d] = (kept + 1) / 2;
      const std::int64_t capacity =
        ComputeMaximumNumberOfLights(tilesX, tilesY, slices, maxTextureSize);
      *dims[d] = kept;
      if (capacity > bestCapacity || (capacity == bestCapacity && kept > *dims[best]))
      {
        best = d;
        bestCapacity = capacity;
      }
    }
    if (best < 0)
    {
      return false;
    }
    *dims[best] = (*dims[best] + 1) / 2;
  }
  return true;
}

} // namespace vtkClusteredLighting

#endif
