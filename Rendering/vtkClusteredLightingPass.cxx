// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingPass.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingAssigner.h"
#include "vtkClusteredLightingBackfaceCulling.h"
#include "vtkClusteredLightingDepthPrepass.h"
#include "vtkClusteredLightingGLHelpers.h"
#include "vtkClusteredLightingLightCollector.h"
#include "vtkClusteredLightingOpaqueStep.h"
#include "vtkClusteredLightingPrepassChoice.h"
#include "vtkClusteredLightingSampleDepths.h"
#include "vtkClusteredLightingSampleZero.h"
#include "vtkClusteredLightingShaderCode.h"
#include "vtkClusteredLightingShaderVariant.h"
#include "vtkClusteredLightingSurfaceBoxes.h"
#include "vtkClusteredLightingTranslucentStep.h"
#include "vtkClusteredLightingVolumetricStep.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h" // for glFinish

#include <algorithm> // for std::find, std::all_of, std::equal, std::copy
#include <chrono>    // for timings
#include <cmath>     // for std::isnan, std::isfinite
#include <cstdint>   // for std::uint64_t
#include <map>       // for std::map
#include <set>       // for std::set
#include <sstream>   // for std::ostringstream
#include <string>    // for std::to_string
#include <vector>    // for std::vector

using namespace vtkClusteredLighting;

namespace
{
//------------------------------------------------------------------------------
// The actor's property, or null for other props.
vtkProperty* GetActorProperty(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor ? actor->GetProperty() : nullptr;
}

// Whether some visible actor of the renderer shades a Phong specular the far specular's
// bins serve (FarFieldSpecularBins: Specular above 0, a power from
// FarSpecularBinsLeastPower on). Actors inside assemblies are not seen: theirs comes from
// the moments, within the stated bound.
bool NeedsFarSpecularBins(vtkRenderer* ren)
{
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    vtkProperty* p = GetActorProperty(prop);
    if (p && prop->GetVisibility() && p->GetInterpolation() != VTK_PBR && p->GetSpecular() > 0.0 &&
      p->GetSpecularPower() >= vtkClusteredLighting::FarSpecularBinsLeastPower)
    {
      return true;
    }
  }
  return false;
}

// Whether the prop shades with VTK's PBR model (the shading code's PBR variant).
bool IsPbr(vtkProp* prop)
{
  vtkProperty* property = GetActorProperty(prop);
  return property && property->GetInterpolation() == VTK_PBR;
}

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

/// One render whose colours encode counts (R + 256 G, B). It turns the renderer's FXAA
/// and SSAO off, and back on when it ends: FXAA blends an edge pixel's colour with its
/// neighbours' (the background's, say) and SSAO scales colours by occlusion, either of
/// which decodes to another count (ParaView's default view, FXAA on over a grey-blue
/// background, counted 76.991 lights evaluated per pixel where 73 lights shone, 17.484).
/// And it renders the state without its 2D actors (text, scalar bars, legends), which the
/// overlay step would draw over the counts with a depth of their own (a caption over a
/// lit sphere: 5,204 lights per pixel, TestClusteredLightingCountViews).
class CountingRender
{
public:
  CountingRender(const vtkRenderState* s, bool counting)
    : Renderer(s->GetRenderer())
    , FXAA(counting && this->Renderer->GetUseFXAA())
    , SSAO(counting && this->Renderer->GetUseSSAO())
    , State(s)
    , Without2D(s->GetRenderer())
  {
    if (this->FXAA)
    {
      this->Renderer->UseFXAAOff();
    }
    if (this->SSAO)
    {
      this->Renderer->UseSSAOOff();
    }
    if (counting)
    {
      for (int i = 0; i < s->GetPropArrayCount(); ++i)
      {
        if (!vtkActor2D::SafeDownCast(s->GetPropArray()[i]))
        {
          this->Props.push_back(s->GetPropArray()[i]);
        }
      }
      if (static_cast<int>(this->Props.size()) != s->GetPropArrayCount())
      {
        this->Without2D.SetFrameBuffer(s->GetFrameBuffer());
        this->Without2D.SetRequiredKeys(s->GetRequiredKeys());
        this->Without2D.SetPropArrayAndCount(
          this->Props.data(), static_cast<int>(this->Props.size()));
        this->State = &this->Without2D;
      }
    }
  }
  ~CountingRender()
  {
    if (this->FXAA)
    {
      this->Renderer->UseFXAAOn();
    }
    if (this->SSAO)
    {
      this->Renderer->UseSSAOOn();
    }
  }
  CountingRender(const CountingRender&) = delete;
  CountingRender& operator=(const CountingRender&) = delete;

  /// The state to render: the given one, or the same without its 2D actors.
  const vtkRenderState* GetState() const { return this->State; }

private:
  vtkRenderer* Renderer;
  const bool FXAA; ///< FXAA was on and is off until the render ends
  const bool SSAO; ///< SSAO likewise
  const vtkRenderState* State;
  vtkRenderState Without2D;
  std::vector<vtkProp*> Props; ///< Without2D's
};

/// Lights evaluated per pixel, decoded from a DEBUG_EVALUATED_COUNT frame.
struct PixelCounts
{
  double Mean = 0.0;
  double ReachingMean = 0.0; ///< of the reaching counts (blue, each saturating at 255)
  int Maximum = 0;
  vtkIdType Pixels = 0;
  bool Read = true;    ///< false when the framebuffer could not be read
  std::string Problem; ///< why not
};

/// Where the renderer's viewport lies in the framebuffer the delegate drew into: the whole
/// of a framebuffer object the render state names, else the renderer's tiled viewport.
void GetReadRectangle(const vtkRenderState* s, int& width, int& height, int& x0, int& y0)
{
  if (auto* fbo = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer()))
  {
    int size[2] = { 0, 0 };
    fbo->GetLastSize(size);
    width = size[0];
    height = size[1];
  }
  else
  {
    s->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  }
}

/// Reads the renderer's viewport back from the framebuffer the delegate drew into: its
/// window depths and (when asked) its RGBA bytes. False when it cannot be read.
bool ReadViewport(const vtkRenderState* s, vtkOpenGLRenderWindow* rw, std::vector<float>& depth,
  std::vector<unsigned char>* rgba)
{
  int width = 0, height = 0, x0 = 0, y0 = 0;
  GetReadRectangle(s, width, height, x0, y0);
  if (width <= 0 || height <= 0)
  {
    return false;
  }
  vtkOpenGLState* state = rw->GetState();
  unsigned int drawBinding = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(drawBinding, drawBuffer);
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  state->vtkglReadBuffer(drawBuffer);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  depth.resize(n);
  if (rgba)
  {
    rgba->resize(4 * n);
    glReadPixels(x0, y0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba->data());
  }
  glReadPixels(x0, y0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  const bool ok = glGetError() == GL_NO_ERROR;
  state->PopReadFramebufferBinding();
  return ok;
}

/// The viewport's window depths and (when asked) RGBA bytes, read back as they are from a
/// single-sampled framebuffer, and one sample of each pixel from a multisampled one
/// (vtkClusteredLightingSampleZero: neither a read nor a resolve of it keeps a fragment's
/// own values). False, with `problem` saying why, when they cannot be read.
bool ReadPixels(const vtkRenderState* s, vtkOpenGLRenderWindow* rw, std::vector<float>& depth,
  std::vector<unsigned char>* rgba, std::string& problem)
{
  if (vtkClusteredLightingSampleDepths::IsDrawFramebufferMultisampled())
  {
    int rectangle[4] = { 0, 0, 0, 0 };
    GetReadRectangle(s, rectangle[2], rectangle[3], rectangle[0], rectangle[1]);
    std::vector<unsigned char> colours;
    return vtkClusteredLightingSampleZero::Read(
      rw, rectangle, rgba ? *rgba : colours, depth, problem);
  }
  if (!ReadViewport(s, rw, depth, rgba))
  {
    problem = "the framebuffer could not be read back";
    return false;
  }
  return true;
}

/// Pixels of the renderer's viewport whose depth is below the far plane (ReadPixels). 0
/// when the depths cannot be read.
std::size_t CountVisiblePixels(const vtkRenderState* s, vtkOpenGLRenderWindow* rw)
{
  std::vector<float> depth;
  std::string problem;
  if (!ReadPixels(s, rw, depth, nullptr, problem))
  {
    return 0;
  }
  return static_cast<std::size_t>(
    std::count_if(depth.begin(), depth.end(), [](float z) { return z < 1.0f; }));
}

/// Decodes the evaluated counts (R + 256 G) and the reaching counts (B) of the pixels
/// covered by geometry (depth below the far plane; ReadPixels). Zero counts when the
/// framebuffer cannot be read.
PixelCounts CountEvaluatedLights(const vtkRenderState* s, vtkOpenGLRenderWindow* rw)
{
  PixelCounts counts;
  std::vector<float> depth;
  std::vector<unsigned char> rgba;
  if (!ReadPixels(s, rw, depth, &rgba, counts.Problem))
  {
    counts.Read = false;
    return counts;
  }
  double sum = 0.0, reaching = 0.0;
  for (std::size_t i = 0; i < depth.size(); ++i)
  {
    if (depth[i] < 1.0f)
    {
      const int evaluated = rgba[4 * i] + 256 * rgba[4 * i + 1];
      sum += evaluated;
      reaching += rgba[4 * i + 2];
      counts.Maximum = std::max(counts.Maximum, evaluated);
      ++counts.Pixels;
    }
  }
  counts.Mean = counts.Pixels > 0 ? sum / static_cast<double>(counts.Pixels) : 0.0;
  counts.ReachingMean = counts.Pixels > 0 ? reaching / static_cast<double>(counts.Pixels) : 0.0;
  return counts;
}

// Names of the enumerated options' values: the suffixes of their SetXTo methods.
const char* const ShadingModeNames[] = { "Clustered", "BruteForce" };
const char* const FalloffNames[] = { "HardCut", "Windowed" };
const char* const SlicingSchemeNames[] = { "Auto", "Exponential", "Linear" };
const char* const DebugViewNames[] = { "None", "ClusterIndex", "HeatMap", "EvaluatedCount",
  "ReachedCount", "NonFinite", "Normal" };
const char* const BoundsMethodNames[] = { "Tangent", "CenterDepthQuad" };

template <std::size_t N>
const char* NameOf(const char* const (&names)[N], int value)
{
  return value >= 0 && value < static_cast<int>(N) ? names[value] : nullptr;
}

/// "0 (Clustered) or 1 (BruteForce)": the accepted values, for error messages.
template <std::size_t N>
std::string Choices(const char* const (&names)[N])
{
  std::ostringstream os;
  for (std::size_t i = 0; i < N; ++i)
  {
    os << (i == 0 ? "" : i + 1 == N ? " or " : ", ") << i << " (" << names[i] << ")";
  }
  return os.str();
}
}

// Setters of the enumerated options: a value that is not one of the option's is rejected
// with an error naming the accepted ones (VTK's clamping setters would silently turn 7
// into the last value).
#define vtkClusteredLightingEnumSetter(option, names, what)                                        \
  void vtkClusteredLightingPass::Set##option(int value)                                            \
  {                                                                                                \
    if (!NameOf(names, value))                                                                     \
    {                                                                                              \
      vtkErrorMacro("Set" #option "(" << value << "): not a " what "; use " << Choices(names)      \
                                      << ". Kept " << NameOf(names, this->option) << ".");         \
      return;                                                                                      \
    }                                                                                              \
    if (this->option != value)                                                                     \
    {                                                                                              \
      this->option = value;                                                                        \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  const char* vtkClusteredLightingPass::Get##option##AsString()                                    \
  {                                                                                                \
    return NameOf(names, this->option);                                                            \
  }

vtkClusteredLightingEnumSetter(ShadingMode, ShadingModeNames, "shading mode");
vtkClusteredLightingEnumSetter(Falloff, FalloffNames, "falloff");
vtkClusteredLightingEnumSetter(SlicingScheme, SlicingSchemeNames, "slicing scheme");
vtkClusteredLightingEnumSetter(DebugView, DebugViewNames, "debug view");
vtkClusteredLightingEnumSetter(BoundsMethod, BoundsMethodNames, "bounds method");
#undef vtkClusteredLightingEnumSetter

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::SetErrorBudgetInSteps(double steps)
{
  if (std::isnan(steps))
  {
    vtkWarningMacro(<< "SetErrorBudgetInSteps: NaN is no number of steps; the budget stays "
                    << this->GetErrorBudgetInSteps() << " steps.");
    return;
  }
  this->SetErrorBudget(steps / 255.0);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::ResetNaNOptions()
{
  static const struct
  {
    const char* Name;
    double vtkClusteredLightingPass::*Member;
  } options[] = { { "ContributionCutoff", &vtkClusteredLightingPass::ContributionCutoff },
    { "FarFieldCutoff", &vtkClusteredLightingPass::FarFieldCutoff },
    { "ErrorBudget", &vtkClusteredLightingPass::ErrorBudget },
    { "FarFieldCellsPerRadius", &vtkClusteredLightingPass::FarFieldCellsPerRadius },
    { "FarFieldTolerance", &vtkClusteredLightingPass::FarFieldTolerance },
    { "FarFieldGrouping", &vtkClusteredLightingPass::FarFieldGrouping },
    { "NearFieldBudget", &vtkClusteredLightingPass::NearFieldBudget },
    { "HeatMapMaximum", &vtkClusteredLightingPass::HeatMapMaximum } };
  vtkSmartPointer<vtkClusteredLightingPass> fresh; // the defaults: a new pass's, if needed
  for (const auto& o : options)
  {
    if (std::isnan(this->*o.Member))
    {
      fresh = fresh ? fresh : vtkSmartPointer<vtkClusteredLightingPass>::New();
      vtkWarningMacro(<< o.Name << " is NaN; it is set back to its default, "
                      << fresh.Get()->*o.Member << ".");
      this->*o.Member = fresh.Get()->*o.Member;
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
    vtkClusteredLighting::PrepassChooser Chooser; ///< AutomaticDepthPrepass
    /// The renderer's own prepass: its readback and the signature of the depths it saved
    /// (ReuseDepthPrepass), so that renderers sharing the pass each reuse theirs.
    vtkSmartPointer<vtkClusteredLightingDepthPrepass> Prepass;
    /// Where the renderer's surfaces lie (FarFieldSkipEmptyBlocks).
    vtkClusteredLightingSurfaceBoxes Surfaces;
  };
  std::map<vtkRenderer*, RendererEntry> Renderers;
  std::vector<vtkSmartPointer<vtkClusteredLightSet>> LightSets;
  vtkClusteredLightingAssigner* Current = nullptr; ///< during Render()
  vtkClusteredLightingShaderVariant Variant;       ///< global part for the current render
  /// The pass's own delegate (VTK's render steps) and its steps: opaque (with the
  /// renderer's SSAO and hidden-line removal), translucent (which also counts the shaded
  /// fragments, MeasureTimings), volumetric (after the renderer's FXAA).
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkClusteredLightingOpaqueStep> OpaqueStep;
  vtkNew<vtkClusteredLightingTranslucentStep> TranslucentStep;
  vtkNew<vtkClusteredLightingVolumetricStep> VolumetricStep;
  /// AutomaticBackfaceCulling, in the prepass and the opaque step.
  vtkClusteredLightingBackfaceCulling BackfaceCulling;
  vtkTimeStamp ShaderStageTime;
  vtkNew<vtkLight> PlaceholderLight;  ///< keeps VTK's lit code when every light is clustered
  vtkNew<vtkLight> ComplexityLight;   ///< keeps VTK's lighting complexity (switched off)
  std::set<std::size_t> BuiltSources; ///< hashes of the shader sources built (NumberOfShaderBuilds)
  vtkClusteredLighting::DepthImage Depths; ///< the prepass's readback, during Render()
  std::string ReportedDepthProblem;        ///< why depth-aware clusters are off, said once
  std::string DepthReuseProblem;           ///< why the last depths were not kept
  bool ReportedShadows = false;            ///< UseShadows, which the pass does not apply
  bool ReportedFarDiffuseOrder = false;    ///< too few texture units for the order-4 diffuse
  bool ReportedFarSpecularBins = false;    ///< too few texture units for the specular's bins
  bool ReportedLoopLimit = false;          ///< the llvmpipe loop limit was reported
  bool ReportedUncountedPixels = false;    ///< a debug view's counts could not be read
  bool ReportedPbrFarField = false;        ///< PBR actors sum their far light exactly
  bool ReportedUnlitVolumes = false;       ///< volumes shown with light sets, said once
  bool RefineAsked = false;                ///< this frame's far field refined (still lights)

  /// The entry of `ren`, made on first use (its assigner and prepass).
  RendererEntry& GetEntry(vtkRenderer* ren)
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
      entry.Prepass = vtkSmartPointer<vtkClusteredLightingDepthPrepass>::New();
    }
    return entry;
  }

  vtkClusteredLightingAssigner* GetAssigner(vtkRenderer* ren)
  {
    return this->GetEntry(ren).Assigner.get();
  }
};

vtkStandardNewMacro(vtkClusteredLightingPass);

//------------------------------------------------------------------------------
vtkClusteredLightingPass::vtkClusteredLightingPass()
  : Internals(new vtkInternals)
{
  this->Internals->Steps->SetOpaquePass(this->Internals->OpaqueStep);
  this->Internals->Steps->SetTranslucentPass(this->Internals->TranslucentStep);
  this->Internals->Steps->SetVolumetricPass(this->Internals->VolumetricStep);
  this->Internals->OpaqueStep->SetBackfaceCulling(&this->Internals->BackfaceCulling);
  this->SetDelegatePass(this->Internals->Steps);

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
void vtkClusteredLightingPass::SetFarFieldRegion(
  double xmin, double xmax, double ymin, double ymax, double zmin, double zmax)
{
  const double region[6] = { xmin, xmax, ymin, ymax, zmin, zmax };
  this->SetFarFieldRegion(region);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::SetFarFieldRegion(const double region[6])
{
  if (!std::all_of(region, region + 6, [](double v) { return std::isfinite(v); }))
  {
    // MakeAssignerInputs would take the grid to the lights' own box (see PlanFarField),
    // leaving geometry outside it with the edge's far light.
    vtkWarningMacro(<< "FarFieldRegion (" << region[0] << ", " << region[1] << ", " << region[2]
                    << ", " << region[3] << ", " << region[4] << ", " << region[5]
                    << ") is not finite; the far field covers the visible props alone.");
  }
  if (!std::equal(region, region + 6, this->FarFieldRegion))
  {
    std::copy(region, region + 6, this->FarFieldRegion);
    this->Modified();
  }
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
const char* vtkClusteredLightingPass::GetDepthPrepassReuseProblem() const
{
  return this->Internals->DepthReuseProblem.c_str();
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
  if (ren->GetSelector())
  {
    this->RenderSelection(s);
    return;
  }
  this->SetUpCamera(ren);
  this->ReportIgnoredRendererOptions(ren);
  this->ResetNaNOptions();

  // 1. Light gathering. An application's delegate (ParaView's) renders the volumes with the
  // surfaces, while the clustered vtkLights are hidden from VTK's lighting code, and a
  // volume mapper lights a volume only with the lights the renderer holds: with a shaded
  // volume in the frame the renderer's lights stay with VTK, surfaces and volumes alike.
  const bool foreign = this->DelegatePass != this->Internals->Steps.GetPointer();
  this->RendererLightsLeftToVTK = this->ClusterRendererLights && foreign &&
    vtkClusteredLightingVolumetricStep::HasVolumes(s, true);
  // Under an application's delegate nothing ends the opaque geometry's draws for the pass:
  // no culling there (vtkClusteredLightingBackfaceCulling).
  vtkClusteredLightingBackfaceCulling& culling = this->Internals->BackfaceCulling;
  culling.BeginFrame(s, rw->GetState(), this->AutomaticBackfaceCulling && !foreign);
  vtkClusteredLightingLightCollection lights;
  vtkClusteredLightingLightCollector::CollectRendererLights(
    ren, this->ClusterRendererLights && !this->RendererLightsLeftToVTK, lights);
  vtkClusteredLightingLightCollector::CollectLightSets(this->Internals->LightSets, lights);
  this->ReportUnlitVolumes(s, lights);

  // 2. Depth prepass (hidden fragments and depth-aware clusters), then assignment. With
  // AutomaticDepthPrepass the renderer's chooser says whether this frame draws it, and
  // which frames to time for its trials (vtkClusteredLightingPrepassChoice.h).
  vtkClusteredLightingAssigner* assigner = this->Internals->GetAssigner(ren);
  vtkClusteredLightingAssignerInputs inputs = this->MakeAssignerInputs(ren, lights);
  this->RefineStillFarField(ren, inputs);
  this->ChooseFarDiffuseOrder(rw, inputs);
  this->DepthPrepassUsed = false;
  this->DepthPrepassReused = false;
  this->DepthPrepassKept = false;
  this->Internals->DepthReuseProblem.clear();
  this->DepthAwareClustersUsed = false;
  this->LastDepthPrepassTime = 0.0;
  const bool eligible = this->UsesDepthPrepass(s, lights);
  PrepassChooser* chooser =
    eligible && this->AutomaticDepthPrepass ? &this->Internals->Renderers[ren].Chooser : nullptr;
  const PrepassFrame frame =
    chooser ? chooser->BeginFrame(this->MakePrepassSignature(s, lights)) : PrepassFrame();
  std::chrono::steady_clock::time_point start;
  if (frame.Timed)
  {
    glFinish(); // earlier GL work is not this frame's
    start = std::chrono::steady_clock::now();
  }
  const bool prepassed = eligible && frame.Prepass;
  if (prepassed)
  {
    this->RenderDepthPrepass(s, rw, inputs);
  }
  if (!this->DepthPrepassKept)
  {
    assigner->GetSavedDepth()->Release(rw); // no memory held for depths no frame reuses
  }
  const vtkClusteredLightingAssignment& result = assigner->Update(rw, inputs);
  this->Internals->Depths = vtkClusteredLighting::DepthImage();
  this->ReportAssignment(result);
  this->ReportLoopLimit(result);

  // 3. Shading, on the prepass's depth buffer when there is one (the camera pass then
  // clears colour only).
  this->UpdateShaderVariant(result);
  this->Internals->Current = assigner;
  const bool preserved = ren->GetPreserveDepthBuffer() != 0;
  if (prepassed && !preserved)
  {
    ren->PreserveDepthBufferOn();
  }
  this->RenderDelegate(s, lights, assigner);
  if (prepassed && !preserved)
  {
    ren->PreserveDepthBufferOff();
  }
  this->Internals->Current = nullptr;
  this->NumberOfBackfaceCulledProps = culling.GetNumberOfCulledProps();
  if (frame.Timed)
  {
    glFinish();
    chooser->EndFrame(Milliseconds(start, std::chrono::steady_clock::now()));
  }
  this->NumberOfDepthPrepassTrials = chooser ? chooser->GetNumberOfTrials() : 0;
  const double ratio = chooser ? chooser->GetLastRatio() : 0.0;
  this->DepthPrepassTrialRatio = std::isnan(ratio) ? 0.0 : ratio;
}

//------------------------------------------------------------------------------
// A hardware selection render (vtkHardwareSelector: VTK's pickers, ParaView's selections)
// draws ids, not light: no light gathering, assignment or shader hooks. VTK's render
// steps (the pass's own delegate) have no selection path, so the renderer's own steps
// render it, as without a pass (vtkOpenGLRenderer::DeviceRender, through vtkRenderPass's
// access to them): its UpdateGeometry hands the props to the selector (and honours a pick
// list). A delegate of the application's (ParaView's vtkPVDefaultPass renders through the
// renderer's steps too) renders it as it would without this pass.
void vtkClusteredLightingPass::RenderSelection(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  if (this->DelegatePass == this->Internals->Steps.GetPointer())
  {
    this->UpdateCamera(ren);
    this->UpdateLightGeometry(ren);
    this->UpdateLights(ren);
    this->UpdateGeometry(ren, s->GetFrameBuffer());
    this->NumberOfRenderedProps = ren->GetNumberOfPropsRendered();
  }
  else
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  }
}

//------------------------------------------------------------------------------
// Renderer options that only the renderer's own render applies (vtkOpenGLRenderer's
// UpdateGeometry and DeviceRenderOpaqueGeometry) and VTK's render steps skip under any
// render pass. The pass's own steps apply UseFXAA, UseSSAO and UseHiddenLineRemoval as the
// renderer does (vtkClusteredLightingOpaqueStep, vtkClusteredLightingVolumetricStep);
// UseShadows stays off: VTK's shadow maps are one depth render per light and shade only
// VTK's own lights, so the clustered lights would cast none. Said once while it is asked
// for; an application's delegate (ParaView's) renders through the renderer and decides.
void vtkClusteredLightingPass::ReportIgnoredRendererOptions(vtkRenderer* ren)
{
  const bool shadows =
    this->DelegatePass == this->Internals->Steps.GetPointer() && ren->GetUseShadows() != 0;
  const bool report = shadows && !this->Internals->ReportedShadows;
  this->Internals->ReportedShadows = shadows;
  if (report)
  {
    vtkWarningMacro("The renderer asks for UseShadows, which this pass does not apply: VTK's "
                    "shadow maps (one depth render per light) are made for the lights VTK "
                    "shades itself, and the clustered lights would cast none. The frame is "
                    "rendered without shadows.");
  }
}

//------------------------------------------------------------------------------
// The order-4 far diffuse reads 14 textures besides the lights' 4 and the specular table: a
// GPU whose fragment shaders have fewer texture units than it needs beside VTK's own
// (FarFieldOrder4TextureUnits) gets the order-2 far field, said once.
void vtkClusteredLightingPass::ChooseFarDiffuseOrder(
  vtkOpenGLRenderWindow* rw, vtkClusteredLightingAssignerInputs& inputs)
{
  if (!inputs.FarField.Enabled || (!inputs.FarField.Order4Diffuse && !inputs.FarField.SpecularBins))
  {
    return;
  }
  int units = 0;
  rw->GetState()->vtkglGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
  const bool binsAsked = inputs.FarField.SpecularBins;
  inputs.FarField.SpecularBins =
    vtkClusteredLighting::ChooseFarSpecularBins(binsAsked, units, inputs.FarField.Order4Diffuse);
  if (binsAsked && !inputs.FarField.SpecularBins && !this->Internals->ReportedFarSpecularBins)
  {
    vtkWarningMacro(<< inputs.SpecularBinsOption << ": this GPU's fragment shaders have " << units
                    << " texture units, fewer than the "
                    << vtkClusteredLighting::GetFarSpecularBinsTextureUnits(
                         inputs.FarField.Order4Diffuse)
                    << " the far specular's bins need beside VTK's own; the far specular comes "
                       "from the moments (its error stays within the stated bound).");
  }
  this->Internals->ReportedFarSpecularBins = binsAsked && !inputs.FarField.SpecularBins;
  if (!inputs.FarField.Order4Diffuse)
  {
    return;
  }
  inputs.FarField.Order4Diffuse = vtkClusteredLighting::ChooseFarDiffuseOrder4(true, units);
  if (!inputs.FarField.Order4Diffuse && !this->Internals->ReportedFarDiffuseOrder)
  {
    vtkWarningMacro(<< "FarFieldOrder4Diffuse: this GPU's fragment shaders have " << units
                    << " texture units, fewer than the "
                    << vtkClusteredLighting::FarFieldOrder4TextureUnits
                    << " the order-4 far diffuse needs beside VTK's own; the far diffuse is of "
                       "order 2 (its error stays within the stated bound).");
  }
  this->Internals->ReportedFarDiffuseOrder = !inputs.FarField.Order4Diffuse;
}

//------------------------------------------------------------------------------
// Volumes are lit by their mappers from the renderer's vtkLights: the pass's own steps
// give them every one (vtkClusteredLightingVolumetricStep), and under an application's
// delegate a shaded volume keeps them with VTK (RendererLightsLeftToVTK). The lights of
// light sets cannot reach a volume (no volume mapper reads them): said once per pass.
void vtkClusteredLightingPass::ReportUnlitVolumes(
  const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights)
{
  if (lights.LightSets.empty() || this->Internals->ReportedUnlitVolumes ||
    !vtkClusteredLightingVolumetricStep::HasVolumes(s))
  {
    return;
  }
  this->Internals->ReportedUnlitVolumes = true;
  vtkWarningMacro("The renderer shows a volume: volumes are lit by the renderer's "
                  "vtkLights only, as VTK lights them, not by the lights of "
                  "vtkClusteredLightSets.");
}

//------------------------------------------------------------------------------
// Whether this frame may draw the depth prepass: the options ask for it, there are
// clustered lights and props (a selection render does not come here), and the opaque
// geometry is drawn on the prepass's depths (not so under the renderer's hidden-line
// removal or SSAO: vtkClusteredLightingOpaqueStep::DrawsOnPrepassDepths).
bool vtkClusteredLightingPass::UsesDepthPrepass(
  const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights) const
{
  const bool hasLights = !lights.ClusteredLights.empty() || !lights.LightSets.empty();
  return (this->DepthPrepass || this->DepthAwareClusters) && hasLights &&
    s->GetPropArrayCount() > 0 && vtkClusteredLightingOpaqueStep::DrawsOnPrepassDepths(s);
}

//------------------------------------------------------------------------------
// What moves the prepass's break-even, hashed: the number of lights in powers of two, the
// renderer's props (added or removed), the viewport's size and the pass's options. A new
// value starts a new trial.
std::uint64_t vtkClusteredLightingPass::MakePrepassSignature(
  const vtkRenderState* s, const vtkClusteredLightingLightCollection& lights)
{
  std::uint64_t n = lights.ClusteredLights.size();
  for (vtkClusteredLightSet* set : lights.LightSets)
  {
    n += static_cast<std::uint64_t>(set->GetNumberOfLights());
  }
  int bits = 0;
  for (; n > 0; n >>= 1)
  {
    ++bits;
  }
  int width = 0, height = 0, x0 = 0, y0 = 0;
  s->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](std::uint64_t v)
  {
    h ^= v;
    h *= 1099511628211ULL;
  };
  mix(static_cast<std::uint64_t>(bits));
  // The renderer's props, not the render state's: those change with the frustum culling
  // as the camera moves, and a moving camera is no new scene.
  vtkPropCollection* props = s->GetRenderer()->GetViewProps();
  mix(static_cast<std::uint64_t>(props->GetNumberOfItems()));
  mix(static_cast<std::uint64_t>(props->GetMTime()));
  mix(static_cast<std::uint64_t>(width));
  mix(static_cast<std::uint64_t>(height));
  mix(static_cast<std::uint64_t>(this->GetMTime()));
  return h;
}

//------------------------------------------------------------------------------
// The depth prepass, for a frame that draws it (UsesDepthPrepass, and the chooser with
// AutomaticDepthPrepass). With depth-aware clusters it also reads the depth back for the
// assigner.
void vtkClusteredLightingPass::RenderDepthPrepass(
  const vtkRenderState* s, vtkOpenGLRenderWindow* rw, vtkClusteredLightingAssignerInputs& inputs)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkInternals::RendererEntry& entry = this->Internals->GetEntry(ren);
  vtkClusteredLightingAssigner* assigner = entry.Assigner.get();
  vtkClusteredLightingDepthPrepass* prepass = entry.Prepass;
  // In a multisampled framebuffer depth-aware clusters need the fragments' own depths,
  // which the prepass then records (vtkClusteredLightingSampleDepths).
  const bool depthAware = this->DepthAwareClusters && inputs.Clustered;
  // The last frame's depths where they still hold (ReuseDepthPrepass), else a draw.
  const std::uint64_t reuse = this->ReuseDepthPrepass
    ? vtkClusteredLightingDepthPrepass::ComputeReuseSignature(
        s, rw, depthAware, &this->Internals->DepthReuseProblem, &this->Internals->BackfaceCulling)
    : 0;
  if (!prepass->RestoreDepth(s, rw, this->MeasureTimings, assigner->GetSavedDepth(), reuse))
  {
    // VTK's lighting code in the prepass's programs follows the renderer's lights: the
    // same as in the shading render (the clustered lights hidden), so that each mapper
    // keeps the same two programs from the first frame on.
    this->HideClusteredLights(ren, *inputs.Lights);
    this->UpdateLights(ren);
    this->Internals->BackfaceCulling.SetActive(true);
    prepass->SetBackfaceCulling(&this->Internals->BackfaceCulling);
    prepass->RenderDepth(s, rw, this->MeasureTimings,
      depthAware ? assigner->GetSampleDepths() : nullptr, assigner->GetSavedDepth(), reuse);
    prepass->SetBackfaceCulling(nullptr);
    this->Internals->BackfaceCulling.SetActive(false);
    this->RestoreRendererLights(ren, *inputs.Lights);
  }
  this->DepthPrepassUsed = true;
  this->DepthPrepassReused = prepass->GetReused();
  this->DepthPrepassKept = prepass->GetKept();
  if (reuse != 0 && !this->DepthPrepassKept)
  {
    this->Internals->DepthReuseProblem = "its depths could not be copied";
  }
  if (depthAware)
  {
    // Where translucent fragments may be: the screen rectangles of the translucent props'
    // boxes (none: anywhere).
    bool translucent = false;
    std::vector<glm::dvec4> translucentRects;
    std::vector<glm::dvec2> translucentDepths;
    vtkClusteredLightingDepthPrepass::ComputeTranslucentRects(
      s, inputs.View.WCVC, inputs.View.VCDC, translucent, translucentRects, translucentDepths);
    std::string problem;
    if (prepass->GetUnknownDepthWrites())
    {
      problem = "a mapper writes its own fragment depth (impostor spheres or tubes, or a "
                "coincident-topology offset with a slope factor)";
    }
    else if (!prepass->ReadDepth(rw))
    {
      problem = prepass->GetProblem();
    }
    if (problem.empty())
    {
      this->Internals->Depths = prepass->GetImage();
      inputs.Depths = &this->Internals->Depths;
      inputs.DepthOptions.WindowMargin =
        vtkClusteredLighting::ComputeWindowMargin(prepass->GetMaximumCoincidentOffset());
      inputs.DepthOptions.PixelSlack = vtkClusteredLightingDepthPrepass::ComputePixelSlack(s);
      inputs.DepthOptions.Translucent = translucent;
      inputs.DepthOptions.TranslucentRects = std::move(translucentRects);
      inputs.DepthOptions.TranslucentDepths = std::move(translucentDepths);
      this->Internals->ReportedDepthProblem.clear();
    }
    else if (problem != this->Internals->ReportedDepthProblem)
    {
      vtkWarningMacro(<< "Depth-aware clusters are off for this view: " << problem
                      << ". Whole clusters are used instead (correct, slower).");
      this->Internals->ReportedDepthProblem = problem;
    }
  }
  this->LastDepthPrepassTime = prepass->GetRenderTime();
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
// Lights that changed in this frame and in the one before are moving: their far field is
// rebuilt every frame, at the options' own settings. Any other build, with more than
// FarFieldRefineLeastLights lights, is refined: 1.5 times the cells per near radius at
// 3.375 times the nodes (the same near radii, nodes 1.5 times closer) and the far
// specular's bins where an actor needs them. Settings that differ from the last build's
// rebuild the far field (the assigner's preparation key), so the first frame after the
// lights stop builds the refined one.
void vtkClusteredLightingPass::RefineStillFarField(
  vtkRenderer* ren, vtkClusteredLightingAssignerInputs& inputs)
{
  // The renderer's assigner updates once per frame: its last update says whether the
  // lights changed in the frame before.
  const vtkClusteredLightingAssigner* assigner = this->Internals->GetAssigner(ren);
  const bool moving = assigner->AreNewSources(inputs.Lights->Key) &&
    (assigner->GetResult().Reasons & CL_DIRTY_LIGHTS) != 0;
  long long count = static_cast<long long>(inputs.Lights->ClusteredLights.size());
  for (vtkClusteredLightSet* set : inputs.Lights->LightSets)
  {
    count += set->GetNumberOfLights();
  }
  const bool refine = this->FarFieldRefineStillLights && inputs.FarField.Enabled &&
    inputs.ErrorBudget <= 0.0 && count > this->FarFieldRefineLeastLights && !moving;
  this->Internals->RefineAsked = refine;
  if (!refine)
  {
    return;
  }
  inputs.FarField.CellsPerRadius = std::min(8.0, 1.5 * inputs.FarField.CellsPerRadius);
  inputs.FarField.TargetNodes = std::min<std::int64_t>(
    16777216, std::llround(3.375 * static_cast<double>(inputs.FarField.TargetNodes)));
  if (!inputs.FarField.SpecularBins && NeedsFarSpecularBins(ren))
  {
    inputs.FarField.SpecularBins = true;
    inputs.SpecularBinsOption = "FarFieldRefineStillLights";
  }
}

//------------------------------------------------------------------------------
vtkClusteredLightingAssignerInputs vtkClusteredLightingPass::MakeAssignerInputs(
  vtkRenderer* ren, vtkClusteredLightingLightCollection& lights) const
{
  vtkClusteredLightingAssignerInputs in;
  in.Lights = &lights;
  in.Preparation.Cutoff = this->ContributionCutoff;
  // The split lights' own cutoff (0: ContributionCutoff's); without a far field nothing is
  // split, and every light takes ContributionCutoff.
  in.Preparation.FarFieldCutoff = this->FarField ? this->FarFieldCutoff : 0.0;
  in.Preparation.MortonOrder = this->MortonOrder;
  in.ErrorBudget = this->ErrorBudget;
  in.Windowed = this->Falloff == FALLOFF_WINDOWED;
  in.FarField.Enabled = this->FarField;
  in.FarField.TargetNodes = this->FarFieldResolution;
  in.FarField.CellsPerRadius = this->FarFieldCellsPerRadius;
  in.FarField.Grouping = this->FarFieldGrouping;
  in.FarField.NearBudget = this->NearFieldBudget;
  in.FarField.SharedColor = this->FarFieldSharedColor;
  in.FarField.Order4Diffuse = this->FarFieldOrder4Diffuse;
  in.FarField.SpecularBins = this->FarFieldSpecularBins && NeedsFarSpecularBins(ren);
  // The far field's region: the visible props' bounds, with FarFieldRegion when it is a
  // box.
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  vtkBoundingBox region;
  region.AddBounds(bounds);
  // A region that is not finite is ignored (SetFarFieldRegion warned).
  if (std::all_of(
        this->FarFieldRegion, this->FarFieldRegion + 6, [](double v) { return std::isfinite(v); }))
  {
    region.AddBounds(this->FarFieldRegion);
  }
  if (region.IsValid())
  {
    region.GetBounds(bounds);
  }
  in.RegionLo = glm::dvec3(bounds[0], bounds[2], bounds[4]);
  in.RegionHi = glm::dvec3(bounds[1], bounds[3], bounds[5]);
  // A multisampled framebuffer shades a fragment that covers some of its pixel's samples
  // at the pixel's centre, on its primitive's plane extrapolated past the primitive: at a
  // silhouette, possibly far from every surface, in a block no surface marks (whose
  // moments are stale or zero). There the blocks that the fragments the depth prepass
  // records reach are summed too (every block without that record).
  if (this->FarField && this->FarFieldSkipEmptyBlocks)
  {
    vtkClusteredLightingSurfaceBoxes& surfaces = this->Internals->GetEntry(ren).Surfaces;
    surfaces.Update(ren);
    in.Surfaces = &surfaces;
    in.FragmentsOffSurfaces = vtkClusteredLightingSampleDepths::IsDrawFramebufferMultisampled();
  }
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
  in.View.SpotConeCulling = this->SpotConeCulling;
  in.Clustered = this->ShadingMode == SHADING_CLUSTERED;
  in.PerClusterCulling = this->PerClusterCulling;
  in.MaximumTextureSize = this->MaximumTextureSize;
  in.MeasureTimings = this->MeasureTimings;
  return in;
}

//------------------------------------------------------------------------------
// Mesa's llvmpipe ends a fragment shader after 65,535 loop iterations in all, silently.
// A cluster's walk takes one light per iteration, brute force 16, the exact far sums one
// up to 16,384 lights and 16 above (ComputeFarPartsPerIteration); where a
// fragment could need more iterations (a cluster that lists about 60,000 lights, brute
// force or the exact far sums past about a million), say so once while it lasts
// (docs/guide.md, "Limits").
void vtkClusteredLightingPass::ReportLoopLimit(const vtkClusteredLightingAssignment& r)
{
  using namespace vtkClusteredLighting;
  const bool brute = this->ShadingMode == SHADING_BRUTE_FORCE;
  long long iterations = 0;
  if (r.Enabled && brute)
  {
    iterations = ComputeEveryLightIterations(r.NumberOfLights);
  }
  else if (r.Enabled && r.Clustered)
  {
    iterations = ComputeWalkIterations(r.MostLightsInACluster, r.NumberOfLights, r.MasterTexels) +
      (r.FarField ? ComputeFarSumIterations(r.NumberOfLights) : 0);
  }
  if (iterations <= ShaderLoopLimit)
  {
    this->Internals->ReportedLoopLimit = false;
    return;
  }
  if (this->Internals->ReportedLoopLimit)
  {
    return;
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer && std::string(renderer).find("llvmpipe") != std::string::npos)
  {
    std::ostringstream what;
    if (brute)
    {
      what << "brute force, 16 lights per iteration";
    }
    else
    {
      what << "a cluster lists up to " << r.MostLightsInACluster << " lights, one per iteration"
           << (r.FarField ? ", and the exact far sums take " +
                    std::to_string(ComputeFarPartsPerIteration(r.NumberOfLights)) + " per iteration"
                          : "");
    }
    vtkWarningMacro(<< r.NumberOfLights
                    << " lights: llvmpipe ends a fragment shader after 65,535 loop iterations, "
                       "and a fragment here can need up to "
                    << iterations << " (" << what.str()
                    << "), so some lights may be left out. Use fewer or shorter-ranged "
                       "lights, or a GPU driver.");
    this->Internals->ReportedLoopLimit = true;
  }
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
  for (const std::string& warning : r.NewWarnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!r.NewError.empty())
  {
    vtkErrorMacro(<< r.NewError);
  }
  for (int a = 0; a < 3; ++a)
  {
    this->ClusterGridInUse[a] = r.Enabled && r.Clustered ? r.Grid[a] : 0;
  }
  this->ClusteringBypassed = r.Enabled && r.Bypassed;
  this->MeanLightsPerCluster = r.Enabled ? r.MeanLightsPerCluster : 0.0;
  this->EffectiveCutoff = r.EffectiveCutoff;
  this->EffectiveFarFieldCutoff = r.EffectiveFarFieldCutoff;
  this->NumberOfClusteredLights = r.NumberOfLights;
  this->NumberOfRejectedLights = r.NumberOfRejected;
  this->NumberOfAlwaysOnLights = r.NumberOfAlwaysOn;
  this->NumberOfLightsBelowCutoff = r.NumberOfBelowCutoff;
  this->NumberOfSpotLights = r.NumberOfSpots;
  this->NumberOfAssignedLights = r.NumberOfAssigned;
  this->NumberOfLightUploads += r.LightsUploaded ? 1 : 0;
  this->LastLightUpdateTime = r.LightUpdateTime;
  this->NumberOfFarFieldLights = r.FarField ? r.NumberOfFarFieldLights : 0;
  this->NumberOfPackedFarFieldLights = r.FarField ? r.NumberOfPackedFarFieldLights : 0;
  this->LastFarFieldBuildTime = r.FarFieldBuildTime;
  this->NumberOfFarFieldNodesBuilt = r.FarField ? r.FarFieldNodesBuilt : 0;
  this->NumberOfFarFieldBlocks = r.FarField ? r.FarFieldBlocks : 0;
  this->NumberOfFarFieldBlocksRead = r.FarField ? r.FarFieldBlocksNeeded : 0;
  this->FarFieldGridSpacing = r.FarField ? r.FarFieldSpacing : 0.0;
  this->NearRadiusCap = r.FarField ? r.NearRadiusCap : 0.0;
  for (int a = 0; a < 3; ++a)
  {
    this->FarFieldDimensions[a] = r.FarField ? r.FarFieldDims[a] : 0;
  }
  this->FarFieldResolutionInUse = r.FarField ? static_cast<int>(r.FarFieldNodesTarget) : 0;
  this->FarFieldErrorBudgetMet = r.FarFieldBudgetChoice.Met;
  this->NumberOfFarFieldResolutionChoices += r.FarFieldResolutionChosen ? 1 : 0;
  this->FarFieldTextureBytes = r.FarFieldBytes;
  this->FarFieldSharedColorUsed = r.FarField && r.FarFieldOneChannel;
  this->FarFieldSpecularBinsUsed = r.FarField && r.FarFieldSpecularBins;
  this->FarFieldRefinedUsed = r.FarField && this->Internals->RefineAsked;
  this->DepthAwareClustersUsed = r.Enabled && r.DepthAware;
  for (int k = 0; k < 2; ++k)
  {
    this->VisibleDepthRange[k] = this->DepthAwareClustersUsed ? r.VisibleDepthRange[k] : 0.0;
    this->SlicingRangeInUse[k] = r.Enabled ? r.SlicingRange[k] : 0.0;
  }
  this->NonEmptyClusterFraction = this->DepthAwareClustersUsed ? r.NonEmptyClusterFraction : 1.0;
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
  variant.FarFieldOneChannel = r.FarField && r.FarFieldOneChannel;
  variant.FarFieldOrder4 = r.FarField && r.FarFieldOrder4;
  variant.FarFieldSpecularBins = r.FarField && r.FarFieldSpecularBins;
  // The exact far sums' code is compiled only where a fragment may take them (FarFieldTolerance,
  // FarFieldExactSumLimit; the same choice as the clFarFieldTolerance uniform).
  const bool sums = r.FarField && this->FarFieldTolerance < 1.0;
  variant.PhongExactFarSums = sums && r.NumberOfLights <= this->FarFieldExactSumLimit;
  variant.PbrExactFarSums = sums;
  variant.FarSumBlocks =
    sums && vtkClusteredLighting::ComputeFarPartsPerIteration(r.NumberOfLights) > 1;
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
  vtkOpenGLRenderWindow* rw = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  const bool enabled = assigner->GetResult().Enabled;
  if (enabled)
  {
    this->HideClusteredLights(ren, lights);
    this->Internals->VolumetricStep->SetVolumeLights(&lights.RendererLights);
    assigner->ActivateShading();
  }
  // A heat map scaled to the data first counts the lights evaluated per pixel: one render
  // with the counting variant (the mappers' shader cache keeps both programs compiled).
  vtkClusteredLightingShaderVariant& variant = this->Internals->Variant;
  const bool counting = enabled && this->DebugView == DEBUG_EVALUATED_COUNT;
  const bool countFirst =
    enabled && this->DebugView == DEBUG_HEAT_MAP && !(this->HeatMapMaximum > 0.0);
  if (countFirst)
  {
    variant.DebugView = vtkClusteredLightingShaderVariant::Debug::EvaluatedCount;
    this->Internals->ShaderStageTime.Modified();
    {
      CountingRender countingRender(s, true);
      this->RenderDelegateOnce(countingRender.GetState());
    }
    this->SetPixelCounts(s, rw);
    variant.DebugView = vtkClusteredLightingShaderVariant::Debug::HeatMap;
    this->Internals->ShaderStageTime.Modified();
  }
  this->HeatMapScale = this->HeatMapMaximum > 0.0
    ? this->HeatMapMaximum
    : std::max(1.0, static_cast<double>(this->MaximumLightsEvaluatedPerPixel));
  const auto s0 = std::chrono::steady_clock::now();
  if (this->MeasureTimings)
  {
    glFinish();
  }
  const auto s1 = std::chrono::steady_clock::now();
  // Fragments that pass the depth test per visible pixel: what a GPU with early depth
  // tests shades (occlusion queries, MeasureTimings only), opaque and translucent apart
  // (vtkClusteredLightingTranslucentStep). Only through the pass's own delegate, whose
  // translucent step switches the queries (another delegate's translucency, ParaView's
  // depth peeling say, may run queries of its own: nothing is counted, 0).
  vtkClusteredLightingTranslucentStep* step = this->Internals->TranslucentStep;
  const bool countFragments =
    this->MeasureTimings && this->DelegatePass == this->Internals->Steps.GetPointer();
  if (countFragments)
  {
    step->BeginCounting();
  }
  {
    // The count views' images encode counts, which FXAA and SSAO would change.
    CountingRender countingRender(
      s, enabled && (counting || this->DebugView == DEBUG_REACHED_COUNT));
    this->RenderDelegateOnce(countingRender.GetState());
  }
  this->ShadedOpaqueFragmentsPerVisiblePixel = 0.0;
  this->ShadedTranslucentFragmentsPerVisiblePixel = 0.0;
  vtkClusteredLightingTranslucentStep::Counts shaded;
  if (countFragments)
  {
    shaded = step->EndCounting();
  }
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  if (counting)
  {
    this->SetPixelCounts(s, rw);
  }
  if (this->MeasureTimings)
  {
    glFinish();
  }
  const auto s2 = std::chrono::steady_clock::now();
  this->LastShadingTime = this->MeasureTimings ? Milliseconds(s1, s2) : Milliseconds(s0, s2);
  if (countFragments)
  {
    // The queries count samples: a multisampled framebuffer's fully covered fragment
    // passes all of its samples.
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    const std::size_t visible = CountVisiblePixels(s, rw);
    const double perPixel = visible > 0
      ? 1.0 / (static_cast<double>(visible) * static_cast<double>(std::max(samples, 1)))
      : 0.0;
    // VTK's SSAO draws two full-viewport quads of its own in the opaque step.
    const bool opaqueMeasured =
      this->Internals->OpaqueStep->GetLastMethod() != vtkClusteredLightingOpaqueStep::Method::SSAO;
    this->ShadedOpaqueFragmentsPerVisiblePixel =
      opaqueMeasured ? static_cast<double>(shaded.Opaque) * perPixel : -1.0;
    this->ShadedTranslucentFragmentsPerVisiblePixel =
      shaded.TranslucentMeasured ? static_cast<double>(shaded.Translucent) * perPixel : -1.0;
  }
  if (enabled)
  {
    assigner->DeactivateShading();
    this->Internals->VolumetricStep->SetVolumeLights(nullptr);
    this->RestoreRendererLights(ren, lights);
  }
}

//------------------------------------------------------------------------------
// VTK's lighting code sees only the lights it shades itself (or a placeholder that keeps
// its cheapest code), never VTK's unrolled code for the clustered lights.
void vtkClusteredLightingPass::HideClusteredLights(
  vtkRenderer* ren, const vtkClusteredLightingLightCollection& lights)
{
  vtkLightCollection* rendererLights = ren->GetLights();
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
}

void vtkClusteredLightingPass::RestoreRendererLights(
  vtkRenderer* ren, const vtkClusteredLightingLightCollection& lights)
{
  vtkClusteredLightingLightCollector::SetRendererLights(ren, lights.RendererLights);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::RenderDelegateOnce(const vtkRenderState* s)
{
  this->PreRender(s);
  this->DelegatePass->Render(s);
  this->PostRender(s);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::SetPixelCounts(const vtkRenderState* s, vtkOpenGLRenderWindow* rw)
{
  const PixelCounts counts = CountEvaluatedLights(s, rw);
  if (!counts.Read && !this->Internals->ReportedUncountedPixels)
  {
    vtkWarningMacro(<< "The lights evaluated per pixel could not be read from the framebuffer ("
                    << counts.Problem << "): GetMeanLightsEvaluatedPerPixel reports 0. The "
                    << "debug view's image shows them (R + 256 G).");
    this->Internals->ReportedUncountedPixels = true;
  }
  this->MeanLightsEvaluatedPerPixel = counts.Mean;
  this->MeanLightsReachingPerPixel = counts.ReachingMean;
  this->MaximumLightsEvaluatedPerPixel = counts.Maximum;
  this->NumberOfCountedPixels = counts.Pixels;
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
  // The debug views write the fragment's last colour: after a texture's (VTK multiplies
  // the lit colour by it, which would scale the encoded counts), before VTK's discard of
  // transparent texels and depth peeling. Without that tag, right after the lighting.
  if (!vtkShaderProgram::Substitute(
        fragmentShader, "//VTK::TCoord::Impl", "//VTK::TCoord::Impl\n//VTK::ClusteredLight::Debug"))
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Impl",
      "//VTK::ClusteredLight::Impl\n//VTK::ClusteredLight::Debug");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  this->InjectShadingCode(fragmentShader, prop);
  // The depth prepass draws VTK's own program: the same vertex code must give the same
  // depth in both for the equal depth test.
  vtkClusteredLightingDepthPrepass::AddInvariantPosition(vertexShader);
  // Around the depth prepass a mapper switches between two programs every frame and
  // rebuilds the source each time (VTK's shader cache keeps both compiled): only sources
  // not built before count.
  const std::hash<std::string> h;
  std::size_t hash = h(vertexShader);
  for (const std::string* source : { &geometryShader, &fragmentShader })
  {
    hash = hash * 1000003u ^ h(*source); // order matters: a source moved to another stage differs
  }
  if (this->Internals->BuiltSources.insert(hash).second)
  {
    ++this->NumberOfShaderBuilds;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingPass::InjectShadingCode(std::string& fragmentShader, vtkProp* prop)
{
  if (fragmentShader.find("//VTK::ClusteredLight::Impl") == std::string::npos)
  {
    return; // clustered lighting off for this build
  }
  vtkClusteredLightingShaderVariant variant = this->Internals->Variant;
  vtkProperty* property = GetActorProperty(prop);
  variant.PBR = IsPbr(prop);
  if (property)
  {
    const double* sc = property->GetSpecularColor();
    variant.Specular =
      property->GetSpecular() > 0.0 && std::max(sc[0], std::max(sc[1], sc[2])) > 0.0;
  }

  // Order-2 moments bound a GGX lobe loosely, so PBR fragments lit by a far field mostly
  // sum it exactly (docs/far-field.md, "PBR actors"): said once, with what to do instead.
  if (variant.PBR && variant.FarField && this->FarFieldTolerance < 1.0 &&
    !this->Internals->ReportedPbrFarField)
  {
    vtkWarningMacro("A PBR actor is lit by the far field: where the far light's order-2 "
                    "moments cannot bound VTK's PBR terms within FarFieldTolerance (for "
                    "lights as users write them, most fragments), its far parts are summed "
                    "exactly, at about brute force's cost. For speed, give the lights an "
                    "explicit radius and SetFalloffToWindowed() (no far field), or "
                    "SetFarFieldTolerance(1) (the moments' estimate alone: not within a "
                    "stated bound, off by up to tens of steps at grazing views).");
    this->Internals->ReportedPbrFarField = true;
  }
  // Lit surfaces have VTK's VC position and normal; PBR surfaces accumulate into Lo.
  const bool lit = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vertexVCVSOutput") != std::string::npos;
  const std::string pbrAnchor = "  color += Lo;\n";
  const bool pbrOK = !variant.PBR || fragmentShader.find(pbrAnchor) != std::string::npos;
  variant.Saturation = !vtkClusteredLighting::WritesColorAfter(
    fragmentShader, fragmentShader.find("//VTK::ClusteredLight::Impl"));
  if (!lit || !pbrOK)
  {
    // Unlit fragments evaluate no light: the count views say 0 there, not their colour
    // (a white line read as 65,535 lights).
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Dec", "");
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Impl", "");
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Debug",
      lit ? std::string() : variant.GetUnlitDebugImplementation());
    return;
  }
  vtkClusteredLighting::InsertDeclarations(
    fragmentShader, "#extension GL_ARB_gpu_shader5 : enable\n");
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::ClusteredLight::Dec", variant.GetDeclarations());
  if (variant.PBR)
  {
    vtkShaderProgram::Substitute(
      fragmentShader, pbrAnchor, variant.GetImplementation() + pbrAnchor);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::ClusteredLight::Impl", "");
  }
  else
  {
    vtkShaderProgram::Substitute(
      fragmentShader, "//VTK::ClusteredLight::Impl", variant.GetImplementation());
  }
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::ClusteredLight::Debug", variant.GetDebugImplementation());
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!this->Internals->Current || !program)
  {
    return true;
  }
  this->Internals->BackfaceCulling.Apply(prop);
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
      "clFarField6", "clFarField7", "clFarField8", "clFarField9", "clFarField10", "clFarField11",
      "clFarField12", "clFarField13"
    };
    for (int q = 0; q < vtkClusteredLighting::FarFieldTextures; ++q)
    {
      if (program->IsUniformUsed(farFieldSamplers[q]))
      {
        program->SetUniformi(farFieldSamplers[q], r.FarFieldUnits[static_cast<std::size_t>(q)]);
      }
    }
    if (program->IsUniformUsed("clLobeTable"))
    {
      program->SetUniformi("clLobeTable", r.LobeTableUnit);
    }
    if (program->IsUniformUsed("clFarSpecularBins"))
    {
      program->SetUniformi("clFarSpecularBins", r.SpecularBinsUnit);
      program->SetUniformi("clFarSpecularAxis", r.SpecularBinsAxis);
      program->SetUniformf(
        "clFarSpecularDepth", static_cast<float>(r.FarFieldDims[r.SpecularBinsAxis]));
    }
    if (program->IsUniformUsed("clFarFieldColor"))
    {
      program->SetUniform3f("clFarFieldColor", r.FarFieldColor);
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
      // Only programs with the exact far sums use it (FAR_EXACT_SUMS: the variant already
      // left them out past FarFieldExactSumLimit, see UpdateShaderVariant).
      program->SetUniformf("clFarFieldTolerance", static_cast<float>(this->FarFieldTolerance));
    }
  }
  if (program->IsUniformUsed("clLightCount"))
  {
    program->SetUniformi("clLightCount", r.NumberOfLights);
  }
  if (program->IsUniformUsed("clSpotBatch"))
  {
    // The lights below this batch are walked without the spot code (PrepareLights orders
    // spot lights last; without MortonOrder the first spot light may come anywhere).
    program->SetUniformi("clSpotBatch", r.FirstSpot / 32);
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  const bool blended = actor && actor->IsRenderingTranslucentPolygonalGeometry();
  if (program->IsUniformUsed("clClampsAtOne"))
  {
    // Blended translucent fragments (depth peeling, order-independent translucency)
    // are weighted by their opacity after the shader: values above 1 still count.
    program->SetUniformi(
      "clClampsAtOne", !blended && vtkClusteredLightingDrawTargetClampsAtOne() ? 1 : 0);
  }
  if (program->IsUniformUsed("clFarSumsOnBackFaces"))
  {
    // A translucent surface's back faces show through its front: they sum as the front
    // does (FarFieldExactSumsOnBackFaces is for opaque ones).
    program->SetUniformi(
      "clFarSumsOnBackFaces", this->FarFieldExactSumsOnBackFaces || blended ? 1 : 0);
  }
  if (program->IsUniformUsed("clHeatMapMaximum"))
  {
    program->SetUniformf("clHeatMapMaximum", static_cast<float>(this->HeatMapScale));
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
  const vtkIndent next = indent.GetNextIndent();
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "NumberOfLightSets: " << this->GetNumberOfLightSets() << "\n";
  os << indent << "ClusterRendererLights: " << (this->ClusterRendererLights ? "On" : "Off") << "\n";
  os << indent << "RendererLightsLeftToVTK: " << this->RendererLightsLeftToVTK << "\n";
  os << indent << "ShadingMode: " << this->GetShadingModeAsString() << "\n";
  os << indent << "ContributionCutoff: " << this->ContributionCutoff << "\n";
  os << indent << "FarFieldCutoff: " << this->FarFieldCutoff << "\n";
  os << indent << "ErrorBudgetInSteps: " << this->GetErrorBudgetInSteps() << "\n";
  os << indent << "EffectiveCutoff: " << this->EffectiveCutoff << "\n";
  os << indent << "EffectiveFarFieldCutoff: " << this->EffectiveFarFieldCutoff << "\n";
  os << indent << "Falloff: " << this->GetFalloffAsString() << "\n";
  os << indent << "FarField: " << (this->FarField ? "On" : "Off") << "\n";
  os << indent << "FarFieldResolution: " << this->FarFieldResolution << "\n";
  os << indent << "Tiles: " << this->TilesX << " x " << this->TilesY << ", Slices: " << this->Slices
     << "\n";
  os << indent << "SlicingScheme: " << this->GetSlicingSchemeAsString() << "\n";
  os << indent << "Advanced:\n";
  os << next << "FarFieldCellsPerRadius: " << this->FarFieldCellsPerRadius << "\n";
  os << next << "FarFieldTolerance: " << this->FarFieldTolerance << "\n";
  os << next << "FarFieldExactSumLimit: " << this->FarFieldExactSumLimit << "\n";
  os << next
     << "FarFieldExactSumsOnBackFaces: " << (this->FarFieldExactSumsOnBackFaces ? "On" : "Off")
     << "\n";
  os << next << "FarFieldGrouping: " << this->FarFieldGrouping << "\n";
  os << next << "FarFieldSharedColor: " << (this->FarFieldSharedColor ? "On" : "Off") << "\n";
  os << next << "FarFieldOrder4Diffuse: " << (this->FarFieldOrder4Diffuse ? "On" : "Off") << "\n";
  os << next << "FarFieldSpecularBins: " << (this->FarFieldSpecularBins ? "On" : "Off") << "\n";
  os << next << "FarFieldSkipEmptyBlocks: " << (this->FarFieldSkipEmptyBlocks ? "On" : "Off")
     << "\n";
  os << next << "FarFieldRefineStillLights: " << (this->FarFieldRefineStillLights ? "On" : "Off")
     << "\n";
  os << next << "FarFieldRefineLeastLights: " << this->FarFieldRefineLeastLights << "\n";
  const double* r = this->FarFieldRegion;
  os << next << "FarFieldRegion: ";
  if (vtkBoundingBox::IsValid(r))
  {
    os << r[0] << " " << r[1] << " " << r[2] << " " << r[3] << " " << r[4] << " " << r[5] << "\n";
  }
  else
  {
    os << "(none: the visible props' bounds)\n";
  }
  os << next << "NearFieldBudget: " << this->NearFieldBudget << "\n";
  os << next << "MortonOrder: " << (this->MortonOrder ? "On" : "Off") << "\n";
  os << next << "PerClusterCulling: " << (this->PerClusterCulling ? "On" : "Off") << "\n";
  os << next << "SpotConeCulling: " << (this->SpotConeCulling ? "On" : "Off") << "\n";
  os << next << "AutomaticBackfaceCulling: " << (this->AutomaticBackfaceCulling ? "On" : "Off")
     << "\n";
  os << next << "DepthPrepass: " << (this->DepthPrepass ? "On" : "Off") << "\n";
  os << next << "AutomaticDepthPrepass: " << (this->AutomaticDepthPrepass ? "On" : "Off") << "\n";
  os << next << "ReuseDepthPrepass: " << (this->ReuseDepthPrepass ? "On" : "Off") << "\n";
  os << next << "DepthAwareClusters: " << (this->DepthAwareClusters ? "On" : "Off") << "\n";
  os << next << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "Diagnostic:\n";
  os << next << "DebugView: " << this->GetDebugViewAsString() << "\n";
  os << next << "HeatMapMaximum: " << this->HeatMapMaximum
     << (this->HeatMapMaximum > 0.0 ? "" : " (scaled to the data)") << "\n";
  os << next << "BoundsMethod: " << this->GetBoundsMethodAsString() << "\n";
  os << next << "MeasureTimings: " << (this->MeasureTimings ? "On" : "Off") << "\n";
  os << indent << "Last render:\n";
  os << next << "NumberOfClusteredLights: " << this->NumberOfClusteredLights << "\n";
  os << next << "NumberOfRejectedLights: " << this->NumberOfRejectedLights << "\n";
  os << next << "NumberOfAlwaysOnLights: " << this->NumberOfAlwaysOnLights << "\n";
  os << next << "NumberOfLightsBelowCutoff: " << this->NumberOfLightsBelowCutoff << "\n";
  os << next << "NumberOfSpotLights: " << this->NumberOfSpotLights << "\n";
  os << next << "NumberOfAssignedLights: " << this->NumberOfAssignedLights << "\n";
  os << next << "NumberOfFarFieldLights: " << this->NumberOfFarFieldLights << "\n";
  os << next << "NumberOfPackedFarFieldLights: " << this->NumberOfPackedFarFieldLights << "\n";
  os << next << "FarFieldSharedColorUsed: " << (this->FarFieldSharedColorUsed ? "yes" : "no")
     << "\n";
  os << next << "FarFieldSpecularBinsUsed: " << (this->FarFieldSpecularBinsUsed ? "yes" : "no")
     << "\n";
  os << next << "FarFieldRefinedUsed: " << (this->FarFieldRefinedUsed ? "yes" : "no") << "\n";
  os << next << "NumberOfFarFieldNodesBuilt: " << this->NumberOfFarFieldNodesBuilt << "\n";
  os << next << "NumberOfFarFieldBlocksRead: " << this->NumberOfFarFieldBlocksRead << " of "
     << this->NumberOfFarFieldBlocks << "\n";
  os << next << "ClusterGridInUse: " << this->ClusterGridInUse[0] << " x "
     << this->ClusterGridInUse[1] << " x " << this->ClusterGridInUse[2] << "\n";
  os << next << "ClusteringBypassed: " << (this->ClusteringBypassed ? "yes" : "no") << "\n";
  os << next << "MeanLightsPerCluster: " << this->MeanLightsPerCluster << "\n";
  os << next << "MeanLightsEvaluatedPerPixel: " << this->MeanLightsEvaluatedPerPixel << " (maximum "
     << this->MaximumLightsEvaluatedPerPixel << ", over " << this->NumberOfCountedPixels
     << " pixels; reaching " << this->MeanLightsReachingPerPixel << ")\n";
  os << next << "DepthPrepassReused: " << (this->DepthPrepassReused ? "yes" : "no")
     << ", kept: " << (this->DepthPrepassKept ? "yes" : "no")
     << (this->Internals->DepthReuseProblem.empty() ? "" : " (")
     << this->Internals->DepthReuseProblem
     << (this->Internals->DepthReuseProblem.empty() ? "" : ")") << "\n";
  os << next << "NumberOfBackfaceCulledProps: " << this->NumberOfBackfaceCulledProps << "\n";
  os << next << "DepthPrepassUsed: " << (this->DepthPrepassUsed ? "yes" : "no") << " ("
     << this->LastDepthPrepassTime << " ms)\n";
  os << next << "NumberOfDepthPrepassTrials: " << this->NumberOfDepthPrepassTrials
     << " (last ratio with / without " << this->DepthPrepassTrialRatio << ")\n";
  os << next << "DepthAwareClustersUsed: " << (this->DepthAwareClustersUsed ? "yes" : "no")
     << ", visible depths " << this->VisibleDepthRange[0] << " to " << this->VisibleDepthRange[1]
     << ", slices over " << this->SlicingRangeInUse[0] << " to " << this->SlicingRangeInUse[1]
     << ", non-empty clusters " << this->NonEmptyClusterFraction << "\n";
  os << next << "ShadedFragmentsPerVisiblePixel: " << this->GetShadedFragmentsPerVisiblePixel()
     << " (opaque " << this->ShadedOpaqueFragmentsPerVisiblePixel << ", translucent "
     << this->ShadedTranslucentFragmentsPerVisiblePixel << ")\n";
  os << next << "NearRadiusCap: " << this->NearRadiusCap << "\n";
  os << next << "FarFieldGridSpacing: " << this->FarFieldGridSpacing << "\n";
  os << next << "FarFieldResolutionInUse: " << this->FarFieldResolutionInUse
     << (this->FarFieldErrorBudgetMet ? "" : " (error budget not met)") << "\n";
}
