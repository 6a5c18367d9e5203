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
 * Lights as data: the set is also a pipeline sink (one optional input port taking
 * vtkPolyData, no output port). Connect a source or filter with SetInputConnection(), or
 * a data set with SetInputData(), and every point of the input becomes a light (cells
 * are ignored), with its parameters taken from point-data arrays:
 *
 * | parameter      | array name option      | default name    | components          |
 * |----------------|------------------------|-----------------|---------------------|
 * | color          | ColorArrayName         | "Color"         | 3 (RGB) or 4 (RGBA) |
 * | intensity      | IntensityArrayName     | "Intensity"     | 1                   |
 * | attenuation    | AttenuationArrayName   | "Attenuation"   | 3 (a0, a1, a2)      |
 * | radius         | RadiusArrayName        | "Radius"        | 1                   |
 * | spot direction | SpotDirectionArrayName | "SpotDirection" | 3                   |
 * | cone angle     | ConeAngleArrayName     | "ConeAngle"     | 1 (degrees)         |
 * | exponent       | ExponentArrayName      | "Exponent"      | 1                   |
 *
 * Any numeric array type is accepted; an unsigned char color array is scaled from
 * [0, 255] to [0, 1]. A missing array (or an empty name) gives every light the
 * matching Default* value (DefaultColor, DefaultIntensity, ...). An array of another
 * kind (e.g. a vtkStringArray), with the wrong number of components or with fewer tuples
 * than points is an error (vtkErrorMacro naming the array), and so is an input that is
 * not a vtkPolyData (reported by the executive): the set then holds no lights until the
 * input, the array names or the defaults change.
 *
 * vtkClusteredLightingPass calls UpdateLights() before it reads the lights, which
 * updates the upstream pipeline and re-reads the arrays only when the input, the array
 * names or the defaults changed; the set's MTime then changes, and the pass re-uploads
 * the light data. An animated source therefore moves the lights each frame; the shaders
 * are not rebuilt for it. While an input is connected the input defines the lights:
 * changes made with the per-light setters are replaced at the next update. After the
 * input is disconnected the set keeps the lights it read last.
 *
 * @sa vtkClusteredLightingPass vtkLight
 */
#ifndef vtkClusteredLightSet_h
#define vtkClusteredLightSet_h

#include "vtkAlgorithm.h"
#include "vtkRenderingClusteredModule.h" // For export macro

#include <memory> // for std::unique_ptr

class vtkPolyData;

class VTKRENDERINGCLUSTERED_EXPORT vtkClusteredLightSet : public vtkAlgorithm
{
public:
  static vtkClusteredLightSet* New();
  vtkTypeMacro(vtkClusteredLightSet, vtkAlgorithm)
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

  ///@{
  /**
   * Feed the lights from a data set instead of a pipeline (the connection made is the
   * same as SetInputConnection() with a trivial producer). GetInput() returns the
   * input's data object if it is a vtkPolyData, or null.
   */
  void SetInputData(vtkPolyData* input);
  vtkPolyData* GetInput();
  ///@}

  /**
   * If an input is connected, bring it up to date and, when it (or an array name or
   * default) changed since the last read, read the lights from it. Does nothing without
   * an input. vtkClusteredLightingPass calls it before every render; call it yourself to
   * query the lights of a connected set outside a render.
   */
  void UpdateLights();

  ///@{
  /**
   * Name of the color array. The names of the point-data arrays the lights are read
   * from when an input is connected (see the class description for the number of
   * components); an empty or null name means "not given": every light gets the matching
   * default. Default is "Color".
   */
  vtkSetStringMacro(ColorArrayName);
  vtkGetStringMacro(ColorArrayName);
  ///@}

  ///@{
  /**
   * Name of the intensity array. Default is "Intensity".
   */
  vtkSetStringMacro(IntensityArrayName);
  vtkGetStringMacro(IntensityArrayName);
  ///@}

  ///@{
  /**
   * Name of the attenuation array (a0, a1, a2). Default is "Attenuation".
   */
  vtkSetStringMacro(AttenuationArrayName);
  vtkGetStringMacro(AttenuationArrayName);
  ///@}

  ///@{
  /**
   * Name of the explicit influence radius array. Default is "Radius".
   */
  vtkSetStringMacro(RadiusArrayName);
  vtkGetStringMacro(RadiusArrayName);
  ///@}

  ///@{
  /**
   * Name of the spot direction array (need not be unit). Default is "SpotDirection".
   */
  vtkSetStringMacro(SpotDirectionArrayName);
  vtkGetStringMacro(SpotDirectionArrayName);
  ///@}

  ///@{
  /**
   * Name of the cone half angle array, in degrees (>= 90: point light).
   * Default is "ConeAngle".
   */
  vtkSetStringMacro(ConeAngleArrayName);
  vtkGetStringMacro(ConeAngleArrayName);
  ///@}

  ///@{
  /**
   * Name of the spot exponent array. Default is "Exponent".
   */
  vtkSetStringMacro(ExponentArrayName);
  vtkGetStringMacro(ExponentArrayName);
  ///@}

  ///@{
  /**
   * Color of the lights read from an input without a color array. The Default* values
   * below follow vtkLight's defaults, except that lights are point lights.
   * Default is (1, 1, 1).
   */
  vtkSetVector3Macro(DefaultColor, double);
  vtkGetVector3Macro(DefaultColor, double);
  ///@}

  ///@{
  /**
   * Intensity of the lights read from an input without an intensity array.
   * Default is 1.
   */
  vtkSetMacro(DefaultIntensity, double);
  vtkGetMacro(DefaultIntensity, double);
  ///@}

  ///@{
  /**
   * Attenuation (a0, a1, a2) of the lights read from an input without an attenuation
   * array. The default never falls off: such lights are always on (see the class
   * description); pipelines of many lights usually set a quadratic term or a radius.
   * Default is (1, 0, 0).
   */
  vtkSetVector3Macro(DefaultAttenuation, double);
  vtkGetVector3Macro(DefaultAttenuation, double);
  ///@}

  ///@{
  /**
   * Explicit radius of the lights read from an input without a radius array; a negative
   * value means no explicit radius (the pass derives it from the cutoff).
   * Default is -1.
   */
  vtkSetMacro(DefaultRadius, double);
  vtkGetMacro(DefaultRadius, double);
  ///@}

  ///@{
  /**
   * Spot direction of the lights read from an input without a spot direction array.
   * Default is (0, 0, -1).
   */
  vtkSetVector3Macro(DefaultSpotDirection, double);
  vtkGetVector3Macro(DefaultSpotDirection, double);
  ///@}

  ///@{
  /**
   * Cone half angle, in degrees, of the lights read from an input without a cone angle
   * array (>= 90: point light). Default is 180.
   */
  vtkSetMacro(DefaultConeAngle, double);
  vtkGetMacro(DefaultConeAngle, double);
  ///@}

  ///@{
  /**
   * Spot exponent of the lights read from an input without an exponent array.
   * Default is 1.
   */
  vtkSetMacro(DefaultExponent, double);
  vtkGetMacro(DefaultExponent, double);
  ///@}

  /**
   * Number of times lights were read from the input (for tests and diagnostics).
   */
  vtkGetMacro(NumberOfInputReads, int);

protected:
  vtkClusteredLightSet();
  ~vtkClusteredLightSet() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * Sends REQUEST_DATA to RequestData(); vtkAlgorithm has no data request of its own.
   */
  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;

  /**
   * Reads the lights from the input's points and point-data arrays.
   */
  virtual int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);

  bool CheckIndex(vtkIdType i) const;

  bool Enabled = true;
  char* ColorArrayName = nullptr;
  char* IntensityArrayName = nullptr;
  char* AttenuationArrayName = nullptr;
  char* RadiusArrayName = nullptr;
  char* SpotDirectionArrayName = nullptr;
  char* ConeAngleArrayName = nullptr;
  char* ExponentArrayName = nullptr;
  double DefaultColor[3] = { 1.0, 1.0, 1.0 };
  double DefaultIntensity = 1.0;
  double DefaultAttenuation[3] = { 1.0, 0.0, 0.0 };
  double DefaultRadius = -1.0;
  double DefaultSpotDirection[3] = { 0.0, 0.0, -1.0 };
  double DefaultConeAngle = 180.0;
  double DefaultExponent = 1.0;
  int NumberOfInputReads = 0;

private:
  vtkClusteredLightSet(const vtkClusteredLightSet&) = delete;
  void operator=(const vtkClusteredLightSet&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
