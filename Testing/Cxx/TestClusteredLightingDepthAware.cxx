// SPDX-License-Identifier: BSD-3-Clause
// The depth prepass and depth-aware clusters (issue 12), against the pass without them:
//  - lights with an explicit radius and windowed falloff (each light's contribution is
//    exactly 0 outside its radius, so dropping a light that does not reach changes no
//    pixel): the image with depth-aware clusters equals the image without them, bit for
//    bit, and the GPU lists have zero false negatives against the double-precision
//    reference cut to the recorded depths;
//  - every visible pixel's exact view depth (read back after the frame and unprojected)
//    lies inside the recorded interval of the cluster the shader computes for it;
//  - in the hard placements: occluders, a parallel projection, a camera inside lights, lines
//    and points (a fragment positioned up to half a width from its pixel), a
//    scene far from the origin, translucent geometry, VTK's coincident-topology offsets
//    (edges on a surface), two viewports;
//  - the culling helps: fewer lights evaluated per pixel than without (a count that could
//    fail), most clusters empty, and the slices span the visible depths;
//  - the prepass shades each visible pixel once: fragments passing the depth test per
//    visible pixel are 1.0 with it, more than 1 without it in an occluding scene; the
//    fragments of translucent draws are counted apart (the opaque part stays 1.0);
//  - a mapper that writes its own depth (points as spheres) turns depth-aware clusters
//    off with one warning, and the image stays correct; splats (vtkPointGaussianMapper),
//    which the prepass leaves out, change nothing;
//  - with 40 positional vtkLights in the renderer (clustered), the prepass and the shading
//    render use the same programs: no shader is rebuilt from frame to frame;
//  - in a multisampled window (VTK's default asks for 8 samples) the same checks pass with
//    the recorded per-pixel ranges, the pass counts the lights evaluated per pixel there
//    and the lights reaching it (one sample of each pixel; both means agree with the same
//    frame's single-sampled ones within 2%), translucent geometry there included (the
//    tiles of its screen rectangle keep every cluster, the others are cut to the depths).
#include "ClusteredLightingTestUtilities.h"
#include "vtkClusteredLightingInspector.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkLight.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPointSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace
{
int Failed = 0;

void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  Failed += ok ? 0 : 1;
}

/// n lights with an explicit radius in a box around AddTestScene (shifted by `offset`).
void MakeLights(vtkClusteredLightSet* lights, int n, double radius, const double offset[3])
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  lights->SetNumberOfLights(n);
  for (int i = 0; i < n; ++i)
  {
    lights->SetPosition(i, offset[0] - 3.0 + 6.0 * u(rng), offset[1] - 0.9 + 2.7 * u(rng),
      offset[2] - 3.0 + 6.0 * u(rng));
    lights->SetColor(i, 0.3 + 0.7 * u(rng), 0.3 + 0.7 * u(rng), 0.3 + 0.7 * u(rng));
    lights->SetIntensity(i, 0.6);
    lights->SetRadius(i, radius);
  }
}

/// Every visible pixel's exact depth inside its cluster's recorded interval, and its
/// centre inside the cluster's recorded rectangle.
int CountPixelsOutside(vtkClusteredLightingPass* pass, vtkRenderWindow* rw, vtkRenderer* ren)
{
  vtkClusteredLightingInspector inspect(pass);
  const vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(ren);
  if (!frame.DepthBounds.Valid)
  {
    return -1;
  }
  int w = 0, h = 0;
  const std::vector<float> z = ClusteredLightingTest::CaptureDepth(rw, ren, w, h);
  const glm::dmat4 inverse = glm::inverse(frame.VCDC);
  const vtkClusteredLighting::ClusterGridParams& g = frame.Grid;
  int outside = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const float d = z[static_cast<std::size_t>(y) * w + x];
      if (!(d < 1.0f))
      {
        continue;
      }
      const glm::dvec3 p = ClusteredLightingTest::UnprojectPixel(x, y, d, w, h, inverse);
      const double depth = -p.z;
      const int tx = vtkClusteredLighting::ComputeTileIndex(x + 0.5, w, g.TilesX);
      const int ty = vtkClusteredLighting::ComputeTileIndex(y + 0.5, h, g.TilesY);
      const int s = vtkClusteredLighting::ComputeSliceIndex(depth, g);
      double lo = 0.0, hi = 0.0, rect[4];
      const double nx = 2.0 * (x + 0.5) / w - 1.0, ny = 2.0 * (y + 0.5) / h - 1.0;
      if (!frame.DepthBounds.GetInterval(tx, ty, s, g.TilesX, lo, hi) || depth < lo || depth > hi ||
        !frame.DepthBounds.GetRect(tx, ty, s, g.TilesX, rect) || nx < rect[0] || nx > rect[2] ||
        ny < rect[1] || ny > rect[3])
      {
        ++outside;
      }
    }
  }
  return outside;
}

/// The evaluated-count debug view read from the window's image (R + 256 G), on average
/// over the pixels that do not show the background. In a multisampled window the image is
/// resolved: an edge pixel averages its samples, the background's colour included.
double MeanOfCounts(vtkRenderWindow* rw, vtkRenderer* ren)
{
  const std::vector<float> rgb = ClusteredLightingTest::CapturePixels(rw);
  double background[3];
  ren->GetBackground(background);
  auto byte = [](double v) { return static_cast<int>(std::lround(v * 255.0)); };
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t p = 0; p + 2 < rgb.size(); p += 3)
  {
    if (byte(rgb[p]) == byte(background[0]) && byte(rgb[p + 1]) == byte(background[1]) &&
      byte(rgb[p + 2]) == byte(background[2]))
    {
      continue;
    }
    sum += byte(rgb[p]) + 256.0 * byte(rgb[p + 1]);
    ++n;
  }
  return n ? sum / static_cast<double>(n) : 0.0;
}

/// Fragments passing the depth test per visible pixel (MeasureTimings) with the prepass
/// and depth-aware clusters, and with both off; printed after `what`. Leaves both on.
void MeasureShaded(const char* what, vtkRenderWindow* rw, vtkClusteredLightingPass* pass,
  double& withPrepass, double& without)
{
  pass->SetMeasureTimings(true);
  pass->SetDepthPrepass(false);
  pass->SetDepthAwareClusters(false);
  rw->Render();
  without = pass->GetShadedFragmentsPerVisiblePixel();
  pass->SetDepthPrepass(true);
  pass->SetDepthAwareClusters(true);
  rw->Render();
  withPrepass = pass->GetShadedFragmentsPerVisiblePixel();
  pass->SetMeasureTimings(false);
  std::printf("%sfragments passing the depth test per visible pixel: %.4f with the prepass, "
              "%.4f without\n",
    what, withPrepass, without);
}

/// Renders the evaluated-count debug view and returns the pass's mean count; the mean of
/// the lights reaching each pixel must be positive and at most that. In a multisampled
/// window the pass reads one sample of each pixel (vtkClusteredLightingSampleZero): its
/// means and pixel count must agree within 2% with the same frame rendered single-sampled
/// (whose framebuffer reads back as it is; the two differ only at edge pixels, where
/// sample 0 and the pixel centre can fall on different surfaces). With translucent
/// geometry the lights evaluated may only be more multisampled: there a translucent tile
/// keeps every cluster to the far plane, single-sampled only those its props' boxes reach.
double MeasureEvaluated(const std::string& what, vtkRenderWindow* rw, vtkRenderer* ren,
  vtkClusteredLightingPass* pass, bool multisampled, double* reachingOut = nullptr,
  bool translucent = false)
{
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  rw->Render();
  const double evaluated = pass->GetMeanLightsEvaluatedPerPixel();
  const double reaching = pass->GetMeanLightsReachingPerPixel();
  const vtkIdType pixels = pass->GetNumberOfCountedPixels();
  // Lights reaching a pixel are among those it evaluates, and some reach (every case
  // here has lights on its surfaces).
  Check(reaching > 0.0 && reaching <= evaluated,
    what + ": lights reaching per pixel (" + std::to_string(reaching) +
      ") above 0 and at most those evaluated");
  if (multisampled)
  {
    const int samples = rw->GetMultiSamples();
    rw->SetMultiSamples(0);
    rw->Render();
    const double single = pass->GetMeanLightsEvaluatedPerPixel();
    const double singleReaching = pass->GetMeanLightsReachingPerPixel();
    const vtkIdType singlePixels = pass->GetNumberOfCountedPixels();
    rw->SetMultiSamples(samples);
    rw->Render();
    std::printf("%s: evaluated / reaching per pixel %.3f / %.3f over %lld pixels (%d samples, "
                "sample 0), %.3f / %.3f over %lld single-sampled; the resolved image shows "
                "%.3f evaluated\n",
      what.c_str(), evaluated, reaching, static_cast<long long>(pixels), samples, single,
      singleReaching, static_cast<long long>(singlePixels), MeanOfCounts(rw, ren));
    const bool evaluatedAgree =
      translucent ? evaluated >= 0.98 * single : std::abs(evaluated - single) <= 0.02 * single;
    Check(pixels > 0 && evaluatedAgree &&
        std::abs(reaching - singleReaching) <= 0.02 * singleReaching &&
        std::abs(static_cast<double>(pixels - singlePixels)) <= 0.02 * singlePixels,
      what +
        ": the pass counts the lights evaluated and reaching per pixel in a multisampled "
        "window (as single-sampled, within 2%; evaluated at least as many with translucent "
        "geometry)");
  }
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  if (reachingOut)
  {
    *reachingOut = reaching;
  }
  return evaluated;
}

/// Renders with and without depth-aware clusters and the prepass; checks the images are
/// identical, the assignment has no false negative, every pixel lies in its cluster, and
/// that culling by depth evaluates fewer lights per pixel and loses none that reaches.
void CheckCase(const std::string& what, vtkRenderWindow* rw, vtkRenderer* ren,
  vtkClusteredLightingPass* pass, bool expectDepthAware = true, bool translucent = false,
  bool multisampled = false, bool unlitOnTop = false)
{
  pass->SetDepthPrepass(false);
  pass->SetDepthAwareClusters(false);
  double reachingOff = 0.0;
  const double evaluatedOff =
    MeasureEvaluated(what + ", both off", rw, ren, pass, multisampled, &reachingOff);
  rw->Render();
  const std::vector<float> off = ClusteredLightingTest::CapturePixels(rw);
  Check(!pass->GetDepthPrepassUsed() && !pass->GetDepthAwareClustersUsed(),
    what + ": both off renders neither");

  pass->SetDepthPrepass(true);
  pass->SetDepthAwareClusters(true);
  rw->Render();
  const std::vector<float> on = ClusteredLightingTest::CapturePixels(rw);
  Check(pass->GetDepthPrepassUsed(), what + ": the prepass ran");
  Check(pass->GetDepthAwareClustersUsed() == expectDepthAware,
    what + (expectDepthAware ? ": depth-aware clusters in use" : ": depth-aware clusters off"));
  const auto cmp = ClusteredLightingTest::CompareImages(on, off);
  ClusteredLightingTest::PrintComparison((what + ": depth-aware vs off").c_str(), cmp);
  Check(cmp.MaxAbsError == 0.0, what + ": the image is the same, bit for bit");
  const auto assignment = ClusteredLightingTest::CheckAssignment(pass, ren, what.c_str());
  Check(assignment.FalseNegatives == 0 && assignment.MasterMismatches == 0,
    what + ": zero false negatives against the reference");
  if (expectDepthAware)
  {
    // (A multisampled depth buffer reads back resolved: its pixels are not the fragments',
    // so this check needs a single-sampled window; unlit geometry drawn over the lit,
    // splats, never finds a cluster, and is not in the prepass.)
    if (!multisampled && !unlitOnTop)
    {
      const int outside = CountPixelsOutside(pass, rw, ren);
      Check(outside == 0,
        what + ": every visible pixel inside its cluster's depths (" + std::to_string(outside) +
          " outside)");
    }
    double reachingOn = 0.0;
    const double evaluatedOn =
      MeasureEvaluated(what, rw, ren, pass, multisampled, &reachingOn, translucent);
    // Culling by depth drops no light that reaches a visible fragment: the pixels count
    // the same reaching lights with and without it (their mean, exactly).
    Check(reachingOn == reachingOff,
      what + ": as many lights reach a pixel on average with depth-aware clusters (" +
        std::to_string(reachingOn) + " and " + std::to_string(reachingOff) + " per pixel)");
    std::printf("%s: evaluated per pixel %.2f depth-aware, %.2f without; non-empty clusters "
                "%.1f%%, visible depths %.3g to %.3g, slices %.3g to %.3g\n",
      what.c_str(), evaluatedOn, evaluatedOff, 100.0 * pass->GetNonEmptyClusterFraction(),
      pass->GetVisibleDepthRange()[0], pass->GetVisibleDepthRange()[1],
      pass->GetSlicingRangeInUse()[0], pass->GetSlicingRangeInUse()[1]);
    Check(evaluatedOn < evaluatedOff, what + ": fewer lights evaluated per pixel");
    // With translucent geometry every cluster in front of the opaque surfaces stays.
    Check(translucent ? pass->GetNonEmptyClusterFraction() < 0.9
                      : pass->GetNonEmptyClusterFraction() < 0.2,
      what +
        (translucent ? ": the clusters behind the opaque surfaces are empty"
                     : ": most clusters are empty"));
  }
}
}

int TestClusteredLightingDepthAware(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 300, 200);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED);
  // This test checks the two options themselves, frame by frame: no timed trials
  // (TestClusteredLightingAutomaticPrepass checks those).
  pass->AutomaticDepthPrepassOff();
  vtkNew<vtkClusteredLightSet> lights;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  MakeLights(lights, 600, 0.6, origin);
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);

  // 1. The usual scene: a sphere occluding a floor.
  CheckCase("occluding sphere", rw, ren, pass);

  // 2. Fragments passing the depth test per visible pixel, with and without the prepass.
  double shadedOn = 0.0, shadedOff = 0.0;
  MeasureShaded("", rw, pass, shadedOn, shadedOff);
  Check(shadedOn > 0.999 && shadedOn < 1.001, "the prepass shades each visible pixel once");
  Check(shadedOff > shadedOn, "without it hidden fragments are shaded too");
  Check(pass->GetShadedTranslucentFragmentsPerVisiblePixel() == 0.0 &&
      pass->GetShadedOpaqueFragmentsPerVisiblePixel() == shadedOn,
    "no translucent geometry: every shaded fragment is counted as opaque");

  // 3. Camera inside lights, looking at the sphere from close by.
  ren->GetActiveCamera()->SetPosition(0.3, 0.4, 2.2);
  ren->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  ren->ResetCameraClippingRange();
  CheckCase("camera inside lights", rw, ren, pass);

  // 4. Parallel projection.
  ren->GetActiveCamera()->SetPosition(0.5, 2.5, 7.0);
  ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  ren->GetActiveCamera()->ParallelProjectionOn();
  ren->GetActiveCamera()->SetParallelScale(3.0);
  ren->ResetCameraClippingRange();
  CheckCase("parallel projection", rw, ren, pass);
  ren->GetActiveCamera()->ParallelProjectionOff();

  // 5. Coincident topology: edges drawn on the surfaces, polygons offset back (units only:
  // VTK 9.2's slope factor has no fixed bound and turns depth-aware clusters off).
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
  vtkMapper::SetResolveCoincidentTopologyPolygonOffsetParameters(0.0, 4.0);
  vtkActorCollection* actors = ren->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->GetProperty()->EdgeVisibilityOn();
  }
  ren->ResetCameraClippingRange();
  CheckCase("edges on surfaces, polygon offset", rw, ren, pass);
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->GetProperty()->EdgeVisibilityOff();
  }
  vtkMapper::SetResolveCoincidentTopologyToOff();

  // 6. Lines and points. A line's fragment takes its position from a point of the line
  // (and a wide line's or a point's from the centre line or the centre), up to half the
  // width from its pixel's centre and often in the next tile, whose clusters the pixel's
  // depth must reach too (DepthBoundsOptions::PixelSlack): a wireframe sphere (lines one
  // pixel wide), a wider one (6 pixels) and points of 9 pixels, above the floor and
  // partly against the background.
  vtkNew<vtkSphereSource> wireSource;
  wireSource->SetCenter(2.0, 0.9, 0.8);
  wireSource->SetRadius(0.7);
  wireSource->SetThetaResolution(16);
  wireSource->SetPhiResolution(16);
  vtkNew<vtkSphereSource> wideSource;
  wideSource->SetCenter(-2.0, 1.0, 0.5);
  wideSource->SetRadius(0.6);
  vtkNew<vtkPointSource> pointSource;
  pointSource->SetCenter(0.0, 1.4, 1.0);
  pointSource->SetNumberOfPoints(40);
  pointSource->SetRadius(0.9);
  vtkAlgorithm* const lineSources[] = { wireSource, wideSource, pointSource };
  const int representations[] = { VTK_WIREFRAME, VTK_WIREFRAME, VTK_POINTS };
  const float widths[] = { 1.0f, 6.0f, 9.0f };
  std::vector<vtkSmartPointer<vtkActor>> lineActors;
  for (int i = 0; i < 3; ++i)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(lineSources[i]->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetRepresentation(representations[i]);
    actor->GetProperty()->SetLineWidth(widths[i]);
    actor->GetProperty()->SetPointSize(widths[i]);
    ren->AddActor(actor);
    lineActors.emplace_back(actor);
  }
  ren->ResetCameraClippingRange();
  CheckCase("lines and points", rw, ren, pass);
  for (vtkActor* actor : lineActors)
  {
    ren->RemoveActor(actor);
  }

  // 7. Translucent geometry in front of the opaque.
  vtkNew<vtkSphereSource> glassSource;
  glassSource->SetCenter(-1.2, 0.2, 1.8);
  glassSource->SetRadius(0.7);
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glassSource->GetOutputPort());
  vtkNew<vtkActor> glass;
  glass->SetMapper(glassMapper);
  glass->GetProperty()->SetOpacity(0.4);
  ren->AddActor(glass);
  ren->ResetCameraClippingRange();
  CheckCase("translucent sphere", rw, ren, pass, true, true);
  // Its fragments are counted apart from the opaque ones: each opaque pixel still shades
  // one fragment, the glass adds its own: a ray crosses a sphere at most twice, so between
  // one and two per pixel it covers (the pixels it changes; 1% more allowed for pixels it
  // covers but does not change), and not VTK's compositing of the layers (one more per
  // viewport pixel, which is 10 times the glass's pixels here).
  pass->SetMeasureTimings(true);
  rw->Render();
  pass->SetMeasureTimings(false);
  const double opaque = pass->GetShadedOpaqueFragmentsPerVisiblePixel();
  const double glassShaded = pass->GetShadedTranslucentFragmentsPerVisiblePixel();
  const double allShaded = pass->GetShadedFragmentsPerVisiblePixel();
  const std::vector<float> withGlass = ClusteredLightingTest::CapturePixels(rw);
  int w = 0;
  int h = 0;
  const std::vector<float> z = ClusteredLightingTest::CaptureDepth(rw, ren, w, h);
  const double visible =
    static_cast<double>(std::count_if(z.begin(), z.end(), [](float d) { return d < 1.0f; }));
  glass->VisibilityOff();
  rw->Render();
  const std::vector<float> withoutGlass = ClusteredLightingTest::CapturePixels(rw);
  glass->VisibilityOn();
  double covered = 0.0;
  for (std::size_t i = 0; i + 2 < withGlass.size(); i += 3)
  {
    if (withGlass[i] != withoutGlass[i] || withGlass[i + 1] != withoutGlass[i + 1] ||
      withGlass[i + 2] != withoutGlass[i + 2])
    {
      covered += 1.0;
    }
  }
  const double glassFragments = glassShaded * visible;
  std::printf("translucent sphere: shaded fragments per visible pixel %.4f opaque, %.4f "
              "translucent (%.0f fragments over the %.0f pixels the glass changes, of %d)\n",
    opaque, glassShaded, glassFragments, covered, w * h);
  Check(opaque > 0.999 && opaque < 1.001, "translucent sphere: one opaque fragment per pixel");
  Check(covered > 0.0 && glassFragments >= 0.98 * covered && glassFragments <= 2.02 * covered,
    "translucent sphere: one or two fragments per pixel of the glass, the compositing not "
    "counted");
  Check(std::abs(allShaded - (opaque + glassShaded)) < 1e-12,
    "translucent sphere: the total is the sum of the parts");
  ren->RemoveActor(glass);

  // 7b. Translucent impostor spheres (vtkOpenGLSphereMapper): the fragment shader puts each
  // fragment on its sphere, outside the box of the centres: their fragments may be
  // anywhere, so every tile keeps the clusters in front of its opaque surfaces.
  vtkNew<vtkPoints> centres;
  centres->InsertNextPoint(-1.0, 0.4, 1.4);
  centres->InsertNextPoint(1.3, 0.0, 1.0);
  vtkNew<vtkCellArray> centreCells;
  for (vtkIdType i = 0; i < 2; ++i)
  {
    centreCells->InsertNextCell(1, &i);
  }
  vtkNew<vtkPolyData> centreData;
  centreData->SetPoints(centres);
  centreData->SetVerts(centreCells);
  vtkNew<vtkOpenGLSphereMapper> impostorMapper;
  impostorMapper->SetInputData(centreData);
  impostorMapper->SetRadius(0.8);
  vtkNew<vtkActor> impostors;
  impostors->SetMapper(impostorMapper);
  impostors->GetProperty()->SetOpacity(0.4);
  ren->AddActor(impostors);
  ren->ResetCameraClippingRange();
  CheckCase("translucent impostor spheres", rw, ren, pass, true, true);
  ren->RemoveActor(impostors);

  // 8. A scene far from the origin (the lights and geometry moved by 1e5).
  const double far[3] = { 1e5, -2e5, 1e5 };
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->SetPosition(far[0], far[1], far[2]);
  }
  MakeLights(lights, 600, 0.6, far);
  ren->GetActiveCamera()->SetPosition(far[0] + 0.5, far[1] + 2.5, far[2] + 7.0);
  ren->GetActiveCamera()->SetFocalPoint(far[0], far[1] - 0.3, far[2]);
  ren->ResetCameraClippingRange();
  CheckCase("scene far from the origin", rw, ren, pass);
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->SetPosition(0, 0, 0);
  }
  MakeLights(lights, 600, 0.6, origin);
  ren->GetActiveCamera()->SetPosition(0.5, 2.5, 7.0);
  ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  ren->ResetCameraClippingRange();

  // 9. Two viewports, each with its own assignment.
  vtkNew<vtkRenderer> right;
  ren->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->SetBackground(0.05, 0.05, 0.08);
  ClusteredLightingTest::AddTestScene(right);
  right->GetActiveCamera()->SetPosition(-3.0, 1.5, 5.0);
  right->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  right->ResetCameraClippingRange();
  right->SetPass(pass);
  rw->AddRenderer(right);
  CheckCase("two viewports (left)", rw, ren, pass);
  const auto rightCheck = ClusteredLightingTest::CheckAssignment(pass, right, "right viewport");
  Check(rightCheck.FalseNegatives == 0, "two viewports (right): zero false negatives");
  Check(CountPixelsOutside(pass, rw, right) == 0, "two viewports (right): pixels inside");
  rw->RemoveRenderer(right);
  ren->SetViewport(0.0, 0.0, 1.0, 1.0);

  // 10. A mapper that writes its own depth: depth-aware clusters off, said once.
  Check(messages->Warnings.empty(), "no warning so far");
  vtkNew<vtkPointSource> points;
  points->SetNumberOfPoints(30);
  points->SetRadius(1.5);
  vtkNew<vtkPolyDataMapper> pointMapper;
  pointMapper->SetInputConnection(points->GetOutputPort());
  vtkNew<vtkActor> spheres;
  spheres->SetMapper(pointMapper);
  spheres->GetProperty()->SetRepresentationToPoints();
  spheres->GetProperty()->RenderPointsAsSpheresOn();
  spheres->GetProperty()->SetPointSize(12);
  spheres->SetPosition(0.0, 1.5, 0.0);
  ren->AddActor(spheres);
  ren->ResetCameraClippingRange();
  CheckCase("points as spheres", rw, ren, pass, false);
  rw->Render();
  Check(messages->Warnings.size() == 1 &&
      messages->Warnings[0].find("writes its own fragment depth") != std::string::npos,
    "one warning names the impostor mapper");
  ren->RemoveActor(spheres);

  // Splats (vtkPointGaussianMapper, which VTK does not light) stay out of the prepass:
  // drawn there, they changed the shading render (242 steps off at 53% of the pixels).
  vtkNew<vtkPointGaussianMapper> splatMapper;
  splatMapper->SetInputConnection(points->GetOutputPort());
  splatMapper->SetScaleFactor(0.4);
  splatMapper->EmissiveOff();
  vtkNew<vtkActor> splats;
  splats->SetMapper(splatMapper);
  splats->SetPosition(0.0, 1.5, 0.0);
  ren->AddActor(splats);
  ren->ResetCameraClippingRange();
  CheckCase("splats", rw, ren, pass, true, false, false, true);
  Check(messages->Warnings.size() == 1, "splats: no warning");
  ren->RemoveActor(splats);

  // 11. Renderer vtkLights: the prepass draws with the shading render's programs, so
  // moving frames rebuild no shader.
  for (int i = 0; i < 40; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetPositional(true);
    light->SetConeAngle(180.0);
    light->SetPosition(-2.5 + 0.125 * i, 1.0, -2.0 + 0.1 * i);
    light->SetAttenuationValues(1.0, 0.0, 4.0);
    light->SetIntensity(0.2);
    ren->AddLight(light);
  }
  rw->Render();
  rw->Render();
  const int builds = pass->GetNumberOfShaderBuilds();
  for (int frame = 0; frame < 3; ++frame)
  {
    ren->GetActiveCamera()->Azimuth(2.0);
    rw->Render();
  }
  Check(pass->GetNumberOfClusteredLights() == 640, "the 40 vtkLights are clustered too");
  Check(pass->GetDepthPrepassUsed(), "the prepass runs with renderer lights");
  Check(pass->GetNumberOfShaderBuilds() == builds,
    "no shader rebuilt in 3 moving frames (" +
      std::to_string(pass->GetNumberOfShaderBuilds() - builds) + ")");
  Check(messages->Errors.empty(), "no error");

  // 12. A multisampled window, as VTK's default asks for: the prepass records each pixel's
  // range of fragment depths (vtkClusteredLightingSampleDepths), including the
  // extrapolated pixel-centre depths of primitives that cover only some samples.
  {
    vtkNew<vtkRenderWindow> msWindow;
    vtkNew<vtkRenderer> msRen;
    ClusteredLightingTest::SetUpTestScene(msWindow, msRen, 300, 200);
    msWindow->SetMultiSamples(8);
    msRen->GetActiveCamera()->SetPosition(0.8, 0.6, 6.5); // grazing floor, sphere outline
    msRen->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
    msRen->ResetCameraClippingRange();
    vtkNew<vtkClusteredLightingPass> msPass;
    msPass->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED);
    msPass->AutomaticDepthPrepassOff();
    msPass->AddLightSet(lights);
    msRen->SetPass(msPass);
    vtkNew<ClusteredLightingTest::MessageCollector> msMessages;
    msMessages->Watch(msPass);
    CheckCase("8 samples", msWindow, msRen, msPass, true, false, true);
    vtkClusteredLightingInspector inspect(msPass);
    Check(inspect.GetNumberOfSampleDepthObjects(msRen) > 0,
      "8 samples: the prepass recorded through its multisampled targets");
    Check(msMessages->Warnings.empty(),
      "8 samples: depth-aware clusters and the counts of lights evaluated per pixel without a "
      "warning");
    // Fragments shaded per visible pixel there: the queries count samples (the pass divides
    // by the sample count) and the visible pixels come from one sample of each pixel.
    // The sphere's back faces drawn (AutomaticBackfaceCulling off), as hidden fragments to
    // count; then culled, as by default: fewer are shaded without the prepass, and still
    // more than with it (the floor under the sphere).
    double msShadedOn = 0.0, msShadedOff = 0.0;
    msPass->AutomaticBackfaceCullingOff();
    MeasureShaded("8 samples, back faces drawn: ", msWindow, msPass, msShadedOn, msShadedOff);
    msPass->AutomaticBackfaceCullingOn();
    // Edge pixels pass some of their samples, and the visible pixels count one of them.
    Check(msShadedOn > 0.98 && msShadedOn < 1.02,
      "8 samples: the prepass shades each visible pixel once");
    Check(msShadedOff > msShadedOn + 0.05, "8 samples: without it hidden fragments are shaded too");
    double msCulledOn = 0.0, msCulledOff = 0.0;
    MeasureShaded("8 samples, back faces culled: ", msWindow, msPass, msCulledOn, msCulledOff);
    Check(msCulledOn > 0.98 && msCulledOn < 1.02 && msCulledOff > msCulledOn &&
        msCulledOff < msShadedOff - 0.02,
      "8 samples: the sphere's back faces culled, fewer hidden fragments are shaded without "
      "the prepass, still more than with it");

    // Translucent geometry is shaded at pixel centres that no opaque sample bounds: the
    // tiles of its screen rectangle keep every cluster (the others are cut to the
    // depths), and the image stays the same.
    vtkNew<vtkActor> msGlass;
    msGlass->SetMapper(glassMapper);
    msGlass->GetProperty()->SetOpacity(0.4);
    msRen->AddActor(msGlass);
    CheckCase("8 samples, translucent sphere", msWindow, msRen, msPass, true, true, true);
    // Its translucent fragments cannot be counted there: order-independent translucency
    // draws them single-sampled and composites them into the multisampled framebuffer.
    msPass->SetMeasureTimings(true);
    msWindow->Render();
    msPass->SetMeasureTimings(false);
    const double msOpaque = msPass->GetShadedOpaqueFragmentsPerVisiblePixel();
    Check(msPass->GetShadedTranslucentFragmentsPerVisiblePixel() == -1.0 &&
        msPass->GetShadedFragmentsPerVisiblePixel() == -1.0 && msOpaque > 0.98 && msOpaque < 1.02,
      "8 samples, translucent sphere: the opaque fragments counted (" + std::to_string(msOpaque) +
        "), the translucent ones said not to be (-1)");
    Check(msMessages->Warnings.empty(), "8 samples, translucent sphere: no warning");
    msRen->RemoveActor(msGlass);

    msPass->ReleaseGraphicsResources(msWindow);
    Check(msPass->GetNumberOfGLObjects() == 0 && inspect.GetNumberOfSampleDepthObjects(msRen) == 0,
      "8 samples: every GL object released");
    Check(msMessages->Errors.empty(), "8 samples: no error");
  }
  return Failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
