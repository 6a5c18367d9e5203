// SPDX-License-Identifier: BSD-3-Clause
// The count views (DEBUG_EVALUATED_COUNT, DEBUG_HEAT_MAP) and the statistics the pass reads
// from them (GetMeanLightsEvaluatedPerPixel, GetMeanLightsReachingPerPixel,
// GetMaximumLightsEvaluatedPerPixel, GetNumberOfCountedPixels, GetHeatMapScale) count the
// lights of the scene's lit surfaces, whatever else the frame shows:
//  - 2D actors (a caption and a filled 2D polygon over the sphere), which the overlay step draws
//  with
//    a depth of their own: the same counts, pixels and count image as without them (before:
//    a caption read as thousands of lights per pixel); the heat map itself still shows
//    them;
//  - points, and lines without normals, which VTK does not light, over the background:
//    visible pixels with 0 lights (the same sum of counts over more pixels, the same
//    maximum), not their colour (white read as 65,535 lights, the heat map scaled to it);
//  - a texture on the floor (VTK multiplies the lit colour by the texture after the
//    lighting code): the same counts as without it (the lights are too dim to saturate a
//    fragment, so both walk every light).
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor2D.h"
#include "vtkClusteredLightSet.h"
#include "vtkImageData.h"
#include "vtkLineSource.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty2D.h"
#include "vtkRegularPolygonSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTexture.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

struct Counts
{
  double Evaluated = 0.0;
  double Reaching = 0.0;
  int Maximum = 0;
  vtkIdType Pixels = 0;
  std::vector<float> Image;
};

/// One frame of DEBUG_EVALUATED_COUNT: the pass's statistics and the count image.
Counts Count(vtkRenderWindow* rw, vtkClusteredLightingPass* pass, const char* what)
{
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  rw->Render();
  Counts c;
  c.Evaluated = pass->GetMeanLightsEvaluatedPerPixel();
  c.Reaching = pass->GetMeanLightsReachingPerPixel();
  c.Maximum = pass->GetMaximumLightsEvaluatedPerPixel();
  c.Pixels = pass->GetNumberOfCountedPixels();
  c.Image = ClusteredLightingTest::CapturePixels(rw);
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  std::printf("%s: %.4f evaluated / %.4f reaching per pixel over %lld pixels, at most %d\n", what,
    c.Evaluated, c.Reaching, static_cast<long long>(c.Pixels), c.Maximum);
  return c;
}

bool SameCounts(const Counts& a, const Counts& b)
{
  return a.Evaluated == b.Evaluated && a.Reaching == b.Reaching && a.Maximum == b.Maximum &&
    a.Pixels == b.Pixels;
}

/// The heat map scaled to the data: its scale, and its image.
double HeatMapScale(vtkRenderWindow* rw, vtkClusteredLightingPass* pass, std::vector<float>* image)
{
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_HEAT_MAP);
  rw->Render();
  if (image)
  {
    *image = ClusteredLightingTest::CapturePixels(rw);
  }
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  return pass->GetHeatMapScale();
}

/// An actor drawing `source` as `representation` (points 6 pixels wide, lines 3).
vtkSmartPointer<vtkActor> MakeUnlitActor(vtkAlgorithm* source, int representation)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentation(representation);
  actor->GetProperty()->SetPointSize(6.0f);
  actor->GetProperty()->SetLineWidth(3.0f);
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  return actor;
}
}

int TestClusteredLightingCountViews(int, char*[])
{
  ClusteredLightingTest::OutputCapture output;
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff(); // no headlight: nothing saturates a fragment
  ClusteredLightingTest::SetUpTestScene(rw, ren, 240, 180);
  // Lights with an explicit range (no far field, whose grid would follow the scene's
  // bounds), and no depth prepass (whose depth-aware clusters follow what the frame
  // shows): a pixel's counts depend on the lights and the cluster grid alone.
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingScenes::LightParameters params;
  params.Intensity = 0.1; // dim enough that no fragment saturates
  params.Quadratic = 1.0;
  ClusteredLightingTest::MakeTestLights(lights, 60, params, 11);
  for (vtkIdType i = 0; i < lights->GetNumberOfLights(); ++i)
  {
    lights->SetRadius(i, 1.5);
  }
  vtkNew<vtkClusteredLightingPass> pass;
  pass->SetFalloffToWindowed();
  pass->AutomaticDepthPrepassOff();
  pass->DepthPrepassOff();
  pass->DepthAwareClustersOff();
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);

  const Counts plain = Count(rw, pass, "the lit scene");
  std::vector<float> plainHeat;
  const double plainScale = HeatMapScale(rw, pass, &plainHeat);
  Check(plain.Pixels > 10000 && plain.Evaluated > 2.0 && plain.Reaching > 0.5 &&
      plain.Maximum <= 60 && plainScale == plain.Maximum,
    "the lit scene: counts between 0 and the 60 lights, the heat map scaled to the maximum");

  // 1. 2D actors over the sphere: a caption and a filled polygon (a legend's box).
  vtkNew<vtkTextActor> caption;
  caption->SetInput("COUNTS");
  caption->GetTextProperty()->SetFontSize(36);
  caption->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  caption->SetPosition(50, 80);
  vtkNew<vtkRegularPolygonSource> box;
  box->SetNumberOfSides(4);
  box->SetCenter(120.0, 120.0, 0.0);
  box->SetRadius(25.0);
  vtkNew<vtkPolyDataMapper2D> boxMapper;
  boxMapper->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkActor2D> box2D;
  box2D->SetMapper(boxMapper);
  box2D->GetProperty()->SetColor(0.9, 0.9, 0.2);
  ren->AddViewProp(caption);
  ren->AddViewProp(box2D);
  const Counts with2D = Count(rw, pass, "with a caption and a 2D polygon");
  Check(SameCounts(with2D, plain) &&
      ClusteredLightingTest::CompareImages(with2D.Image, plain.Image).MaxAbsError == 0.0,
    "2D actors: the counts, pixels and count image of the scene without them");
  std::vector<float> heat2D;
  const double scale2D = HeatMapScale(rw, pass, &heat2D);
  Check(scale2D == plainScale &&
      ClusteredLightingTest::CompareImages(heat2D, plainHeat).MaxAbsError > 0.0,
    "2D actors: the heat map's scale as without them (" + std::to_string(scale2D) +
      "), and the heat map shows them");
  ren->RemoveViewProp(caption);
  ren->RemoveViewProp(box2D);

  // 2. Unlit points and lines (no normals) over the background beyond the floor's far
  // edge, nearer than the floor's far corners (the slicing range stays).
  vtkNew<vtkPointSource> points;
  points->SetCenter(-1.0, 1.5, -2.5);
  points->SetRadius(0.4);
  points->SetNumberOfPoints(30);
  vtkNew<vtkLineSource> line;
  line->SetPoint1(0.5, 1.2, -2.5);
  line->SetPoint2(2.0, 1.8, -2.5);
  vtkSmartPointer<vtkActor> pointActor = MakeUnlitActor(points, VTK_POINTS);
  vtkSmartPointer<vtkActor> lineActor = MakeUnlitActor(line, VTK_SURFACE);
  ren->AddActor(pointActor);
  ren->AddActor(lineActor);
  const Counts unlit = Count(rw, pass, "with unlit points and lines");
  const double plainSum = plain.Evaluated * static_cast<double>(plain.Pixels);
  const double unlitSum = unlit.Evaluated * static_cast<double>(unlit.Pixels);
  const double plainReached = plain.Reaching * static_cast<double>(plain.Pixels);
  const double unlitReached = unlit.Reaching * static_cast<double>(unlit.Pixels);
  Check(unlit.Pixels > plain.Pixels + 100 && std::abs(unlitSum - plainSum) < 1e-6 * plainSum &&
      std::abs(unlitReached - plainReached) < 1e-6 * plainReached && unlit.Maximum == plain.Maximum,
    "unlit points and lines: " + std::to_string(unlit.Pixels - plain.Pixels) +
      " more pixels, each with 0 lights evaluated and reaching (the same sums of counts, " +
      std::to_string(unlitSum) + " and " + std::to_string(plainSum) + ", the same maximum)");
  Check(HeatMapScale(rw, pass, nullptr) == plainScale,
    "unlit points and lines: the heat map's scale as without them");
  ren->RemoveActor(pointActor);
  ren->RemoveActor(lineActor);

  // 3. A texture on the floor (the plane source's texture coordinates): grey squares at
  // half and three quarters of full intensity.
  vtkNew<vtkImageData> checker;
  checker->SetDimensions(8, 8, 1);
  checker->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 8; ++x)
    {
      auto* texel = static_cast<unsigned char*>(checker->GetScalarPointer(x, y, 0));
      texel[0] = texel[1] = texel[2] = (x + y) % 2 ? 128 : 192;
    }
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(checker);
  vtkActor* floor = vtkActor::SafeDownCast(ren->GetActors()->GetItemAsObject(0));
  floor->SetTexture(texture);
  // VTK 9.1 uploads a mapper's texture coordinates when the mapper or its input changes,
  // not when its actor gets a texture (stock VTK would not show it either).
  floor->GetMapper()->Modified();
  const Counts textured = Count(rw, pass, "with a textured floor");
  Check(SameCounts(textured, plain),
    "a texture: the counts of the scene without it (the texture scales the lit colour, not "
    "the counts)");
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  rw->Render();
  const std::vector<float> litTextured = ClusteredLightingTest::CapturePixels(rw);
  floor->SetTexture(nullptr);
  floor->GetMapper()->Modified();
  rw->Render();
  const double shown =
    ClusteredLightingTest::CompareImages(litTextured, ClusteredLightingTest::CapturePixels(rw))
      .MaxAbsError;
  Check(shown > 0.05,
    "a texture: the lit frame shows it (up to " + std::to_string(shown * 255.0) + " steps)");

  Check(messages->Warnings.empty() && messages->Errors.empty(), "no warning or error");
  const std::string printed = output.Finish();
  Check(printed.empty(), "nothing reached VTK's output window: " + printed);
  return ClusteredLightingTest::CheckStatus();
}
