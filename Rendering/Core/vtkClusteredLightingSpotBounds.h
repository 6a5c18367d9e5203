// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingSpotBounds.h
 * @brief Where a spot light can reach: its cone against a ball, and its sector's sphere.
 *
 * A spot light at apex p with unit axis a and half angle theta (VTK's ConeAngle, < 90
 * degrees) lights only points x with dot(x - p, a) >= cos(theta) |x - p| (the shading
 * code's `coneDot >= cos(cone)`, spot factor 0 outside). Within its culling radius r it
 * lights only the sector  K = cone ∩ sphere(p, r).  Two conservative tests cut the
 * clusters a spot light is assigned to (the option `SpotConeCulling` of the pass):
 *
 * - **The cone against a ball** (SpotConeMayReachBall; the list pass's
 *   `clSpotConeMayReach` per cluster, with the ball about the cluster cell's bounding
 *   box). A ball of radius rho whose centre lies at distance D from the apex and angle
 *   phi from the axis is seen from the apex within asin(rho / D) of phi; it meets the
 *   (infinite) cone iff phi - asin(rho / D) <= theta, or D <= rho (it holds the apex);
 *   evaluated as cos(phi) >= cos(theta + asin(rho / D)) (SpotCone).
 *   The shader evaluates the same test without inverse trigonometry: the distance from
 *   the centre to the cone's lateral surface is D sin(phi - theta) = cos(theta) across -
 *   sin(theta) along (along = D cos(phi), across = D sin(phi)), never more than the
 *   distance to the cone itself, and every point of the cone has along >= 0. So the ball
 *   may meet the cone only if that distance is <= rho and along >= -rho.
 *
 * - **The sector's bounding sphere** (ComputeSpotSectorSphere, on the CPU before the
 *   list pass: the (light, slice) tile rectangles are those of this sphere when it is
 *   smaller than the light's). For theta <= 45 degrees the sphere through the apex and
 *   the cap's rim with its centre on the axis, centre p + a r / (2 cos theta), radius
 *   r / (2 cos theta), holds the whole cap (its points lie nearer the centre than the
 *   rim's); above 45 degrees the sphere about the rim's circle, centre
 *   p + a r cos(theta), radius r sin(theta), holds the apex and the cap. A cone of 30
 *   degrees (VTK's default) is held by a sphere of 0.577 r (0.19 of the volume), one of
 *   60 degrees by 0.866 r.
 *
 * **Float slack.** The shading code computes coneDot in float, so it may light a point
 * up to about 4e-4 radians outside the cone at tiny angles (at theta = 0 it compares
 * with cos = 1). Both tests widen the cone by SpotConeSlack = 2e-3 radians (the sector
 * sphere also grows by 1e-5 of r), and the list shader adds twice that, 4e-3 D, to rho,
 * so that the float test on the GPU passes wherever the double-precision one here does
 * (the CPU reference assigner, vtkClusteredLightingReference.h, uses these).
 */
#ifndef vtkClusteredLightingSpotBounds_h
#define vtkClusteredLightingSpotBounds_h

#include <algorithm> // for std::min
#include <cmath>     // for std::acos, std::sqrt
#include <glm/glm.hpp>

namespace vtkClusteredLighting
{

/// Radians by which the assignment's cone tests widen a spot light's cone.
constexpr double SpotConeSlack = 2e-3;

/// Relative lateral slack the list shader adds to the ball's radius (its `4e-3`): at least
/// twice SpotConeSlack, so that its float test passes wherever SpotConeMayReachBall does.
constexpr double SpotConeShaderSlack = 4e-3;
static_assert(
  SpotConeShaderSlack >= 2.0 * SpotConeSlack, "the shader's slack must cover the core's");

/**
 * A spot light's cone widened by `slack` radians, ready for many ball tests
 * (MayReachBall): the cosine and sine of the widened half angle a = acos(cosCone) + slack
 * are computed once. The far-field build tests each spot light against every block of
 * nodes (FarFieldLightTree::SpotCones); with three inverse trigonometric calls per test
 * those took about a third of its time (2026-12-05).
 */
struct SpotCone
{
  glm::dvec3 Apex = glm::dvec3(0.0);
  glm::dvec3 Axis = glm::dvec3(0.0, 0.0, -1.0);
  double CosWide = -1.0, SinWide = 0.0; ///< cos(a), sin(a)
  bool Everywhere = true;               ///< a >= pi: every ball passes

  SpotCone() = default;
  SpotCone(const glm::dvec3& apex, const glm::dvec3& axis, double cosCone, double slack)
    : Apex(apex)
    , Axis(axis)
  {
    const double c = std::min(std::max(cosCone, -1.0), 1.0);
    const double s = std::sqrt(std::max(1.0 - c * c, 0.0));
    const double cs = std::cos(slack), ss = std::sin(slack);
    this->CosWide = c * cs - s * ss;
    this->SinWide = s * cs + c * ss;
    // sin(a) < 0 only past pi (the slack is small and not negative); NaN passes everywhere.
    this->Everywhere = !(this->SinWide >= 0.0) || !(this->CosWide > -1.0);
  }

  /**
   * Whether the ball (centre, rho) may hold a point of the widened cone: the angle phi of
   * its centre from the axis, less asin(rho / D), at most a (see the file description),
   * tested as cos(phi) >= cos(a + asin(rho / D)) while a + asin(rho / D) < pi (true past
   * it). The cosine form resolves angles near the axis to about 2e-8 radians (cos(x) =
   * 1 - x^2 / 2 in double precision), well inside any slack of 1e-6 radians or more: where
   * the two forms could differ, the widened cone's angle exceeds the true one by the slack.
   */
  bool MayReachBall(const glm::dvec3& centre, double rho) const
  {
    const glm::dvec3 v = centre - this->Apex;
    const double D = glm::length(v);
    if (!(D > rho) || this->Everywhere)
    {
      return true; // the ball holds the apex, or the cone is everything
    }
    const double sinB = std::max(rho, 0.0) / D; // < 1
    const double cosB = std::sqrt(1.0 - sinB * sinB);
    if (this->CosWide <= -cosB)
    {
      return true; // a + asin(rho / D) >= pi
    }
    const double cosSum = this->CosWide * cosB - this->SinWide * sinB;
    return glm::dot(v, this->Axis) >= cosSum * D;
  }
};

/**
 * Whether the ball (centre, rho) may hold a point of the cone at `apex` with unit axis
 * `axis` and cos(half angle) `cosCone`, the cone widened by `slack` radians. False only
 * where every point of the ball is outside the widened cone (SpotCone::MayReachBall).
 */
inline bool SpotConeMayReachBall(const glm::dvec3& apex, const glm::dvec3& axis, double cosCone,
  const glm::dvec3& centre, double rho, double slack = SpotConeSlack)
{
  return SpotCone(apex, axis, cosCone, slack).MayReachBall(centre, rho);
}

/// A ball: centre and radius.
struct SpotSectorSphere
{
  glm::dvec3 Centre = glm::dvec3(0.0);
  double Radius = 0.0;
};

/**
 * A sphere holding every point within `radius` of `apex` inside the cone (unit `axis`,
 * cos(half angle) `cosCone`) widened by SpotConeSlack, grown by 1e-5 of `radius`. A cone
 * of 90 degrees or more (once widened) gets the light's own sphere.
 */
inline SpotSectorSphere ComputeSpotSectorSphere(
  const glm::dvec3& apex, const glm::dvec3& axis, double cosCone, double radius)
{
  const double halfPi = 1.57079632679489661923;
  const double theta = std::acos(std::min(std::max(cosCone, -1.0), 1.0)) + SpotConeSlack;
  SpotSectorSphere s;
  s.Centre = apex;
  s.Radius = radius;
  if (!(theta < halfPi))
  {
    return s;
  }
  const double grow = 1e-5 * radius;
  if (theta <= 0.5 * halfPi)
  {
    const double half = radius / (2.0 * std::cos(theta));
    s.Centre = apex + half * axis;
    s.Radius = half + grow;
  }
  else
  {
    s.Centre = apex + (radius * std::cos(theta)) * axis;
    s.Radius = radius * std::sin(theta) + grow;
  }
  return s;
}

} // namespace vtkClusteredLighting

#endif
