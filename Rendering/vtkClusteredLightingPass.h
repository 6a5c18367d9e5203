// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingPass
 * @brief   render pass that shades thousands of point and spot lights by clustering
 *
 * Drop-in use (C++): create the pass with vtkNew, then call renderer->SetPass(pass).
 * In Python: pass = vtkClusteredLightingPass(); renderer.SetPass(pass).
 *
 * The pass wraps a delegate (by default a vtkRenderStepsPass whose steps behave like
 * stock VTK's renderer: order-independent transparency, or depth peeling when the
 * renderer asks for it; the renderer's SSAO, hidden-line removal and FXAA), so opaque,
 * translucent, volume and overlay props render as before.
 *
 * Where the lights come from:
 *
 * - every switched-on positional vtkLight of the renderer (point lights, and spot lights
 *   with a cone angle below 90 degrees) while ClusterRendererLights is on (the default).
 *   VTK does not generate its per-light shader code for them (stock VTK 9.1 needs minutes
 *   to compile hundreds of lights). Directional lights and the headlight stay with VTK.
 *
 * - vtkClusteredLightSet objects added with AddLightSet(): tens of thousands of lights
 *   without one vtkObject per light, also from a VTK pipeline.
 *
 * Which lights are fast, and how accurate: lights with an explicit radius and
 * FALLOFF_WINDOWED are the fastest. Lights as VTK users write them (inverse-square
 * attenuation, no radius) are split: the near part of each light is evaluated exactly,
 * the far part comes from the far field (on by default) with a stated per-pixel error
 * bound (ComputeFarFieldErrorBound, docs/far-field.md). ShadingMode BRUTE_FORCE
 * evaluates every light for every fragment: the exact reference.
 *
 * Saturated fragments stop early (Phong, exact): lights only add, so once a fragment's
 * sum so far (VTK's own lighting, the far field's proven lower bound, the near lights
 * walked) reaches 1 in every channel, the lights left cannot change a colour that is
 * clamped at 1. The pass does this only where that clamp is certain: a fixed-point
 * colour target, an opaque draw, and no code after the lighting that rescales the colour
 * (an actor texture). Under a vtkToneMappingPass (float target), for translucent
 * fragments and for textured actors every light is evaluated.
 *
 * Algorithm (compute-less clustered lighting, after wizgrav/cl2): the view frustum is cut
 * into TilesX by TilesY screen tiles and Slices depth slices. A depth prepass draws the
 * opaque geometry depth-only first (DepthPrepass, kept per renderer only where timing
 * shows it pays: AutomaticDepthPrepass), so no hidden fragment is shaded; its
 * depth, read back, cuts every cluster to the depths and screen rectangle it holds and
 * places the slices between the nearest and deepest visible surfaces
 * (DepthAwareClusters, docs/depth.md). When lights, camera, viewport or visible depths
 * change, the CPU (GL-free core in Rendering/Core) gives every light an influence
 * radius and exact screen and depth bounds; a list pass draws one quad per light into a
 * texture of per-cluster light bitmasks; a master pass folds it into one
 * bit per non-empty batch of 32 lights. The fragment shaders find their cluster, walk
 * the master bits, then the list bits, and shade those lights with VTK's own formulas
 * (attenuation, spot cone, Phong or PBR).
 *
 * A selection render (a vtkHardwareSelector's: VTK's pickers, ParaView's selections)
 * draws ids, not light: the pass does no light work for it and hands it to the renderer's
 * own steps, as without a pass, or to an application's own delegate.
 *
 * Options come in three groups: the main options (ShadingMode, ContributionCutoff,
 * FarFieldCutoff, ErrorBudgetInSteps, Falloff, FarField, FarFieldResolution, the grid),
 * advanced options for tuning (their doc starts with "Advanced"), and diagnostic options
 * for debugging and measurements (their doc starts with "Diagnostic"). PrintSelf prints
 * them in these groups.
 *
 * Limits: with GL_MAX_TEXTURE_SIZE 16384 the default 32 by 16 by 32 grid holds 524,288
 * lights. With more lights the pass renders them all on the largest smaller grid that
 * holds them and warns once (GetClusterGridInUse); only when no grid holds them does it
 * report an error naming the limit. Invalid lights (NaN or Inf, negative values, bad
 * attenuation) are skipped with a warning naming them; no light is dropped silently.
 *
 * Memory at the default grid (16384 clusters): the list texture takes 16384 times
 * ceil(N/32) times 4 bytes (8 MiB at 4,096 lights), the master 16384 times ceil(N/1024)
 * times 4 bytes, light records 64 bytes per light, the far field 112 bytes per node (48
 * when its lights share a colour, FarFieldSharedColor).
 *
 * @sa vtkClusteredLightSet vtkRenderStepsPass vtkLight
 */
#ifndef vtkClusteredLightingPass_h
#define vtkClusteredLightingPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingClusteredModule.h" // For export macro

#include <cstdint> // for std::uint64_t
#include <memory>  // for std::unique_ptr
#include <vector>  // for std::vector

class vtkClusteredLightSet;
class vtkClusteredLightingAssigner;
class vtkOpenGLRenderWindow;
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

  //@{
  /**
   * The pass that renders the scene. Default is a vtkRenderStepsPass whose steps apply
   * the renderer's options as stock VTK does: translucency (OIT, or depth peeling when the
   * renderer uses it), UseSSAO, UseHiddenLineRemoval and UseFXAA (VTK's own render steps
   * skip those three). UseShadows is not applied (a warning says so).
   */
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);
  //@}

  //@{
  /**
   * Bulk light sets shaded by the pass, in addition to the renderer's positional lights.
   */
  void AddLightSet(vtkClusteredLightSet* lights);
  void RemoveLightSet(vtkClusteredLightSet* lights);
  void RemoveAllLightSets();
  int GetNumberOfLightSets() const;
  vtkClusteredLightSet* GetLightSet(int i) const;
  //@}

  //@{
  /**
   * Take the renderer's switched-on positional vtkLights over as clustered lights.
   * Under an application's delegate pass (SetDelegatePass, as ParaView's view does), a
   * frame that shows a shaded volume leaves them to VTK's own lighting code instead
   * (GetRendererLightsLeftToVTK): such a delegate renders the volumes together with the
   * surfaces, and the volume mappers light a volume only with the lights the renderer
   * holds while they render. Default is on.
   */
  vtkSetMacro(ClusterRendererLights, bool);
  vtkGetMacro(ClusterRendererLights, bool);
  vtkBooleanMacro(ClusterRendererLights, bool);
  //@}

  enum ShadingModes
  {
    SHADING_CLUSTERED = 0,  ///< walk the fragment's cluster lists
    SHADING_BRUTE_FORCE = 1 ///< the same light model, every light for every fragment (reference)
  };
  //@{
  /**
   * Clustered shading, or brute force (every light for every fragment, exactly) for
   * reference images and speed comparisons. A value that is not a shading mode is
   * rejected with an error and the mode is kept. When every light reaches every cluster
   * (lights that never fall off and are not split by the far field), clustered shading
   * takes the brute-force loop by itself, which gives the same image faster
   * (GetClusteringBypassed). Default is SHADING_CLUSTERED.
   */
  virtual void SetShadingMode(int mode);
  vtkGetMacro(ShadingMode, int);
  void SetShadingModeToClustered() { this->SetShadingMode(SHADING_CLUSTERED); }
  void SetShadingModeToBruteForce() { this->SetShadingMode(SHADING_BRUTE_FORCE); }
  const char* GetShadingModeAsString();
  //@}

  //@{
  /**
   * Contribution below which a light is ignored in the near field, as a fraction of full
   * brightness (per channel, white material; 1/255 is one 8-bit step). It sets each
   * light's cutoff radius; with the far field on, what lies past that radius is added
   * back by the far field. Not an angle (see vtkLight::SetConeAngle for spot cones).
   * Range [1e-9, 1]. Default is 1/1024 (a quarter of an 8-bit step).
   */
  vtkSetClampMacro(ContributionCutoff, double, 1e-9, 1.0);
  vtkGetMacro(ContributionCutoff, double);
  //@}

  //@{
  /**
   * The cutoff of the lights the far field splits (FarField on; lights without an
   * explicit radius, spot lights included), in ContributionCutoff's units: it sets their
   * near radii, past which the far field holds them. A looser cutoff than the culled lights'
   * costs them nothing here, since no tail is cut: it moves light from the exact near walk
   * to the far field, within its stated bound (ComputeFarFieldErrorBound). 0 gives them
   * ContributionCutoff. With an error budget (ErrorBudgetInSteps) the budget chooses it,
   * from ContributionCutoff outwards, and this option is not used. On the benchmark's bunny
   * (4,096 lights, docs/far-field.md) 1/256 evaluates 2.7 near lights per pixel instead of
   * 12.9 at 1/1024, in about four fifths of the frame, at max 1 step from brute force
   * (stated bound 1.9 steps at probes, 0.7 at 1/1024). Range [0, 1]. Default is 1/256.
   */
  vtkSetClampMacro(FarFieldCutoff, double, 0.0, 1.0);
  vtkGetMacro(FarFieldCutoff, double);
  //@}

  //@{
  /**
   * Former name of ContributionCutoff, kept working: the same value, the same units.
   */
  void SetCutoff(double cutoff) { this->SetContributionCutoff(cutoff); }
  double GetCutoff() { return this->GetContributionCutoff(); }
  //@}

  //@{
  /**
   * Largest acceptable image error in 8-bit steps (1 step = 1/255 of full brightness,
   * white material with Diffuse + Specular at most 1). When above 0, the pass ignores
   * ContributionCutoff and, whenever the lights change, picks the largest cutoff whose
   * summed cut tails stay within the budget at sample points spread over the lights'
   * bounding box, at the lights themselves and over the box of the geometry to shade (N.L
   * taken as 1; a spot light's tail counted only inside its cone).
   * With FarField on, the lights it splits have no cut tail (their far parts are added
   * back), so only the culled lights (explicit radii) choose the cutoff that
   * way. The far field's error is held to the budget by its resolution instead: the pass
   * ignores FarFieldResolution and takes the coarsest of 4,096 to 262,144 nodes (powers
   * of two) whose stated bound, summarized over probe points as ComputeFarFieldErrorBound
   * reports it, is within the budget, among those that evaluate no more near lights than
   * the finest (a coarse grid can force larger near radii). When both kinds of lights are
   * present, the cut tails and the far field each get half of the budget. The split
   * lights' cutoff is their own, and the far field's share may loosen it: from
   * ContributionCutoff by factors of 4 up to 1/16, each step taken while a grid no finer
   * than FarFieldResolution meets the share and it evaluates fewer near lights, the search
   * ending at the first step no such grid meets (shorter near radii, more of each light in
   * the far field: on the benchmark's bunny 4 steps take 1/256 and 16 steps 1/64,
   * docs/far-field.md); the culled lights' tails choose theirs with their share. The
   * choice is made when the budget, the far field's options or region, or the number of
   * lights change (0.1 to 0.25 s per resolution tried at 4,096 lights on 2 threads; 0.8
   * to 1.9 s for a first frame with 2,000 lights as a new user writes them, with and
   * without spot lights), not when lights move or change brightness (the
   * budget was met when chosen; ComputeFarFieldErrorBound gives the bound now). When no
   * resolution meets it (the rest of the bound is the order-2 moments' own, which
   * NearFieldBudget moves somewhat and the resolution does not), the pass takes the one
   * with the smallest bound and warns once.
   * GetEffectiveCutoff(), GetEffectiveFarFieldCutoff(), GetFarFieldResolutionInUse() and
   * GetFarFieldErrorBudgetMet() report the choices. Range [0, 255]. Default is 0 (use
   * ContributionCutoff and FarFieldResolution).
   */
  void SetErrorBudgetInSteps(double steps);
  double GetErrorBudgetInSteps() { return 255.0 * this->ErrorBudget; }
  //@}

  //@{
  /**
   * The error budget as a fraction of full brightness (ErrorBudgetInSteps / 255), the
   * option's former form, kept working. Range [0, 1]. Default is 0.
   */
  vtkSetClampMacro(ErrorBudget, double, 0.0, 1.0);
  vtkGetMacro(ErrorBudget, double);
  //@}

  /**
   * The contribution cutoff the last light update gave the lights it culls (explicit
   * radii; every light with FarField off): ContributionCutoff, or the one the
   * error budget chose for their tails. A fraction of full brightness.
   */
  vtkGetMacro(EffectiveCutoff, double);

  /**
   * The contribution cutoff the last light update gave the lights the far field may split
   * (no explicit radius, spot lights included; their near radii): FarFieldCutoff (or
   * ContributionCutoff where it is 0), or the one the error budget chose for the far field
   * (ErrorBudgetInSteps). With no light to
   * split (FarField off, or every light culled) the same as GetEffectiveCutoff(). A
   * fraction of full brightness.
   */
  vtkGetMacro(EffectiveFarFieldCutoff, double);

  enum Falloffs
  {
    FALLOFF_HARD_CUT = 0, ///< VTK's attenuation, zero beyond the radius
    FALLOFF_WINDOWED = 1  ///< VTK's attenuation times (1 - (d/r)^4)^2 (smooth, darker)
  };
  //@{
  /**
   * Falloff at the influence radius: FALLOFF_HARD_CUT matches VTK within the cutoff;
   * FALLOFF_WINDOWED, with an explicit radius per light, is the fastest setup. A value
   * that is not a falloff is rejected with an error. Default is FALLOFF_HARD_CUT.
   */
  virtual void SetFalloff(int falloff);
  vtkGetMacro(Falloff, int);
  void SetFalloffToHardCut() { this->SetFalloff(FALLOFF_HARD_CUT); }
  void SetFalloffToWindowed() { this->SetFalloff(FALLOFF_WINDOWED); }
  const char* GetFalloffAsString();
  //@}

  //@{
  /**
   * Far field: what each light's near radius cuts off is added back, not dropped. Every
   * light without an explicit radius (VTK's inverse-square lights, always-on lights with
   * attenuation (1, 0, 0), spot lights, ...) is split smoothly at its near radius (a spot
   * light at its cutoff radius, its cone in both parts):
   * the near part is evaluated exactly through the clusters, the far part is summed on a
   * world-space grid over the visible geometry (order-2 moments of its directions per node)
   * and added to every fragment by trilinear interpolation, diffuse and Phong specular.
   * Rebuilt only when the lights change (or the geometry leaves the grid's box), never
   * for a moving camera. The error has a stated per-pixel bound (docs/far-field.md).
   * Off: such lights are cut at their cutoff radius (darker than VTK).
   * Default is on.
   */
  vtkSetMacro(FarField, bool);
  vtkGetMacro(FarField, bool);
  vtkBooleanMacro(FarField, bool);
  //@}

  //@{
  /**
   * Resolution of the far field: the number of grid nodes over the bounding box of the
   * visible geometry (112 bytes of GPU memory each: 7 RGBA32F texels; 48 bytes, 3 texels,
   * when the far-field lights share a colour, see FarFieldSharedColor). The grid spacing h
   * follows, and the near radius of bright and always-on lights is FarFieldCellsPerRadius
   * times h: more nodes mean smaller near radii, fewer lights evaluated per fragment,
   * longer far-field builds. An error budget (ErrorBudgetInSteps) chooses the resolution
   * itself (GetFarFieldResolutionInUse). Range [512, 16777216]. Default is 32768.
   */
  vtkSetClampMacro(FarFieldResolution, int, 512, 16777216);
  vtkGetMacro(FarFieldResolution, int);
  //@}

  //@{
  /**
   * Advanced: a world-space box (xmin, xmax, ymin, ymax, zmin, zmax) the far field's grid
   * covers, with the bounding box of the renderer's visible props (their union, so the
   * geometry the pass shades is always inside). The grid follows that region, so an
   * application that renders pieces of one data set on several processes (ParaView over
   * MPI) sets the bounds of the whole data set here: every process then builds the same far
   * field, with no seam where the pieces meet, whatever it renders, and a prop that comes
   * and goes inside it (a selection's highlight) moves nothing. ParaView's Clustered
   * Lighting view sets its geometry bounds here. An empty box (xmin > xmax) adds nothing.
   * A box with a bound that is not finite is ignored, with a warning when it is set.
   * Default is an empty box.
   */
  virtual void SetFarFieldRegion(
    double xmin, double xmax, double ymin, double ymax, double zmin, double zmax);
  virtual void SetFarFieldRegion(const double region[6]);
  vtkGetVector6Macro(FarFieldRegion, double);
  //@}

  //@{
  /**
   * Screen tiles across (X) and down (Y), and depth slices (Z), in [1, 256]. When the grid
   * cannot hold the lights, the pass uses a smaller one (GetClusterGridInUse).
   * Defaults are 32, 16 and 32.
   */
  vtkSetClampMacro(TilesX, int, 1, 256);
  vtkGetMacro(TilesX, int);
  vtkSetClampMacro(TilesY, int, 1, 256);
  vtkGetMacro(TilesY, int);
  vtkSetClampMacro(Slices, int, 1, 256);
  vtkGetMacro(Slices, int);
  //@}

  enum SlicingSchemes
  {
    SLICING_AUTO = 0,        ///< exponential for perspective, linear for parallel cameras
    SLICING_EXPONENTIAL = 1, ///< slice k starts at near * (far/near)^(k/Z)
    SLICING_LINEAR = 2       ///< equal slices between near and far
  };
  //@{
  /**
   * How depth is cut into slices: between the nearest and deepest visible surfaces with
   * depth-aware clusters, else between the camera clipping planes. A value that is not a
   * scheme is rejected with an error. Default is SLICING_AUTO.
   */
  virtual void SetSlicingScheme(int scheme);
  vtkGetMacro(SlicingScheme, int);
  void SetSlicingSchemeToAuto() { this->SetSlicingScheme(SLICING_AUTO); }
  void SetSlicingSchemeToExponential() { this->SetSlicingScheme(SLICING_EXPONENTIAL); }
  void SetSlicingSchemeToLinear() { this->SetSlicingScheme(SLICING_LINEAR); }
  const char* GetSlicingSchemeAsString();
  //@}

  // Advanced options: tuning knobs, with defaults that were measured (docs/benchmark).

  //@{
  /**
   * Advanced: grid cells per near radius (the far field's accuracy: its error was found
   * flat from 2 cells per near radius on, docs/far-field.md). Range [1, 8]. Default is 2.
   */
  vtkSetClampMacro(FarFieldCellsPerRadius, double, 1.0, 8.0);
  vtkGetMacro(FarFieldCellsPerRadius, double);
  //@}

  //@{
  /**
   * Advanced: how uncertain (in [0, 1] colour units) the far field may leave a fragment
   * near saturation. The node moments prove an interval the far light's true contribution
   * lies in; where that interval is wider than this and decides whether the fragment
   * saturates (its lowest value is below 1, its highest above), the far parts are summed
   * exactly, light by light (Phong fragments only up to FarFieldExactSumLimit lights).
   * Bright far fields (lights that light the whole scene) need it on a few fragments;
   * faint ones never. PBR actors (tone-mapped) use the width
   * alone, of an interval that holds VTK's whole PBR terms (each light's Fresnel and GGX
   * specular): order-2 moments bound a GGX lobe loosely, so most PBR fragments lit by a
   * bright far field sum exactly, at about brute force's cost (docs/far-field.md, "PBR
   * actors"). The exact sum stops once the fragment saturates where the colour is certain
   * to clamp at 1 (see the class description). 1 turns it off (PBR actors then take the
   * moments' estimate, far from exact at grazing views). Range [0, 1]. Default is 2/255.
   */
  vtkSetClampMacro(FarFieldTolerance, double, 0.0, 1.0);
  vtkGetMacro(FarFieldTolerance, double);
  //@}

  //@{
  /**
   * Advanced: the most lights for which Phong fragments take the exact far sums of
   * FarFieldTolerance. An exact sum visits every light, so a fragment that needs one costs
   * as much as brute force, and on a GPU the frame grows with the number of lights the
   * sums visit. With more lights than this, Phong fragments keep the moments' estimate,
   * whose error stays inside the stated bound (ComputeFarFieldErrorBound): at 65,536
   * lights on the benchmark's bunny the exact sums left the error against brute force
   * unchanged (max 3 steps, RMSE 0.456) and took 93% of an NVIDIA H200's frame
   * (docs/far-field.md, "The exact far sums on a GPU"). PBR actors always take them (their
   * far light has no stated bound without). 0 turns them off for Phong fragments.
   * Range [0, VTK_INT_MAX]. Default is 16384.
   */
  vtkSetClampMacro(FarFieldExactSumLimit, int, 0, VTK_INT_MAX);
  vtkGetMacro(FarFieldExactSumLimit, int);
  //@}

  //@{
  /**
   * Advanced: whether back-facing Phong fragments take the exact far sums of
   * FarFieldTolerance too. Off, they keep the moments' estimate, whose error stays inside
   * the stated bound (ComputeFarFieldErrorBound), as every fragment's does past
   * FarFieldExactSumLimit. A closed surface's back faces are hidden behind its front, but
   * a software rasterizer (Mesa's llvmpipe) runs the fragment shader of hidden fragments
   * all the same: it tests depth before the shader, yet skips no block of fragments that
   * all fail (it does only under a stencil test, and VTK's framebuffer has no stencil),
   * and a loop runs while any fragment of the block needs it. The back faces of a ball lit
   * by 4,096 lights as a new user writes them straddle saturation as its front does, and
   * their sums made the frame 20 times longer (1.85 s against 91 ms on llvmpipe), with the
   * same image (docs/far-field.md,
   * "The exact far sums where they show"). Turn it on for open surfaces seen from behind
   * under a bright far field. Translucent surfaces, whose back faces show through their
   * front, sum on both sides whatever this says. PBR fragments take the sums on both sides (their
   * far light has no stated bound without them). Default is false.
   */
  vtkSetMacro(FarFieldExactSumsOnBackFaces, bool);
  vtkGetMacro(FarFieldExactSumsOnBackFaces, bool);
  vtkBooleanMacro(FarFieldExactSumsOnBackFaces, bool);
  //@}

  //@{
  /**
   * Advanced: how the far field's build groups lights (Barnes-Hut). A group of lights
   * seen from far enough is summed as one light at its centroid when its extent is below
   * this fraction of its distance (relative error about its square); 0 sums every light
   * at every node (exact, slow). The error it makes is inside the stated bound
   * (ComputeFarFieldErrorBound), which grows a little with it. Range [0, 1]. Default is 1.
   */
  vtkSetClampMacro(FarFieldGrouping, double, 0.0, 1.0);
  vtkGetMacro(FarFieldGrouping, double);
  //@}

  //@{
  /**
   * Advanced: when every light the far field holds has the same colour up to its
   * intensity (white vtkLights, VTK's default, for one), store and read the far field as
   * one channel times that colour: 5 texture reads per shaded fragment instead of 14 and 80
   * bytes per grid node instead of 224 (3 and 48 instead of 7 and 112 with
   * FarFieldOrder4Diffuse off). Exact: each channel's moments are then the same
   * multiple of one channel's (FindFarFieldSharedColor in
   * Rendering/Core/vtkClusteredLightingFarField.h), so the image is the same up to float
   * rounding. Off always keeps three channels (for comparisons). See
   * GetFarFieldSharedColorUsed(). Default is on.
   */
  vtkSetMacro(FarFieldSharedColor, bool);
  vtkGetMacro(FarFieldSharedColor, bool);
  vtkBooleanMacro(FarFieldSharedColor, bool);
  //@}

  //@{
  /**
   * Advanced: the far diffuse to order 4 (the clamped cosine's Legendre series to its
   * fourth term, from the far light's fourth moments: ApplyFarDiffuse in
   * Rendering/Core/vtkClusteredLightingFarField.h), else to order 2. Order 4 stores twice
   * the moments (14 texture reads per shaded fragment instead of 7, 5 instead of 3 with
   * FarFieldSharedColor; 224 bytes per grid node instead of 112) and brings the diffuse's
   * angular error down where the far light comes from many directions: VTK's default
   * always-on lights, and tens of thousands of lights (docs/far-field.md, "The order-4 far
   * diffuse"). Both stay within the stated bound, which counts the order taken. Off
   * needs 7 texture units for the far field instead of 14; a GPU whose fragment shaders
   * have fewer than 28 units (OpenGL guarantees 16; llvmpipe and desktop GPUs have 32)
   * gets order 2 whatever this says, with a warning. Default is on.
   */
  vtkSetMacro(FarFieldOrder4Diffuse, bool);
  vtkGetMacro(FarFieldOrder4Diffuse, bool);
  vtkBooleanMacro(FarFieldOrder4Diffuse, bool);
  //@}

  //@{
  /**
   * Advanced: the Phong far specular of specular powers from 8 on from directional bins:
   * per grid node the far light of 26 cells of directions, its sum and mean direction,
   * each cell shaded as a spread of light against VTK's lobe
   * (Rendering/Core/vtkClusteredLightingFarSpecularBins.h). A lobe of power 20 is too
   * narrow for the far field's moments, which leave its highlights of tens of thousands
   * of lights up to 3 steps off; the bins bring it within 2 (docs/far-field.md, "A far
   * specular from directional bins"). Built only while some visible actor of the renderer
   * has a Phong specular they serve (Specular above 0, SpecularPower 8 or more), so a
   * diffuse scene pays nothing. Costs one more texture (832 bytes per grid node, 416 with
   * FarFieldSharedColor), 26 or 52 texture reads per specular fragment, and the bins'
   * sums in each far-field build. Off, or where the GPU has too few texture units or 3D
   * textures too shallow for the grid (warned once), the far specular comes from the
   * moments, within the stated bound either way. Off by default: on llvmpipe the bins'
   * reads double the frame of 4,096 lights, whose images they do not change by a step
   * (docs/far-field.md). Still lights above FarFieldRefineLeastLights get the bins
   * whatever this says (FarFieldRefineStillLights). Default is off.
   */
  vtkSetMacro(FarFieldSpecularBins, bool);
  vtkGetMacro(FarFieldSpecularBins, bool);
  vtkBooleanMacro(FarFieldSpecularBins, bool);
  //@}

  //@{
  /**
   * Advanced: sum the far field only in the blocks of 4 x 4 x 4 grid nodes that the
   * visible props' surfaces read (Rendering/Core/vtkClusteredLightingFarFieldBlocks.h).
   * The grid fills the box of the visible geometry, but a floor and a model touch a small
   * part of its volume, so where lights move every frame this cuts each rebuild to that
   * part. Where the surfaces lie is read from the props, not the camera: actors of VTK's
   * own classes whose mappers draw their input as it is (vtkOpenGLPolyDataMapper,
   * vtkCompositePolyDataMapper2) give a box per cell, any other prop its bounds, and an
   * actor that draws lines as tubes or points as spheres every block. A prop that moves or
   * appears later gets its blocks summed in the frame it does (the others are kept).
   * Switch it off only for shader replacements that move vertices off the mapper's
   * input (vtkShaderProperty), which the boxes do not see: every block is then summed.
   * In a multisampled framebuffer (VTK's default MultiSamples of 8, for one) a fragment
   * covering part of its pixel is shaded at the pixel's centre, on its primitive's plane
   * extrapolated past the primitive, and at a silhouette that point may lie far from every
   * surface, in blocks no surface marks. There the blocks those fragments reach are summed
   * too: the depth prepass records the depths each pixel's fragments are shaded at (for
   * the depth-aware clusters), and every square of 8 x 8 pixels marks the blocks of the
   * piece of the view those depths span. These marks follow the camera: a camera move
   * sums the nodes it reaches anew, if any. Without that record (DepthAwareClusters or
   * the depth prepass off, or a frame without the prepass), and in a frame with visible
   * translucent geometry (not in the record), every block is summed (docs/far-field.md,
   * "Multisampled framebuffers"). GetNumberOfFarFieldBlocksRead tells how many blocks are
   * summed. Default is on.
   */
  vtkSetMacro(FarFieldSkipEmptyBlocks, bool);
  vtkGetMacro(FarFieldSkipEmptyBlocks, bool);
  vtkBooleanMacro(FarFieldSkipEmptyBlocks, bool);
  //@}

  //@{
  /**
   * Refine the far field for lights that hold still. With more than
   * FarFieldRefineLeastLights lights, a far field built for lights that did not also
   * change in the frame before is built finer: FarFieldCellsPerRadius times 1.5 at
   * FarFieldResolution times 3.375 (every light keeps its near radius, and the far parts
   * are interpolated from nodes 1.5 times closer), with the far specular from directional
   * bins where an actor needs them (as FarFieldSpecularBins). Lights that change in two
   * frames running are moving: their far field is rebuilt every frame at the options' own
   * settings, which cost less than the light assignment, and the first frame after they
   * stop builds the refined one, once. So a still frame of tens of thousands of lights is
   * within 2 steps of brute force (65,536 lights on the benchmark's bunny: 3 steps off at
   * 302 of 786,432 pixels without), and moving lights keep a rebuild below the
   * assignment's cost (docs/far-field.md, "Still lights refined"). A refined build costs
   * several times an ordinary one (0.4 to 0.6 s at 65,536 lights on 2 threads), once per
   * stop. An application that animates lights renders once more after they stop to show
   * the refined image. Where the GPU cannot hold the bins for the refined grid, the far
   * specular comes from the moments, with a warning that names this option. Not used
   * with an error budget (ErrorBudgetInSteps chooses the resolution). GetFarFieldRefinedUsed tells
   * whether the last render's far field was refined. Default is on.
   */
  vtkSetMacro(FarFieldRefineStillLights, bool);
  vtkGetMacro(FarFieldRefineStillLights, bool);
  vtkBooleanMacro(FarFieldRefineStillLights, bool);
  //@}

  //@{
  /**
   * Advanced: the most lights (renderer lights the pass clusters and light sets' lights
   * together) whose still far field is not refined (FarFieldRefineStillLights). The
   * default's far field at 4,096 lights is within a step of brute force on the benchmark's
   * bunny, and the bins' reads cost half its frame again on llvmpipe for no step of
   * difference; above FarFieldExactSumLimit lights (16,384 by default) Phong fragments
   * take the moments' far specular everywhere, which is what the bins replace.
   * Range [0, VTK_INT_MAX]. Default is 16384.
   */
  vtkSetClampMacro(FarFieldRefineLeastLights, int, 0, VTK_INT_MAX);
  vtkGetMacro(FarFieldRefineLeastLights, int);
  //@}

  //@{
  /**
   * Advanced: how many lights per point, on average over the box of the visible geometry,
   * the near field may evaluate exactly (a light counts at most once per point). When all
   * lights fit whole, each keeps its cutoff radius and the far field holds only the tails
   * past it (none at all for up to 16 vtkLights that reach everywhere, whatever this
   * budget); otherwise the lights with the largest radii are cut to one radius R that
   * fills the budget (a few bright lights among many keep exact highlights), never below
   * FarFieldCellsPerRadius grid cells, and the far field carries the rest. Lights that
   * never fall off (attenuation (1, 0, 0)) keep a radius that fills 16 per point while its
   * sphere holds half the box, the smallest radius otherwise (docs/far-field.md).
   * Range [0, 1e6]. Default is 8.
   */
  vtkSetClampMacro(NearFieldBudget, double, 0.0, 1e6);
  vtkGetMacro(NearFieldBudget, double);
  //@}

  //@{
  /**
   * Advanced: sort lights in Morton order before upload so that nearby lights share
   * batches (35% faster on the benchmark), point lights before spot lights, so that the
   * shader evaluates the point lights' batches without the spot code (13% to 15% faster
   * with a tenth of 4,096 lights spot lights). Off: the input order. Default is on.
   */
  vtkSetMacro(MortonOrder, bool);
  vtkGetMacro(MortonOrder, bool);
  vtkBooleanMacro(MortonOrder, bool);
  //@}

  //@{
  /**
   * Advanced: in the list pass, test each light's sphere against the view-space bounding
   * box of every cluster of its screen rectangle and slice range (with a margin far above
   * float error), instead of assigning the whole range. Removes the corners of the range,
   * so fewer lights are evaluated per fragment; stays conservative. Default is on.
   */
  vtkSetMacro(PerClusterCulling, bool);
  vtkGetMacro(PerClusterCulling, bool);
  vtkBooleanMacro(PerClusterCulling, bool);
  //@}

  //@{
  /**
   * Advanced: assign a spot light only to the clusters its cone may reach: its tile
   * rectangles are those of the smallest sphere about its cone within its radius, and the
   * list pass tests each cluster's box against the cone (widened by 2e-3 radians;
   * vtkClusteredLightingSpotBounds.h). The image is the same (a spot light adds nothing
   * outside its cone); fewer lights are walked per fragment. Off assigns spot lights by
   * their spheres, as point lights. Default is on.
   */
  vtkSetMacro(SpotConeCulling, bool);
  vtkGetMacro(SpotConeCulling, bool);
  vtkBooleanMacro(SpotConeCulling, bool);
  //@}

  //@{
  /**
   * Cull the back faces of closed opaque surfaces where no back face can be seen: an
   * actor drawn as a surface by a plain vtkPolyDataMapper, without translucency, textures,
   * clipping planes or shader code of its own, whose polygons bound a solid with one
   * orientation (points with equal coordinates merged) and whose bounding box lies beyond
   * the near plane (vtkClusteredLightingClosedSurface.h). The image is unchanged: every
   * back face of such a surface lies behind a front face of it. On llvmpipe a hidden
   * fragment costs about what a visible one does, and a closed surface's back faces were
   * a third of a frame (docs/depth.md). Applies under the pass's own delegate (VTK's
   * render steps), in the depth prepass and the opaque step; a mesh that folds through
   * itself (locally inverted polygons) may lose back faces it showed. Off draws every face
   * as VTK does. Default is on.
   */
  vtkSetMacro(AutomaticBackfaceCulling, bool);
  vtkGetMacro(AutomaticBackfaceCulling, bool);
  vtkBooleanMacro(AutomaticBackfaceCulling, bool);
  //@}

  //@{
  /**
   * Render the opaque geometry depth-only before shading it, so that no hidden fragment
   * is shaded: the shading render then keeps that depth buffer and every opaque fragment
   * behind the visible surface fails the depth test before its lights are walked. Costs
   * one more pass over the opaque geometry (vertex work and rasterization, no lighting).
   * Depth-aware clusters render it whatever this option says. It pays for itself when the
   * scene hides much of its geometry or many lights reach each cluster; on a heavy mesh
   * that hides little, lit by up to about a thousand lights, it costs more than it saves
   * on a software rasterizer (measured in docs/depth.md). AutomaticDepthPrepass (on by
   * default) times both per renderer and drops the prepass, and the depth-aware clusters,
   * where it does not pay. Default is on.
   */
  vtkSetMacro(DepthPrepass, bool);
  vtkGetMacro(DepthPrepass, bool);
  vtkBooleanMacro(DepthPrepass, bool);
  //@}

  //@{
  /**
   * Depth-aware clusters: after the depth prepass, read the viewport's depth back and cut
   * each cluster to the depths its fragments really have and its tile to the screen
   * rectangle they cover (an empty cluster gets no light), and put the depth slices
   * between the nearest and deepest visible surfaces instead of the camera's clipping
   * range. Conservative: in a multisampled framebuffer (VTK's default window) the
   * prepass records the depths its fragments have at the pixel centres, where they are
   * shaded (vtkClusteredLightingSampleDepths); translucent geometry widens the clusters
   * of the tiles its props' boxes cover on screen to the depths of those boxes in front
   * of the tile's deepest opaque surface (every tile, from the near plane, for props whose
   * fragments may leave their box: impostor mappers, custom shader code, VTK's LOD
   * actors; in a multisampled framebuffer, to the far plane); a frame whose depths
   * cannot be used (opaque impostor mappers that write their own depth, an oblique
   * projection) falls back to whole clusters, with a warning once. Costs the prepass, a depth
   * readback and a CPU pass over its pixels (GetLastDepthPrepassTime, GetLastAssignmentTime); the
   * list and master passes then run whenever the visible depths change. Default is on.
   */
  vtkSetMacro(DepthAwareClusters, bool);
  vtkGetMacro(DepthAwareClusters, bool);
  vtkBooleanMacro(DepthAwareClusters, bool);
  //@}

  //@{
  /**
   * Choose the depth prepass per renderer by timing it: the pass renders a few frames
   * with the prepass (and depth-aware clusters, as DepthPrepass and DepthAwareClusters
   * say) and a few without, side by side on the device it runs on, and keeps the faster
   * (the other must be 5% faster to change the choice). A trial runs 3 frames after the
   * scene changes (the number of lights in powers of two, the props, the viewport, the
   * pass's options) and again every 600 frames; it times its frames with a glFinish on
   * each side. Where the prepass pays depends on the device (geometry against shading
   * cost) and the scene, so no fixed rule is used (docs/depth.md). Both modes give the
   * same image within the pass's stated bounds (bit for bit for lights with an explicit
   * radius and windowed falloff). Off: the prepass follows DepthPrepass and
   * DepthAwareClusters alone, in every frame. Has no effect when both are off.
   * Default is on.
   */
  vtkSetMacro(AutomaticDepthPrepass, bool);
  vtkGetMacro(AutomaticDepthPrepass, bool);
  vtkBooleanMacro(AutomaticDepthPrepass, bool);
  //@}

  //@{
  /**
   * Reuse the depth prepass of the last frame when it would draw the same depths: the
   * same renderer, framebuffer, viewport and camera, and no visible prop, mapper,
   * clipping plane or input modified since (a still camera over moving lights, or a
   * re-render of an unchanged scene). The frame copies the saved depth buffer back (and
   * keeps its readback) instead of drawing the opaque geometry again; the image is the
   * same bit for bit. Only props whose modification times cover everything that moves
   * their depths take part: plain vtkActors with a vtkPolyDataMapper drawing one piece,
   * without shader replacements or UpdateShaderEvent observers, and overlays that write
   * no depth (2D actors with VTK's polydata mapper, text, scalar bars, corner
   * annotations); any other visible prop (an LOD actor, a follower, a glyph or composite
   * mapper, cube axes, a volume) makes every frame draw its prepass, as does a renderer
   * that keeps the depth buffer of an earlier one (GetDepthPrepassReuseProblem names it).
   * Costs one depth copy per prepass frame and a depth buffer's memory
   * (GetDepthPrepassReused says whether the last frame reused; docs/depth.md).
   * Default is on.
   */
  vtkSetMacro(ReuseDepthPrepass, bool);
  vtkGetMacro(ReuseDepthPrepass, bool);
  vtkBooleanMacro(ReuseDepthPrepass, bool);
  //@}

  //@{
  /**
   * Advanced: largest texture side, in texels, the pass allocates for its list and master
   * textures; 0 means the context's GL_MAX_TEXTURE_SIZE. A smaller value bounds GPU memory
   * (the list texture is at most MaximumTextureSize squared times 4 bytes) and lowers the
   * light limit of each grid (see GetMaximumNumberOfLights). Default is 0.
   */
  vtkSetClampMacro(MaximumTextureSize, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumTextureSize, int);
  //@}

  // Diagnostic options: for debugging and measurements, not for production images.

  enum DebugViews
  {
    DEBUG_NONE = 0,
    DEBUG_CLUSTER_INDEX = 1, ///< (tile x, tile y, slice) / (X-1, Y-1, Z-1) as RGB
    DEBUG_HEAT_MAP = 2,      ///< lights evaluated per pixel, colour map up to GetHeatMapScale
    /// lights evaluated (R + 256 G, saturates at 65,535), lights reaching (B, saturates at
    /// 255), both up to where a saturated fragment stops (class description)
    DEBUG_EVALUATED_COUNT = 3,
    DEBUG_REACHED_COUNT = 4, ///< lights that reach the fragment (R + 256 G, up to 65,535)
    DEBUG_NON_FINITE = 5,    ///< red where the lit colour is NaN or Inf
    DEBUG_NORMAL = 6         ///< the shading normal (view coordinates) as 0.5 + 0.5 N
  };
  //@{
  /**
   * Diagnostic: a debug view replacing the shaded colour of lit surfaces (compiled in only
   * when set; after a texture's colour). Frames rendered with DEBUG_EVALUATED_COUNT or
   * DEBUG_HEAT_MAP count the lights evaluated per pixel (GetMeanLightsEvaluatedPerPixel).
   * The count views (DEBUG_HEAT_MAP, DEBUG_EVALUATED_COUNT, DEBUG_REACHED_COUNT) show 0
   * lights where VTK lights nothing (points, and lines without normals), and their
   * counting render leaves the renderer's 2D actors (text, legends) out: both would
   * otherwise decode as thousands of lights. Props drawn without the polydata mappers'
   * shader code (image slices, vtkTextActor3D) keep their colours there. A value that is
   * not a debug view is rejected with an error. Default is DEBUG_NONE.
   */
  virtual void SetDebugView(int view);
  vtkGetMacro(DebugView, int);
  void SetDebugViewToNone() { this->SetDebugView(DEBUG_NONE); }
  void SetDebugViewToClusterIndex() { this->SetDebugView(DEBUG_CLUSTER_INDEX); }
  void SetDebugViewToHeatMap() { this->SetDebugView(DEBUG_HEAT_MAP); }
  void SetDebugViewToEvaluatedCount() { this->SetDebugView(DEBUG_EVALUATED_COUNT); }
  void SetDebugViewToReachedCount() { this->SetDebugView(DEBUG_REACHED_COUNT); }
  void SetDebugViewToNonFinite() { this->SetDebugView(DEBUG_NON_FINITE); }
  void SetDebugViewToNormal() { this->SetDebugView(DEBUG_NORMAL); }
  const char* GetDebugViewAsString();
  //@}

  //@{
  /**
   * Diagnostic: lights per pixel shown as the hottest colour of DEBUG_HEAT_MAP. 0 scales
   * the heat map to the data: each heat-map frame first counts the lights evaluated per
   * pixel (one extra render in this debug view) and its maximum becomes the hottest
   * colour. GetHeatMapScale() reports the scale used. Range [0, 1e6]. Default is 0.
   */
  vtkSetClampMacro(HeatMapMaximum, double, 0.0, 1e6);
  vtkGetMacro(HeatMapMaximum, double);
  //@}

  enum BoundsMethods
  {
    BOUNDS_TANGENT = 0,          ///< exact tangent bounds, conservative
    BOUNDS_CENTER_DEPTH_QUAD = 1 ///< NOT conservative; only to measure what it gets wrong
  };
  //@{
  /**
   * Diagnostic: how light spheres are bounded on screen. BOUNDS_CENTER_DEPTH_QUAD misses
   * lights and exists only to measure what it gets wrong. A value that is not a method is
   * rejected with an error. Default is BOUNDS_TANGENT.
   */
  virtual void SetBoundsMethod(int method);
  vtkGetMacro(BoundsMethod, int);
  void SetBoundsMethodToTangent() { this->SetBoundsMethod(BOUNDS_TANGENT); }
  void SetBoundsMethodToCenterDepthQuad() { this->SetBoundsMethod(BOUNDS_CENTER_DEPTH_QUAD); }
  const char* GetBoundsMethodAsString();
  //@}

  //@{
  /**
   * Diagnostic: finish the GL work around the assignment and shading stages and record
   * their times (GetLastAssignmentTime, GetLastShadingTime), and count the fragments of
   * the shading render that pass the depth test (GetShadedFragmentsPerVisiblePixel and
   * its opaque and translucent parts: occlusion queries, counted only through the pass's
   * own delegate: an application's delegate may run such queries itself, so its counts
   * stay 0). Costs a pipeline stall; for benchmarks. Default is off. Changes what is
   * measured, not what is drawn, so it does not modify the pass: turning it on does not
   * make a new scene for AutomaticDepthPrepass (no new trial).
   */
  void SetMeasureTimings(bool measure) { this->MeasureTimings = measure; }
  vtkGetMacro(MeasureTimings, bool);
  vtkBooleanMacro(MeasureTimings, bool);
  //@}

  // Statistics of the last render (one getter each).

  /// Number of valid lights shaded by the pass in the last render.
  vtkGetMacro(NumberOfClusteredLights, int);
  /// Number of invalid lights skipped with a warning in the last render.
  vtkGetMacro(NumberOfRejectedLights, int);
  /// Number of lights that never fall off (attenuation (1, 0, 0)): they reach everywhere.
  vtkGetMacro(NumberOfAlwaysOnLights, int);
  /// Number of lights below the contribution cutoff everywhere.
  vtkGetMacro(NumberOfLightsBelowCutoff, int);
  /// Number of spot lights among the valid lights.
  vtkGetMacro(NumberOfSpotLights, int);
  /// Number of lights drawn in the list pass (those that touch the view).
  vtkGetMacro(NumberOfAssignedLights, int);
  /// Cluster grid of the last render (tiles X, tiles Y, slices): the options' grid, or a
  /// smaller one when that grid cannot hold the lights (a warning says so once).
  vtkGetVector3Macro(ClusterGridInUse, int);
  /// Whether the last render shaded the lights in a plain loop, because every light
  /// reaches every cluster (same image as clustered shading, less work).
  vtkGetMacro(ClusteringBypassed, bool);
  /// Lights assigned to a cluster, on average over the grid's clusters (with depth-aware
  /// clusters, over the clusters that hold fragments, counting the lights whose depth
  /// extent reaches them), at the last assignment (before per-cluster culling); near
  /// GetNumberOfClusteredLights means that
  /// clustering culls little (a warning names the cause and the fix once).
  vtkGetMacro(MeanLightsPerCluster, double);
  /// Lights evaluated per pixel of lit geometry, on average, in the last frame that
  /// counted them (DEBUG_EVALUATED_COUNT or DEBUG_HEAT_MAP); 0 before any. In a
  /// multisampled framebuffer (VTK's default window) one sample of each pixel is read,
  /// its colour and depth, since a resolve would average an edge pixel's counts with the
  /// background; 0, with one warning naming why, if the framebuffer cannot be read.
  vtkGetMacro(MeanLightsEvaluatedPerPixel, double);
  /// Lights that reach the pixel (inside their radius and cone), on average over the same
  /// pixels of the same frame, as DEBUG_EVALUATED_COUNT's blue counts them: each pixel's
  /// count saturates at 255, and a saturated fragment stops counting where it stops its
  /// walk. GetMeanLightsEvaluatedPerPixel over it says how well the clusters cull (1:
  /// every light walked reaches).
  vtkGetMacro(MeanLightsReachingPerPixel, double);
  /// Most lights evaluated at one pixel in the last frame that counted them.
  vtkGetMacro(MaximumLightsEvaluatedPerPixel, int);
  /// Pixels covered by 3D geometry (depth below the far plane; 2D actors left out) in the
  /// last frame that counted them.
  vtkGetMacro(NumberOfCountedPixels, vtkIdType);
  /// Lights per pixel shown as the hottest colour of the last heat map.
  vtkGetMacro(HeatMapScale, double);
  /// Time in ms of the last assignment: view records, list and master passes.
  vtkGetMacro(LastAssignmentTime, double);
  /// Time in ms of the last light update: reading, preparing and uploading lights.
  vtkGetMacro(LastLightUpdateTime, double);
  /// Time in ms of the last delegate render (exact with MeasureTimings).
  vtkGetMacro(LastShadingTime, double);
  /// Whether the last render drew a depth prepass.
  vtkGetMacro(DepthPrepassUsed, bool);
  /// Props whose hidden faces the last render culled (AutomaticBackfaceCulling).
  vtkGetMacro(NumberOfBackfaceCulledProps, int);
  /// Whether the last render left the renderer's positional vtkLights to VTK's lighting
  /// code, though ClusterRendererLights is on: an application's delegate pass rendered a
  /// shaded volume, which VTK lights only with the lights the renderer holds (the pass's
  /// own delegate hands them to the volumes itself). They are then shaded by VTK, surfaces
  /// and volumes alike, as without the pass; light sets are still clustered.
  vtkGetMacro(RendererLightsLeftToVTK, bool);
  /// Time in ms of the last depth prepass, its depth readback included.
  vtkGetMacro(LastDepthPrepassTime, double);
  /// Whether the last render's prepass copied the frame before's depths back
  /// (ReuseDepthPrepass) instead of drawing.
  vtkGetMacro(DepthPrepassReused, bool);
  /// Whether the last render kept its prepass's depths for the next frame
  /// (ReuseDepthPrepass); if not, GetDepthPrepassReuseProblem says why.
  vtkGetMacro(DepthPrepassKept, bool);
  /// Why the last render did not keep its prepass's depths for the next frame, for example
  /// "a vtkFollower is drawn" (docs/depth.md); "" when it kept them, when
  /// ReuseDepthPrepass is off, or when the frame drew no prepass.
  const char* GetDepthPrepassReuseProblem() const;
  /// AutomaticDepthPrepass: trials completed for the last rendered renderer since its
  /// scene last changed or began. Whether the last frame drew the prepass is
  /// GetDepthPrepassUsed.
  vtkGetMacro(NumberOfDepthPrepassTrials, int);
  /// AutomaticDepthPrepass: the last trial's median frame time with the prepass over the
  /// median without it, for the last rendered renderer (below 1: the prepass paid; 0
  /// before any trial).
  vtkGetMacro(DepthPrepassTrialRatio, double);
  /// Whether the last render's clusters were cut to the visible depths.
  vtkGetMacro(DepthAwareClustersUsed, bool);
  /// Nearest and deepest visible opaque depth (view coordinates) of the last depth-aware
  /// render; 0 otherwise.
  vtkGetVector2Macro(VisibleDepthRange, double);
  /// Depth range the slices of the last render spanned (view coordinates).
  vtkGetVector2Macro(SlicingRangeInUse, double);
  /// Share of clusters that held fragments in the last depth-aware render (1 otherwise).
  vtkGetMacro(NonEmptyClusterFraction, double);
  /// Fragments of the last shading render that passed the depth test (so were shaded by a
  /// GPU with early depth tests), per pixel showing opaque geometry, with MeasureTimings
  /// on (GL_SAMPLES_PASSED queries; in a multisampled framebuffer the samples passed over
  /// the sample count, edge pixels counting part of a fragment); 0 when not measured. The sum of
  /// the two parts below, or -1 when either was not measured.
  double GetShadedFragmentsPerVisiblePixel()
  {
    return this->ShadedOpaqueFragmentsPerVisiblePixel < 0.0 ||
        this->ShadedTranslucentFragmentsPerVisiblePixel < 0.0
      ? -1.0
      : this->ShadedOpaqueFragmentsPerVisiblePixel +
        this->ShadedTranslucentFragmentsPerVisiblePixel;
  }
  /// Its part from the opaque draws: 1.0 means no hidden opaque fragment was shaded (a
  /// face drawn twice at the same depth, or coincident faces, count more). -1 when the
  /// renderer's UseSSAO is on: VTK's SSAO draws full-viewport quads of its own there.
  vtkGetMacro(ShadedOpaqueFragmentsPerVisiblePixel, double);
  /// Its part from the translucent draws: every translucent layer in front of the opaque
  /// surface is shaded and blended, as it must be. Not VTK's compositing of the layers
  /// (order-independent translucency draws one unlit full-viewport quad, which is not
  /// counted). -1 when the renderer peels translucent geometry in depth (UseDepthPeeling):
  /// depth peeling counts samples with the same kind of query, which cannot run twice at
  /// once, so nothing is counted while it renders; -1 too for translucent geometry in a
  /// multisampled framebuffer (its layers are drawn single-sampled, then composited).
  vtkGetMacro(ShadedTranslucentFragmentsPerVisiblePixel, double);
  /// Number of lights split into near and far parts in the last render.
  vtkGetMacro(NumberOfFarFieldLights, int);
  /// Of those, the lights packed closer than the far field's grid resolves (a clump, or a
  /// small cloud of lights under a grid stretched over a large region), whose near radii
  /// were raised to FarFieldCellsPerRadius grid cells so that the grid resolves their far
  /// parts (RaiseUnresolvedNearRadii in Rendering/Core/vtkClusteredLightingFarField.h):
  /// they are shaded exactly up to there, at the cost of their near spheres.
  vtkGetMacro(NumberOfPackedFarFieldLights, int);
  /// Time in ms of the last far-field build.
  vtkGetMacro(LastFarFieldBuildTime, double);
  /// Grid nodes the last render's far-field build summed (see FarFieldSkipEmptyBlocks;
  /// 0 when it built nothing).
  vtkGetMacro(NumberOfFarFieldNodesBuilt, vtkTypeInt64);
  /// Blocks of 4 x 4 x 4 nodes of the far field's grid; 0 without a far field.
  vtkGetMacro(NumberOfFarFieldBlocks, vtkTypeInt64);
  /// Of those, the blocks the visible surfaces read, with those the recorded fragments
  /// reach in a multisampled framebuffer (all of them with FarFieldSkipEmptyBlocks off,
  /// or multisampled without the prepass's record).
  vtkGetMacro(NumberOfFarFieldBlocksRead, vtkTypeInt64);
  /// Spacing of the far field's grid in world units, 0 without a far field.
  vtkGetMacro(FarFieldGridSpacing, double);
  /// Near radius of bright and always-on lights when the far field splits them.
  vtkGetMacro(NearRadiusCap, double);
  /// Far-field grid nodes per axis.
  vtkGetVector3Macro(FarFieldDimensions, int);
  /// The far field's resolution in use (nodes asked for: FarFieldResolution, or the one
  /// the error budget chose); 0 without a far field.
  vtkGetMacro(FarFieldResolutionInUse, int);
  /// With an error budget and a far field: whether a resolution brought the far field's
  /// stated bound within its share of the budget (false: the pass warned); true otherwise.
  vtkGetMacro(FarFieldErrorBudgetMet, bool);
  /// Diagnostic: how many times an error budget chose the far field's resolution (once per
  /// change of the budget, the far field's options or region, or the number of lights).
  vtkGetMacro(NumberOfFarFieldResolutionChoices, int);
  /// GPU memory of the far field in bytes.
  vtkGetMacro(FarFieldTextureBytes, vtkTypeUInt64);
  /// Whether the last render's far field was one channel (FarFieldSharedColor: its lights
  /// share a colour); false without a far field.
  vtkGetMacro(FarFieldSharedColorUsed, bool);
  /// Whether the last render's far specular came from directional bins
  /// (FarFieldSpecularBins, with an actor that needs them and a GPU that holds them).
  vtkGetMacro(FarFieldSpecularBinsUsed, bool);
  /// Whether the last render's far field was built refined for still lights
  /// (FarFieldRefineStillLights).
  vtkGetMacro(FarFieldRefinedUsed, bool);
  /// Whether the last render reassigned lights to clusters.
  vtkGetMacro(LastAssignmentUpdated, bool);

  /**
   * The far field's stated error bound (docs/far-field.md) for the last frame's lights, in
   * 8-bit steps of a white, fully diffuse surface: the largest over probe points spread
   * through the far field's region (each with the 6 axis normals) and over the renderers
   * the pass renders. Computed on request on the CPU, the probes spread over VTK's SMP
   * threads (on 2 threads about 0.25 s for 4,096 lights, 0.7 s for 65,536, 1.1 s for
   * 524,288: docs/far-field.md), never during a render. 0 without a far field.
   * The bound at a pixel depends on its position, normal and material; the tests check it
   * pixel by pixel against brute force.
   */
  double ComputeFarFieldErrorBound();

  //@{
  /**
   * Counters since construction: light-data uploads, list/master runs, and shader
   * programs built by mappers that use the pass (sources not built before: a mapper that
   * switches back to a program VTK's shader cache holds, as every mapper does around the
   * depth prepass each frame, rebuilds its source but compiles nothing, and is not
   * counted).
   */
  vtkGetMacro(NumberOfLightUploads, int);
  vtkGetMacro(NumberOfAssignmentUpdates, int);
  vtkGetMacro(NumberOfShaderBuilds, int);
  //@}

  //@{
  /**
   * GPU memory held for the last rendered renderer, in bytes.
   */
  vtkGetMacro(ListTextureBytes, vtkTypeUInt64);
  vtkGetMacro(MasterTextureBytes, vtkTypeUInt64);
  vtkGetMacro(LightBufferBytes, vtkTypeUInt64);
  //@}

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

  //@{
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
  //@}

protected:
  /// The clustered shading code for one fragment shader (PostReplaceShaderValues).
  void InjectShadingCode(std::string& fragmentShader, vtkProp* prop);

  vtkClusteredLightingPass();
  ~vtkClusteredLightingPass() override;

  vtkRenderPass* DelegatePass = nullptr;

  bool ClusterRendererLights = true;
  bool RendererLightsLeftToVTK = false;
  int TilesX = 32;
  int TilesY = 16;
  int Slices = 32;
  int SlicingScheme = SLICING_AUTO;
  double ContributionCutoff = 1.0 / 1024.0;
  double FarFieldCutoff = 1.0 / 256.0;
  double ErrorBudget = 0.0; ///< fraction of full brightness (ErrorBudgetInSteps / 255)
  double EffectiveCutoff = 1.0 / 1024.0;
  double EffectiveFarFieldCutoff = 1.0 / 1024.0;
  int Falloff = FALLOFF_HARD_CUT;
  int ShadingMode = SHADING_CLUSTERED;
  int DebugView = DEBUG_NONE;
  double HeatMapMaximum = 0.0;
  bool MortonOrder = true;
  int BoundsMethod = BOUNDS_TANGENT;
  bool PerClusterCulling = true;
  bool SpotConeCulling = true;
  bool AutomaticBackfaceCulling = true;
  bool DepthPrepass = true;
  bool DepthAwareClusters = true;
  bool AutomaticDepthPrepass = true;
  bool ReuseDepthPrepass = true;
  int MaximumTextureSize = 0;
  bool MeasureTimings = false;
  bool FarField = true;
  int FarFieldResolution = 32768;
  double FarFieldRegion[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  double FarFieldCellsPerRadius = 2.0;
  double FarFieldTolerance = 2.0 / 255.0;
  int FarFieldExactSumLimit = 16384;
  bool FarFieldExactSumsOnBackFaces = false;
  double FarFieldGrouping = 1.0;
  bool FarFieldSharedColor = true;
  bool FarFieldOrder4Diffuse = true;
  bool FarFieldSpecularBins = false;
  bool FarFieldSkipEmptyBlocks = true;
  bool FarFieldRefineStillLights = true;
  int FarFieldRefineLeastLights = 16384;
  double NearFieldBudget = 8.0;

  int NumberOfClusteredLights = 0;
  int NumberOfRejectedLights = 0;
  int NumberOfAlwaysOnLights = 0;
  int NumberOfLightsBelowCutoff = 0;
  int NumberOfSpotLights = 0;
  int NumberOfAssignedLights = 0;
  int ClusterGridInUse[3] = { 0, 0, 0 };
  bool ClusteringBypassed = false;
  double MeanLightsPerCluster = 0.0;
  double MeanLightsEvaluatedPerPixel = 0.0;
  double MeanLightsReachingPerPixel = 0.0;
  int MaximumLightsEvaluatedPerPixel = 0;
  vtkIdType NumberOfCountedPixels = 0;
  double HeatMapScale = 0.0;
  double LastAssignmentTime = 0.0;
  double LastLightUpdateTime = 0.0;
  int NumberOfFarFieldLights = 0;
  int NumberOfPackedFarFieldLights = 0;
  double LastFarFieldBuildTime = 0.0;
  vtkTypeInt64 NumberOfFarFieldNodesBuilt = 0;
  vtkTypeInt64 NumberOfFarFieldBlocks = 0;
  vtkTypeInt64 NumberOfFarFieldBlocksRead = 0;
  double FarFieldGridSpacing = 0.0;
  double NearRadiusCap = 0.0;
  int FarFieldDimensions[3] = { 0, 0, 0 };
  int FarFieldResolutionInUse = 0;
  bool FarFieldErrorBudgetMet = true;
  int NumberOfFarFieldResolutionChoices = 0;
  vtkTypeUInt64 FarFieldTextureBytes = 0;
  bool FarFieldSharedColorUsed = false;
  bool FarFieldSpecularBinsUsed = false;
  bool FarFieldRefinedUsed = false;
  double LastShadingTime = 0.0;
  bool DepthPrepassUsed = false;
  int NumberOfBackfaceCulledProps = 0;
  bool DepthPrepassReused = false;
  bool DepthPrepassKept = false;
  double LastDepthPrepassTime = 0.0;
  int NumberOfDepthPrepassTrials = 0;
  double DepthPrepassTrialRatio = 0.0;
  bool DepthAwareClustersUsed = false;
  double VisibleDepthRange[2] = { 0.0, 0.0 };
  double SlicingRangeInUse[2] = { 0.0, 0.0 };
  double NonEmptyClusterFraction = 1.0;
  double ShadedOpaqueFragmentsPerVisiblePixel = 0.0;
  double ShadedTranslucentFragmentsPerVisiblePixel = 0.0;
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
  void RenderSelection(const vtkRenderState* s);
  void ReportIgnoredRendererOptions(vtkRenderer* ren);
  // FarFieldRefineStillLights: the finer far field for lights that hold still.
  void RefineStillFarField(vtkRenderer* ren, vtkClusteredLightingAssignerInputs& inputs);
  // FarFieldOrder4Diffuse where the GPU has the texture units for it (else order 2, said
  // once), and FarFieldSpecularBins likewise.
  void ChooseFarDiffuseOrder(vtkOpenGLRenderWindow* rw, vtkClusteredLightingAssignerInputs& inputs);
  // Sets each floating-point option that is NaN (vtkSetClampMacro stores NaN as given)
  // back to its default, with a warning, before a frame reads them.
  void ResetNaNOptions();
  void ReportUnlitVolumes(
    const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights);
  vtkClusteredLightingAssignerInputs MakeAssignerInputs(
    vtkRenderer* ren, vtkClusteredLightingLightCollection& lights) const;
  void ReportAssignment(const vtkClusteredLightingAssignment& result);
  void UpdateShaderVariant(const vtkClusteredLightingAssignment& result);
  void RenderDelegate(const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights,
    vtkClusteredLightingAssigner* assigner);
  void RenderDelegateOnce(const vtkRenderState* s);
  void HideClusteredLights(vtkRenderer* ren, const vtkClusteredLightingLightCollection& lights);
  void RestoreRendererLights(vtkRenderer* ren, const vtkClusteredLightingLightCollection& lights);
  bool UsesDepthPrepass(
    const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights) const;
  std::uint64_t MakePrepassSignature(
    const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights);
  void RenderDepthPrepass(
    const vtkRenderState* s, vtkOpenGLRenderWindow* rw, vtkClusteredLightingAssignerInputs& inputs);
  void SetPixelCounts(const vtkRenderState* s, vtkOpenGLRenderWindow* rw);
  void ReportLoopLimit(const vtkClusteredLightingAssignment& r);

  // Test hook (Testing/Cxx/vtkClusteredLightingInspector.h): the assigners of the renderers.
  friend class vtkClusteredLightingInspector;
  vtkClusteredLightingAssigner* GetAssigner(vtkRenderer* renderer) const;
  std::vector<vtkClusteredLightingAssigner*> GetAssigners() const;
};

#endif
