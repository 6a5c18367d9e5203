// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingAssigner.h"

#include "vtkCamera.h"
#include "vtkClusteredLightingFarFieldBlocks.h"
#include "vtkClusteredLightingLightCollector.h"
#include "vtkClusteredLightingRasterBackend.h"
#include "vtkClusteredLightingSurfaceBoxes.h"
#include "vtkCommand.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for glFinish, GL limits

#include <algorithm> // for std::min, std::count_if
#include <chrono>    // for timings
#include <cmath>     // for std::isinf
#include <sstream>   // for std::ostringstream

using namespace vtkClusteredLighting;

namespace
{
/// Fewer lights than this never get the "clustering cannot cull" warning: a handful of
/// vtkLights that reach everywhere is an ordinary scene, not a mistake.
constexpr int MinimumLightsForCullingWarning = 64;
/// Grids of fewer clusters than this cull little by the user's choice (a 1x1x1 grid
/// culls nothing): no "culls little" warning for them.
constexpr int MinimumClustersForCullingWarning = 64;

double Milliseconds(
  std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}

glm::dmat4 ToGLM(vtkMatrix4x4* m)
{
  glm::dmat4 g;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      g[c][r] = m->GetElement(r, c);
    }
  }
  return g;
}

bool SameGrid(const ClusterGridParams& a, const ClusterGridParams& b)
{
  return a.TilesX == b.TilesX && a.TilesY == b.TilesY && a.Slices == b.Slices &&
    a.ViewportWidth == b.ViewportWidth && a.ViewportHeight == b.ViewportHeight &&
    a.NearVC == b.NearVC && a.FarVC == b.FarVC && a.SlicingNearVC == b.SlicingNearVC &&
    a.SlicingFarVC == b.SlicingFarVC && a.Scheme == b.Scheme;
}
}

//------------------------------------------------------------------------------
ViewParameters vtkClusteredLightingAssigner::ComputeView(
  vtkRenderer* renderer, const vtkClusteredLightingGridOptions& options)
{
  ViewParameters view;
  vtkCamera* camera = renderer->GetActiveCamera();
  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  const bool parallel = camera->GetParallelProjection() != 0;
  if (vtkOpenGLCamera* glCamera = vtkOpenGLCamera::SafeDownCast(camera))
  {
    // Exactly the matrices the mappers will use (stored transposed for GL).
    vtkMatrix4x4* wcvc = nullptr;
    vtkMatrix3x3* normals = nullptr;
    vtkMatrix4x4* vcdc = nullptr;
    vtkMatrix4x4* wcdc = nullptr;
    glCamera->GetKeyMatrices(renderer, wcvc, normals, vcdc, wcdc);
    view.WCVC = glm::transpose(ToGLM(wcvc));
    view.VCDC = glm::transpose(ToGLM(vcdc));
  }
  else
  {
    view.WCVC = ToGLM(camera->GetModelViewTransformMatrix());
    view.VCDC = ToGLM(camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
  }
  double range[2];
  camera->GetClippingRange(range);
  view.Grid.TilesX = options.TilesX;
  view.Grid.TilesY = options.TilesY;
  view.Grid.Slices = options.Slices;
  view.Grid.ViewportWidth = std::max(width, 1);
  view.Grid.ViewportHeight = std::max(height, 1);
  view.Grid.NearVC = range[0];
  view.Grid.FarVC = range[1];
  SanitizeDepthRange(view.Grid.NearVC, view.Grid.FarVC);
  const bool linear = options.Scheme == vtkClusteredLightingGridOptions::Slicing::Linear ||
    (options.Scheme == vtkClusteredLightingGridOptions::Slicing::Auto && parallel);
  view.Grid.Scheme = linear ? SlicingScheme::Linear : SlicingScheme::Exponential;
  view.Bounds = options.Bounds;
  return view;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingAssigner::PreparationKey::operator!=(const PreparationKey& o) const
{
  return this->Cutoff != o.Cutoff || this->FarFieldCutoff != o.FarFieldCutoff ||
    this->ErrorBudget != o.ErrorBudget || this->Windowed != o.Windowed ||
    this->MortonOrder != o.MortonOrder || this->FarField.Enabled != o.FarField.Enabled ||
    this->FarField.CellsPerRadius != o.FarField.CellsPerRadius ||
    this->FarField.TargetNodes != o.FarField.TargetNodes ||
    this->FarField.Grouping != o.FarField.Grouping ||
    this->FarField.NearBudget != o.FarField.NearBudget ||
    this->FarField.SharedColor != o.FarField.SharedColor ||
    this->FarField.Order4Diffuse != o.FarField.Order4Diffuse ||
    this->FarField.SpecularBins != o.FarField.SpecularBins || this->RegionLo != o.RegionLo ||
    this->RegionHi != o.RegionHi;
}

unsigned int vtkClusteredLightingAssigner::ViewKey::CompareWith(const ViewKey& o) const
{
  unsigned int reasons = 0;
  if (this->WCVC != o.WCVC || this->VCDC != o.VCDC)
  {
    reasons |= CL_DIRTY_VIEW;
  }
  if (!SameGrid(this->Grid, o.Grid))
  {
    reasons |= CL_DIRTY_GRID;
  }
  if (this->Bounds != o.Bounds || this->Clustered != o.Clustered ||
    this->PerClusterCulling != o.PerClusterCulling || this->SpotConeCulling != o.SpotConeCulling)
  {
    reasons |= CL_DIRTY_MODE;
  }
  return reasons;
}

//------------------------------------------------------------------------------
vtkClusteredLightingAssigner::vtkClusteredLightingAssigner()
  : Backend(new vtkClusteredLightingRasterBackend)
{
}

vtkClusteredLightingAssigner::~vtkClusteredLightingAssigner()
{
  this->ReleaseGraphicsResources(nullptr);
  this->SetWindow(nullptr);
}

//------------------------------------------------------------------------------
// The window is watched so that its GL objects are released, in its own context, when it
// is deleted, even if its renderer no longer uses the pass then (VTK only releases the
// passes of the renderers it still holds, and vtkOpenGLBufferObject would later delete
// its stale name in whatever context is current).
void vtkClusteredLightingAssigner::SetWindow(vtkOpenGLRenderWindow* rw)
{
  if (this->Window == rw)
  {
    return;
  }
  if (this->Window && this->WindowObserver)
  {
    this->Window->RemoveObserver(this->WindowObserver);
  }
  this->WindowObserver = 0;
  this->Window = rw;
  if (rw)
  {
    this->WindowObserver = rw->AddObserver(
      vtkCommand::DeleteEvent, this, &vtkClusteredLightingAssigner::OnWindowDeleted);
  }
}

void vtkClusteredLightingAssigner::OnWindowDeleted()
{
  this->ReleaseGraphicsResources(this->Window);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingAssigner::ReleaseGraphicsResources(vtkWindow* win)
{
  // Make the objects' own context current: vtkOpenGLBufferObject and
  // vtkOpenGLVertexArrayObject delete their names in whatever context is current (which
  // may be another window's, with names of its own), and a null window (destructor)
  // would otherwise leave them alive.
  vtkOpenGLRenderWindow* w =
    vtkOpenGLRenderWindow::SafeDownCast(win ? win : this->Window.GetPointer());
  const bool push = w && this->GetNumberOfGLObjects() > 0;
  if (push)
  {
    w->PushContext();
  }
  this->LightData.Release(w);
  this->LightView.Release(w);
  this->FarField.Release(w);
  this->Backend->ReleaseGraphicsResources(w);
  if (push)
  {
    w->PopContext();
  }
  this->SampleDepths.Release(w); // in its own context
  this->SavedDepth.Release(w);
  this->LightDataUploaded = false;
  this->AssignmentValid = false;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingAssigner::GetNumberOfGLObjects() const
{
  return this->LightData.GetNumberOfGLObjects() + this->LightView.GetNumberOfGLObjects() +
    this->FarField.GetNumberOfGLObjects() + this->Backend->GetNumberOfGLObjects() +
    this->SampleDepths.GetNumberOfGLObjects() + this->SavedDepth.GetNumberOfGLObjects();
}

void vtkClusteredLightingAssigner::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  this->LightData.GetGLObjectNames(names);
  this->LightView.GetGLObjectNames(names);
  this->FarField.GetGLObjectNames(names);
  this->Backend->GetGLObjectNames(names);
  this->SampleDepths.GetGLObjectNames(names);
  this->SavedDepth.GetGLObjectNames(names);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingAssigner::AreNewSources(const vtkClusteredLightingSourceKey& key) const
{
  return !this->HaveSources || key.Objects != this->SourceObjects ||
    key.NewestMTime != this->SourceMTime;
}

//------------------------------------------------------------------------------
const vtkClusteredLightingAssignment& vtkClusteredLightingAssigner::Update(
  vtkOpenGLRenderWindow* rw, const vtkClusteredLightingAssignerInputs& asked)
{
  // What this update uses: the asked inputs, with a smaller grid when the asked one cannot
  // hold the lights and the plain loop when every light reaches every cluster (step 3).
  vtkClusteredLightingAssignerInputs inputs = asked;
  vtkClusteredLightingAssignment& r = this->Result;
  r.Reasons = 0;
  r.LightsUploaded = false;
  r.FarFieldResolutionChosen = false;
  r.Reassigned = false;
  r.NewProblems.clear();
  r.NewError.clear();
  r.NewWarnings.clear();
  r.Linear = inputs.View.Grid.Scheme == SlicingScheme::Linear;

  // 1. What changed.
  if (this->Window != rw)
  {
    if (this->Window)
    {
      this->ReleaseGraphicsResources(this->Window);
    }
    this->SetWindow(rw);
    r.Reasons |= CL_DIRTY_RESOURCES;
  }
  if (!this->LightDataUploaded && !this->AssignmentValid)
  {
    r.Reasons |= CL_DIRTY_RESOURCES;
  }
  const vtkClusteredLightingSourceKey& key = inputs.Lights->Key;
  if (this->AreNewSources(key))
  {
    r.Reasons |= CL_DIRTY_LIGHTS;
  }
  this->UpdateRegion(inputs);
  PreparationKey preparation;
  preparation.Cutoff = inputs.Preparation.Cutoff;
  // The split lights' own cutoff, unless an error budget chooses it.
  preparation.FarFieldCutoff = inputs.ErrorBudget > 0.0 ? 0.0 : inputs.Preparation.FarFieldCutoff;
  preparation.FarField = inputs.FarField;
  preparation.RegionLo = this->RegionLo;
  preparation.RegionHi = this->RegionHi;
  preparation.ErrorBudget = inputs.ErrorBudget;
  preparation.Windowed = inputs.ErrorBudget > 0.0 && inputs.Windowed; // only the budget uses it
  preparation.MortonOrder = inputs.Preparation.MortonOrder;
  if (preparation != this->LastPreparation)
  {
    r.Reasons |= CL_DIRTY_PREPARATION;
  }

  // 2. Prepare lights.
  const auto t0 = std::chrono::steady_clock::now();
  r.LightUpdateTime = 0.0;
  if (r.Reasons & (CL_DIRTY_LIGHTS | CL_DIRTY_PREPARATION))
  {
    this->HaveSources = true;
    this->SourceObjects = key.Objects;
    this->SourceMTime = key.NewestMTime;
    this->LastPreparation = preparation;
    this->PrepareLights(inputs);
  }
  const PreparedLights& prepared = this->Prepared;
  r.EffectiveCutoff = this->EffectiveCutoff;
  r.EffectiveFarFieldCutoff = this->EffectiveFarFieldCutoff;
  r.NumberOfLights = static_cast<int>(prepared.Lights.size());
  r.NumberOfRejected = static_cast<int>(prepared.Problems.size());
  r.NumberOfAlwaysOn = static_cast<int>(prepared.NumberOfAlwaysOn);
  r.NumberOfBelowCutoff = static_cast<int>(prepared.NumberOfBelowCutoff);
  r.NumberOfSpots = static_cast<int>(prepared.NumberOfSpots);
  r.FirstSpot = static_cast<int>(prepared.FirstSpot);
  r.NumberOfExplicitRadius = static_cast<int>(prepared.NumberOfExplicitRadius);

  // 3. Limits (may choose a smaller grid) and the plain loop when clustering cannot cull.
  r.Bypassed = inputs.Clustered && !prepared.Lights.empty() &&
    this->NumberReachingEveryCluster == prepared.Lights.size();
  inputs.Clustered = inputs.Clustered && !r.Bypassed;
  r.Clustered = inputs.Clustered;
  r.Enabled = this->CheckLimits(rw, inputs);
  r.Grid[0] = inputs.View.Grid.TilesX;
  r.Grid[1] = inputs.View.Grid.TilesY;
  r.Grid[2] = inputs.View.Grid.Slices;

  // 4. Depth-aware clusters: slices where the geometry is, each cluster cut to its depths
  // (before the far field, whose marks in a multisampled framebuffer are made again when
  // these change).
  const auto boundsStart = std::chrono::steady_clock::now();
  this->UpdateDepthBounds(inputs);
  const double boundsTime = Milliseconds(boundsStart, std::chrono::steady_clock::now());

  // 5. Light records, uploaded only when the lights changed. The far field is summed on
  // the blocks the surfaces read: all of them when the lights changed, else those that
  // surfaces reached since (a prop that moved or appeared, or, multisampled, a view whose
  // recorded fragments reach new blocks).
  if (r.Enabled && this->FarFieldPlan.Active)
  {
    this->UpdateFarFieldBlocks(inputs);
  }
  r.FarFieldNodesBuilt = 0;
  if (r.Enabled && this->LightDataUploaded && this->FarFieldPlan.Active &&
    this->FarField.GetNumberOfGLObjects() > 0 && !this->FarFieldNeededBuilt)
  {
    bool ok = true;
    if (this->FarField.IsMissingBlocks(this->FarFieldNeeded))
    {
      ok = this->FarField.Extend(rw, this->FarFieldPlan, prepared.Lights, this->FarFieldNeeded);
      if (!ok)
      {
        r.NewError = "Could not upload the far field (its RGBA32F 3D textures).";
      }
      r.FarFieldBuildTime = this->FarField.GetBuildTime();
      r.FarFieldNodesBuilt = this->FarField.GetNodesBuilt();
    }
    this->FarFieldNeededBuilt = ok;
  }
  if (r.Enabled && !this->LightDataUploaded)
  {
    this->LightData.Upload(rw, PackLightData(prepared.Lights));
    this->LightDataUploaded = true;
    r.LightsUploaded = true;
    // The far field holds what the near radii cut off; it changes with the lights only.
    r.FarField = false;
    if (this->FarFieldPlan.Active)
    {
      r.FarField =
        this->FarField.Build(rw, this->FarFieldPlan, prepared.Lights, &this->FarFieldNeeded);
      this->FarFieldNeededBuilt = r.FarField;
      r.FarFieldBuildTime = this->FarField.GetBuildTime();
      r.FarFieldNodesBuilt = this->FarField.GetNodesBuilt();
      if (!r.FarField)
      {
        r.NewError = "Could not upload the far field (its RGBA32F 3D textures).";
      }
      else if (this->FarField.GetSpecularBinsTooDeep())
      {
        const std::array<int, 3>& d = this->FarFieldPlan.Grid.Dims;
        r.NewWarnings.emplace_back(std::string(inputs.SpecularBinsOption) +
          ": the far field's grid (" + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
          std::to_string(d[2]) +
          " nodes) needs a 3D texture larger than this GPU's largest (GL_MAX_3D_TEXTURE_SIZE) "
          "for the far specular's bins; the far specular comes from the moments alone. A "
          "smaller FarFieldResolution makes room.");
      }
    }
    else
    {
      this->FarField.Release(rw);
    }
  }
  r.FarField = r.Enabled && this->FarFieldPlan.Active && this->FarField.GetNumberOfGLObjects() > 0;
  r.NumberOfFarFieldLights = static_cast<int>(this->FarFieldPlan.NumberOfFarFieldLights);
  r.NumberOfPackedFarFieldLights = static_cast<int>(this->FarFieldPlan.NumberOfPackedNearRadii);
  r.FarFieldSpacing = this->FarFieldPlan.Active ? this->FarFieldPlan.Grid.Spacing : 0.0;
  r.FarFieldBlocks =
    this->FarFieldPlan.Active ? GetNumberOfFarFieldBlocks(this->FarFieldPlan.Grid) : 0;
  r.FarFieldBlocksNeeded = this->FarFieldPlan.Active ? this->NeededBlocks : 0;
  r.NearRadiusCap = this->FarFieldPlan.Active ? this->FarFieldPlan.NearRadiusCap : 0.0;
  for (int a = 0; a < 3; ++a)
  {
    r.FarFieldDims[a] = this->FarFieldPlan.Active ? this->FarFieldPlan.Grid.Dims[a] : 0;
  }
  r.FarFieldBytes = this->FarField.GetBytes();
  const glm::dvec3 shared = r.FarField ? this->FarField.GetSharedColor() : glm::dvec3(0.0);
  r.FarFieldOneChannel = shared != glm::dvec3(0.0);
  r.FarFieldOrder4 = r.FarField && this->FarFieldPlan.Order4Diffuse;
  r.FarFieldSpecularBins = r.FarField && this->FarField.HasSpecularBins();
  r.SpecularBinsAxis = this->FarField.GetSpecularBinsAxis();
  for (int c = 0; c < 3; ++c)
  {
    r.FarFieldColor[c] = static_cast<float>(shared[c]);
  }
  if (r.Reasons & (CL_DIRTY_LIGHTS | CL_DIRTY_PREPARATION))
  {
    if (inputs.MeasureTimings)
    {
      glFinish();
    }
    // Not the depth bounds' time, measured on its own (DepthBoundsTime).
    r.LightUpdateTime = Milliseconds(t0, std::chrono::steady_clock::now()) - boundsTime;
  }

  // 6-7. View records, list and master: only when something changed.
  ViewKey view;
  view.WCVC = inputs.View.WCVC;
  view.VCDC = inputs.View.VCDC;
  view.Grid = inputs.View.Grid;
  view.Bounds = static_cast<int>(inputs.View.Bounds);
  view.Clustered = inputs.Clustered;
  view.PerClusterCulling = inputs.PerClusterCulling;
  view.SpotConeCulling = inputs.View.SpotConeCulling;
  r.Reasons |= view.CompareWith(this->LastView);
  if (!r.Enabled)
  {
    this->AssignmentValid = false;
  }
  else if (r.Reasons != 0 || !this->AssignmentValid)
  {
    this->LastView = view;
    this->Assign(rw, inputs);
  }
  r.Enabled = r.Enabled && this->AssignmentValid;
  if (r.Enabled && r.Reassigned)
  {
    this->CheckCulling(inputs);
  }
  r.NumberOfAssigned = r.Enabled ? r.NumberOfAssigned : 0;
  r.MasterTexels = std::max(this->Layout.MasterTexelsPerCluster, 1);
  r.ListBytes = this->Backend->GetListBytes();
  r.MasterBytes = this->Backend->GetMasterBytes();
  r.LightBufferBytes =
    16u * (this->LightData.GetNumberOfTexels() + this->LightView.GetNumberOfTexels()) +
    this->Backend->GetWorkBytes();
  return r;
}

//------------------------------------------------------------------------------
// Squares of pixels marked together (MarkFarFieldBlocksOfPixels): 8 x 8 pixels at a few
// metres are a fraction of a far-field cell, and a 1024 x 768 view is 12,288 squares.
constexpr int FarFieldMarkPiece = 8;

//------------------------------------------------------------------------------
// The surfaces' marks are made again only when their boxes or the grid changed: lights
// that move every frame reuse them. Where fragments may lie off their surfaces, the marks
// of the prepass's recorded depths are added again when the depth-aware clusters or the
// view changed (a moving camera); without that record every block is marked.
void vtkClusteredLightingAssigner::UpdateFarFieldBlocks(
  const vtkClusteredLightingAssignerInputs& inputs)
{
  const vtkClusteredLighting::FarFieldGrid& grid = this->FarFieldPlan.Grid;
  const std::size_t blocks = static_cast<std::size_t>(GetNumberOfFarFieldBlocks(grid));
  const vtkClusteredLightingSurfaceBoxes* surfaces = inputs.Surfaces;
  const bool everywhere = !surfaces || surfaces->GetEverywhere();
  const std::uint64_t version = surfaces ? surfaces->GetVersion() : 0;
  bool changed = false;
  if (!(this->SurfaceNeeded.size() == blocks && everywhere == this->NeededEverywhere &&
        (everywhere || version == this->NeededVersion) && grid.Origin == this->NeededGrid.Origin &&
        grid.Spacing == this->NeededGrid.Spacing && grid.Dims == this->NeededGrid.Dims))
  {
    this->NeededEverywhere = everywhere;
    this->NeededVersion = version;
    this->NeededGrid = grid;
    this->SurfaceNeeded.assign(blocks, everywhere ? vtkClusteredLighting::FarFieldAllNodes : 0);
    this->SurfaceBlocks = everywhere ? static_cast<std::int64_t>(blocks) : 0;
    if (!everywhere)
    {
      const std::vector<glm::dvec3>& boxes = surfaces->GetBoxes();
      for (std::size_t i = 0; i + 1 < boxes.size(); i += 2)
      {
        this->SurfaceBlocks += vtkClusteredLighting::MarkFarFieldBlocks(
          grid, boxes[i], boxes[i + 1], this->SurfaceNeeded);
      }
    }
    changed = true;
  }
  const bool offSurfaces = inputs.FragmentsOffSurfaces && !everywhere;
  if (offSurfaces &&
    (changed || !this->PixelsMarked || this->MarkedDepthBoundsVersion != this->DepthBoundsVersion ||
      this->MarkedWCVC != inputs.View.WCVC || this->MarkedVCDC != inputs.View.VCDC))
  {
    this->FarFieldNeeded = this->SurfaceNeeded;
    std::int64_t added = 0;
    // The record holds the opaque fragments the prepass drew: a frame with translucent
    // geometry (shaded off its surfaces too, and not recorded) marks every block.
    if (inputs.Depths && this->DepthBounds.Valid && !inputs.DepthOptions.Translucent &&
      vtkClusteredLighting::MarkFarFieldBlocksOfPixels(grid, *inputs.Depths, inputs.View.WCVC,
        inputs.View.VCDC, inputs.DepthOptions.WindowMargin, FarFieldMarkPiece, this->FarFieldNeeded,
        &added))
    {
      this->NeededBlocks = this->SurfaceBlocks + added;
    }
    else
    {
      this->FarFieldNeeded.assign(blocks, vtkClusteredLighting::FarFieldAllNodes);
      this->NeededBlocks = static_cast<std::int64_t>(blocks);
    }
    this->MarkedDepthBoundsVersion = this->DepthBoundsVersion;
    this->MarkedWCVC = inputs.View.WCVC;
    this->MarkedVCDC = inputs.View.VCDC;
    changed = true;
  }
  else if (!offSurfaces && (changed || this->PixelsMarked))
  {
    this->FarFieldNeeded = this->SurfaceNeeded;
    this->NeededBlocks = this->SurfaceBlocks;
    changed = true;
  }
  this->PixelsMarked = offSurfaces;
  if (changed)
  {
    this->FarFieldNeededBuilt = false; // new marks: the textures may miss some
  }
}

//------------------------------------------------------------------------------
// The far field's region follows the geometry but is sticky: it changes only when the
// geometry leaves it or shrinks to less than half of it on some axis, so that animated
// geometry does not rebuild the far field every frame. It is grown by FarFieldRegionMargin
// on every side when adopted, and the geometry's lower corner at that time anchors the
// grid's node planes (ComputeFarFieldGrid: a floor at the bottom lies on a node plane).
void vtkClusteredLightingAssigner::UpdateRegion(const vtkClusteredLightingAssignerInputs& inputs)
{
  const glm::dvec3 lo = inputs.RegionLo, hi = inputs.RegionHi;
  if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z))
  {
    return; // no geometry: keep what we have (or the lights' box, see PlanFarField)
  }
  const bool valid = this->RegionLo.x <= this->RegionHi.x;
  bool keep = valid;
  for (int a = 0; a < 3 && keep; ++a)
  {
    const double current = this->RegionHi[a] - this->RegionLo[a];
    keep = lo[a] >= this->RegionLo[a] && hi[a] <= this->RegionHi[a] &&
      (hi[a] - lo[a]) >= 0.5 * current - 1e-12 * std::abs(current);
  }
  if (!keep)
  {
    const glm::dvec3 grow = vtkClusteredLighting::FarFieldRegionMargin * (hi - lo);
    this->RegionLo = lo - grow;
    this->RegionHi = hi + grow;
    this->RegionAnchor = lo;
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingAssigner::PrepareLights(const vtkClusteredLightingAssignerInputs& inputs)
{
  vtkClusteredLightingLightCollection& lights = *inputs.Lights;
  vtkClusteredLightingLightCollector::Read(lights);
  auto nameOf = [&lights](std::size_t i) { return lights.NameOf(i); };
  LightPreparationOptions options = inputs.Preparation;
  double farBudget = 0.0; // the far field's share of the error budget (fraction)
  if (inputs.ErrorBudget > 0.0)
  {
    // Validate once, share the budget between the culled lights' tails and the far field
    // (ShareErrorBudget: half each when both are present), then pick the cutoff that meets
    // the tails' share over the lights that are culled, not split (ChooseBudgetCutoff).
    LightPreparationOptions probe = options;
    probe.MortonOrder = false;
    const PreparedLights valid = vtkClusteredLighting::PrepareLights(lights.Sources, probe, nameOf);
    const vtkClusteredLighting::ErrorBudgetShares shares = vtkClusteredLighting::ShareErrorBudget(
      valid.Lights, inputs.ErrorBudget, inputs.FarField.Enabled);
    options.Cutoff = vtkClusteredLighting::ChooseBudgetCutoff(valid.Lights, shares.CutTails,
      inputs.FarField.Enabled, options.Cutoff, inputs.Windowed, this->RegionLo, this->RegionHi);
    farBudget = shares.FarField;
    if (farBudget > 0.0)
    {
      // The split lights' cutoff is their own, chosen with the far field's share
      // (ChooseFarFieldOptions) from ContributionCutoff (not FarFieldCutoff: the search
      // only loosens, and a tight budget may need the tighter cutoff); the last choice's
      // while it stands (the same preparation key; the numbers of lights are checked
      // after preparing).
      options.FarFieldCutoff = inputs.Preparation.Cutoff;
      if (this->HaveBudgetChoice && !(this->BudgetChoiceKey != this->LastPreparation))
      {
        options.FarFieldCutoff = this->BudgetChoice.Cutoff;
      }
    }
  }
  this->Prepared = vtkClusteredLighting::PrepareLights(lights.Sources, options, nameOf);
  // Near radii and the far field's grid (caps the culling radii of far-field lights); a
  // new budget choice may take another cutoff for the split lights, and prepare again.
  const vtkClusteredLighting::FarFieldOptions farOptions =
    this->ChooseFarFieldOptions(inputs, farBudget, options);
  if (farBudget > 0.0 && this->HaveBudgetChoice &&
    this->BudgetChoice.Cutoff != options.FarFieldCutoff)
  {
    options.FarFieldCutoff = this->BudgetChoice.Cutoff;
    this->Prepared = vtkClusteredLighting::PrepareLights(lights.Sources, options, nameOf);
  }
  this->EffectiveCutoff = options.Cutoff;
  this->EffectiveFarFieldCutoff = options.GetFarFieldCutoff();
  this->FarFieldPlan = PlanFarField(
    this->Prepared.Lights, this->RegionLo, this->RegionHi, farOptions, this->RegionAnchor);
  this->Result.FarFieldNodesTarget = this->FarFieldPlan.Active ? farOptions.TargetNodes : 0;
  this->NumberReachingEveryCluster = static_cast<std::size_t>(std::count_if(
    this->Prepared.Lights.begin(), this->Prepared.Lights.end(), &ReachesEveryCluster));
  // Report each problem once: a bad light stays reported while it stays bad, even when
  // other lights change every frame.
  // Many at once are summarized: a few lines per light set (vtkClusteredLightingMessages.h).
  std::set<std::string> problems(this->Prepared.Problems.begin(), this->Prepared.Problems.end());
  std::vector<std::string> fresh;
  for (const std::string& problem : this->Prepared.Problems)
  {
    if (!this->ReportedProblems.count(problem))
    {
      fresh.push_back(problem);
    }
  }
  this->Result.NewProblems = vtkClusteredLighting::SummarizeProblems(
    fresh, vtkClusteredLighting::DefaultMaximumProblemsPerSource);
  this->ReportedProblems.swap(problems);
  this->LightDataUploaded = false;
  this->AssignmentValid = false;
}

//------------------------------------------------------------------------------
// The far field's options for this preparation: the pass's, with the resolution and the
// split lights' cutoff an error budget chooses with the far field's share `budget`
// (vtkClusteredLightingFarFieldBudget.h; the caller prepares again at a new cutoff). The
// choice is made again only when what it depends on changes (the preparation key:
// budget, options, region; the number of lights and of split lights), not when lights
// move or change brightness (the budget was met when chosen; ComputeFarFieldErrorBound
// gives the bound now): it summarizes the bound at up to 7 resolutions per cutoff tried
// (0.1 to 0.25 s each at 4,096 lights on 2 threads).
vtkClusteredLighting::FarFieldOptions vtkClusteredLightingAssigner::ChooseFarFieldOptions(
  const vtkClusteredLightingAssignerInputs& inputs, double budget,
  const vtkClusteredLighting::LightPreparationOptions& preparation)
{
  vtkClusteredLighting::FarFieldOptions options = inputs.FarField;
  vtkClusteredLightingAssignment& r = this->Result;
  if (!(budget > 0.0) || !options.Enabled)
  {
    this->HaveBudgetChoice = false;
    r.FarFieldBudgetChoice = vtkClusteredLighting::FarFieldResolutionChoice();
    return options;
  }
  const std::vector<PreparedLight>& lights = this->Prepared.Lights;
  const std::size_t split = static_cast<std::size_t>(
    std::count_if(lights.begin(), lights.end(), &vtkClusteredLighting::IsFarFieldLight));
  if (!this->HaveBudgetChoice || this->BudgetChoiceKey != this->LastPreparation ||
    this->BudgetChoiceLights != lights.size() || this->BudgetChoiceSplit != split)
  {
    const bool warned = this->HaveBudgetChoice && !this->BudgetChoice.Resolution.Met &&
      this->BudgetChoiceKey.ErrorBudget == this->LastPreparation.ErrorBudget;
    // The lights as prepared with the split lights at the pass's cutoff (the budget's
    // starting point), or at a looser one; the culled lights keep theirs.
    const vtkClusteredLightingLightCollection& collection = *inputs.Lights;
    auto nameOf = [&collection](std::size_t i) { return collection.NameOf(i); };
    auto prepare = [&](double cutoff) -> std::vector<PreparedLight>
    {
      if (cutoff == preparation.FarFieldCutoff)
      {
        return lights;
      }
      vtkClusteredLighting::LightPreparationOptions at = preparation;
      at.FarFieldCutoff = cutoff;
      return vtkClusteredLighting::PrepareLights(collection.Sources, at, nameOf).Lights;
    };
    this->BudgetChoice = vtkClusteredLighting::ChooseFarFieldCutoffAndResolution(prepare,
      inputs.Preparation.Cutoff, this->RegionLo, this->RegionHi, options, this->RegionAnchor,
      255.0 * budget, &SummarizeOnThreads);
    this->HaveBudgetChoice = true;
    this->BudgetChoiceKey = this->LastPreparation;
    this->BudgetChoiceLights = lights.size();
    this->BudgetChoiceSplit = split;
    r.FarFieldResolutionChosen = true;
    if (!this->BudgetChoice.Resolution.Met && !warned)
    {
      std::ostringstream os;
      os << "ErrorBudgetInSteps " << 255.0 * inputs.ErrorBudget << ": the far field's stated bound "
         << "is " << this->BudgetChoice.Resolution.Bound
         << " steps (its largest value over probe points) at its best resolution ("
         << this->BudgetChoice.Resolution.Nodes << " nodes), above its share "
         << "of the budget (" << 255.0 * budget << " steps); no resolution tried ("
         << vtkClusteredLighting::FarFieldBudgetCoarsestNodes << " to "
         << vtkClusteredLighting::FarFieldBudgetFinestNodes << " nodes) gives less, so that "
         << "one is used. A larger NearFieldBudget (lights per point evaluated exactly, now "
         << options.NearBudget << ") lowers it somewhat, at more time per frame; a larger "
         << "budget accepts it.";
      r.NewWarnings.push_back(os.str());
    }
  }
  r.FarFieldBudgetChoice = this->BudgetChoice.Resolution;
  options.TargetNodes = this->BudgetChoice.Resolution.Nodes;
  return options;
}

//------------------------------------------------------------------------------
// Whether the lights fit the GL limits (texture buffer size, list and master texture
// sizes); computes the texture layout. A new error is put in the result.
bool vtkClusteredLightingAssigner::CheckLimits(
  vtkOpenGLRenderWindow* rw, vtkClusteredLightingAssignerInputs& inputs)
{
  const int numberOfLights = static_cast<int>(this->Prepared.Lights.size());
  this->Layout = ClusterTextureLayout();
  if (numberOfLights == 0)
  {
    return false;
  }
  int maxTexture = vtkTextureObject::GetMaximumTextureSize(rw);
  if (inputs.MaximumTextureSize > 0)
  {
    maxTexture = std::min(maxTexture, inputs.MaximumTextureSize);
  }
  GLint maxBuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxBuffer);
  std::string error;
  bool ok = true;
  if (static_cast<vtkTypeInt64>(numberOfLights) * 2 > maxBuffer)
  {
    std::ostringstream os;
    os << numberOfLights << " lights need " << 2 * static_cast<vtkTypeInt64>(numberOfLights)
       << " texels of light records, over GL_MAX_TEXTURE_BUFFER_SIZE " << maxBuffer;
    error = os.str();
    ok = false;
  }
  else if (inputs.Clustered)
  {
    // Never leave the lights unlit when a smaller grid holds them: use the largest such
    // grid and say so once (vtkClusteredLightingLayout.h, ChooseGridForLights).
    ClusterGridParams& g = inputs.View.Grid;
    const int asked[3] = { g.TilesX, g.TilesY, g.Slices };
    int x = g.TilesX, y = g.TilesY, z = g.Slices;
    const bool fits = ChooseGridForLights(x, y, z, numberOfLights, maxTexture);
    std::string warning;
    if (fits && (x != asked[0] || y != asked[1] || z != asked[2]))
    {
      std::ostringstream os;
      os << "A " << asked[0] << "x" << asked[1] << "x" << asked[2] << " cluster grid holds at most "
         << ComputeMaximumNumberOfLights(asked[0], asked[1], asked[2], maxTexture)
         << " lights with textures of at most " << maxTexture << " texels a side; the "
         << numberOfLights << " lights are rendered on a " << x << "x" << y << "x" << z
         << " grid instead (it holds " << ComputeMaximumNumberOfLights(x, y, z, maxTexture)
         << "). Set TilesX, TilesY and Slices to choose the grid yourself.";
      warning = os.str();
    }
    if (!warning.empty() && warning != this->ReportedGridWarning)
    {
      this->Result.NewWarnings.push_back(warning);
    }
    this->ReportedGridWarning = warning;
    // The chosen grid; when none holds the lights, 1x1x1, whose limit the error names.
    g.TilesX = x;
    g.TilesY = y;
    g.Slices = z;
    ok =
      ComputeLayout(g.TilesX, g.TilesY, g.Slices, numberOfLights, maxTexture, this->Layout, &error);
    if (!ok)
    {
      std::ostringstream os;
      os << "no cluster grid holds " << numberOfLights << " lights with textures of at most "
         << maxTexture << " texels a side: even a " << x << "x" << y << "x" << z
         << " grid holds at most " << ComputeMaximumNumberOfLights(x, y, z, maxTexture)
         << " (fewer lights, or a larger MaximumTextureSize up to GL_MAX_TEXTURE_SIZE, would fit)";
      error = os.str();
    }
  }
  if (!ok && error != this->ReportedError)
  {
    this->Result.NewError = "Clustered lights are not rendered: " + error + ".";
  }
  this->ReportedError = ok ? std::string() : error;
  return ok;
}

//------------------------------------------------------------------------------
// A light every cluster holds whatever the view: one that never falls off (no cutoff
// radius, no explicit radius) and that the far field does not split.
bool vtkClusteredLightingAssigner::ReachesEveryCluster(const PreparedLight& light)
{
  return std::isinf(light.Radius) && !light.FarField;
}

//------------------------------------------------------------------------------
// Tells the user once when clustering cannot help: the lights reach (nearly) every
// cluster, so every fragment evaluates (nearly) every light. Names the cause and the fix.
void vtkClusteredLightingAssigner::CheckCulling(const vtkClusteredLightingAssignerInputs& inputs)
{
  const vtkClusteredLightingAssignment& r = this->Result;
  const int n = r.NumberOfLights;
  std::string warning;
  int kind = 0; // 1: bypassed, 2: culls little
  const ClusterGridParams& g = inputs.View.Grid;
  const long long clusters = static_cast<long long>(g.TilesX) * g.TilesY * g.Slices;
  if (n >= MinimumLightsForCullingWarning &&
    (r.Bypassed || clusters >= MinimumClustersForCullingWarning))
  {
    std::ostringstream os;
    const bool farFieldOff = !inputs.FarField.Enabled;
    if (r.Bypassed)
    {
      os << "Clustering cannot cull these lights: all " << n
         << " reach every cluster, because they never fall off (attenuation (1, 0, 0), no "
            "radius)"
         << (farFieldOff ? " and the far field is off" : "")
         << ". They are shaded in a plain loop over all lights (the same image, less work). "
            "To make clustering pay, "
         << (farFieldOff ? "turn the far field on (FarFieldOn), or " : "")
         << "give the lights a falloff (attenuation (0, 0, k)) or an explicit radius.";
      warning = os.str();
      kind = 1;
    }
    else if (r.MeanLightsPerCluster >= 0.5 * n)
    {
      os.precision(3);
      os << "Clustering culls little here: a cluster holds on average " << r.MeanLightsPerCluster
         << " of the " << n << " lights, so every pixel evaluates about as many lights as "
         << "brute force would. ";
      if (this->NumberReachingEveryCluster >= static_cast<std::size_t>(n / 2))
      {
        os << this->NumberReachingEveryCluster
           << " of them never fall off (attenuation (1, 0, 0), no radius): give them a falloff "
              "or an explicit radius";
      }
      else if (this->FarFieldPlan.Active &&
        this->FarFieldPlan.NumberOfPackedNearRadii >= static_cast<std::size_t>(n / 2))
      {
        os << this->FarFieldPlan.NumberOfPackedNearRadii
           << " of them are packed closer than the far field's grid resolves (spacing "
           << this->FarFieldPlan.Grid.Spacing << "), so each is evaluated exactly within "
           << this->FarFieldPlan.Grid.Spacing
           << " x FarFieldCellsPerRadius of it: where the geometry is much larger than the "
              "lights' cloud (a large floor), a larger FarFieldResolution gives them shorter "
              "near radii";
      }
      else
      {
        os << "Their cutoff radii (where each falls to the contribution cutoff "
           << this->EffectiveCutoff << ") span most of the view: give the lights an explicit "
           << "radius with FALLOFF_WINDOWED, or raise ContributionCutoff";
      }
      os << (farFieldOff ? ", or turn the far field on (FarFieldOn), which evaluates only "
                           "their near parts one by one."
                         : ".");
      warning = os.str();
      kind = 2;
    }
  }
  // Reported once per episode: the numbers may drift from frame to frame, the kind not.
  if (kind != 0 && kind != this->ReportedCullingWarning)
  {
    this->Result.NewWarnings.push_back(warning);
  }
  this->ReportedCullingWarning = kind;
}

//------------------------------------------------------------------------------
// The prepass's depths: the slicing range (it changes the grid, so the view records) and
// each cluster's depth interval (compared with the last, so a still frame stays still).
void vtkClusteredLightingAssigner::UpdateDepthBounds(vtkClusteredLightingAssignerInputs& inputs)
{
  vtkClusteredLightingAssignment& r = this->Result;
  r.DepthAware = false;
  r.DepthBoundsTime = 0.0;
  r.VisibleDepthRange[0] = r.VisibleDepthRange[1] = 0.0;
  ClusterDepthBounds bounds;
  if (inputs.Depths && inputs.Clustered && r.Enabled && HasDepthOnlyClipZ(inputs.View.VCDC))
  {
    const auto t0 = std::chrono::steady_clock::now();
    const DepthImage& image = *inputs.Depths;
    const VisibleRange range = MeasureVisibleRange(image, inputs.View.VCDC);
    ChooseSlicingRange(range.Visible, range.Nearest, range.Deepest, inputs.View.Grid);
    const ClusterGridParams& grid = inputs.View.Grid;
    InitializeClusterDepthBounds(grid, bounds);
    // Tile rows are independent: split them over the threads.
    vtkSMPTools::For(0, grid.TilesY,
      [&](vtkIdType begin, vtkIdType end)
      {
        ComputeClusterDepthBoundsRows(image, inputs.View.VCDC, grid, inputs.DepthOptions,
          static_cast<int>(begin), static_cast<int>(end), bounds);
      });
    FinishClusterDepthBounds(range, bounds);
    r.DepthBoundsTime = Milliseconds(t0, std::chrono::steady_clock::now());
    r.VisibleDepthRange[0] = bounds.VisibleNear;
    r.VisibleDepthRange[1] = bounds.VisibleFar;
    r.NonEmptyClusterFraction = bounds.LoHi.empty()
      ? 0.0
      : static_cast<double>(bounds.NonEmptyClusters) / (bounds.LoHi.size() / 2);
  }
  r.DepthAware = bounds.Valid;
  if (!bounds.Valid)
  {
    r.NonEmptyClusterFraction = 1.0;
    if (this->Window)
    {
      this->Backend->ReleaseDepthResources(this->Window);
    }
  }
  r.SlicingRange[0] = inputs.View.Grid.GetSlicingNear();
  r.SlicingRange[1] = inputs.View.Grid.GetSlicingFar();
  if (bounds != this->DepthBounds)
  {
    r.Reasons |= CL_DIRTY_DEPTHS;
    this->DepthBounds = std::move(bounds);
    ++this->DepthBoundsVersion;
  }
}

//------------------------------------------------------------------------------
// The view records and quads in fixed chunks of lights over the threads, joined in chunk
// order: the same quads, in the same order, as one thread would give.
ViewData vtkClusteredLightingAssigner::ComputeViewDataInParallel(
  const vtkClusteredLightingAssignerInputs& inputs) const
{
  const std::vector<PreparedLight>& lights = this->Prepared.Lights;
  const ClusterDepthBounds* depths = inputs.Clustered ? &this->DepthBounds : nullptr;
  const std::size_t chunk = 512;
  const std::size_t chunks = (lights.size() + chunk - 1) / chunk;
  ViewData out;
  out.LightView.resize(lights.size() * FloatsPerLightRecord);
  std::vector<ViewData> parts(chunks);
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType k = first; k < last; ++k)
      {
        const std::size_t begin = static_cast<std::size_t>(k) * chunk;
        ComputeViewDataRange(lights, inputs.View, depths, begin,
          std::min(begin + chunk, lights.size()), out.LightView.data(),
          parts[static_cast<std::size_t>(k)]);
      }
    });
  std::size_t floats = 0;
  for (const ViewData& part : parts)
  {
    floats += part.Quads.size();
  }
  out.Quads.reserve(floats);
  for (const ViewData& part : parts)
  {
    AppendViewData(out, part);
  }
  return out;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingAssigner::Assign(
  vtkOpenGLRenderWindow* rw, const vtkClusteredLightingAssignerInputs& inputs)
{
  vtkClusteredLightingAssignment& r = this->Result;
  const auto t0 = std::chrono::steady_clock::now();
  if (inputs.MeasureTimings)
  {
    glFinish();
  }
  const auto t1 = std::chrono::steady_clock::now();
  const ViewData data = this->ComputeViewDataInParallel(inputs);
  bool ok = this->LightView.Upload(rw, data.LightView);
  if (ok && inputs.Clustered)
  {
    ok = this->Backend->Assign(rw, this->Layout, data,
      ComputeListPassParameters(inputs.View, inputs.PerClusterCulling, &this->DepthBounds),
      this->LightView.GetTexture());
    if (!ok)
    {
      std::ostringstream os;
      os << "Could not allocate or fill the cluster textures (" << this->Layout.ListWidth << "x"
         << this->Layout.ListHeight << " R32UI) with the " << this->Backend->GetName()
         << " back end.";
      r.NewError = os.str();
    }
  }
  if (inputs.MeasureTimings)
  {
    glFinish();
  }
  const auto t2 = std::chrono::steady_clock::now();
  r.AssignmentTime = inputs.MeasureTimings ? Milliseconds(t1, t2) : Milliseconds(t0, t2);
  r.AssignmentTime += r.DepthBoundsTime; // the CPU part of depth-aware clusters
  r.NumberOfQuads = data.NumberOfQuads;
  const ClusterGridParams& g = inputs.View.Grid;
  // For the shader loop limit of llvmpipe (vtkClusteredLightingPass::ReportLoopLimit):
  // up to 50,000 lights no walk, with or without the exact far sums, comes near it.
  r.MostLightsInACluster = inputs.Clustered && r.NumberOfLights > 50000
    ? ComputeMostLightsInACluster(data.Quads, g.TilesX, g.TilesY, g.Slices)
    : r.NumberOfLights;
  const double clusters = this->DepthBounds.Valid
    ? static_cast<double>(std::max<std::size_t>(this->DepthBounds.NonEmptyClusters, 1))
    : static_cast<double>(g.TilesX) * static_cast<double>(g.TilesY) * static_cast<double>(g.Slices);
  r.MeanLightsPerCluster = data.ClusterCoverage / clusters;
  r.NumberOfAssigned = data.NumberOfAssignedLights;
  r.Shading = ComputeShadingParameters(inputs.View, this->Layout);
  if (this->FarFieldPlan.Active)
  {
    const glm::dmat4 fromVC =
      ComputeFarFieldTextureFromVC(this->FarFieldPlan.Grid, inputs.View.WCVC);
    const glm::dmat3 worldFromVC = glm::inverse(glm::dmat3(inputs.View.WCVC));
    for (int i = 0; i < 16; ++i)
    {
      r.FarFieldFromVC[i] = static_cast<float>((&fromVC[0][0])[i]);
    }
    for (int i = 0; i < 9; ++i)
    {
      r.WorldFromVC[i] = static_cast<float>((&worldFromVC[0][0])[i]);
    }
  }
  r.Reassigned = true;
  this->AssignmentValid = ok;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingAssigner::ActivateShading()
{
  vtkClusteredLightingAssignment& r = this->Result;
  for (vtkTextureObject* tex : { this->LightData.GetTexture(), this->LightView.GetTexture() })
  {
    if (tex)
    {
      tex->Activate();
    }
  }
  if (r.Clustered)
  {
    this->Backend->ActivateShadingTextures();
  }
  if (r.FarField && r.Clustered)
  {
    this->FarField.Activate();
    r.FarFieldUnits = this->FarField.GetUnits();
    r.LobeTableUnit = this->FarField.GetLobeTableUnit();
    r.SpecularBinsUnit = this->FarField.GetSpecularBinsUnit();
  }
  r.LightDataUnit =
    this->LightData.GetTexture() ? this->LightData.GetTexture()->GetTextureUnit() : -1;
  r.LightViewUnit =
    this->LightView.GetTexture() ? this->LightView.GetTexture()->GetTextureUnit() : -1;
  r.ListUnit = r.Clustered ? this->Backend->GetListUnit() : -1;
  r.MasterUnit = r.Clustered ? this->Backend->GetMasterUnit() : -1;
}

void vtkClusteredLightingAssigner::DeactivateShading()
{
  for (vtkTextureObject* tex : { this->LightData.GetTexture(), this->LightView.GetTexture() })
  {
    if (tex && tex->GetTextureUnit() >= 0)
    {
      tex->Deactivate();
    }
  }
  this->Backend->DeactivateShadingTextures();
  this->FarField.Deactivate();
  vtkClusteredLightingAssignment& r = this->Result;
  r.FarFieldUnits.fill(-1);
  r.LobeTableUnit = -1;
  r.SpecularBinsUnit = -1;
  r.LightDataUnit = r.LightViewUnit = r.ListUnit = r.MasterUnit = -1;
}

//------------------------------------------------------------------------------
vtkClusteredLighting::FarFieldBoundSummary
vtkClusteredLightingAssigner::SummarizeFarFieldErrorBound() const
{
  if (!this->Result.FarField)
  {
    return vtkClusteredLighting::FarFieldBoundSummary();
  }
  const vtkClusteredLighting::FarFieldBuildInputs in{ &this->FarFieldPlan.Grid,
    &this->Prepared.Lights, &this->FarField.GetNearRadii(), &this->FarField.GetTree(),
    this->FarFieldPlan.Grouping, this->FarFieldPlan.Order4Diffuse,
    this->Result.FarFieldSpecularBins };
  return SummarizeOnThreads(in);
}

//------------------------------------------------------------------------------
vtkClusteredLighting::FarFieldBoundSummary vtkClusteredLightingAssigner::SummarizeOnThreads(
  const vtkClusteredLighting::FarFieldBuildInputs& in)
{
  // The probes are independent: one per task, combined in probe order (the core's
  // serial summary, bit for bit).
  std::vector<double> values(
    static_cast<std::size_t>(vtkClusteredLighting::GetFarFieldBoundProbeCount(in)));
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        values[static_cast<std::size_t>(i)] =
          vtkClusteredLighting::ComputeFarFieldBoundAtProbe(in, static_cast<int>(i));
      }
    });
  return vtkClusteredLighting::SummarizeFarFieldBoundProbes(values);
}

//------------------------------------------------------------------------------
vtkClusteredLightingAssignmentSnapshot vtkClusteredLightingAssigner::GetSnapshot() const
{
  vtkClusteredLightingAssignmentSnapshot f;
  f.Valid = this->AssignmentValid;
  f.Grid = this->LastView.Grid;
  f.WCVC = this->LastView.WCVC;
  f.VCDC = this->LastView.VCDC;
  f.Layout = this->Layout;
  f.Lights = this->Prepared.Lights;
  f.NumberOfQuads = this->Result.NumberOfQuads;
  f.FarField = this->Result.FarField ? this->FarFieldPlan : vtkClusteredLighting::FarFieldPlan();
  f.FarField.SpecularBins = this->Result.FarFieldSpecularBins; // asked and built
  f.DepthBounds = this->Result.DepthAware ? this->DepthBounds : ClusterDepthBounds();
  f.SpotConeCulling = this->LastView.SpotConeCulling;
  return f;
}

bool vtkClusteredLightingAssigner::ReadBackAssignment(
  std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& master)
{
  if (!this->Window || !this->AssignmentValid)
  {
    return false;
  }
  this->Window->MakeCurrent();
  return this->Backend->ReadBack(this->Window, list, master);
}
