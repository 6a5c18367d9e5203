// SPDX-License-Identifier: BSD-3-Clause
// Debug views, checked against the CPU:
//  - DEBUG_CLUSTER_INDEX: the cluster (tile x, tile y, slice) of every pixel equals the one
//    computed on the CPU from the pixel centre and its depth (core functions);
//  - DEBUG_EVALUATED_COUNT: lights evaluated per pixel equal the bits set in the read-back
//    list texture for that pixel's cluster, and are >= the lights reaching the pixel;
//  - DEBUG_REACHED_COUNT: lights reaching each pixel (distance < radius) equal the CPU
//    count: no reaching light is missing from the fragment's cluster walk;
//  - DEBUG_HEAT_MAP: regression image.
// Pixels whose depth-buffer depth is ambiguous (slice boundary or light radius within the
// depth quantization) are skipped and counted.
#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkSphereSource.h"

#include <random>

using namespace vtkClusteredLighting;

int TestClusteredLightingDebugViews(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(320, 240);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  renWin->AddRenderer(ren);
  ClusteredLightingTest::AddFloor(ren, 4);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.5, 0.5, 0.8);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(40);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  ren->AddActor(sphereActor);

  vtkNew<vtkClusteredLightSet> lights;
  lights->SetNumberOfLights(2000);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 2000; ++i)
  {
    lights->SetPosition(i, -4 + 8 * U(rng), -4 + 8 * U(rng), 0.05 + 2.0 * U(rng));
    lights->SetAttenuation(i, 1.0, 0.0, 2000.0 + 4000.0 * U(rng));
  }
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  pass->SetHeatMapMaximum(40);
  // Every light at ContributionCutoff, split ones too (FarFieldCutoff 0): lights that
  // reach many clusters, so the counts and the heat map have something to show.
  pass->SetFarFieldCutoff(0.0);
  ren->SetPass(pass);
  ren->GetActiveCamera()->SetPosition(0, -7, 5);
  ren->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  ren->ResetCameraClippingRange();
  renWin->Render();

  int status = EXIT_SUCCESS;
  vtkClusteredLightingInspector inspect(pass);
  const vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(ren);
  const auto lightsVC = vtkClusteredLightingInspector::ComputeLightsVC(frame);
  const ClusterGridParams& grid = frame.Grid;
  std::vector<std::uint32_t> list, master;
  inspect.ReadBackAssignment(ren, list, master);
  int w = 0, h = 0;
  const std::vector<float> depth = ClusteredLightingTest::CaptureDepth(renWin, ren, w, h);
  const glm::dmat4 inverse = glm::inverse(frame.VCDC);

  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_CLUSTER_INDEX);
  renWin->Render();
  const std::vector<float> clusterView = ClusteredLightingTest::CapturePixels(renWin);
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  renWin->Render();
  const std::vector<float> evaluatedView = ClusteredLightingTest::CapturePixels(renWin);
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_REACHED_COUNT);
  renWin->Render();
  const std::vector<float> reachedView = ClusteredLightingTest::CapturePixels(renWin);

  std::size_t checked = 0, ambiguous = 0, clusterMismatch = 0, evaluatedMismatch = 0,
              reachedMismatch = 0, reachedOverEvaluated = 0;
  double sumEvaluated = 0.0, sumReached = 0.0;
  auto byte = [](float v) { return static_cast<int>(std::lround(v * 255.0f)); };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const float z = depth[static_cast<std::size_t>(y) * w + x];
      if (!(z < 1.0f))
      {
        continue;
      }
      // The depth buffer holds 24 bits: bracket the fragment's true depth.
      const glm::dvec3 p = ClusteredLightingTest::UnprojectPixel(x, y, z, w, h, inverse);
      const double dz = 2.0 / 16777216.0;
      const glm::dvec3 pLo = ClusteredLightingTest::UnprojectPixel(x, y, z - dz, w, h, inverse);
      const glm::dvec3 pHi = ClusteredLightingTest::UnprojectPixel(x, y, z + dz, w, h, inverse);
      const int tx = ComputeTileIndex(x + 0.5, w, grid.TilesX);
      const int ty = ComputeTileIndex(y + 0.5, h, grid.TilesY);
      const int s = ComputeSliceIndex(-p.z, grid);
      bool unsure = ComputeSliceIndex(-pLo.z, grid) != s || ComputeSliceIndex(-pHi.z, grid) != s;
      int reached = 0;
      for (std::size_t i = 0; i < frame.Lights.size(); ++i)
      {
        const double r = lightsVC[i].Radius;
        const double d = glm::length(p - lightsVC[i].CenterVC);
        const double spread = glm::length(pHi - pLo) + 1e-5 * r;
        unsure = unsure || std::abs(d - r) <= spread;
        reached += d < r ? 1 : 0;
      }
      if (unsure)
      {
        ++ambiguous;
        continue;
      }
      ++checked;
      const std::size_t pi = 3 * (static_cast<std::size_t>(y) * w + x);
      const int gtx =
        static_cast<int>(std::lround(byte(clusterView[pi]) * (grid.TilesX - 1) / 255.0));
      const int gty =
        static_cast<int>(std::lround(byte(clusterView[pi + 1]) * (grid.TilesY - 1) / 255.0));
      const int gs =
        static_cast<int>(std::lround(byte(clusterView[pi + 2]) * (grid.Slices - 1) / 255.0));
      clusterMismatch += (gtx != tx || gty != ty || gs != s) ? 1 : 0;
      int bits = 0;
      for (int b = 0; b < frame.Layout.Batches; ++b)
      {
        const TexelCoord t = frame.Layout.ListTexel(tx, ty, s, b);
        bits += PopCount32(list[static_cast<std::size_t>(t.Y) * frame.Layout.ListWidth + t.X]);
      }
      const int evaluated = byte(evaluatedView[pi]) + 256 * byte(evaluatedView[pi + 1]);
      const int gpuReached = byte(reachedView[pi]) + 256 * byte(reachedView[pi + 1]);
      evaluatedMismatch += evaluated != bits ? 1 : 0;
      reachedMismatch += gpuReached != reached ? 1 : 0;
      reachedOverEvaluated += gpuReached > evaluated ? 1 : 0;
      sumEvaluated += evaluated;
      sumReached += gpuReached;
    }
  }
  std::printf("checked %zu pixels (%zu ambiguous skipped): cluster mismatches %zu, evaluated != "
              "list bits %zu, reached != CPU %zu, reached > evaluated %zu; mean evaluated %.2f, "
              "mean reached %.2f (culling efficiency %.1f%%)\n",
    checked, ambiguous, clusterMismatch, evaluatedMismatch, reachedMismatch, reachedOverEvaluated,
    sumEvaluated / checked, sumReached / checked, 100.0 * sumReached / sumEvaluated);
  if (checked < static_cast<std::size_t>(w * h / 4) || clusterMismatch || evaluatedMismatch ||
    reachedMismatch || reachedOverEvaluated)
  {
    status = EXIT_FAILURE;
  }

  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_HEAT_MAP);
  renWin->Render();
  return ClusteredLightingTest::FinishImageTest(argc, argv, renWin, status);
}
