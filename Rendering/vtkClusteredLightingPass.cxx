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
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
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
#include <map>       // for std::map
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
  this->Superclass::ReleaseGraphicsResources(w);
  for (auto& it : this->Internals->States)
  {
    vtkClusteredLightingRendererState* state = it.second.get();
    if (!w || state->Window == w)
    {
      state->GPU.ReleaseGraphicsResources(w ? w : state->Window.GetPointer());
      state->LightDataUploaded = false;
      state->AssignmentValid = false;
      state->ViewSignature.clear();
    }
  }
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->LastAssignmentUpdated = false;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* rw =
    ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  if (!ren || !rw)
  {
    vtkErrorMacro("vtkClusteredLightingPass needs an OpenGL renderer and render window.");
    return;
  }
  if (!this->DelegatePass)
  {
    vtkWarningMacro("No delegate pass: nothing is rendered.");
    return;
  }
  vtkClusteredLightingRendererState* state = this->Internals->GetState(ren, rw);
  this->Internals->Current = state;

  // ---- 1. Gather lights -------------------------------------------------------
  // Camera lights and headlights follow the camera before they are read.
  this->UpdateLightGeometry(ren);
  vtkLightCollection* lights = ren->GetLights();
  std::vector<vtkSmartPointer<vtkLight>> allLights, stockLights;
  std::vector<vtkLight*> clusteredVTKLights;
  bool anyOn = false;
  {
    vtkCollectionSimpleIterator it;
    vtkLight* light;
    for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
    {
      anyOn = anyOn || light->GetSwitch();
    }
    if (!anyOn && ren->GetAutomaticLightCreation())
    {
      ren->CreateLight(); // what VTK would do in UpdateLights
    }
    for (lights->InitTraversal(it); (light = lights->GetNextLight(it));)
    {
      allLights.emplace_back(light);
      if (this->ClusterRendererLights && light->GetSwitch() && light->GetPositional())
      {
        clusteredVTKLights.push_back(light);
      }
      else
      {
        stockLights.emplace_back(light);
      }
    }
  }

  // Signature of everything the prepared lights depend on.
  std::vector<vtkTypeUInt64> signature;
  signature.push_back(static_cast<vtkTypeUInt64>(this->Cutoff * 1e12));
  signature.push_back(this->MortonOrder ? 1 : 0);
  for (vtkLight* l : clusteredVTKLights)
  {
    vtkMTimeType t = l->GetMTime();
    if (l->GetTransformMatrix())
    {
      t = std::max(t, l->GetTransformMatrix()->GetMTime());
    }
    signature.push_back(reinterpret_cast<vtkTypeUInt64>(l));
    signature.push_back(t);
  }
  for (const auto& set : this->Internals->LightSets)
  {
    signature.push_back(reinterpret_cast<vtkTypeUInt64>(set.Get()));
    signature.push_back(set->GetEnabled() ? set->GetMTime() : 0);
  }
  if (signature != state->LightSignature)
  {
    state->LightSignature = signature;
    std::vector<LightSource> sources;
    std::vector<std::string> names; // filled lazily: only for messages
    for (vtkLight* l : clusteredVTKLights)
    {
      LightSource src;
      const double* p = l->GetTransformedPosition();
      const double* f = l->GetTransformedFocalPoint();
      src.PositionWC = glm::dvec3(p[0], p[1], p[2]);
      src.DirectionWC = glm::dvec3(f[0] - p[0], f[1] - p[1], f[2] - p[2]);
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
    for (const auto& set : this->Internals->LightSets)
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
        os << "vtkLight " << clusteredVTKLights[i] << " (renderer light " << i << ")";
      }
      else
      {
        const auto& so = setOf[i - firstSetLight];
        os << "vtkClusteredLightSet " << so.first << " light " << so.second;
      }
      return os.str();
    };
    LightPreparationOptions options;
    options.Cutoff = this->Cutoff;
    options.MortonOrder = this->MortonOrder;
    state->Prepared = PrepareLights(sources, options, nameOf);
    for (const std::string& problem : state->Prepared.Problems)
    {
      vtkWarningMacro(<< problem);
    }
    ++state->LightsVersion;
    state->LightDataUploaded = false;
  }
  const PreparedLights& prepared = state->Prepared;
  const int numberOfLights = static_cast<int>(prepared.Lights.size());
  this->NumberOfClusteredLights = numberOfLights;
  this->NumberOfRejectedLights = static_cast<int>(prepared.Problems.size());
  this->NumberOfAlwaysOnLights = static_cast<int>(prepared.NumberOfAlwaysOn);
  this->NumberOfLightsBelowCutoff = static_cast<int>(prepared.NumberOfBelowCutoff);
  this->NumberOfSpotLights = static_cast<int>(prepared.NumberOfSpots);

  // ---- 2. Limits --------------------------------------------------------------
  const bool clustered = this->ShadingMode == SHADING_CLUSTERED;
  bool enabled = numberOfLights > 0;
  int width = 0, height = 0, originX = 0, originY = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  ClusterTextureLayout layout;
  if (enabled)
  {
    const int maxTexture = vtkTextureObject::GetMaximumTextureSize(rw);
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
    else if (clustered)
    {
      ok = ComputeLayout(
        this->TilesX, this->TilesY, this->Slices, numberOfLights, maxTexture, layout, &error);
    }
    if (!ok)
    {
      if (error != state->LayoutError)
      {
        vtkErrorMacro("Clustered lights are not rendered: " << error << ".");
      }
      state->LayoutError = error;
      enabled = false;
    }
    else
    {
      state->LayoutError.clear();
    }
  }

  // ---- 3. Upload light records (only when the lights changed) -----------------
  if (enabled && !state->LightDataUploaded)
  {
    state->GPU.UploadLightData(rw, PackLightData(prepared.Lights));
    state->LightDataUploaded = true;
    ++this->NumberOfLightUploads;
  }

  // ---- 4. View: records in VC and assignment (only when something changed) ----
  vtkCamera* camera = ren->GetActiveCamera();
  const bool parallel = camera->GetParallelProjection() != 0;
  double range[2];
  camera->GetClippingRange(range);
  ViewParameters view;
  view.WCVC = ToGLM(camera->GetModelViewTransformMatrix());
  view.VCDC = ToGLM(camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));
  view.Grid.TilesX = this->TilesX;
  view.Grid.TilesY = this->TilesY;
  view.Grid.Slices = this->Slices;
  view.Grid.ViewportWidth = std::max(width, 1);
  view.Grid.ViewportHeight = std::max(height, 1);
  view.Grid.NearVC = range[0];
  view.Grid.FarVC = range[1];
  SanitizeDepthRange(view.Grid.NearVC, view.Grid.FarVC);
  const bool linear =
    this->SlicingScheme == SLICING_LINEAR || (this->SlicingScheme == SLICING_AUTO && parallel);
  view.Grid.Scheme = linear ? SlicingScheme::Linear : SlicingScheme::Exponential;
  view.Bounds = this->BoundsMethod == BOUNDS_CENTER_DEPTH_QUAD ? BoundsMethod::CenterDepthQuad
                                                               : BoundsMethod::Tangent;
  std::vector<double> viewSignature(&view.WCVC[0][0], &view.WCVC[0][0] + 16);
  viewSignature.insert(viewSignature.end(), &view.VCDC[0][0], &view.VCDC[0][0] + 16);
  const double more[] = { double(view.Grid.TilesX), double(view.Grid.TilesY),
    double(view.Grid.Slices), double(view.Grid.ViewportWidth), double(view.Grid.ViewportHeight),
    view.Grid.NearVC, view.Grid.FarVC, double(linear), double(this->BoundsMethod),
    double(state->LightsVersion), double(clustered), double(enabled),
    double(this->PerClusterCulling) };
  viewSignature.insert(viewSignature.end(), std::begin(more), std::end(more));

  if (enabled && (viewSignature != state->ViewSignature || !state->AssignmentValid))
  {
    const auto t0 = std::chrono::steady_clock::now();
    if (this->MeasureTimings)
    {
      glFinish();
    }
    const auto t1 = std::chrono::steady_clock::now();
    ViewData data = ComputeViewData(prepared.Lights, view);
    state->GPU.UploadLightView(rw, data.LightView);
    bool ok = true;
    if (clustered)
    {
      state->GPU.UploadQuads(rw, data.Quads);
      vtkClusteredLightingListPassParameters listPass;
      const glm::dmat4& P = view.VCDC;
      // Per-cluster culling unprojects tile edges; it needs VTK's usual projection form.
      listPass.CullClusters = this->PerClusterCulling && P[1][0] == 0.0 && P[0][1] == 0.0 &&
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
      listPass.DepthRange[1] = static_cast<float>(view.Grid.FarVC);
      ok = state->GPU.AllocateTextures(rw, layout) &&
        state->GPU.BuildAssignment(rw, layout, data.NumberOfQuads, listPass);
      if (!ok)
      {
        vtkErrorMacro("Could not allocate or fill the cluster textures ("
          << layout.ListWidth << "x" << layout.ListHeight << " R32UI).");
      }
    }
    if (this->MeasureTimings)
    {
      glFinish();
    }
    const auto t2 = std::chrono::steady_clock::now();
    this->LastAssignmentTime = this->MeasureTimings ? Milliseconds(t1, t2) : Milliseconds(t0, t2);
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
    state->Frame.ViewportOrigin[0] = originX;
    state->Frame.ViewportOrigin[1] = originY;
    state->Frame.Layout = layout;
    state->Frame.LightsVC = std::move(data.LightsVC);
    state->Frame.Lights = prepared.Lights;
    state->Frame.NumberOfQuads = data.NumberOfQuads;
    this->LastAssignmentUpdated = true;
    ++this->NumberOfAssignmentUpdates;
  }
  enabled = enabled && state->AssignmentValid;
  this->NumberOfAssignedLights = enabled ? state->NumberOfAssignedLights : 0;
  this->ListTextureBytes = state->GPU.GetListBytes();
  this->MasterTextureBytes = state->GPU.GetMasterBytes();
  this->LightBufferBytes = state->GPU.GetLightBufferBytes();

  // ---- 5. Shader variant (global part) -----------------------------------------
  vtkClusteredLightingShaderVariant variant;
  variant.Enabled = enabled;
  variant.Clustered = clustered;
  variant.Spot = prepared.NumberOfSpots > 0;
  variant.Window = this->Falloff == FALLOFF_WINDOWED;
  variant.LinearSlices = linear;
  variant.MasterTexels = std::max(layout.MasterTexelsPerCluster, 1);
  variant.DebugView = this->DebugView;
  if (!variant.SameGlobalPart(this->Internals->Variant))
  {
    this->Internals->Variant = variant;
    this->Internals->ShaderStageTime.Modified();
  }

  // ---- 6. Shade: delegate render with the clustered lights hidden from VTK ------
  if (enabled)
  {
    lights->RemoveAllItems();
    bool stockOn = false;
    for (const auto& l : stockLights)
    {
      lights->AddItem(l);
      stockOn = stockOn || l->GetSwitch();
    }
    if (!stockOn)
    {
      lights->AddItem(this->Internals->PlaceholderLight);
    }
    state->GPU.ActivateShadingTextures(clustered);
  }
  const auto s0 = std::chrono::steady_clock::now();
  if (this->MeasureTimings)
  {
    glFinish();
  }
  const auto s1 = std::chrono::steady_clock::now();
  this->PreRender(s);
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  this->PostRender(s);
  if (this->MeasureTimings)
  {
    glFinish();
  }
  const auto s2 = std::chrono::steady_clock::now();
  this->LastShadingTime = this->MeasureTimings ? Milliseconds(s1, s2) : Milliseconds(s0, s2);
  if (enabled)
  {
    state->GPU.DeactivateShadingTextures();
    lights->RemoveAllItems();
    for (const auto& l : allLights)
    {
      lights->AddItem(l);
    }
  }
  this->Internals->Current = nullptr;
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
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "ShadingMode: " << this->ShadingMode << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "HeatMapMaximum: " << this->HeatMapMaximum << "\n";
  os << indent << "MortonOrder: " << this->MortonOrder << "\n";
  os << indent << "BoundsMethod: " << this->BoundsMethod << "\n";
  os << indent << "MeasureTimings: " << this->MeasureTimings << "\n";
  os << indent << "NumberOfClusteredLights: " << this->NumberOfClusteredLights << "\n";
  os << indent << "NumberOfAssignedLights: " << this->NumberOfAssignedLights << "\n";
}
