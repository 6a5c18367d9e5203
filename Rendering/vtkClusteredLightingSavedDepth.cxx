// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingSavedDepth.h"

#include "vtkClusteredLightingGLHelpers.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h" // for GL calls

//------------------------------------------------------------------------------
vtkClusteredLightingSavedDepth::~vtkClusteredLightingSavedDepth()
{
  this->Release(nullptr);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingSavedDepth::Release(vtkWindow* win)
{
  // The objects' own context while their window lives.
  vtkOpenGLRenderWindow* w =
    this->Window ? this->Window.GetPointer() : vtkOpenGLRenderWindow::SafeDownCast(win);
  if (w && this->GetNumberOfGLObjects() > 0)
  {
    w->PushContext();
    if (this->Framebuffer)
    {
      // Never left bound: every use pops the bindings it pushed.
      glDeleteFramebuffers(1, &this->Framebuffer);
    }
    if (this->Renderbuffer)
    {
      glDeleteRenderbuffers(1, &this->Renderbuffer);
    }
    w->PopContext();
  }
  this->Framebuffer = 0;
  this->Renderbuffer = 0;
  this->TargetSize[0] = this->TargetSize[1] = 0;
  this->SampleCount = 0;
  this->DepthFormat = 0;
  this->Saved = false;
  this->Window = nullptr;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingSavedDepth::GetNumberOfGLObjects() const
{
  return (this->Framebuffer ? 1 : 0) + (this->Renderbuffer ? 1 : 0);
}

void vtkClusteredLightingSavedDepth::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  if (this->Framebuffer)
  {
    names.emplace_back(GL_FRAMEBUFFER, this->Framebuffer);
  }
  if (this->Renderbuffer)
  {
    names.emplace_back(GL_RENDERBUFFER, this->Renderbuffer);
  }
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSavedDepth::Allocate(
  vtkOpenGLRenderWindow* rw, int width, int height, int samples, unsigned int format)
{
  if (this->Window != rw)
  {
    this->Release(this->Window);
    this->Window = rw;
  }
  if (this->Framebuffer && this->TargetSize[0] == width && this->TargetSize[1] == height &&
    this->SampleCount == samples && this->DepthFormat == format)
  {
    return true;
  }
  if (!this->Framebuffer)
  {
    glGenFramebuffers(1, &this->Framebuffer);
  }
  if (!this->Renderbuffer)
  {
    glGenRenderbuffers(1, &this->Renderbuffer);
  }
  GLint bound = 0;
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &bound);
  glBindRenderbuffer(GL_RENDERBUFFER, this->Renderbuffer);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(bound));
  vtkOpenGLState* state = rw->GetState();
  state->PushDrawFramebufferBinding();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->Framebuffer);
  glFramebufferRenderbuffer(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, this->Renderbuffer);
  const bool complete = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  state->PopDrawFramebufferBinding();
  bool failed = !complete;
  while (glGetError() != GL_NO_ERROR)
  {
    failed = true;
  }
  if (failed)
  {
    this->TargetSize[0] = this->TargetSize[1] = 0;
    this->SampleCount = 0;
    this->DepthFormat = 0;
    return false;
  }
  this->TargetSize[0] = width;
  this->TargetSize[1] = height;
  this->SampleCount = samples;
  this->DepthFormat = format;
  return true;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSavedDepth::Copy(
  vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2])
{
  const int from[4] = { origin[0], origin[1], size[0], size[1] };
  return vtkClusteredLightingBlitDepth(rw->GetState(), from, origin[0], origin[1]);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSavedDepth::Save(
  vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2])
{
  this->Saved = false;
  while (glGetError() != GL_NO_ERROR)
  {
  }
  vtkOpenGLState* state = rw->GetState();
  unsigned int binding = 0, buffer = 0;
  state->GetCurrentDrawFramebufferState(binding, buffer);
  const unsigned int format = vtkClusteredLightingQueryDepthFormat(binding);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (format == 0 || size[0] < 1 || size[1] < 1 ||
    !this->Allocate(rw, origin[0] + size[0], origin[1] + size[1], samples, format))
  {
    return false;
  }
  std::vector<float> positions = vtkClusteredLightingQuerySamplePositions(samples);
  state->PushFramebufferBindings();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, binding);
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->Framebuffer);
  // The copy must land on the same sample positions it will be restored to.
  bool ok =
    vtkClusteredLightingQuerySamplePositions(samples) == positions && Copy(rw, origin, size);
  state->PopFramebufferBindings();
  if (ok)
  {
    this->Source = binding;
    this->SamplePositions = std::move(positions);
    for (int i = 0; i < 2; ++i)
    {
      this->Origin[i] = origin[i];
      this->Size[i] = size[i];
    }
  }
  this->Saved = ok;
  return ok;
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSavedDepth::Restore(
  vtkOpenGLRenderWindow* rw, const int origin[2], const int size[2])
{
  if (!this->Saved || this->Window != rw || origin[0] != this->Origin[0] ||
    origin[1] != this->Origin[1] || size[0] != this->Size[0] || size[1] != this->Size[1])
  {
    return false;
  }
  while (glGetError() != GL_NO_ERROR)
  {
  }
  vtkOpenGLState* state = rw->GetState();
  unsigned int binding = 0, buffer = 0;
  state->GetCurrentDrawFramebufferState(binding, buffer);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (binding != this->Source || samples != this->SampleCount ||
    vtkClusteredLightingQueryDepthFormat(binding) != this->DepthFormat ||
    vtkClusteredLightingQuerySamplePositions(samples) != this->SamplePositions)
  {
    return false;
  }
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, this->Framebuffer);
  const bool ok = Copy(rw, origin, size);
  state->PopReadFramebufferBinding();
  return ok;
}
