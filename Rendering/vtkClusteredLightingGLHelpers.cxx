// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingGLHelpers.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL calls

#include <cstring> // for std::strlen

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
  if (this->Texture)
  {
    if (w)
    {
      this->Texture->ReleaseGraphicsResources(w);
    }
    this->Texture->Delete();
    this->Texture = nullptr;
  }
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
