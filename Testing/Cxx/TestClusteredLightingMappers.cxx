// SPDX-License-Identifier: BSD-3-Clause
// The mappers VTK apps use for surfaces, lit by 1,024 clustered lights:
//  - vtkPolyDataMapper (a floor),
//  - vtkCompositePolyDataMapper2 (a multiblock dataset of spheres, as ParaView renders it),
//  - vtkGlyph3DMapper (instanced cone glyphs),
//  - a translucent actor, with depth peeling on.
// Each actor sits in its own quarter of the image; the test checks that clustered lights
// light each of them (quarter brightness with and without the lights), that clustered
// matches brute force within the derived cutoff tolerance, zero false negatives of the
// assignment, and no NaN pixel.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkConeSource.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkSphereSource.h"

#include <random>

namespace
{
// The translucent step of an application's own delegate (as ParaView's view sets one):
// the renderer's translucency, depth peeling here.
class RendererTranslucency : public vtkRenderPass
{
public:
  static RendererTranslucency* New();
  vtkTypeMacro(RendererTranslucency, vtkRenderPass)
  void Render(const vtkRenderState* s) override
  {
    s->GetRenderer()->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
  }
};
vtkStandardNewMacro(RendererTranslucency);

double QuarterMean(const std::vector<float>& px, int w, int h, int qx, int qy)
{
  double sum = 0.0;
  std::size_t n = 0;
  for (int y = qy * h / 2; y < (qy + 1) * h / 2; ++y)
  {
    for (int x = qx * w / 2; x < (qx + 1) * w / 2; ++x)
    {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * w + x);
      sum += px[i] + px[i + 1] + px[i + 2];
      ++n;
    }
  }
  return sum / (3.0 * n);
}
}

int TestClusteredLightingMappers(int argc, char* argv[])
{
  const int w = 300, h = 300;
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(w, h);
  renWin->SetMultiSamples(0);
  renWin->SetAlphaBitPlanes(1);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AutomaticLightCreationOff();
  ren->SetUseDepthPeeling(1);
  ren->SetMaximumNumberOfPeels(8);
  ren->SetOcclusionRatio(0.0);
  renWin->AddRenderer(ren);

  // Lower left: plain mapper (a floor patch).
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2, -2, 0);
  plane->SetPoint1(0, -2, 0);
  plane->SetPoint2(-2, 0, 0);
  plane->SetResolution(20, 20);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  ren->AddActor(planeActor);

  // Lower right: multiblock through the composite mapper.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(4);
  for (int b = 0; b < 4; ++b)
  {
    vtkNew<vtkSphereSource> s;
    s->SetCenter(0.5 + (b % 2), -1.5 + (b / 2), 0.0);
    s->SetRadius(0.45);
    s->SetThetaResolution(32);
    s->SetPhiResolution(32);
    s->Update();
    blocks->SetBlock(b, s->GetOutput());
  }
  vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(compositeMapper);
  compositeActor->GetProperty()->SetSpecular(0.4);
  compositeActor->GetProperty()->SetSpecularPower(20);
  ren->AddActor(compositeActor);

  // Upper left: glyphs.
  vtkNew<vtkPointSource> points;
  points->SetCenter(-1, 1, 0);
  points->SetRadius(0.8);
  points->SetNumberOfPoints(60);
  points->SetRandomSequence(nullptr);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(16);
  cone->SetHeight(0.35);
  cone->SetRadius(0.15);
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputConnection(points->GetOutputPort());
  glyphMapper->SetSourceConnection(cone->GetOutputPort());
  glyphMapper->ScalingOff();
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphMapper);
  ren->AddActor(glyphActor);

  // Upper right: translucent sphere over an opaque backdrop.
  vtkNew<vtkSphereSource> glass;
  glass->SetCenter(1, 1, 0.3);
  glass->SetRadius(0.8);
  glass->SetThetaResolution(48);
  glass->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glass->GetOutputPort());
  vtkNew<vtkActor> glassActor;
  glassActor->SetMapper(glassMapper);
  glassActor->GetProperty()->SetOpacity(0.5);
  glassActor->GetProperty()->SetColor(0.6, 0.8, 1.0);
  ren->AddActor(glassActor);
  vtkNew<vtkPlaneSource> backdrop;
  backdrop->SetOrigin(0, 0, -0.6);
  backdrop->SetPoint1(2, 0, -0.6);
  backdrop->SetPoint2(0, 2, -0.6);
  vtkNew<vtkPolyDataMapper> backdropMapper;
  backdropMapper->SetInputConnection(backdrop->GetOutputPort());
  vtkNew<vtkActor> backdropActor;
  backdropActor->SetMapper(backdropMapper);
  ren->AddActor(backdropActor);

  // 1,024 lights in a slab in front of everything; influence radius 1 at the cutoff.
  // The same lights at zero intensity give the unlit reference.
  vtkNew<vtkClusteredLightSet> lights, unlit;
  lights->SetNumberOfLights(1024);
  unlit->SetNumberOfLights(1024);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 1024; ++i)
  {
    const double p[3] = { -2 + 4 * U(rng), -2 + 4 * U(rng), 0.05 + 1.25 * U(rng) };
    lights->SetPosition(i, p[0], p[1], p[2]);
    lights->SetColor(i, 0.3 + 0.7 * U(rng), 0.3 + 0.7 * U(rng), 0.3 + 0.7 * U(rng));
    lights->SetIntensity(i, 1.0);
    lights->SetAttenuation(i, 1.0, 0.0, 1023.0);
    unlit->SetPosition(i, p[0], p[1], p[2]);
    unlit->SetIntensity(i, 0.0);
  }
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);

  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0, 0, 6);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewAngle(38);
  ren->ResetCameraClippingRange();
  renWin->Render();

  int status = EXIT_SUCCESS;
  // Lit by the clustered lights: every quarter brighter with them than without.
  const std::vector<float> lit = ClusteredLightingTest::CapturePixels(renWin);
  pass->RemoveAllLightSets();
  pass->AddLightSet(unlit);
  renWin->Render();
  const std::vector<float> dark = ClusteredLightingTest::CapturePixels(renWin);
  pass->RemoveAllLightSets();
  pass->AddLightSet(lights);
  const char* names[2][2] = { { "plain mapper", "composite mapper" },
    { "glyph mapper", "translucent actor (depth peeling)" } };
  for (int qy = 0; qy < 2; ++qy)
  {
    for (int qx = 0; qx < 2; ++qx)
    {
      const double with = QuarterMean(lit, w, h, qx, qy);
      const double without = QuarterMean(dark, w, h, qx, qy);
      std::printf(
        "%s: mean %.4f with clustered lights, %.4f without\n", names[qy][qx], with, without);
      if (!(with > 2.0 * without + 0.01))
      {
        std::printf("%s is not lit by the clustered lights\n", names[qy][qx]);
        status = EXIT_FAILURE;
      }
    }
  }
  renWin->Render();
  // Translucent surfaces lie in front of the opaque depth: maximize the tail along rays.
  if (ClusteredLightingTest::CheckClusteredFrame(pass, renWin, ren, 1.4, "mappers", 8) != 0)
  {
    status = EXIT_FAILURE;
  }

  // Counting shaded fragments (MeasureTimings) draws the same image: depth peeling counts
  // samples with the same kind of occlusion query, of which only one can run, so none of
  // the pass's runs while it peels, and the translucent part is reported not measured.
  // Two more translucent spheres in the glass make layers that take more than one peel,
  // and a high occlusion ratio makes the peeling stop by its query's count (a query that
  // fails shows: the peeling goes on), both undone before the regression image.
  ren->SetOcclusionRatio(0.5);
  vtkNew<vtkActor> layers[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkSphereSource> layer;
    layer->SetCenter(i ? 0.7 : 1.3, i ? 0.9 : 1.2, i ? 1.0 : 0.8);
    layer->SetRadius(i ? 0.4 : 0.5);
    layer->SetThetaResolution(32);
    layer->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> layerMapper;
    layerMapper->SetInputConnection(layer->GetOutputPort());
    layers[i]->SetMapper(layerMapper);
    layers[i]->GetProperty()->SetOpacity(0.5);
    layers[i]->GetProperty()->SetColor(i ? 1.0 : 0.4, 0.5, i ? 0.3 : 1.0);
    ren->AddActor(layers[i]);
  }
  renWin->Render();
  const std::vector<float> uncounted = ClusteredLightingTest::CapturePixels(renWin);
  pass->SetMeasureTimings(true);
  renWin->Render();
  pass->SetMeasureTimings(false);
  const std::vector<float> counted = ClusteredLightingTest::CapturePixels(renWin);
  const auto cmp = ClusteredLightingTest::CompareImages(counted, uncounted);
  ClusteredLightingTest::PrintComparison("depth peeling, fragments counted vs not", cmp);
  const double opaque = pass->GetShadedOpaqueFragmentsPerVisiblePixel();
  std::printf("depth peeling: shaded fragments per visible pixel %.4f opaque, %.4f "
              "translucent, %.4f in all\n",
    opaque, pass->GetShadedTranslucentFragmentsPerVisiblePixel(),
    pass->GetShadedFragmentsPerVisiblePixel());
  if (!(ren->GetLastRenderingUsedDepthPeeling() && cmp.MaxAbsError == 0.0 && opaque > 0.999 &&
        opaque < 1.01 && pass->GetShadedTranslucentFragmentsPerVisiblePixel() == -1.0 &&
        pass->GetShadedFragmentsPerVisiblePixel() == -1.0))
  {
    std::printf("depth peeling: counting fragments changed the image, or its counts are "
                "wrong\n");
    status = EXIT_FAILURE;
  }

  // Through a delegate of the application's, the pass counts nothing (the delegate's
  // translucency may run queries of its own): the counts are 0 and the image is the same.
  vtkSmartPointer<vtkRenderPass> own = pass->GetDelegatePass();
  vtkNew<vtkRenderStepsPass> foreign;
  vtkNew<RendererTranslucency> foreignTranslucency;
  foreign->SetTranslucentPass(foreignTranslucency);
  pass->SetDelegatePass(foreign);
  renWin->Render();
  const std::vector<float> foreignUncounted = ClusteredLightingTest::CapturePixels(renWin);
  pass->SetMeasureTimings(true);
  renWin->Render();
  pass->SetMeasureTimings(false);
  const auto foreignCmp = ClusteredLightingTest::CompareImages(
    ClusteredLightingTest::CapturePixels(renWin), foreignUncounted);
  ClusteredLightingTest::PrintComparison(
    "an application's delegate, fragments counted vs not", foreignCmp);
  std::printf("an application's delegate: shaded fragments per visible pixel %.4f opaque, "
              "%.4f translucent\n",
    pass->GetShadedOpaqueFragmentsPerVisiblePixel(),
    pass->GetShadedTranslucentFragmentsPerVisiblePixel());
  if (!(foreignCmp.MaxAbsError == 0.0 && pass->GetShadedOpaqueFragmentsPerVisiblePixel() == 0.0 &&
        pass->GetShadedTranslucentFragmentsPerVisiblePixel() == 0.0))
  {
    std::printf("an application's delegate: counting changed the image, or counted\n");
    status = EXIT_FAILURE;
  }
  pass->ReleaseGraphicsResources(renWin);
  pass->SetDelegatePass(own);
  for (vtkActor* layer : layers)
  {
    ren->RemoveActor(layer);
  }
  ren->SetOcclusionRatio(0.0);

  renWin->Render();
  return ClusteredLightingTest::FinishImageTest(argc, argv, renWin, status);
}
