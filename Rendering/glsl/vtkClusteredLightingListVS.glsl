//VTK::System::Dec
// SPDX-License-Identifier: BSD-3-Clause
// List pass: one instance per (light, depth slice) draws a quad over the tiles of that
// slice the light can reach. The tile rectangles were computed on the CPU in double
// precision (vtkClusteredLightingSphereBounds.h, ComputeSliceTileRanges) and arrive as
// integers in a float texture buffer (exact below 2^24):
//   texel 2q   : (tileMinX, tileMinY, tileMaxX, tileMaxY)
//   texel 2q+1 : (slice, lightIndex, cone, 0): cone is a spot light's cos(cone angle) when
//                the fragment shader tests its cone per cluster, -2 otherwise
// In a batch block the clusters of slice s start at column s * X (slice-major layout).

uniform samplerBuffer clQuads;
uniform samplerBuffer clLightView; // (positionVC, radius), (spot axis, explicit radius) per light
uniform ivec4 clGrid;       // tilesX, tilesY, slices, batchRows (vtkClusteredLightingLayout.h)
uniform vec2 clListSize;    // list texture size in texels

flat out uint clBitVSOutput;
flat out vec4 clSphereVSOutput; // light centre (VC) and radius
flat out vec4 clConeVSOutput;   // spot axis (VC) and cos(cone angle), or -2: no cone test

void main()
{
  vec4 tiles = texelFetch(clQuads, 2 * gl_InstanceID);
  vec4 record = texelFetch(clQuads, 2 * gl_InstanceID + 1);
  int slice = int(record.x);
  int light = int(record.y);
  int batch = light / 32;
  int column = batch / clGrid.w;
  int row = batch - column * clGrid.w;
  // corner of a triangle strip: (0,0) (1,0) (0,1) (1,1)
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  float x0 = float(column * clGrid.x * clGrid.z + slice * clGrid.x);
  vec2 lo = vec2(x0 + tiles.x, float(row * clGrid.y) + tiles.y);
  vec2 hi = vec2(x0 + tiles.z + 1.0, float(row * clGrid.y) + tiles.w + 1.0);
  vec2 texel = mix(lo, hi, corner);
  gl_Position = vec4(2.0 * texel / clListSize - 1.0, 0.0, 1.0);
  clBitVSOutput = 1u << uint(light & 31);
  clSphereVSOutput = texelFetch(clLightView, 2 * light);
  clConeVSOutput = vec4(texelFetch(clLightView, 2 * light + 1).xyz, record.z);
}
