// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingRasterBackend
 * @brief   "compute-less" light assignment: list and master textures by rasterization
 *
 * Private to the module; the vtkClusteredLightingAssignmentBackend the assigner uses.
 *
 *  1. List pass (RunListPass): the (light, slice) tile rectangles of the view
 *     (ViewData::Quads) are uploaded to clQuads, then one instanced draw of one quad per
 *     rectangle writes the light's bit into the R32UI list texture with glLogicOp(GL_OR)
 *     (overlapping writes are harmless, no carry can corrupt another light). Each fragment
 *     may first test the light's sphere against its cluster's view-space bounding box
 *     (ListPassParameters::CullClusters). Shaders: vtkClusteredLightingList{VS,FS}.glsl.
 *  2. Master pass (RunMasterPass): one full-screen triangle folds the list into the R32UI
 *     master texture, one bit per non-empty batch (vtkClusteredLightingMasterFS.glsl);
 *     with depth-aware clusters it reads no list texel of a cluster without fragments.
 *
 * GL objects: clQuads (texture buffer, 2 RGBA32F texels per quad), list and master
 * textures (sized by ClusterTextureLayout, re-allocated only when it changes), one FBO,
 * one attribute-free VAO; programs come from VTK's shader cache. Each pass runs inside a
 * GL debug group ("vtkClusteredLighting list pass", "... master pass"). All GL state it
 * touches is restored: framebuffer bindings, viewport, blend, depth and scissor tests,
 * face culling, colour mask, logic op, vertex array binding.
 *
 * @sa vtkClusteredLightingAssignmentBackend vtkClusteredLightingAssigner
 */
#ifndef vtkClusteredLightingRasterBackend_h
#define vtkClusteredLightingRasterBackend_h

#include "vtkClusteredLightingAssignmentBackend.h"
#include "vtkClusteredLightingGLHelpers.h" // for vtkClusteredLightingTextureBuffer, ...VertexArray

class vtkOpenGLFramebufferObject;
class vtkShaderProgram;

class vtkClusteredLightingRasterBackend : public vtkClusteredLightingAssignmentBackend
{
public:
  vtkClusteredLightingRasterBackend() = default;
  ~vtkClusteredLightingRasterBackend() override;

  const char* GetName() const override { return "raster (list/master quads)"; }

  bool Assign(vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::ClusterTextureLayout& layout,
    const vtkClusteredLighting::ViewData& view,
    const vtkClusteredLighting::ListPassParameters& parameters,
    vtkTextureObject* lightView) override;

  void ReleaseDepthResources(vtkOpenGLRenderWindow* rw) override;
  void ActivateShadingTextures() override;
  void DeactivateShadingTextures() override;
  int GetListUnit() const override;
  int GetMasterUnit() const override;

  bool ReadBack(vtkOpenGLRenderWindow* rw, std::vector<std::uint32_t>& list,
    std::vector<std::uint32_t>& master) override;

  std::uint64_t GetListBytes() const override;
  std::uint64_t GetMasterBytes() const override;
  std::uint64_t GetWorkBytes() const override;

  int GetNumberOfGLObjects() const override;
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const override;

  void ReleaseGraphicsResources(vtkWindow* w) override;

private:
  vtkClusteredLightingRasterBackend(const vtkClusteredLightingRasterBackend&) = delete;
  void operator=(const vtkClusteredLightingRasterBackend&) = delete;

  bool AllocateTextures(
    vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::ClusterTextureLayout& layout);
  bool RunListPass(vtkOpenGLRenderWindow* rw,
    const vtkClusteredLighting::ClusterTextureLayout& layout, int numberOfQuads,
    const vtkClusteredLighting::ListPassParameters& parameters, vtkTextureObject* lightView);
  bool RunMasterPass(vtkOpenGLRenderWindow* rw,
    const vtkClusteredLighting::ClusterTextureLayout& layout, bool depthAware);
  bool BindTarget(vtkTextureObject* tex);
  vtkShaderProgram* ReadyProgram(
    vtkOpenGLRenderWindow* rw, const char* vs, const char* fs, bool depthAware);
  void DeactivateDepths(bool depthAware);
  bool UploadClusterDepths(
    vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::ClusterDepthBounds& bounds);

  vtkClusteredLightingTextureBuffer Quads;
  vtkTextureObject* List = nullptr;
  vtkTextureObject* Master = nullptr;
  vtkTextureObject* ClusterDepths = nullptr; ///< RG32F, depth-aware clusters only
  vtkTextureObject* ClusterRects = nullptr;  ///< RGBA32F, depth-aware clusters only
  vtkOpenGLFramebufferObject* FBO = nullptr;
  vtkClusteredLightingVertexArray VAO;
  int ListSize[2] = { 0, 0 };
  int MasterSize[2] = { 0, 0 };
};

#endif
