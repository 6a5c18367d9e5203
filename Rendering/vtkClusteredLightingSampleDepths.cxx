// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingSampleDepths.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL calls

#include "vtkClusteredLightingFullScreenVS.h"
#include "vtkClusteredLightingSampleDepthsFS.h"

#include <cstddef> // for std::size_t

//------------------------------------------------------------------------------
vtkClusteredLightingSampleDepths::~vtkClusteredLightingSampleDepths()
{
  this->Release(nullptr);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSampleDepths::IsDrawFramebufferMultisampled()
{
  GLint buffers = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &buffers);
  return buffers > 0;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingSampleDepths::Release(vtkWindow* win)
{
  // The objects' own context while their window lives (an owner releasing for another
  // window it used before must not delete these names in that one's context).
  vtkOpenGLRenderWindow* w =
    this->Window ? this->Window.GetPointer() : vtkOpenGLRenderWindow::SafeDownCast(win);
  const bool push = w && this->GetNumberOfGLObjects() > 0;
  if (push)
  {
    w->PushContext();
  }
  vtkClusteredLightingReleaseObject(this->Target, w);
  vtkClusteredLightingReleaseObject(this->ResolveTarget, w);
  vtkClusteredLightingReleaseObject(this->Depth, w);
  vtkClusteredLightingReleaseObject(this->Samples, w);
  vtkClusteredLightingReleaseObject(this->Range, w);
  this->VAO.Release(w);
  if (push)
  {
    w->PopContext();
  }
  this->TargetSize[0] = this->TargetSize[1] = 0;
  this->SampleCount = 0;
  this->DepthFormat = 0;
  this->Window = nullptr;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingSampleDepths::GetNumberOfGLObjects() const
{
  int n = 0;
  for (vtkTextureObject* tex : { this->Depth, this->Samples, this->Range })
  {
    n += (tex && tex->GetHandle()) ? 1 : 0;
  }
  for (vtkOpenGLFramebufferObject* fbo : { this->Target, this->ResolveTarget })
  {
    n += (fbo && fbo->GetFBOIndex()) ? 1 : 0;
  }
  return n + this->VAO.GetNumberOfGLObjects();
}

void vtkClusteredLightingSampleDepths::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  for (vtkTextureObject* tex : { this->Depth, this->Samples, this->Range })
  {
    if (tex && tex->GetHandle())
    {
      names.emplace_back(GL_TEXTURE, tex->GetHandle());
    }
  }
  for (vtkOpenGLFramebufferObject* fbo : { this->Target, this->ResolveTarget })
  {
    if (fbo && fbo->GetFBOIndex())
    {
      names.emplace_back(GL_FRAMEBUFFER, fbo->GetFBOIndex());
    }
  }
  this->VAO.GetGLObjectNames(names);
}

//------------------------------------------------------------------------------
// The recording targets: a multisampled depth texture and a multisampled RG32F texture
// of the draw framebuffer's size (at least the viewport's far corner).
bool vtkClusteredLightingSampleDepths::Allocate(
  vtkOpenGLRenderWindow* rw, int width, int height, int samples, int depthFormat)
{
  if (this->Window != rw)
  {
    this->Release(this->Window);
    this->Window = rw;
  }
  if (this->Target && this->TargetSize[0] == width && this->TargetSize[1] == height &&
    this->SampleCount == samples && this->DepthFormat == depthFormat)
  {
    return true;
  }
  vtkClusteredLightingReleaseObject(this->Target, rw);
  vtkClusteredLightingReleaseObject(this->Depth, rw);
  vtkClusteredLightingReleaseObject(this->Samples, rw);
  this->TargetSize[0] = this->TargetSize[1] = 0;

  auto newTexture = [rw, samples]()
  {
    vtkTextureObject* tex = vtkTextureObject::New();
    tex->SetContext(rw);
    tex->SetSamples(static_cast<unsigned int>(samples));
    tex->SetMinificationFilter(vtkTextureObject::Nearest);
    tex->SetMagnificationFilter(vtkTextureObject::Nearest);
    return tex;
  };
  this->Depth = newTexture();
  this->Depth->SetInternalFormat(static_cast<unsigned int>(depthFormat));
  this->Samples = newTexture();
  this->Samples->SetInternalFormat(GL_RG32F);
  this->Samples->SetFormat(GL_RG);
  this->Samples->SetDataType(GL_FLOAT);
  const auto w = static_cast<unsigned int>(width);
  const auto h = static_cast<unsigned int>(height);
  if (!this->Depth->AllocateDepth(w, h, vtkTextureObject::Fixed24) ||
    !this->Samples->Allocate2D(w, h, 2, VTK_FLOAT) ||
    this->Depth->GetTarget() != GL_TEXTURE_2D_MULTISAMPLE ||
    this->Samples->GetTarget() != GL_TEXTURE_2D_MULTISAMPLE)
  {
    vtkClusteredLightingReleaseObject(this->Depth, rw);
    vtkClusteredLightingReleaseObject(this->Samples, rw);
    return false;
  }
  this->Target = vtkOpenGLFramebufferObject::New();
  this->Target->SetContext(rw);
  this->TargetSize[0] = width;
  this->TargetSize[1] = height;
  this->SampleCount = samples;
  this->DepthFormat = depthFormat;
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSampleDepths::Begin(
  vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2])
{
  this->Problem.clear();
  vtkOpenGLState* state = rw->GetState();
  unsigned int binding = 0, buffer = 0;
  state->GetCurrentDrawFramebufferState(binding, buffer);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  const GLenum depthFormat = vtkClusteredLightingQueryDepthFormat(binding);
  if (depthFormat == 0)
  {
    this->Problem = "its depth buffer has a format the sample depths cannot be copied to";
    return false;
  }
  const std::vector<float> positions = vtkClusteredLightingQuerySamplePositions(samples);
  if (!this->Allocate(
        rw, origin[0] + size[0], origin[1] + size[1], samples, static_cast<int>(depthFormat)))
  {
    this->Problem = "the multisampled targets for its sample depths could not be allocated";
    return false;
  }
  while (glGetError() != GL_NO_ERROR)
  {
  }
  this->WindowBinding = binding;
  for (int i = 0; i < 2; ++i)
  {
    this->Origin[i] = origin[i];
    this->Size[i] = size[i];
  }

  state->PushFramebufferBindings();
  this->Target->Bind(GL_DRAW_FRAMEBUFFER);
  this->Target->AddDepthAttachment(this->Depth);
  this->Target->AddColorAttachment(1, this->Samples);
  GLenum buffers[2] = { GL_NONE, GL_COLOR_ATTACHMENT1 };
  state->vtkDrawBuffers(2, buffers, this->Target);
  GLint targetSamples = 0;
  glGetIntegerv(GL_SAMPLES, &targetSamples);
  bool ok = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  if (!ok)
  {
    this->Problem = "the framebuffer for its sample depths is incomplete";
  }
  else if (targetSamples != samples ||
    vtkClusteredLightingQuerySamplePositions(samples) != positions)
  {
    ok = false;
    this->Problem = "its samples (their number or positions) differ from a multisampled "
                    "texture's";
  }
  if (ok)
  {
    // The window's depth (cleared or kept, as the renderer asked) in, sample by sample.
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, binding);
    state->vtkglBlitFramebuffer(origin[0], origin[1], origin[0] + size[0], origin[1] + size[1],
      origin[0], origin[1], origin[0] + size[0], origin[1] + size[1], GL_DEPTH_BUFFER_BIT,
      GL_NEAREST);
    const GLfloat cleared[4] = { 0.0f, -1.0f, 0.0f, 0.0f };
    vtkOpenGLState::ScopedglColorMask savedColorMask(state);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearBufferfv(GL_COLOR, 1, cleared);
    ok = glGetError() == GL_NO_ERROR;
    if (!ok)
    {
      this->Problem = "copying its depth into the sample-depth framebuffer failed";
    }
  }
  if (!ok)
  {
    state->PopFramebufferBindings();
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSampleDepths::End(
  vtkOpenGLRenderWindow* rw, std::vector<float>& lo, std::vector<float>& hi)
{
  vtkOpenGLState* state = rw->GetState();
  const int* o = this->Origin;
  const int* s = this->Size;
  // The prepass's depth back into the window for the shading render.
  this->Target->Bind(GL_READ_FRAMEBUFFER);
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->WindowBinding);
  state->vtkglBlitFramebuffer(o[0], o[1], o[0] + s[0], o[1] + s[1], o[0], o[1], o[0] + s[0],
    o[1] + s[1], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  bool ok = glGetError() == GL_NO_ERROR;
  if (!ok)
  {
    this->Problem = "copying the sample depths back into the framebuffer failed";
  }
  else
  {
    ok = this->Resolve(rw, lo, hi);
  }
  state->PopFramebufferBindings();
  return ok;
}

//------------------------------------------------------------------------------
// Per pixel, the smallest and largest depth over its samples, read back.
bool vtkClusteredLightingSampleDepths::Resolve(
  vtkOpenGLRenderWindow* rw, std::vector<float>& lo, std::vector<float>& hi)
{
  vtkOpenGLState* state = rw->GetState();
  const int w = this->Size[0], h = this->Size[1];
  if (this->Range &&
    (static_cast<int>(this->Range->GetWidth()) != w ||
      static_cast<int>(this->Range->GetHeight()) != h))
  {
    vtkClusteredLightingReleaseObject(this->ResolveTarget, rw);
    vtkClusteredLightingReleaseObject(this->Range, rw);
  }
  if (!this->Range)
  {
    this->Range = vtkTextureObject::New();
    this->Range->SetContext(rw);
    this->Range->SetInternalFormat(GL_RG32F);
    this->Range->SetFormat(GL_RG);
    this->Range->SetDataType(GL_FLOAT);
    this->Range->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Range->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!this->Range->Allocate2D(
          static_cast<unsigned int>(w), static_cast<unsigned int>(h), 2, VTK_FLOAT))
    {
      vtkClusteredLightingReleaseObject(this->Range, rw);
      this->Problem = "the texture for its pixels' depth ranges could not be allocated";
      return false;
    }
  }
  if (!this->ResolveTarget)
  {
    this->ResolveTarget = vtkOpenGLFramebufferObject::New();
    this->ResolveTarget->SetContext(rw);
  }
  vtkShaderProgram* program = rw->GetShaderCache()->ReadyShaderProgram(
    vtkClusteredLightingFullScreenVS, vtkClusteredLightingSampleDepthsFS, "");
  if (!program)
  {
    this->Problem = "the program that takes its pixels' depth ranges did not build";
    return false;
  }
  bool ok = false;
  {
    vtkClusteredLightingPlainDrawState plain(state);
    this->ResolveTarget->Bind(GL_DRAW_FRAMEBUFFER);
    this->ResolveTarget->AddColorAttachment(0, this->Range);
    this->ResolveTarget->ActivateDrawBuffers(1);
    if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE)
    {
      state->vtkglViewport(0, 0, w, h);
      this->Samples->Activate();
      program->SetUniformi("clSamples", this->Samples->GetTextureUnit());
      program->SetUniformi("clSampleCount", this->SampleCount);
      program->SetUniform2i("clOrigin", this->Origin);
      this->VAO.Bind();
      glDrawArrays(GL_TRIANGLES, 0, 3);
      this->VAO.Unbind();
      this->Samples->Deactivate();

      const std::size_t n = static_cast<std::size_t>(w) * h;
      lo.resize(n);
      hi.resize(n);
      this->ResolveTarget->Bind(GL_READ_FRAMEBUFFER);
      this->ResolveTarget->ActivateReadBuffer(0);
      state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
      glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, lo.data());
      glReadPixels(0, 0, w, h, GL_GREEN, GL_FLOAT, hi.data());
      ok = glGetError() == GL_NO_ERROR;
    }
    this->ResolveTarget->RemoveColorAttachments(1);
  }
  if (!ok)
  {
    this->Problem = "reading its pixels' depth ranges back failed";
  }
  return ok;
}
