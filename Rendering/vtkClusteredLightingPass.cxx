// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingAssigner.h"
#include "vtkClusteredLightingLightCollector.h"
#include "vtkClusteredLightingShaderVariant.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h" // for glFinish

#include <algorithm> // for std::find
#include <chrono>    // for timings
#include <map>       // for std::map
#include <set>       // for std::set

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

  double Milliseconds(
    std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}

vtkClusteredLightingShaderVariant::Debug ToVariantDebug(int view)
{
  using Debug = vtkClusteredLightingShaderVariant::Debug;
  switch (view)
  {
    case vtkClusteredLightingPass::DEBUG_CLUSTER_INDEX:
      return Debug::ClusterIndex;
    case vtkClusteredLightingPass::DEBUG_HEAT_MAP:
      return Debug::HeatMap;
    case vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT:
      return Debug::EvaluatedCount;
    case vtkClusteredLightingPass::DEBUG_REACHED_COUNT:
      return Debug::ReachedCount;
    case vtkClusteredLightingPass::DEBUG_NON_FINITE:
      return Debug::NonFinite;
    case vtkClusteredLightingPass::DEBUG_NORMAL:
      return Debug::Normal;
    default:
      return Debug::None;
  }
}
}

//------------------------------------------------------------------------------
// One assigner per renderer (it owns that renderer's GL objects), and what the shader
// hooks need while the delegate renders.
struct vtkClusteredLightingPass::vtkInternals
{
  struct RendererEntry
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    std::unique_ptr<vtkClusteredLightingAssigner> Assigner;
  };
  std::map<vtkRenderer*, RendererEntry> Renderers;
  std::vector<vtkSmartPointer<vtkClusteredLightSet>> LightSets;
  vtkClusteredLightingAssigner* Current = nullptr; ///< during Render()
  vtkClusteredLightingShaderVariant Variant;       ///< global part for the current render
  vtkTimeStamp ShaderStageTime;
  vtkNew<vtkLight> PlaceholderLight; ///< keeps VTK's lit code when every light is clustered
  vtkNew<vtkLight> ComplexityLight;  ///< keeps VTK's lighting complexity (switched off)

  vtkClusteredLightingAssigner* GetAssigner(vtkRenderer* ren)
  {
    // Forget renderers that were deleted: their assigner releases its GL objects in its
    // window's context (and restores the current one).
    for (auto it = this->Renderers.begin(); it != this->Renderers.end();)
    {
      it = it->second.Renderer ? std::next(it) : this->Renderers.erase(it);
    }
    RendererEntry& entry = this->Renderers[ren];
    if (!entry.Assigner)
    {
      entry.Renderer = ren;
      entry.Assigner.reset(new vtkClusteredLightingAssigner);
    }
    return entry.Assigner.get();
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
  // A switched-off positional light raises VTK's lighting complexity to 3 and costs
  // nothing: VTK generates code and uniforms only for switched-on lights.
  vtkLight* complexity = this->Internals->ComplexityLight;
  complexity->SetLightTypeToSceneLight();
  complexity->SetPositional(true);
  complexity->SetConeAngle(180.0);
  complexity->SwitchOff();
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
  for (const auto& it : this->Internals->Renderers)
  {
    n += it.second.Assigner->GetNumberOfGLObjects();
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
  for (auto& it : this->Internals->Renderers)
  {
    vtkClusteredLightingAssigner* assigner = it.second.Assigner.get();
    vtkWindow* own = assigner->GetWindow();
    if (!w || own == w)
    {
      if (own)
      {
        windows.insert(own);
      }
      assigner->ReleaseGraphicsResources(w ? w : own);
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
// The stages, in order: light gathering, assignment, shading.
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
  this->SetUpCamera(ren);

  // 1. Light gathering.
  vtkClusteredLightingLightCollection lights;
  vtkClusteredLightingLightCollector::CollectRendererLights(
    ren, this->ClusterRendererLights, lights);
  vtkClusteredLightingLightCollector::CollectLightSets(this->Internals->LightSets, lights);

  // 2. Assignment.
  vtkClusteredLightingAssigner* assigner = this->Internals->GetAssigner(ren);
  const vtkClusteredLightingAssignment& result =
    assigner->Update(rw, this->MakeAssignerInputs(ren, lights));
  this->ReportAssignment(result);

  // 3. Shading.
  this->UpdateShaderVariant(result);
  this->Internals->Current = assigner;
  this->RenderDelegate(s, lights, assigner);
  this->Internals->Current = nullptr;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::SetUpCamera(vtkRenderer* ren)
{
  // VTK's pass-less pipeline sets the camera's stereo flag in vtkOpenGLCamera::Render;
  // vtkCameraPass does not, so under a render pass every eye would render the same (mono)
  // view. When the flag disagrees with the window, set the camera up as VTK's own
  // pipeline does (viewport, scissor, clear and stereo flag).
  if (ren->GetActiveCamera()->GetStereo() != ren->GetRenderWindow()->GetStereoRender())
  {
    this->UpdateCamera(ren);
  }
  // Camera lights and headlights follow the camera before they are read.
  this->UpdateLightGeometry(ren);
}

//------------------------------------------------------------------------------
vtkClusteredLightingAssignerInputs vtkClusteredLightingPass::MakeAssignerInputs(
  vtkRenderer* ren, vtkClusteredLightingLightCollection& lights) const
{
  vtkClusteredLightingAssignerInputs in;
  in.Lights = &lights;
  in.Preparation.Cutoff = this->Cutoff;
  in.Preparation.MortonOrder = this->MortonOrder;
  in.ErrorBudget = this->ErrorBudget;
  in.Windowed = this->Falloff == FALLOFF_WINDOWED;
  in.FarField.Enabled = this->FarField;
  in.FarField.TargetNodes = this->FarFieldResolution;
  in.FarField.CellsPerRadius = this->FarFieldCellsPerRadius;
  in.FarField.Grouping = this->FarFieldGrouping;
  in.FarField.NearBudget = this->NearFieldBudget;
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  in.RegionLo = glm::dvec3(bounds[0], bounds[2], bounds[4]);
  in.RegionHi = glm::dvec3(bounds[1], bounds[3], bounds[5]);
  vtkClusteredLightingGridOptions grid;
  grid.TilesX = this->TilesX;
  grid.TilesY = this->TilesY;
  grid.Slices = this->Slices;
  grid.Scheme = this->SlicingScheme == SLICING_LINEAR
    ? vtkClusteredLightingGridOptions::Slicing::Linear
    : this->SlicingScheme == SLICING_EXPONENTIAL
    ? vtkClusteredLightingGridOptions::Slicing::Exponential
    : vtkClusteredLightingGridOptions::Slicing::Auto;
  grid.Bounds = this->BoundsMethod == BOUNDS_CENTER_DEPTH_QUAD ? BoundsMethod::CenterDepthQuad
                                                               : BoundsMethod::Tangent;
  in.View = vtkClusteredLightingAssigner::ComputeView(ren, grid);
  in.Clustered = this->ShadingMode == SHADING_CLUSTERED;
  in.PerClusterCulling = this->PerClusterCulling;
  in.MaximumTextureSize = this->MaximumTextureSize;
  in.MeasureTimings = this->MeasureTimings;
  return in;
}

//------------------------------------------------------------------------------
// Messages and statistics of an assignment.
void vtkClusteredLightingPass::ReportAssignment(const vtkClusteredLightingAssignment& r)
{
  for (const vtkClusteredLighting::ProblemGroup& group : r.NewProblems)
  {
    vtkClusteredLightSet* set = nullptr;
    for (const auto& candidate : this->Internals->LightSets)
    {
      set = static_cast<const void*>(candidate.Get()) == group.Object ? candidate.Get() : set;
    }
    for (const std::string& line : group.Lines)
    {
      vtkWarningMacro(<< line);
      if (set)
      {
        set->ReportProblem(line.c_str());
      }
    }
  }
  if (!r.NewError.empty())
  {
    vtkErrorMacro(<< r.NewError);
  }
  this->EffectiveCutoff = r.EffectiveCutoff;
  this->NumberOfClusteredLights = r.NumberOfLights;
  this->NumberOfRejectedLights = r.NumberOfRejected;
  this->NumberOfAlwaysOnLights = r.NumberOfAlwaysOn;
  this->NumberOfLightsBelowCutoff = r.NumberOfBelowCutoff;
  this->NumberOfSpotLights = r.NumberOfSpots;
  this->NumberOfAssignedLights = r.NumberOfAssigned;
  this->NumberOfLightUploads += r.LightsUploaded ? 1 : 0;
  this->LastLightUpdateTime = r.LightUpdateTime;
  this->NumberOfFarFieldLights = r.FarField ? r.NumberOfFarFieldLights : 0;
  this->LastFarFieldBuildTime = r.FarFieldBuildTime;
  this->FarFieldGridSpacing = r.FarField ? r.FarFieldSpacing : 0.0;
  this->NearRadiusCap = r.FarField ? r.NearRadiusCap : 0.0;
  for (int a = 0; a < 3; ++a)
  {
    this->FarFieldDimensions[a] = r.FarField ? r.FarFieldDims[a] : 0;
  }
  this->FarFieldTextureBytes = r.FarFieldBytes;
  if (r.Reassigned)
  {
    this->LastAssignmentTime = r.AssignmentTime;
    this->LastAssignmentUpdated = true;
    ++this->NumberOfAssignmentUpdates;
  }
  this->ListTextureBytes = r.ListBytes;
  this->MasterTextureBytes = r.MasterBytes;
  this->LightBufferBytes = r.LightBufferBytes;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::UpdateShaderVariant(const vtkClusteredLightingAssignment& r)
{
  // The global part of the variant; the actor's part is decided in the shader hooks.
  vtkClusteredLightingShaderVariant variant;
  variant.Enabled = r.Enabled;
  variant.Clustered = r.Clustered;
  variant.Spot = r.NumberOfSpots > 0;
  variant.Window = this->Falloff == FALLOFF_WINDOWED;
  variant.Explicit = r.NumberOfExplicitRadius > 0;
  variant.FarField = r.FarField;
  variant.LinearSlices = r.Linear;
  variant.MasterTexels = r.MasterTexels;
  variant.DebugView = ToVariantDebug(this->DebugView);
  if (!variant.SameGlobalPart(this->Internals->Variant))
  {
    this->Internals->Variant = variant;
    this->Internals->ShaderStageTime.Modified();
  }
}

//------------------------------------------------------------------------------
// Renders the delegate with the clustered lights hidden from VTK's lighting code and the
// assignment's textures bound.
void vtkClusteredLightingPass::RenderDelegate(const vtkRenderState* s,
  const vtkClusteredLightingLightCollection& lights, vtkClusteredLightingAssigner* assigner)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkLightCollection* rendererLights = ren->GetLights();
  const bool enabled = assigner->GetResult().Enabled;
  if (enabled)
  {
    rendererLights->RemoveAllItems();
    std::vector<vtkLight*> stock;
    bool stockOn = false;
    for (const auto& l : lights.StockLights)
    {
      rendererLights->AddItem(l);
      stock.push_back(l);
      stockOn = stockOn || l->GetSwitch();
    }
    if (!stockOn)
    {
      // Nothing of VTK's lighting shows: the cheapest code (complexity 1) will do.
      rendererLights->AddItem(this->Internals->PlaceholderLight);
    }
    else if (vtkClusteredLightingLightCollector::ComputeVTKLightingComplexity(stock) <
      lights.RendererComplexity)
    {
      // VTK's own lights must be shaded by the code VTK would generate for the whole
      // collection (the headlight's specular differs between complexity 1 and 3).
      rendererLights->AddItem(this->Internals->ComplexityLight);
    }
    assigner->ActivateShading();
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
    assigner->DeactivateShading();
    rendererLights->RemoveAllItems();
    for (const auto& l : lights.RendererLights)
    {
      rendererLights->AddItem(l);
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
  if (!this->Internals->Current || !program)
  {
    return true;
  }
  const vtkClusteredLightingAssignment& r = this->Internals->Current->GetResult();
  // Each uniform is set only if the program uses it: debug views let the compiler drop
  // the lighting math (and its samplers), programs without clustered code use none.
  const struct
  {
    const char* Name;
    int Unit;
  } samplers[] = { { "clLightData", r.LightDataUnit }, { "clLightView", r.LightViewUnit },
    { "clMaster", r.MasterUnit }, { "clList", r.ListUnit } };
  for (const auto& sampler : samplers)
  {
    if (program->IsUniformUsed(sampler.Name))
    {
      program->SetUniformi(sampler.Name, sampler.Unit);
    }
  }
  if (program->IsUniformUsed("clGrid"))
  {
    vtkClusteredLightingSetUniform4i(program, "clGrid", r.Shading.Grid);
  }
  if (program->IsUniformUsed("clProjection"))
  {
    program->SetUniformMatrix4x4("clProjection", const_cast<float*>(r.Shading.Projection));
  }
  if (program->IsUniformUsed("clSlicing"))
  {
    program->SetUniform4f("clSlicing", r.Shading.Slicing);
  }
  if (r.FarField)
  {
    static const char* const farFieldSamplers[vtkClusteredLighting::FarFieldTextures] = {
      "clFarField0", "clFarField1", "clFarField2", "clFarField3", "clFarField4", "clFarField5",
      "clFarField6"
    };
    for (int q = 0; q < vtkClusteredLighting::FarFieldTextures; ++q)
    {
      if (program->IsUniformUsed(farFieldSamplers[q]))
      {
        program->SetUniformi(farFieldSamplers[q], r.FarFieldUnits[static_cast<std::size_t>(q)]);
      }
    }
    if (program->IsUniformUsed("clFarFieldFromVC"))
    {
      program->SetUniformMatrix4x4("clFarFieldFromVC", const_cast<float*>(r.FarFieldFromVC));
    }
    if (program->IsUniformUsed("clWorldFromVC"))
    {
      program->SetUniformMatrix3x3("clWorldFromVC", const_cast<float*>(r.WorldFromVC));
    }
    if (program->IsUniformUsed("clFarFieldTolerance"))
    {
      program->SetUniformf("clFarFieldTolerance", static_cast<float>(this->FarFieldTolerance));
    }
  }
  if (program->IsUniformUsed("clLightCount"))
  {
    program->SetUniformi("clLightCount", r.NumberOfLights);
  }
  if (program->IsUniformUsed("clHeatMapMaximum"))
  {
    program->SetUniformf("clHeatMapMaximum", static_cast<float>(this->HeatMapMaximum));
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkClusteredLightingPass::ComputeFarFieldErrorBound()
{
  double bound = 0.0;
  for (vtkClusteredLightingAssigner* assigner : this->GetAssigners())
  {
    bound = std::max(bound, assigner->SummarizeFarFieldErrorBound().Max);
  }
  return bound;
}

//------------------------------------------------------------------------------
vtkClusteredLightingAssigner* vtkClusteredLightingPass::GetAssigner(vtkRenderer* renderer) const
{
  auto it = this->Internals->Renderers.find(renderer);
  return it == this->Internals->Renderers.end() ? nullptr : it->second.Assigner.get();
}

std::vector<vtkClusteredLightingAssigner*> vtkClusteredLightingPass::GetAssigners() const
{
  std::vector<vtkClusteredLightingAssigner*> out;
  for (const auto& it : this->Internals->Renderers)
  {
    out.push_back(it.second.Assigner.get());
  }
  return out;
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
  os << indent << "FarField: " << this->FarField << "\n";
  os << indent << "FarFieldResolution: " << this->FarFieldResolution << "\n";
  os << indent << "FarFieldCellsPerRadius: " << this->FarFieldCellsPerRadius << "\n";
  os << indent << "FarFieldTolerance: " << this->FarFieldTolerance << "\n";
  os << indent << "FarFieldGrouping: " << this->FarFieldGrouping << "\n";
  os << indent << "NearFieldBudget: " << this->NearFieldBudget << "\n";
  os << indent << "NumberOfClusteredLights: " << this->NumberOfClusteredLights << "\n";
  os << indent << "NumberOfFarFieldLights: " << this->NumberOfFarFieldLights << "\n";
  os << indent << "NearRadiusCap: " << this->NearRadiusCap << "\n";
  os << indent << "FarFieldGridSpacing: " << this->FarFieldGridSpacing << "\n";
  os << indent << "NumberOfAssignedLights: " << this->NumberOfAssignedLights << "\n";
}
