// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the GL-free unit tests: VTK-style projection matrices.
#ifndef ClusteredLightingTestUtilities_h
#define ClusteredLightingTestUtilities_h

#include "vtkClusteredLightingGrid.h"

#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ClusteredLightingTest
{
/// A cluster grid of tilesX x tilesY x slices over a width x height viewport.
inline vtkClusteredLighting::ClusterGridParams MakeGrid(int tilesX, int tilesY, int slices,
  int width, int height, double nearVC, double farVC, vtkClusteredLighting::SlicingScheme scheme)
{
  vtkClusteredLighting::ClusterGridParams g;
  g.TilesX = tilesX;
  g.TilesY = tilesY;
  g.Slices = slices;
  g.ViewportWidth = width;
  g.ViewportHeight = height;
  g.NearVC = nearVC;
  g.FarVC = farVC;
  g.Scheme = scheme;
  return g;
}

/// Perspective VC->clip matrix like vtkCamera's: vertical view angle in degrees,
/// window centre (SetWindowCenter) shifting the frustum off axis.
inline glm::dmat4 Perspective(double viewAngleDeg, double aspect, double nearVC, double farVC,
  double centerX = 0.0, double centerY = 0.0)
{
  const double t = nearVC * std::tan(0.5 * viewAngleDeg * 3.14159265358979323846 / 180.0);
  const double w = t * aspect;
  return glm::frustum(
    -w + centerX * w, w + centerX * w, -t + centerY * t, t + centerY * t, nearVC, farVC);
}

/// Parallel VC->clip matrix like vtkCamera's (ParallelScale = half height).
inline glm::dmat4 Parallel(double parallelScale, double aspect, double nearVC, double farVC)
{
  return glm::ortho(
    -parallelScale * aspect, parallelScale * aspect, -parallelScale, parallelScale, nearVC, farVC);
}
} // namespace ClusteredLightingTest
#endif
