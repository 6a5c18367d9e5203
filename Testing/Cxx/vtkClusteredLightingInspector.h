// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingInspector
 * @brief   test-only window into a vtkClusteredLightingPass: what it assigned, and its GL objects
 *
 * Not part of the product: tests include this header (from Testing/Cxx) and the pass
 * names the class as a friend. Everything is read when asked: the snapshot of what the
 * last assignment of a renderer used (vtkClusteredLightingAssignmentSnapshot: grid,
 * matrices, texture layout, prepared lights in upload order) is copied by GetFrame().
 *
 *   renWin->Render();
 *   vtkClusteredLightingInspector inspect(pass);
 *   const vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(renderer);
 *   inspect.ReadBackAssignment(renderer, list, master); // list and master textures
 *
 * Reference lights in view coordinates for the CPU reference assigner
 * (Rendering/Core/vtkClusteredLightingReference.h) come from ComputeLightsVC().
 */
#ifndef vtkClusteredLightingInspector_h
#define vtkClusteredLightingInspector_h

#include "vtkClusteredLightingAssigner.h"
#include "vtkClusteredLightingPass.h"
#include "vtkClusteredLightingReference.h"

#include <cstdint>
#include <utility>
#include <vector>

class vtkClusteredLightingInspector
{
public:
  explicit vtkClusteredLightingInspector(vtkClusteredLightingPass* pass)
    : Pass(pass)
  {
  }

  /// What the last assignment for `renderer` used (Valid is false if there is none).
  vtkClusteredLightingAssignmentSnapshot GetFrame(vtkRenderer* renderer) const
  {
    vtkClusteredLightingAssigner* a = this->Pass->GetAssigner(renderer);
    return a ? a->GetSnapshot() : vtkClusteredLightingAssignmentSnapshot();
  }

  /// The list and master textures of `renderer` (row-major).
  bool ReadBackAssignment(
    vtkRenderer* renderer, std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& master)
  {
    vtkClusteredLightingAssigner* a = this->Pass->GetAssigner(renderer);
    return a && a->ReadBackAssignment(list, master);
  }

  /// GL objects of the depth prepass's multisampled recording for `renderer` (0 when it
  /// never recorded: a single-sampled framebuffer, or depth-aware clusters off).
  int GetNumberOfSampleDepthObjects(vtkRenderer* renderer) const
  {
    vtkClusteredLightingAssigner* a = this->Pass->GetAssigner(renderer);
    return a ? a->GetSampleDepths()->GetNumberOfGLObjects() : 0;
  }

  /// (kind, GL name) of every GL object the pass holds, for all renderers.
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const
  {
    for (vtkClusteredLightingAssigner* a : this->Pass->GetAssigners())
    {
      a->GetGLObjectNames(names);
    }
  }

  /// Why the last update of `renderer` did work (vtkClusteredLightingDirtyReason bits).
  unsigned int GetLastUpdateReasons(vtkRenderer* renderer) const
  {
    vtkClusteredLightingAssigner* a = this->Pass->GetAssigner(renderer);
    return a ? a->GetResult().Reasons : 0u;
  }

  /// Light centres and radii in view coordinates, upload order; spot lights with their
  /// axes and cones when the frame culled cones (SpotConeCulling).
  static std::vector<vtkClusteredLighting::ReferenceLight> ComputeLightsVC(
    const vtkClusteredLightingAssignmentSnapshot& frame)
  {
    std::vector<vtkClusteredLighting::ReferenceLight> out;
    out.reserve(frame.Lights.size());
    const glm::dmat3 axisMatrix = vtkClusteredLighting::ComputeAxisMatrix(frame.WCVC);
    for (const auto& l : frame.Lights)
    {
      vtkClusteredLighting::ReferenceLight r{
        glm::dvec3(frame.WCVC * glm::dvec4(l.PositionWC, 1.0)), l.Radius
      };
      const glm::dvec3 axis = vtkClusteredLighting::ComputeSpotAxisVC(axisMatrix, l);
      if (vtkClusteredLighting::IsAssignedByCone(frame.SpotConeCulling, l, axis))
      {
        r.AxisVC = axis;
        r.CosCone = l.CosCone;
      }
      out.push_back(r);
    }
    return out;
  }

private:
  vtkClusteredLightingPass* Pass;
};

#endif
