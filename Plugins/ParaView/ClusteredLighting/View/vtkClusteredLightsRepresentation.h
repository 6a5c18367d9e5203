// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightsRepresentation
 * @brief   representation that turns the points of a vtkPolyData into clustered lights
 *
 * "Lights as data" for ParaView: every point of the input (a vtkPolyData, or a composite
 * data set of vtkPolyData blocks: the blocks' points, with the point arrays all blocks
 * have) becomes a light of a
 * vtkClusteredLightSet, with its color, intensity, attenuation, radius and spot cone read
 * from point-data arrays named by the *ArrayName properties, or the Default* values where
 * an array is not given or missing. The representation draws no geometry: it adds its
 * light set to the vtkPVClusteredLightingView it is shown in, and the view's pass shades
 * the view's other representations with it.
 *
 * Data delivery: a light on one rank's piece may light geometry on any other rank, so the
 * points and point data (not the cells) are gathered from every data rank and delivered to
 * every rendering rank (vtkPVRenderView::SetDeliverToAllProcesses), where each rank's pass
 * clusters all lights. Points that ParaView marks as duplicates of another piece's
 * (vtkGhostType with DUPLICATEPOINT, e.g. after Ghost Cells Generator) are left out, so
 * that a point shared by pieces is one light; pieces that share points without marking
 * them (e.g. the Sphere source split over ranks) give such points once per piece.
 *
 * Hiding the representation (or removing it from the view) switches its lights off. In a
 * view other than vtkPVClusteredLightingView the representation does nothing but warn
 * once.
 *
 * @sa vtkClusteredLightSet vtkPVClusteredLightingView
 */
#ifndef vtkClusteredLightsRepresentation_h
#define vtkClusteredLightsRepresentation_h

#include "vtkClusteredLightingViewModule.h" // For export macro
#include "vtkNew.h"                         // For vtkNew
#include "vtkPVDataRepresentation.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

class vtkClusteredLightSet;
class vtkPVClusteredLightingView;
class vtkPolyData;

class VTKCLUSTEREDLIGHTINGVIEW_EXPORT vtkClusteredLightsRepresentation
  : public vtkPVDataRepresentation
{
public:
  static vtkClusteredLightsRepresentation* New();
  vtkTypeMacro(vtkClusteredLightsRepresentation, vtkPVDataRepresentation)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Delivers the lights' points to every rendering rank (REQUEST_UPDATE) and connects the
   * delivered data to the light set (REQUEST_RENDER).
   */
  int ProcessViewRequest(vtkInformationRequestKey* requestType, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  /**
   * Hidden lights are switched off (vtkClusteredLightSet::SetEnabled).
   */
  void SetVisibility(bool visible) override;

  ///@{
  /**
   * Names of the point-data arrays the lights' parameters are read from (see
   * vtkClusteredLightSet). NoneArrayName (the list's "(none)" entry in ParaView), like an
   * empty name or a name the data does not have, gives every light the matching Default*
   * value. Defaults are "Color", "Intensity", "Attenuation", "Radius", "SpotDirection",
   * "ConeAngle" and "Exponent".
   */
  void SetColorArrayName(const char* name);
  void SetIntensityArrayName(const char* name);
  void SetAttenuationArrayName(const char* name);
  void SetRadiusArrayName(const char* name);
  void SetSpotDirectionArrayName(const char* name);
  void SetConeAngleArrayName(const char* name);
  void SetExponentArrayName(const char* name);
  static const char* NoneArrayName() { return "(none)"; }
  ///@}

  ///@{
  /**
   * Parameters of lights whose array is not given or missing (see vtkClusteredLightSet for
   * their meaning). Defaults are vtkClusteredLightSet's: color (1, 1, 1), intensity 1,
   * attenuation (1, 0, 0), radius -1 (none), spot direction (0, 0, -1), cone angle 180
   * (point light), exponent 1.
   */
  void SetDefaultColor(double r, double g, double b);
  void SetDefaultIntensity(double intensity);
  void SetDefaultAttenuation(double constant, double linear, double quadratic);
  void SetDefaultRadius(double radius);
  void SetDefaultSpotDirection(double x, double y, double z);
  void SetDefaultConeAngle(double angle);
  void SetDefaultExponent(double exponent);
  ///@}

  /**
   * The light set fed by the delivered data (for tests and diagnostics).
   */
  vtkClusteredLightSet* GetLightSet();

  /**
   * Number of lights read from the delivered data on this rank, after UpdateLights().
   */
  vtkIdType GetNumberOfLights();

protected:
  vtkClusteredLightsRepresentation();
  ~vtkClusteredLightsRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

  static const char* ArrayName(const char* name);

  /**
   * Copies the input's points and point data into output, without its cells and without
   * the points that ParaView marks as duplicates of another piece's (ghost points).
   */
  static void CopyOwnedPoints(vtkPolyData* input, vtkPolyData* output);

  vtkNew<vtkClusteredLightSet> LightSet;
  vtkNew<vtkPolyData> Points; ///< the input's points and point data, without cells
  vtkWeakPointer<vtkPVClusteredLightingView> LightingView;
  bool WarnedAboutView = false;

private:
  vtkClusteredLightsRepresentation(const vtkClusteredLightsRepresentation&) = delete;
  void operator=(const vtkClusteredLightsRepresentation&) = delete;
};

#endif
