// SPDX-License-Identifier: BSD-3-Clause
// Clustered lighting: declarations injected at //VTK::Light::Dec of the polydata
// fragment shader. Names mirror the GL-free core (Rendering/Core). Lines between
// //CL_IF(FLAG) and //CL_ENDIF are kept only for the variants that need them
// (vtkClusteredLightingShaderVariant), so each shader holds only its own code paths.

#ifdef GL_ARB_gpu_shader5
#define clFindLSB(v) findLSB(v)
#else
int clFindLSB(uint v)
{
  int n = 0;
  if ((v & 0xFFFFu) == 0u) { n += 16; v >>= 16; }
  if ((v & 0xFFu) == 0u) { n += 8; v >>= 8; }
  if ((v & 0xFu) == 0u) { n += 4; v >>= 4; }
  if ((v & 0x3u) == 0u) { n += 2; v >>= 2; }
  if ((v & 0x1u) == 0u) { n += 1; }
  return n;
}
#endif

// Light records: 2 RGBA32F texels per light (upload order = Morton order).
//  clLightData (uploaded when lights change): (color * intensity, exponent), (a0, a1, a2, cos(cone) or -2)
//  clLightView (uploaded when the view changes): (positionVC, culling radius),
//    (spot axis VC, explicit radius: the light model's own range, 1e30 when none)
uniform samplerBuffer clLightData;
uniform samplerBuffer clLightView;
//CL_IF(CLUSTERED)
uniform usampler2D clMaster;
uniform usampler2D clList;
uniform ivec4 clGrid;     // tilesX, tilesY, slices, batchRows
uniform mat4 clProjection; // VC -> clip of the current camera (VTK's VCDC)
uniform vec4 clSlicing;   // ComputeSliceShaderParameters
const int clMasterTexels = @CL_MASTER_TEXELS@;

// Mirrors vtkClusteredLighting::ComputeSliceIndex (Rendering/Core/vtkClusteredLightingGrid.h).
int clComputeSliceIndex(float depthVC)
{
//CL_IF(LINEAR_SLICES)
  float s = floor((depthVC - clSlicing.z) * clSlicing.y);
//CL_ELSE
  float s = depthVC * clSlicing.x > 1.0 ? floor(log(depthVC * clSlicing.x) * clSlicing.y) : 0.0;
//CL_ENDIF
  return int(clamp(s, 0.0, float(clGrid.z - 1)));
}

// Mirrors ComputeTileIndex for both axes (from the fragment's own projection, so it is
// independent of the viewport origin, tiled displays and offscreen peeling buffers),
// then ComputeSliceIndex.
ivec3 clComputeCluster(vec4 positionVC)
{
  vec4 clip = clProjection * positionVC;
  vec2 u = 0.5 * clip.xy / clip.w + 0.5;
  vec2 t = clamp(floor(u * vec2(clGrid.xy)), vec2(0.0), vec2(clGrid.xy - ivec2(1)));
  return ivec3(int(t.x), int(t.y), clComputeSliceIndex(-positionVC.z));
}

// Mirrors ClusterTextureLayout::ListTexel / MasterTexel.
// The column b / clGrid.w comes from a float division, corrected to the exact quotient:
// llvmpipe has no vector integer division and divides lane by lane, once per batch.
ivec2 clListTexel(ivec3 c, int b)
{
  int column = int((float(b) + 0.5) / float(clGrid.w));
  column -= column * clGrid.w > b ? 1 : 0;
  column += (column + 1) * clGrid.w <= b ? 1 : 0;
  int row = b - column * clGrid.w;
  return ivec2(column * clGrid.x * clGrid.z + c.z * clGrid.x + c.x, row * clGrid.y + c.y);
}

ivec2 clMasterTexel(ivec3 c, int m)
{
  return ivec2(c.z * clGrid.x + c.x, c.y * clMasterTexels + m);
}
//CL_IF(SPOT)
// The bits below n of a 32-bit word (none for n <= 0, all for n >= 32).
uint clBitsBelow(int n)
{
  return n >= 32 ? 0xffffffffu : (1u << uint(max(n, 0))) - 1u;
}

// The bits of the four master texels from batch `first` on (32 batches each) whose
// batches lie in [begin, end).
uvec4 clBatchMask(int first, int begin, int end)
{
  return uvec4(clBitsBelow(end - first) & ~clBitsBelow(begin - first),
    clBitsBelow(end - first - 32) & ~clBitsBelow(begin - first - 32),
    clBitsBelow(end - first - 64) & ~clBitsBelow(begin - first - 64),
    clBitsBelow(end - first - 96) & ~clBitsBelow(begin - first - 96));
}
//CL_ENDIF
//CL_ENDIF
//CL_IF(SATURATION)
// true where the draw's colour target clamps at 1 (fixed point) and the fragment is not
// blended as translucent: a saturated fragment stops walking its lights
uniform bool clClampsAtOne;
//CL_ENDIF
//CL_IF(BRUTE_FORCE)
uniform int clLightCount;
//CL_ENDIF
//CL_IF(SPOT)
// The first batch of 32 lights that holds a spot light (the pass orders them last): the
// lights below it are walked, and brute force evaluates them, without the spot code.
uniform int clSpotBatch;
//CL_ENDIF
//CL_IF(FAR_FIELD)
// The far field (Rendering/Core/vtkClusteredLightingFarField.h): per node of a world
// grid, the order-2 moments of the far light's directions, S, V and T (trace T = S), then
// the 9 fourth moments F400 .. F031 (FAR_ORDER4 reads them), RGB each, in 14 RGBA32F 3D
// textures (moment-major: S, Vx, Vy, Vz, Txx, Tyy, Txy, Txz, Tyz in the first 7, F after;
// PackFarFieldTexels); when the far-field lights share a colour, one channel in 5
// textures ((S, Vx, Vy, Vz), (Txx, Tyy, Txy, Txz), (Tyz, F400, F310, F220), (F130, F040,
// F301, F211), (F121, F031, 0, 0)) times that colour (PackFarFieldTexelsOneChannel).
uniform sampler3D clFarField0;
uniform sampler3D clFarField1;
uniform sampler3D clFarField2;
//CL_IF(FAR_SHARED_COLOR)
uniform vec3 clFarFieldColor; // the shared colour, largest component 1
//CL_IF(FAR_ORDER4)
uniform sampler3D clFarField3;
uniform sampler3D clFarField4;
//CL_ENDIF
//CL_ELSE
uniform sampler3D clFarField3;
uniform sampler3D clFarField4;
uniform sampler3D clFarField5;
uniform sampler3D clFarField6;
//CL_IF(FAR_ORDER4)
uniform sampler3D clFarField7;
uniform sampler3D clFarField8;
uniform sampler3D clFarField9;
uniform sampler3D clFarField10;
uniform sampler3D clFarField11;
uniform sampler3D clFarField12;
uniform sampler3D clFarField13;
//CL_ENDIF
//CL_ENDIF
uniform mat4 clFarFieldFromVC; // VC -> texture coordinates of the grid
uniform mat3 clWorldFromVC;    // VC -> world directions (the moments' axes)

// A^T T B per channel, T the moments' second-order tensor (Tzz = S - Txx - Tyy): mirrors
// ComputeMomentForm.
vec3 clMomentForm(vec3 A, vec3 B, vec3 S, vec3 Txx, vec3 Tyy, vec3 Txy, vec3 Txz, vec3 Tyz)
{
  return Txx * (A.x * B.x) + Tyy * (A.y * B.y) + (S - Txx - Tyy) * (A.z * B.z) +
    Txy * (A.x * B.y + A.y * B.x) + Txz * (A.x * B.z + A.z * B.x) + Tyz * (A.y * B.z + A.z * B.y);
}

//CL_IF(FAR_ORDER4)
// F(D) = sum g (D.u)^4 per channel from the 9 stored fourth moments F[0..8] (F400, F310,
// F220, F130, F040, F301, F211, F121, F031) and T, which gives the other six: mirrors
// ComputeFourthMomentForm.
vec3 clFourthMomentForm(vec3 D, vec3 S, vec3 Txx, vec3 Tyy, vec3 Txy, vec3 Txz, vec3 Tyz,
  vec3 F[9])
{
  vec3 xxzz = Txx - F[0] - F[2];
  vec3 xyzz = Txy - F[1] - F[3];
  vec3 yyzz = Tyy - F[2] - F[4];
  vec3 xzzz = Txz - F[5] - F[7];
  vec3 yzzz = Tyz - F[6] - F[8];
  vec3 zzzz = (S - Txx - Tyy) - xxzz - yyzz;
  float x = D.x, y = D.y, z = D.z;
  float x2 = x * x, y2 = y * y, z2 = z * z;
  return (x2 * x2) * F[0] + (4.0 * x2 * x * y) * F[1] + (6.0 * x2 * y2) * F[2] +
    (4.0 * x * y2 * y) * F[3] + (y2 * y2) * F[4] + (4.0 * x2 * x * z) * F[5] +
    (12.0 * x2 * y * z) * F[6] + (12.0 * x * y2 * z) * F[7] + (4.0 * y2 * y * z) * F[8] +
    (6.0 * x2 * z2) * xxzz + (12.0 * x * y * z2) * xyzz + (6.0 * y2 * z2) * yyzz +
    (4.0 * x * z2 * z) * xzzz + (4.0 * y * z2 * z) * yzzz + (z2 * z2) * zzzz;
}
//CL_ENDIF

// Mirrors vtkClusteredLighting::ApplyKernelToContractions for RGB: the kernel with
// Legendre coefficients k (ComputeLobeKernel gives k) applied to one direction D's
// contractions of the moments, VD = V.D and DTD = D^T T D (clMomentForm), clamped into the
// interval the moments prove the true value lies in (lobe: a Phong lobe of the given
// power, else the clamped cosine; the lobe's upper end by power as GetLobeUpperEnd). The
// callers contract each direction once and share it: the normal's serves the diffuse and
// the lobe's blend, the mirrored view's the zonal lobe and the projection.
vec3 clApplyFarKernel(vec3 k, vec3 S, vec3 VD, vec3 DTD, bool lobe, float power,
  out vec3 lower, out vec3 upper)
{
  vec3 estimate = k.x * S + k.y * VD + k.z * 0.5 * (3.0 * DTD - S);
  upper = min(0.5 * (VD + sqrt(max(S * DTD, vec3(0.0)))), 0.25 * (S + 2.0 * VD + DTD));
  lower = max(max(VD, vec3(0.0)), 0.5 * (VD + DTD));
  if (lobe)
  {
    // ComputeLobeQuadraticUpper: the least of ((t - c) / (1 - c))^2 over -1 <= c <= 0.
    vec3 c = mix(vec3(0.0), clamp((VD - DTD) / max(S - VD, vec3(1e-30)), -1.0, 0.0),
      greaterThan(S - VD, vec3(0.0)));
    vec3 quadratic = (DTD - 2.0 * c * VD + c * c * S) / ((1.0 - c) * (1.0 - c));
    upper = power >= 2.0 ? min(upper, min(DTD, quadratic)) : (power >= 1.0 ? upper : S);
    lower = vec3(0.0);
  }
  upper = max(upper, lower);
  return min(max(estimate, lower), upper);
}

uniform int clLightCount;         // for the exact far parts
uniform float clFarFieldTolerance; // see the far-field block of the shading code
//CL_IF(PHONG)
uniform bool clFarSumsOnBackFaces; // FarFieldExactSumsOnBackFaces
//CL_ENDIF

// Light i's far part at P when it is split (its exponent slot is negative): VTK's
// attenuation times (1 - window(d / near radius)), and a spot light's spot factor (its
// exponent e stored as -1 - e). Returns false for other lights and outside a cone.
bool clFarLight(int i, vec3 P, out vec3 L, out float att, out vec3 color)
{
  vec4 data0 = texelFetch(clLightData, 2 * i);
  if (!(data0.w < 0.0))
  {
    return false;
  }
  vec4 view0 = texelFetch(clLightView, 2 * i);
  vec3 toP = P - view0.xyz;
  float d = length(toP);
  L = d > 0.0 ? toP / d : vec3(0.0, 0.0, -1.0);
  vec4 data1 = texelFetch(clLightData, 2 * i + 1);
  float x2 = d * d / max(view0.w * view0.w, 1e-30);
  float window = clamp(1.0 - x2 * x2, 0.0, 1.0);
  att = (1.0 - window * window) / max(data1.x + data1.y * d + data1.z * d * d, 1e-30);
//CL_IF(SPOT)
  if (data1.w > -1.5)
  {
    float coneDot = dot(L, texelFetch(clLightView, 2 * i + 1).xyz);
    if (coneDot < data1.w)
    {
      return false;
    }
    att *= pow(coneDot, -1.0 - data0.w);
  }
//CL_ENDIF
  color = data0.rgb;
  return true;
}

// Mirrors ComputeLobeKernel(n): Legendre coefficients of max(0, t)^n.
vec3 clLobeKernel(float n)
{
  return vec3(0.5 / (n + 1.0), 1.5 / (n + 2.0), 2.5 * (1.5 / (n + 3.0) - 0.5 / (n + 1.0)));
}
//CL_IF(SPECULAR)
// The Phong far specular: VTK's lobe on the lit side only (N.L > 0), projected to order 2
// (Rendering/Core/vtkClusteredLightingLobeProjection.h). Its six coefficients for c = N.R
// and the power come from a 65 x 66 table (columns c in [-1, 1]; rows log2(1 + power) over
// [0, log2(129)], (k_S, k_XV, k_RV, k_XX) in rows 0 to 32, (k_RR, k_XR) 33 rows further),
// read texel by texel and interpolated bilinearly as LookupLobeProjection does.
uniform sampler2D clLobeTable;
vec4 clLobeTexel(ivec2 i, vec2 f, int row)
{
  return mix(mix(texelFetch(clLobeTable, i + ivec2(0, row), 0),
               texelFetch(clLobeTable, i + ivec2(1, row), 0), f.x),
    mix(texelFetch(clLobeTable, i + ivec2(0, row + 1), 0),
      texelFetch(clLobeTable, i + ivec2(1, row + 1), 0), f.x),
    f.y);
}
void clLobeProjection(float c, float power, out vec4 k0, out vec2 k1)
{
  vec2 f = vec2(clamp((c + 1.0) * 32.0, 0.0, 64.0),
    log2(1.0 + clamp(power, 0.0, 128.0)) / log2(129.0) * 32.0);
  ivec2 i = ivec2(min(floor(f), vec2(63.0, 31.0)));
  f -= vec2(i);
  k0 = clLobeTexel(i, f, 0);
  k1 = clLobeTexel(i, f, 33).xy;
}

// Mirrors ApplyFarLobe for world normal N and mirrored view R: the zonal lobe's estimate
// (clApplyFarKernel, clamped into the lobe's interval), moved toward the lit-side lobe's
// projection by the share of far light behind the surface (ComputeLobeBlend: the least
// light behind the moments allow, from the normal's contractions VN = V.N and NTN =
// N^T T N, against D, the far diffuse estimate), clamped again.
vec3 clApplyFarLobe(vec3 N, vec3 R, float power, vec3 D, vec3 VN, vec3 NTN, vec3 S, vec3 Vx,
  vec3 Vy, vec3 Vz, vec3 Txx, vec3 Tyy, vec3 Txy, vec3 Txz, vec3 Tyz, out vec3 lower,
  out vec3 upper)
{
  vec3 RV = Vx * R.x + Vy * R.y + Vz * R.z;
  vec3 RTR = clMomentForm(R, R, S, Txx, Tyy, Txy, Txz, Tyz);
  vec3 zonal = clApplyFarKernel(clLobeKernel(power), S, RV, RTR, true, power, lower, upper);
  float c = dot(N, R);
  vec3 w = N - c * R;
  float len = length(w);
  vec3 X = len > 1e-6 ? w / len : vec3(0.0);
  vec4 k0;
  vec2 k1;
  clLobeProjection(c, power, k0, k1);
  vec3 projected = k0.x * S + k0.y * (Vx * X.x + Vy * X.y + Vz * X.z) + k0.z * RV +
    k0.w * clMomentForm(X, X, S, Txx, Tyy, Txy, Txz, Tyz) + k1.x * RTR +
    k1.y * clMomentForm(X, R, S, Txx, Tyy, Txy, Txz, Tyz);
  vec3 back = max(max(-VN, vec3(0.0)), 0.5 * (NTN - VN));
  vec3 total = D + back;
  vec3 a = mix(vec3(0.0), min(back / max(0.1 * total, vec3(1e-30)), vec3(1.0)),
    greaterThan(total, vec3(0.0)));
  return min(max(zonal + a * (projected - zonal), lower), upper);
}
//CL_IF(FAR_SPECULAR_BINS)
// The far specular's bins (Rendering/Core/vtkClusteredLightingFarSpecularBins.h): per node
// and cell of directions the far light's sum S and direction sum V, in one RGBA32F 3D
// texture of the grid's size with the bins' slabs stacked along the grid's shallowest
// axis (PackFarSpecularBinTexels: with a shared colour one slab per bin, (S, Vx, Vy, Vz);
// else two, (S_r, S_g, S_b, 0) then (Vx, Vy, Vz, 0)).
uniform sampler3D clFarSpecularBins;
uniform int clFarSpecularAxis;    // the axis the slabs are stacked along
uniform float clFarSpecularDepth; // the grid's nodes along it, a slab's depth

// Mirrors ComputeNormalShare: the standard normal distribution's share below x.
float clNormalShare(float x)
{
  float z = abs(x) * 0.70710678;
  float t = 1.0 / (1.0 + 0.3275911 * z);
  float poly = t *
    (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  float tail = 0.5 * poly * exp(-z * z);
  return x >= 0.0 ? 1.0 - tail : tail;
}

// Mirrors EvaluateFarSpecularBinLobe: one bin's far specular per unit of its light S.
float clFarSpecularBinLobe(float S, vec3 V, vec3 N, vec3 R, float n)
{
  if (!(S > 0.0))
  {
    return 0.0;
  }
  float len = length(V);
  float rho = min(len / S, 0.9999);
  vec3 mu = len > 0.0 ? V / len : R;
  float kappa = rho * (3.0 - rho * rho) / (1.0 - rho * rho);
  float lambda = n + 1.0;
  vec3 w = kappa * mu + lambda * R;
  float m = length(w);
  float kappaTerm = kappa > 1e-3 ? kappa / (1.0 - exp(-2.0 * kappa)) : 0.5 + 0.5 * kappa;
  float mTerm = m > 1e-3 ? (1.0 - exp(-2.0 * m)) / m : 2.0 - 2.0 * m;
  float e = exp(m - kappa - lambda) * kappaTerm * mTerm;
  float na = m > 1e-3 ? dot(N, w) / m : 0.0;
  float mm = max(m, 1e-3);
  float sd = sqrt(max(1.0 - na * na, 1.0 / mm) / mm);
  return e * clNormalShare(na / sd);
}

// Mirrors GetFarSpecularBinReach: the least cosine between R and a bin's axis for which
// the bin is read (FarSpecularBinLobeFloor 1/4096, FarSpecularBinCellRadius 0.86285621).
float clFarSpecularBinReach(float n)
{
  float c = 1.0 + log(1.0 / 4096.0) / max(n, 1e-6);
  float angle = acos(clamp(c, -1.0, 1.0)) + acos(0.86285621);
  return angle >= 3.14159265 ? -1.0 : cos(angle);
}

// Mirrors GetFarSpecularBinAxis.
vec3 clFarSpecularBinAxis(int b)
{
  int i = b + (b >= 13 ? 1 : 0);
  return normalize(vec3(float(i / 9 - 1), float((i / 3) % 3 - 1), float(i % 3 - 1)));
}

// Mirrors EvaluateFarSpecularBins at the grid's texture coordinates uvw, for world N and R:
// a mask of the bins in reach (IsFarSpecularBinInReach; -0.50544947 is -sin of the cell's
// radius), then only those bins read, so a group of fragments loops as often as its
// fragments' most bins in reach (a masked-out texture read may still cost its time).
vec3 clFarSpecularFromBins(vec3 uvw, vec3 N, vec3 R, float n)
{
  // Within a slab: the coordinate along the axis clamped to its texel centres, so the
  // filter never mixes two slabs.
  float depth = clFarSpecularDepth;
  float z = clamp(uvw[clFarSpecularAxis] * depth, 0.5, depth - 0.5);
  vec3 c = uvw;
  vec3 sum = vec3(0.0);
  float reach = clFarSpecularBinReach(n);
  uint inReach = 0u;
  for (int b = 0; b < 26; ++b)
  {
    vec3 a = clFarSpecularBinAxis(b);
    if (dot(R, a) >= reach && dot(N, a) >= -0.50544947)
    {
      inReach |= 1u << uint(b);
    }
  }
  while (inReach != 0u)
  {
    int b = clFindLSB(inReach);
    inReach &= inReach - 1u;
//CL_IF(FAR_SHARED_COLOR)
    c[clFarSpecularAxis] = (z + float(b) * depth) / (26.0 * depth);
    vec4 t = texture(clFarSpecularBins, c);
    sum += t.x * clFarSpecularBinLobe(t.x, t.yzw, N, R, n) * clFarFieldColor;
//CL_ELSE
    c[clFarSpecularAxis] = (z + float(2 * b) * depth) / (52.0 * depth);
    vec4 s = texture(clFarSpecularBins, c);
    c[clFarSpecularAxis] = (z + float(2 * b + 1) * depth) / (52.0 * depth);
    vec4 v = texture(clFarSpecularBins, c);
    sum += s.rgb * clFarSpecularBinLobe(s.r + s.g + s.b, v.xyz, N, R, n);
//CL_ENDIF
  }
  return sum;
}
//CL_ENDIF
//CL_ENDIF
//CL_ENDIF
//CL_IF(HEAT_MAP)
uniform float clHeatMapMaximum;
vec3 clHeatColor(float t)
{
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)),
    0.0, 1.0) * (t > 0.0 ? 1.0 : 0.0);
}
//CL_ENDIF

// Distance test and the light model (VTK's attenuation and spot formula, cut at an
// explicit radius); returns false if the light does not reach P. L is the unit direction
// from the light to P (VTK's vertLightDirectionVC). Clustered shading also stops at the
// culling radius (where the light falls below the cutoff); brute force evaluates the
// light model alone. `spot` is a constant at every call: false where light i is known not
// to be a spot light (below clSpotBatch), which compiles the spot code away there.
bool clLightAttenuation(int i, vec3 P, bool spot, out vec3 L, out float att, out vec3 color)
{
  vec4 view0 = texelFetch(clLightView, 2 * i);
  vec3 toP = P - view0.xyz;
  float d = length(toP);
//CL_IF(CUTOFF)
  if (!(d < view0.w))
  {
    return false;
  }
//CL_ENDIF
//CL_IF(VIEW1)
  vec4 view1 = texelFetch(clLightView, 2 * i + 1);
//CL_ENDIF
//CL_IF(MODEL_RADIUS)
//CL_IF(BRUTE_FORCE)
  if (!(d < view1.w))
  {
    return false;
  }
//CL_ENDIF
//CL_ENDIF
  L = d > 0.0 ? toP / d : vec3(0.0, 0.0, -1.0);
  vec4 data0 = texelFetch(clLightData, 2 * i);
  vec4 data1 = texelFetch(clLightData, 2 * i + 1);
  att = 1.0 / max(data1.x + data1.y * d + data1.z * d * d, 1e-30);
//CL_IF(SPOT)
  if (spot && data1.w > -1.5)
  {
    float coneDot = dot(L, view1.xyz);
    if (coneDot < data1.w)
    {
      return false;
    }
    att *= pow(coneDot, data0.w < 0.0 ? -1.0 - data0.w : data0.w);
  }
//CL_ENDIF
//CL_IF(FAR_FIELD)
  // A light split into near and far parts (its exponent slot is negative, see clFarLight):
  // the near part is windowed at the near radius, the far field holds the rest.
  if (data0.w < 0.0)
  {
    float x2 = d * d / (view0.w * view0.w);
    float window = clamp(1.0 - x2 * x2, 0.0, 1.0);
    att *= window * window;
  }
//CL_ENDIF
//CL_IF(WINDOW)
  // (1 - (d/r)^4)^2 at the explicit radius; clustered shading windows lights without
  // one at their culling radius.
//CL_IF(MODEL_RADIUS)
//CL_IF(BRUTE_FORCE)
  float clWindowRadius = view1.w;
  if (clWindowRadius < 1e29)
//CL_ELSE
  float clWindowRadius = view1.w < 1e29 ? view1.w : view0.w;
//CL_ENDIF
//CL_ELSE
  float clWindowRadius = view0.w;
//CL_ENDIF
  {
    float x2 = d * d / (clWindowRadius * clWindowRadius);
    float window = clamp(1.0 - x2 * x2, 0.0, 1.0);
    att *= window * window;
  }
//CL_ENDIF
  color = data0.rgb;
  return true;
}

//CL_IF(PHONG)
// VTK's positional-light Phong terms (vtkOpenGLPolyDataMapper, lighting complexity 3).
bool clShadeLight(int i, bool spot, vec3 P, vec3 N, vec3 V, float power, inout vec3 diffuse,
  inout vec3 specular)
{
  vec3 L;
  float att;
  vec3 color;
  if (!clLightAttenuation(i, P, spot, L, att, color))
  {
    return false;
  }
  float df = max(0.0, att * dot(N, -L));
  diffuse += df * color;
//CL_IF(SPECULAR)
  float rv = max(0.0, dot(reflect(L, N), V));
  float sf = sign(df) * att * (rv > 0.0 ? pow(rv, power) : 0.0);
  specular += sf * color;
//CL_ENDIF
  return true;
}
//CL_ENDIF
//CL_IF(PBR)
// VTK's positional-light PBR terms (isotropic, vtkPBRFunctions.glsl) for the unit
// direction L from the fragment to the light: (diffuse + specular) * N.L.
vec3 clPbrTerms(vec3 L, vec3 N, vec3 V, float NdV, vec3 albedo, float roughness,
  float metallic, vec3 F0, vec3 F90)
{
  vec3 H = normalize(V + L);
  float NdL = clamp(dot(N, L), 1e-5, 1.0);
  float NdH = clamp(dot(N, H), 1e-5, 1.0);
  float HdL = clamp(dot(H, L), 1e-5, 1.0);
  vec3 F;
  vec3 spec = SpecularIsotropic(NdH, NdV, NdL, HdL, roughness, F0, F90, F);
  vec3 diff = (1.0 - metallic) * (1.0 - F) * DiffuseLambert(albedo);
  return (diff + spec) * NdL;
}

// VTK's positional-light PBR terms (isotropic, vtkPBRFunctions.glsl).
bool clShadeLight(int i, bool spot, vec3 P, vec3 N, vec3 V, float NdV, vec3 albedo, float roughness,
  float metallic, vec3 F0, vec3 F90, inout vec3 Lo)
{
  vec3 Lin;
  float att;
  vec3 color;
  if (!clLightAttenuation(i, P, spot, Lin, att, color))
  {
    return false;
  }
  Lo += color * att * clPbrTerms(-Lin, N, V, NdV, albedo, roughness, metallic, F0, F90);
  return true;
}
//CL_ENDIF

// The loops over every light. Mesa's llvmpipe ends a fragment shader after 65,535 loop
// iterations in all (one counter shared by every loop of the shader), silently, so brute
// force takes 16 lights per iteration, one call each, and so do the exact far sums past
// 16,384 lights (FAR_SUM_BLOCKS; ComputeFarPartsPerIteration). Below, the sums take one:
// llvmpipe never skips the body of an if (its lanes are masked) and tests a loop's exit
// at the end of an iteration, so every group of fragments runs a first iteration of the
// sums even where no fragment needs them, and 16 far parts there cost the bunny with
// 4,096 lights a tenth of its frame. A cluster's walk takes one light per iteration: its
// lists are short, and several per iteration made the bunny with 4,096 lights 40% slower
// on llvmpipe (each SIMD group of fragments runs the rounded-up count); the pass reports
// a list too long for the limit (docs/guide.md, "Limits").
//CL_IF(BRUTE_FORCE)
//CL_IF(PHONG)
// Brute force's light i, if there is one; counts (evaluated, reached).
void clBruteForceLight(int i, bool spot, vec3 P, vec3 N, vec3 V, float power,
  inout vec3 diffuse, inout vec3 specular, inout ivec2 counts)
{
  if (i < clLightCount)
  {
    bool hit = clShadeLight(i, spot, P, N, V, power, diffuse, specular);
    counts += ivec2(1, hit ? 1 : 0);
  }
}
//CL_ENDIF
//CL_IF(PBR)
// Brute force's light i, if there is one; counts (evaluated, reached).
void clBruteForceLight(int i, bool spot, vec3 P, vec3 N, vec3 V, float NdV, vec3 albedo,
  float roughness, float metallic, vec3 F0, vec3 F90, inout vec3 Lo, inout ivec2 counts)
{
  if (i < clLightCount)
  {
    bool hit = clShadeLight(i, spot, P, N, V, NdV, albedo, roughness, metallic, F0, F90, Lo);
    counts += ivec2(1, hit ? 1 : 0);
  }
}
//CL_ENDIF
//CL_ENDIF
//CL_IF(FAR_FIELD)
// The light k places after `start` in the stored order, wrapping around.
int clFarIndex(int k, int start)
{
  int i = start + k;
  return i >= clLightCount ? i - clLightCount : i;
}

//CL_IF(PBR)
// Mirrors ComputePbrSpecularBound: an upper end of VTK's isotropic specular times N.L over
// every light direction, per channel: D_GGX <= 1 / (pi a^4) (a the roughness),
// V_SmithCorrelated * N.L <= 0.5 / sqrt(a^2 + NdV^2 (1 - a^2)) (its second term dropped),
// F_Schlick <= max(F0, F90).
vec3 clPbrSpecularBound(float NdV, float roughness, vec3 F0, vec3 F90)
{
  float a2 = roughness * roughness;
  float dMax = 1.0 / (3.14159265 * max(a2 * a2, 1e-12));
  float vMax = 0.5 / sqrt(max(a2 + NdV * NdV * (1.0 - a2), 1e-12));
  return dMax * vMax * max(F0, F90);
}

// Adds the far part of the light k places after `start` (wrapping around), if there is
// one, with VTK's whole PBR terms (diffuse with the light's own Fresnel, and specular), and
// counts it.
void clAddFarPart(int k, int start, vec3 P, vec3 N, vec3 V, float NdV, vec3 albedo,
  float roughness, float metallic, vec3 F0, vec3 F90, inout vec3 Lo, inout int count)
{
  if (k < clLightCount)
  {
    vec3 Lin;
    float att;
    vec3 color;
    if (clFarLight(clFarIndex(k, start), P, Lin, att, color))
    {
      Lo += color * att * clPbrTerms(-Lin, N, V, NdV, albedo, roughness, metallic, F0, F90);
    }
    ++count;
  }
}
//CL_ELSE
// Adds the far part of the light k places after `start` (wrapping around), if there is
// one, to the sums (specular with Phong's power), and counts it.
void clAddFarPart(int k, int start, vec3 P, vec3 N, vec3 V, float power, inout vec3 diffuse,
  inout vec3 specular, inout int count)
{
  if (k < clLightCount)
  {
    vec3 L;
    float att;
    vec3 color;
    if (clFarLight(clFarIndex(k, start), P, L, att, color))
    {
      float df = max(0.0, att * dot(N, -L));
      diffuse += df * color;
//CL_IF(SPECULAR)
      float rv = max(0.0, dot(reflect(L, N), V));
      specular += sign(df) * att * (rv > 0.0 ? pow(rv, power) : 0.0) * color;
//CL_ENDIF
    }
    ++count;
  }
}
//CL_ENDIF
//CL_ENDIF
