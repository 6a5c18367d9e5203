// SPDX-License-Identifier: BSD-3-Clause
// Times the CPU pass over a depth image (vtkClusteredLightingDepthBounds.h) on one thread:
// a 1024x768 image of a receding, bumpy floor (every 97th pixel background), the default
// 32x16x32 grid, best of 15 rounds. Built by run.sh against two versions of the header.
#include "TestUtilities.h"
#include "vtkClusteredLightingDepthBounds.h"

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace vtkClusteredLighting;

int main()
{
  const int width = 1024, height = 768;
  const glm::dmat4 P = ClusteredLightingTest::Perspective(30.0, 4.0 / 3.0, 0.5, 40.0);
  ClusterGridParams g = ClusteredLightingTest::MakeGrid(
    32, 16, 32, width, height, 0.5, 40.0, SlicingScheme::Exponential);
  std::vector<float> depth(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double d = 3.0 + 10.0 * y / height + 0.5 * std::sin(x * 0.05) * std::cos(y * 0.03);
      const double w = WindowDepthFromViewDepth(d, P);
      depth[static_cast<std::size_t>(y) * width + x] =
        (x + y) % 97 == 0 ? 1.0f : static_cast<float>(std::round(w * 16777216.0) / 16777216.0);
    }
  }
  const DepthImage image{ depth.data(), width, height };
  const DepthBoundsOptions options;
  double bestRange = 1e30, bestRows = 1e30;
  ClusterDepthBounds b;
  for (int round = 0; round < 15; ++round)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const VisibleRange range = MeasureVisibleRange(image, P);
    const auto t1 = std::chrono::steady_clock::now();
    ChooseSlicingRange(range.Visible, range.Nearest, range.Deepest, g);
    InitializeClusterDepthBounds(g, b);
    ComputeClusterDepthBoundsRows(image, P, g, options, 0, g.TilesY, b);
    FinishClusterDepthBounds(range, b);
    const auto t2 = std::chrono::steady_clock::now();
    bestRange = std::min(bestRange, std::chrono::duration<double, std::milli>(t1 - t0).count());
    bestRows = std::min(bestRows, std::chrono::duration<double, std::milli>(t2 - t1).count());
  }
  double sum = 0.0;
  for (const float v : b.LoHi)
  {
    sum += v;
  }
  std::printf("visible range %.2f ms, cluster bounds %.2f ms; %zu non-empty clusters, "
              "sum of the intervals %.9g\n",
    bestRange, bestRows, b.NonEmptyClusters, sum);
  return 0;
}
