// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingGPUResources.h"

#include "vtkCommand.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL calls

#include "vtkClusteredLightingFullScreenVS.h"
#include "vtkClusteredLightingListFS.h"
#include "vtkClusteredLightingListVS.h"
#include "vtkClusteredLightingMasterFS.h"

using namespace vtkClusteredLighting;

//------------------------------------------------------------------------------
// vtkShaderProgram has no ivec4 setter in VTK 9.1; the program must be bound.
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
vtkClusteredLightingGPUResources::vtkClusteredLightingGPUResources() = default;

//------------------------------------------------------------------------------
vtkClusteredLightingGPUResources::~vtkClusteredLightingGPUResources()
{
  this->ReleaseGraphicsResources(nullptr);
  this->SetContext(nullptr);
}

//------------------------------------------------------------------------------
// The window is watched so that its GL objects are released, in its own context, when it
// is deleted, even if its renderer no longer uses the pass then (VTK only releases the
// passes of the renderers it still holds, and vtkOpenGLBufferObject would later delete
// its stale name in whatever context is current).
void vtkClusteredLightingGPUResources::SetContext(vtkOpenGLRenderWindow* rw)
{
  if (this->Context == rw)
  {
    return;
  }
  if (this->Context && this->WindowObserver)
  {
    this->Context->RemoveObserver(this->WindowObserver);
  }
  this->WindowObserver = 0;
  this->Context = rw;
  if (rw)
  {
    this->WindowObserver = rw->AddObserver(
      vtkCommand::DeleteEvent, this, &vtkClusteredLightingGPUResources::OnWindowDeleted);
  }
}

void vtkClusteredLightingGPUResources::OnWindowDeleted()
{
  this->ReleaseGraphicsResources(this->Context);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingGPUResources::Release(TextureBuffer& tb, vtkWindow* w)
{
  if (tb.Texture)
  {
    if (w)
    {
      tb.Texture->ReleaseGraphicsResources(w);
    }
    tb.Texture->Delete();
    tb.Texture = nullptr;
  }
  if (tb.Buffer)
  {
    if (w)
    {
      tb.Buffer->ReleaseGraphicsResources();
    }
    tb.Buffer->Delete();
    tb.Buffer = nullptr;
  }
  tb.Texels = 0;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingGPUResources::ReleaseGraphicsResources(vtkWindow* win)
{
  // Make the objects' own context current: vtkOpenGLBufferObject and
  // vtkOpenGLVertexArrayObject delete their names in whatever context is current (which
  // may be another window's, with names of its own), and a null window (destructor)
  // would otherwise leave them alive.
  vtkOpenGLRenderWindow* w =
    vtkOpenGLRenderWindow::SafeDownCast(win ? win : this->Context.GetPointer());
  const bool push = w && this->GetNumberOfGLObjects() > 0;
  if (push)
  {
    w->PushContext();
  }
  Release(this->LightData, w);
  Release(this->LightView, w);
  Release(this->Quads, w);
  for (vtkTextureObject** tex : { &this->List, &this->Master })
  {
    if (*tex)
    {
      if (w)
      {
        (*tex)->ReleaseGraphicsResources(w);
      }
      (*tex)->Delete();
      *tex = nullptr;
    }
  }
  if (this->FBO)
  {
    if (w)
    {
      this->FBO->ReleaseGraphicsResources(w);
    }
    this->FBO->Delete();
    this->FBO = nullptr;
  }
  if (this->VAO)
  {
    if (w)
    {
      this->VAO->ReleaseGraphicsResources();
    }
    this->VAO->Delete();
    this->VAO = nullptr;
  }
  this->VAOCreated = false;
  this->VAOName = 0;
  this->ListSize[0] = this->ListSize[1] = 0;
  this->MasterSize[0] = this->MasterSize[1] = 0;
  if (push)
  {
    w->PopContext();
  }
}

//------------------------------------------------------------------------------
int vtkClusteredLightingGPUResources::GetNumberOfGLObjects() const
{
  int n = 0;
  for (const TextureBuffer* tb : { &this->LightData, &this->LightView, &this->Quads })
  {
    n += (tb->Texture && tb->Texture->GetHandle()) ? 1 : 0;
    n += (tb->Buffer && tb->Buffer->GetHandle()) ? 1 : 0;
  }
  n += (this->List && this->List->GetHandle()) ? 1 : 0;
  n += (this->Master && this->Master->GetHandle()) ? 1 : 0;
  n += (this->FBO && this->FBO->GetFBOIndex()) ? 1 : 0;
  n += (this->VAO && this->VAOCreated) ? 1 : 0;
  return n;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingGPUResources::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  for (const TextureBuffer* tb : { &this->LightData, &this->LightView, &this->Quads })
  {
    if (tb->Texture && tb->Texture->GetHandle())
    {
      names.emplace_back(GL_TEXTURE, tb->Texture->GetHandle());
    }
    if (tb->Buffer && tb->Buffer->GetHandle())
    {
      names.emplace_back(GL_BUFFER, static_cast<unsigned int>(tb->Buffer->GetHandle()));
    }
  }
  for (vtkTextureObject* tex : { this->List, this->Master })
  {
    if (tex && tex->GetHandle())
    {
      names.emplace_back(GL_TEXTURE, tex->GetHandle());
    }
  }
  if (this->FBO && this->FBO->GetFBOIndex())
  {
    names.emplace_back(GL_FRAMEBUFFER, this->FBO->GetFBOIndex());
  }
  if (this->VAO && this->VAOCreated)
  {
    names.emplace_back(GL_VERTEX_ARRAY, this->VAOName);
  }
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingGPUResources::Upload(
  vtkOpenGLRenderWindow* rw, TextureBuffer& tb, const std::vector<float>& data)
{
  this->SetContext(rw);
  const std::size_t texels = data.size() / 4;
  if (texels == 0)
  {
    return true;
  }
  if (!tb.Buffer)
  {
    tb.Buffer = vtkOpenGLBufferObject::New();
    tb.Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  }
  if (!tb.Buffer->Upload(data, vtkOpenGLBufferObject::TextureBuffer))
  {
    return false;
  }
  if (!tb.Texture || tb.Texels != texels)
  {
    if (!tb.Texture)
    {
      tb.Texture = vtkTextureObject::New();
    }
    tb.Texture->SetContext(rw);
    if (!tb.Texture->CreateTextureBuffer(
          static_cast<unsigned int>(texels), 4, VTK_FLOAT, tb.Buffer))
    {
      return false;
    }
    tb.Texels = texels;
  }
  return true;
}

bool vtkClusteredLightingGPUResources::UploadLightData(
  vtkOpenGLRenderWindow* rw, const std::vector<float>& data)
{
  return this->Upload(rw, this->LightData, data);
}

bool vtkClusteredLightingGPUResources::UploadLightView(
  vtkOpenGLRenderWindow* rw, const std::vector<float>& data)
{
  return this->Upload(rw, this->LightView, data);
}

bool vtkClusteredLightingGPUResources::UploadQuads(
  vtkOpenGLRenderWindow* rw, const std::vector<float>& data)
{
  return this->Upload(rw, this->Quads, data);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkClusteredLightingGPUResources::NewIntegerTexture(
  vtkOpenGLRenderWindow* rw, int w, int h)
{
  vtkTextureObject* tex = vtkTextureObject::New();
  tex->SetContext(rw);
  tex->SetInternalFormat(GL_R32UI);
  tex->SetFormat(GL_RED_INTEGER);
  tex->SetDataType(GL_UNSIGNED_INT);
  tex->SetMinificationFilter(vtkTextureObject::Nearest);
  tex->SetMagnificationFilter(vtkTextureObject::Nearest);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  if (!tex->Allocate2D(
        static_cast<unsigned int>(w), static_cast<unsigned int>(h), 1, VTK_UNSIGNED_INT))
  {
    tex->Delete();
    return nullptr;
  }
  return tex;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingGPUResources::AllocateTextures(
  vtkOpenGLRenderWindow* rw, const ClusterTextureLayout& layout)
{
  this->SetContext(rw);
  if (!this->List || this->ListSize[0] != layout.ListWidth ||
    this->ListSize[1] != layout.ListHeight)
  {
    if (this->List)
    {
      this->List->ReleaseGraphicsResources(rw);
      this->List->Delete();
    }
    this->List = NewIntegerTexture(rw, layout.ListWidth, layout.ListHeight);
    this->ListSize[0] = this->List ? layout.ListWidth : 0;
    this->ListSize[1] = this->List ? layout.ListHeight : 0;
  }
  if (!this->Master || this->MasterSize[0] != layout.MasterWidth ||
    this->MasterSize[1] != layout.MasterHeight)
  {
    if (this->Master)
    {
      this->Master->ReleaseGraphicsResources(rw);
      this->Master->Delete();
    }
    this->Master = NewIntegerTexture(rw, layout.MasterWidth, layout.MasterHeight);
    this->MasterSize[0] = this->Master ? layout.MasterWidth : 0;
    this->MasterSize[1] = this->Master ? layout.MasterHeight : 0;
  }
  return this->List && this->Master;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingGPUResources::BindVAO()
{
  this->VAO->Bind();
  this->VAOCreated = true;
  GLint name = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &name);
  this->VAOName = static_cast<unsigned int>(name);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingGPUResources::BindTarget(vtkTextureObject* tex)
{
  this->FBO->AddColorAttachment(0, tex);
  this->FBO->ActivateDrawBuffers(1);
  return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingGPUResources::BuildAssignment(vtkOpenGLRenderWindow* rw,
  const ClusterTextureLayout& layout, int numberOfQuads,
  const vtkClusteredLightingListPassParameters& parameters)
{
  if (!this->List || !this->Master)
  {
    return false;
  }
  vtkOpenGLState* state = rw->GetState();
  vtkOpenGLShaderCache* cache = rw->GetShaderCache();
  if (!this->FBO)
  {
    this->FBO = vtkOpenGLFramebufferObject::New();
  }
  if (!this->VAO)
  {
    this->VAO = vtkOpenGLVertexArrayObject::New();
  }
  this->FBO->SetContext(rw);

  bool ok = true;
  // Nor the vertex array binding (vtkOpenGLVertexArrayObject::Release binds 0).
  GLint vertexArray = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
  state->PushFramebufferBindings();
  {
    vtkOpenGLState::ScopedglViewport savedViewport(state);
    vtkOpenGLState::ScopedglColorMask savedColorMask(state);
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable savedCull(state, GL_CULL_FACE);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    this->FBO->Bind();
    const GLuint zero[4] = { 0u, 0u, 0u, 0u };
    const int grid[4] = { layout.TilesX, layout.TilesY, layout.Slices, layout.BatchRows };

    // --- list pass: one instanced quad per visible light, bits OR-ed in ---
    ok = this->BindTarget(this->List);
    if (ok)
    {
      state->vtkglViewport(0, 0, layout.ListWidth, layout.ListHeight);
      glClearBufferuiv(GL_COLOR, 0, zero);
      if (numberOfQuads > 0 && this->Quads.Texture && this->LightView.Texture)
      {
        vtkShaderProgram* program =
          cache->ReadyShaderProgram(vtkClusteredLightingListVS, vtkClusteredLightingListFS, "");
        ok = program != nullptr;
        if (ok)
        {
          this->Quads.Texture->Activate();
          this->LightView.Texture->Activate();
          program->SetUniformi("clQuads", this->Quads.Texture->GetTextureUnit());
          program->SetUniformi("clLightView", this->LightView.Texture->GetTextureUnit());
          vtkClusteredLightingSetUniform4i(program, "clGrid", grid);
          const float size[2] = { static_cast<float>(layout.ListWidth),
            static_cast<float>(layout.ListHeight) };
          program->SetUniform2f("clListSize", size);
          program->SetUniformi("clCullClusters", parameters.CullClusters ? 1 : 0);
          program->SetUniform3f("clProjectionX", parameters.ProjectionX);
          program->SetUniform3f("clProjectionY", parameters.ProjectionY);
          program->SetUniform2f("clProjectionW", parameters.ProjectionW);
          program->SetUniform4f("clSlicing", parameters.Slicing);
          program->SetUniform2f("clDepthRange", parameters.DepthRange);
          this->BindVAO();
          // vtkOpenGLState does not track the logic op: restore exactly what was set.
          const GLboolean logicOp = glIsEnabled(GL_COLOR_LOGIC_OP);
          GLint logicOpMode = GL_COPY;
          glGetIntegerv(GL_LOGIC_OP_MODE, &logicOpMode);
          glEnable(GL_COLOR_LOGIC_OP);
          glLogicOp(GL_OR);
          glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, numberOfQuads);
          glLogicOp(static_cast<GLenum>(logicOpMode));
          if (!logicOp)
          {
            glDisable(GL_COLOR_LOGIC_OP);
          }
          this->VAO->Release();
          this->LightView.Texture->Deactivate();
          this->Quads.Texture->Deactivate();
        }
      }
    }

    // --- master pass: one bit per non-empty 32-light batch ---
    ok = ok && this->BindTarget(this->Master);
    if (ok)
    {
      state->vtkglViewport(0, 0, layout.MasterWidth, layout.MasterHeight);
      vtkShaderProgram* program = cache->ReadyShaderProgram(
        vtkClusteredLightingFullScreenVS, vtkClusteredLightingMasterFS, "");
      ok = program != nullptr;
      if (ok)
      {
        this->List->Activate();
        program->SetUniformi("clList", this->List->GetTextureUnit());
        vtkClusteredLightingSetUniform4i(program, "clGrid", grid);
        program->SetUniformi("clBatches", layout.Batches);
        program->SetUniformi("clMasterTexels", std::max(layout.MasterTexelsPerCluster, 1));
        this->BindVAO();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        this->VAO->Release();
        this->List->Deactivate();
      }
    }
    this->FBO->RemoveColorAttachments(1);
    this->FBO->UnBind();
  }
  state->PopFramebufferBindings();
  glBindVertexArray(static_cast<GLuint>(vertexArray));
  return ok;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingGPUResources::ActivateShadingTextures(bool clustered)
{
  for (vtkTextureObject* tex : { this->LightData.Texture, this->LightView.Texture })
  {
    if (tex)
    {
      tex->Activate();
    }
  }
  if (clustered && this->List && this->Master)
  {
    this->List->Activate();
    this->Master->Activate();
  }
}

void vtkClusteredLightingGPUResources::DeactivateShadingTextures()
{
  for (vtkTextureObject* tex :
    { this->LightData.Texture, this->LightView.Texture, this->List, this->Master })
  {
    if (tex && tex->GetTextureUnit() >= 0)
    {
      tex->Deactivate();
    }
  }
}

int vtkClusteredLightingGPUResources::GetLightDataUnit() const
{
  return this->LightData.Texture ? this->LightData.Texture->GetTextureUnit() : -1;
}
int vtkClusteredLightingGPUResources::GetLightViewUnit() const
{
  return this->LightView.Texture ? this->LightView.Texture->GetTextureUnit() : -1;
}
int vtkClusteredLightingGPUResources::GetListUnit() const
{
  return this->List ? this->List->GetTextureUnit() : -1;
}
int vtkClusteredLightingGPUResources::GetMasterUnit() const
{
  return this->Master ? this->Master->GetTextureUnit() : -1;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingGPUResources::ReadBack(
  vtkOpenGLRenderWindow* rw, std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& master)
{
  if (!this->List || !this->Master)
  {
    return false;
  }
  rw->MakeCurrent();
  vtkOpenGLState::ScopedglActiveTexture savedUnit(rw->GetState());
  list.assign(static_cast<std::size_t>(this->ListSize[0]) * this->ListSize[1], 0u);
  master.assign(static_cast<std::size_t>(this->MasterSize[0]) * this->MasterSize[1], 0u);
  // Through vtkOpenGLState: a direct glPixelStorei would leave VTK's cached pack
  // alignment stale, and VTK's next RGB read-back would overrun its buffer.
  rw->GetState()->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  this->List->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, list.data());
  this->List->Deactivate();
  this->Master->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, master.data());
  this->Master->Deactivate();
  return glGetError() == GL_NO_ERROR;
}

//------------------------------------------------------------------------------
std::uint64_t vtkClusteredLightingGPUResources::GetLightBufferBytes() const
{
  return 16u * (this->LightData.Texels + this->LightView.Texels + this->Quads.Texels);
}

std::uint64_t vtkClusteredLightingGPUResources::GetListBytes() const
{
  return 4ull * this->ListSize[0] * this->ListSize[1];
}

std::uint64_t vtkClusteredLightingGPUResources::GetMasterBytes() const
{
  return 4ull * this->MasterSize[0] * this->MasterSize[1];
}
