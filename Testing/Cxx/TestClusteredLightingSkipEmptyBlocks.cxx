// SPDX-License-Identifier: BSD-3-Clause
// FarFieldSkipEmptyBlocks: the far field is summed only on the nodes that the visible
// surfaces read (Rendering/Core/vtkClusteredLightingFarFieldBlocks.h). Lights as users
// write them (inverse-square, no radius) over the test scene (a floor and a ball, plain
// mappers), with a multiblock through vtkCompositePolyDataMapper2 (a box per cell of
// each block) and instanced glyphs (vtkGlyph3DMapper: the prop's bounds). Checks that
//  - the first build sums a part of the grid's nodes, and the frame is within the stated
//    bound of brute force at every pixel, with zero false negatives;
//  - switched off, the rest is summed and the image does not change, bit for bit (the
//    nodes surfaces read hold exactly what a whole build puts there);
//  - with moving lights every frame sums the same part again, and the image is the one
//    the whole build gives;
//  - a prop that moves under still lights gets its nodes summed in that frame (a part,
//    not the whole grid), and the image is the whole build's; a prop that does not move
//    and lights that do not change sum nothing;
//  - after the first build only the summed nodes are uploaded (boxes of them into the
//    textures it made), the far specular's bins included: within the bound, and bit for bit
//    the whole build's image;
//  - an actor that draws lines as tubes (fragments off its geometry) asks for every block;
//  - a multisampled framebuffer also sums the blocks the depth-aware clusters reach: a
//    fragment that covers part of its pixel is shaded at the pixel's centre, on its
//    primitive's plane extrapolated past the primitive, and at a silhouette that may be
//    far from every surface, but inside its cluster. The scene of
//    Examples/Python/user_lights.py (a ball on a floor, 2,000 lights as users write them)
//    with 8 samples asked (llvmpipe gives 4), on a finer grid than the default (262,144
//    nodes: smaller blocks, which such a fragment leaves more often): not every block,
//    and within 2 steps of brute force (when only the surfaces' blocks were summed,
//    silhouette pixels were up to 12 steps off); a camera orbiting still lights sums a
//    part of the grid and stays within 2 steps; with a translucent prop (not recorded) and
//    without depth-aware clusters every block;
//    a part of the grid again single-sampled;
//  - PrintSelf names the option and the counts; nothing is reported.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkConeSource.h"
#include "vtkGlyph3DMapper.h"
#include "vtkLineSource.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <cstdio>
#include <sstream>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

/// Renders, calls `change` and renders again; returns the largest difference between the
/// two images.
template <typename Change>
double ChangeInImage(vtkRenderWindow* rw, Change change)
{
  rw->Render();
  const std::vector<float> before = ClusteredLightingTest::CapturePixels(rw);
  change();
  rw->Render();
  return ClusteredLightingTest::CompareImages(ClusteredLightingTest::CapturePixels(rw), before)
    .MaxAbsError;
}

/// Renders, switches FarFieldSkipEmptyBlocks off (the rest of the grid is summed) and
/// renders again; returns whether the two images are the same, bit for bit. Leaves the
/// option on, with every node summed.
bool SameAsWholeBuild(vtkClusteredLightingPass* pass, vtkRenderWindow* rw, const char* what)
{
  const double diff = ChangeInImage(rw, [&] { pass->FarFieldSkipEmptyBlocksOff(); });
  const vtkTypeInt64 rest = pass->GetNumberOfFarFieldNodesBuilt();
  std::printf("%s: %lld more nodes summed for the whole grid; largest difference %g\n", what,
    static_cast<long long>(rest), diff);
  Check(pass->GetNumberOfFarFieldBlocksRead() == pass->GetNumberOfFarFieldBlocks(),
    "switched off, every block counts as read");
  pass->FarFieldSkipEmptyBlocksOn();
  return diff == 0.0 && rest > 0;
}

vtkTypeInt64 GridNodes(vtkClusteredLightingPass* pass)
{
  const int* d = pass->GetFarFieldDimensions();
  return static_cast<vtkTypeInt64>(d[0]) * d[1] * d[2];
}

/// A multisampled framebuffer: every block is summed (see the file's first comment).
void CheckMultisampled()
{
  vtkNew<vtkRenderWindow> rw;
  rw->SetSize(400, 300);
  rw->SetMultiSamples(8);
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  rw->AddRenderer(ren);
  ClusteredLightingScenes::AddBallScene(ren);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(1177);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingScenes::MakeBallLights(lights, 2000, 0.02, random);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  pass->SetFarFieldResolution(262144);
  ren->SetPass(pass);

  rw->Render();
  if (rw->GetMultiSamples() < 2)
  {
    std::printf("this GPU gave the window no multisampling: not checked\n");
    return;
  }
  std::printf("multisampled (%d samples): %lld of %lld blocks read\n", rw->GetMultiSamples(),
    static_cast<long long>(pass->GetNumberOfFarFieldBlocksRead()),
    static_cast<long long>(pass->GetNumberOfFarFieldBlocks()));
  Check(pass->GetFarFieldSkipEmptyBlocks() && pass->GetDepthAwareClustersUsed() &&
      pass->GetNumberOfFarFieldBlocksRead() < pass->GetNumberOfFarFieldBlocks(),
    "multisampled: the surfaces' blocks and the recorded fragments', not every block");
  auto checkBrute = [&](const char* what)
  {
    const std::vector<float> clustered = ClusteredLightingTest::CapturePixels(rw);
    const ClusteredLightingTest::ImageComparison c = ClusteredLightingTest::CompareImages(
      clustered, ClusteredLightingTest::CaptureBruteForce(pass, rw));
    ClusteredLightingTest::PrintComparison(what, c);
    Check(c.MaxAbsError <= 2.0 / 255.0 + 1e-6, what);
  };
  checkBrute("multisampled: within 2 steps of brute force");

  // The camera orbits, the lights stay: the recorded fragments reach other blocks, which
  // are summed in that frame (a part of the grid, not all of it), and the image is as
  // close. First a light moves a little, so that the far field is built afresh on the
  // blocks read (the brute-force render above has no clusters, so no marks of its
  // fragments, and summed every block).
  double p[3];
  lights->GetPosition(0, p);
  lights->SetPosition(0, p[0] + 0.01, p[1], p[2]);
  rw->Render();
  const vtkTypeInt64 total = GridNodes(pass);
  const vtkTypeInt64 first = pass->GetNumberOfFarFieldNodesBuilt();
  std::printf("a light moved: %lld of %lld nodes summed\n", static_cast<long long>(first),
    static_cast<long long>(total));
  Check(first > 0 && first < total / 2, "a light moved: a part of the grid is summed");
  vtkCamera* camera = ren->GetActiveCamera();
  bool parts = true;
  vtkTypeInt64 extended = 0;
  for (int step = 0; step < 3; ++step)
  {
    camera->Azimuth(25.0);
    camera->Elevation(step == 1 ? -12.0 : 6.0);
    camera->OrthogonalizeViewUp();
    ren->ResetCameraClippingRange();
    rw->Render();
    const vtkTypeInt64 built = pass->GetNumberOfFarFieldNodesBuilt();
    std::printf("orbit %d: %lld of %lld nodes summed, %lld of %lld blocks read\n", step,
      static_cast<long long>(built), static_cast<long long>(total),
      static_cast<long long>(pass->GetNumberOfFarFieldBlocksRead()),
      static_cast<long long>(pass->GetNumberOfFarFieldBlocks()));
    parts = parts && built < total / 2 &&
      pass->GetNumberOfFarFieldBlocksRead() < pass->GetNumberOfFarFieldBlocks();
    extended += built;
  }
  Check(
    parts && extended > 0, "an orbiting camera sums the nodes its recorded fragments reach anew");
  checkBrute("multisampled, after the orbit: within 2 steps of brute force");

  // A translucent prop's fragments are not in the prepass's record, and multisampled they
  // are shaded off their surfaces too: every block while one is visible.
  vtkNew<vtkSphereSource> glass;
  glass->SetCenter(1.2, -0.5, 0.8);
  glass->SetRadius(0.4);
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glass->GetOutputPort());
  vtkNew<vtkActor> glassActor;
  glassActor->SetMapper(glassMapper);
  glassActor->GetProperty()->SetOpacity(0.5);
  ren->AddActor(glassActor);
  rw->Render();
  Check(pass->GetNumberOfFarFieldBlocksRead() == pass->GetNumberOfFarFieldBlocks(),
    "multisampled with a translucent prop: every block is read");
  ren->RemoveActor(glassActor);
  rw->Render();
  Check(pass->GetNumberOfFarFieldBlocksRead() < pass->GetNumberOfFarFieldBlocks(),
    "multisampled, the translucent prop gone: a part again");

  // Without depth-aware clusters nothing says where the extrapolated fragments are:
  // every block.
  pass->DepthAwareClustersOff();
  rw->Render();
  Check(pass->GetNumberOfFarFieldBlocksRead() == pass->GetNumberOfFarFieldBlocks(),
    "multisampled without depth-aware clusters: every block is read");
  pass->DepthAwareClustersOn();

  rw->SetMultiSamples(0);
  rw->Render();
  std::printf("single-sampled: %lld of %lld blocks read\n",
    static_cast<long long>(pass->GetNumberOfFarFieldBlocksRead()),
    static_cast<long long>(pass->GetNumberOfFarFieldBlocks()));
  Check(pass->GetNumberOfFarFieldBlocksRead() < pass->GetNumberOfFarFieldBlocks() / 2,
    "single-sampled: less than half of the blocks again");
}
}

int TestClusteredLightingSkipEmptyBlocks(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 240, 180);

  // Two spheres through the composite mapper, and glyphs, inside the floor's box.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  for (int b = 0; b < 2; ++b)
  {
    vtkNew<vtkSphereSource> s;
    s->SetCenter(b ? 2.0 : -2.2, -0.6, b ? 1.2 : 0.8);
    s->SetRadius(0.35);
    s->Update();
    blocks->SetBlock(b, s->GetOutput());
  }
  vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(compositeMapper);
  ren->AddActor(compositeActor);
  vtkNew<vtkPointSource> points;
  points->SetCenter(-1.5, -0.7, -1.5);
  points->SetRadius(0.4);
  points->SetNumberOfPoints(12);
  points->SetRandomSequence(nullptr);
  vtkNew<vtkConeSource> cone;
  cone->SetHeight(0.3);
  cone->SetRadius(0.12);
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputConnection(points->GetOutputPort());
  glyphMapper->SetSourceConnection(cone->GetOutputPort());
  glyphMapper->ScalingOff();
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphMapper);
  ren->AddActor(glyphActor);

  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, 400, 0.03, 5);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);

  // 1. The first build sums a part of the grid; the frame is within its bound.
  rw->Render();
  const vtkTypeInt64 total = GridNodes(pass);
  const vtkTypeInt64 part = pass->GetNumberOfFarFieldNodesBuilt();
  std::printf("grid %lld nodes, %lld summed; %lld of %lld blocks read\n",
    static_cast<long long>(total), static_cast<long long>(part),
    static_cast<long long>(pass->GetNumberOfFarFieldBlocksRead()),
    static_cast<long long>(pass->GetNumberOfFarFieldBlocks()));
  Check(pass->GetFarFieldSkipEmptyBlocks() && part > 0 && part < total / 2 &&
      pass->GetNumberOfFarFieldBlocksRead() < pass->GetNumberOfFarFieldBlocks(),
    "the first build sums less than half of the grid's nodes");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "skip empty blocks") == 0,
    "within the stated bound of brute force at every pixel, zero false negatives");
  Check(SameAsWholeBuild(pass, rw, "first build"),
    "the whole grid's build gives the same image, bit for bit");

  // 2. Moving lights: every frame sums the same part again.
  bool samePart = true;
  for (int frame = 0; frame < 3; ++frame)
  {
    double p[3];
    lights->GetPosition(frame, p);
    lights->SetPosition(frame, p[0] + 0.1, p[1], p[2] - 0.05);
    rw->Render();
    samePart = samePart && pass->GetNumberOfFarFieldNodesBuilt() == part;
  }
  Check(samePart, "moving lights sum the same part every frame");
  // Every light elsewhere: the textures made by the first build now hold what was
  // uploaded box by box, and nothing of the first lights may be left where surfaces read.
  ClusteredLightingTest::MakeUserLights(lights, 400, 0.03, 6);
  rw->Render();
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "new lights") == 0,
    "other lights (boxes uploaded): within the bound of brute force");
  lights->SetPosition(3, 0.3, 0.2, 0.1);
  Check(SameAsWholeBuild(pass, rw, "moved lights"),
    "after the lights moved: the whole grid's image, bit for bit");

  // 3. Still lights and props: nothing is summed. A prop that moves: its new nodes only.
  lights->SetPosition(4, -0.3, 0.4, 0.2); // a new build of the part
  rw->Render();
  rw->Render();
  Check(pass->GetNumberOfFarFieldNodesBuilt() == 0, "nothing changed: nothing summed");
  vtkActor* ball = nullptr;
  {
    vtkActorCollection* actors = ren->GetActors();
    actors->InitTraversal();
    actors->GetNextActor(); // the floor
    ball = actors->GetNextActor();
  }
  ball->SetPosition(1.2, 0.0, -0.8);
  rw->Render();
  const vtkTypeInt64 moved = pass->GetNumberOfFarFieldNodesBuilt();
  std::printf("the ball moved: %lld nodes summed\n", static_cast<long long>(moved));
  Check(moved > 0 && moved < part, "a moved prop sums its new nodes, fewer than a build");
  Check(SameAsWholeBuild(pass, rw, "moved ball"),
    "after the ball moved: the whole grid's image, bit for bit");

  // 4. The far specular's bins (the ball is shiny): made whole, then uploaded box by box
  // for other lights.
  pass->FarFieldSpecularBinsOn();
  rw->Render();
  Check(pass->GetFarFieldSpecularBinsUsed(), "the ball's specular takes the bins");
  ClusteredLightingTest::MakeUserLights(lights, 400, 0.03, 7);
  rw->Render();
  Check(pass->GetNumberOfFarFieldNodesBuilt() > 0 &&
      pass->GetNumberOfFarFieldNodesBuilt() < GridNodes(pass) / 2,
    "other lights: a part summed again");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "bins, other lights") == 0,
    "the bins uploaded box by box: within the bound of brute force");
  {
    // Bins made afresh (switched off, which releases their texture, and on: uploaded
    // whole) for the same lights give the same image.
    const double diff = ChangeInImage(rw,
      [&]
      {
        pass->FarFieldSpecularBinsOff();
        rw->Render();
        pass->FarFieldSpecularBinsOn();
      });
    std::printf("bins made afresh: largest difference %g\n", diff);
    Check(diff == 0.0, "the bins uploaded box by box: the image of bins made afresh, bit for bit");
  }
  lights->SetPosition(6, -0.5, 0.3, 0.4);
  Check(SameAsWholeBuild(pass, rw, "bins"), "with the bins: the whole grid's image, bit for bit");
  pass->FarFieldSpecularBinsOff();

  // 5. Lines drawn as tubes: every block.
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-2.0, -0.5, 2.0);
  line->SetPoint2(2.0, -0.5, 2.0);
  vtkNew<vtkPolyDataMapper> lineMapper;
  lineMapper->SetInputConnection(line->GetOutputPort());
  vtkNew<vtkActor> tube;
  tube->SetMapper(lineMapper);
  tube->GetProperty()->SetLineWidth(6.0);
  tube->GetProperty()->RenderLinesAsTubesOn();
  ren->AddActor(tube);
  rw->Render();
  Check(pass->GetNumberOfFarFieldBlocksRead() == pass->GetNumberOfFarFieldBlocks(),
    "lines drawn as tubes: every block is read");
  // Tubes write their own depths, which turns depth-aware clusters off, said once.
  Check(messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("Depth-aware clusters are off") != std::string::npos,
    "the tubes' one warning: depth-aware clusters off");
  messages->Warnings.clear();
  ren->RemoveActor(tube);
  rw->Render();
  Check(pass->GetNumberOfFarFieldBlocksRead() < pass->GetNumberOfFarFieldBlocks(),
    "without them: a part again");

  // 6. A multisampled framebuffer (its own window and pass).
  CheckMultisampled();

  std::ostringstream printed;
  pass->Print(printed);
  Check(printed.str().find("FarFieldSkipEmptyBlocks: On") != std::string::npos &&
      printed.str().find("NumberOfFarFieldBlocksRead: ") != std::string::npos,
    "PrintSelf names the option and the blocks read");
  Check(messages->Errors.empty() && messages->Warnings.empty(), "nothing else reported");
  return ClusteredLightingTest::CheckStatus();
}
