// SPDX-License-Identifier: BSD-3-Clause
// GL state around vtkClusteredLightingPass. A probe pass records the GL state (asked of GL
// itself) at three points of each frame: before the pass, when the pass hands over to its
// delegate (that is, right after the list/master assignment passes and the binding of
// the shading textures), and after the pass. Checks, over frames that reassign lights,
// reuse the assignment, run brute force, a debug view, and no lights at all, that
//  - the assignment leaves every piece of state as it found it: logic op (off, GL_COPY),
//    blend (enable, functions, equations), depth test / function / mask, scissor test and
//    box, face culling, stencil test, colour mask, viewport, draw / read framebuffers and
//    buffers, vertex array binding; the only changes are the shading textures bound on
//    texture units reserved from VTK's texture unit manager (and the current program,
//    which VTK's shader cache binds and tracks);
//  - after the pass the texture unit manager has exactly the units it had before (no unit
//    leaks), and the state is what it is right after the delegate rendered;
//  - vtkOpenGLState's cached state agrees with GL at every point (nothing was changed
//    behind VTK's back), and the current program is the one VTK's shader cache thinks;
//  - an unrelated prop rendered after the pass (a second renderer on top) gives exactly
//    the pixels it gives when rendered alone.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingScenes.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderPass.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureUnitManager.h"

#include <cstdio>
#include <map>
#include <set>
#include <string>

using ClusteredLightingTest::Check;
using ClusteredLightingTest::CheckSameGLObjects;

namespace
{
/// GL state as GL reports it, by name, plus what vtkOpenGLState caches (to compare).
struct GLStateSnapshot
{
  std::map<std::string, long long> GL;
  std::map<std::string, long long> Cache;
  int AllocatedUnits = 0;
  bool ProgramMatchesCache = true;
};

GLStateSnapshot TakeSnapshot(vtkOpenGLRenderWindow* rw)
{
  GLStateSnapshot s;
  auto enabled = [&](const char* name, GLenum cap) { s.GL[name] = glIsEnabled(cap) ? 1 : 0; };
  auto integers = [&](const char* name, GLenum pname, int n)
  {
    GLint v[4] = { 0, 0, 0, 0 };
    glGetIntegerv(pname, v);
    for (int i = 0; i < n; ++i)
    {
      s.GL[std::string(name) + (n > 1 ? "[" + std::to_string(i) + "]" : "")] = v[i];
    }
  };
  enabled("GL_COLOR_LOGIC_OP", GL_COLOR_LOGIC_OP);
  integers("GL_LOGIC_OP_MODE", GL_LOGIC_OP_MODE, 1);
  enabled("GL_BLEND", GL_BLEND);
  integers("GL_BLEND_SRC_RGB", GL_BLEND_SRC_RGB, 1);
  integers("GL_BLEND_DST_RGB", GL_BLEND_DST_RGB, 1);
  integers("GL_BLEND_SRC_ALPHA", GL_BLEND_SRC_ALPHA, 1);
  integers("GL_BLEND_DST_ALPHA", GL_BLEND_DST_ALPHA, 1);
  integers("GL_BLEND_EQUATION_RGB", GL_BLEND_EQUATION_RGB, 1);
  integers("GL_BLEND_EQUATION_ALPHA", GL_BLEND_EQUATION_ALPHA, 1);
  enabled("GL_DEPTH_TEST", GL_DEPTH_TEST);
  integers("GL_DEPTH_FUNC", GL_DEPTH_FUNC, 1);
  integers("GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1);
  enabled("GL_SCISSOR_TEST", GL_SCISSOR_TEST);
  integers("GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
  enabled("GL_CULL_FACE", GL_CULL_FACE);
  integers("GL_CULL_FACE_MODE", GL_CULL_FACE_MODE, 1);
  enabled("GL_STENCIL_TEST", GL_STENCIL_TEST);
  enabled("GL_POLYGON_OFFSET_FILL", GL_POLYGON_OFFSET_FILL);
  integers("GL_COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4);
  integers("GL_VIEWPORT", GL_VIEWPORT, 4);
  integers("GL_DRAW_FRAMEBUFFER_BINDING", GL_DRAW_FRAMEBUFFER_BINDING, 1);
  integers("GL_READ_FRAMEBUFFER_BINDING", GL_READ_FRAMEBUFFER_BINDING, 1);
  integers("GL_DRAW_BUFFER", GL_DRAW_BUFFER, 1);
  integers("GL_READ_BUFFER", GL_READ_BUFFER, 1);
  integers("GL_ACTIVE_TEXTURE", GL_ACTIVE_TEXTURE, 1);
  integers("GL_VERTEX_ARRAY_BINDING", GL_VERTEX_ARRAY_BINDING, 1);
  integers("GL_CURRENT_PROGRAM", GL_CURRENT_PROGRAM, 1);

  vtkOpenGLState* state = rw->GetState();
  s.Cache["GL_BLEND"] = state->GetEnumState(GL_BLEND) ? 1 : 0;
  s.Cache["GL_DEPTH_TEST"] = state->GetEnumState(GL_DEPTH_TEST) ? 1 : 0;
  s.Cache["GL_SCISSOR_TEST"] = state->GetEnumState(GL_SCISSOR_TEST) ? 1 : 0;
  s.Cache["GL_CULL_FACE"] = state->GetEnumState(GL_CULL_FACE) ? 1 : 0;
  s.Cache["GL_STENCIL_TEST"] = state->GetEnumState(GL_STENCIL_TEST) ? 1 : 0;
  int v[4];
  for (GLenum pname : { GL_VIEWPORT, GL_SCISSOR_BOX })
  {
    state->vtkglGetIntegerv(pname, v);
    const std::string name = pname == GL_VIEWPORT ? "GL_VIEWPORT" : "GL_SCISSOR_BOX";
    for (int i = 0; i < 4; ++i)
    {
      s.Cache[name + "[" + std::to_string(i) + "]"] = v[i];
    }
  }
  int blend[4];
  state->GetBlendFuncState(blend);
  s.Cache["GL_BLEND_SRC_RGB"] = blend[0];
  s.Cache["GL_BLEND_DST_RGB"] = blend[1];
  s.Cache["GL_BLEND_SRC_ALPHA"] = blend[2];
  s.Cache["GL_BLEND_DST_ALPHA"] = blend[3];
  state->vtkglGetIntegerv(GL_DEPTH_FUNC, v);
  s.Cache["GL_DEPTH_FUNC"] = v[0];
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, v);
  s.Cache["GL_CULL_FACE_MODE"] = v[0];
  unsigned char mask[4];
  state->vtkglGetBooleanv(GL_COLOR_WRITEMASK, mask);
  for (int i = 0; i < 4; ++i)
  {
    s.Cache["GL_COLOR_WRITEMASK[" + std::to_string(i) + "]"] = mask[i];
  }
  state->vtkglGetBooleanv(GL_DEPTH_WRITEMASK, mask);
  s.Cache["GL_DEPTH_WRITEMASK"] = mask[0];

  vtkTextureUnitManager* units = state->GetTextureUnitManager();
  for (int u = 0; u < units->GetNumberOfTextureUnits(); ++u)
  {
    s.AllocatedUnits += units->IsAllocated(u) ? 1 : 0;
  }
  vtkShaderProgram* last = rw->GetShaderCache()->GetLastShaderBound();
  s.ProgramMatchesCache =
    s.GL["GL_CURRENT_PROGRAM"] == (last ? static_cast<long long>(last->GetHandle()) : 0LL);
  return s;
}

/// Names whose values differ between a and b (keys of a), except those in `ignore`.
std::string Differences(const std::map<std::string, long long>& a,
  const std::map<std::string, long long>& b, const std::set<std::string>& ignore = {})
{
  std::string out;
  for (const auto& kv : a)
  {
    auto it = b.find(kv.first);
    if (!ignore.count(kv.first) && it != b.end() && it->second != kv.second)
    {
      out += " " + kv.first + " " + std::to_string(kv.second) + " -> " + std::to_string(it->second);
    }
  }
  return out;
}

/// Render pass that snapshots the GL state before and after its delegate renders.
class ProbePass : public vtkRenderPass
{
public:
  static ProbePass* New();
  vtkTypeMacro(ProbePass, vtkRenderPass)
  void Render(const vtkRenderState* s) override
  {
    vtkOpenGLRenderWindow* rw =
      vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
    if (this->ApplicationState)
    {
      // State an application may have set that VTK neither sets nor tracks.
      if (!this->ApplicationVAO)
      {
        glGenVertexArrays(1, &this->ApplicationVAO);
      }
      glEnable(GL_COLOR_LOGIC_OP);
      glLogicOp(GL_COPY);
      glBindVertexArray(this->ApplicationVAO);
    }
    this->Before = TakeSnapshot(rw);
    this->Delegate->Render(s);
    this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
    this->After = TakeSnapshot(rw);
    ++this->Frames;
    if (this->ApplicationState)
    {
      glDisable(GL_COLOR_LOGIC_OP);
      glBindVertexArray(0);
    }
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    this->Delegate->ReleaseGraphicsResources(w);
  }
  vtkSmartPointer<vtkRenderPass> Delegate;
  GLStateSnapshot Before, After;
  int Frames = 0;
  bool ApplicationState = false;
  GLuint ApplicationVAO = 0;

protected:
  ProbePass() = default;
  ~ProbePass() override = default;

private:
  ProbePass(const ProbePass&) = delete;
  void operator=(const ProbePass&) = delete;
};
vtkStandardNewMacro(ProbePass);

void ExpectCacheMatchesGL(const GLStateSnapshot& s, const std::string& where)
{
  const std::string diff = Differences(s.Cache, s.GL);
  Check(diff.empty() && s.ProgramMatchesCache,
    where + ": vtkOpenGLState and the shader cache agree with GL" + diff +
      (s.ProgramMatchesCache ? "" : " (current program)"));
}
}

int TestClusteredLightingGLState(int, char*[])
{
  using namespace ClusteredLightingTest;
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetNumberOfLayers(2);
  vtkNew<vtkRenderer> ren;
  SetUpTestScene(renWin, ren, 160, 120);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(180.0);
  light->SetPosition(0.0, 1.0, 2.0);
  light->SetAttenuationValues(1.0, 0.0, 2.0);
  ren->AddLight(light);
  vtkNew<vtkClusteredLightSet> lights;
  MakeTestLights(lights, 300, 0.9, 3);

  // The overlay: an unlit cube in a renderer of layer 1, drawn after the pass.
  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->SetViewport(0.3, 0.2, 0.8, 0.9);
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkPolyDataMapper> cubeMapper;
  cubeMapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> box;
  box->SetMapper(cubeMapper);
  box->GetProperty()->SetColor(0.2, 0.6, 0.9);
  box->GetProperty()->SetAmbient(0.6);
  box->GetProperty()->SetDiffuse(0.4);
  box->RotateX(30);
  box->RotateY(40);
  overlay->AddActor(box);
  renWin->AddRenderer(overlay);

  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  vtkNew<MessageCollector> messages;
  messages->Watch(pass);
  vtkNew<ProbePass> outer, inner;
  inner->Delegate = pass->GetDelegatePass();
  pass->SetDelegatePass(inner);
  outer->Delegate = pass.GetPointer();
  ren->SetPass(outer);

  struct Frame
  {
    const char* Name;
    int Shading;
    int Debug;
    bool MoveCamera;
    bool Lights;
    bool ApplicationState;
  };
  const Frame frames[] = {
    { "first frame (assignment)", vtkClusteredLightingPass::SHADING_CLUSTERED,
      vtkClusteredLightingPass::DEBUG_NONE, false, true, false },
    { "camera moved (assignment)", vtkClusteredLightingPass::SHADING_CLUSTERED,
      vtkClusteredLightingPass::DEBUG_NONE, true, true, false },
    { "nothing changed (no assignment)", vtkClusteredLightingPass::SHADING_CLUSTERED,
      vtkClusteredLightingPass::DEBUG_NONE, false, true, false },
    { "brute force", vtkClusteredLightingPass::SHADING_BRUTE_FORCE,
      vtkClusteredLightingPass::DEBUG_NONE, true, true, false },
    { "heat map", vtkClusteredLightingPass::SHADING_CLUSTERED,
      vtkClusteredLightingPass::DEBUG_HEAT_MAP, true, true, false },
    { "no clustered lights", vtkClusteredLightingPass::SHADING_CLUSTERED,
      vtkClusteredLightingPass::DEBUG_NONE, true, false, false },
    { "application's logic op and VAO (assignment)", vtkClusteredLightingPass::SHADING_CLUSTERED,
      vtkClusteredLightingPass::DEBUG_NONE, true, true, true },
  };

  for (const Frame& f : frames)
  {
    pass->SetShadingMode(f.Shading);
    pass->SetDebugView(f.Debug);
    lights->SetEnabled(f.Lights);
    outer->ApplicationState = f.ApplicationState;
    light->SetSwitch(f.Lights);
    if (f.MoveCamera)
    {
      ren->GetActiveCamera()->Azimuth(7.0);
      ren->ResetCameraClippingRange();
    }
    renWin->Render();
    const std::string name = f.Name;
    std::printf("%s: %d clustered lights, assignment %s\n", f.Name,
      pass->GetNumberOfClusteredLights(), pass->GetLastAssignmentUpdated() ? "updated" : "reused");

    // Before the pass -> start of the delegate: only the shading textures (on reserved
    // units, with GL_ACTIVE_TEXTURE following the last one bound) and the program.
    const bool shading = f.Lights;
    const std::string assignment = Differences(
      outer->Before.GL, inner->Before.GL, { "GL_ACTIVE_TEXTURE", "GL_CURRENT_PROGRAM" });
    Check(assignment.empty(),
      name + ": the assignment and texture binding change no other state" + assignment);
    const int reserved = inner->Before.AllocatedUnits - outer->Before.AllocatedUnits;
    // Clustered shading: lights, light view, master, list; and the far field's moment
    // textures (14 for three channels to order 4) and its specular table while the lights
    // have one. Brute force: lights and light view.
    const int farField = pass->GetNumberOfFarFieldLights() > 0
      ? ClusteredLightingTest::FarFieldGLObjectsOf(pass.GetPointer())
      : 0;
    const int expectedUnits =
      !shading ? 0 : (f.Shading == vtkClusteredLightingPass::SHADING_CLUSTERED ? 4 + farField : 2);
    Check(reserved == expectedUnits,
      name + ": " + std::to_string(reserved) + " texture units reserved for shading (expected " +
        std::to_string(expectedUnits) + ")");
    // End of the delegate -> after the pass: units given back, nothing else changed.
    const std::string after = Differences(inner->After.GL, outer->After.GL);
    Check(after.empty(), name + ": nothing changes after the delegate" + after);
    Check(outer->After.AllocatedUnits == outer->Before.AllocatedUnits,
      name + ": every texture unit is given back (" + std::to_string(outer->Before.AllocatedUnits) +
        " -> " + std::to_string(outer->After.AllocatedUnits) + ")");
    Check(outer->After.GL["GL_COLOR_LOGIC_OP"] == (f.ApplicationState ? 1 : 0) &&
        outer->After.GL["GL_LOGIC_OP_MODE"] == GL_COPY,
      name +
        (f.ApplicationState ? ": the application's logic op (on, GL_COPY) is kept"
                            : ": logic op off and GL_COPY after the pass"));
    if (f.ApplicationState)
    {
      const long long vao = outer->ApplicationVAO;
      // (The delegate's mappers then bind their own, as stock VTK does.)
      Check(vao != 0 && outer->Before.GL["GL_VERTEX_ARRAY_BINDING"] == vao &&
          inner->Before.GL["GL_VERTEX_ARRAY_BINDING"] == vao,
        name + ": the application's vertex array is bound again after the assignment");
    }
    ExpectCacheMatchesGL(outer->Before, name + ", before the pass");
    ExpectCacheMatchesGL(inner->Before, name + ", after the assignment");
    ExpectCacheMatchesGL(outer->After, name + ", after the pass");
    std::string first;
    const int errors = CountGLErrors(renWin, &first);
    Check(errors == 0, name + ": no GL error " + first);
  }
  Check(outer->Frames == 7, "the probe saw every frame");
  renWin->MakeCurrent();
  glDeleteVertexArrays(1, &outer->ApplicationVAO);

  // The overlay after the pass, against the overlay alone (same window, the main
  // renderer drawing only its background, without the pass).
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  lights->SetEnabled(true);
  light->SwitchOn();
  ren->GetActiveCamera()->Azimuth(7.0);
  renWin->Render();
  Check(pass->GetLastAssignmentUpdated(), "the overlay frame reassigns lights");
  const std::vector<float> withPass = CapturePixels(renWin);
  ren->SetPass(nullptr);
  ren->RemoveAllViewProps();
  renWin->Render();
  const std::vector<float> alone = CapturePixels(renWin);
  int x0, y0, w, h;
  overlay->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  const double bg[3] = { 0.05, 0.05, 0.08 };
  std::size_t boxPixels = 0, differing = 0;
  const int width = renWin->GetSize()[0];
  for (int y = y0; y < y0 + h; ++y)
  {
    for (int x = x0; x < x0 + w; ++x)
    {
      const std::size_t p = 3 * (static_cast<std::size_t>(y) * width + x);
      bool isBox = false;
      for (int c = 0; c < 3; ++c)
      {
        isBox = isBox || std::abs(alone[p + c] - bg[c]) > 1.5 / 255.0;
      }
      if (isBox)
      {
        ++boxPixels;
        differing += (alone[p] != withPass[p] || alone[p + 1] != withPass[p + 1] ||
                       alone[p + 2] != withPass[p + 2])
          ? 1
          : 0;
      }
    }
  }
  Check(boxPixels > 1000, "the overlay box covers " + std::to_string(boxPixels) + " pixels");
  Check(differing == 0,
    "the overlay drawn after the pass is identical to the overlay alone (" +
      std::to_string(differing) + " pixels differ)");
  Check(
    messages->Errors.empty() && messages->Warnings.empty(), "no warning or error from the pass");
  return CheckStatus();
}
