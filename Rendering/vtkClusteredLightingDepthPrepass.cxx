// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingDepthPrepass.h"

#include "vtkClusteredLightingBackfaceCulling.h"
#include "vtkClusteredLightingGLHelpers.h" // for vtkClusteredLightingHasShaderCode
#include "vtkClusteredLightingSampleDepths.h"
#include "vtkClusteredLightingSavedDepth.h"
#include "vtkClusteredLightingShaderCode.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkMapper2D.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkProp3DCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h" // for GL calls

#include <algorithm> // for std::max
#include <chrono>    // for the render time
#include <cmath>     // for std::abs
#include <cstdint>   // for std::uintptr_t
#include <cstring>   // for std::memcpy, std::strcmp
#include <limits>    // for std::numeric_limits
#include <vector>    // for std::vector

namespace
{
/// The recorded depth output as the shader cache writes it (AddDepthOutput).
const char* const RecordedOutput = "fragOutput1 = vec4(gl_FragCoord.z, -gl_FragCoord.z, 0.0, 1.0);";

/// Number of non-overlapping occurrences of `what` in `text`.
std::size_t Count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1))
  {
    ++n;
  }
  return n;
}

/// The viewport and scissor as vtkCameraPass sets them.
void GetViewport(const vtkRenderState* s, int origin[2], int size[2])
{
  origin[0] = origin[1] = size[0] = size[1] = 0;
  if (auto* fbo = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer()))
  {
    fbo->GetLastSize(size);
  }
  else
  {
    s->GetRenderer()->GetTiledSizeAndOrigin(size, size + 1, origin, origin + 1);
  }
}

/// Props whose opaque render writes no depth, so that nothing about them moves the
/// prepass's depths: VTK's 2D actors whose mapper draws in the overlay only
/// (vtkMapper2D::RenderOpaqueGeometry does nothing, and vtkOpenGLPolyDataMapper2D keeps
/// it; label mappers override it and are not listed), and text, scalar bars and corner
/// annotations, whose parts are such 2D actors.
bool DrawsNoOpaqueDepth(vtkProp* prop)
{
  const char* name = prop->GetClassName();
  if (std::strcmp(name, "vtkActor2D") == 0)
  {
    vtkMapper2D* mapper = static_cast<vtkActor2D*>(prop)->GetMapper();
    return !mapper || std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper2D") == 0;
  }
  for (const char* overlay :
    { "vtkTextActor", "vtkOpenGLTextActor", "vtkScalarBarActor", "vtkCornerAnnotation" })
  {
    if (std::strcmp(name, overlay) == 0)
    {
      return true;
    }
  }
  return false;
}

/// Calls f(actor) for a visible actor, or for each visible actor among a visible
/// assembly's parts (nested assemblies included).
template <typename F>
void ForEachVisibleActor(vtkProp* prop, F&& f)
{
  if (!prop || !prop->GetVisibility())
  {
    return;
  }
  if (auto* actor = vtkActor::SafeDownCast(prop))
  {
    f(actor);
  }
  else if (auto* assembly = vtkAssembly::SafeDownCast(prop))
  {
    vtkProp3DCollection* parts = assembly->GetParts();
    parts->InitTraversal();
    while (vtkProp3D* part = parts->GetNextProp3D())
    {
      ForEachVisibleActor(part, f);
    }
  }
}

/// Whether a visible prop (or an assembly's part) draws points as sprites
/// (vtkPointGaussianMapper's splats, which VTK does not light).
bool DrawsSprites(vtkProp* prop)
{
  bool sprites = false;
  ForEachVisibleActor(prop,
    [&](vtkActor* actor)
    { sprites = sprites || vtkPointGaussianMapper::SafeDownCast(actor->GetMapper()); });
  return sprites;
}

/// 64-bit FNV-1a over the values mixed in.
class SignatureHash
{
public:
  void Mix(std::uint64_t v)
  {
    for (int i = 0; i < 8; ++i)
    {
      this->Value ^= (v >> (8 * i)) & 0xFFu;
      this->Value *= 1099511628211ULL;
    }
  }
  void Mix(const void* p)
  {
    this->Mix(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p)));
  }
  void Mix(double d)
  {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, sizeof(bits));
    this->Mix(bits);
  }
  /// Never 0 (which means "no reuse").
  std::uint64_t Get() const { return this->Value == 0 ? 1 : this->Value; }

private:
  std::uint64_t Value = 1469598103934665603ULL;
};
}

vtkStandardNewMacro(vtkClusteredLightingDepthPrepass);

//------------------------------------------------------------------------------
void vtkClusteredLightingDepthPrepass::Render(const vtkRenderState* s)
{
  vtkRenderer* ren = s ? s->GetRenderer() : nullptr;
  auto* rw = ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  if (!rw)
  {
    vtkErrorMacro("The depth prepass needs an OpenGL render window.");
    return;
  }
  this->NumberOfRenderedProps = this->RenderDepth(s, rw, false);
}

//------------------------------------------------------------------------------
// The last frame's depths, when nothing they depend on changed (ComputeReuseSignature);
// what that frame noted about its programs and read back stays valid with them.
bool vtkClusteredLightingDepthPrepass::RestoreDepth(const vtkRenderState* s,
  vtkOpenGLRenderWindow* rw, bool finish, vtkClusteredLightingSavedDepth* saved,
  std::uint64_t reuse)
{
  this->Reused = false;
  if (!saved || reuse == 0 || reuse != this->SavedSignature)
  {
    return false;
  }
  if (finish)
  {
    glFinish();
  }
  const auto t0 = std::chrono::steady_clock::now();
  int size[2] = { 0, 0 };
  int origin[2] = { 0, 0 };
  GetViewport(s, origin, size);
  if (!saved->Restore(rw, origin, size))
  {
    return false;
  }
  this->FrameSignature = reuse;
  this->Reused = true;
  if (finish)
  {
    glFinish();
  }
  this->RenderTime =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return true;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingDepthPrepass::RenderDepth(const vtkRenderState* s,
  vtkOpenGLRenderWindow* rw, bool finish, vtkClusteredLightingSampleDepths* sampleDepths,
  vtkClusteredLightingSavedDepth* saved, std::uint64_t reuse)
{
  if (finish)
  {
    glFinish();
  }
  const auto t0 = std::chrono::steady_clock::now();
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLState* state = rw->GetState();

  // The viewport and scissor as vtkCameraPass sets them.
  int size[2] = { 0, 0 };
  int origin[2] = { 0, 0 };
  GetViewport(s, origin, size);
  this->Size[0] = size[0];
  this->Size[1] = size[1];
  this->Origin[0] = origin[0];
  this->Origin[1] = origin[1];
  this->FrameSignature = saved ? reuse : 0;
  this->Reused = false;
  this->MaxCoincidentOffset = 0.0;
  this->UnknownDepthWrites = false;
  this->UnrecordedDepths = false;
  this->Recorded = false;
  this->SampleProblem.clear();

  // vtkOpenGLState does not track the vertex array binding (the mappers' VAOs bind 0 when
  // they release): restore the application's.
  GLint vertexArray = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
  int rendered = 0;
  {
    vtkOpenGLState::ScopedglViewport savedViewport(state);
    vtkOpenGLState::ScopedglScissor savedScissor(state);
    vtkOpenGLState::ScopedglEnableDisable savedScissorTest(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglColorMask savedColorMask(state);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
    state->vtkglViewport(origin[0], origin[1], size[0], size[1]);
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglScissor(origin[0], origin[1], size[0], size[1]);
    state->vtkglDepthMask(GL_TRUE);
    if (rw->GetErase() && ren->GetErase() && !ren->GetPreserveDepthBuffer())
    {
      state->vtkglClearDepth(1.0);
      state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    }
    state->vtkglEnable(GL_DEPTH_TEST);
    // A multisampled framebuffer: the fragments' depths are recorded (with depth-aware
    // clusters), in the recording framebuffer with GL_MAX blending.
    this->Multisampled = vtkClusteredLightingSampleDepths::IsDrawFramebufferMultisampled();
    const bool record = sampleDepths && this->Multisampled && sampleDepths->Begin(rw, origin, size);
    if (sampleDepths && this->Multisampled && !record)
    {
      this->SampleProblem = sampleDepths->GetProblem();
    }
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    int blendEquation[2] = { GL_FUNC_ADD, GL_FUNC_ADD };
    if (record)
    {
      state->vtkglGetIntegerv(GL_BLEND_EQUATION_RGB, blendEquation);
      state->vtkglGetIntegerv(GL_BLEND_EQUATION_ALPHA, blendEquation + 1);
      state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendEquation(GL_MAX);
    }
    else
    {
      state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    }

    // The props carry this pass in their keys: the mappers build VTK's own program.
    this->PreRender(s);
    for (int i = 0; i < s->GetPropArrayCount(); ++i)
    {
      // Sprites (DrawsSprites) stay out: drawn here, vtkPointGaussianMapper's splats
      // changed the shading render (TestClusteredLightingDepthAware: 242 steps off at 53%
      // of the pixels). Unlit, drawn once against the others' depths, they are right.
      vtkProp* prop = s->GetPropArray()[i];
      if (prop->GetVisibility() && !DrawsSprites(prop))
      {
        rendered += prop->RenderOpaqueGeometry(ren);
        if (this->BackfaceCulling)
        {
          this->BackfaceCulling->EndProp();
        }
      }
    }
    this->PostRender(s);
    if (record)
    {
      int equation[2] = { 0, 0 };
      state->vtkglGetIntegerv(GL_BLEND_EQUATION_RGB, equation);
      state->vtkglGetIntegerv(GL_BLEND_EQUATION_ALPHA, equation + 1);
      // Something that changed the blending meanwhile makes the record unusable.
      const bool blended = glIsEnabled(GL_BLEND) && equation[0] == GL_MAX && equation[1] == GL_MAX;
      state->vtkglBlendEquationSeparate(
        static_cast<unsigned int>(blendEquation[0]), static_cast<unsigned int>(blendEquation[1]));
      this->Recorded = sampleDepths->End(rw, this->Depth, this->DepthMax) && blended;
      if (!this->Recorded)
      {
        this->SampleProblem = blended ? sampleDepths->GetProblem()
                                      : "a mapper changed the blending of the depth prepass";
      }
    }
  }
  glBindVertexArray(static_cast<GLuint>(vertexArray));
  // Kept for the next frames with the same signature.
  this->SavedSignature = 0;
  if (this->FrameSignature != 0 && saved->Save(rw, origin, size))
  {
    this->SavedSignature = this->FrameSignature;
  }
  if (finish)
  {
    glFinish();
  }
  this->RenderTime =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return rendered;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingDepthPrepass::ReadDepth(vtkOpenGLRenderWindow* rw)
{
  const auto t0 = std::chrono::steady_clock::now();
  this->Problem.clear();
  if (this->Reused && this->DepthSignature != 0 && this->DepthSignature == this->SavedSignature)
  {
    return true; // the depths read with the saved ones
  }
  this->DepthSignature = 0;
  if (this->Recorded)
  {
    // Recorded by RenderDepth (a multisampled framebuffer).
    if (this->UnrecordedDepths)
    {
      this->Problem = "the framebuffer is multisampled and a mapper's program does not record "
                      "its fragments' depths";
      this->Depth.clear();
      this->DepthMax.clear();
      return false;
    }
    this->DepthSignature = this->FrameSignature;
    return true;
  }
  this->Depth.clear();
  this->DepthMax.clear();
  vtkOpenGLState* state = rw->GetState();
  if (this->Multisampled)
  {
    this->Problem = "the framebuffer is multisampled and " +
      (this->SampleProblem.empty() ? std::string("its sample depths were not recorded")
                                   : this->SampleProblem);
    return false;
  }
  if (this->Size[0] < 1 || this->Size[1] < 1)
  {
    this->Problem = "the viewport is empty";
    return false;
  }
  while (glGetError() != GL_NO_ERROR)
  {
  }
  unsigned int drawBinding = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(drawBinding, drawBuffer);
  this->Depth.resize(static_cast<std::size_t>(this->Size[0]) * this->Size[1]);
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  // A packed depth-stencil read is a plain copy for the usual D24S8 buffer (a float read
  // converts every pixel in the driver, several times slower on llvmpipe); the float read
  // is the fallback for buffers without stencil.
  bool ok = false;
  {
    std::vector<unsigned int>& packed = this->Packed; // kept between frames
    packed.resize(this->Depth.size());
    glReadPixels(this->Origin[0], this->Origin[1], this->Size[0], this->Size[1], GL_DEPTH_STENCIL,
      GL_UNSIGNED_INT_24_8, packed.data());
    ok = glGetError() == GL_NO_ERROR;
    if (ok)
    {
      const float scale = 1.0f / 16777215.0f;
      for (std::size_t p = 0; p < packed.size(); ++p)
      {
        const unsigned int z = packed[p] >> 8;
        this->Depth[p] = z == 0xFFFFFFu ? 1.0f : static_cast<float>(z) * scale;
      }
    }
  }
  if (!ok)
  {
    glReadPixels(this->Origin[0], this->Origin[1], this->Size[0], this->Size[1], GL_DEPTH_COMPONENT,
      GL_FLOAT, this->Depth.data());
    ok = glGetError() == GL_NO_ERROR;
  }
  state->PopReadFramebufferBinding();
  if (!ok)
  {
    this->Problem = "reading the depth buffer failed";
    this->Depth.clear();
  }
  else
  {
    this->DepthSignature = this->FrameSignature;
  }
  this->RenderTime +=
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return ok;
}

//------------------------------------------------------------------------------
namespace
{
/// Whether polydata has line or vertex cells (drawn as lines and points whatever the
/// representation).
bool HasLinesOrVerts(vtkDataObject* data)
{
  auto* poly = vtkPolyData::SafeDownCast(data);
  return poly && (poly->GetNumberOfLines() > 0 || poly->GetNumberOfVerts() > 0);
}

/// Whether a mapper may draw lines or points: its polydata (or a composite's leaves)
/// has line or vertex cells; true for a mapper of another kind, which may draw anything.
bool MayDrawLinesOrPoints(vtkMapper* mapper)
{
  if (!mapper)
  {
    return false;
  }
  const bool known = std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper") == 0 ||
    std::strcmp(mapper->GetClassName(), "vtkCompositePolyDataMapper2") == 0;
  if (!known)
  {
    return true;
  }
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> leaves;
    leaves.TakeReference(composite->NewIterator());
    for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
    {
      if (HasLinesOrVerts(leaves->GetCurrentDataObject()))
      {
        return true;
      }
    }
    return false;
  }
  return HasLinesOrVerts(input);
}

/// The widest line or point a visible prop (or an assembly's parts) may draw: its
/// vtkProperty's LineWidth or PointSize where it draws lines or points (another
/// representation than surface, edges, vertices, or line and vertex cells), 0 where it
/// draws none.
double WidestLineOrPoint(vtkProp* prop)
{
  double widest = 0.0;
  ForEachVisibleActor(prop,
    [&](vtkActor* actor)
    {
      vtkProperty* property = actor->GetProperty();
      if (property->GetRepresentation() != VTK_SURFACE || property->GetEdgeVisibility() ||
        property->GetVertexVisibility() || MayDrawLinesOrPoints(actor->GetMapper()))
      {
        widest = std::max({ widest, 1.0, static_cast<double>(property->GetLineWidth()),
          static_cast<double>(property->GetPointSize()) });
      }
    });
  return widest;
}
}

namespace
{
/// Whether the fragments of a translucent prop lie inside its mapper's bounds under its
/// matrix, and that box in world coordinates. ParaView's vtkPVLODActor draws through an
/// internal vtkOpenGLActor to which each render copies its matrix and shader property,
/// with the mapper its GetMapper() returns (the full or the level-of-detail one, chosen
/// per render): that mapper's bounds under its matrix hold what it draws.
bool GetTranslucentBox(vtkProp* prop, double box[6])
{
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (!mapper ||
    (std::strcmp(actor->GetClassName(), "vtkOpenGLActor") != 0 &&
      std::strcmp(actor->GetClassName(), "vtkPVLODActor") != 0) ||
    (std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper") != 0 &&
      std::strcmp(mapper->GetClassName(), "vtkCompositePolyDataMapper2") != 0))
  {
    return false;
  }
  // Shader code or replacements may move a fragment's position anywhere (VTK's impostor
  // mappers set it in the fragment shader).
  if (vtkClusteredLightingHasShaderCode(actor))
  {
    return false;
  }
  const double* b = mapper->GetBounds();
  if (!b || !(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
  {
    return false;
  }
  // The actor's matrix as it is now, corner by corner.
  vtkMatrix4x4* m = actor->GetMatrix();
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] = std::numeric_limits<double>::max();
    box[2 * a + 1] = -std::numeric_limits<double>::max();
  }
  for (int i = 0; i < 8; ++i)
  {
    const double in[4] = { b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + (i >> 2)], 1.0 };
    double out[4];
    m->MultiplyPoint(in, out);
    if (!(out[3] > 0.0))
    {
      return false;
    }
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], out[a] / out[3]);
      box[2 * a + 1] = std::max(box[2 * a + 1], out[a] / out[3]);
    }
  }
  return true;
}
}

void vtkClusteredLightingDepthPrepass::ComputeTranslucentRects(const vtkRenderState* s,
  const glm::dmat4& wcvc, const glm::dmat4& vcdc, bool& translucent, std::vector<glm::dvec4>& rects,
  std::vector<glm::dvec2>& depths)
{
  translucent = false;
  rects.clear();
  depths.clear();
  bool bounded = true;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!prop->GetVisibility() || !prop->HasTranslucentPolygonalGeometry())
    {
      continue;
    }
    translucent = true;
    double box[6];
    glm::dvec4 rect;
    glm::dvec2 depth;
    if (bounded && GetTranslucentBox(prop, box))
    {
      // A box reaching behind the camera covers the whole viewport (the rectangle
      // ProjectBoxToViewport leaves then), still within its depths.
      vtkClusteredLighting::ProjectBoxToViewport(box, wcvc, vcdc, rect, &depth);
      rects.push_back(rect);
      depths.push_back(depth);
    }
    else
    {
      bounded = false;
    }
  }
  if (!bounded)
  {
    rects.clear();
    depths.clear();
  }
}

double vtkClusteredLightingDepthPrepass::ComputePixelSlack(const vtkRenderState* s)
{
  double widest = 0.0;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    widest = std::max(widest, WidestLineOrPoint(s->GetPropArray()[i]));
  }
  return widest > 0.0 ? 0.5 * widest + 1.0 : 0.0;
}

//------------------------------------------------------------------------------
// Everything the prepass's depths depend on, hashed: where it draws (renderer, window,
// framebuffer, samples, viewport), the camera's matrices, VTK's global coincident-topology
// settings, and every visible prop with its mapper, clipping planes and input. Props are
// accepted only where these modification times cover everything that moves their depths.
std::uint64_t vtkClusteredLightingDepthPrepass::ComputeReuseSignature(const vtkRenderState* s,
  vtkOpenGLRenderWindow* rw, bool record, std::string* why,
  vtkClusteredLightingBackfaceCulling* culling)
{
  auto refuse = [why](const std::string& reason)
  {
    if (why)
    {
      *why = reason;
    }
    return std::uint64_t(0);
  };
  vtkRenderer* ren = s->GetRenderer();
  if (!(rw->GetErase() && ren->GetErase() && !ren->GetPreserveDepthBuffer()))
  {
    return refuse("the prepass draws on depths it does not clear");
  }
  SignatureHash h;
  h.Mix(ren);
  h.Mix(rw);
  h.Mix(s->GetFrameBuffer());
  unsigned int binding = 0, buffer = 0;
  rw->GetState()->GetCurrentDrawFramebufferState(binding, buffer);
  h.Mix(static_cast<std::uint64_t>(binding));
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  h.Mix(static_cast<std::uint64_t>(samples));
  h.Mix(static_cast<std::uint64_t>(record ? 1 : 0));
  int origin[2], size[2];
  GetViewport(s, origin, size);
  for (int v : { origin[0], origin[1], size[0], size[1] })
  {
    h.Mix(static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)));
  }
  // The camera: its matrices (the aspect, eye and tile included), which hold all of it
  // that moves depths. Not its time: ParaView's synchronized renderers set every rank's
  // camera (and reset its clipping range) before each render, which modifies it with the
  // same values, and vtkOpenGLCamera recomputes the same matrices from them.
  vtkCamera* camera = ren->GetActiveCamera();
  h.Mix(camera);
  h.Mix(static_cast<std::uint64_t>(camera->GetLeftEye()));
  h.Mix(static_cast<std::uint64_t>(rw->GetStereoRender()));
  const double* tile = rw->GetTileViewport();
  for (int i = 0; i < 4; ++i)
  {
    h.Mix(tile[i]);
  }
  const double aspect = ren->GetTiledAspectRatio();
  h.Mix(aspect);
  vtkMatrix4x4* projection = camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  for (int i = 0; i < 16; ++i)
  {
    h.Mix(projection->GetElement(i / 4, i % 4));
  }
  // VTK's global coincident-topology settings (no modification time).
  h.Mix(static_cast<std::uint64_t>(vtkMapper::GetResolveCoincidentTopology()));
  double factor = 0.0, units = 0.0;
  vtkMapper::GetResolveCoincidentTopologyPolygonOffsetParameters(factor, units);
  h.Mix(factor);
  h.Mix(units);
  vtkMapper::GetResolveCoincidentTopologyLineOffsetParameters(factor, units);
  h.Mix(factor);
  h.Mix(units);
  vtkMapper::GetResolveCoincidentTopologyPointOffsetParameter(units);
  h.Mix(units);
  h.Mix(vtkMapper::GetResolveCoincidentTopologyZShift());

  h.Mix(static_cast<std::uint64_t>(s->GetPropArrayCount()));
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    h.Mix(prop);
    h.Mix(static_cast<std::uint64_t>(prop->GetVisibility()));
    if (!prop->GetVisibility())
    {
      continue;
    }
    if (DrawsNoOpaqueDepth(prop))
    {
      continue;
    }
    // ParaView's vtkPVLODActor draws through an internal actor to which each render copies
    // its property, textures, shader property, matrix and keys, with the mapper its
    // GetMapper() returns (the full or the level-of-detail one): its depths are those of
    // a vtkOpenGLActor with its own state, and the chosen mapper is hashed below. Its
    // vtkPVCenterAxesActor is a vtkOpenGLActor that overrides no rendering (a vtkAxes
    // source through a vtkPolyDataMapper).
    auto* actor = vtkActor::SafeDownCast(prop);
    const char* actorClass = prop->GetClassName();
    if (!actor ||
      (std::strcmp(actorClass, "vtkOpenGLActor") != 0 &&
        std::strcmp(actorClass, "vtkPVLODActor") != 0 &&
        std::strcmp(actorClass, "vtkPVCenterAxesActor") != 0))
    {
      return refuse(std::string("a ") + actorClass + " is drawn");
    }
    vtkMapper* mapper = actor->GetMapper();
    h.Mix(mapper);
    if (!mapper)
    {
      continue; // draws nothing
    }
    auto* polyMapper = vtkPolyDataMapper::SafeDownCast(mapper);
    auto* compositeMapper = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
    if (!polyMapper ||
      (std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper") != 0 &&
        std::strcmp(mapper->GetClassName(), "vtkCompositePolyDataMapper2") != 0))
    {
      return refuse(std::string("a ") + mapper->GetClassName() + " draws");
    }
    if (polyMapper->GetNumberOfSubPieces() != 1)
    {
      return refuse("a mapper draws several pieces");
    }
    if (polyMapper->HasObserver(vtkCommand::UpdateShaderEvent))
    {
      return refuse("a mapper has an UpdateShaderEvent observer");
    }
    if (vtkClusteredLightingHasShaderCode(actor))
    {
      return refuse("an actor has shader replacements");
    }
    // The actor's time covers its transform, property, backface property and texture;
    // the mapper's its own settings and its clipping planes' collection, not the planes.
    // At an actor's first render under a pass, vtkOpenGLRenderPass::PreRender gives it
    // information keys and vtkActor makes its property (GetProperty): both change its
    // time after this frame's signature, and the next frame would draw again. Make
    // them now, as that render will.
    if (!actor->GetPropertyKeys())
    {
      vtkNew<vtkInformation> keys;
      actor->SetPropertyKeys(keys);
    }
    actor->GetProperty();
    h.Mix(static_cast<std::uint64_t>(actor->GetMTime()));
    h.Mix(static_cast<std::uint64_t>(mapper->GetMTime()));
    if (vtkPlaneCollection* planes = mapper->GetClippingPlanes())
    {
      for (int k = 0; k < planes->GetNumberOfItems(); ++k)
      {
        vtkPlane* plane = planes->GetItem(k);
        h.Mix(static_cast<std::uint64_t>(plane ? plane->GetMTime() : 0));
      }
    }
    // Its input brought up to date as the renderer does for the clipping range (the
    // mapper's own piece; a static mapper promises its input does not change).
    if (!polyMapper->GetStatic())
    {
      polyMapper->GetBounds();
    }
    vtkDataObject* input = polyMapper->GetInputDataObject(0, 0);
    h.Mix(input);
    h.Mix(static_cast<std::uint64_t>(input ? input->GetMTime() : 0));
    // The face its draws cull (decided now, its input up to date).
    h.Mix(static_cast<std::uint64_t>(culling ? culling->GetFace(prop) + 2 : 0));
    if (compositeMapper)
    {
      // A composite mapper's time covers its blocks' display attributes (visibility,
      // opacity: whether a block is opaque); it rebuilds a block's buffers from that
      // block's own time, which a change in place leaves off the data set's.
      if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
      {
        vtkSmartPointer<vtkCompositeDataIterator> leaves;
        leaves.TakeReference(composite->NewIterator());
        for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
        {
          vtkDataObject* leaf = leaves->GetCurrentDataObject();
          h.Mix(static_cast<std::uint64_t>(leaves->GetCurrentFlatIndex()));
          h.Mix(leaf);
          h.Mix(static_cast<std::uint64_t>(leaf ? leaf->GetMTime() : 0));
        }
      }
    }
  }
  return h.Get();
}

//------------------------------------------------------------------------------
vtkClusteredLighting::DepthImage vtkClusteredLightingDepthPrepass::GetImage() const
{
  vtkClusteredLighting::DepthImage image;
  if (!this->Depth.empty())
  {
    image.Depth = this->Depth.data();
    image.Width = this->Size[0];
    image.Height = this->Size[1];
    image.DepthMax = this->DepthMax.size() == this->Depth.size() ? this->DepthMax.data() : nullptr;
  }
  return image;
}

//------------------------------------------------------------------------------
vtkClusteredLightingDepthPrepass::ProgramFacts vtkClusteredLightingDepthPrepass::ReadProgramFacts(
  const std::string& fs)
{
  ProgramFacts facts;
  facts.Records = fs.find(RecordedOutput) != std::string::npos;
  facts.Writes = Count(fs, "gl_FragDepth =");
  // VTK's coincident-topology offset (vtkOpenGLPolyDataMapper::ReplaceShaderCoincidentOffset):
  // 9.1 adds cOffset / 65000; 9.2 also adds cFactor times the depth slope, which no fixed
  // margin bounds, so only cFactor = 0 is accepted there.
  const std::size_t offsets91 = Count(fs, "gl_FragDepth = gl_FragCoord.z + 1.0*cOffset/65000;");
  const std::size_t offsets92 =
    Count(fs, "gl_FragDepth = gl_FragCoord.z + cFactor*cscale + 1.0*cOffset/65000;");
  facts.KnownOffsets = offsets91 + offsets92 == facts.Writes;
  facts.SlopeFactor = offsets92 > 0;
  return facts;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingDepthPrepass::NoteProgram(vtkShaderProgram* program)
{
  if (!program || !program->GetFragmentShader())
  {
    return;
  }
  const std::string hash = program->GetMD5Hash();
  auto it = hash.empty() ? this->Facts.end() : this->Facts.find(hash);
  const ProgramFacts facts = it != this->Facts.end()
    ? it->second
    : ReadProgramFacts(program->GetFragmentShader()->GetSource());
  if (!hash.empty() && it == this->Facts.end())
  {
    this->Facts.emplace(hash, facts);
  }
  if (!facts.Records)
  {
    this->UnrecordedDepths = true;
  }
  if (facts.Writes == 0)
  {
    return;
  }
  // The offsets' values are uniforms, set per draw.
  const GLuint handle = static_cast<GLuint>(program->GetHandle());
  auto uniform = [handle](const char* name)
  {
    GLfloat value = 0.0f;
    const GLint location = glGetUniformLocation(handle, name);
    if (location >= 0)
    {
      glGetUniformfv(handle, location, &value);
    }
    return static_cast<double>(value);
  };
  if (!facts.KnownOffsets || (facts.SlopeFactor && uniform("cFactor") != 0.0))
  {
    this->UnknownDepthWrites = true;
    return;
  }
  this->MaxCoincidentOffset = std::max(this->MaxCoincidentOffset, std::abs(uniform("cOffset")));
}

//------------------------------------------------------------------------------
void vtkClusteredLightingDepthPrepass::AddInvariantPosition(std::string& vertexShader)
{
  const std::string line = "invariant gl_Position;\n";
  if (vertexShader.find("\n" + line) == std::string::npos)
  {
    vtkClusteredLighting::InsertDeclarations(vertexShader, line);
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingDepthPrepass::AddDepthOutput(std::string& fragmentShader)
{
  // VTK's shader cache turns gl_FragData[i] into the output fragOutputi at location i.
  if (fragmentShader.find("gl_FragData[0]") == std::string::npos ||
    fragmentShader.find("gl_FragData[1]") != std::string::npos)
  {
    return;
  }
  const std::size_t mainAt = fragmentShader.find("void main()");
  const std::size_t open =
    mainAt == std::string::npos ? std::string::npos : fragmentShader.find('{', mainAt);
  if (open != std::string::npos)
  {
    fragmentShader.insert(open + 1,
      "\n  // the pixel-centre depth, for vtkClusteredLightingSampleDepths\n"
      "  gl_FragData[1] = vec4(gl_FragCoord.z, -gl_FragCoord.z, 0.0, 1.0);\n");
  }
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingDepthPrepass::PostReplaceShaderValues(std::string& vertexShader,
  std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  AddInvariantPosition(vertexShader);
  AddDepthOutput(fragmentShader);
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingDepthPrepass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  this->NoteProgram(program);
  if (this->BackfaceCulling)
  {
    this->BackfaceCulling->Apply(prop);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingDepthPrepass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "MaximumCoincidentOffset: " << this->MaxCoincidentOffset << "\n";
  os << indent << "UnknownDepthWrites: " << (this->UnknownDepthWrites ? "yes" : "no") << "\n";
  os << indent << "SampleDepthsRecorded: " << (this->Recorded ? "yes" : "no")
     << (this->SampleProblem.empty() ? "" : " (") << this->SampleProblem
     << (this->SampleProblem.empty() ? "" : ")") << "\n";
  os << indent << "RenderTime: " << this->RenderTime << " ms\n";
  os << indent << "Reused: " << (this->Reused ? "yes" : "no") << "\n";
}
