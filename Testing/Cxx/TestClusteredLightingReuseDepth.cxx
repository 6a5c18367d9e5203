// SPDX-License-Identifier: BSD-3-Clause
// ReuseDepthPrepass: a frame whose depth prepass would draw what the last one drew copies
// the last depths back instead, and renders the same image bit for bit; anything that
// moves the depths makes it draw again. Each case changes one thing, renders with the
// reuse on (and checks whether it reused), then renders the same scene with the reuse off
// and compares the two images exactly:
//  - still frames, and a moved light (lights do not change depths): reused, from the
//    second frame of an actor whose property its first render made;
//  - the camera, an actor's transform, its property (wireframe), an upstream source, the
//    points of an input changed in place, a clipping plane moved in place, the window's
//    size: drawn again;
//  - a prop the signature cannot vouch for (a vtkFollower): never reused;
//  - the same in a multisampled window with depth-aware clusters (the recorded depths);
//  - two renderers sharing the pass: each reuses its own depths;
//  - a composite mapper (ParaView's): still frames reuse; a block's points changed in
//    place, a block hidden or made translucent: drawn again.
// The lights are as users write them (inverse-square, no radius), so the far field and the
// depth-aware clusters are on.
#include "ClusteredLightingTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkClusteredLightSet.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkCubeSource.h"
#include "vtkFollower.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPlane.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <functional>

namespace
{
int Expect(bool condition, const std::string& what)
{
  std::printf("%s %s\n", condition ? "ok:  " : "FAIL:", what.c_str());
  return condition ? 0 : 1;
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkClusteredLightingPass> Pass;
  vtkNew<vtkClusteredLightSet> Lights;
  vtkNew<vtkSphereSource> Sphere;
  vtkNew<vtkActor> Ball;
  vtkNew<vtkPolyData> Box;
  vtkNew<vtkPlane> Clip;

  explicit Scene(int samples)
  {
    ClusteredLightingTest::SetUpTestScene(this->Window, this->Renderer, 200, 150);
    this->Window->SetMultiSamples(samples);
    this->Renderer->AutomaticLightCreationOff();
    // The test scene's sphere and floor, with handles on their sources and mappers.
    vtkActorCollection* actors = this->Renderer->GetActors();
    actors->InitTraversal();
    actors->GetNextActor(); // the floor
    vtkActor* ball = actors->GetNextActor();
    this->Renderer->RemoveActor(ball);
    this->Sphere->SetThetaResolution(24);
    this->Sphere->SetPhiResolution(24);
    vtkNew<vtkPolyDataMapper> ballMapper;
    ballMapper->SetInputConnection(this->Sphere->GetOutputPort());
    this->Ball->SetMapper(ballMapper);
    this->Ball->SetScale(1.5);
    this->Ball->GetProperty()->SetSpecular(0.4);
    this->Renderer->AddActor(this->Ball);
    // A plane that clips nothing yet; later it cuts the ball's front open, which shows
    // surfaces the last depths hide.
    this->Clip->SetOrigin(0, 0, -10);
    this->Clip->SetNormal(0, 0, 1);
    ballMapper->AddClippingPlane(this->Clip);
    // A box given as data (no pipeline), to change its points in place.
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(1.8, -0.5, 1.2);
    cube->SetXLength(0.8);
    cube->SetYLength(1.0);
    cube->SetZLength(0.8);
    cube->Update();
    this->Box->DeepCopy(cube->GetOutput());
    vtkNew<vtkPolyDataMapper> boxMapper;
    boxMapper->SetInputData(this->Box);
    vtkNew<vtkActor> box;
    box->SetMapper(boxMapper);
    this->Renderer->AddActor(box);

    ClusteredLightingTest::MakeUserLights(this->Lights, 300, 0.3, 7);
    this->Pass->AddLightSet(this->Lights);
    this->Pass->AutomaticDepthPrepassOff(); // every frame draws (or reuses) its prepass
    this->Renderer->SetPass(this->Pass);
    this->Window->Render();
    this->Window->Render();
  }

  /// Renders after `change` with the reuse on, then the same scene with it off; the two
  /// images must be equal and the first must have reused exactly when `reuse` says.
  int Check(const std::string& what, bool reuse, const std::function<void()>& change)
  {
    change();
    this->Window->Render();
    const bool reused = this->Pass->GetDepthPrepassReused();
    const bool drawn = this->Pass->GetDepthPrepassUsed();
    const std::vector<float> image = ClusteredLightingTest::CapturePixels(this->Window);
    this->Pass->ReuseDepthPrepassOff();
    this->Window->Render();
    const bool offReused = this->Pass->GetDepthPrepassReused();
    const std::vector<float> reference = ClusteredLightingTest::CapturePixels(this->Window);
    this->Pass->ReuseDepthPrepassOn();
    this->Window->Render(); // draws and saves again
    const ClusteredLightingTest::ImageComparison c =
      ClusteredLightingTest::CompareImages(image, reference);
    std::printf("%s: %s, max difference %g\n", what.c_str(), reused ? "reused" : "drawn",
      c.MaxAbsError * 255.0);
    const bool kept = this->Pass->GetDepthPrepassKept();
    const std::string problem = this->Pass->GetDepthPrepassReuseProblem();
    int failed = Expect(drawn && reused == reuse,
      what + (reuse ? ": the last depths are copied back" : ": the prepass draws again"));
    failed += Expect(kept == problem.empty(),
      what + ": the depths are kept for the next frame, or a reason says why not" +
        (problem.empty() ? std::string() : " (" + problem + ")"));
    failed += Expect(!offReused, what + ": never with ReuseDepthPrepass off");
    failed += Expect(c.MaxAbsError == 0.0, what + ": the same image as without reuse");
    return failed;
  }
};

int RunCases(int samples)
{
  std::printf("--- %d samples\n", samples);
  Scene scene(samples);
  vtkClusteredLightingPass* pass = scene.Pass;
  int failed = 0;
  failed += scene.Check("still frame", true, [] {});
  failed += Expect(pass->GetDepthAwareClustersUsed(), "depth-aware clusters in use");
  failed += scene.Check("second still frame", true, [] {});
  failed +=
    scene.Check("a light moved", true, [&] { scene.Lights->SetPosition(5, 0.3, -0.5, 0.4); });
  failed += scene.Check("camera turned", false,
    [&]
    {
      scene.Renderer->GetActiveCamera()->Azimuth(4.0);
      scene.Renderer->ResetCameraClippingRange();
    });
  failed += scene.Check("still after the turn", true, [] {});
  failed += scene.Check("actor moved", false, [&] { scene.Ball->SetPosition(0.4, 0.0, 0.3); });
  failed += scene.Check("actor in wireframe", false,
    [&] { scene.Ball->GetProperty()->SetRepresentationToWireframe(); });
  failed += scene.Check("actor back to surface", false,
    [&] { scene.Ball->GetProperty()->SetRepresentationToSurface(); });
  failed +=
    scene.Check("upstream source changed", false, [&] { scene.Sphere->SetCenter(-0.5, 0.2, 0.0); });
  failed += scene.Check("input points changed in place", false,
    [&]
    {
      vtkPoints* points = scene.Box->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        points->GetPoint(i, p);
        points->SetPoint(i, p[0] - 0.6, p[1] + 0.3, p[2]);
      }
      points->Modified();
    });
  failed += scene.Check("clipping plane moved in place", false,
    [&]
    {
      scene.Clip->SetOrigin(0, 0, 0.3);
      scene.Clip->SetNormal(0, 0, -1);
    });
  failed += scene.Check("still after the changes", true, [] {});
  failed += scene.Check("window resized", false, [&] { scene.Window->SetSize(210, 150); });
  vtkNew<vtkFollower> follower;
  failed += scene.Check("a follower added", false,
    [&]
    {
      vtkNew<vtkPolyDataMapper> mapper;
      vtkNew<vtkCubeSource> cube;
      cube->SetCenter(-2, 0, 1);
      mapper->SetInputConnection(cube->GetOutputPort());
      follower->SetMapper(mapper);
      follower->SetCamera(scene.Renderer->GetActiveCamera());
      scene.Renderer->AddActor(follower);
    });
  failed += scene.Check("still with the follower", false, [] {});
  failed += Expect(!pass->GetDepthPrepassKept() &&
      std::string(pass->GetDepthPrepassReuseProblem()).find("Follower") != std::string::npos,
    "the follower is named as the reason");
  failed += scene.Check("follower removed", false, [&] { scene.Renderer->RemoveActor(follower); });
  failed += scene.Check("still without it", true, [] {});
  // An actor added without a property: at its first render under the pass VTK gives it
  // information keys and a property, which changes its time. The frame after reuses.
  vtkNew<vtkActor> plain;
  vtkNew<vtkPolyDataMapper> plainMapper;
  vtkNew<vtkCubeSource> plainCube;
  plainCube->SetCenter(-1.8, -0.5, 1.2);
  plainMapper->SetInputConnection(plainCube->GetOutputPort());
  plain->SetMapper(plainMapper);
  scene.Renderer->AddActor(plain);
  scene.Window->Render();
  failed += Expect(!pass->GetDepthPrepassReused(), "an actor added: the prepass draws");
  scene.Window->Render();
  failed += Expect(pass->GetDepthPrepassReused(),
    "the frame after the added actor's first render (which made its property) reuses");
  failed += scene.Check("still with the added actor", true, [] {});
  return failed;
}
}

/// A vtkCompositePolyDataMapper2 (ParaView's mapper) over a multiblock of two boxes given
/// as data: still frames reuse; a block's points changed in place (the multiblock's own
/// time unchanged), a block hidden or made translucent through the display attributes
/// make the frame draw.
int RunComposite()
{
  std::printf("--- a composite mapper\n");
  Scene scene(0);
  vtkNew<vtkMultiBlockDataSet> blocks;
  vtkNew<vtkPolyData> boxes[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(-1.6 + 0.9 * i, 0.6, 1.0 + 0.3 * i);
    cube->SetXLength(0.7);
    cube->SetYLength(0.9);
    cube->SetZLength(0.7);
    cube->Update();
    boxes[i]->DeepCopy(cube->GetOutput());
    blocks->SetBlock(i, boxes[i]);
  }
  vtkNew<vtkCompositePolyDataMapper2> mapper;
  mapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  mapper->SetCompositeDataDisplayAttributes(attributes);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  scene.Renderer->AddActor(actor);
  scene.Window->Render();
  scene.Window->Render();
  int failed = 0;
  failed += scene.Check("still frame", true, [] {});
  failed += Expect(scene.Pass->GetDepthPrepassKept(),
    std::string("the composite mapper is accepted (") + scene.Pass->GetDepthPrepassReuseProblem() +
      ")");
  failed += scene.Check("a block's points changed in place", false,
    [&]
    {
      vtkPoints* points = boxes[1]->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        points->GetPoint(i, p);
        points->SetPoint(i, p[0] + 0.5, p[1] - 0.4, p[2] + 0.3);
      }
      points->Modified();
    });
  failed += scene.Check("still after the change", true, [] {});
  failed +=
    scene.Check("a block hidden", false, [&] { attributes->SetBlockVisibility(boxes[0], false); });
  failed += scene.Check(
    "a block shown again", false, [&] { attributes->SetBlockVisibility(boxes[0], true); });
  failed += scene.Check(
    "a block made translucent", false, [&] { attributes->SetBlockOpacity(boxes[1], 0.5); });
  failed += scene.Check("still with the translucent block", true, [] {});
  return failed;
}

/// Whether a renderer's frame reused its prepass, read as the renderer ends.
struct ReuseWatch
{
  vtkClusteredLightingPass* Pass = nullptr;
  bool Reused = false;
  static void Ended(vtkObject*, unsigned long, void* watch, void*)
  {
    auto* w = static_cast<ReuseWatch*>(watch);
    w->Reused = w->Pass->GetDepthPrepassReused();
  }
};

/// Two renderers side by side sharing one pass: each keeps its own prepass depths and
/// reuses them on still frames, though the other renders in between; a camera turned in
/// one makes that one draw. The image is the same as with the reuse off.
int RunSharedPass()
{
  std::printf("--- two renderers sharing a pass\n");
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> left;
  vtkNew<vtkRenderer> right;
  ClusteredLightingTest::SetUpTestScene(window, left, 300, 150);
  ClusteredLightingTest::SetUpTestScene(window, right, 300, 150);
  left->AutomaticLightCreationOff();
  right->AutomaticLightCreationOff();
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->GetActiveCamera()->Azimuth(40.0);
  right->ResetCameraClippingRange();
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, 300, 0.3, 7);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  pass->AutomaticDepthPrepassOff();
  left->SetPass(pass);
  right->SetPass(pass);
  ReuseWatch watches[2];
  vtkRenderer* renderers[2] = { left, right };
  for (int i = 0; i < 2; ++i)
  {
    watches[i].Pass = pass;
    vtkNew<vtkCallbackCommand> ended;
    ended->SetClientData(&watches[i]);
    ended->SetCallback(&ReuseWatch::Ended);
    renderers[i]->AddObserver(vtkCommand::EndEvent, ended);
  }
  int failed = 0;
  window->Render();
  failed += Expect(!watches[0].Reused && !watches[1].Reused, "first frame: both draw");
  window->Render();
  failed += Expect(watches[0].Reused && watches[1].Reused, "still frame: both reuse their own");
  const std::vector<float> image = ClusteredLightingTest::CapturePixels(window);
  pass->ReuseDepthPrepassOff();
  window->Render();
  failed += Expect(!watches[0].Reused && !watches[1].Reused, "reuse off: both draw");
  const ClusteredLightingTest::ImageComparison c =
    ClusteredLightingTest::CompareImages(image, ClusteredLightingTest::CapturePixels(window));
  failed += Expect(c.MaxAbsError == 0.0, "the same image as without reuse");
  pass->ReuseDepthPrepassOn();
  window->Render();
  right->GetActiveCamera()->Azimuth(10.0);
  right->ResetCameraClippingRange();
  window->Render();
  failed += Expect(watches[0].Reused && !watches[1].Reused,
    "one camera turned: that renderer draws, the other reuses");
  return failed;
}

int TestClusteredLightingReuseDepth(int, char*[])
{
  int failed = RunCases(0);
  failed += RunCases(8);
  failed += RunSharedPass();
  failed += RunComposite();
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
