//VTK::System::Dec
// SPDX-License-Identifier: BSD-3-Clause
// Master pass: texel (x, ty * M + m) gets bit (b & 31) for every batch b in
// [32 m, min(32 m + 32, B)) whose list texel for this cluster is non-zero.

uniform usampler2D clList;
uniform ivec4 clGrid;        // tilesX, tilesY, slices, batchRows
uniform int clBatches;       // B
uniform int clMasterTexels;  // M

out uvec4 clMasterOutput;

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int ty = texel.y / clMasterTexels;
  int m = texel.y - ty * clMasterTexels;
  int rowWidth = clGrid.x * clGrid.z;
  uint mask = 0u;
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
