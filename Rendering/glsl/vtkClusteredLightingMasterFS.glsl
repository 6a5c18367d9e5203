//VTK::System::Dec
// SPDX-License-Identifier: BSD-3-Clause
// Master pass: texel (x, ty * M + m) gets bit (b & 31) for every batch b in
// [32 m, min(32 m + 32, B)) whose list texel for this cluster is non-zero.
// Depth-aware clusters (CL_DEPTH_AWARE): a cluster without fragments has no light (the
// list pass gave it none), so its list texels are not read.
//CL_DEPTH_AWARE

uniform usampler2D clList;
uniform ivec4 clGrid;        // tilesX, tilesY, slices, batchRows
uniform int clBatches;       // B
uniform int clMasterTexels;  // M
#ifdef CL_DEPTH_AWARE
uniform sampler2D clClusterDepths; // (lo, hi) per cluster, texel (s * X + tx, ty)
#endif

out uvec4 clMasterOutput;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int ty = texel.y / clMasterTexels;
  int m = texel.y - ty * clMasterTexels;
  int rowWidth = clGrid.x * clGrid.z;
  uint mask = 0u;
#ifdef CL_DEPTH_AWARE
  vec2 recorded = texelFetch(clClusterDepths, ivec2(texel.x, ty), 0).xy;
  if (recorded.x > recorded.y)
  {
    clMasterOutput = uvec4(0u);
    return;
  }
#endif
  int last = min(32 * m + 32, clBatches);
  for (int b = 32 * m; b < last; ++b)
  {
    int column = b / clGrid.w;
    int row = b - column * clGrid.w;
    uint bits = texelFetch(clList, ivec2(column * rowWidth + texel.x, row * clGrid.y + ty), 0).r;
    if (bits != 0u)
    {
      mask |= 1u << uint(b & 31);
    }
  }
  clMasterOutput = uvec4(mask, 0u, 0u, 0u);
}
