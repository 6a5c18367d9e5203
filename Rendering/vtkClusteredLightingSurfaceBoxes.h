// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingSurfaceBoxes
 * @brief   where a renderer's visible surfaces lie, as world boxes, for the far field's blocks
 *
 * Private to the module; one per renderer, kept by vtkClusteredLightingPass. The far field
 * is read only at surface points, so its build sums only the blocks of nodes that some
 * surface can read (vtkClusteredLightingFarFieldBlocks.h). This class says where the
 * surfaces are, independently of the camera (a moving camera changes nothing here):
 *  - an actor of VTK's own classes (vtkActor, vtkOpenGLActor) whose mapper draws its input
 *    as it is (vtkOpenGLPolyDataMapper, vtkCompositePolyDataMapper2) gives one box per
 *    cell of its polygonal data (per triangle of a strip, per segment of a polyline), in
 *    world coordinates through the actor's matrix;
 *  - any other visible prop (volumes, image slices, glyph and LOD mappers, ParaView's LOD
 *    actors, actors of other classes) gives its bounds: everything it draws is inside;
 *  - an actor that draws lines as tubes or points as spheres (fragments off its
 *    geometry by a width in pixels) or whose bounds are not finite asks for every block
 *    (GetEverywhere).
 * Update reads the props again only when one of them, its matrix, mapper or input has
 * changed (their MTimes) or the set of visible props has; the version then grows.
 *
 * A shader replacement that moves vertices (vtkShaderProperty) is not seen here:
 * vtkClusteredLightingPass::FarFieldSkipEmptyBlocks off builds every block.
 *
 * @sa vtkClusteredLightingPass vtkClusteredLightingFarFieldTextures
 */
#ifndef vtkClusteredLightingSurfaceBoxes_h
#define vtkClusteredLightingSurfaceBoxes_h

#include "vtkType.h" // for vtkMTimeType

#include <cstdint> // for std::uint64_t
#include <glm/glm.hpp>
#include <vector> // for std::vector

class vtkProp;
class vtkRenderer;

class vtkClusteredLightingSurfaceBoxes
{
public:
  /// Reads the visible props of `ren` when any has changed. Returns whether the boxes did.
  bool Update(vtkRenderer* ren);

  /// World boxes, low and high corners in turn.
  const std::vector<glm::dvec3>& GetBoxes() const { return this->Boxes; }
  /// Whether some prop may draw anywhere (every block is needed).
  bool GetEverywhere() const { return this->Everywhere; }
  /// Grows whenever the boxes change.
  std::uint64_t GetVersion() const { return this->Version; }

private:
  /// Adds `prop`'s boxes (see the class description).
  void AddProp(vtkProp* prop);

  std::vector<glm::dvec3> Boxes;
  bool Everywhere = false;
  std::uint64_t Version = 0;
  /// What the boxes were read from: per visible prop, its address and newest MTime.
  std::vector<std::pair<const void*, vtkMTimeType>> Signature;
};

#endif
