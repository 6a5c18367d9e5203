// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingGLHelpers.h"

#include "vtkActor.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL calls

#include <cstring> // for std::strlen

//------------------------------------------------------------------------------
bool vtkClusteredLightingHasShaderCode(vtkActor* actor)
{
  vtkShaderProperty* shaders = actor ? actor->GetShaderProperty() : nullptr;
  return shaders &&
    (shaders->GetNumberOfShaderReplacements() > 0 || shaders->HasVertexShaderCode() ||
      shaders->HasGeometryShaderCode() || shaders->HasFragmentShaderCode());
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingDrawTargetClampsAtOne()
{
  GLint buffer = GL_NONE;
  glGetIntegerv(GL_DRAW_BUFFER0, &buffer);
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  if (framebuffer == 0)
  {
    // The default framebuffer names its buffers FRONT_LEFT ... BACK_RIGHT only.
    switch (buffer)
    {
      case GL_FRONT:
        buffer = GL_FRONT_LEFT;
        break;
      case GL_BACK:
      case GL_LEFT:
      case GL_FRONT_AND_BACK:
        buffer = GL_BACK_LEFT;
        break;
      case GL_RIGHT:
        buffer = GL_BACK_RIGHT;
        break;
      default:
        break;
    }
  }
  if (buffer == GL_NONE)
  {
    return false;
  }
  GLint object = GL_NONE;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, static_cast<GLenum>(buffer),
    GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &object);
  if (object == GL_NONE)
  {
    return false;
  }
  GLint type = GL_NONE;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, static_cast<GLenum>(buffer),
    GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
  return type == GL_UNSIGNED_NORMALIZED;
}

//------------------------------------------------------------------------------
unsigned int vtkClusteredLightingQueryDepthFormat(unsigned int binding)
{
  const GLenum depth = binding == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
  const GLenum stencil = binding == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
  GLint depthBits = 0, stencilBits = 0, type = 0, stencilType = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, depth, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &stencilType);
  if (stencilType != GL_NONE)
  {
    glGetFramebufferAttachmentParameteriv(
      GL_DRAW_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
  }
  bool failed = false;
  while (glGetError() != GL_NO_ERROR)
  {
    failed = true;
  }
  if (failed)
  {
    return 0;
  }
  if (depthBits == 24 && type == GL_UNSIGNED_NORMALIZED)
  {
    return stencilBits == 8 ? GL_DEPTH24_STENCIL8 : stencilBits == 0 ? GL_DEPTH_COMPONENT24 : 0;
  }
  if (depthBits == 32 && type == GL_UNSIGNED_NORMALIZED && stencilBits == 0)
  {
    return GL_DEPTH_COMPONENT32; // VTK 9.1's own render framebuffer
  }
  if (depthBits == 32 && type == GL_FLOAT)
  {
    return stencilBits == 8 ? GL_DEPTH32F_STENCIL8 : stencilBits == 0 ? GL_DEPTH_COMPONENT32F : 0;
  }
  if (depthBits == 16 && type == GL_UNSIGNED_NORMALIZED && stencilBits == 0)
  {
    return GL_DEPTH_COMPONENT16;
  }
  return 0;
}

//------------------------------------------------------------------------------
std::vector<float> vtkClusteredLightingQuerySamplePositions(int samples)
{
  std::vector<float> positions(2 * static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i)
  {
    glGetMultisamplefv(GL_SAMPLE_POSITION, static_cast<GLuint>(i), &positions[2 * i]);
  }
  return positions;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingBlitDepth(vtkOpenGLState* state, const int from[4], int toX, int toY)
{
  // A blit writes through the scissor test and the depth mask: neither may clip it.
  vtkOpenGLState::ScopedglEnableDisable savedScissorTest(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglBlitFramebuffer(from[0], from[1], from[0] + from[2], from[1] + from[3], toX, toY,
    toX + from[2], toY + from[3], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  bool failed = false;
  while (glGetError() != GL_NO_ERROR)
  {
    failed = true;
  }
  return !failed;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSetUniform4i(vtkShaderProgram* program, const char* name, const int v[4])
{
  const int location = program->FindUniform(name);
  if (location < 0)
  {
    return false;
  }
  glUniform4i(location, v[0], v[1], v[2], v[3]);
  return true;
}

//------------------------------------------------------------------------------
vtkClusteredLightingPlainDrawState::vtkClusteredLightingPlainDrawState(vtkOpenGLState* state)
  : Viewport(state)
  , ColorMask(state)
  , Blend(state, GL_BLEND)
  , Depth(state, GL_DEPTH_TEST)
  , Scissor(state, GL_SCISSOR_TEST)
  , Cull(state, GL_CULL_FACE)
{
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

//------------------------------------------------------------------------------
vtkClusteredLightingVertexArray::~vtkClusteredLightingVertexArray()
{
  this->Release(nullptr);
}

void vtkClusteredLightingVertexArray::Bind()
{
  if (!this->VAO)
  {
    this->VAO = vtkOpenGLVertexArrayObject::New();
  }
  this->VAO->Bind();
  this->Created = true;
  GLint name = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &name);
  this->Name = static_cast<unsigned int>(name);
}

void vtkClusteredLightingVertexArray::Unbind()
{
  if (this->VAO)
  {
    this->VAO->Release();
  }
}

void vtkClusteredLightingVertexArray::Release(vtkWindow* w)
{
  if (this->VAO)
  {
    if (w)
    {
      this->VAO->ReleaseGraphicsResources();
    }
    this->VAO->Delete();
    this->VAO = nullptr;
  }
  this->Created = false;
  this->Name = 0;
}

void vtkClusteredLightingVertexArray::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  if (this->Created)
  {
    names.emplace_back(GL_VERTEX_ARRAY, this->Name);
  }
}

//------------------------------------------------------------------------------
vtkClusteredLightingTextureBuffer::~vtkClusteredLightingTextureBuffer()
{
  this->Release(nullptr);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingTextureBuffer::Upload(
  vtkOpenGLRenderWindow* rw, const std::vector<float>& data)
{
  const std::size_t texels = data.size() / 4;
  if (texels == 0)
  {
    return true;
  }
  if (!this->Buffer)
  {
    this->Buffer = vtkOpenGLBufferObject::New();
    this->Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  }
  if (!this->Buffer->Upload(data, vtkOpenGLBufferObject::TextureBuffer))
  {
    return false;
  }
  if (!this->Texture || this->Texels != texels)
  {
    if (!this->Texture)
    {
      this->Texture = vtkTextureObject::New();
    }
    this->Texture->SetContext(rw);
    if (!this->Texture->CreateTextureBuffer(
          static_cast<unsigned int>(texels), 4, VTK_FLOAT, this->Buffer))
    {
      return false;
    }
    this->Texels = texels;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingTextureBuffer::Release(vtkWindow* w)
{
  vtkClusteredLightingReleaseObject(this->Texture, w);
  if (this->Buffer)
  {
    if (w)
    {
      this->Buffer->ReleaseGraphicsResources();
    }
    this->Buffer->Delete();
    this->Buffer = nullptr;
  }
  this->Texels = 0;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingTextureBuffer::GetNumberOfGLObjects() const
{
  return ((this->Texture && this->Texture->GetHandle()) ? 1 : 0) +
    ((this->Buffer && this->Buffer->GetHandle()) ? 1 : 0);
}

void vtkClusteredLightingTextureBuffer::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  if (this->Texture && this->Texture->GetHandle())
  {
    names.emplace_back(GL_TEXTURE, this->Texture->GetHandle());
  }
  if (this->Buffer && this->Buffer->GetHandle())
  {
    names.emplace_back(GL_BUFFER, static_cast<unsigned int>(this->Buffer->GetHandle()));
  }
}

//------------------------------------------------------------------------------
vtkClusteredLightingDebugGroup::vtkClusteredLightingDebugGroup(const char* name)
{
  if ((GLEW_VERSION_4_3 || GLEW_KHR_debug) && glPushDebugGroup)
  {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(std::strlen(name)), name);
    this->Pushed = true;
  }
}

vtkClusteredLightingDebugGroup::~vtkClusteredLightingDebugGroup()
{
  if (this->Pushed)
  {
    glPopDebugGroup();
  }
}
