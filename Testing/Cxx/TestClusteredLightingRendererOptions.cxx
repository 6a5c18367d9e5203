// SPDX-License-Identifier: BSD-3-Clause
// Renderer options that only the renderer's own render applies (UseFXAA, UseSSAO,
// UseHiddenLineRemoval, UseShadows: vtkOpenGLRenderer's UpdateGeometry and
// DeviceRenderOpaqueGeometry). VTK's render steps skip them under any render pass; the
// pass's own steps apply the first three as the renderer does (until 2026-11-28 the pass
// dropped all four, at first without a word). Checks:
//  1. On the test scene lit by the renderer's headlight, which the pass leaves to VTK (so
//     without these options its image is stock VTK's, bit for bit): each option changes
//     stock VTK's image here (so the checks can fail), and under the pass each gives stock
//     VTK's image with that option, bit for bit, with no message.
//  2. With clustered lights (positional vtkLights, so the pass's shader hooks light every
//     prop): FXAA equals a vtkOpenGLFXAAPass around the pass, bit for bit; SSAO darkens
//     the clustered image by stock VTK's ambient-occlusion factor of the same geometry
//     (col.rgb * ao, within the rounding of the 8-bit images the factor is read from);
//     hidden-line removal hides the same wireframe pixels as stock VTK's.
//     The count debug views (and the heat map's count) are rendered without FXAA and SSAO,
//     which change the colours that encode the counts: the same counts and images as
//     without the options, and the options still on afterwards.
//  3. The shaded-fragment count (MeasureTimings) says "not measured" (-1) for the opaque
//     part under SSAO, which draws full-viewport quads of its own.
//  4. One pass in two windows, each with SSAO: each window keeps its own image frame
//     after frame, and after the pass's resources are released.
//  5. UseShadows is not applied: one warning that says why, again when asked for again.
//  6. The GL objects of the SSAO pass and FXAA filter the pass keeps for a renderer go
//     when the pass releases their window and when the pass is deleted, in their own
//     context while another window's is current.
//  (Under SSAO or hidden-line removal the pass draws no depth prepass: the prepass hid
//  the props behind the wireframes' back lines, and under SSAO a wireframe pixel lost
//  its clustered light.)
// Nothing reaches VTK's output window (a shader of VTK's that failed to build would).
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightingPass.h"
#include "vtkLight.h"
#include "vtkOpenGLFXAAPass.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

std::vector<float> Frame(vtkRenderWindow* rw, int frames = 1)
{
  for (int i = 0; i < frames; ++i)
  {
    rw->Render();
  }
  return ClusteredLightingTest::CapturePixels(rw);
}

double MaxDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  return ClusteredLightingTest::CompareImages(a, b).MaxAbsError;
}

/// Pixels whose colour is not the background's (0.05, 0.05, 0.08 in 8 bits).
std::vector<bool> Coverage(const std::vector<float>& image)
{
  const float background[3] = { 0.05f, 0.05f, 0.08f };
  std::vector<bool> covered(image.size() / 3);
  for (std::size_t p = 0; p < covered.size(); ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      covered[p] = covered[p] || std::abs(image[3 * p + k] - background[k]) > 0.6f / 255.0f;
    }
  }
  return covered;
}

std::size_t CountDifferent(const std::vector<bool>& a, const std::vector<bool>& b)
{
  std::size_t n = 0;
  for (std::size_t p = 0; p < a.size() && p < b.size(); ++p)
  {
    n += a[p] != b[p] ? 1 : 0;
  }
  return n;
}

/// A wireframe sphere beside the test scene's ball (hidden-line removal's subject).
void AddWireframeSphere(vtkRenderer* ren)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(12);
  source->SetPhiResolution(12);
  source->SetCenter(2.0, 0.0, 0.5);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToWireframe();
  actor->GetProperty()->SetColor(0.6, 0.9, 0.6);
  ren->AddActor(actor);
}

/// Positional lights the pass clusters.
void AddClusteredLights(vtkRenderer* ren)
{
  const double positions[4][3] = { { -2, 0.5, 1.5 }, { 1.5, 0.2, 1.8 }, { 0, 1.2, -1.5 },
    { 2.5, -0.5, 0.5 } };
  const double colors[4][3] = { { 1, 0.3, 0.2 }, { 0.2, 0.5, 1 }, { 0.9, 0.9, 0.3 },
    { 0.3, 1, 0.4 } };
  for (int i = 0; i < 4; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetPositional(true);
    light->SetLightTypeToSceneLight();
    light->SetPosition(positions[i]);
    light->SetColor(colors[i]);
    light->SetConeAngle(180.0);
    light->SetAttenuationValues(1.0, 0.0, 0.5);
    ren->AddLight(light);
  }
}

/// SSAO multiplies the lit colour by the occlusion factor ao (VTK 9.1, vtkSSAOPass's
/// combine shader: col.rgb * ao). ao depends on positions and normals only, so it is read
/// from stock VTK's pair of images (with and without SSAO) where the plain channel is at
/// least 0.25 and neither plain channel is clamped at 1 (VTK's SSAO renders into
/// a float target and darkens the unclamped colour; the pass then evaluates every light);
/// there, with every image rounded to 8 bits, the clustered SSAO image must
/// equal the clustered plain image times ao within 5 steps (0.5 / 0.25 steps from each
/// stock value, 0.5 from each clustered value). Returns the largest error in steps; `over`
/// counts the channels SSAO darkened by more than 8 steps.
double CheckOcclusionFactor(const std::vector<float>& stockPlain,
  const std::vector<float>& stockSsao, const std::vector<float>& plain,
  const std::vector<float>& ssao, std::size_t& over, std::size_t& compared)
{
  double worst = 0.0;
  over = 0;
  compared = 0;
  for (std::size_t i = 0; i < plain.size(); ++i)
  {
    over += plain[i] - ssao[i] > 8.0f / 255.0f ? 1 : 0;
    const float clamped = 254.5f / 255.0f;
    if (stockPlain[i] < 0.25f || stockPlain[i] > clamped || plain[i] > clamped)
    {
      continue;
    }
    const double ao = double(stockSsao[i]) / double(stockPlain[i]);
    worst = std::max(worst, std::abs(double(ssao[i]) - double(plain[i]) * ao) * 255.0);
    ++compared;
  }
  return worst;
}
}

int TestClusteredLightingRendererOptions(int, char*[])
{
  ClusteredLightingTest::OutputCapture output;

  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 200, 150, 8);
  AddWireframeSphere(ren);

  // 1. Stock VTK, each option alone, then the same under the pass (headlight only).
  struct Option
  {
    const char* Name;
    void (*Set)(vtkRenderer*, bool);
    std::vector<float> Stock;
  };
  Option options[] = {
    { "UseFXAA", [](vtkRenderer* r, bool on) { r->SetUseFXAA(on); }, {} },
    { "UseSSAO", [](vtkRenderer* r, bool on) { r->SetUseSSAO(on); }, {} },
    { "UseHiddenLineRemoval", [](vtkRenderer* r, bool on) { r->SetUseHiddenLineRemoval(on); }, {} },
  };
  const std::vector<float> stockPlain = Frame(rw);
  for (Option& o : options)
  {
    o.Set(ren, true);
    o.Stock = Frame(rw);
    o.Set(ren, false);
    Check(MaxDifference(o.Stock, stockPlain) > 0.0,
      std::string(o.Name) + " changes stock VTK's image here");
  }

  vtkNew<vtkClusteredLightingPass> pass;
  // The prepass in every frame (not chosen by timing): the wireframe's silhouette edges
  // belong to a front and a back triangle at nearly equal depths, and which of the two
  // shades a pixel there depends on whether the depths were laid down first.
  pass->AutomaticDepthPrepassOff();
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  ren->SetPass(pass);
  Check(MaxDifference(Frame(rw, 2), stockPlain) == 0.0,
    "under the pass, without the options: stock VTK's image, bit for bit");
  for (Option& o : options)
  {
    o.Set(ren, true);
    const std::vector<float> image = Frame(rw, 2);
    o.Set(ren, false);
    const double d = MaxDifference(image, o.Stock);
    Check(d == 0.0,
      std::string(o.Name) + " under the pass: stock VTK's image with it, bit for bit (max " +
        std::to_string(d * 255.0) + " steps)");
  }
  Check(messages->Warnings.empty() && messages->Errors.empty(), "no message for them");

  // 2. Clustered lights.
  AddClusteredLights(ren);
  const std::vector<float> plain = Frame(rw, 2);
  Check(pass->GetNumberOfClusteredLights() == 4, "the pass clusters the 4 positional lights");
  Check(MaxDifference(plain, stockPlain) > 0.1, "they light the scene");

  ren->UseFXAAOn();
  const std::vector<float> fxaa = Frame(rw, 2);
  ren->UseFXAAOff();
  vtkNew<vtkOpenGLFXAAPass> wrapper;
  wrapper->SetDelegatePass(pass);
  ren->SetPass(wrapper);
  const std::vector<float> wrapped = Frame(rw, 2);
  ren->SetPass(pass);
  Check(MaxDifference(fxaa, plain) > 0.0 && MaxDifference(fxaa, wrapped) == 0.0,
    "clustered, UseFXAA: the image of a vtkOpenGLFXAAPass around the pass, bit for bit");

  ren->UseSSAOOn();
  const std::vector<float> ssao = Frame(rw, 2);
  const bool ssaoPrepassed = pass->GetDepthPrepassUsed() || pass->GetDepthAwareClustersUsed();
  ren->UseSSAOOff();
  // VTK's SSAO renders the opaque step into a framebuffer of its own, without the
  // prepass's depths, and the pass then draws no prepass: its plain counterpart is the
  // frame without the prepass.
  pass->DepthPrepassOff();
  pass->DepthAwareClustersOff();
  const std::vector<float> plainWithoutPrepass = Frame(rw);
  pass->DepthPrepassOn();
  pass->DepthAwareClustersOn();
  Check(!ssaoPrepassed, "no depth prepass under SSAO");
  std::size_t darkened = 0;
  std::size_t compared = 0;
  const double aoError = CheckOcclusionFactor(
    stockPlain, options[1].Stock, plainWithoutPrepass, ssao, darkened, compared);
  std::printf("SSAO: %zu channels compared, largest error %.2f steps, %zu darkened by more "
              "than 8 steps\n",
    compared, aoError, darkened);
  Check(compared > 10000 && aoError <= 5.0,
    "clustered, UseSSAO: the clustered image times stock VTK's occlusion factor");
  Check(darkened > 500, "SSAO darkens the clustered image");

  ren->UseHiddenLineRemovalOn();
  const std::vector<float> hlr = Frame(rw, 2);
  const bool prepassed = pass->GetDepthPrepassUsed() || pass->GetDepthAwareClustersUsed();
  ren->UseHiddenLineRemovalOff();
  const std::vector<float> after = Frame(rw);
  const std::size_t hidden = CountDifferent(Coverage(plain), Coverage(hlr));
  const std::size_t differ = CountDifferent(Coverage(hlr), Coverage(options[2].Stock));
  std::printf(
    "hidden-line removal: %zu pixels change coverage, %zu differ from stock\n", hidden, differ);
  Check(hidden > 50 && differ == 0,
    "clustered, UseHiddenLineRemoval: the wireframe pixels stock VTK's shows, no others "
    "(with a depth prepass the floor behind the wireframe's back lines went missing)");
  Check(!prepassed && pass->GetDepthPrepassUsed(),
    "no depth prepass while hidden lines are removed; again without them");
  Check(MaxDifference(after, plain) == 0.0, "each option off again: the plain image");

  // The count views encode counts in their colours (R + 256 G, and B), which FXAA (an edge
  // pixel blended with the background) and SSAO (colours scaled by occlusion) would
  // change: the pass renders them without either, and so the heat map's count first.
  // A bright background (ParaView's is): FXAA leaves the dark edges of this scene's
  // (0.05, 0.05, 0.08) alone.
  double background[3];
  ren->GetBackground(background);
  ren->SetBackground(0.6, 0.6, 0.7);
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  const std::vector<float> counts = Frame(rw);
  const double evaluated = pass->GetMeanLightsEvaluatedPerPixel();
  const double reaching = pass->GetMeanLightsReachingPerPixel();
  ren->UseFXAAOn();
  const std::vector<float> countsFXAA = Frame(rw);
  const bool fxaaKept = ren->GetUseFXAA();
  std::printf("evaluated / reaching per pixel: %.4f / %.4f, with FXAA %.4f / %.4f\n", evaluated,
    reaching, pass->GetMeanLightsEvaluatedPerPixel(), pass->GetMeanLightsReachingPerPixel());
  Check(evaluated > 0.5 && MaxDifference(countsFXAA, counts) == 0.0 &&
      pass->GetMeanLightsEvaluatedPerPixel() == evaluated &&
      pass->GetMeanLightsReachingPerPixel() == reaching && fxaaKept,
    "DEBUG_EVALUATED_COUNT with UseFXAA: the counts and their image as without it, and "
    "UseFXAA still on after the frame");
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_HEAT_MAP);
  const std::vector<float> heatFXAA = Frame(rw);
  const double scaleFXAA = pass->GetHeatMapScale();
  ren->UseFXAAOff();
  const std::vector<float> heat = Frame(rw);
  Check(pass->GetHeatMapScale() == scaleFXAA &&
      pass->GetMeanLightsEvaluatedPerPixel() == evaluated && MaxDifference(heatFXAA, heat) > 0.0,
    "DEBUG_HEAT_MAP with UseFXAA: the same scale (" + std::to_string(scaleFXAA) +
      ") and counts as without it, and the heat map itself anti-aliased");
  // SSAO draws no prepass: its counts are those of the frame without one.
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  pass->DepthPrepassOff();
  pass->DepthAwareClustersOff();
  const std::vector<float> countsUnculled = Frame(rw);
  const double evaluatedUnculled = pass->GetMeanLightsEvaluatedPerPixel();
  const double reachingUnculled = pass->GetMeanLightsReachingPerPixel();
  pass->DepthPrepassOn();
  pass->DepthAwareClustersOn();
  ren->UseSSAOOn();
  const std::vector<float> countsSSAO = Frame(rw);
  const bool ssaoKept = ren->GetUseSSAO();
  ren->UseSSAOOff();
  Check(MaxDifference(countsSSAO, countsUnculled) == 0.0 &&
      pass->GetMeanLightsEvaluatedPerPixel() == evaluatedUnculled &&
      pass->GetMeanLightsReachingPerPixel() == reachingUnculled && ssaoKept,
    "DEBUG_EVALUATED_COUNT with UseSSAO: the counts and their image as without it (no "
    "prepass, " +
      std::to_string(evaluatedUnculled) + " per pixel), and UseSSAO still on after the frame");
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  ren->SetBackground(background);

  // 3. The opaque count under SSAO.
  pass->MeasureTimingsOn();
  Frame(rw);
  const double opaque = pass->GetShadedOpaqueFragmentsPerVisiblePixel();
  ren->UseSSAOOn();
  const std::vector<float> measured = Frame(rw);
  Check(opaque >= 1.0 && opaque < 1.2 && pass->GetShadedOpaqueFragmentsPerVisiblePixel() == -1.0 &&
      pass->GetShadedFragmentsPerVisiblePixel() == -1.0,
    "shaded opaque fragments per pixel " + std::to_string(opaque) +
      " without SSAO, not measured (-1) with it");
  Check(MaxDifference(measured, ssao) == 0.0, "counting does not change the SSAO image");
  pass->MeasureTimingsOff();

  // 4. One pass, two windows, SSAO in both; a release between frames.
  vtkNew<vtkRenderWindow> rw2;
  vtkNew<vtkRenderer> ren2;
  ClusteredLightingTest::SetUpTestScene(rw2, ren2, 160, 120, 8);
  AddWireframeSphere(ren2);
  AddClusteredLights(ren2);
  ren2->SetPass(pass);
  ren2->UseSSAOOn();
  const std::vector<float> second = Frame(rw2, 2);
  bool same = true;
  for (int i = 0; i < 3; ++i)
  {
    same =
      same && MaxDifference(Frame(rw), ssao) == 0.0 && MaxDifference(Frame(rw2), second) == 0.0;
  }
  pass->ReleaseGraphicsResources(rw);
  same = same && MaxDifference(Frame(rw), ssao) == 0.0 && MaxDifference(Frame(rw2), second) == 0.0;
  Check(same, "one pass in two windows with SSAO: each keeps its image, also after a release");
  ren->UseSSAOOff();

  // 5. Shadows: not applied, said once, and again when asked for again.
  ren->UseShadowsOn();
  Check(MaxDifference(Frame(rw, 2), plain) == 0.0, "UseShadows: not applied");
  Check(messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("UseShadows") != std::string::npos &&
      messages->Warnings[0].find("cast none") != std::string::npos,
    "UseShadows: one warning in 2 frames that names it and says why");
  if (!messages->Warnings.empty())
  {
    std::printf("the warning: %s\n", messages->Warnings[0].c_str());
  }
  ren->UseShadowsOff();
  Frame(rw);
  ren->UseShadowsOn();
  Frame(rw);
  Check(messages->Warnings.size() == 2, "asked for again: said again");
  ren->UseShadowsOff();
  Frame(rw);
  Check(messages->Errors.empty(), "no error");

  // 6. The SSAO pass and FXAA filter the pass keeps for a renderer hold GL objects; they
  // go in their own window's context, when the pass releases that window and when the
  // pass is deleted, whatever context is current then (another window's here: VTK deletes
  // vertex arrays in the current context). Counted against the GL objects after a first
  // round and a release, so that what the window itself makes on first use is there
  // already; vertex arrays by number only, as VTK's mappers change theirs with every
  // switch between the prepass's program and the shading program.
  for (const bool deleteThePass : { false, true })
  {
    vtkNew<vtkRenderWindow> rw3;
    vtkNew<vtkRenderer> ren3;
    ClusteredLightingTest::SetUpTestScene(rw3, ren3, 120, 90, 8);
    AddClusteredLights(ren3);
    vtkSmartPointer<vtkClusteredLightingPass> pass3 =
      vtkSmartPointer<vtkClusteredLightingPass>::New();
    ren3->SetPass(pass3);
    ren3->UseFXAAOn();
    ren3->UseSSAOOn();
    Frame(rw3, 2);
    pass3->ReleaseGraphicsResources(rw3);
    const ClusteredLightingTest::GLNames before = ClusteredLightingTest::TakeGLNameCensus(rw3);
    Frame(rw3, 2);
    const std::size_t made =
      ClusteredLightingTest::Minus(ClusteredLightingTest::TakeGLNameCensus(rw3), before).size();
    ren3->UseFXAAOff();
    ren3->UseSSAOOff();
    if (deleteThePass)
    {
      // VTK's mappers keep the render passes of their last draw: one stock frame first.
      ren3->SetPass(nullptr);
      Frame(rw3);
      rw->MakeCurrent(); // another window's context
      pass3 = nullptr;
    }
    else
    {
      rw->MakeCurrent();
      pass3->ReleaseGraphicsResources(rw3);
    }
    const ClusteredLightingTest::GLNames after = ClusteredLightingTest::TakeGLNameCensus(rw3);
    const auto arrays = [](const ClusteredLightingTest::GLNames& names)
    {
      return std::count_if(names.begin(), names.end(),
        [](const std::pair<unsigned int, unsigned int>& n) { return n.first == GL_VERTEX_ARRAY; });
    };
    ClusteredLightingTest::GLNames left;
    for (const auto& n : ClusteredLightingTest::Minus(after, before))
    {
      if (n.first != GL_VERTEX_ARRAY)
      {
        left.insert(n);
      }
    }
    Check(made > 10 && left.empty() && arrays(after) <= arrays(before),
      std::string(deleteThePass ? "the pass deleted" : "the pass's window released") +
        " with another context current: the " + std::to_string(made) +
        " GL objects of its SSAO pass, FXAA filter and assignment go (" +
        std::to_string(left.size()) + " left: " + ClusteredLightingTest::Describe(left) +
        "; vertex arrays " + std::to_string(arrays(after)) + " after, " +
        std::to_string(arrays(before)) + " before)");
  }

  wrapper->ReleaseGraphicsResources(rw);
  pass->ReleaseGraphicsResources(nullptr);
  const std::string printed = output.Finish();
  Check(printed.empty(), "nothing reached VTK's output window: " + printed);
  return ClusteredLightingTest::CheckStatus();
}
