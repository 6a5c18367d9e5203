// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingGLHelpers.h
 * @brief Small GL building blocks shared by the light buffers and the assignment back end.
 *
 * Private to the module:
 *  - vtkClusteredLightingTextureBuffer: a float RGBA texture buffer (a buffer object plus
 *    the texture that samples it), re-created only when its size changes;
 *  - vtkClusteredLightingDebugGroup: a scoped GL debug group (glPushDebugGroup), so that
 *    the list and master passes show up by name in GL debuggers and traces; a no-op where
 *    neither GL 4.3 nor KHR_debug is available;
 *  - vtkClusteredLightingVertexArray: the attribute-free vertex array that full-screen
 *    and instanced draws bind (core profiles need one), with its GL name for the tests;
 *  - vtkClusteredLightingReleaseObject: releases and deletes a texture or framebuffer;
 *  - vtkClusteredLightingPlainDrawState: the state of a draw that writes every texel it
 *    covers (no blending, depth, scissor or culling, every colour channel), restored
 *    when it goes out of scope;
 *  - vtkClusteredLightingSetUniform4i: vtkShaderProgram has no ivec4 setter in VTK 9.1;
 *  - vtkClusteredLightingDrawTargetClampsAtOne: whether the colour being drawn clamps;
 *  - vtkClusteredLightingQueryDepthFormat, vtkClusteredLightingQuerySamplePositions: what
 *    a copy of the draw framebuffer's depth must match (its format, its samples);
 *  - vtkClusteredLightingBlitDepth: one such copy between the bound framebuffers;
 *  - vtkClusteredLightingHasShaderCode: whether an actor brings shader code of its own.
 *
 * None of them makes a context current: callers do (see vtkClusteredLightingAssigner).
 */
#ifndef vtkClusteredLightingGLHelpers_h
#define vtkClusteredLightingGLHelpers_h

#include "vtkOpenGLState.h" // for the scoped state of vtkClusteredLightingPlainDrawState

#include <cstddef> // for std::size_t
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkActor;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

/// Whether `actor`'s shader property holds shader code or replacements of its own: they
/// may move its vertices, set its fragments' depths or discard fragments.
bool vtkClusteredLightingHasShaderCode(vtkActor* actor);

/// True if the current draw framebuffer's first draw buffer stores fixed-point colour
/// (GL_UNSIGNED_NORMALIZED: written values clamp to [0, 1]). False for float targets (a
/// vtkToneMappingPass around the pass, for one), for no draw buffer, and if the query
/// fails. Needs a current context.
bool vtkClusteredLightingDrawTargetClampsAtOne();

/// The internal format of the current draw framebuffer's depth buffer (`binding` is its
/// name, 0 for the window's own), or 0 when it is not one whose depth can be copied
/// exactly: 24-bit or 32-bit float, each with or without 8 stencil bits; 32-bit fixed
/// point (VTK 9.1's own render framebuffer) or 16-bit without.
unsigned int vtkClusteredLightingQueryDepthFormat(unsigned int binding);

/// The positions of the current draw framebuffer's `samples` samples (x, y each).
std::vector<float> vtkClusteredLightingQuerySamplePositions(int samples);

/// Copies the depths of the bound read framebuffer's rectangle `from` (x, y, width,
/// height) to (toX, toY) of the bound draw framebuffer with glBlitFramebuffer (from a
/// multisampled one into a single-sampled one it keeps one sample per pixel), lifting the
/// scissor test and the depth mask while it copies. False on a GL error.
bool vtkClusteredLightingBlitDepth(vtkOpenGLState* state, const int from[4], int toX, int toY);

/// ivec4 uniform setter (the program must be bound). Returns false if the program does
/// not use the uniform.
bool vtkClusteredLightingSetUniform4i(vtkShaderProgram* program, const char* name, const int v[4]);

/// Releases `object` (a vtkTextureObject or vtkOpenGLFramebufferObject) in the current
/// context when `w` is given, deletes it and sets it to null.
template <class T>
void vtkClusteredLightingReleaseObject(T*& object, vtkWindow* w)
{
  if (object)
  {
    if (w)
    {
      object->ReleaseGraphicsResources(w);
    }
    object->Delete();
    object = nullptr;
  }
}

/// Sets the state of a draw that writes every texel it covers, and restores the
/// previous state (viewport included, which the caller sets) when destroyed.
class vtkClusteredLightingPlainDrawState
{
public:
  explicit vtkClusteredLightingPlainDrawState(vtkOpenGLState* state);

private:
  vtkClusteredLightingPlainDrawState(const vtkClusteredLightingPlainDrawState&) = delete;
  void operator=(const vtkClusteredLightingPlainDrawState&) = delete;

  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Depth;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglEnableDisable Cull;
};

/// An attribute-free vertex array (created on the first Bind).
class vtkClusteredLightingVertexArray
{
public:
  vtkClusteredLightingVertexArray() = default;
  ~vtkClusteredLightingVertexArray();

  /// Binds it, creating it first if needed.
  void Bind();
  /// Binds no vertex array.
  void Unbind();
  /// Deletes the GL object (in the current context when w is given).
  void Release(vtkWindow* w);
  int GetNumberOfGLObjects() const { return this->Created ? 1 : 0; }
  /// Appends (GL_VERTEX_ARRAY, name) when it exists.
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;

private:
  vtkClusteredLightingVertexArray(const vtkClusteredLightingVertexArray&) = delete;
  void operator=(const vtkClusteredLightingVertexArray&) = delete;

  vtkOpenGLVertexArrayObject* VAO = nullptr;
  bool Created = false;
  unsigned int Name = 0; ///< for GetGLObjectNames
};

/// A float RGBA texture buffer (samplerBuffer in GLSL).
class vtkClusteredLightingTextureBuffer
{
public:
  vtkClusteredLightingTextureBuffer() = default;
  ~vtkClusteredLightingTextureBuffer();

  /// Uploads data (4 floats per texel); keeps the texture when the size is unchanged.
  /// An empty vector keeps whatever was uploaded before.
  bool Upload(vtkOpenGLRenderWindow* rw, const std::vector<float>& data);

  /// Deletes the GL objects (in the current context when w is given).
  void Release(vtkWindow* w);

  vtkTextureObject* GetTexture() const { return this->Texture; }
  std::size_t GetNumberOfTexels() const { return this->Texels; }
  int GetNumberOfGLObjects() const;
  /// Appends (GL_TEXTURE or GL_BUFFER, name) of the live objects.
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;

private:
  vtkClusteredLightingTextureBuffer(const vtkClusteredLightingTextureBuffer&) = delete;
  void operator=(const vtkClusteredLightingTextureBuffer&) = delete;

  vtkOpenGLBufferObject* Buffer = nullptr;
  vtkTextureObject* Texture = nullptr;
  std::size_t Texels = 0;
};

/// Scoped GL debug group: pushed by the constructor, popped by the destructor.
class vtkClusteredLightingDebugGroup
{
public:
  explicit vtkClusteredLightingDebugGroup(const char* name);
  ~vtkClusteredLightingDebugGroup();

private:
  vtkClusteredLightingDebugGroup(const vtkClusteredLightingDebugGroup&) = delete;
  void operator=(const vtkClusteredLightingDebugGroup&) = delete;

  bool Pushed = false;
};

#endif
