// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightSet
 * @brief   compact set of point and spot lights for vtkClusteredLightingPass
 *
 * Holds tens of thousands of positional lights as plain arrays, without one vtkLight
 * object per light. Each light has the parameters of a positional vtkLight and follows
 * the same conventions and formulas:
 *
 * - position (world coordinates);
 * - color (VTK's DiffuseColor) and intensity: the light's color is color * intensity;
 * - attenuation (a0, a1, a2): contribution 1 / (a0 + a1 d + a2 d^2) at distance d;
 * - optional radius: caps the influence distance (the pass otherwise derives it from
 *   color, intensity, attenuation and its Cutoff);
 * - optional spot: direction, cone half angle in degrees (< 90 makes a spot, as
 *   vtkLight::SetConeAngle) and exponent.
 *
 * New lights get VTK's vtkLight defaults: white, intensity 1, attenuation (1, 0, 0),
 * no radius, no spot. Note that attenuation (1, 0, 0) never falls off: such a light is
 * "always on" and is shaded for every fragment; give lights an attenuation with a
 * linear or quadratic term, or a radius, to make clustering effective.
 *
 * Values are validated by the pass when it prepares lights: a light with a NaN/Inf
 * value, a negative intensity, color or radius, or an invalid attenuation is skipped
 * with a warning naming the set and the light index; all other lights are unaffected.
 *
 * Add the set to a pass with vtkClusteredLightingPass::AddLightSet(). Every setter marks
 * the set modified, so the pass re-uploads light data on the next render only when a
 * set actually changed.
 *
 * @sa vtkClusteredLightingPass vtkLight
 */
#ifndef vtkClusteredLightSet_h
#define vtkClusteredLightSet_h

#include "vtkObject.h"
#include "vtkRenderingClusteredModule.h" // For export macro

#include <memory> // for std::unique_ptr

class VTKRENDERINGCLUSTERED_EXPORT vtkClusteredLightSet : public vtkObject
{
public:
  static vtkClusteredLightSet* New();
  vtkTypeMacro(vtkClusteredLightSet, vtkObject)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of lights. Growing the set gives the new lights the default parameters
   * (vtkLight's defaults, at the origin).
   */
  void SetNumberOfLights(vtkIdType n);
  vtkIdType GetNumberOfLights() const;
  ///@}

  /**
   * Append a point light with default parameters at (x, y, z); returns its index.
   */
  vtkIdType AddLight(double x, double y, double z);

  /**
   * Remove every light.
   */
  void RemoveAllLights();

  ///@{
  /**
   * Per-light parameters. Indices outside [0, GetNumberOfLights()) are reported with
   * vtkErrorMacro and ignored.
   */
  void SetPosition(vtkIdType i, double x, double y, double z);
  void GetPosition(vtkIdType i, double position[3]) const;
  void SetColor(vtkIdType i, double r, double g, double b);
  void GetColor(vtkIdType i, double color[3]) const;
  void SetIntensity(vtkIdType i, double intensity);
  double GetIntensity(vtkIdType i) const;
  void SetAttenuation(vtkIdType i, double constant, double linear, double quadratic);
  void GetAttenuation(vtkIdType i, double attenuation[3]) const;
  ///@}

  ///@{
  /**
   * Explicit influence radius (world units). It caps the radius derived from the
   * cutoff; UnsetRadius() goes back to the derived radius only. A radius of 0 is valid
   * (the light reaches nothing); a negative radius is rejected when lights are prepared.
   */
  void SetRadius(vtkIdType i, double radius);
  void UnsetRadius(vtkIdType i);
  bool HasRadius(vtkIdType i) const;
  double GetRadius(vtkIdType i) const;
  ///@}

  ///@{
  /**
   * Make light i a spot light: axis direction (need not be unit), cone half angle in
   * degrees (>= 90 means no cone, as in VTK) and exponent of the cos falloff.
   * SetPointLight() removes the cone.
   */
  void SetSpot(vtkIdType i, double dx, double dy, double dz, double coneAngle, double exponent);
  void SetPointLight(vtkIdType i);
  void GetSpotDirection(vtkIdType i, double direction[3]) const;
  double GetConeAngle(vtkIdType i) const;
  double GetExponent(vtkIdType i) const;
  ///@}

  ///@{
  /**
   * Switch the whole set on or off without clearing it. Default is on.
   */
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);
  vtkBooleanMacro(Enabled, bool);
  ///@}

protected:
  vtkClusteredLightSet();
  ~vtkClusteredLightSet() override;

  bool CheckIndex(vtkIdType i) const;

  bool Enabled = true;

private:
  vtkClusteredLightSet(const vtkClusteredLightSet&) = delete;
  void operator=(const vtkClusteredLightSet&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
