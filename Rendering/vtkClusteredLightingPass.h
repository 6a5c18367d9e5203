// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingPass
 * @brief   render pass that shades thousands of point and spot lights by clustering
 *
 * Drop-in use: `vtkNew<vtkClusteredLightingPass> pass; renderer->SetPass(pass);`
 *
 * The pass wraps a delegate (by default a vtkRenderStepsPass whose translucent step
 * behaves like stock VTK: order-independent transparency, or depth peeling when the
 * renderer asks for it), so opaque, translucent and overlay props render as before.
 *
 * Clustered lights come from
 *  1. every switched-on positional vtkLight of the renderer (point lights and spot lights
 *     with a cone angle < 90), when ClusterRendererLights is on (default). While the
 *     delegate renders, these lights are hidden from the renderer so that VTK does not
 *     generate its per-light shader code for them (stock VTK 9.1 needs minutes to compile
 *     hundreds of lights and fails to link at about 1,090); directional lights and the
 *     headlight stay with VTK's own lighting code;
 *  2. vtkClusteredLightSet objects added with AddLightSet(), for tens of thousands of
 *     lights without one vtkObject per light.
 *
 * Algorithm (compute-less clustered lighting, after wizgrav/cl2): the view frustum is cut
 * into TilesX x TilesY screen tiles and Slices depth slices (exponential or linear
 * between the camera clipping planes). Each frame in which lights, camera or viewport
 * changed:
 *  - CPU (double precision, GL-free core in Rendering/Core): every light gets an influence
 *    radius (where its contribution falls to Cutoff), exact conservative screen bounds of
 *    its sphere under the actual projection (off-axis and parallel included, no NaN when
 *    the camera is inside or the light straddles the near plane), snapped outward to a
 *    tile and slice range;
 *  - list pass: one instanced draw of one quad per visible light into an R32UI "list"
 *    texture holding, per cluster, a 32-light bitmask per batch of 32 lights; bits are
 *    OR-ed with glLogicOp(GL_OR);
 *  - master pass: one full-screen draw folds the list into an R32UI "master" texture with
 *    one bit per non-empty batch.
 * The polydata fragment shaders then find their cluster, walk the master bits, then the
 * list bits, and shade only those lights, with VTK's own positional-light formulas
 * (attenuation 1/(a0 + a1 d + a2 d^2), spot cone and exponent, diffuse and specular of
 * the actor's vtkProperty, or VTK's PBR terms for PBR actors). Lights are sorted in
 * Morton order so that nearby lights share batches.
 *
 * Accuracy: the only approximation is the cutoff: a light is ignored where its
 * contribution is below Cutoff (default 1/1024, a quarter of an 8-bit step). Lights that
 * never fall off (VTK's default attenuation (1, 0, 0)) are always-on lights, assigned to
 * every cluster, never dropped. ShadingMode BRUTE_FORCE evaluates every light for every
 * fragment with the same light model (explicit radius, windowed falloff, spot cone) and no
 * culling or cutoff: the reference for images and speed comparisons.
 *
 * VTK's own lights (headlight, light kit, directional and camera lights) are shaded by
 * VTK's code exactly as without the pass: the pass keeps the lighting complexity VTK picks
 * for the renderer's whole light collection (a switched-off positional placeholder light
 * when needed), so the code VTK generates for them does not change.
 *
 * Limits: the list texture is (X*Z*C) x (Y*R) texels for C columns of R batches; with
 * GL_MAX_TEXTURE_SIZE 16384 the default 32x16x32 grid holds 524,288 lights. Past a
 * limit the pass reports an error naming the limit and renders without the clustered
 * lights; it never truncates silently. Invalid lights (NaN/Inf, negative values, bad
 * attenuation) are skipped with a warning naming them.
 *
 * Memory at the default grid (X*Y*Z = 16384 clusters): list = 16384 * ceil(N/32) * 4
 * bytes (8 MiB at 4,096 lights, 128 MiB at 65,536), master = 16384 * ceil(N/1024) * 4
 * bytes, light records 64 bytes per light (+32 per visible light for the list pass).
 *
 * @sa vtkClusteredLightSet vtkRenderStepsPass vtkLight
 */
#ifndef vtkClusteredLightingPass_h
#define vtkClusteredLightingPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingClusteredModule.h" // For export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkClusteredLightSet;
class vtkClusteredLightingAssigner;
class vtkRenderer;
struct vtkClusteredLightingAssignerInputs;
struct vtkClusteredLightingAssignment;
struct vtkClusteredLightingLightCollection;

class VTKRENDERINGCLUSTERED_EXPORT vtkClusteredLightingPass : public vtkOpenGLRenderPass
{
public:
  static vtkClusteredLightingPass* New();
  vtkTypeMacro(vtkClusteredLightingPass, vtkOpenGLRenderPass)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Render the delegate with clustered lighting.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Release every GL object the pass made for the given window (all windows if null),
   * and the delegate's.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The pass that renders the scene. Default is a vtkRenderStepsPass whose translucent
   * step matches stock VTK (OIT, or depth peeling when the renderer uses it).
   */
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);
  ///@}

  ///@{
  /**
   * Bulk light sets shaded by the pass, in addition to the renderer's positional lights.
   */
  void AddLightSet(vtkClusteredLightSet* lights);
  void RemoveLightSet(vtkClusteredLightSet* lights);
  void RemoveAllLightSets();
  int GetNumberOfLightSets() const;
  vtkClusteredLightSet* GetLightSet(int i) const;
  ///@}

  ///@{
  /**
   * Take the renderer's switched-on positional vtkLights over as clustered lights.
   * Default is on.
   */
  vtkSetMacro(ClusterRendererLights, bool);
  vtkGetMacro(ClusterRendererLights, bool);
  vtkBooleanMacro(ClusterRendererLights, bool);
  ///@}

  ///@{
  /**
   * Screen tiles across (X) and down (Y), and depth slices (Z), in [1, 256].
   * Defaults are 32, 16 and 32.
   */
  vtkSetClampMacro(TilesX, int, 1, 256);
  vtkGetMacro(TilesX, int);
  vtkSetClampMacro(TilesY, int, 1, 256);
  vtkGetMacro(TilesY, int);
  vtkSetClampMacro(Slices, int, 1, 256);
  vtkGetMacro(Slices, int);
  ///@}

  enum SlicingSchemes
  {
    SLICING_AUTO = 0,        ///< exponential for perspective, linear for parallel cameras
    SLICING_EXPONENTIAL = 1, ///< slice k starts at near * (far/near)^(k/Z)
    SLICING_LINEAR = 2       ///< equal slices between near and far
  };
  ///@{
  /**
   * How depth between the camera clipping planes is cut into slices.
   * Default is SLICING_AUTO.
   */
  vtkSetClampMacro(SlicingScheme, int, SLICING_AUTO, SLICING_LINEAR);
  vtkGetMacro(SlicingScheme, int);
  ///@}

  ///@{
  /**
   * Contribution (per light, per channel, for a white material) below which a light is
   * ignored; it sets each light's influence radius. Range [1e-9, 1].
   * Default is 1/1024 (a quarter of an 8-bit step).
   */
  vtkSetClampMacro(Cutoff, double, 1e-9, 1.0);
  vtkGetMacro(Cutoff, double);
  ///@}

  ///@{
  /**
   * Error budget: the largest acceptable image error (in [0, 1], for a white material with
   * Diffuse + Specular <= 1). When > 0 the pass ignores Cutoff and, whenever the lights
   * change, picks the largest cutoff whose summed cut tails stay within the budget at
   * sample points spread over the lights' bounding box and at the lights themselves (a
   * conservative bound: N.L is taken as 1). GetEffectiveCutoff() reports the choice.
   * Default is 0 (use Cutoff).
   */
  vtkSetClampMacro(ErrorBudget, double, 0.0, 1.0);
  vtkGetMacro(ErrorBudget, double);
  vtkGetMacro(EffectiveCutoff, double);
  ///@}

  enum Falloffs
  {
    FALLOFF_HARD_CUT = 0, ///< VTK's attenuation, zero beyond the radius
    FALLOFF_WINDOWED = 1  ///< VTK's attenuation times (1 - (d/r)^4)^2 (smooth, darker)
  };
  ///@{
  /**
   * Falloff at the influence radius. Default is FALLOFF_HARD_CUT, which matches VTK
   * within the cutoff.
   */
  vtkSetClampMacro(Falloff, int, FALLOFF_HARD_CUT, FALLOFF_WINDOWED);
  vtkGetMacro(Falloff, int);
  ///@}

  ///@{
  /**
   * Far field: what each light's near radius cuts off is added back, not dropped. Every
   * light without an explicit radius (VTK's inverse-square lights, always-on lights with
   * attenuation (1, 0, 0), ...), except spot lights, is split smoothly at its near radius:
   * the near part is evaluated exactly through the clusters, the far part is summed on a
   * world-space grid over the visible geometry (order-2 moments of its directions per node)
   * and added to every fragment by trilinear interpolation, diffuse and Phong specular.
   * Rebuilt only when the lights change (or the geometry leaves the grid's box), never
   * for a moving camera. The error has a stated per-pixel bound (docs/far-field.md).
   * Off: such lights are cut at their cutoff radius (darker than VTK, see Cutoff).
   * Default is on.
   */
  vtkSetMacro(FarField, bool);
  vtkGetMacro(FarField, bool);
  vtkBooleanMacro(FarField, bool);
  ///@}

  ///@{
  /**
   * Resolution of the far field: the number of grid nodes over the bounding box of the
   * visible geometry (112 bytes of GPU memory each: 7 RGBA32F texels). The grid spacing h follows,
   * and the near radius of bright and always-on lights is FarFieldCellsPerRadius * h: more nodes
   * mean smaller near radii, fewer lights evaluated per fragment, longer far-field builds.
   * Range [512, 16777216]. Default is 32768.
   */
  vtkSetClampMacro(FarFieldResolution, int, 512, 16777216);
  vtkGetMacro(FarFieldResolution, int);
  ///@}

  ///@{
  /**
   * Advanced: grid cells per near radius (the far field's accuracy: its error was found
   * flat from 2 cells per near radius on, docs/far-field.md). Range [1, 8]. Default is 2.
   */
  vtkSetClampMacro(FarFieldCellsPerRadius, double, 1.0, 8.0);
  vtkGetMacro(FarFieldCellsPerRadius, double);
  ///@}

  ///@{
  /**
   * Advanced: how uncertain (in [0, 1] colour units) the far field may leave a fragment
   * near saturation. The node moments prove an interval the far light's true contribution
   * lies in; where that interval is wider than this and decides whether the fragment
   * saturates (its lowest value is below 1, its highest above), the far parts are summed
   * exactly, light by light. Bright far fields (lights that light the whole scene) need
   * it on a few fragments; faint ones never. PBR actors (tone-mapped) use the width
   * alone. 1 turns it off. Range [0, 1]. Default is 2/255.
   */
  vtkSetClampMacro(FarFieldTolerance, double, 0.0, 1.0);
  vtkGetMacro(FarFieldTolerance, double);
  ///@}

  ///@{
  /**
   * Advanced: how the far field's build groups lights (Barnes-Hut). A group of lights
   * seen from far enough is summed as one light at its centroid when its extent is below
   * this fraction of its distance (relative error about its square); 0 sums every light
   * at every node (exact, slow). The error it makes is inside the stated bound
   * (ComputeFarFieldErrorBound), which grows a little with it. Range [0, 1]. Default is 1.
   */
  vtkSetClampMacro(FarFieldGrouping, double, 0.0, 1.0);
  vtkGetMacro(FarFieldGrouping, double);
  ///@}

  ///@{
  /**
   * Advanced: how many lights per point, on average over the box of the visible geometry,
   * the near field may evaluate exactly (a light counts at most once per point). When all
   * lights fit whole, each keeps its cutoff radius and the far field holds only the tails
   * past it (none at all for up to 16 vtkLights that reach everywhere); otherwise the
   * lights with the largest radii are cut to one radius R that fills the budget (a few
   * bright lights among many keep exact highlights), never below FarFieldCellsPerRadius
   * grid cells, and the far field carries the rest. Range [0, 1e6]. Default is 16.
   */
  vtkSetClampMacro(NearFieldBudget, double, 0.0, 1e6);
  vtkGetMacro(NearFieldBudget, double);
  ///@}

  enum ShadingModes
  {
    SHADING_CLUSTERED = 0,  ///< walk the fragment's cluster lists
    SHADING_BRUTE_FORCE = 1 ///< the same light model, every light for every fragment (reference)
  };
  ///@{
  /**
   * Clustered shading, or brute force for reference images and speed comparisons.
   * Default is SHADING_CLUSTERED.
   */
  vtkSetClampMacro(ShadingMode, int, SHADING_CLUSTERED, SHADING_BRUTE_FORCE);
  vtkGetMacro(ShadingMode, int);
  ///@}

  enum DebugViews
  {
    DEBUG_NONE = 0,
    DEBUG_CLUSTER_INDEX = 1,   ///< (tile x, tile y, slice) / (X-1, Y-1, Z-1) as RGB
    DEBUG_HEAT_MAP = 2,        ///< lights evaluated per pixel, colour map up to HeatMapMaximum
    DEBUG_EVALUATED_COUNT = 3, ///< lights evaluated (R + 256 G), lights reaching (B, saturates)
    DEBUG_REACHED_COUNT = 4,   ///< lights that reach the fragment (R + 256 G)
    DEBUG_NON_FINITE = 5,      ///< red where the lit colour is NaN or Inf
    DEBUG_NORMAL = 6           ///< the shading normal (view coordinates) as 0.5 + 0.5 N
  };
  ///@{
  /**
   * Debug view replacing the shaded colour of lit surfaces (compiled in only when set).
   * Default is DEBUG_NONE.
   */
  vtkSetClampMacro(DebugView, int, DEBUG_NONE, DEBUG_NORMAL);
  vtkGetMacro(DebugView, int);
  ///@}

  ///@{
  /**
   * Lights per pixel shown as the hottest colour of DEBUG_HEAT_MAP. Default is 64.
   */
  vtkSetClampMacro(HeatMapMaximum, double, 1.0, 1e6);
  vtkGetMacro(HeatMapMaximum, double);
  ///@}

  ///@{
  /**
   * Sort lights in Morton order before upload so that nearby lights share batches.
   * Default is on.
   */
  vtkSetMacro(MortonOrder, bool);
  vtkGetMacro(MortonOrder, bool);
  vtkBooleanMacro(MortonOrder, bool);
  ///@}

  enum BoundsMethods
  {
    BOUNDS_TANGENT = 0,          ///< exact tangent bounds, conservative
    BOUNDS_CENTER_DEPTH_QUAD = 1 ///< NOT conservative; only to measure what it gets wrong
  };
  ///@{
  /**
   * How light spheres are bounded on screen. Default is BOUNDS_TANGENT.
   */
  vtkSetClampMacro(BoundsMethod, int, BOUNDS_TANGENT, BOUNDS_CENTER_DEPTH_QUAD);
  vtkGetMacro(BoundsMethod, int);
  ///@}

  ///@{
  /**
   * In the list pass, test each light's sphere against the view-space bounding box of
   * every cluster of its screen rectangle and slice range (with a margin far above float
   * error), instead of assigning the whole range. Removes the corners of the range, so
   * fewer lights are evaluated per fragment; stays conservative. Default is on.
   */
  vtkSetMacro(PerClusterCulling, bool);
  vtkGetMacro(PerClusterCulling, bool);
  vtkBooleanMacro(PerClusterCulling, bool);
  ///@}

  ///@{
  /**
   * Largest texture side, in texels, the pass allocates for its list and master
   * textures; 0 means the context's GL_MAX_TEXTURE_SIZE. A smaller value bounds GPU memory
   * (the list texture is at most MaximumTextureSize^2 * 4 bytes) and lowers the light
   * limit accordingly (see GetMaximumNumberOfLights). Default is 0.
   */
  vtkSetClampMacro(MaximumTextureSize, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumTextureSize, int);
  ///@}

  ///@{
  /**
   * Finish the GL work around the assignment and shading stages and record their times
   * (GetLastAssignmentTime, GetLastShadingTime). Costs a pipeline stall; for
   * benchmarks. Default is off.
   */
  vtkSetMacro(MeasureTimings, bool);
  vtkGetMacro(MeasureTimings, bool);
  vtkBooleanMacro(MeasureTimings, bool);
  ///@}

  ///@{
  /**
   * Statistics of the last render.
   */
  vtkGetMacro(NumberOfClusteredLights, int);   ///< valid lights shaded by the pass
  vtkGetMacro(NumberOfRejectedLights, int);    ///< invalid lights skipped with a warning
  vtkGetMacro(NumberOfAlwaysOnLights, int);    ///< lights that never fall off
  vtkGetMacro(NumberOfLightsBelowCutoff, int); ///< below the cutoff everywhere
  vtkGetMacro(NumberOfSpotLights, int);
  vtkGetMacro(NumberOfAssignedLights, int);    ///< lights drawn in the list pass (visible)
  vtkGetMacro(LastAssignmentTime, double);     ///< ms, view records + list + master passes
  vtkGetMacro(LastLightUpdateTime, double);    ///< ms, reading, preparing and uploading lights
  vtkGetMacro(LastShadingTime, double);        ///< ms, delegate render (MeasureTimings)
  vtkGetMacro(NumberOfFarFieldLights, int);    ///< lights split into near and far parts
  vtkGetMacro(LastFarFieldBuildTime, double);  ///< ms, the last far-field build
  vtkGetMacro(FarFieldGridSpacing, double);    ///< world units, 0 without a far field
  vtkGetMacro(NearRadiusCap, double);          ///< near radius of bright and always-on lights
  vtkGetVector3Macro(FarFieldDimensions, int); ///< nodes per axis
  vtkGetMacro(FarFieldTextureBytes, vtkTypeUInt64);
  vtkGetMacro(LastAssignmentUpdated, bool); ///< whether the last render reassigned lights
  ///@}

  /**
   * The far field's stated error bound (docs/far-field.md) for the last frame's lights, in
   * 8-bit steps of a white, fully diffuse surface: the largest over probe points spread
   * through the far field's region (each with the 6 axis normals) and over the renderers
   * the pass renders. Computed on request on the CPU (milliseconds for thousands of
   * lights, about a second for 500,000), never during a render. 0 without a far field.
   * The bound at a pixel depends on its position, normal and material; the tests check it
   * pixel by pixel against brute force.
   */
  double ComputeFarFieldErrorBound();

  ///@{
  /**
   * Counters since construction: light-data uploads, list/master runs, shader rebuilds
   * of mappers that use the pass.
   */
  vtkGetMacro(NumberOfLightUploads, int);
  vtkGetMacro(NumberOfAssignmentUpdates, int);
  vtkGetMacro(NumberOfShaderBuilds, int);
  ///@}

  ///@{
  /**
   * GPU memory held for the last rendered renderer, in bytes.
   */
  vtkGetMacro(ListTextureBytes, vtkTypeUInt64);
  vtkGetMacro(MasterTextureBytes, vtkTypeUInt64);
  vtkGetMacro(LightBufferBytes, vtkTypeUInt64);
  ///@}

  /**
   * Number of GL objects the pass holds across all renderers (textures, buffers, FBO,
   * VAO). Zero after ReleaseGraphicsResources.
   */
  int GetNumberOfGLObjects() const;

  /**
   * Largest number of lights a grid can hold with a given maximum texture size.
   */
  static vtkTypeInt64 GetMaximumNumberOfLights(
    int tilesX, int tilesY, int slices, int maxTextureSize);

  ///@{
  /**
   * vtkOpenGLRenderPass hooks: inject the clustered shading code, set its uniforms.
   */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  ///@}

protected:
  vtkClusteredLightingPass();
  ~vtkClusteredLightingPass() override;

  vtkRenderPass* DelegatePass = nullptr;

  bool ClusterRendererLights = true;
  int TilesX = 32;
  int TilesY = 16;
  int Slices = 32;
  int SlicingScheme = SLICING_AUTO;
  double Cutoff = 1.0 / 1024.0;
  double ErrorBudget = 0.0;
  double EffectiveCutoff = 1.0 / 1024.0;
  int Falloff = FALLOFF_HARD_CUT;
  int ShadingMode = SHADING_CLUSTERED;
  int DebugView = DEBUG_NONE;
  double HeatMapMaximum = 64.0;
  bool MortonOrder = true;
  int BoundsMethod = BOUNDS_TANGENT;
  bool PerClusterCulling = true;
  int MaximumTextureSize = 0;
  bool MeasureTimings = false;
  bool FarField = true;
  int FarFieldResolution = 32768;
  double FarFieldCellsPerRadius = 2.0;
  double FarFieldTolerance = 2.0 / 255.0;
  double FarFieldGrouping = 1.0;
  double NearFieldBudget = 16.0;

  int NumberOfClusteredLights = 0;
  int NumberOfRejectedLights = 0;
  int NumberOfAlwaysOnLights = 0;
  int NumberOfLightsBelowCutoff = 0;
  int NumberOfSpotLights = 0;
  int NumberOfAssignedLights = 0;
  double LastAssignmentTime = 0.0;
  double LastLightUpdateTime = 0.0;
  int NumberOfFarFieldLights = 0;
  double LastFarFieldBuildTime = 0.0;
  double FarFieldGridSpacing = 0.0;
  double NearRadiusCap = 0.0;
  int FarFieldDimensions[3] = { 0, 0, 0 };
  vtkTypeUInt64 FarFieldTextureBytes = 0;
  double LastShadingTime = 0.0;
  bool LastAssignmentUpdated = false;
  int NumberOfLightUploads = 0;
  int NumberOfAssignmentUpdates = 0;
  int NumberOfShaderBuilds = 0;
  vtkTypeUInt64 ListTextureBytes = 0;
  vtkTypeUInt64 MasterTextureBytes = 0;
  vtkTypeUInt64 LightBufferBytes = 0;

private:
  vtkClusteredLightingPass(const vtkClusteredLightingPass&) = delete;
  void operator=(const vtkClusteredLightingPass&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  // The steps of Render() (see the .cxx).
  void SetUpCamera(vtkRenderer* ren);
  vtkClusteredLightingAssignerInputs MakeAssignerInputs(
    vtkRenderer* ren, vtkClusteredLightingLightCollection& lights) const;
  void ReportAssignment(const vtkClusteredLightingAssignment& result);
  void UpdateShaderVariant(const vtkClusteredLightingAssignment& result);
  void RenderDelegate(const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights,
    vtkClusteredLightingAssigner* assigner);

  // Test hook (Testing/Cxx/vtkClusteredLightingInspector.h): the assigners of the renderers.
  friend class vtkClusteredLightingInspector;
  vtkClusteredLightingAssigner* GetAssigner(vtkRenderer* renderer) const;
  std::vector<vtkClusteredLightingAssigner*> GetAssigners() const;
};

#endif
