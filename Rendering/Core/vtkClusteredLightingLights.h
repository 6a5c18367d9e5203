// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingLights.h
 * @brief GL-free light preparation: validation, influence radius, Morton order.
 *
 * Shading follows VTK 9.1's positional-light formulas exactly:
 *
 *   att(d)   = 1 / (a0 + a1 d + a2 d^2)
 *   spot     : att *= coneDot^exponent if coneDot >= cos(coneAngle), else 0
 *   diffuse  += max(0, att N.(-L)) * color * intensity
 *   specular += sign(df) att max(0, reflect(L, N).V)^power * color * intensity
 *
 * att never reaches 0, so clustering needs a finite influence radius. With
 * peak = intensity * max(color) and a cutoff eps (the contribution below which a light
 * is ignored), the radius solves  peak * att(r) = eps,  i.e.
 *
 *   a2 r^2 + a1 r + a0 = peak / eps  ->  r = 2 (K - a0) / (a1 + sqrt(a1^2 + 4 a2 (K - a0)))
 *
 * with K = peak / eps (this form is stable when a2 -> 0). Then:
 *  - a1 = a2 = 0 (VTK's default attenuation (1,0,0)) gives r = infinity: the light is an
 *    "always-on" light, assigned to every cluster and never dropped;
 *  - a0 >= K means the light is below the cutoff everywhere: r = 0 (it is still kept in
 *    the light buffer so that the brute-force reference evaluates it);
 *  - an explicit radius caps the derived one: r = min(explicit, derived).
 * The cutoff is per light and per channel for a white material with Diffuse = 1;
 * material coefficients scale it (Diffuse + Specular <= 1 keeps the bound).
 *
 * Invalid input (non-finite or negative values, attenuation that is negative, non-finite
 * or all zero, a spot without a direction or with a cone angle of -90 or less, values the
 * GPU's 32-bit floats cannot hold, positions included) is
 * reported per light with a message naming it; such a light is skipped and no other
 * light is affected.
 */
#ifndef vtkClusteredLightingLights_h
#define vtkClusteredLightingLights_h

#include "vtkClusteredLightingMorton.h"

#include <algorithm> // for std::max
#include <cmath>     // for std::isfinite
#include <cstdint>
#include <functional> // for std::function
#include <glm/glm.hpp>
#include <limits>  // for std::numeric_limits
#include <sstream> // for std::ostringstream
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace vtkClusteredLighting
{

/// One light as the user describes it (world coordinates, VTK conventions).
struct LightSource
{
  glm::dvec3 PositionWC = glm::dvec3(0.0);
  glm::dvec3 Color = glm::dvec3(1.0); ///< VTK's DiffuseColor
  double Intensity = 1.0;
  glm::dvec3 Attenuation = glm::dvec3(1.0, 0.0, 0.0); ///< (constant, linear, quadratic)
  double Radius = 0.0;                                ///< used only when HasRadius
  bool HasRadius = false;
  glm::dvec3 DirectionWC = glm::dvec3(0.0, 0.0, -1.0); ///< spot axis (need not be unit)
  double ConeAngle = 180.0; ///< half angle in degrees; < 90 makes a spot light (as VTK;
                            ///< a negative angle in (-90, 0) lights as |angle| does)
  double Exponent = 1.0;

  bool IsSpot() const { return this->ConeAngle < 90.0; }
};

/// A validated light ready for upload (sorted order).
struct PreparedLight
{
  glm::dvec3 PositionWC;
  double Radius;    ///< 0: below the cutoff everywhere; +inf: always on
  glm::dvec3 Color; ///< color * intensity
  double Exponent;
  glm::dvec3 Attenuation;
  double CosCone;            ///< cos(coneAngle) for spots, -2 for point lights
  glm::dvec3 DirectionWC;    ///< unit spot axis (0 for point lights)
  std::uint32_t SourceIndex; ///< index into the LightSource array
  double ExplicitRadius;     ///< the user's radius cap (+inf when none)
  /// Split at Radius into a windowed near part and a far part that the far field holds
  /// (vtkClusteredLightingFarField.h); set by PlanFarField.
  bool FarField = false;

  bool IsSpot() const { return this->CosCone > -1.5; }
  /// Its brightest channel of Color: the level its cutoff and radii are measured by.
  double GetPeak() const { return std::max(this->Color.x, std::max(this->Color.y, this->Color.z)); }
};

struct LightPreparationOptions
{
  double Cutoff = 1.0 / 1024.0;
  bool MortonOrder = true;
  /// > 0: the cutoff of the lights a far field may split (no explicit radius:
  /// IsFarFieldLight once prepared), whose error a budget holds apart from the
  /// culled lights' tails (vtkClusteredLightingFarFieldBudget.h); 0: Cutoff for every light.
  double FarFieldCutoff = 0.0;

  /// The cutoff the lights a far field may split take: FarFieldCutoff when set, else Cutoff.
  double GetFarFieldCutoff() const
  {
    return this->FarFieldCutoff > 0.0 ? this->FarFieldCutoff : this->Cutoff;
  }
};

struct PreparedLights
{
  std::vector<PreparedLight> Lights;
  std::vector<std::string> Problems; ///< one message per skipped light
  std::size_t NumberOfAlwaysOn = 0;
  std::size_t NumberOfBelowCutoff = 0;
  std::size_t NumberOfSpots = 0;
  std::size_t NumberOfExplicitRadius = 0; ///< lights whose model has its own range
  /// Index in Lights of the first spot light (Lights.size() when none). With MortonOrder
  /// the spot lights come last, so the lights before it need no spot code in the shader
  /// (the walk's batches below FirstSpot / 32 run without it).
  std::size_t FirstSpot = 0;
};

/// Attenuation exactly as VTK's shader computes it.
inline double EvaluateAttenuation(double d, const glm::dvec3& att)
{
  return 1.0 / (att.x + att.y * d + att.z * d * d);
}

/**
 * Distance where peak * att(d) falls to cutoff. +inf when the light never falls off,
 * 0 when it never exceeds the cutoff. Inputs must be valid (see ValidateLightSource).
 */
inline double ComputeInfluenceRadius(double peak, const glm::dvec3& att, double cutoff)
{
  if (!(peak > 0.0))
  {
    return 0.0;
  }
  if (!(cutoff > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  const double k = peak / cutoff;
  if (!std::isfinite(k))
  {
    return std::numeric_limits<double>::infinity();
  }
  const double excess = k - att.x;
  if (!(excess > 0.0))
  {
    return 0.0;
  }
  if (att.y == 0.0 && att.z == 0.0)
  {
    return std::numeric_limits<double>::infinity();
  }
  // 2 e / (a1 + sqrt(a1^2 + 4 a2 e)) written so that no intermediate overflows: a1^2,
  // 4 a2 e and 2 e overflow for huge but finite input, which gave Inf/Inf = NaN (or a
  // radius of 0). A result beyond the double range is +inf: the light is always on.
  const double root = std::hypot(att.y, 2.0 * std::sqrt(att.z) * std::sqrt(excess));
  return excess / (0.5 * att.y + 0.5 * root);
}

namespace Detail
{
inline bool IsFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
/// Whether every component survives the conversion to the GPU's 32-bit floats (|v| <=
/// FLT_MAX; larger values become Inf there, and Inf times 0 is NaN in the shader).
inline bool FitsInFloat(const glm::dvec3& v)
{
  const double m = static_cast<double>(std::numeric_limits<float>::max());
  return std::abs(v.x) <= m && std::abs(v.y) <= m && std::abs(v.z) <= m;
}
/// The largest |component| of v (0 only for the zero vector, even where |v|^2 underflows).
inline double LargestMagnitude(const glm::dvec3& v)
{
  return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
}
inline std::string ToString(const glm::dvec3& v)
{
  std::ostringstream os;
  os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return os.str();
}
} // namespace Detail

/// Empty string when the light is valid, else a message naming the light (who) and the
/// problem.
inline std::string ValidateLightSource(const LightSource& l, const std::string& who)
{
  std::ostringstream os;
  if (!Detail::IsFinite(l.PositionWC))
  {
    os << who << ": position " << Detail::ToString(l.PositionWC) << " is not finite";
  }
  else if (!Detail::FitsInFloat(l.PositionWC))
  {
    // The far field's region, grid and groups would take it in, and the GPU would see Inf.
    os << who << ": position " << Detail::ToString(l.PositionWC)
       << " is outside the range of the GPU's 32-bit floats (magnitudes above 3.4e38 become Inf)";
  }
  else if (!Detail::IsFinite(l.Color))
  {
    os << who << ": color " << Detail::ToString(l.Color) << " is not finite";
  }
  else if (l.Color.x < 0.0 || l.Color.y < 0.0 || l.Color.z < 0.0)
  {
    os << who << ": color " << Detail::ToString(l.Color) << " is negative";
  }
  else if (!std::isfinite(l.Intensity))
  {
    os << who << ": intensity " << l.Intensity << " is not finite";
  }
  else if (l.Intensity < 0.0)
  {
    os << who << ": intensity " << l.Intensity << " is negative";
  }
  else if (!Detail::IsFinite(l.Attenuation) || l.Attenuation.x < 0.0 || l.Attenuation.y < 0.0 ||
    l.Attenuation.z < 0.0 ||
    (l.Attenuation.x == 0.0 && l.Attenuation.y == 0.0 && l.Attenuation.z == 0.0))
  {
    os << who << ": attenuation " << Detail::ToString(l.Attenuation)
       << " is invalid (coefficients must be finite, non-negative and not all zero; "
          "otherwise 1/(a0 + a1 d + a2 d^2) is infinite or negative)";
  }
  else if (l.HasRadius && !(l.Radius >= 0.0))
  {
    os << who << ": radius " << l.Radius << " is negative or NaN";
  }
  else if (!Detail::FitsInFloat(l.Color * l.Intensity) || !Detail::FitsInFloat(l.Attenuation) ||
    std::max(l.Attenuation.x, std::max(l.Attenuation.y, l.Attenuation.z)) <
      static_cast<double>(std::numeric_limits<float>::min()))
  {
    os << who << ": color x intensity " << Detail::ToString(l.Color * l.Intensity)
       << " or attenuation " << Detail::ToString(l.Attenuation)
       << " is outside the range of the GPU's 32-bit floats (magnitudes above 3.4e38 become "
          "Inf, an attenuation whose coefficients are all below 1.2e-38 becomes 0)";
  }
  else if (l.HasRadius && std::isinf(l.Radius))
  {
    os << who << ": radius is infinite (unset the radius to derive it from the attenuation)";
  }
  else if (l.IsSpot())
  {
    if (!std::isfinite(l.ConeAngle) || !std::isfinite(l.Exponent) || l.Exponent < 0.0 ||
      l.Exponent > static_cast<double>(std::numeric_limits<float>::max()))
    {
      os << who << ": spot cone angle " << l.ConeAngle << " or exponent " << l.Exponent
         << " is invalid";
    }
    else if (l.ConeAngle <= -90.0)
    {
      // VTK's shader tests the cone with cos(angle), which is even in the angle: a cone of
      // -30 degrees lights what 30 does, and the pass takes |angle| above -90. From -90 on
      // the cone's cosine is <= 0 and VTK raises negative cosines to the exponent, which
      // GLSL leaves undefined.
      os << who << ": spot cone angle " << l.ConeAngle
         << " is -90 or less (VTK's own shading of it is undefined)";
    }
    else if (!Detail::IsFinite(l.DirectionWC) || !(Detail::LargestMagnitude(l.DirectionWC) > 0.0))
    {
      os << who << ": spot direction " << Detail::ToString(l.DirectionWC)
         << " is zero or not finite";
    }
  }
  else if (std::isnan(l.ConeAngle))
  {
    os << who << ": cone angle is NaN";
  }
  std::string msg = os.str();
  if (!msg.empty())
  {
    msg += "; the light is skipped";
  }
  return msg;
}

/// Validates, derives radii (at options.Cutoff, or FarFieldCutoff for the lights a far field
/// may split when it is set) and sorts: point lights before spot lights, always-on lights
/// first among each, then Morton order (with options.MortonOrder; else the input order).
/// nameOf(i) names source i in messages (default: "light i").
inline PreparedLights PrepareLights(const std::vector<LightSource>& sources,
  const LightPreparationOptions& options,
  const std::function<std::string(std::size_t)>& nameOf = nullptr)
{
  PreparedLights out;
  std::vector<PreparedLight> valid;
  valid.reserve(sources.size());
  for (std::size_t i = 0; i < sources.size(); ++i)
  {
    const LightSource& s = sources[i];
    std::string problem =
      ValidateLightSource(s, nameOf ? nameOf(i) : std::string("light ") + std::to_string(i));
    if (!problem.empty())
    {
      out.Problems.push_back(std::move(problem));
      continue;
    }
    PreparedLight p;
    p.PositionWC = s.PositionWC;
    p.Color = s.Color * s.Intensity;
    const double peak = p.GetPeak();
    const bool splittable = !s.HasRadius;
    double r = ComputeInfluenceRadius(
      peak, s.Attenuation, splittable ? options.GetFarFieldCutoff() : options.Cutoff);
    if (s.HasRadius)
    {
      r = std::min(r, s.Radius);
    }
    p.Radius = r;
    p.ExplicitRadius = s.HasRadius ? s.Radius : std::numeric_limits<double>::infinity();
    p.Exponent = s.IsSpot() ? s.Exponent : 1.0; // unused by point lights: never upload NaN
    p.Attenuation = s.Attenuation;
    if (s.IsSpot())
    {
      // |angle|: VTK's cone test takes its cosine, so -30 lights what 30 does (below -90
      // the light was rejected above).
      const double halfAngle = std::abs(s.ConeAngle) * (3.14159265358979323846 / 180.0);
      p.CosCone = std::cos(halfAngle);
      // Scaled first: the squared length of a finite (1e300, 0, 0) overflows to Inf and
      // glm::normalize would return 0; after scaling the largest component is +-1.
      p.DirectionWC = glm::normalize(s.DirectionWC / Detail::LargestMagnitude(s.DirectionWC));
      ++out.NumberOfSpots;
    }
    else
    {
      p.CosCone = -2.0;
      p.DirectionWC = glm::dvec3(0.0);
    }
    p.SourceIndex = static_cast<std::uint32_t>(i);
    out.NumberOfAlwaysOn += std::isinf(r) ? 1 : 0;
    out.NumberOfBelowCutoff += r == 0.0 ? 1 : 0;
    out.NumberOfExplicitRadius += s.HasRadius ? 1 : 0;
    valid.push_back(p);
  }

  if (options.MortonOrder)
  {
    std::vector<glm::dvec3> points(valid.size());
    std::vector<std::uint8_t> group(valid.size());
    for (std::size_t i = 0; i < valid.size(); ++i)
    {
      points[i] = valid[i].PositionWC;
      group[i] = static_cast<std::uint8_t>(
        (valid[i].IsSpot() ? 2 : 0) + (std::isinf(valid[i].Radius) ? 0 : 1));
    }
    const std::vector<std::uint32_t> order = ComputeMortonOrder(points, &group);
    out.Lights.reserve(valid.size());
    for (std::uint32_t idx : order)
    {
      out.Lights.push_back(valid[idx]);
    }
  }
  else
  {
    out.Lights = std::move(valid);
  }
  out.FirstSpot = out.Lights.size();
  for (std::size_t i = 0; i < out.Lights.size(); ++i)
  {
    if (out.Lights[i].IsSpot())
    {
      out.FirstSpot = i;
      break;
    }
  }
  return out;
}

/// The windowed falloff factor (1 - (d/r)^4)^2 of vtkClusteredLightingPass::FALLOFF_WINDOWED.
inline double EvaluateFalloffWindow(double d, double radius)
{
  if (!(radius > 0.0) || std::isinf(radius))
  {
    return std::isinf(radius) ? 1.0 : 0.0;
  }
  const double x2 = (d * d) / (radius * radius);
  const double w = std::min(1.0, std::max(0.0, 1.0 - x2 * x2));
  return w * w;
}

/**
 * The light model at distance d for a peak contribution c (spot factor and N.L aside):
 * VTK's attenuation, cut at an explicit radius (zero at and beyond it) and windowed there
 * with windowed falloff. Lights without an explicit radius reach everywhere. This is what
 * brute force evaluates.
 */
inline double EvaluateLightModel(double c, double d, const PreparedLight& l, bool windowed)
{
  if (std::isinf(l.ExplicitRadius))
  {
    return c;
  }
  if (!(d < l.ExplicitRadius))
  {
    return 0.0;
  }
  return windowed ? c * EvaluateFalloffWindow(d, l.ExplicitRadius) : c;
}

/**
 * Upper bound of what the cutoff removes at a point, against the light model
 * (EvaluateLightModel, what brute force shows): the sum, over the lights whose culling
 * radius the point is at or beyond, of the model's contribution there (peak color, spot
 * factor and N.L taken as 1). Multiply by the material's Diffuse + Specular. Lights within
 * (1 - slack) * radius count as reached. A light culled at its explicit radius (one no
 * larger than its cutoff radius) has no tail: both modes stop at the same radius. With
 * windowed falloff, reached lights without an explicit radius add what the window at
 * their culling radius removes (lights with one are windowed at it, in the model as in
 * clustered shading).
 */
inline glm::dvec3 ComputeCutoffTailBound(const glm::dvec3& pointVC,
  const std::vector<PreparedLight>& lights, const std::vector<glm::dvec3>& centersVC,
  bool windowed = false, double slack = 1e-3)
{
  glm::dvec3 tail(0.0);
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    const PreparedLight& l = lights[i];
    if (l.Radius >= l.ExplicitRadius || l.FarField)
    {
      continue; // culled where the model ends, or the far field adds the rest back
    }
    const double d = glm::length(pointVC - centersVC[i]);
    const double a = EvaluateAttenuation(d, l.Attenuation);
    if (d >= l.Radius * (1.0 - slack))
    {
      tail += l.Color * EvaluateLightModel(a, d, l, windowed);
    }
    else if (windowed && std::isinf(l.ExplicitRadius))
    {
      tail += l.Color * a * (1.0 - EvaluateFalloffWindow(d, l.Radius * (1.0 + slack)));
    }
  }
  return tail;
}

/**
 * VTK's spot factor of spot light `l` where the cosine of the angle from its axis is
 * cosAngle, as the shading code evaluates it: 0 outside the cone, pow(cos(angle),
 * Exponent) inside. A cosine within `slack` of the cone's counts as inside, with the
 * cosine taken `slack` larger: the default 1e-6 gives an upper bound of the factor the
 * float shading code may compute there (for the tails' bounds), 0 VTK's formula itself
 * (the far field, ComputeFarContribution).
 */
inline double EvaluateSpotFactorAtCosine(
  double cosAngle, const PreparedLight& l, double slack = 1e-6)
{
  if (cosAngle < l.CosCone - slack)
  {
    return 0.0;
  }
  const double c = std::min(std::max(cosAngle + slack, 0.0), 1.0);
  return l.Exponent == 1.0 ? c : std::pow(c, l.Exponent);
}

/// EvaluateSpotFactorAtCosine at world point p: 1 for a point light and at the light itself.
inline double EvaluateSpotFactor(const glm::dvec3& p, const PreparedLight& l, double slack = 1e-6)
{
  if (!l.IsSpot())
  {
    return 1.0;
  }
  const glm::dvec3 toP = p - l.PositionWC;
  const double d = glm::length(toP);
  if (!(d > 0.0) || !std::isfinite(d))
  {
    return 1.0;
  }
  return EvaluateSpotFactorAtCosine(glm::dot(toP / d, l.DirectionWC), l, slack);
}

/// Each light's culling radius at `cutoff` (the radius PrepareLights gives it, capped at its
/// explicit radius), as ComputeTailAtRadii takes them.
inline std::vector<double> ComputeCutoffRadii(
  const std::vector<PreparedLight>& lights, double cutoff)
{
  std::vector<double> radii(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    const PreparedLight& l = lights[i];
    const double peak = std::max(l.Color.x, std::max(l.Color.y, l.Color.z));
    radii[i] = std::min(ComputeInfluenceRadius(peak, l.Attenuation, cutoff), l.ExplicitRadius);
  }
  return radii;
}

/// ComputeTailAtCutoff with the lights' radii at that cutoff (ComputeCutoffRadii) given.
inline double ComputeTailAtRadii(const glm::dvec3& p, const std::vector<PreparedLight>& lights,
  const std::vector<double>& radii, bool windowed)
{
  double tail = 0.0;
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    const PreparedLight& l = lights[i];
    const double r = radii[i];
    if (r >= l.ExplicitRadius)
    {
      continue; // culled where the model ends: nothing is cut
    }
    const double peak = std::max(l.Color.x, std::max(l.Color.y, l.Color.z));
    const double d = glm::length(p - l.PositionWC);
    const double c = peak * EvaluateAttenuation(d, l.Attenuation) * EvaluateSpotFactor(p, l);
    if (d >= r)
    {
      tail += EvaluateLightModel(c, d, l, windowed);
    }
    else if (windowed && std::isinf(l.ExplicitRadius))
    {
      tail += c * (1.0 - EvaluateFalloffWindow(d, r));
    }
  }
  return tail;
}

/**
 * Error budget. The image error of the cutoff at a point p is at most the sum of the cut
 * tails there (ComputeCutoffTailBound, for a white material with Diffuse + Specular <= 1;
 * here with each spot light's own factor at p, EvaluateSpotFactor: a spot light's tail
 * reaches only the points inside its cone).
 * As the cutoff decreases every radius grows, so that sum can only decrease: the largest
 * cutoff whose bound stays within `budget` at every sample point is found by bisection on
 * log(cutoff) in [minCutoff, maxCutoff]. Returns minCutoff if even that is not enough
 * (lights that never fall off contribute no tail and are unaffected).
 */
inline double ComputeTailAtCutoff(
  const glm::dvec3& p, const std::vector<PreparedLight>& lights, double cutoff, bool windowed)
{
  return ComputeTailAtRadii(p, lights, ComputeCutoffRadii(lights, cutoff), windowed);
}

/// Sample points for the error budget: a 6 x 6 x 6 grid over the lights' bounding box
/// (grown by 10%), up to 64 light positions, where dense groups put their tails, and, when
/// [regionLo, regionHi] is a valid box (the geometry to shade), a 6 x 6 x 6 grid over it:
/// a spot light's tail reaches only its cone (EvaluateSpotFactor), which may miss every
/// point near the lights (spot lights in a plane, shining away from it) and light the
/// geometry.
inline std::vector<glm::dvec3> ComputeErrorBudgetSamples(const std::vector<PreparedLight>& lights,
  const glm::dvec3& regionLo = glm::dvec3(1.0), const glm::dvec3& regionHi = glm::dvec3(-1.0))
{
  std::vector<glm::dvec3> samples;
  if (lights.empty())
  {
    return samples;
  }
  auto addGrid = [&samples](const glm::dvec3& lo, const glm::dvec3& hi)
  {
    for (int i = 0; i < 6; ++i)
    {
      for (int j = 0; j < 6; ++j)
      {
        for (int k = 0; k < 6; ++k)
        {
          samples.push_back(
            lo + (hi - lo) * glm::dvec3((i + 0.5) / 6, (j + 0.5) / 6, (k + 0.5) / 6));
        }
      }
    }
  };
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const PreparedLight& l : lights)
  {
    lo = glm::min(lo, l.PositionWC);
    hi = glm::max(hi, l.PositionWC);
  }
  const glm::dvec3 grow = 0.05 * (hi - lo);
  addGrid(lo - grow, hi + grow);
  const std::size_t step = std::max<std::size_t>(1, lights.size() / 64);
  for (std::size_t i = 0; i < lights.size() && samples.size() < 216 + 64; i += step)
  {
    samples.push_back(lights[i].PositionWC);
  }
  bool region = true;
  for (int a = 0; a < 3; ++a)
  {
    region = region && std::isfinite(regionLo[a]) && std::isfinite(regionHi[a]) &&
      regionLo[a] <= regionHi[a];
  }
  if (region)
  {
    addGrid(regionLo, regionHi);
  }
  return samples;
}

inline double ChooseCutoffForErrorBudget(const std::vector<PreparedLight>& lights, double budget,
  const std::vector<glm::dvec3>& samples, bool windowed = false, double minCutoff = 1e-7,
  double maxCutoff = 1.0 / 16.0)
{
  // Whether the tails at `cutoff` stay within the budget at every sample: the radii once per
  // cutoff, and the first sample over the budget decides.
  auto meets = [&](double cutoff)
  {
    const std::vector<double> radii = ComputeCutoffRadii(lights, cutoff);
    return std::none_of(samples.begin(), samples.end(),
      [&](const glm::dvec3& p) { return ComputeTailAtRadii(p, lights, radii, windowed) > budget; });
  };
  if (meets(maxCutoff))
  {
    return maxCutoff;
  }
  if (!meets(minCutoff))
  {
    return minCutoff;
  }
  double lo = std::log(minCutoff), hi = std::log(maxCutoff); // meets(lo), not meets(hi)
  for (int it = 0; it < 24; ++it)
  {
    const double mid = 0.5 * (lo + hi);
    (meets(std::exp(mid)) ? lo : hi) = mid;
  }
  return std::exp(lo);
}

} // namespace vtkClusteredLighting

#endif
