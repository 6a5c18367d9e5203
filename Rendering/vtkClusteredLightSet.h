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
 *   color, intensity, attenuation and its ContributionCutoff);
 * - optional spot: direction, cone half angle in degrees (below 90 makes a spot, as
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
 * (A cone angle of +Inf is no exception to VTK's rule: like any angle of 90 degrees or
 * more it makes a point light.)
 * The pass gives these warnings to the set's own WarningEvent observers too (see
 * ReportProblem()).
 *
 * All lights at once: SetPositions(), SetColors(), SetIntensities(), ... take a
 * vtkDataArray of one tuple per light, and GetPositions(), GetColors(), ... fill a
 * vtkDoubleArray; from Python, clusteredlighting.light_set_from_numpy() and
 * light_set_to_numpy() wrap them for numpy arrays.
 *
 * Exposure: IntensityScale multiplies the intensity of every light of the set (thousands
 * of lights of intensity 1 wash a scene out; a scale of 0.1 brings it back without
 * touching each light). vtkToneMappingPass around the pass is the other remedy.
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
 * - color: option ColorArrayName, default name "Color", 3 components (RGB) or 4 (RGBA);
 * - intensity: IntensityArrayName, "Intensity", 1 component;
 * - attenuation: AttenuationArrayName, "Attenuation", 3 components (a0, a1, a2);
 * - radius: RadiusArrayName, "Radius", 1 component;
 * - spot direction: SpotDirectionArrayName, "SpotDirection", 3 components;
 * - cone angle: ConeAngleArrayName, "ConeAngle", 1 component (degrees);
 * - exponent: ExponentArrayName, "Exponent", 1 component.
 *
 * Any numeric array type is accepted; an unsigned char color array is scaled from
 * [0, 255] to [0, 1]. A missing array (or an empty name) gives every light the
 * matching Default* value (DefaultColor, DefaultIntensity, ...). An array of another
 * kind (e.g. a vtkStringArray), with the wrong number of components or with fewer tuples
 * than points is an error (vtkErrorMacro naming the array), and so is an input that is
 * not a vtkPolyData (an error of the set naming the type, given once while that input
 * stays): the set then holds no lights until the input, the array names or the defaults
 * change.
 *
 * vtkClusteredLightingPass calls UpdateLights() before it reads the lights, which
 * updates the upstream pipeline and re-reads the arrays only when the input, the array
 * names or the defaults changed; the set's MTime then changes, and the pass re-uploads
 * the light data. An animated source therefore moves the lights each frame; the shaders
 * are not rebuilt for it. While an input is connected the input defines the lights:
 * changes made with the per-light setters are replaced at the next update, and the first
 * such call warns (once while the same input stays connected). After the input is
 * disconnected the set keeps the lights it read last, and the setters work again.
 *
 * @sa vtkClusteredLightingPass vtkLight
 */
#ifndef vtkClusteredLightSet_h
#define vtkClusteredLightSet_h

#include "vtkAlgorithm.h"
#include "vtkRenderingClusteredModule.h" // For export macro
#include "vtkWrappingHints.h"            // For VTK_SIZEHINT

#include <memory> // for std::unique_ptr

class vtkDataArray;
class vtkDoubleArray;
class vtkPolyData;

class VTKRENDERINGCLUSTERED_EXPORT vtkClusteredLightSet : public vtkAlgorithm
{
public:
  static vtkClusteredLightSet* New();
  vtkTypeMacro(vtkClusteredLightSet, vtkAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  //@{
  /**
   * Number of lights. Growing the set gives the new lights the default parameters
   * (vtkLight's defaults, at the origin). SetNumberOfLights(), AddLight(),
   * RemoveAllLights() and every per-light or bulk setter below warn when the set has an
   * input (the input defines the lights and replaces the change at the next update);
   * the warning is given once while the same input stays connected.
   */
  void SetNumberOfLights(vtkIdType n);
  vtkIdType GetNumberOfLights() const;
  //@}

  /**
   * Append a point light with default parameters at (x, y, z); returns its index.
   */
  vtkIdType AddLight(double x, double y, double z);

  /**
   * Remove every light.
   */
  void RemoveAllLights();

  //@{
  /**
   * Per-light parameters. Indices outside [0, GetNumberOfLights()) are reported with
   * vtkErrorMacro and ignored. GetIntensity() returns the intensity as set, without
   * IntensityScale (see GetScaledIntensity()).
   */
  void SetPosition(vtkIdType i, double x, double y, double z);
  void GetPosition(vtkIdType i, double position[3]) const;
  void SetColor(vtkIdType i, double r, double g, double b);
  void GetColor(vtkIdType i, double color[3]) const;
  void SetIntensity(vtkIdType i, double intensity);
  double GetIntensity(vtkIdType i) const;
  void SetAttenuation(vtkIdType i, double constant, double linear, double quadratic);
  void GetAttenuation(vtkIdType i, double attenuation[3]) const;
  //@}

  //@{
  /**
   * The same getters returning the value (from Python: a tuple, e.g.
   * `lights.GetPosition(3)`). The pointer is to the set's own storage of light i: it
   * stays valid until the number of lights changes or the set reads its input, and must
   * not be written through (use the setters, which mark the set modified). An index out
   * of range is an error and returns (0, 0, 0); from Python it raises ValueError.
   */
  const double* GetPosition(vtkIdType i) const VTK_EXPECTS(0 <= i && i < GetNumberOfLights())
    VTK_SIZEHINT(3);
  const double* GetColor(vtkIdType i) const VTK_EXPECTS(0 <= i && i < GetNumberOfLights())
    VTK_SIZEHINT(3);
  const double* GetAttenuation(vtkIdType i) const VTK_EXPECTS(0 <= i && i < GetNumberOfLights())
    VTK_SIZEHINT(3);
  const double* GetSpotDirection(vtkIdType i) const VTK_EXPECTS(0 <= i && i < GetNumberOfLights())
    VTK_SIZEHINT(3);
  //@}

  //@{
  /**
   * Explicit influence radius (world units). It caps the radius derived from the
   * cutoff; UnsetRadius() goes back to the derived radius only. A radius of 0 is valid
   * (the light reaches nothing); a negative radius is rejected when lights are prepared.
   */
  void SetRadius(vtkIdType i, double radius);
  void UnsetRadius(vtkIdType i);
  bool HasRadius(vtkIdType i) const;
  double GetRadius(vtkIdType i) const;
  //@}

  //@{
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
  //@}

  //@{
  /**
   * All lights at once, one tuple per light (any numeric vtkDataArray; from Python, any
   * numpy array through vtkmodules.util.numpy_support, or the package's
   * light_set_from_numpy()). SetPositions() sets the number of lights to the array's
   * number of tuples (lights it adds get the default parameters); the other setters need
   * exactly GetNumberOfLights() tuples. Components: 3 for positions, attenuations
   * (a0, a1, a2) and spot directions; 3 or 4 for colors (alpha ignored; an unsigned char
   * array is scaled from [0, 255] to [0, 1], as for an input's color array); 1 for
   * intensities, radii, cone angles (degrees) and exponents. A negative radius means "no
   * explicit radius" (as DefaultRadius); GetRadii() gives -1 for such lights. A null
   * array or a wrong number of components or of tuples is an error (vtkErrorMacro
   * naming the method) that changes nothing; the setters return false then.
   * The getters resize the given vtkDoubleArray to GetNumberOfLights() tuples and fill
   * it; intensities are given as set, without IntensityScale.
   */
  bool SetPositions(vtkDataArray* positions);
  void GetPositions(vtkDoubleArray* positions) const;
  bool SetColors(vtkDataArray* colors);
  void GetColors(vtkDoubleArray* colors) const;
  bool SetIntensities(vtkDataArray* intensities);
  void GetIntensities(vtkDoubleArray* intensities) const;
  bool SetAttenuations(vtkDataArray* attenuations);
  void GetAttenuations(vtkDoubleArray* attenuations) const;
  bool SetRadii(vtkDataArray* radii);
  void GetRadii(vtkDoubleArray* radii) const;
  bool SetSpotDirections(vtkDataArray* directions);
  void GetSpotDirections(vtkDoubleArray* directions) const;
  bool SetConeAngles(vtkDataArray* coneAngles);
  void GetConeAngles(vtkDoubleArray* coneAngles) const;
  bool SetExponents(vtkDataArray* exponents);
  void GetExponents(vtkDoubleArray* exponents) const;
  //@}

  //@{
  /**
   * Exposure: a factor applied to the intensity of every light of the set when the pass
   * reads it (GetScaledIntensity()), whether the lights were set one by one, in bulk or
   * read from an input. The per-light intensities are left as they are. Clamped to
   * [0, VTK_FLOAT_MAX]; NaN is an error and ignored. Default is 1.
   */
  virtual void SetIntensityScale(double scale);
  vtkGetMacro(IntensityScale, double);
  //@}

  /**
   * The intensity light i is shaded with: GetIntensity(i) * GetIntensityScale().
   */
  double GetScaledIntensity(vtkIdType i) const;

  /**
   * Raises a problem found in this set's lights on the set itself: the set's WarningEvent
   * observers receive "Warning: vtkClusteredLightSet (<address>): <message>".
   * vtkClusteredLightingPass calls it for each warning it gives about the set's lights
   * (an invalid light is skipped; many are summarized in one line), so that an
   * application can observe its own sets. Nothing is printed (the pass prints its own
   * copy, or gives it to the pass's observers), and nothing happens without an observer
   * or when vtkObject's global warning display is off.
   */
  void ReportProblem(const char* message);

  //@{
  /**
   * Switch the whole set on or off without clearing it. Default is on.
   */
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);
  vtkBooleanMacro(Enabled, bool);
  //@}

  //@{
  /**
   * Feed the lights from a data set instead of a pipeline (the connection made is the
   * same as SetInputConnection() with a trivial producer). GetInput() returns the
   * input's data object if it is a vtkPolyData, or null.
   */
  void SetInputData(vtkPolyData* input);
  vtkPolyData* GetInput();
  //@}

  /**
   * If an input is connected, bring it up to date and, when it (or an array name or
   * default) changed since the last read, read the lights from it. Does nothing without
   * an input. vtkClusteredLightingPass calls it before every render; call it yourself to
   * query the lights of a connected set outside a render.
   */
  void UpdateLights();

  //@{
  /**
   * Name of the color array. The names of the point-data arrays the lights are read
   * from when an input is connected (see the class description for the number of
   * components); an empty or null name means "not given": every light gets the matching
   * default. Default is "Color".
   */
  vtkSetStringMacro(ColorArrayName);
  vtkGetStringMacro(ColorArrayName);
  //@}

  //@{
  /**
   * Name of the intensity array. Default is "Intensity".
   */
  vtkSetStringMacro(IntensityArrayName);
  vtkGetStringMacro(IntensityArrayName);
  //@}

  //@{
  /**
   * Name of the attenuation array (a0, a1, a2). Default is "Attenuation".
   */
  vtkSetStringMacro(AttenuationArrayName);
  vtkGetStringMacro(AttenuationArrayName);
  //@}

  //@{
  /**
   * Name of the explicit influence radius array. Default is "Radius".
   */
  vtkSetStringMacro(RadiusArrayName);
  vtkGetStringMacro(RadiusArrayName);
  //@}

  //@{
  /**
   * Name of the spot direction array (need not be unit). Default is "SpotDirection".
   */
  vtkSetStringMacro(SpotDirectionArrayName);
  vtkGetStringMacro(SpotDirectionArrayName);
  //@}

  //@{
  /**
   * Name of the cone half angle array, in degrees (>= 90: point light).
   * Default is "ConeAngle".
   */
  vtkSetStringMacro(ConeAngleArrayName);
  vtkGetStringMacro(ConeAngleArrayName);
  //@}

  //@{
  /**
   * Name of the spot exponent array. Default is "Exponent".
   */
  vtkSetStringMacro(ExponentArrayName);
  vtkGetStringMacro(ExponentArrayName);
  //@}

  //@{
  /**
   * Color of the lights read from an input without a color array. The Default* values
   * below follow vtkLight's defaults, except that lights are point lights.
   * Default is (1, 1, 1).
   */
  vtkSetVector3Macro(DefaultColor, double);
  vtkGetVector3Macro(DefaultColor, double);
  //@}

  //@{
  /**
   * Intensity of the lights read from an input without an intensity array.
   * Default is 1.
   */
  vtkSetMacro(DefaultIntensity, double);
  vtkGetMacro(DefaultIntensity, double);
  //@}

  //@{
  /**
   * Attenuation (a0, a1, a2) of the lights read from an input without an attenuation
   * array. The default never falls off: such lights are always on (see the class
   * description); pipelines of many lights usually set a quadratic term or a radius.
   * Default is (1, 0, 0).
   */
  vtkSetVector3Macro(DefaultAttenuation, double);
  vtkGetVector3Macro(DefaultAttenuation, double);
  //@}

  //@{
  /**
   * Explicit radius of the lights read from an input without a radius array; a negative
   * value means no explicit radius (the pass derives it from the cutoff).
   * Default is -1.
   */
  vtkSetMacro(DefaultRadius, double);
  vtkGetMacro(DefaultRadius, double);
  //@}

  //@{
  /**
   * Spot direction of the lights read from an input without a spot direction array.
   * Default is (0, 0, -1).
   */
  vtkSetVector3Macro(DefaultSpotDirection, double);
  vtkGetVector3Macro(DefaultSpotDirection, double);
  //@}

  //@{
  /**
   * Cone half angle, in degrees, of the lights read from an input without a cone angle
   * array (>= 90: point light). Default is 180.
   */
  vtkSetMacro(DefaultConeAngle, double);
  vtkGetMacro(DefaultConeAngle, double);
  //@}

  //@{
  /**
   * Spot exponent of the lights read from an input without an exponent array.
   * Default is 1.
   */
  vtkSetMacro(DefaultExponent, double);
  vtkGetMacro(DefaultExponent, double);
  //@}

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

  /**
   * Warns (once while the same input stays connected) that `setter` changes lights that
   * the connected input defines. Does nothing without an input.
   */
  void WarnIfInputDefinesLights(const char* setter);

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
  double IntensityScale = 1.0;
  int NumberOfInputReads = 0;

private:
  vtkClusteredLightSet(const vtkClusteredLightSet&) = delete;
  void operator=(const vtkClusteredLightSet&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
