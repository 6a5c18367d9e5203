// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingSampleZero.h"

#include "vtkClusteredLightingGLHelpers.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL calls

#include "vtkClusteredLightingFullScreenVS.h"
#include "vtkClusteredLightingSampleZeroFS.h"

#include <cstddef> // for std::size_t

namespace
{
/// The textures and framebuffers of one Read(), deleted (in the window's context) when it
/// goes out of scope.
struct Objects
{
  explicit Objects(vtkOpenGLRenderWindow* rw)
    : Window(rw)
  {
  }
  ~Objects()
  {
    for (vtkTextureObject** tex :
      { &this->Color, &this->Depth, &this->SampleColor, &this->SampleDepth })
    {
      vtkClusteredLightingReleaseObject(*tex, this->Window);
    }
    vtkClusteredLightingReleaseObject(this->Copy, this->Window);
    vtkClusteredLightingReleaseObject(this->Output, this->Window);
    this->VAO.Release(this->Window);
  }
  Objects(const Objects&) = delete;
  void operator=(const Objects&) = delete;

  vtkTextureObject* NewTexture(unsigned int samples, unsigned int internalFormat)
  {
    vtkTextureObject* tex = vtkTextureObject::New();
    tex->SetContext(this->Window);
    tex->SetSamples(samples);
    tex->SetInternalFormat(internalFormat);
    tex->SetMinificationFilter(vtkTextureObject::Nearest);
    tex->SetMagnificationFilter(vtkTextureObject::Nearest);
    return tex;
  }

  vtkOpenGLRenderWindow* Window;
  vtkTextureObject* Color = nullptr;       ///< multisampled copy of the colour
  vtkTextureObject* Depth = nullptr;       ///< multisampled copy of the depth
  vtkTextureObject* SampleColor = nullptr; ///< sample 0 of the colour
  vtkTextureObject* SampleDepth = nullptr; ///< sample 0 of the depth
  vtkOpenGLFramebufferObject* Copy = nullptr;
  vtkOpenGLFramebufferObject* Output = nullptr;
  vtkClusteredLightingVertexArray VAO;
};
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSampleZero::Read(vtkOpenGLRenderWindow* rw, const int rectangle[4],
  std::vector<unsigned char>& rgba, std::vector<float>& depth, std::string& problem)
{
  const int x0 = rectangle[0], y0 = rectangle[1], w = rectangle[2], h = rectangle[3];
  vtkOpenGLState* state = rw->GetState();
  unsigned int binding = 0, buffer = 0;
  state->GetCurrentDrawFramebufferState(binding, buffer);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  const unsigned int depthFormat = vtkClusteredLightingQueryDepthFormat(binding);
  if (w <= 0 || h <= 0 || x0 < 0 || y0 < 0 || samples <= 0)
  {
    problem = "no multisampled rectangle to read";
    return false;
  }
  if (depthFormat == 0)
  {
    problem = "its depth buffer has a format a copy cannot match";
    return false;
  }
  while (glGetError() != GL_NO_ERROR)
  {
  }

  // 1. The multisampled copies, as large as the rectangle's far corner: a blit from a
  // multisampled framebuffer copies to the same coordinates only.
  Objects o(rw);
  const auto width = static_cast<unsigned int>(x0 + w);
  const auto height = static_cast<unsigned int>(y0 + h);
  o.Color = o.NewTexture(static_cast<unsigned int>(samples), GL_RGBA8);
  o.Depth = o.NewTexture(static_cast<unsigned int>(samples), depthFormat);
  if (!o.Color->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR) ||
    !o.Depth->AllocateDepth(width, height, vtkTextureObject::Fixed24) ||
    o.Color->GetTarget() != GL_TEXTURE_2D_MULTISAMPLE ||
    o.Depth->GetTarget() != GL_TEXTURE_2D_MULTISAMPLE)
  {
    problem = "the multisampled textures could not be allocated";
    return false;
  }
  o.SampleColor = o.NewTexture(0, GL_RGBA8);
  o.SampleDepth = o.NewTexture(0, GL_R32F);
  o.SampleDepth->SetFormat(GL_RED);
  o.SampleDepth->SetDataType(GL_FLOAT);
  if (!o.SampleColor->Allocate2D(
        static_cast<unsigned int>(w), static_cast<unsigned int>(h), 4, VTK_UNSIGNED_CHAR) ||
    !o.SampleDepth->Allocate2D(
      static_cast<unsigned int>(w), static_cast<unsigned int>(h), 1, VTK_FLOAT))
  {
    problem = "the textures for sample 0 could not be allocated";
    return false;
  }
  vtkShaderProgram* program = rw->GetShaderCache()->ReadyShaderProgram(
    vtkClusteredLightingFullScreenVS, vtkClusteredLightingSampleZeroFS, "");
  if (!program)
  {
    problem = "the program that reads sample 0 did not build";
    return false;
  }

  bool ok = false;
  state->PushFramebufferBindings();
  {
    vtkClusteredLightingPlainDrawState plain(state); // no scissor clips the blit either
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
    state->vtkglDepthMask(GL_TRUE);
    o.Copy = vtkOpenGLFramebufferObject::New();
    o.Copy->SetContext(rw);
    o.Copy->Bind(GL_DRAW_FRAMEBUFFER);
    o.Copy->AddColorAttachment(0, o.Color);
    o.Copy->AddDepthAttachment(o.Depth);
    o.Copy->ActivateDrawBuffers(1);
    GLint copySamples = 0;
    glGetIntegerv(GL_SAMPLES, &copySamples);
    if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
      copySamples != samples)
    {
      problem = "the multisampled copy's framebuffer is incomplete or has other samples";
    }
    else
    {
      state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, binding);
      state->vtkglReadBuffer(buffer);
      state->vtkglBlitFramebuffer(x0, y0, x0 + w, y0 + h, x0, y0, x0 + w, y0 + h,
        GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
      ok = glGetError() == GL_NO_ERROR;
      if (!ok)
      {
        problem = "copying the framebuffer's samples failed";
      }
    }
    // 2. Sample 0 of each pixel into the single-sampled textures, read back.
    if (ok)
    {
      o.Output = vtkOpenGLFramebufferObject::New();
      o.Output->SetContext(rw);
      o.Output->Bind(GL_DRAW_FRAMEBUFFER);
      o.Output->AddColorAttachment(0, o.SampleColor);
      o.Output->AddColorAttachment(1, o.SampleDepth);
      o.Output->ActivateDrawBuffers(2);
      ok = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
      if (ok)
      {
        state->vtkglViewport(0, 0, w, h);
        o.Color->Activate();
        o.Depth->Activate();
        program->SetUniformi("clColor", o.Color->GetTextureUnit());
        program->SetUniformi("clDepth", o.Depth->GetTextureUnit());
        const int origin[2] = { x0, y0 };
        program->SetUniform2i("clOrigin", origin);
        o.VAO.Bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        o.VAO.Unbind();
        o.Depth->Deactivate();
        o.Color->Deactivate();
        const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        std::vector<unsigned char> colorRead(4 * n);
        std::vector<float> depthRead(n);
        o.Output->Bind(GL_READ_FRAMEBUFFER);
        state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
        o.Output->ActivateReadBuffer(0);
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, colorRead.data());
        o.Output->ActivateReadBuffer(1);
        glReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, depthRead.data());
        ok = glGetError() == GL_NO_ERROR;
        if (ok)
        {
          rgba.swap(colorRead);
          depth.swap(depthRead);
        }
      }
      if (!ok)
      {
        problem = "reading sample 0 back failed";
      }
      o.Output->RemoveColorAttachments(2);
    }
    o.Copy->RemoveColorAttachments(1);
    o.Copy->RemoveDepthAttachment();
  }
  state->PopFramebufferBindings();
  while (glGetError() != GL_NO_ERROR)
  {
  }
  return ok;
}
