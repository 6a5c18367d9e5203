//VTK::System::Dec
// SPDX-License-Identifier: BSD-3-Clause
// List pass: set this light's bit in every texel (cluster) of its quad whose cell the
// light's sphere can reach. Bits are OR-ed by glLogicOp(GL_OR) on the R32UI
// target, so overlapping writes are harmless and no carry can corrupt another light.
//
// Per-cluster culling (clCullClusters = 1): the cell of cluster (tx, ty, s) is the part
// of the frustum between NDC tile edges and slice depths; its view-space bounding box is
// spanned by the 8 corners (x and y are bilinear in NDC and depth). A light whose sphere
// misses the box, grown by a margin far above float error, cannot reach any fragment the
// shading pass puts in that cluster.
//
// Depth-aware clusters (CL_DEPTH_AWARE): the cell is cut to the depths the cluster's
// fragments really have (clClusterDepths, from the depth prepass,
// vtkClusteredLightingDepthBounds.h) and its tile to the screen rectangle they cover
// (clClusterRects); a cluster without fragments gets no light. The
// CPU has already shrunk each quad to the clusters whose intervals the light's depth
// extent overlaps (ShrinkToReachableClusters, vtkClusteredLightingAssignment.h), a subset
// of what this test rejects, so it only saves texels.
//
// Spot cones (clConeVSOutput.w > -1.5, the pass's SpotConeCulling): a spot light lights
// only its cone, so a cluster whose box's bounding ball lies outside the cone gets no bit
// (clSpotConeMayReach mirrors SpotConeMayReachBall, vtkClusteredLightingSpotBounds.h).
//CL_DEPTH_AWARE

uniform ivec4 clGrid;        // tilesX, tilesY, slices, batchRows
uniform int clCullClusters;  // 0: whole rectangle x slice range
uniform vec3 clProjectionX;  // (P00, P02, P03) of VC->clip; culling needs P01 = P10 = 0
uniform vec3 clProjectionY;  // (P11, P12, P13)
uniform vec2 clProjectionW;  // (P32, P33); P30 = P31 = 0
uniform vec4 clSlicing;      // ComputeSliceShaderParameters
uniform vec2 clDepthRange;   // camera near depth, deepest fragment (GetMaxFragmentDepth)
#ifdef CL_DEPTH_AWARE
uniform sampler2D clClusterDepths; // (lo, hi) per cluster, texel (s * X + tx, ty)
uniform sampler2D clClusterRects;  // NDC (x0, y0, x1, y1) per cluster, the same texel
#endif

flat in uint clBitVSOutput;
flat in vec4 clSphereVSOutput;
flat in vec4 clConeVSOutput;

out uvec4 clListOutput;

// Mirrors ComputeSliceBoundary (Rendering/Core/vtkClusteredLightingGrid.h); clSlicing.z is
// the slicing near depth.
float clSliceBoundary(int k)
{
  if (clSlicing.w == 0.0)
  {
    return clSlicing.z * exp(float(k) / clSlicing.y);
  }
  return clSlicing.z + float(k) / clSlicing.y;
}

// View-space coordinate on an axis (row = (Paa, Pa2, Pa3)) for an NDC value and depth.
float clUnproject(vec3 row, float ndc, float depth)
{
  float zVC = -depth;
  float w = clProjectionW.x * zVC + clProjectionW.y;
  return (ndc * w - row.y * zVC - row.z) / row.x;
}

// Whether the ball (centre, rho) may meet the cone at apex (unit axis cone.xyz,
// cos(cone angle) cone.w): D sin(phi - theta) = cos(theta) across - sin(theta) along is
// at most the distance to the cone, and every point of the cone has along >= 0. rho grows
// by SpotConeShaderSlack (4e-3) of the distance, twice the core's angular slack.
bool clSpotConeMayReach(vec3 apex, vec4 cone, vec3 centre, float rho)
{
  vec3 v = centre - apex;
  float along = dot(v, cone.xyz);
  float across = sqrt(max(dot(v, v) - along * along, 0.0));
  float sinCone = sqrt(max(1.0 - cone.w * cone.w, 0.0));
  float slack = rho + 4e-3 * length(v);
  return cone.w * across - sinCone * along <= slack && along >= -slack;
}

void main()
{
#ifdef CL_DEPTH_AWARE
  if (clCullClusters != 0)
#else
  if (clCullClusters != 0 && (clSphereVSOutput.w < 1e29 || clConeVSOutput.w > -1.5))
#endif
  {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int inBlock = texel.x % (clGrid.x * clGrid.z);
    int slice = inBlock / clGrid.x;
    int tx = inBlock - slice * clGrid.x;
    int ty = texel.y % clGrid.y;
    float z0 = slice == 0 ? clDepthRange.x : max(clSliceBoundary(slice), clDepthRange.x);
    float z1 = slice == clGrid.z - 1 ? clDepthRange.y : min(clSliceBoundary(slice + 1), clDepthRange.y);
#ifdef CL_DEPTH_AWARE
    // Slice edges in float may be off by a little: cut only where the recorded depths lie
    // inside the slice's own range widened by the same relative margin as below.
    vec2 recorded = texelFetch(clClusterDepths, ivec2(inBlock, ty), 0).xy;
    if (recorded.x > recorded.y)
    {
      discard; // no fragment in this cluster
    }
    z0 = max(z0, recorded.x);
    z1 = min(z1, recorded.y);
    if (z0 > z1 * (1.0 + 1e-4) + 1e-6)
    {
      discard; // the fragments of this tile lie in other slices
    }
    z1 = max(z1, z0);
#endif
    vec2 ndc0 = 2.0 * vec2(tx, ty) / vec2(clGrid.xy) - 1.0;
    vec2 ndc1 = 2.0 * vec2(tx + 1, ty + 1) / vec2(clGrid.xy) - 1.0;
#ifdef CL_DEPTH_AWARE
    vec4 rect = texelFetch(clClusterRects, ivec2(inBlock, ty), 0);
    ndc0 = max(ndc0, rect.xy);
    ndc1 = max(min(ndc1, rect.zw), ndc0);
#endif
    vec4 xs = vec4(clUnproject(clProjectionX, ndc0.x, z0), clUnproject(clProjectionX, ndc1.x, z0),
      clUnproject(clProjectionX, ndc0.x, z1), clUnproject(clProjectionX, ndc1.x, z1));
    vec4 ys = vec4(clUnproject(clProjectionY, ndc0.y, z0), clUnproject(clProjectionY, ndc1.y, z0),
      clUnproject(clProjectionY, ndc0.y, z1), clUnproject(clProjectionY, ndc1.y, z1));
    vec3 lo = vec3(min(min(xs.x, xs.y), min(xs.z, xs.w)), min(min(ys.x, ys.y), min(ys.z, ys.w)), -z1);
    vec3 hi = vec3(max(max(xs.x, xs.y), max(xs.z, xs.w)), max(max(ys.x, ys.y), max(ys.z, ys.w)), -z0);
    vec3 c = clSphereVSOutput.xyz;
    float margin = 1e-4 * (z1 + length(c)) + 1e-6;
    lo -= vec3(margin);
    hi += vec3(margin);
    vec3 outside = max(max(lo - c, c - hi), vec3(0.0));
    float r = clSphereVSOutput.w;
    if (dot(outside, outside) > r * r)
    {
      discard;
    }
    if (clConeVSOutput.w > -1.5 &&
      !clSpotConeMayReach(c, clConeVSOutput, 0.5 * (lo + hi), 0.5 * length(hi - lo)))
    {
      discard;
    }
  }
  clListOutput = uvec4(clBitVSOutput, 0u, 0u, 0u);
}
