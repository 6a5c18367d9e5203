// SPDX-License-Identifier: BSD-3-Clause
// Fuzz-style robustness tests of the GL-free core: random and hostile input (NaN, Inf,
// 1e300, 1e-300, negative values, zero / NaN / huge / non-VTK projection matrices,
// near = far, near <= 0, far < near, 1x1 and huge viewports, huge grids and light
// counts) through every entry point the pass uses. Each test runs a fixed number of
// iterations from a fixed seed, so a failure is reproducible; the message names the
// iteration. Properties checked:
//  - no crash, and no undefined behaviour (the suite also runs under ASan + UBSan with
//    -fno-sanitize-recover, see scripts/run-sanitizers.sh);
//  - every light is either prepared or rejected with a message, and what is prepared is
//    finite, including the 32-bit floats uploaded to the GPU;
//  - bounds are never NaN; tile, slice, texel and light indices are always in range;
//  - the reference assigner and the texture comparison agree with each other.
// The pass sanitizes the camera depth range with SanitizeDepthRange before it builds a
// grid, so the grid functions get sanitized near/far; the raw near/far values still go
// into the projection matrices, and ComputeSliceIndex / SanitizeDepthRange get them raw.
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingLayout.h"
#include "vtkClusteredLightingLights.h"
#include "vtkClusteredLightingMorton.h"
#include "vtkClusteredLightingReference.h"
#include "vtkClusteredLightingSphereBounds.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

using namespace vtkClusteredLighting;

namespace
{
constexpr double Inf = std::numeric_limits<double>::infinity();

/// Random values, a third of them hostile. Deterministic for a given seed (libstdc++).
class HostileGenerator
{
public:
  explicit HostileGenerator(std::uint64_t seed)
    : Engine(seed)
  {
  }

  bool Chance(double p)
  {
    return std::uniform_real_distribution<double>(0.0, 1.0)(this->Engine) < p;
  }
  int Pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(this->Engine); }
  double Uniform(double lo, double hi)
  {
    return std::uniform_real_distribution<double>(lo, hi)(this->Engine);
  }

  /// Any double: ordinary, or one of the values that break naive code.
  double Real()
  {
    static const double special[] = { std::nan(""), Inf, -Inf, 1e300, -1e300, 1e-300, -1e-300, 0.0,
      -0.0, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
      std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(), 3.5e38,
      -3.5e38, 1e38, 1e-38, 1e-45, 1.0, -1.0, 1e-9, 1e9 };
    switch (this->Pick(4))
    {
      case 0:
        return special[this->Pick(static_cast<int>(sizeof(special) / sizeof(special[0])))];
      case 1:
        return this->Uniform(-1e6, 1e6);
      default:
        return this->Uniform(-10.0, 10.0);
    }
  }
  /// Mostly ordinary non-negative values, sometimes hostile.
  double NonNegative() { return this->Chance(0.7) ? this->Uniform(0.0, 4.0) : this->Real(); }
  glm::dvec3 Vec3() { return glm::dvec3(this->Real(), this->Real(), this->Real()); }

  /// Any int: small, zero, negative or huge.
  int Int(int typicalMax)
  {
    static const int special[] = { 0, -1, 1, 2, std::numeric_limits<int>::max(),
      std::numeric_limits<int>::min(), std::numeric_limits<int>::max() - 1, 1 << 16, 1 << 20, 16384,
      16385, 32768, -65536 };
    if (this->Chance(0.7))
    {
      return std::uniform_int_distribution<int>(1, typicalMax)(this->Engine);
    }
    return special[this->Pick(static_cast<int>(sizeof(special) / sizeof(special[0])))];
  }

  /// A light as a user could describe it, from sensible to absurd.
  LightSource Light()
  {
    LightSource l;
    const bool hostile = this->Chance(0.4);
    l.PositionWC = hostile && this->Chance(0.3)
      ? this->Vec3()
      : glm::dvec3(this->Uniform(-20, 20), this->Uniform(-20, 20), this->Uniform(-20, 20));
    l.Color = hostile && this->Chance(0.3)
      ? this->Vec3()
      : glm::dvec3(this->Uniform(0, 1), this->Uniform(0, 1), this->Uniform(0, 1));
    l.Intensity = hostile && this->Chance(0.3) ? this->Real() : this->Uniform(0.0, 3.0);
    if (hostile && this->Chance(0.3))
    {
      l.Attenuation = this->Vec3();
    }
    else
    {
      l.Attenuation = glm::dvec3(this->NonNegative(), this->NonNegative(), this->NonNegative());
    }
    l.HasRadius = this->Chance(0.3);
    l.Radius = hostile ? this->Real() : this->Uniform(0.0, 10.0);
    if (this->Chance(0.4))
    {
      l.ConeAngle = hostile ? this->Real() : this->Uniform(0.0, 89.0);
      l.Exponent = hostile ? this->Real() : this->Uniform(0.0, 10.0);
      l.DirectionWC =
        hostile ? this->Vec3() : glm::dvec3(this->Uniform(-1, 1), this->Uniform(-1, 1), -1.0);
    }
    else if (hostile && this->Chance(0.4))
    {
      l.ConeAngle = this->Real(); // may still be >= 90: a point light
      l.Exponent = this->Real();  // unused by point lights
    }
    return l;
  }

  /// A VC -> clip matrix: VTK-like (perspective, off-axis, parallel, with hostile
  /// parameters including near = far, near <= 0 and far < near) or degenerate (zero, NaN,
  /// huge, random, general w row).
  glm::dmat4 Projection()
  {
    const double n = this->Chance(0.8) ? this->Uniform(1e-4, 10.0) : this->Real();
    const double f = this->Chance(0.8) ? n + this->Uniform(0.0, 1000.0) : this->Real();
    switch (this->Pick(10))
    {
      case 0:
      case 1:
      {
        const double fov = this->Chance(0.8) ? this->Uniform(1e-3, 179.99) : this->Real();
        const double aspect = this->Chance(0.8) ? this->Uniform(0.1, 10.0) : this->Real();
        const double t = n * std::tan(0.5 * fov * 3.14159265358979323846 / 180.0);
        const double w = t * aspect;
        const double cx = this->Chance(0.5) ? 0.0 : this->Uniform(-2.0, 2.0);
        const double cy = this->Chance(0.5) ? 0.0 : this->Uniform(-2.0, 2.0);
        return glm::frustum(-w + cx * w, w + cx * w, -t + cy * t, t + cy * t, n, f);
      }
      case 2:
      {
        const double s = this->Chance(0.8) ? this->Uniform(1e-3, 100.0) : this->Real();
        return glm::ortho(-s, s, -s, s, n, f);
      }
      case 3:
        return glm::frustum(-1.0, 1.0, -1.0, 1.0, n, n); // near = far
      case 4:
        return glm::dmat4(0.0);
      case 5:
        return glm::dmat4(std::nan(""));
      case 6:
        return glm::dmat4(this->Chance(0.5) ? 1e300 : -1e300);
      case 7:
      {
        glm::dmat4 m;
        for (int c = 0; c < 4; ++c)
        {
          for (int r = 0; r < 4; ++r)
          {
            m[c][r] = this->Real();
          }
        }
        return m;
      }
      case 8:
      {
        glm::dmat4 m = glm::frustum(-1.0, 1.0, -1.0, 1.0, 0.5, 50.0);
        m[0][3] = this->Real(); // w depends on x: not a form VTK produces
        return m;
      }
      default:
        return glm::dmat4(1.0);
    }
  }

  /// A world -> view matrix: rigid, scaled, singular or garbage.
  glm::dmat4 ViewMatrix()
  {
    switch (this->Pick(6))
    {
      case 0:
        return glm::dmat4(0.0);
      case 1:
        return glm::dmat4(std::nan(""));
      case 2:
      {
        glm::dmat4 m(this->Real());
        m[3][3] = 1.0;
        return m;
      }
      default:
      {
        const glm::dvec3 eye(
          this->Uniform(-30, 30), this->Uniform(-30, 30), this->Uniform(-30, 30));
        const glm::dvec3 at(this->Uniform(-5, 5), this->Uniform(-5, 5), this->Uniform(-5, 5));
        return glm::lookAt(eye, at, glm::dvec3(0.0, 1.0, 0.0));
      }
    }
  }

  /// A grid the pass could build (counts >= 1), from small to huge, with a hostile
  /// viewport and a depth range sanitized as the pass does. maxSlices bounds the slice
  /// count for functions whose output grows with it.
  ClusterGridParams Grid(int maxTiles, int maxSlices)
  {
    ClusterGridParams g;
    g.TilesX = std::clamp(this->Int(64), 1, maxTiles);
    g.TilesY = std::clamp(this->Int(64), 1, maxTiles);
    g.Slices = std::clamp(this->Int(64), 1, maxSlices);
    g.ViewportWidth = this->Chance(0.2) ? 1 : this->Int(4096);
    g.ViewportHeight = this->Chance(0.2) ? 1 : this->Int(4096);
    g.NearVC = this->Chance(0.7) ? this->Uniform(1e-4, 10.0) : this->Real();
    g.FarVC = this->Chance(0.7) ? g.NearVC + this->Uniform(0.0, 1000.0) : this->Real();
    SanitizeDepthRange(g.NearVC, g.FarVC);
    g.Scheme = this->Chance(0.5) ? SlicingScheme::Exponential : SlicingScheme::Linear;
    return g;
  }

private:
  std::mt19937_64 Engine;
};

/// The fixed seed of a test, or CLUSTERED_LIGHTING_FUZZ_SEED + it when that variable is set
/// (to explore more inputs locally; CI always uses the fixed seeds).
std::uint64_t Seed(std::uint64_t fixed)
{
  const char* env = std::getenv("CLUSTERED_LIGHTING_FUZZ_SEED");
  return env ? fixed + std::strtoull(env, nullptr, 10) : fixed;
}

bool IsFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Indices of a cluster range (when not empty) lie inside the grid.
::testing::AssertionResult InGrid(const ClusterRange& r, const ClusterGridParams& g)
{
  if (r.IsEmpty())
  {
    return ::testing::AssertionSuccess();
  }
  const int tiles[2] = { g.TilesX, g.TilesY };
  for (int a = 0; a < 2; ++a)
  {
    if (r.TileMin[a] < 0 || r.TileMax[a] >= tiles[a] || r.TileMin[a] > r.TileMax[a])
    {
      return ::testing::AssertionFailure() << "tile range " << r.TileMin[a] << ".." << r.TileMax[a]
                                           << " on axis " << a << " of " << tiles[a] << " tiles";
    }
  }
  if (r.SliceMin < 0 || r.SliceMax >= g.Slices)
  {
    return ::testing::AssertionFailure()
      << "slice range " << r.SliceMin << ".." << r.SliceMax << " of " << g.Slices << " slices";
  }
  return ::testing::AssertionSuccess();
}

/// Visible bounds are finite, inside NDC [-1, 1], ordered, and their depth range is not NaN.
::testing::AssertionResult WellFormed(const SphereScreenBounds& b)
{
  if (!b.Visible)
  {
    return ::testing::AssertionSuccess();
  }
  for (int a = 0; a < 2; ++a)
  {
    if (!(b.NDCMin[a] >= -1.0 && b.NDCMin[a] <= b.NDCMax[a] && b.NDCMax[a] <= 1.0))
    {
      return ::testing::AssertionFailure()
        << "NDC range " << b.NDCMin[a] << ".." << b.NDCMax[a] << " on axis " << a;
    }
  }
  if (std::isnan(b.DepthMin) || std::isnan(b.DepthMax) || b.DepthMin > b.DepthMax)
  {
    return ::testing::AssertionFailure()
      << "depth range " << b.DepthMin << ".." << b.DepthMax << " of a visible light";
  }
  return ::testing::AssertionSuccess();
}
} // namespace

TEST(Fuzz, PrepareLightsKeepsOrRejectsEveryLightAndPreparesOnlyFiniteData)
{
  HostileGenerator gen(Seed(0xC1u));
  for (int iteration = 0; iteration < 5000; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    std::vector<LightSource> sources(static_cast<std::size_t>(gen.Pick(40)));
    for (LightSource& l : sources)
    {
      l = gen.Light();
    }
    LightPreparationOptions options;
    options.Cutoff = gen.Chance(0.8) ? gen.Uniform(1e-9, 1.0) : gen.Real();
    options.MortonOrder = gen.Chance(0.7);
    const PreparedLights prepared = PrepareLights(sources, options);

    ASSERT_EQ(prepared.Lights.size() + prepared.Problems.size(), sources.size());
    std::vector<bool> seen(sources.size(), false);
    std::size_t alwaysOn = 0, below = 0, spots = 0;
    bool finiteSeen = false, spotSeen = false;
    std::size_t firstSpot = prepared.Lights.size();
    for (const PreparedLight& p : prepared.Lights)
    {
      ASSERT_LT(p.SourceIndex, sources.size());
      ASSERT_FALSE(seen[p.SourceIndex]) << "light " << p.SourceIndex << " prepared twice";
      seen[p.SourceIndex] = true;
      ASSERT_EQ(ValidateLightSource(sources[p.SourceIndex], "light"), "");
      ASSERT_TRUE(IsFinite(p.PositionWC));
      ASSERT_TRUE(IsFinite(p.Color) && p.Color.x >= 0 && p.Color.y >= 0 && p.Color.z >= 0)
        << "colour " << p.Color.x << " " << p.Color.y << " " << p.Color.z;
      ASSERT_TRUE(IsFinite(p.Attenuation) && p.Attenuation.x >= 0 && p.Attenuation.y >= 0 &&
        p.Attenuation.z >= 0 && (p.Attenuation.x + p.Attenuation.y + p.Attenuation.z) > 0);
      ASSERT_TRUE(std::isfinite(p.Exponent));
      ASSERT_FALSE(std::isnan(p.Radius));
      ASSERT_GE(p.Radius, 0.0);
      ASSERT_TRUE(p.CosCone == -2.0 || (p.CosCone >= -1.0 && p.CosCone <= 1.0)) << p.CosCone;
      ASSERT_TRUE(IsFinite(p.DirectionWC));
      const double len = glm::length(p.DirectionWC);
      ASSERT_TRUE(p.CosCone == -2.0 ? len == 0.0 : std::abs(len - 1.0) < 1e-9) << len;
      // In Morton order point lights come before spot lights (the shader walks the
      // lights below FirstSpot without the spot code), and always-on lights first among each.
      const bool spot = p.CosCone != -2.0;
      if (spot && !spotSeen)
      {
        firstSpot = static_cast<std::size_t>(&p - prepared.Lights.data());
        spotSeen = true;
        finiteSeen = false;
      }
      if (options.MortonOrder)
      {
        ASSERT_FALSE(spotSeen && !spot) << "point light after a spot light";
        ASSERT_FALSE(finiteSeen && std::isinf(p.Radius)) << "always-on light after a finite one";
      }
      finiteSeen = finiteSeen || !std::isinf(p.Radius);
      alwaysOn += std::isinf(p.Radius) ? 1 : 0;
      below += p.Radius == 0.0 ? 1 : 0;
      spots += p.CosCone != -2.0 ? 1 : 0;
    }
    EXPECT_EQ(prepared.NumberOfAlwaysOn, alwaysOn);
    EXPECT_EQ(prepared.NumberOfBelowCutoff, below);
    EXPECT_EQ(prepared.NumberOfSpots, spots);
    EXPECT_EQ(prepared.FirstSpot, firstSpot);
    for (const std::string& problem : prepared.Problems)
    {
      ASSERT_NE(problem.find("skipped"), std::string::npos) << problem;
    }
    // What the GPU gets is finite: a light that passes validation must fit in floats.
    const std::vector<float> packed = PackLightData(prepared.Lights);
    for (std::size_t k = 0; k < packed.size(); ++k)
    {
      ASSERT_TRUE(std::isfinite(packed[k]))
        << "GPU light record float " << k % FloatsPerLightRecord << " of light "
        << prepared.Lights[k / FloatsPerLightRecord].SourceIndex << " is " << packed[k];
    }
  }
}

TEST(Fuzz, SliceIndexIsInRangeForAnyDepthAndDepthRange)
{
  HostileGenerator gen(Seed(0xC2u));
  for (int iteration = 0; iteration < 100000; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    ClusterGridParams g;
    g.Slices = std::max(gen.Int(256), 1);
    g.NearVC = gen.Real(); // raw: not sanitized
    g.FarVC = gen.Real();
    g.Scheme = gen.Chance(0.5) ? SlicingScheme::Exponential : SlicingScheme::Linear;
    const double depth = gen.Real();
    const int s = ComputeSliceIndex(depth, g);
    ASSERT_GE(s, 0) << "depth " << depth << " near " << g.NearVC << " far " << g.FarVC;
    ASSERT_LT(s, g.Slices) << "depth " << depth << " near " << g.NearVC << " far " << g.FarVC;

    // Sanitized ranges are valid and give finite shader parameters (uploaded as floats).
    double n = g.NearVC, f = g.FarVC;
    SanitizeDepthRange(n, f);
    ASSERT_TRUE(std::isfinite(n) && std::isfinite(f) && n > 0.0 && f > n)
      << "raw " << g.NearVC << " " << g.FarVC << " sanitized " << n << " " << f;
    g.NearVC = n;
    g.FarVC = f;
    double p[4];
    ComputeSliceShaderParameters(g, p);
    for (double v : p)
    {
      ASSERT_TRUE(std::isfinite(static_cast<float>(v)))
        << "shader parameter " << v << " for near " << n << " far " << f;
    }
    const int sanitized = ComputeSliceIndex(depth, g);
    ASSERT_TRUE(sanitized >= 0 && sanitized < g.Slices);
    const int tiles = std::max(gen.Int(256), 1);
    const int t = ComputeTileIndex(gen.Real(), gen.Int(4096), tiles);
    ASSERT_TRUE(t >= 0 && t < tiles);
  }
}

TEST(Fuzz, SphereBoundsAndClusterRangesAreNeverNaNAndStayInTheGrid)
{
  HostileGenerator gen(Seed(0xC3u));
  std::vector<SliceTileRange> ranges;
  for (int iteration = 0; iteration < 100000; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    // Huge tile counts are fine here; slices stay <= 4096 because ComputeSliceTileRanges
    // appends one range per slice the light reaches (the pass allows 256).
    const ClusterGridParams g = gen.Grid(std::numeric_limits<int>::max(), 4096);
    const glm::dmat4 P = gen.Projection();
    const glm::dvec3 c = gen.Chance(0.6)
      ? glm::dvec3(gen.Uniform(-20, 20), gen.Uniform(-20, 20), gen.Uniform(-60, 5))
      : gen.Vec3();
    const double r = gen.Chance(0.6) ? gen.Uniform(0.0, 30.0) : gen.Real();
    const bool quad = gen.Chance(0.2);
    const SphereScreenBounds b = quad ? ComputeCenterDepthQuadBounds(c, r, P, g.NearVC, g.FarVC)
                                      : ComputeSphereScreenBounds(c, r, P, g.NearVC, g.FarVC);
    ASSERT_TRUE(WellFormed(b)) << "centre " << c.x << " " << c.y << " " << c.z << " radius " << r;
    ClusterRangePadding pad;
    if (gen.Chance(0.2))
    {
      pad.Pixels = gen.NonNegative();
      pad.RelativeDepth = gen.Chance(0.5) ? gen.Uniform(0.0, 1e-3) : gen.NonNegative();
    }
    ASSERT_TRUE(InGrid(ComputeClusterRange(b, g, pad), g));

    // Bounds that did not come from ComputeSphereScreenBounds at all.
    SphereScreenBounds junk;
    junk.Visible = true;
    junk.NDCMin = glm::dvec2(gen.Real(), gen.Real());
    junk.NDCMax = glm::dvec2(gen.Real(), gen.Real());
    junk.DepthMin = gen.Real();
    junk.DepthMax = gen.Real();
    ASSERT_TRUE(InGrid(ComputeClusterRange(junk, g, pad), g));

    ranges.clear();
    const int added = ComputeSliceTileRanges(c, r, P, g, ranges, quad, pad);
    ASSERT_EQ(added, static_cast<int>(ranges.size()));
    int lastSlice = -1;
    for (const SliceTileRange& sr : ranges)
    {
      ASSERT_GT(sr.Slice, lastSlice);
      ASSERT_LT(sr.Slice, g.Slices);
      lastSlice = sr.Slice;
      ClusterRange cr;
      for (int a = 0; a < 2; ++a)
      {
        cr.TileMin[a] = sr.TileMin[a];
        cr.TileMax[a] = sr.TileMax[a];
      }
      cr.SliceMin = cr.SliceMax = sr.Slice;
      ASSERT_FALSE(cr.IsEmpty());
      ASSERT_TRUE(InGrid(cr, g));
    }
  }
}

TEST(Fuzz, ViewDataQuadsAreFiniteAndIndexTheGrid)
{
  HostileGenerator gen(Seed(0xC4u));
  for (int iteration = 0; iteration < 4000; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    std::vector<LightSource> sources(static_cast<std::size_t>(gen.Pick(24)));
    for (LightSource& l : sources)
    {
      l = gen.Light();
    }
    const PreparedLights prepared = PrepareLights(sources, LightPreparationOptions());
    ViewParameters v;
    v.WCVC = gen.ViewMatrix();
    v.VCDC = gen.Projection();
    v.Grid = gen.Grid(256, 256);
    v.Bounds = gen.Chance(0.2) ? BoundsMethod::CenterDepthQuad : BoundsMethod::Tangent;
    const ViewData data = ComputeViewData(prepared.Lights, v);
    const std::size_t n = prepared.Lights.size();
    ASSERT_EQ(data.LightView.size(), n * FloatsPerLightRecord);
    ASSERT_EQ(data.Quads.size(), static_cast<std::size_t>(data.NumberOfQuads) * FloatsPerQuad);
    ASSERT_LE(data.NumberOfAssignedLights + data.NumberOfCulled, static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i)
    {
      const float* o = &data.LightView[i * FloatsPerLightRecord];
      ASSERT_FALSE(std::isnan(o[3])) << "radius of light " << i;
      ASSERT_GE(o[3], 0.0f);
      for (int k = 4; k < 8; ++k)
      {
        ASSERT_TRUE(std::isfinite(o[k])) << "spot axis of light " << i;
      }
    }
    std::vector<int> quadsOfLight(n, 0);
    for (int q = 0; q < data.NumberOfQuads; ++q)
    {
      const float* o = &data.Quads[static_cast<std::size_t>(q) * FloatsPerQuad];
      for (int k = 0; k < FloatsPerQuad; ++k)
      {
        ASSERT_TRUE(std::isfinite(o[k])) << "quad " << q;
      }
      ASSERT_TRUE(o[0] >= 0 && o[0] <= o[2] && o[2] < v.Grid.TilesX) << "quad " << q;
      ASSERT_TRUE(o[1] >= 0 && o[1] <= o[3] && o[3] < v.Grid.TilesY) << "quad " << q;
      ASSERT_TRUE(o[4] >= 0 && o[4] < v.Grid.Slices) << "quad " << q;
      ASSERT_TRUE(o[5] >= 0 && o[5] < static_cast<float>(n)) << "quad " << q;
      ++quadsOfLight[static_cast<std::size_t>(o[5])];
    }
    int assigned = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      assigned += quadsOfLight[i] > 0 ? 1 : 0;
      if (!(prepared.Lights[i].Radius > 0.0))
      {
        ASSERT_EQ(quadsOfLight[i], 0) << "light " << i << " with radius 0 got quads";
      }
    }
    ASSERT_EQ(assigned, data.NumberOfAssignedLights);
  }
}

TEST(Fuzz, LayoutFitsTheTextureOrReportsWhyNot)
{
  HostileGenerator gen(Seed(0xC5u));
  for (int iteration = 0; iteration < 100000; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    const int x = gen.Int(64), y = gen.Int(64), z = gen.Int(64);
    const int n = gen.Chance(0.5) ? gen.Int(100000) : gen.Int(1000);
    const int maxTexture = gen.Chance(0.8) ? 16384 : gen.Int(65536);
    ClusterTextureLayout L;
    std::string error;
    const bool ok = ComputeLayout(x, y, z, n, maxTexture, L, &error);
    const std::int64_t maxN = ComputeMaximumNumberOfLights(x, y, z, maxTexture);
    ASSERT_GE(maxN, 0);
    SCOPED_TRACE(::testing::Message() << "grid " << x << "x" << y << "x" << z << ", " << n
                                      << " lights, max texture " << maxTexture);
    if (!ok)
    {
      ASSERT_FALSE(error.empty());
      continue;
    }
    ASSERT_TRUE(x > 0 && y > 0 && z > 0 && n >= 0);
    ASSERT_LE(n, maxN);
    ASSERT_GE(static_cast<std::int64_t>(L.Batches) * LightsPerBatch, n);
    ASSERT_TRUE(L.ListWidth > 0 && L.ListWidth <= maxTexture);
    ASSERT_TRUE(L.ListHeight > 0 && L.ListHeight <= maxTexture);
    ASSERT_TRUE(L.MasterWidth > 0 && L.MasterWidth <= maxTexture);
    ASSERT_TRUE(L.MasterHeight > 0 && L.MasterHeight <= maxTexture);
    // Extreme and random (cluster, batch) pairs land inside the textures.
    for (int k = 0; k < 8; ++k)
    {
      const int tx = k & 1 ? x - 1 : gen.Pick(x);
      const int ty = k & 2 ? y - 1 : gen.Pick(y);
      const int s = k & 4 ? z - 1 : gen.Pick(z);
      const int b = L.Batches > 0 ? (k == 7 ? L.Batches - 1 : gen.Pick(L.Batches)) : 0;
      const TexelCoord t = L.ListTexel(tx, ty, s, b);
      ASSERT_TRUE(t.X >= 0 && t.X < L.ListWidth && t.Y >= 0 && t.Y < L.ListHeight);
      const TexelCoord m = L.MasterTexel(tx, ty, s, MasterTexelOfBatch(b));
      ASSERT_TRUE(m.X >= 0 && m.X < L.MasterWidth && m.Y >= 0 && m.Y < L.MasterHeight);
    }
  }
}

TEST(Fuzz, MortonOrderIsAPermutationForAnyPoints)
{
  HostileGenerator gen(Seed(0xC6u));
  for (int iteration = 0; iteration < 10000; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    std::vector<glm::dvec3> points(static_cast<std::size_t>(gen.Pick(64)));
    std::vector<std::uint8_t> group(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      points[i] = gen.Vec3();
      group[i] = static_cast<std::uint8_t>(gen.Pick(2));
    }
    const bool grouped = gen.Chance(0.5);
    const std::vector<std::uint32_t> order = ComputeMortonOrder(points, grouped ? &group : nullptr);
    ASSERT_EQ(order.size(), points.size());
    std::vector<bool> seen(points.size(), false);
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      ASSERT_LT(order[k], points.size());
      ASSERT_FALSE(seen[order[k]]);
      seen[order[k]] = true;
      if (grouped && k > 0)
      {
        ASSERT_LE(group[order[k - 1]], group[order[k]]);
      }
    }
    const double lo = gen.Real(), hi = gen.Real();
    ASSERT_LE(QuantizeMorton10(gen.Real(), lo, hi), 1023u);
  }
}

TEST(Fuzz, ReferenceAssignerAgreesWithItsOwnTextureEncoding)
{
  HostileGenerator gen(Seed(0xC7u));
  for (int iteration = 0; iteration < 1500; ++iteration)
  {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    const ClusterGridParams g = gen.Grid(6, 6);
    const glm::dmat4 P = gen.Projection();
    std::vector<ReferenceLight> lights(static_cast<std::size_t>(gen.Pick(70)));
    for (ReferenceLight& l : lights)
    {
      l.CenterVC = gen.Chance(0.6)
        ? glm::dvec3(gen.Uniform(-10, 10), gen.Uniform(-10, 10), gen.Uniform(-40, 5))
        : gen.Vec3();
      l.Radius = gen.Chance(0.6) ? gen.Uniform(0.0, 10.0) : gen.Real();
    }
    const ReferenceAssignment ref = ComputeReferenceAssignment(lights, g, P, g.NearVC, g.FarVC);
    const int n = static_cast<int>(lights.size());
    ASSERT_EQ(ref.Batches, (n + 31) / 32);
    ASSERT_EQ(ref.Words.size(), static_cast<std::size_t>(g.GetNumberOfClusters()) * ref.Batches);
    for (int i = 0; i < n; ++i)
    {
      if (!(lights[i].Radius > 0.0))
      {
        for (int id = 0; id < g.GetNumberOfClusters(); ++id)
        {
          ASSERT_FALSE(ref.Contains(id, i)) << "light " << i << " without radius is assigned";
        }
      }
    }
    // Encode the reference into list/master textures as the GPU lays them out: the
    // comparison must then find no difference at all.
    ClusterTextureLayout L;
    ASSERT_TRUE(ComputeLayout(g.TilesX, g.TilesY, g.Slices, n, 16384, L));
    std::vector<std::uint32_t> list(static_cast<std::size_t>(L.ListWidth) * L.ListHeight, 0u);
    std::vector<std::uint32_t> master(static_cast<std::size_t>(L.MasterWidth) * L.MasterHeight, 0u);
    for (int ty = 0; ty < g.TilesY; ++ty)
    {
      for (int tx = 0; tx < g.TilesX; ++tx)
      {
        for (int s = 0; s < g.Slices; ++s)
        {
          const int id = ComputeClusterId(tx, ty, s, g);
          for (int b = 0; b < L.Batches; ++b)
          {
            const std::uint32_t word = ref.Words[static_cast<std::size_t>(id) * ref.Batches + b];
            const TexelCoord t = L.ListTexel(tx, ty, s, b);
            list[static_cast<std::size_t>(t.Y) * L.ListWidth + t.X] = word;
            if (word)
            {
              const TexelCoord m = L.MasterTexel(tx, ty, s, MasterTexelOfBatch(b));
              master[static_cast<std::size_t>(m.Y) * L.MasterWidth + m.X] |= 1u
                << MasterBitOfBatch(b);
            }
          }
        }
      }
    }
    const AssignmentComparison cmp = CompareWithReference(ref, list, master, L, g);
    ASSERT_EQ(cmp.FalseNegatives, 0u);
    ASSERT_EQ(cmp.FalsePositives, 0u);
    ASSERT_EQ(cmp.MasterMismatches, 0u);
    ASSERT_EQ(cmp.GPUPairs, cmp.ReferencePairs);
  }
}

// Regression tests: the smallest inputs for each bug the fuzz tests above found in the
// core (each failed, crashed or was reported by UBSan before the fix).

TEST(FuzzRegression, LayoutBatchCountDoesNotOverflowForHugeLightCounts)
{
  // (n + 31) / 32 overflowed an int: the layout claimed success with -67,108,864 batches.
  const int n = std::numeric_limits<int>::max() - 1;
  ClusterTextureLayout L;
  ASSERT_TRUE(ComputeLayout(47, 60, 16, n, std::numeric_limits<int>::max(), L));
  EXPECT_EQ(static_cast<std::int64_t>(L.Batches), (static_cast<std::int64_t>(n) + 31) / 32);
  EXPECT_GT(L.ListHeight, 0);
}

TEST(FuzzRegression, MaximumLightCountDoesNotOverflowForHugeTextures)
{
  // rows * cols * 32 overflowed 64 bits for a 1x1x1 grid (UBSan: signed integer overflow).
  const std::int64_t rows = std::numeric_limits<int>::max();
  EXPECT_EQ(ComputeMaximumNumberOfLights(1, 1, 1, std::numeric_limits<int>::max()),
    rows * BatchesPerMaster * LightsPerBatch);
}

TEST(FuzzRegression, InfluenceRadiusOfHugeButValidLightsIsNotNaNOrZero)
{
  // a1^2 overflowed: the radius came out 0 instead of (K - a0) / a1.
  const double linear = ComputeInfluenceRadius(1e300, glm::dvec3(1.0, 1e200, 0.0), 1.0);
  EXPECT_NEAR(linear, (1e300 - 1.0) / 1e200, 1e-12 * 1e100);
  // 2 (K - a0) and 4 a2 (K - a0) overflowed: Inf / Inf = NaN.
  const double quadratic = ComputeInfluenceRadius(1e308, glm::dvec3(1.0, 0.0, 1e10), 1.0);
  EXPECT_NEAR(quadratic, std::sqrt((1e308 - 1.0) / 1e10), 1e-12 * 1e149);
}

TEST(FuzzRegression, HugeSpotDirectionIsNormalized)
{
  // glm::normalize((1e300, 0, 0)) is 0: its squared length overflows.
  LightSource spot;
  spot.Attenuation = glm::dvec3(1, 0, 1);
  spot.ConeAngle = 30.0;
  spot.DirectionWC = glm::dvec3(1e300, 0.0, -1e300);
  const PreparedLights p = PrepareLights({ spot }, LightPreparationOptions());
  ASSERT_EQ(p.Lights.size(), 1u);
  EXPECT_NEAR(p.Lights[0].DirectionWC.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(p.Lights[0].DirectionWC.z, -std::sqrt(0.5), 1e-15);
}

TEST(FuzzRegression, LightsBeyondTheFloatRangeAreRejectedWithAMessage)
{
  // These passed validation and reached the GPU as Inf (or an all-zero attenuation, 1/0).
  std::vector<LightSource> lights(6);
  for (LightSource& l : lights)
  {
    l.Attenuation = glm::dvec3(1, 0, 1);
  }
  lights[0].Color = glm::dvec3(1e200);
  lights[0].Intensity = 1e200; // product overflows even a double
  lights[1].Attenuation = glm::dvec3(1.0, 1e39, 0.0);
  lights[2].Attenuation = glm::dvec3(1e-40, 0.0, 1e-41);
  lights[3].ConeAngle = 20.0;
  lights[3].Exponent = 1e39;
  lights[4].Exponent = std::nan(""); // a point light: the exponent is unused, not an error
  const PreparedLights p = PrepareLights(lights, LightPreparationOptions());
  ASSERT_EQ(p.Problems.size(), 4u);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NE(p.Problems[i].find("light " + std::to_string(i)), std::string::npos);
    EXPECT_NE(p.Problems[i].find("32-bit floats"), std::string::npos) << p.Problems[i];
  }
  EXPECT_NE(p.Problems[3].find("exponent"), std::string::npos) << p.Problems[3];
  ASSERT_EQ(p.Lights.size(), 2u);
  for (float v : PackLightData(p.Lights))
  {
    EXPECT_TRUE(std::isfinite(v));
  }
}

TEST(FuzzRegression, NonFiniteCentresGiveNoNaNBounds)
{
  const glm::dmat4 P = glm::frustum(-1.0, 1.0, -1.0, 1.0, 0.5, 50.0);
  // A NaN centre depth (degenerate view matrix) made a visible light with a NaN depth range.
  EXPECT_FALSE(
    ComputeSphereScreenBounds(glm::dvec3(0, 0, std::nan("")), 2.0, P, 0.5, 50.0).Visible);
  EXPECT_FALSE(
    ComputeCenterDepthQuadBounds(glm::dvec3(0, 0, std::nan("")), 2.0, P, 0.5, 50.0).Visible);
  // Centre at depth Inf with an infinite radius: d - r was NaN in the centre-depth quad.
  const SphereScreenBounds b =
    ComputeCenterDepthQuadBounds(glm::dvec3(0, 0, -Inf), Inf, P, 0.5, 50.0);
  EXPECT_TRUE(b.Visible);
  EXPECT_EQ(b.DepthMin, 0.5);
  EXPECT_EQ(b.DepthMax, 50.0);
  // A NaN projection gave NaN NDC bounds in the centre-depth quad.
  const SphereScreenBounds q =
    ComputeCenterDepthQuadBounds(glm::dvec3(0, 0, -5), 1.0, glm::dmat4(std::nan("")), 0.5, 50.0);
  ASSERT_TRUE(q.Visible);
  EXPECT_EQ(q.NDCMin, glm::dvec2(-1.0));
  EXPECT_EQ(q.NDCMax, glm::dvec2(1.0));
}

TEST(FuzzRegression, DepthRangesAndSliceParametersFitInFloats)
{
  // far = 2 near overflowed to Inf for a huge near.
  double n = std::numeric_limits<double>::max(), f = std::nan("");
  SanitizeDepthRange(n, f);
  EXPECT_TRUE(std::isfinite(static_cast<float>(n)) && std::isfinite(static_cast<float>(f)));
  EXPECT_GT(f, n);
  // 1/near was 1e45, Inf as a float uniform.
  n = 1e-45;
  f = 0.44;
  SanitizeDepthRange(n, f);
  ClusterGridParams g;
  g.NearVC = n;
  g.FarVC = f;
  double p[4];
  ComputeSliceShaderParameters(g, p);
  EXPECT_TRUE(std::isfinite(static_cast<float>(p[0])));
  // far / near rounding to 1 gave Slices / log(1) = Inf.
  g.NearVC = 1.9999999999999998;
  g.FarVC = 2.0;
  ComputeSliceShaderParameters(g, p);
  EXPECT_TRUE(std::isfinite(static_cast<float>(p[1])));
  g.Scheme = SlicingScheme::Linear;
  g.NearVC = 1e-30;
  g.FarVC = 1e-30 * (1.0 + 1e-15);
  ComputeSliceShaderParameters(g, p);
  EXPECT_TRUE(std::isfinite(static_cast<float>(p[1])));
}
