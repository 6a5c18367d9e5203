// SPDX-License-Identifier: BSD-3-Clause
// The pass culls the hidden faces of closed opaque surfaces (AutomaticBackfaceCulling,
// vtkClusteredLightingBackfaceCulling). Each case renders 300 lights as users write them
// over a scene with the option on and off, with the depth prepass drawn and without it,
// and checks
//  - how many props the pass culled (GetNumberOfBackfaceCulledProps): the closed ball
//    (outward, inward, mirrored by a negative scale; followed by an image slice seen from
//    behind, which must not be culled with it) and a cube whose faces have points of their
//    own; not an open sphere, a translucent or wireframe ball, a ball of triangle
//    strips, one with clipping planes, one whose mapper discards fragments (VTK 9.0's
//    deprecated per-mapper replacement), one with VTK's own culling, one that the near plane
//    cuts, or a sphere around the camera;
//  - that the image is the one with the option off: no pixel off by more than one step,
//    except at most a few at the rim, where a back face and a front face meet at one
//    depth and a back face won the depth test (culled, the front face shows). Culling the
//    wrong face, or a surface whose back faces show, changes hundreds of pixels;
//  - that face culling is off after the frame (nothing culled after the pass);
//  - that a mesh modified before every render is not tested again while it keeps
//    changing, and is once it stays unchanged, also where a frame renders several views
//    (two renderers sharing the pass, a stereo pair); that a mesh opened is not culled;
//  - that a still frame reuses the prepass's depths only when the same faces are culled.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkCubeSource.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPlane.h"
#include "vtkProperty.h"
#include "vtkReverseSense.h"
#include "vtkShader.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"
#include "vtkVersionMacros.h"
#include "vtk_glew.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
using ClusteredLightingTest::Check;

/// The test scene's ball (the actor drawn from a vtkSphereSource) and its source.
vtkActor* FindBall(vtkRenderer* ren, vtkSphereSource*& sphere)
{
  vtkActorCollection* actors = ren->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    sphere = vtkSphereSource::SafeDownCast(a->GetMapper()->GetInputAlgorithm());
    if (sphere)
    {
      return a;
    }
  }
  return nullptr;
}

/// Pixels of two images that differ by more than one step in a channel.
int CountDiffering(const std::vector<float>& a, const std::vector<float>& b)
{
  const ClusteredLightingTest::ImageComparison c = ClusteredLightingTest::CompareImages(a, b);
  return c.Pixels == 0 ? 1 << 30 : static_cast<int>(std::lround(c.FractionOverOneStep * c.Pixels));
}

/// The test scene (an open floor and a closed ball, the usual camera) with `n` lights as
/// users write them, through the pass.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkClusteredLightSet> Lights;
  vtkNew<vtkClusteredLightingPass> Pass;

  Scene(int width, int height, int n, unsigned seed, int sphereResolution)
  {
    ClusteredLightingTest::SetUpTestScene(
      this->Window, this->Renderer, width, height, sphereResolution);
    ClusteredLightingTest::MakeUserLights(this->Lights, n, 0.05, seed);
    this->Pass->AddLightSet(this->Lights);
    this->Renderer->SetPass(this->Pass);
  }
};

struct Case
{
  const char* Name;
  int Culled;  ///< props the pass must cull
  double Near; ///< the near plane's distance (0: fit to the scene)
  std::function<void(vtkRenderer*, vtkActor* ball, vtkSphereSource* sphere)> SetUp;
};

/// A scene of its own for each case: the test scene and 300 lights as users write them.
void RunCase(const Case& c, bool prepass)
{
  Scene scene(240, 180, 300, 5, 32);
  vtkRenderWindow* rw = scene.Window;
  vtkRenderer* ren = scene.Renderer;
  vtkClusteredLightingPass* pass = scene.Pass;
  pass->AutomaticDepthPrepassOff();
  pass->SetDepthPrepass(prepass);
  vtkSphereSource* sphere = nullptr;
  vtkActor* ball = FindBall(ren, sphere);
  if (!ball)
  {
    Check(false, "the test scene has its ball");
    return;
  }
  c.SetUp(ren, ball, sphere);
  ren->ResetCameraClippingRange();
  if (c.Near > 0.0)
  {
    ren->GetActiveCamera()->SetClippingRange(c.Near, 20.0);
  }

  const std::string what = std::string(c.Name) + (prepass ? ", prepass" : ", no prepass");
  rw->Render();
  const std::vector<float> culled = ClusteredLightingTest::CapturePixels(rw);
  const int count = pass->GetNumberOfBackfaceCulledProps();
  Check(!glIsEnabled(GL_CULL_FACE), what + ": face culling is off after the frame");
  pass->AutomaticBackfaceCullingOff();
  rw->Render();
  const std::vector<float> drawn = ClusteredLightingTest::CapturePixels(rw);
  const int countOff = pass->GetNumberOfBackfaceCulledProps();
  const int differing = CountDiffering(culled, drawn);
  std::printf(
    "%s: %d culled, %d pixels differ by more than one step\n", what.c_str(), count, differing);
  Check(count == c.Culled, what + ": " + std::to_string(c.Culled) + " culled");
  Check(countOff == 0, what + ": none culled with the option off");
  Check(differing <= 4, what + ": the same image but for a few rim pixels");
}
}

int TestClusteredLightingBackfaceCulling(int, char*[])
{
  const std::vector<Case> cases = {
    { "closed ball", 1, 0.0, [](vtkRenderer*, vtkActor*, vtkSphereSource*) {} },
    { "ball turned inside out (inward normals)", 1, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource* sphere)
      {
        vtkNew<vtkReverseSense> reverse;
        reverse->SetInputConnection(sphere->GetOutputPort());
        reverse->ReverseCellsOn();
        reverse->ReverseNormalsOn();
        vtkPolyDataMapper::SafeDownCast(ball->GetMapper())
          ->SetInputConnection(reverse->GetOutputPort());
      } },
    { "ball mirrored by a negative scale", 1, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*) { ball->SetScale(-1.5, 1.5, 1.2); } },
    { "cube with points of its own per face", 1, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*)
      {
        vtkNew<vtkCubeSource> cube;
        cube->SetXLength(1.6);
        cube->SetYLength(1.2);
        cube->SetZLength(1.4);
        vtkPolyDataMapper::SafeDownCast(ball->GetMapper())
          ->SetInputConnection(cube->GetOutputPort());
        ball->SetOrientation(20, 35, 0);
        ball->SetScale(1.0);
      } },
    { "closed ball, then an image slice seen from behind", 1, 0.0,
      [](vtkRenderer* ren, vtkActor*, vtkSphereSource*)
      {
        // Drawn after the ball in the opaque step by a mapper that sets no face culling of
        // its own: culled too if the ball's culling were left on (it faces away from the
        // camera, so its quad is wound clockwise on screen).
        vtkNew<vtkImageData> image;
        image->SetDimensions(16, 16, 1);
        image->SetSpacing(0.2, 0.2, 1.0);
        image->SetOrigin(-1.5, -1.0, 0.0);
        image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
        for (int j = 0; j < 16; ++j)
        {
          for (int i = 0; i < 16; ++i)
          {
            auto* p = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
            p[0] = static_cast<unsigned char>(16 * i);
            p[1] = static_cast<unsigned char>(16 * j);
            p[2] = 200;
          }
        }
        vtkNew<vtkImageActor> slice;
        slice->GetMapper()->SetInputData(image);
        slice->SetPosition(0.0, 0.0, -2.5);
        slice->RotateY(180.0); // its front faces -z, away from the camera
        ren->AddViewProp(slice);
      } },
    { "open ball (a wedge cut out, seen through the cut)", 0, 0.0,
      [](vtkRenderer*, vtkActor*, vtkSphereSource* sphere)
      {
        sphere->SetStartTheta(10);
        sphere->SetEndTheta(280);
      } },
    { "translucent ball", 0, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*)
      { ball->GetProperty()->SetOpacity(0.5); } },
    { "wireframe ball", 0, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*)
      { ball->GetProperty()->SetRepresentationToWireframe(); } },
    { "ball of triangle strips", 0, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource* sphere)
      {
        vtkNew<vtkStripper> strips;
        strips->SetInputConnection(sphere->GetOutputPort());
        vtkPolyDataMapper::SafeDownCast(ball->GetMapper())
          ->SetInputConnection(strips->GetOutputPort());
      } },
    { "ball with a clipping plane", 0, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*)
      {
        vtkNew<vtkPlane> plane;
        plane->SetOrigin(0.0, 0.2, 0.0);
        plane->SetNormal(0.3, -1.0, 0.2);
        ball->GetMapper()->AddClippingPlane(plane);
      } },
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 2, 0) // VTK 9.2 removed the per-mapper API
    // VTK moves a mapper's own replacements to the actor's shader property when it builds
    // the shaders. The ball's centre is about 7.45 from the eye: its far half, seen from
    // inside, shows where the near half is discarded, unless it is culled.
    { "ball whose mapper discards its near half (VTK 9.0's deprecated per-mapper replacement)", 0,
      0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*)
      {
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
        vtkOpenGLPolyDataMapper::SafeDownCast(ball->GetMapper())
          ->AddShaderReplacement(vtkShader::Fragment, "//VTK::Clip::Impl", true,
            "//VTK::Clip::Impl\n  if (vertexVC.z > -7.45) { discard; }\n", false);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
      } },
#endif
    { "ball with VTK's own back-face culling", 0, 0.0,
      [](vtkRenderer*, vtkActor* ball, vtkSphereSource*)
      { ball->GetProperty()->BackfaceCullingOn(); } },
    { "ball cut by the near plane", 0, 3.9,
      [](vtkRenderer* ren, vtkActor*, vtkSphereSource*)
      {
        // The eye 4.2 from the ball's centre, the near plane 3.9 from the eye: it cuts
        // off the ball's front cap, and its inside shows.
        ren->GetActiveCamera()->SetPosition(0.0, 0.0, 4.2);
        ren->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
      } },
    { "camera inside a sphere", 0, 0.2,
      [](vtkRenderer* ren, vtkActor* ball, vtkSphereSource*)
      {
        ball->SetScale(8.0); // radius 4: the eye, 2.1 from its centre, is inside
        ren->GetActiveCamera()->SetPosition(0.5, 0.5, 2.0);
        ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
      } },
  };
  for (const Case& c : cases)
  {
    for (bool prepass : { true, false })
    {
      RunCase(c, prepass);
    }
  }

  // An animated mesh (modified before every frame) is tested once, then not culled until
  // a frame in which it stays unchanged, in one renderer and where a frame renders several
  // views (one pass shared by two renderers, a stereo pair's two eyes): the mesh is then
  // modified between consecutive renders of each view, but not between the views' renders
  // of one frame, and must still not be tested while it keeps changing (about 0.2 s per
  // million triangles). A mesh that is opened is not culled.
  for (const char* views : { "one renderer", "two renderers sharing the pass", "a stereo pair" })
  {
    Scene scene(160, 120, 50, 3, 24);
    vtkRenderWindow* rw = scene.Window;
    vtkSphereSource* sphere = nullptr;
    FindBall(scene.Renderer, sphere);
    Check(sphere != nullptr, "the test scene's ball comes from a vtkSphereSource");
    vtkNew<vtkRenderer> second;
    const std::string name = views;
    if (name == "a stereo pair")
    {
      rw->SetStereoTypeToSplitViewportHorizontal();
      rw->StereoRenderOn();
    }
    else if (name == "two renderers sharing the pass")
    {
      scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
      second->SetViewport(0.5, 0.0, 1.0, 1.0);
      second->SetActiveCamera(scene.Renderer->GetActiveCamera());
      vtkActorCollection* actors = scene.Renderer->GetActors();
      actors->InitTraversal();
      while (vtkActor* a = actors->GetNextActor())
      {
        second->AddActor(a);
      }
      second->SetPass(scene.Pass);
      rw->AddRenderer(second);
    }
    // The props culled in each view's render, read when its renderer ends.
    struct Record
    {
      vtkClusteredLightingPass* Pass;
      std::vector<int> Culled;
    } record{ scene.Pass, {} };
    vtkNew<vtkCallbackCommand> onEnd;
    onEnd->SetClientData(&record);
    onEnd->SetCallback(
      [](vtkObject*, unsigned long, void* data, void*)
      {
        Record* r = static_cast<Record*>(data);
        r->Culled.push_back(r->Pass->GetNumberOfBackfaceCulledProps());
      });
    scene.Renderer->AddObserver(vtkCommand::EndEvent, onEnd);
    second->AddObserver(vtkCommand::EndEvent, onEnd);
    for (int frame = 0; frame < 6 && sphere; ++frame)
    {
      if (frame < 4)
      {
        sphere->SetRadius(0.5 + 0.01 * frame); // modified before frames 0 to 3
      }
      rw->Render();
    }
    std::string line;
    for (int c : record.Culled)
    {
      line += " " + std::to_string(c);
    }
    std::printf("%s: culled per view render, the ball modified before frames 0 to 3:%s\n", views,
      line.c_str());
    // Per frame (one value per view): culled, then not for three frames, then culled.
    std::vector<int> expected;
    const std::size_t perFrame = name == "one renderer" ? 1 : 2;
    for (int culled : { 1, 0, 0, 0, 1, 1 })
    {
      expected.insert(expected.end(), perFrame, culled);
    }
    Check(record.Culled == expected,
      name +
        ": an animated mesh is tested at its first frame, not while it keeps changing, and "
        "again once it stays unchanged, in every view");
    if (sphere && name == "one renderer")
    {
      sphere->SetEndTheta(300.0); // opened
      rw->Render();
      rw->Render();
      Check(scene.Pass->GetNumberOfBackfaceCulledProps() == 0, "the ball, opened, is not culled");
    }
  }

  // A still frame reuses the last prepass's depths (ReuseDepthPrepass) only if its props
  // cull the same faces: a prepass drawn with other faces may hold a back face's depth
  // where it won a tie, which the culled draw would not meet.
  {
    Scene scene(160, 120, 50, 3, 24);
    vtkRenderWindow* rw = scene.Window;
    vtkClusteredLightingPass* pass = scene.Pass;
    pass->AutomaticDepthPrepassOff();
    pass->DepthPrepassOn();
    pass->ReuseDepthPrepassOn();
    std::vector<int> reused;
    for (bool culling : { true, true, false, false, true, true })
    {
      pass->SetAutomaticBackfaceCulling(culling);
      rw->Render();
      reused.push_back(pass->GetDepthPrepassReused() ? 1 : 0);
    }
    std::printf("prepass depths reused, culling on, on, off, off, on, on: %d %d %d %d %d %d\n",
      reused[0], reused[1], reused[2], reused[3], reused[4], reused[5]);
    Check(reused == std::vector<int>({ 0, 1, 0, 1, 0, 1 }),
      "a still frame reuses the prepass's depths only when the culled faces are the same");
  }
  return ClusteredLightingTest::CheckStatus();
}
