// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingPass.h"

#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingAssignment.h"
#include "vtkClusteredLightingFrameState.h"
#include "vtkClusteredLightingGPUResources.h"
#include "vtkClusteredLightingShaderVariant.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h" // for glFinish, GL limits

#include <algorithm> // for std::find
#include <chrono>    // for timings
#include <cstring>   // for std::memcpy
#include <map>       // for std::map
#include <set>       // for std::set
#include <sstream>   // for std::ostringstream

using namespace vtkClusteredLighting;

namespace
{
//------------------------------------------------------------------------------
// Translucent step that behaves like stock VTK: order-independent transparency, or
// (dual) depth peeling when the renderer has UseDepthPeeling on.
class vtkClusteredLightingTranslucentStep : public vtkRenderPass
{
public:
  static vtkClusteredLightingTranslucentStep* New();
  vtkTypeMacro(vtkClusteredLightingTranslucentStep, vtkRenderPass)
  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    vtkRenderer* ren = s->GetRenderer();
    const int before = ren->GetNumberOfPropsRendered();
    ren->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
    this->NumberOfRenderedProps = ren->GetNumberOfPropsRendered() - before;
  }

protected:
  vtkClusteredLightingTranslucentStep() = default;
  ~vtkClusteredLightingTranslucentStep() override = default;
};
vtkStandardNewMacro(vtkClusteredLightingTranslucentStep)

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

double Milliseconds(
  std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}
}

//------------------------------------------------------------------------------
// Everything the pass keeps per renderer.
struct vtkClusteredLightingRendererState
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkClusteredLightingGPUResources GPU;

  // Lights: signature of what they were prepared from, and the result.
  std::vector<vtkTypeUInt64> LightSignature;
  PreparedLights Prepared;
  double EffectiveCutoff = 1.0 / 1024.0;
  std::set<std::string> ReportedProblems;
  unsigned long LightsVersion = 0;
  bool LightDataUploaded = false;

  // View: signature of the last assignment.
  std::vector<double> ViewSignature;
  bool AssignmentValid = false;
  int NumberOfQuads = 0;
  int NumberOfAssignedLights = 0;
  bool LayoutOK = false;
  std::string LayoutError;

  vtkClusteredLightingFrameState Frame;
  glm::dmat4 VCDC = glm::dmat4(1.0);
  double SliceParameters[4] = { 0, 0, 0, 0 };
};

struct vtkClusteredLightingPass::vtkInternals
{
  // The steps of Render(), in order (a nested class sees the pass's options).
  struct Frame;
  void SetUpCamera(vtkClusteredLightingPass* self, Frame& f);
  void PartitionRendererLights(vtkClusteredLightingPass* self, Frame& f);
  void PrepareLightsIfChanged(vtkClusteredLightingPass* self, Frame& f);
  void CheckLimits(vtkClusteredLightingPass* self, Frame& f);
  void ComputeView(vtkClusteredLightingPass* self, Frame& f);
  void UpdateAssignment(vtkClusteredLightingPass* self, Frame& f);
  void UpdateShaderVariant(vtkClusteredLightingPass* self, Frame& f);
  void RenderDelegate(vtkClusteredLightingPass* self, const vtkRenderState* s, Frame& f);

  std::vector<vtkSmartPointer<vtkClusteredLightSet>> LightSets;
  std::map<vtkRenderer*, std::unique_ptr<vtkClusteredLightingRendererState>> States;
  vtkClusteredLightingRendererState* Current = nullptr;
  vtkClusteredLightingShaderVariant Variant; ///< global part for the current render
  vtkTimeStamp ShaderStageTime;
  vtkNew<vtkLight> PlaceholderLight;

  vtkClusteredLightingRendererState* GetState(vtkRenderer* ren, vtkOpenGLRenderWindow* rw)
  {
    // Forget renderers that were deleted (their window may still own the GL objects;
    // the release makes that window's context current and restores the current one).
    for (auto it = this->States.begin(); it != this->States.end();)
    {
      if (!it->second->Renderer)
      {
        if (it->second->Window)
        {
          it->second->GPU.ReleaseGraphicsResources(it->second->Window);
        }
        it = this->States.erase(it);
      }
      else
      {
        ++it;
      }
    }
    auto& state = this->States[ren];
    if (!state)
    {
      state.reset(new vtkClusteredLightingRendererState);
      state->Renderer = ren;
    }
    if (state->Window != rw)
    {
      if (state->Window)
      {
        state->GPU.ReleaseGraphicsResources(state->Window);
      }
      state->Window = rw;
      state->LightDataUploaded = false;
      state->AssignmentValid = false;
      state->ViewSignature.clear();
    }
    return state.get();
  }
};

vtkStandardNewMacro(vtkClusteredLightingPass);

//------------------------------------------------------------------------------
vtkClusteredLightingPass::vtkClusteredLightingPass()
  : Internals(new vtkInternals)
{
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkClusteredLightingTranslucentStep> translucent;
  steps->SetTranslucentPass(translucent);
  this->SetDelegatePass(steps);

  // Keeps VTK's lighting code generated (complexity 1) when every light is clustered.
  vtkLight* placeholder = this->Internals->PlaceholderLight;
  placeholder->SetLightTypeToHeadlight();
  placeholder->SetIntensity(0.0);
  placeholder->SwitchOn();
  this->Internals->ShaderStageTime.Modified();
}

//------------------------------------------------------------------------------
vtkClusteredLightingPass::~vtkClusteredLightingPass()
{
  this->SetDelegatePass(nullptr);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::SetDelegatePass(vtkRenderPass* delegatePass)
{
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, delegatePass);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::AddLightSet(vtkClusteredLightSet* lights)
{
  if (!lights)
  {
    return;
  }
  auto& sets = this->Internals->LightSets;
  if (std::find(sets.begin(), sets.end(), lights) == sets.end())
  {
    sets.emplace_back(lights);
    this->Modified();
  }
}

void vtkClusteredLightingPass::RemoveLightSet(vtkClusteredLightSet* lights)
{
  auto& sets = this->Internals->LightSets;
  auto it = std::find(sets.begin(), sets.end(), lights);
  if (it != sets.end())
  {
    sets.erase(it);
    this->Modified();
  }
}

void vtkClusteredLightingPass::RemoveAllLightSets()
{
  if (!this->Internals->LightSets.empty())
  {
    this->Internals->LightSets.clear();
    this->Modified();
  }
}

int vtkClusteredLightingPass::GetNumberOfLightSets() const
{
  return static_cast<int>(this->Internals->LightSets.size());
}

vtkClusteredLightSet* vtkClusteredLightingPass::GetLightSet(int i) const
{
  const auto& sets = this->Internals->LightSets;
  return (i >= 0 && i < static_cast<int>(sets.size())) ? sets[i].Get() : nullptr;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkClusteredLightingPass::GetMaximumNumberOfLights(
  int tilesX, int tilesY, int slices, int maxTextureSize)
{
  return ComputeMaximumNumberOfLights(tilesX, tilesY, slices, maxTextureSize);
}

//------------------------------------------------------------------------------
int vtkClusteredLightingPass::GetNumberOfGLObjects() const
{
  int n = 0;
  for (const auto& it : this->Internals->States)
  {
    n += it.second->GPU.GetNumberOfGLObjects();
  }
  return n;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::ReleaseGraphicsResources(vtkWindow* w)
{
  // A null window means every window the pass rendered into. VTK's own passes need a
  // window (VTK 9.2 asserts w != nullptr in vtkRenderPass::ReleaseGraphicsResources), so
  // they are released once per known window.
  std::set<vtkWindow*> windows;
  for (auto& it : this->Internals->States)
  {
    vtkClusteredLightingRendererState* state = it.second.get();
    if (!w || state->Window == w)
    {
      if (state->Window)
      {
        windows.insert(state->Window.GetPointer());
      }
      state->GPU.ReleaseGraphicsResources(w ? w : state->Window.GetPointer());
      state->LightDataUploaded = false;
      state->AssignmentValid = false;
      state->ViewSignature.clear();
    }
  }
  if (w)
  {
    windows.insert(w);
  }
  for (vtkWindow* window : windows)
  {
    this->Superclass::ReleaseGraphicsResources(window);
    if (this->DelegatePass)
    {
      this->DelegatePass->ReleaseGraphicsResources(window);
    }
  }
}

//------------------------------------------------------------------------------
// What one Render() works with, step to step.
struct vtkClusteredLightingPass::vtkInternals::Frame
{
  vtkOpenGLRenderer* Renderer = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkClusteredLightingRendererState* State = nullptr;
  std::vector<vtkSmartPointer<vtkLight>> AllLights;   ///< the renderer's, in order
  std::vector<vtkSmartPointer<vtkLight>> StockLights; ///< left to VTK's lighting code
  std::vector<vtkLight*> ClusteredVTKLights;
  ClusterTextureLayout Layout;
  ViewParameters View;
  bool Clustered = true;
  bool Linear = false;
  bool Enabled = false;
  int ViewportOrigin[2] = { 0, 0 };
};

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->LastAssignmentUpdated = false;
  vtkInternals::Frame frame;
  frame.Renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  frame.Window = frame.Renderer
    ? vtkOpenGLRenderWindow::SafeDownCast(frame.Renderer->GetRenderWindow())
    : nullptr;
  if (!frame.Renderer || !frame.Window)
  {
    vtkErrorMacro("vtkClusteredLightingPass needs an OpenGL renderer and render window.");
    return;
  }
  if (!this->DelegatePass)
  {
    vtkWarningMacro("No delegate pass: nothing is rendered.");
    return;
  }
  frame.State = this->Internals->GetState(frame.Renderer, frame.Window);
  frame.Clustered = this->ShadingMode == SHADING_CLUSTERED;
  this->Internals->Current = frame.State;

  this->Internals->SetUpCamera(this, frame);
  this->Internals->PartitionRendererLights(this, frame);
  this->Internals->PrepareLightsIfChanged(this, frame);
  this->Internals->CheckLimits(this, frame);
  this->Internals->ComputeView(this, frame);
  this->Internals->UpdateAssignment(this, frame);
  this->Internals->UpdateShaderVariant(this, frame);
  this->Internals->RenderDelegate(this, s, frame);
  this->Internals->Current = nullptr;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::vtkInternals::SetUpCamera(vtkClusteredLightingPass* self, Frame& f)
{
  // VTK's pass-less pipeline sets the camera's stereo flag in vtkOpenGLCamera::Render;
  // vtkCameraPass does not, so under a render pass every eye would render the same (mono)
  // view. When the flag disagrees with the window, set the camera up as VTK's own
  // pipeline does (viewport, scissor, clear and stereo flag).
  if (f.Renderer->GetActiveCamera()->GetStereo() != f.Window->GetStereoRender())
  {
    self->UpdateCamera(f.Renderer);
  }
  // Camera lights and headlights follow the camera before they are read.
  self->UpdateLightGeometry(f.Renderer);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::vtkInternals::PartitionRendererLights(
  vtkClusteredLightingPass* self, Frame& f)
{
  vtkLightCollection* lights = f.Renderer->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  bool anyOn = false;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    anyOn = anyOn || light->GetSwitch();
  }
  if (!anyOn && f.Renderer->GetAutomaticLightCreation())
  {
    f.Renderer->CreateLight(); // what VTK would do in UpdateLights
  }
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
  {
    f.AllLights.emplace_back(light);
    if (self->ClusterRendererLights && light->GetSwitch() && light->GetPositional())
    {
      f.ClusteredVTKLights.push_back(light);
    }
    else
    {
      f.StockLights.emplace_back(light);
    }
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::vtkInternals::PrepareLightsIfChanged(
  vtkClusteredLightingPass* self, Frame& f)
{
  // Signature of everything the prepared lights depend on.
  std::vector<vtkTypeUInt64> signature;
  auto bits = [](double v)
  {
    vtkTypeUInt64 u;
    std::memcpy(&u, &v, sizeof(u));
    return u;
  };
  signature.push_back(bits(self->Cutoff));
  signature.push_back(bits(self->ErrorBudget));
  signature.push_back(self->ErrorBudget > 0.0 ? static_cast<vtkTypeUInt64>(self->Falloff) : 0u);
  signature.push_back(self->MortonOrder ? 1 : 0);
  for (vtkLight* l : f.ClusteredVTKLights)
  {
    vtkMTimeType t = l->GetMTime();
    if (l->GetTransformMatrix())
    {
      t = std::max(t, l->GetTransformMatrix()->GetMTime());
    }
    signature.push_back(reinterpret_cast<vtkTypeUInt64>(l));
    signature.push_back(t);
  }
  for (const auto& set : this->LightSets)
  {
    set->UpdateLights(); // a set fed by a pipeline reads its input here
    signature.push_back(reinterpret_cast<vtkTypeUInt64>(set.Get()));
    signature.push_back(set->GetEnabled() ? set->GetMTime() : 0);
  }
  if (signature != f.State->LightSignature)
  {
    f.State->LightSignature = signature;
    std::vector<LightSource> sources;
    for (vtkLight* l : f.ClusteredVTKLights)
    {
      LightSource src;
      const double* p = l->GetTransformedPosition();
      const double* focal = l->GetTransformedFocalPoint();
      src.PositionWC = glm::dvec3(p[0], p[1], p[2]);
      src.DirectionWC = glm::dvec3(focal[0] - p[0], focal[1] - p[1], focal[2] - p[2]);
      const double* c = l->GetDiffuseColor();
      src.Color = glm::dvec3(c[0], c[1], c[2]);
      src.Intensity = l->GetIntensity();
      const double* a = l->GetAttenuationValues();
      src.Attenuation = glm::dvec3(a[0], a[1], a[2]);
      src.ConeAngle = l->GetConeAngle();
      src.Exponent = l->GetExponent();
      sources.push_back(src);
    }
    const std::size_t firstSetLight = sources.size();
    std::vector<std::pair<vtkClusteredLightSet*, vtkIdType>> setOf;
    for (const auto& set : this->LightSets)
    {
      if (!set->GetEnabled())
      {
        continue;
      }
      const vtkIdType n = set->GetNumberOfLights();
      for (vtkIdType i = 0; i < n; ++i)
      {
        LightSource src;
        double v[3];
        set->GetPosition(i, v);
        src.PositionWC = glm::dvec3(v[0], v[1], v[2]);
        set->GetColor(i, v);
        src.Color = glm::dvec3(v[0], v[1], v[2]);
        src.Intensity = set->GetIntensity(i);
        set->GetAttenuation(i, v);
        src.Attenuation = glm::dvec3(v[0], v[1], v[2]);
        src.HasRadius = set->HasRadius(i);
        src.Radius = set->GetRadius(i);
        src.ConeAngle = set->GetConeAngle(i);
        src.Exponent = set->GetExponent(i);
        set->GetSpotDirection(i, v);
        src.DirectionWC = glm::dvec3(v[0], v[1], v[2]);
        sources.push_back(src);
        setOf.emplace_back(set.Get(), i);
      }
    }
    auto nameOf = [&](std::size_t i)
    {
      std::ostringstream os;
      if (i < firstSetLight)
      {
        os << "vtkLight " << f.ClusteredVTKLights[i] << " (renderer light " << i << ")";
      }
      else
      {
        const auto& so = setOf[i - firstSetLight];
        os << "vtkClusteredLightSet " << so.first << " light " << so.second;
      }
      return os.str();
    };
    LightPreparationOptions options;
    options.Cutoff = self->Cutoff;
    options.MortonOrder = self->MortonOrder;
    if (self->ErrorBudget > 0.0)
    {
      // Validate once, then pick the cutoff that meets the budget (see the header).
      LightPreparationOptions probe = options;
      probe.MortonOrder = false;
      const PreparedLights valid = PrepareLights(sources, probe, nameOf);
      options.Cutoff = ChooseCutoffForErrorBudget(valid.Lights, self->ErrorBudget,
        ComputeErrorBudgetSamples(valid.Lights),
        self->Falloff == vtkClusteredLightingPass::FALLOFF_WINDOWED);
    }
    f.State->EffectiveCutoff = options.Cutoff;
    f.State->Prepared = PrepareLights(sources, options, nameOf);
    // Warn once per problem: a bad light stays reported while it stays bad, even when
    // other lights change every frame.
    std::set<std::string> problems(
      f.State->Prepared.Problems.begin(), f.State->Prepared.Problems.end());
    for (const std::string& problem : problems)
    {
      if (!f.State->ReportedProblems.count(problem))
      {
        vtkWarningWithObjectMacro(self, << problem);
      }
    }
    f.State->ReportedProblems.swap(problems);
    ++f.State->LightsVersion;
    f.State->LightDataUploaded = false;
  }
  const PreparedLights& prepared = f.State->Prepared;
  self->EffectiveCutoff = f.State->EffectiveCutoff;
  const int numberOfLights = static_cast<int>(prepared.Lights.size());
  self->NumberOfClusteredLights = numberOfLights;
  self->NumberOfRejectedLights = static_cast<int>(prepared.Problems.size());
  self->NumberOfAlwaysOnLights = static_cast<int>(prepared.NumberOfAlwaysOn);
  self->NumberOfLightsBelowCutoff = static_cast<int>(prepared.NumberOfBelowCutoff);
  self->NumberOfSpotLights = static_cast<int>(prepared.NumberOfSpots);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::vtkInternals::CheckLimits(vtkClusteredLightingPass* self, Frame& f)
{
  const int numberOfLights = static_cast<int>(f.State->Prepared.Lights.size());
  f.Enabled = numberOfLights > 0;
  if (f.Enabled)
  {
    int maxTexture = vtkTextureObject::GetMaximumTextureSize(f.Window);
    if (self->MaximumTextureSize > 0)
    {
      maxTexture = std::min(maxTexture, self->MaximumTextureSize);
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
    else if (f.Clustered)
    {
      ok = ComputeLayout(
        self->TilesX, self->TilesY, self->Slices, numberOfLights, maxTexture, f.Layout, &error);
    }
    if (!ok)
    {
      if (error != f.State->LayoutError)
      {
        vtkErrorWithObjectMacro(self, "Clustered lights are not rendered: " << error << ".");
      }
      f.State->LayoutError = error;
      f.Enabled = false;
    }
    else
    {
      f.State->LayoutError.clear();
    }
  }

  // Light records are uploaded only when the lights changed.
  if (f.Enabled && !f.State->LightDataUploaded)
  {
    f.State->GPU.UploadLightData(f.Window, PackLightData(f.State->Prepared.Lights));
    f.State->LightDataUploaded = true;
    ++self->NumberOfLightUploads;
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::vtkInternals::ComputeView(vtkClusteredLightingPass* self, Frame& f)
{
  vtkCamera* camera = f.Renderer->GetActiveCamera();
  int width = 0, height = 0;
  f.Renderer->GetTiledSizeAndOrigin(&width, &height, &f.ViewportOrigin[0], &f.ViewportOrigin[1]);
  const bool parallel = camera->GetParallelProjection() != 0;
  double range[2];
  camera->GetClippingRange(range);
  ViewParameters& view = f.View;
  if (vtkOpenGLCamera* glCamera = vtkOpenGLCamera::SafeDownCast(camera))
  {
    // Exactly the matrices the mappers will use (VTK caches them per camera and renderer;
    // they are stored transposed for GL).
    vtkMatrix4x4* wcvc = nullptr;
    vtkMatrix3x3* normals = nullptr;
    vtkMatrix4x4* vcdc = nullptr;
    vtkMatrix4x4* wcdc = nullptr;
    glCamera->GetKeyMatrices(f.Renderer, wcvc, normals, vcdc, wcdc);
    view.WCVC = glm::transpose(ToGLM(wcvc));
    view.VCDC = glm::transpose(ToGLM(vcdc));
  }
  else
  {
    view.WCVC = ToGLM(camera->GetModelViewTransformMatrix());
    view.VCDC =
      ToGLM(camera->GetProjectionTransformMatrix(f.Renderer->GetTiledAspectRatio(), -1, 1));
  }
  view.Grid.TilesX = self->TilesX;
  view.Grid.TilesY = self->TilesY;
  view.Grid.Slices = self->Slices;
  view.Grid.ViewportWidth = std::max(width, 1);
  view.Grid.ViewportHeight = std::max(height, 1);
  view.Grid.NearVC = range[0];
  view.Grid.FarVC = range[1];
  SanitizeDepthRange(view.Grid.NearVC, view.Grid.FarVC);
  f.Linear = self->SlicingScheme == vtkClusteredLightingPass::SLICING_LINEAR ||
    (self->SlicingScheme == vtkClusteredLightingPass::SLICING_AUTO && parallel);
  view.Grid.Scheme = f.Linear ? SlicingScheme::Linear : SlicingScheme::Exponential;
  view.Bounds = self->BoundsMethod == vtkClusteredLightingPass::BOUNDS_CENTER_DEPTH_QUAD
    ? BoundsMethod::CenterDepthQuad
    : BoundsMethod::Tangent;
}

//------------------------------------------------------------------------------
// The list and master passes run only when lights, camera, viewport or grid changed.
void vtkClusteredLightingPass::vtkInternals::UpdateAssignment(
  vtkClusteredLightingPass* self, Frame& f)
{
  const ViewParameters& view = f.View;
  vtkClusteredLightingRendererState* state = f.State;
  vtkOpenGLRenderWindow* rw = f.Window;
  const ClusterTextureLayout& layout = f.Layout;
  const PreparedLights& prepared = state->Prepared;
  std::vector<double> viewSignature(&view.WCVC[0][0], &view.WCVC[0][0] + 16);
  viewSignature.insert(viewSignature.end(), &view.VCDC[0][0], &view.VCDC[0][0] + 16);
  const double more[] = { double(view.Grid.TilesX), double(view.Grid.TilesY),
    double(view.Grid.Slices), double(view.Grid.ViewportWidth), double(view.Grid.ViewportHeight),
    view.Grid.NearVC, view.Grid.FarVC, double(f.Linear), double(self->BoundsMethod),
    double(state->LightsVersion), double(f.Clustered), double(f.Enabled),
    double(self->PerClusterCulling) };
  viewSignature.insert(viewSignature.end(), std::begin(more), std::end(more));

  if (f.Enabled && (viewSignature != state->ViewSignature || !state->AssignmentValid))
  {
    const auto t0 = std::chrono::steady_clock::now();
    if (self->MeasureTimings)
    {
      glFinish();
    }
    const auto t1 = std::chrono::steady_clock::now();
    ViewData data = ComputeViewData(prepared.Lights, view);
    state->GPU.UploadLightView(rw, data.LightView);
    bool ok = true;
    if (f.Clustered)
    {
      state->GPU.UploadQuads(rw, data.Quads);
      vtkClusteredLightingListPassParameters listPass;
      const glm::dmat4& P = view.VCDC;
      // Per-cluster culling unprojects tile edges; it needs VTK's usual projection form.
      listPass.CullClusters = self->PerClusterCulling && P[1][0] == 0.0 && P[0][1] == 0.0 &&
        P[0][3] == 0.0 && P[1][3] == 0.0;
      const float px[3] = { float(P[0][0]), float(P[2][0]), float(P[3][0]) };
      const float py[3] = { float(P[1][1]), float(P[2][1]), float(P[3][1]) };
      std::copy(px, px + 3, listPass.ProjectionX);
      std::copy(py, py + 3, listPass.ProjectionY);
      listPass.ProjectionW[0] = float(P[2][3]);
      listPass.ProjectionW[1] = float(P[3][3]);
      double slicing[4];
      ComputeSliceShaderParameters(view.Grid, slicing);
      for (int k = 0; k < 4; ++k)
      {
        listPass.Slicing[k] = static_cast<float>(slicing[k]);
      }
      listPass.DepthRange[0] = static_cast<float>(view.Grid.NearVC);
      listPass.DepthRange[1] = static_cast<float>(view.Grid.GetMaxFragmentDepth());
      ok = state->GPU.AllocateTextures(rw, layout) &&
        state->GPU.BuildAssignment(rw, layout, data.NumberOfQuads, listPass);
      if (!ok)
      {
        vtkErrorWithObjectMacro(self,
          "Could not allocate or fill the cluster textures (" << layout.ListWidth << "x"
                                                              << layout.ListHeight << " R32UI).");
      }
    }
    if (self->MeasureTimings)
    {
      glFinish();
    }
    const auto t2 = std::chrono::steady_clock::now();
    self->LastAssignmentTime = self->MeasureTimings ? Milliseconds(t1, t2) : Milliseconds(t0, t2);
    state->NumberOfQuads = data.NumberOfQuads;
    state->NumberOfAssignedLights = data.NumberOfAssignedLights;
    state->AssignmentValid = ok;
    state->ViewSignature = viewSignature;
    state->VCDC = view.VCDC;
    ComputeSliceShaderParameters(view.Grid, state->SliceParameters);
    state->Frame.Valid = ok;
    state->Frame.Grid = view.Grid;
    state->Frame.WCVC = view.WCVC;
    state->Frame.VCDC = view.VCDC;
    state->Frame.ViewportOrigin[0] = f.ViewportOrigin[0];
    state->Frame.ViewportOrigin[1] = f.ViewportOrigin[1];
    state->Frame.Layout = layout;
    state->Frame.LightsVC = std::move(data.LightsVC);
    state->Frame.Lights = prepared.Lights;
    state->Frame.NumberOfQuads = data.NumberOfQuads;
    self->LastAssignmentUpdated = true;
    ++self->NumberOfAssignmentUpdates;
  }
  f.Enabled = f.Enabled && state->AssignmentValid;
  self->NumberOfAssignedLights = f.Enabled ? state->NumberOfAssignedLights : 0;
  self->ListTextureBytes = state->GPU.GetListBytes();
  self->MasterTextureBytes = state->GPU.GetMasterBytes();
  self->LightBufferBytes = state->GPU.GetLightBufferBytes();
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::vtkInternals::UpdateShaderVariant(
  vtkClusteredLightingPass* self, Frame& f)
{
  // The global part of the variant; the actor's part is decided in the shader hooks.
  vtkClusteredLightingShaderVariant variant;
  variant.Enabled = f.Enabled;
  variant.Clustered = f.Clustered;
  variant.Spot = f.State->Prepared.NumberOfSpots > 0;
  variant.Window = self->Falloff == vtkClusteredLightingPass::FALLOFF_WINDOWED;
  variant.LinearSlices = f.Linear;
  variant.MasterTexels = std::max(f.Layout.MasterTexelsPerCluster, 1);
  variant.DebugView = self->DebugView;
  if (!variant.SameGlobalPart(this->Variant))
  {
    this->Variant = variant;
    this->ShaderStageTime.Modified();
  }
}

//------------------------------------------------------------------------------
// Renders the delegate with the clustered lights hidden from VTK's lighting code.
void vtkClusteredLightingPass::vtkInternals::RenderDelegate(
  vtkClusteredLightingPass* self, const vtkRenderState* s, Frame& f)
{
  vtkLightCollection* lights = f.Renderer->GetLights();
  if (f.Enabled)
  {
    lights->RemoveAllItems();
    bool stockOn = false;
    for (const auto& l : f.StockLights)
    {
      lights->AddItem(l);
      stockOn = stockOn || l->GetSwitch();
    }
    if (!stockOn)
    {
      lights->AddItem(this->PlaceholderLight);
    }
    f.State->GPU.ActivateShadingTextures(f.Clustered);
  }
  const auto s0 = std::chrono::steady_clock::now();
  if (self->MeasureTimings)
  {
    glFinish();
  }
  const auto s1 = std::chrono::steady_clock::now();
  self->PreRender(s);
  self->DelegatePass->Render(s);
  self->NumberOfRenderedProps += self->DelegatePass->GetNumberOfRenderedProps();
  self->PostRender(s);
  if (self->MeasureTimings)
  {
    glFinish();
  }
  const auto s2 = std::chrono::steady_clock::now();
  self->LastShadingTime = self->MeasureTimings ? Milliseconds(s1, s2) : Milliseconds(s0, s2);
  if (f.Enabled)
  {
    f.State->GPU.DeactivateShadingTextures();
    lights->RemoveAllItems();
    for (const auto& l : f.AllLights)
    {
      lights->AddItem(l);
    }
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkClusteredLightingPass::GetShaderStageMTime()
{
  return this->Internals->ShaderStageTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (!this->Internals->Variant.Enabled)
  {
    return true;
  }
  // Markers after VTK's own tags: VTK still generates its code for the remaining
  // (directional/head) lights, and passes that look for //VTK::Light::Impl still work.
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", "//VTK::Light::Dec\n//VTK::ClusteredLight::Dec");
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Impl", "//VTK::Light::Impl\n//VTK::ClusteredLight::Impl");
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  ++this->NumberOfShaderBuilds;
  if (fragmentShader.find("//VTK::ClusteredLight::Impl") == std::string::npos)
  {
    return true; // clustered lighting off for this build
  }
  vtkClusteredLightingShaderVariant variant = this->Internals->Variant;
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  variant.PBR = property && property->GetInterpolation() == VTK_PBR;
  if (property)
  {
    const double* sc = property->GetSpecularColor();
    variant.Specular =
      property->GetSpecular() > 0.0 && std::max(sc[0], std::max(sc[1], sc[2])) > 0.0;
  }

  // Lit surfaces have VTK's VC position and normal; PBR surfaces accumulate into Lo.
  const bool lit = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vertexVCVSOutput") != std::string::npos;
  const std::string pbrAnchor = "  color += Lo;\n";
  const bool pbrOK = !variant.PBR || fragmentShader.find(pbrAnchor) != std::string::npos;
  if (!lit || !pbrOK)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Dec", "");
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Impl", "");
    return true;
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
    "//VTK::System::Dec\n#extension GL_ARB_gpu_shader5 : enable\n");
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::ClusteredLight::Dec", variant.GetDeclarations());
  if (variant.PBR)
  {
    vtkShaderProgram::Substitute(
      fragmentShader, pbrAnchor, variant.GetImplementation() + pbrAnchor);
    vtkShaderProgram::Substitute(
      fragmentShader, "//VTK::ClusteredLight::Impl", variant.GetDebugImplementation());
  }
  else
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Impl",
      variant.GetImplementation() + variant.GetDebugImplementation());
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  vtkClusteredLightingRendererState* state = this->Internals->Current;
  if (!state || !program)
  {
    return true;
  }
  // Each uniform is set only if the program uses it: debug views let the compiler drop
  // the lighting math (and its samplers), programs without clustered code use none.
  if (program->IsUniformUsed("clLightData"))
  {
    program->SetUniformi("clLightData", state->GPU.GetLightDataUnit());
  }
  if (program->IsUniformUsed("clLightView"))
  {
    program->SetUniformi("clLightView", state->GPU.GetLightViewUnit());
  }
  if (program->IsUniformUsed("clMaster"))
  {
    program->SetUniformi("clMaster", state->GPU.GetMasterUnit());
  }
  if (program->IsUniformUsed("clList"))
  {
    program->SetUniformi("clList", state->GPU.GetListUnit());
  }
  if (program->IsUniformUsed("clGrid"))
  {
    const ClusterTextureLayout& layout = state->Frame.Layout;
    const int grid[4] = { layout.TilesX, layout.TilesY, layout.Slices, layout.BatchRows };
    vtkClusteredLightingSetUniform4i(program, "clGrid", grid);
  }
  if (program->IsUniformUsed("clProjection"))
  {
    float projection[16];
    for (int i = 0; i < 16; ++i)
    {
      projection[i] = static_cast<float>((&state->VCDC[0][0])[i]); // column-major
    }
    program->SetUniformMatrix4x4("clProjection", projection);
  }
  if (program->IsUniformUsed("clSlicing"))
  {
    const float slicing[4] = { static_cast<float>(state->SliceParameters[0]),
      static_cast<float>(state->SliceParameters[1]), static_cast<float>(state->SliceParameters[2]),
      static_cast<float>(state->SliceParameters[3]) };
    program->SetUniform4f("clSlicing", slicing);
  }
  if (program->IsUniformUsed("clLightCount"))
  {
    program->SetUniformi("clLightCount", static_cast<int>(state->Prepared.Lights.size()));
  }
  if (program->IsUniformUsed("clHeatMapMaximum"))
  {
    program->SetUniformf("clHeatMapMaximum", static_cast<float>(this->HeatMapMaximum));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingPass::ReadBackAssignment(
  vtkRenderer* renderer, std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& master)
{
  auto it = this->Internals->States.find(renderer);
  if (it == this->Internals->States.end() || !it->second->Window || !it->second->AssignmentValid)
  {
    return false;
  }
  return it->second->GPU.ReadBack(it->second->Window, list, master);
}

//------------------------------------------------------------------------------
const vtkClusteredLightingFrameState* vtkClusteredLightingPass::GetFrameState(
  vtkRenderer* renderer) const
{
  auto it = this->Internals->States.find(renderer);
  return it == this->Internals->States.end() ? nullptr : &it->second->Frame;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  for (const auto& it : this->Internals->States)
  {
    it.second->GPU.GetGLObjectNames(names);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "NumberOfLightSets: " << this->GetNumberOfLightSets() << "\n";
  os << indent << "ClusterRendererLights: " << this->ClusterRendererLights << "\n";
  os << indent << "Tiles: " << this->TilesX << " x " << this->TilesY << ", Slices: " << this->Slices
     << "\n";
  os << indent << "SlicingScheme: " << this->SlicingScheme << "\n";
  os << indent << "Cutoff: " << this->Cutoff << "\n";
  os << indent << "ErrorBudget: " << this->ErrorBudget << "\n";
  os << indent << "EffectiveCutoff: " << this->EffectiveCutoff << "\n";
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "ShadingMode: " << this->ShadingMode << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "HeatMapMaximum: " << this->HeatMapMaximum << "\n";
  os << indent << "MortonOrder: " << this->MortonOrder << "\n";
  os << indent << "BoundsMethod: " << this->BoundsMethod << "\n";
  os << indent << "PerClusterCulling: " << this->PerClusterCulling << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "MeasureTimings: " << this->MeasureTimings << "\n";
  os << indent << "NumberOfClusteredLights: " << this->NumberOfClusteredLights << "\n";
  os << indent << "NumberOfAssignedLights: " << this->NumberOfAssignedLights << "\n";
}
