// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingGPUResources
 * @brief   GL objects of one renderer's clustered lighting and the two assignment passes
 *
 * Private helper of vtkClusteredLightingPass (one instance per renderer). It owns:
 *
 *   clLightData  texture buffer, RGBA32F, 2 texels per light (changes with the lights)
 *   clLightView  texture buffer, RGBA32F, 2 texels per light (changes with the view)
 *   clQuads      texture buffer, RGBA32F, 2 texels per visible light (list-pass input)
 *   list         2D texture, R32UI, ClusterTextureLayout::ListWidth x ListHeight
 *   master       2D texture, R32UI, MasterWidth x MasterHeight
 *   an FBO, an attribute-free VAO, and the list/master programs (from the shader cache)
 *
 * BuildAssignment() runs the list pass (one instanced draw, bits OR-ed with
 * glLogicOp(GL_OR)) and the master pass (one full-screen triangle). All GL state it
 * touches is restored: framebuffer bindings, viewport, blend, depth and scissor tests,
 * face culling, color mask, logic op.
 *
 * @sa vtkClusteredLightingPass
 */
#ifndef vtkClusteredLightingGPUResources_h
#define vtkClusteredLightingGPUResources_h

#include "vtkClusteredLightingLayout.h" // for ClusterTextureLayout
#include "vtkOpenGLRenderWindow.h"      // for vtkWeakPointer<vtkOpenGLRenderWindow>
#include "vtkWeakPointer.h"             // for vtkWeakPointer

#include <cstdint> // for std::uint32_t
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

/// Values the list pass needs beyond the layout (per-cluster culling).
struct vtkClusteredLightingListPassParameters
{
  bool CullClusters = true;
  float ProjectionX[3] = { 1, 0, 0 }; ///< P00, P02, P03
  float ProjectionY[3] = { 1, 0, 0 }; ///< P11, P12, P13
  float ProjectionW[2] = { -1, 0 };   ///< P32, P33
  float Slicing[4] = { 0, 0, 0, 0 };  ///< ComputeSliceShaderParameters
  float DepthRange[2] = { 0, 1 };     ///< camera near, far
};

/// ivec4 uniform setter (vtkShaderProgram has none in VTK 9.1); program must be bound.
bool vtkClusteredLightingSetUniform4i(vtkShaderProgram* program, const char* name, const int v[4]);

class vtkClusteredLightingGPUResources
{
public:
  vtkClusteredLightingGPUResources();
  ~vtkClusteredLightingGPUResources();

  /// Upload clLightData / clLightView / clQuads (float RGBA texels).
  bool UploadLightData(vtkOpenGLRenderWindow* rw, const std::vector<float>& data);
  bool UploadLightView(vtkOpenGLRenderWindow* rw, const std::vector<float>& data);
  bool UploadQuads(vtkOpenGLRenderWindow* rw, const std::vector<float>& data);

  /// (Re)allocate the list and master textures for a layout; no-op if unchanged.
  bool AllocateTextures(
    vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::ClusterTextureLayout& layout);

  /// Run the list and master passes for numberOfQuads quads.
  bool BuildAssignment(vtkOpenGLRenderWindow* rw,
    const vtkClusteredLighting::ClusterTextureLayout& layout, int numberOfQuads,
    const vtkClusteredLightingListPassParameters& parameters);

  /// Bind the textures the shading code samples (before the delegate renders).
  void ActivateShadingTextures(bool clustered);
  void DeactivateShadingTextures();

  /// Texture units of the active textures (-1 when inactive).
  int GetLightDataUnit() const;
  int GetLightViewUnit() const;
  int GetListUnit() const;
  int GetMasterUnit() const;

  /// Read the list and master textures back (row-major, texel row 0 first).
  bool ReadBack(vtkOpenGLRenderWindow* rw, std::vector<std::uint32_t>& list,
    std::vector<std::uint32_t>& master);

  /// Number of GL objects (textures, buffers, FBO, VAO) currently alive.
  int GetNumberOfGLObjects() const;

  /// For tests: appends (kind, GL name) of every object currently alive, kind being
  /// GL_TEXTURE, GL_BUFFER, GL_FRAMEBUFFER or GL_VERTEX_ARRAY.
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;

  /// Bytes held by the light records, the list and the master texture.
  std::uint64_t GetLightBufferBytes() const;
  std::uint64_t GetListBytes() const;
  std::uint64_t GetMasterBytes() const;

  /// Release every GL object, with the context of w (or, for a null w, of the window the
  /// objects were made in, while it lives) made current for the duration: buffers and
  /// VAOs are deleted in whatever context is current, which may belong to another window.
  void ReleaseGraphicsResources(vtkWindow* w);

private:
  vtkClusteredLightingGPUResources(const vtkClusteredLightingGPUResources&) = delete;
  void operator=(const vtkClusteredLightingGPUResources&) = delete;

  struct TextureBuffer
  {
    vtkOpenGLBufferObject* Buffer = nullptr;
    vtkTextureObject* Texture = nullptr;
    std::size_t Texels = 0;
  };
  bool Upload(vtkOpenGLRenderWindow* rw, TextureBuffer& tb, const std::vector<float>& data);
  static void Release(TextureBuffer& tb, vtkWindow* w);
  static vtkTextureObject* NewIntegerTexture(vtkOpenGLRenderWindow* rw, int w, int h);
  bool BindTarget(vtkTextureObject* tex);
  void BindVAO();
  void SetContext(vtkOpenGLRenderWindow* rw);
  void OnWindowDeleted();

  TextureBuffer LightData;
  TextureBuffer LightView;
  TextureBuffer Quads;
  vtkTextureObject* List = nullptr;
  vtkTextureObject* Master = nullptr;
  vtkOpenGLFramebufferObject* FBO = nullptr;
  vtkOpenGLVertexArrayObject* VAO = nullptr;
  bool VAOCreated = false;
  unsigned int VAOName = 0;                      ///< for GetGLObjectNames
  vtkWeakPointer<vtkOpenGLRenderWindow> Context; ///< window the GL objects belong to
  unsigned long WindowObserver = 0;              ///< DeleteEvent observer on Context
  int ListSize[2] = { 0, 0 };
  int MasterSize[2] = { 0, 0 };
};

#endif
