// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingRasterBackend.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL calls

#include "vtkClusteredLightingFullScreenVS.h"
#include "vtkClusteredLightingListFS.h"
#include "vtkClusteredLightingListVS.h"
#include "vtkClusteredLightingMasterFS.h"

#include <algorithm> // for std::max
#include <string>    // for std::string

using namespace vtkClusteredLighting;

namespace
{
/// A w x h texture read with texelFetch (nearest, clamped); nullptr when it cannot be
/// allocated.
vtkTextureObject* NewTexelTexture(vtkOpenGLRenderWindow* rw, int w, int h, unsigned int internal,
  unsigned int format, unsigned int glType, int components, int vtkType)
{
  vtkTextureObject* tex = vtkTextureObject::New();
  tex->SetContext(rw);
  tex->SetInternalFormat(internal);
  tex->SetFormat(format);
  tex->SetDataType(glType);
  tex->SetMinificationFilter(vtkTextureObject::Nearest);
  tex->SetMagnificationFilter(vtkTextureObject::Nearest);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  if (!tex->Allocate2D(
        static_cast<unsigned int>(w), static_cast<unsigned int>(h), components, vtkType))
  {
    tex->Delete();
    return nullptr;
  }
  return tex;
}

/// Re-allocates `tex` when its size differs from (w, h); returns whether it exists.
bool Reallocate(vtkOpenGLRenderWindow* rw, vtkTextureObject*& tex, int size[2], int w, int h)
{
  if (tex && size[0] == w && size[1] == h)
  {
    return true;
  }
  vtkClusteredLightingReleaseObject(tex, rw);
  tex = NewTexelTexture(rw, w, h, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, 1, VTK_UNSIGNED_INT);
  size[0] = tex ? w : 0;
  size[1] = tex ? h : 0;
  return tex != nullptr;
}

}

//------------------------------------------------------------------------------
vtkClusteredLightingRasterBackend::~vtkClusteredLightingRasterBackend()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingRasterBackend::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Quads.Release(w);
  vtkClusteredLightingReleaseObject(this->List, w);
  vtkClusteredLightingReleaseObject(this->Master, w);
  vtkClusteredLightingReleaseObject(this->ClusterDepths, w);
  vtkClusteredLightingReleaseObject(this->ClusterRects, w);
  vtkClusteredLightingReleaseObject(this->FBO, w);
  this->VAO.Release(w);
  this->ListSize[0] = this->ListSize[1] = 0;
  this->MasterSize[0] = this->MasterSize[1] = 0;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingRasterBackend::GetNumberOfGLObjects() const
{
  return this->Quads.GetNumberOfGLObjects() + ((this->List && this->List->GetHandle()) ? 1 : 0) +
    ((this->Master && this->Master->GetHandle()) ? 1 : 0) +
    ((this->ClusterDepths && this->ClusterDepths->GetHandle()) ? 1 : 0) +
    ((this->ClusterRects && this->ClusterRects->GetHandle()) ? 1 : 0) +
    ((this->FBO && this->FBO->GetFBOIndex()) ? 1 : 0) + this->VAO.GetNumberOfGLObjects();
}

void vtkClusteredLightingRasterBackend::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  this->Quads.GetGLObjectNames(names);
  for (vtkTextureObject* tex :
    { this->List, this->Master, this->ClusterDepths, this->ClusterRects })
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
  this->VAO.GetGLObjectNames(names);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingRasterBackend::AllocateTextures(
  vtkOpenGLRenderWindow* rw, const ClusterTextureLayout& layout)
{
  const bool list = Reallocate(rw, this->List, this->ListSize, layout.ListWidth, layout.ListHeight);
  const bool master =
    Reallocate(rw, this->Master, this->MasterSize, layout.MasterWidth, layout.MasterHeight);
  return list && master;
}

//------------------------------------------------------------------------------
//------------------------------------------------------------------------------
bool vtkClusteredLightingRasterBackend::BindTarget(vtkTextureObject* tex)
{
  this->FBO->AddColorAttachment(0, tex);
  this->FBO->ActivateDrawBuffers(1);
  return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingRasterBackend::Assign(vtkOpenGLRenderWindow* rw,
  const ClusterTextureLayout& layout, const ViewData& view, const ListPassParameters& parameters,
  vtkTextureObject* lightView)
{
  if (!this->AllocateTextures(rw, layout) || !this->Quads.Upload(rw, view.Quads))
  {
    return false;
  }
  vtkOpenGLState* state = rw->GetState();
  if (!this->FBO)
  {
    this->FBO = vtkOpenGLFramebufferObject::New();
  }
  this->FBO->SetContext(rw);

  // vtkOpenGLState does not track the vertex array binding (VAO::Release binds 0).
  GLint vertexArray = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
  bool ok = true;
  state->PushFramebufferBindings();
  {
    vtkClusteredLightingPlainDrawState plain(state);
    this->FBO->Bind();
    ok = this->RunListPass(rw, layout, view.NumberOfQuads, parameters, lightView) &&
      this->RunMasterPass(rw, layout, parameters.DepthBounds != nullptr);
    this->FBO->RemoveColorAttachments(1);
    this->FBO->UnBind();
  }
  state->PopFramebufferBindings();
  glBindVertexArray(static_cast<GLuint>(vertexArray));
  return ok;
}

//------------------------------------------------------------------------------
// Each cluster's depth interval as an RG32F texel (s * X + tx, ty), and its screen
// rectangle as an RGBA32F texel of a second texture.
bool vtkClusteredLightingRasterBackend::UploadClusterDepths(
  vtkOpenGLRenderWindow* rw, const ClusterDepthBounds& bounds)
{
  if (bounds.Rects.size() != 2 * bounds.LoHi.size())
  {
    return false;
  }
  auto upload = [&](vtkTextureObject*& tex, int components, const float* data)
  {
    if (tex &&
      (static_cast<int>(tex->GetWidth()) != bounds.Width ||
        static_cast<int>(tex->GetHeight()) != bounds.Height))
    {
      vtkClusteredLightingReleaseObject(tex, rw);
    }
    const GLenum format = components == 2 ? GL_RG : GL_RGBA;
    if (!tex)
    {
      tex = NewTexelTexture(rw, bounds.Width, bounds.Height,
        components == 2 ? GL_RG32F : GL_RGBA32F, format, GL_FLOAT, components, VTK_FLOAT);
      if (!tex)
      {
        return false;
      }
    }
    tex->Bind();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, bounds.Width, bounds.Height, format, GL_FLOAT, data);
    return true;
  };
  return upload(this->ClusterDepths, 2, bounds.LoHi.data()) &&
    upload(this->ClusterRects, 4, bounds.Rects.data());
}

//------------------------------------------------------------------------------
// The list and master passes have two programs each: the depth-aware one (CL_DEPTH_AWARE)
// reads the cluster-depth texture, activated here (DeactivateDepths after the draw).
vtkShaderProgram* vtkClusteredLightingRasterBackend::ReadyProgram(
  vtkOpenGLRenderWindow* rw, const char* vs, const char* fs, bool depthAware)
{
  std::string source = fs;
  if (depthAware)
  {
    vtkShaderProgram::Substitute(source, "//CL_DEPTH_AWARE", "#define CL_DEPTH_AWARE");
  }
  vtkShaderProgram* program = rw->GetShaderCache()->ReadyShaderProgram(vs, source.c_str(), "");
  if (program && depthAware)
  {
    this->ClusterDepths->Activate();
    program->SetUniformi("clClusterDepths", this->ClusterDepths->GetTextureUnit());
  }
  return program;
}

void vtkClusteredLightingRasterBackend::DeactivateDepths(bool depthAware)
{
  if (depthAware)
  {
    this->ClusterDepths->Deactivate();
  }
}

//------------------------------------------------------------------------------
// One instanced quad per (light, slice) rectangle, bits OR-ed into the list texture.
bool vtkClusteredLightingRasterBackend::RunListPass(vtkOpenGLRenderWindow* rw,
  const ClusterTextureLayout& layout, int numberOfQuads, const ListPassParameters& parameters,
  vtkTextureObject* lightView)
{
  vtkClusteredLightingDebugGroup group("vtkClusteredLighting list pass");
  if (!this->BindTarget(this->List))
  {
    return false;
  }
  rw->GetState()->vtkglViewport(0, 0, layout.ListWidth, layout.ListHeight);
  const GLuint zero[4] = { 0u, 0u, 0u, 0u };
  glClearBufferuiv(GL_COLOR, 0, zero);
  const bool depthAware = parameters.DepthBounds != nullptr;
  if (depthAware && !this->UploadClusterDepths(rw, *parameters.DepthBounds))
  {
    return false;
  }
  if (!depthAware)
  {
    this->ReleaseDepthResources(rw); // held only while the clusters are depth-aware
  }
  if (numberOfQuads <= 0 || !this->Quads.GetTexture() || !lightView)
  {
    return true;
  }
  vtkShaderProgram* program =
    this->ReadyProgram(rw, vtkClusteredLightingListVS, vtkClusteredLightingListFS, depthAware);
  if (!program)
  {
    return false;
  }
  if (depthAware)
  {
    this->ClusterRects->Activate();
    program->SetUniformi("clClusterRects", this->ClusterRects->GetTextureUnit());
  }
  vtkTextureObject* quads = this->Quads.GetTexture();
  quads->Activate();
  lightView->Activate();
  program->SetUniformi("clQuads", quads->GetTextureUnit());
  program->SetUniformi("clLightView", lightView->GetTextureUnit());
  const int grid[4] = { layout.TilesX, layout.TilesY, layout.Slices, layout.BatchRows };
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
  this->VAO.Bind();
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
  this->VAO.Unbind();
  lightView->Deactivate();
  quads->Deactivate();
  if (depthAware)
  {
    this->ClusterRects->Deactivate();
  }
  this->DeactivateDepths(depthAware);
  return true;
}

//------------------------------------------------------------------------------
// One bit per non-empty 32-light batch of each cluster.
bool vtkClusteredLightingRasterBackend::RunMasterPass(
  vtkOpenGLRenderWindow* rw, const ClusterTextureLayout& layout, bool depthAware)
{
  vtkClusteredLightingDebugGroup group("vtkClusteredLighting master pass");
  if (!this->BindTarget(this->Master))
  {
    return false;
  }
  rw->GetState()->vtkglViewport(0, 0, layout.MasterWidth, layout.MasterHeight);
  // The depth-aware program skips the clusters without fragments.
  depthAware = depthAware && this->ClusterDepths;
  vtkShaderProgram* program = this->ReadyProgram(
    rw, vtkClusteredLightingFullScreenVS, vtkClusteredLightingMasterFS, depthAware);
  if (!program)
  {
    return false;
  }
  this->List->Activate();
  program->SetUniformi("clList", this->List->GetTextureUnit());
  const int grid[4] = { layout.TilesX, layout.TilesY, layout.Slices, layout.BatchRows };
  vtkClusteredLightingSetUniform4i(program, "clGrid", grid);
  program->SetUniformi("clBatches", layout.Batches);
  program->SetUniformi("clMasterTexels", std::max(layout.MasterTexelsPerCluster, 1));
  this->VAO.Bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  this->VAO.Unbind();
  this->List->Deactivate();
  this->DeactivateDepths(depthAware);
  return true;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingRasterBackend::ReleaseDepthResources(vtkOpenGLRenderWindow* rw)
{
  vtkClusteredLightingReleaseObject(this->ClusterDepths, rw);
  vtkClusteredLightingReleaseObject(this->ClusterRects, rw);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingRasterBackend::ActivateShadingTextures()
{
  if (this->List && this->Master)
  {
    this->List->Activate();
    this->Master->Activate();
  }
}

void vtkClusteredLightingRasterBackend::DeactivateShadingTextures()
{
  for (vtkTextureObject* tex : { this->List, this->Master })
  {
    if (tex && tex->GetTextureUnit() >= 0)
    {
      tex->Deactivate();
    }
  }
}

int vtkClusteredLightingRasterBackend::GetListUnit() const
{
  return this->List ? this->List->GetTextureUnit() : -1;
}

int vtkClusteredLightingRasterBackend::GetMasterUnit() const
{
  return this->Master ? this->Master->GetTextureUnit() : -1;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingRasterBackend::ReadBack(
  vtkOpenGLRenderWindow* rw, std::vector<std::uint32_t>& list, std::vector<std::uint32_t>& master)
{
  if (!this->List || !this->Master)
  {
    return false;
  }
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
std::uint64_t vtkClusteredLightingRasterBackend::GetListBytes() const
{
  return 4ull * this->ListSize[0] * this->ListSize[1];
}

std::uint64_t vtkClusteredLightingRasterBackend::GetMasterBytes() const
{
  return 4ull * this->MasterSize[0] * this->MasterSize[1];
}

std::uint64_t vtkClusteredLightingRasterBackend::GetWorkBytes() const
{
  return 16ull * this->Quads.GetNumberOfTexels();
}
