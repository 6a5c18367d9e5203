// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingAssignmentBackend
 * @brief   interface of a light-assignment back end: fills the list and master textures
 *
 * Private to the module. For every view, vtkClusteredLightingAssigner computes on the
 * CPU each light's record in view coordinates (uploaded as clLightView) and the tile
 * rectangles each light covers in each depth slice (ViewData::Quads,
 * Rendering/Core/vtkClusteredLightingAssignment.h). A back end turns them into the two
 * textures the shading code walks (layout: Rendering/Core/vtkClusteredLightingLayout.h):
 *
 *   list    R32UI, one 32-light bitmask per (cluster, batch of 32 lights)
 *   master  R32UI, one bit per non-empty batch of a cluster
 *
 * Every back end must fill exactly this layout: the shading code reads it, and the tests
 * compare it bit by bit with the double-precision reference. How it gets there is its own
 * business. The shipped back end, vtkClusteredLightingRasterBackend, rasterizes one
 * instanced quad per (light, slice) with glLogicOp(GL_OR) (the "compute-less" technique);
 * a compute-shader back end would implement the same interface (and be chosen in
 * vtkClusteredLightingAssigner's constructor).
 *
 * A back end owns its GL objects. Its caller makes the right context current around
 * every call (the assigner does), so back ends never switch contexts themselves.
 *
 * @sa vtkClusteredLightingAssigner vtkClusteredLightingRasterBackend
 */
#ifndef vtkClusteredLightingAssignmentBackend_h
#define vtkClusteredLightingAssignmentBackend_h

#include "vtkClusteredLightingAssignment.h" // for ViewData, ListPassParameters
#include "vtkClusteredLightingLayout.h"     // for ClusterTextureLayout

#include <cstdint> // for std::uint32_t
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkClusteredLightingAssignmentBackend
{
public:
  virtual ~vtkClusteredLightingAssignmentBackend() = default;

  /// Name for messages and GL debug groups.
  virtual const char* GetName() const = 0;

  /**
   * Fills the list and master textures for one view. `lightView` is the uploaded
   * clLightView texture buffer (per light: centre in VC and radius, spot axis).
   * Returns false (and leaves the textures unusable) on a GL failure.
   */
  virtual bool Assign(vtkOpenGLRenderWindow* rw,
    const vtkClusteredLighting::ClusterTextureLayout& layout,
    const vtkClusteredLighting::ViewData& view,
    const vtkClusteredLighting::ListPassParameters& parameters, vtkTextureObject* lightView) = 0;

  /// Depth-aware clusters are off for this renderer: release what only they use.
  virtual void ReleaseDepthResources(vtkOpenGLRenderWindow* rw) = 0;

  ///@{
  /// Bind the list and master textures for the shading pass; their units (-1 when not
  /// bound) go to clList and clMaster.
  virtual void ActivateShadingTextures() = 0;
  virtual void DeactivateShadingTextures() = 0;
  virtual int GetListUnit() const = 0;
  virtual int GetMasterUnit() const = 0;
  ///@}

  /// Reads the list and master textures back (row-major, texel row 0 first).
  virtual bool ReadBack(vtkOpenGLRenderWindow* rw, std::vector<std::uint32_t>& list,
    std::vector<std::uint32_t>& master) = 0;

  ///@{
  /// GPU memory held, in bytes.
  virtual std::uint64_t GetListBytes() const = 0;
  virtual std::uint64_t GetMasterBytes() const = 0;
  virtual std::uint64_t GetWorkBytes() const = 0; ///< inputs of the back end (e.g. quads)
  ///@}

  ///@{
  /// Live GL objects, (GL_TEXTURE, GL_BUFFER, GL_FRAMEBUFFER or GL_VERTEX_ARRAY, name).
  virtual int GetNumberOfGLObjects() const = 0;
  virtual void GetGLObjectNames(
    std::vector<std::pair<unsigned int, unsigned int>>& names) const = 0;
  ///@}

  /// Deletes every GL object (the caller made w's context current; null: just forget).
  virtual void ReleaseGraphicsResources(vtkWindow* w) = 0;
};

#endif
