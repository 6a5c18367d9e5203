// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingAssigner
 * @brief   light assignment for one renderer: change detection, light records, list/master
 *
 * Private to the module; the second stage of vtkClusteredLightingPass::Render(), one
 * instance per renderer (it owns that renderer's GL objects):
 *
 *   light gathering (vtkClusteredLightingLightCollector)
 *     -> Update():
 *          1. what changed (explicit reasons, vtkClusteredLightingDirtyReason)
 *          2. prepare lights    (only when LIGHTS or PREPARATION: validate, radii, Morton
 *                                order, error budget; Rendering/Core/...Lights.h)
 *          3. limits            (texture layout for the light count: a smaller grid when
 *                                the asked one cannot hold the lights, an error when none
 *                                can; the plain loop when every light reaches every cluster)
 *          4. upload clLightData (only when the prepared lights changed)
 *          5. depth bounds      (only after a depth prepass: the slicing range from the
 *                                visible depths, each cluster's depth interval,
 *                                Rendering/Core/...DepthBounds.h)
 *          6. view              (only when anything changed: clLightView records and the
 *                                (light, slice) tile rectangles, ...Assignment.h)
 *          7. list and master   (the back end, vtkClusteredLightingAssignmentBackend)
 *        and returns a vtkClusteredLightingAssignment: statistics, messages to report,
 *        and the values the shading code needs (one struct for SetShaderParameters)
 *     -> shading (the pass: shader variant, delegate render with the textures bound)
 *
 * Change detection compares typed inputs with those of the last update, never a flat
 * signature: the light sources' key (objects and newest MTime), the preparation
 * options, and the view key (matrices, grid, mode). A still frame with unchanged lights
 * does no work at all (after a depth prepass: step 5 only, whose result is compared
 * with the last); a moving camera re-runs steps 5-7 only; a changed light re-runs 2-7.
 *
 * GL objects (all in the context of the window of the last update, released in that
 * context when the window is deleted, when the assigner is destroyed, or on
 * ReleaseGraphicsResources):
 *   clLightData  texture buffer, RGBA32F, 2 texels per light (changes with the lights)
 *   clLightView  texture buffer, RGBA32F, 2 texels per light (changes with the view)
 *   + whatever the back end owns (raster back end: quads, list, master, FBO, VAO)
 *   + in a multisampled framebuffer with depth-aware clusters, the depth prepass's
 *     recording targets (vtkClusteredLightingSampleDepths, GetSampleDepths()), and
 *     with ReuseDepthPrepass the copy of its last depths (vtkClusteredLightingSavedDepth,
 *     GetSavedDepth()), which the assigner owns for the renderer so that they share its
 *     lifetime
 *
 * For tests (vtkClusteredLightingInspector, Testing/Cxx), GetSnapshot() copies what the
 * last assignment used (grid, matrices, layout, prepared lights) when asked; nothing is
 * kept for it otherwise.
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightingLightCollector
 */
#ifndef vtkClusteredLightingAssigner_h
#define vtkClusteredLightingAssigner_h

#include "vtkClusteredLightingAssignment.h"       // for ViewParameters, ShadingParameters
#include "vtkClusteredLightingFarFieldBound.h"    // for FarFieldOptions, FarFieldPlan, the bound
#include "vtkClusteredLightingFarFieldBudget.h"   // for FarFieldResolutionChoice
#include "vtkClusteredLightingFarFieldTextures.h" // for vtkClusteredLightingFarFieldTextures
#include "vtkClusteredLightingGLHelpers.h"        // for vtkClusteredLightingTextureBuffer
#include "vtkClusteredLightingLayout.h"           // for ClusterTextureLayout
#include "vtkClusteredLightingLights.h"           // for PreparedLights
#include "vtkClusteredLightingMessages.h"         // for ProblemGroup
#include "vtkClusteredLightingSampleDepths.h"     // for vtkClusteredLightingSampleDepths
#include "vtkClusteredLightingSavedDepth.h"       // for vtkClusteredLightingSavedDepth
#include "vtkOpenGLRenderWindow.h"                // for vtkWeakPointer<vtkOpenGLRenderWindow>
#include "vtkWeakPointer.h"                       // for vtkWeakPointer

#include <cstdint> // for std::uint64_t
#include <memory>  // for std::unique_ptr
#include <set>     // for std::set
#include <string>  // for std::string
#include <vector>  // for std::vector

class vtkClusteredLightingAssignmentBackend;
class vtkClusteredLightingSurfaceBoxes;
class vtkRenderer;
struct vtkClusteredLightingLightCollection;
struct vtkClusteredLightingSourceKey;

/// Why an update did work (a bit set; 0: nothing changed, nothing was done).
enum vtkClusteredLightingDirtyReason : unsigned int
{
  CL_DIRTY_LIGHTS = 1u << 0,      ///< a light source was added, removed or modified
  CL_DIRTY_PREPARATION = 1u << 1, ///< cutoff, error budget, Morton order or far field changed
  CL_DIRTY_VIEW = 1u << 2,        ///< the camera matrices changed
  CL_DIRTY_GRID = 1u << 3,        ///< tiles, slices, viewport, depth range or slicing changed
  CL_DIRTY_MODE = 1u << 4,        ///< shading mode, bounds method or per-cluster culling changed
  CL_DIRTY_RESOURCES = 1u << 5,   ///< first update, another window, or GL objects released
  CL_DIRTY_DEPTHS = 1u << 6       ///< depth-aware clusters: the visible depths changed
};

/// The cluster grid as the pass's options describe it.
struct vtkClusteredLightingGridOptions
{
  int TilesX = 32, TilesY = 16, Slices = 32;
  enum class Slicing
  {
    Auto, ///< exponential for perspective cameras, linear for parallel ones
    Exponential,
    Linear
  };
  Slicing Scheme = Slicing::Auto;
  vtkClusteredLighting::BoundsMethod Bounds = vtkClusteredLighting::BoundsMethod::Tangent;
};

/// What one update needs; the pass fills it from its options, the camera and the lights.
struct vtkClusteredLightingAssignerInputs
{
  vtkClusteredLightingLightCollection* Lights = nullptr; ///< Read() is called when needed
  vtkClusteredLighting::LightPreparationOptions Preparation;
  /// > 0: choose the cutoffs of culled and of split lights and the far field's resolution
  /// for it (from Preparation.Cutoff; FarField.TargetNodes ignored;
  /// vtkClusteredLightingFarFieldBudget.h)
  double ErrorBudget = 0.0;
  bool Windowed = false; ///< windowed falloff (the error budget accounts for it)
  vtkClusteredLighting::FarFieldOptions FarField;
  /// The option that asked for the far specular's bins (FarField.SpecularBins), named in
  /// the warning when they cannot be made.
  const char* SpecularBinsOption = "FarFieldSpecularBins";
  /// World box of the geometry to shade (the far field's region; invalid: the lights' box).
  glm::dvec3 RegionLo = glm::dvec3(1.0), RegionHi = glm::dvec3(-1.0);
  /// Where surfaces lie: the far field sums only the blocks they read (nullptr: every
  /// block; vtkClusteredLightingFarFieldBlocks.h).
  const vtkClusteredLightingSurfaceBoxes* Surfaces = nullptr;
  /// Whether fragments may lie off their surfaces (a multisampled framebuffer shades
  /// partly covered pixels at their centres): the far field then also sums the blocks
  /// that the fragments the prepass recorded (Depths, with DepthMax) reach, every block
  /// without that record (vtkClusteredLightingFarFieldBlocks.h, MarkFarFieldBlocksOfPixels).
  bool FragmentsOffSurfaces = false;
  vtkClusteredLighting::ViewParameters View; ///< see vtkClusteredLightingAssigner::ComputeView
  bool Clustered = true;                     ///< false: brute force (no list and master passes)
  bool PerClusterCulling = true;
  int MaximumTextureSize = 0; ///< 0: the context's limit
  bool MeasureTimings = false;
  /// Depth-aware clusters: the viewport's window depths after a depth prepass (nullptr:
  /// whole frustum cells, camera-range slicing), and the margins of their readback.
  const vtkClusteredLighting::DepthImage* Depths = nullptr;
  vtkClusteredLighting::DepthBoundsOptions DepthOptions;
};

/// What an update did and found; SetShaderParameters reads only this.
struct vtkClusteredLightingAssignment
{
  unsigned int Reasons = 0; ///< vtkClusteredLightingDirtyReason bits
  bool LightsUploaded = false;
  bool Reassigned = false; ///< the view records (and list and master) were rebuilt
  bool Enabled = false;    ///< clustered lights are shaded in this render
  bool Clustered = true;
  bool Linear = false; ///< linear depth slices

  // Statistics.
  int NumberOfLights = 0; ///< valid lights
  int NumberOfRejected = 0;
  int NumberOfAlwaysOn = 0;
  int NumberOfBelowCutoff = 0;
  int NumberOfSpots = 0;
  int FirstSpot = 0; ///< index of the first spot light in the uploaded order (lights when none)
  int NumberOfExplicitRadius = 0; ///< lights with an explicit radius (their model's range)
  int NumberOfAssigned = 0;       ///< lights with at least one list-pass quad
  int NumberOfQuads = 0;
  /// The most lights one cluster's list can hold (ComputeMostLightsInACluster; up to
  /// 50,000 lights, the number of lights: a bound that needs no count)
  int MostLightsInACluster = 0;
  int Grid[3] = { 0, 0, 0 }; ///< cluster grid used (smaller than asked when that cannot hold
                             ///< the lights)
  bool Bypassed = false;     ///< clustered shading asked, every light reaches every cluster:
                             ///< shaded by the plain loop (same image, less work)
  double MeanLightsPerCluster = 0.0;     ///< at the last assignment, before per-cluster culling
  double EffectiveCutoff = 1.0 / 1024.0; ///< of the culled lights
  double EffectiveFarFieldCutoff = 1.0 / 1024.0; ///< of the lights the far field may split
  double AssignmentTime = 0.0;                   ///< ms, when Reassigned
  double LightUpdateTime = 0.0; ///< ms: reading, preparing and uploading changed lights,
                                ///< building the far field included
  // Depth-aware clusters (vtkClusteredLightingDepthBounds.h).
  bool DepthAware = false;      ///< the list pass cut the cells to the visible depths
  double DepthBoundsTime = 0.0; ///< ms: the visible range and per-cluster depths (CPU)
  double VisibleDepthRange[2] = { 0.0, 0.0 }; ///< nearest and deepest opaque depth (VC)
  double SlicingRange[2] = { 0.0, 0.0 };      ///< the slices' depth range in use (VC)
  double NonEmptyClusterFraction = 1.0;       ///< clusters holding fragments (depth-aware)

  // The far field (Rendering/Core/vtkClusteredLightingFarField.h).
  bool FarField = false; ///< lights have far parts: the shading code adds the far field
  int NumberOfFarFieldLights = 0;
  int NumberOfPackedFarFieldLights = 0; ///< FarFieldPlan::NumberOfPackedNearRadii
  double FarFieldBuildTime = 0.0;       ///< ms, the last build
  /// Nodes the last build summed (the blocks surfaces read; a build that only adds blocks
  /// for surfaces that moved counts those), and the blocks the grid has and surfaces read.
  std::int64_t FarFieldNodesBuilt = 0;
  std::int64_t FarFieldBlocks = 0, FarFieldBlocksNeeded = 0;
  double FarFieldSpacing = 0.0; ///< grid spacing h (world units)
  double NearRadiusCap = 0.0;   ///< near radius of bright and always-on lights
  int FarFieldDims[3] = { 0, 0, 0 };
  std::int64_t FarFieldNodesTarget = 0; ///< FarFieldOptions::TargetNodes used (0: no far field)
  /// With an error budget: the choice of the far field's resolution (Nodes 0: none made).
  vtkClusteredLighting::FarFieldResolutionChoice FarFieldBudgetChoice;
  bool FarFieldResolutionChosen = false; ///< this update made that choice (again)
  std::uint64_t FarFieldBytes = 0;
  /// The far-field lights share a colour: one channel in 5 textures (3 at order 2), times
  /// FarFieldColor (FindFarFieldSharedColor); else three channels in 14 (7).
  bool FarFieldOneChannel = false;
  bool FarFieldOrder4 = false; ///< the far diffuse to order 4 (FarFieldPlan::Order4Diffuse)
  /// The far specular from directional bins (FarFieldPlan::SpecularBins, built).
  bool FarFieldSpecularBins = false;
  float FarFieldColor[3] = { 0.0f, 0.0f, 0.0f };
  float FarFieldFromVC[16] = { 0 }; ///< VC -> far-field texture coordinates (column-major)
  float WorldFromVC[9] = { 0 };     ///< VC -> world directions (column-major)
  std::array<int, vtkClusteredLighting::FarFieldTextures> FarFieldUnits{}; ///< while bound
  int LobeTableUnit = -1;    ///< the far specular's table, while bound
  int SpecularBinsUnit = -1; ///< the far specular's bins, while bound
  int SpecularBinsAxis = 2;  ///< the grid axis their slabs are stacked along
  std::uint64_t ListBytes = 0, MasterBytes = 0, LightBufferBytes = 0;

  // Messages new in this update (each problem is reported once while it persists).
  /// Invalid lights newly found (warnings), grouped by light set and capped per set.
  std::vector<vtkClusteredLighting::ProblemGroup> NewProblems;
  std::string NewError;                 ///< a limit that keeps the lights from rendering
  std::vector<std::string> NewWarnings; ///< a smaller grid, clustering that cannot cull

  // Shading inputs.
  int MasterTexels = 1; ///< master texels per cluster (a compile-time constant of the GLSL)
  vtkClusteredLighting::ShadingParameters Shading;
  int LightDataUnit = -1, LightViewUnit = -1, ListUnit = -1, MasterUnit = -1; ///< while bound
};

/// What the last assignment used (a copy made for tests, GetSnapshot()).
struct vtkClusteredLightingAssignmentSnapshot
{
  bool Valid = false;
  vtkClusteredLighting::ClusterGridParams Grid; ///< includes the camera near/far
  glm::dmat4 WCVC = glm::dmat4(1.0);
  glm::dmat4 VCDC = glm::dmat4(1.0);
  vtkClusteredLighting::ClusterTextureLayout Layout;
  std::vector<vtkClusteredLighting::PreparedLight> Lights; ///< upload order, world coords
  int NumberOfQuads = 0;
  vtkClusteredLighting::FarFieldPlan FarField;          ///< Active when the far field is shaded
  vtkClusteredLighting::ClusterDepthBounds DepthBounds; ///< Valid when depth-aware
  bool SpotConeCulling = true; ///< spot lights were assigned by their cones
};

class vtkClusteredLightingAssigner
{
public:
  vtkClusteredLightingAssigner();
  ~vtkClusteredLightingAssigner();

  /**
   * The view step's input: the matrices the mappers use for this renderer (VTK caches
   * them per camera and renderer), the viewport, the camera clipping range as the
   * clustering depth range, and the grid.
   */
  static vtkClusteredLighting::ViewParameters ComputeView(
    vtkRenderer* renderer, const vtkClusteredLightingGridOptions& grid);

  /// Brings the assignment up to date for this render (the window's context is current).
  const vtkClusteredLightingAssignment& Update(
    vtkOpenGLRenderWindow* rw, const vtkClusteredLightingAssignerInputs& inputs);

  /// The result of the last update.
  const vtkClusteredLightingAssignment& GetResult() const { return this->Result; }

  /// Whether `key` names other light sources than the last update read: an update with it
  /// prepares the lights again (CL_DIRTY_LIGHTS).
  bool AreNewSources(const vtkClusteredLightingSourceKey& key) const;

  /// The far field's stated error bound over probe points (SummarizeFarFieldErrorBound,
  /// Rendering/Core/vtkClusteredLightingFarFieldBound.h) for the last build; zeros without
  /// a far field. CPU only, the probes on VTK's SMP threads (the core's serial summary,
  /// bit for bit); its cost grows with the number of lights.
  vtkClusteredLighting::FarFieldBoundSummary SummarizeFarFieldErrorBound() const;

  ///@{
  /// Bind the light records (and, clustered, list and master) for the shading pass and
  /// fill the result's texture units; unbind after the delegate rendered.
  void ActivateShading();
  void DeactivateShading();
  ///@}

  /// The depth prepass's recording targets for this renderer (multisampled framebuffers).
  vtkClusteredLightingSampleDepths* GetSampleDepths() { return &this->SampleDepths; }
  /// The copy of this renderer's last prepass depths (ReuseDepthPrepass).
  vtkClusteredLightingSavedDepth* GetSavedDepth() { return &this->SavedDepth; }

  /// The window whose context holds the GL objects (null after it was deleted).
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }

  /// Releases every GL object, in the context of w (or of the assigner's window, for a
  /// null w, while it lives), made current for the duration.
  void ReleaseGraphicsResources(vtkWindow* w);

  int GetNumberOfGLObjects() const;

  ///@{
  /// For tests (vtkClusteredLightingInspector).
  vtkClusteredLightingAssignmentSnapshot GetSnapshot() const;
  bool ReadBackAssignment(std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& master);
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;
  ///@}

private:
  vtkClusteredLightingAssigner(const vtkClusteredLightingAssigner&) = delete;
  void operator=(const vtkClusteredLightingAssigner&) = delete;

  /// Preparation options as a comparable value.
  struct PreparationKey
  {
    double Cutoff = 0.0, FarFieldCutoff = 0.0, ErrorBudget = 0.0;
    bool Windowed = false, MortonOrder = true;
    vtkClusteredLighting::FarFieldOptions FarField;
    glm::dvec3 RegionLo = glm::dvec3(0.0), RegionHi = glm::dvec3(0.0);
    bool operator!=(const PreparationKey& o) const;
  };
  /// Everything a view assignment depends on, as a comparable value.
  struct ViewKey
  {
    glm::dmat4 WCVC = glm::dmat4(0.0), VCDC = glm::dmat4(0.0);
    vtkClusteredLighting::ClusterGridParams Grid;
    int Bounds = 0;
    bool Clustered = true, PerClusterCulling = true, SpotConeCulling = true;
    unsigned int CompareWith(const ViewKey& o) const; ///< dirty reasons between the two
  };

  void SetWindow(vtkOpenGLRenderWindow* rw);
  void OnWindowDeleted();
  void PrepareLights(const vtkClusteredLightingAssignerInputs& inputs);
  vtkClusteredLighting::FarFieldOptions ChooseFarFieldOptions(
    const vtkClusteredLightingAssignerInputs& inputs, double budget,
    const vtkClusteredLighting::LightPreparationOptions& preparation);
  static vtkClusteredLighting::FarFieldBoundSummary SummarizeOnThreads(
    const vtkClusteredLighting::FarFieldBuildInputs& in);
  void UpdateRegion(const vtkClusteredLightingAssignerInputs& inputs);
  /// The far field's blocks that the surfaces read (FarFieldNeeded), marked again when
  /// the surfaces or the grid changed; with FragmentsOffSurfaces, and those the recorded
  /// fragments reach, marked again when the depth-aware clusters or the view changed.
  void UpdateFarFieldBlocks(const vtkClusteredLightingAssignerInputs& inputs);
  bool CheckLimits(vtkOpenGLRenderWindow* rw, vtkClusteredLightingAssignerInputs& inputs);
  void CheckCulling(const vtkClusteredLightingAssignerInputs& inputs);
  static bool ReachesEveryCluster(const vtkClusteredLighting::PreparedLight& light);
  void Assign(vtkOpenGLRenderWindow* rw, const vtkClusteredLightingAssignerInputs& inputs);
  vtkClusteredLighting::ViewData ComputeViewDataInParallel(
    const vtkClusteredLightingAssignerInputs& inputs) const;
  void UpdateDepthBounds(vtkClusteredLightingAssignerInputs& inputs);

  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  unsigned long WindowObserver = 0;

  // Lights.
  bool HaveSources = false;
  std::vector<const void*> SourceObjects;
  unsigned long long SourceMTime = 0;
  PreparationKey LastPreparation;
  vtkClusteredLighting::PreparedLights Prepared;
  /// The split lights' cutoff and the far field's resolution chosen for the error budget,
  /// and what they were chosen for: chosen again when the preparation key or the number
  /// of (split) lights changes, kept while lights move or change brightness
  /// (ChooseFarFieldOptions).
  vtkClusteredLighting::FarFieldBudgetChoice BudgetChoice;
  PreparationKey BudgetChoiceKey;
  std::size_t BudgetChoiceLights = 0, BudgetChoiceSplit = 0;
  bool HaveBudgetChoice = false;
  double EffectiveCutoff = 1.0 / 1024.0, EffectiveFarFieldCutoff = 1.0 / 1024.0;
  std::set<std::string> ReportedProblems;
  std::string ReportedError;
  std::string ReportedGridWarning;
  int ReportedCullingWarning = 0;             ///< kind of the last culling warning, 0: none
  std::size_t NumberReachingEveryCluster = 0; ///< prepared lights (ReachesEveryCluster)
  bool LightDataUploaded = false;

  // View.
  ViewKey LastView;
  vtkClusteredLighting::ClusterDepthBounds DepthBounds; ///< of the last assignment
  std::uint64_t DepthBoundsVersion = 0;                 ///< grows when DepthBounds change
  bool AssignmentValid = false;
  vtkClusteredLighting::ClusterTextureLayout Layout;

  vtkClusteredLightingTextureBuffer LightData;
  vtkClusteredLightingTextureBuffer LightView;
  vtkClusteredLighting::FarFieldPlan FarFieldPlan;
  vtkClusteredLightingFarFieldTextures FarField;
  /// Per block of the far field's grid: its nodes some fragment reads, as a mask
  /// (UpdateFarFieldBlocks), and what they were marked from: the surfaces' marks
  /// (SurfaceNeeded), with those of the recorded fragments where fragments may lie off
  /// their surfaces.
  std::vector<std::uint64_t> FarFieldNeeded;
  std::vector<std::uint64_t> SurfaceNeeded;
  std::int64_t NeededBlocks = 0;  ///< blocks with a node marked in FarFieldNeeded
  std::int64_t SurfaceBlocks = 0; ///< blocks with a node marked in SurfaceNeeded
  bool PixelsMarked = false;      ///< FarFieldNeeded has the recorded fragments' marks
  std::uint64_t MarkedDepthBoundsVersion = 0;
  glm::dmat4 MarkedWCVC = glm::dmat4(0.0), MarkedVCDC = glm::dmat4(0.0);
  bool FarFieldNeededBuilt = false; ///< whether the textures hold every node marked
  std::uint64_t NeededVersion = 0;
  bool NeededEverywhere = true;
  vtkClusteredLighting::FarFieldGrid NeededGrid;
  vtkClusteredLightingSampleDepths SampleDepths;
  vtkClusteredLightingSavedDepth SavedDepth;
  glm::dvec3 RegionLo = glm::dvec3(1.0), RegionHi = glm::dvec3(-1.0); ///< the far field's region
  glm::dvec3 RegionAnchor = glm::dvec3(0.0); ///< its node planes (see UpdateRegion)
  std::unique_ptr<vtkClusteredLightingAssignmentBackend> Backend;

  vtkClusteredLightingAssignment Result;
};

#endif
