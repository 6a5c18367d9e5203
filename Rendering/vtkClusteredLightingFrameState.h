// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFrameState.h
 * @brief What one assignment used, kept by vtkClusteredLightingPass for tests.
 *
 * Tests compare the GPU list/master textures (vtkClusteredLightingPass::ReadBackAssignment)
 * with the double-precision reference of Rendering/Core/vtkClusteredLightingReference.h,
 * computed from these inputs (not from the pass's bounds).
 */
#ifndef vtkClusteredLightingFrameState_h
#define vtkClusteredLightingFrameState_h

#include "vtkClusteredLightingLayout.h"
#include "vtkClusteredLightingLights.h"
#include "vtkClusteredLightingReference.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

struct vtkClusteredLightingFrameState
{
  bool Valid = false;
  vtkClusteredLighting::ClusterGridParams Grid; ///< includes the camera near/far
  glm::dmat4 WCVC = glm::dmat4(1.0);
  glm::dmat4 VCDC = glm::dmat4(1.0);
  int ViewportOrigin[2] = { 0, 0 };
  vtkClusteredLighting::ClusterTextureLayout Layout;
  std::vector<vtkClusteredLighting::ReferenceLight> LightsVC; ///< upload order
  std::vector<vtkClusteredLighting::PreparedLight> Lights;    ///< upload order, world coords
  int NumberOfQuads = 0;
};

#endif
