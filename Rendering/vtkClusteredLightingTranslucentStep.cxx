// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingTranslucentStep.h"

#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtk_glew.h" // for the queries

#include <algorithm> // for std::max

vtkStandardNewMacro(vtkClusteredLightingTranslucentStep);

namespace
{
/// Whether any prop of the state has translucent polygonal geometry (what VTK's
/// order-independent translucency checks before it renders, and composites, anything).
bool HasTranslucentGeometry(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (s->GetPropArray()[i]->HasTranslucentPolygonalGeometry())
    {
      return true;
    }
  }
  return false;
}

/// Pixels of the viewport VTK's order-independent translucency composites (its own
/// choice: the renderer's tiled viewport, or the whole framebuffer object when there is
/// one). Only counted in a single-sampled framebuffer (see Render).
std::uint64_t CountCompositeSamples(const vtkRenderState* s)
{
  int width = 0;
  int height = 0;
  if (s->GetFrameBuffer() == nullptr)
  {
    int x0 = 0;
    int y0 = 0;
    s->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  }
  else
  {
    int size[2] = { 0, 0 };
    s->GetWindowSize(size);
    width = size[0];
    height = size[1];
  }
  return static_cast<std::uint64_t>(std::max(width, 0)) *
    static_cast<std::uint64_t>(std::max(height, 0));
}
}

//------------------------------------------------------------------------------
void vtkClusteredLightingTranslucentStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Counting: " << this->Counting << "\n";
}

//------------------------------------------------------------------------------
void vtkClusteredLightingTranslucentStep::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  // The renderer's own choice between depth peeling and order-independent translucency.
  const bool peeling = ren->GetUseDepthPeeling() != 0;
  const bool translucent = this->Counting && HasTranslucentGeometry(s);
  if (this->Counting)
  {
    this->EndQuery(); // the opaque part ends here
    // Depth peeling runs queries of its own; in a multisampled framebuffer translucency
    // draws single-sampled layers and a multisampled composite, which one query mixes.
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    if (!peeling && !(translucent && samples > 0))
    {
      this->CompositeSamples = translucent ? CountCompositeSamples(s) : 0;
      glBeginQuery(GL_SAMPLES_PASSED, this->Queries[1]);
      this->ActiveQuery = 1;
      this->TranslucentBegun = true;
    }
    else if (translucent)
    {
      this->TranslucentMeasured = false;
    }
  }
  const int before = ren->GetNumberOfPropsRendered();
  ren->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
  this->NumberOfRenderedProps = ren->GetNumberOfPropsRendered() - before;
  if (this->Counting)
  {
    this->EndQuery();
  }
}

//------------------------------------------------------------------------------
void vtkClusteredLightingTranslucentStep::BeginCounting()
{
  glGenQueries(2, this->Queries);
  glBeginQuery(GL_SAMPLES_PASSED, this->Queries[0]);
  this->ActiveQuery = 0;
  this->Counting = true;
  this->TranslucentBegun = false;
  this->CompositeSamples = 0;
  this->TranslucentMeasured = true;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingTranslucentStep::EndQuery()
{
  if (this->ActiveQuery >= 0)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    this->ActiveQuery = -1;
  }
}

//------------------------------------------------------------------------------
vtkClusteredLightingTranslucentStep::Counts vtkClusteredLightingTranslucentStep::EndCounting()
{
  Counts counts;
  if (!this->Counting)
  {
    return counts;
  }
  this->EndQuery();
  GLuint64 samples[2] = { 0, 0 };
  glGetQueryObjectui64v(this->Queries[0], GL_QUERY_RESULT, samples);
  if (this->TranslucentBegun)
  {
    glGetQueryObjectui64v(this->Queries[1], GL_QUERY_RESULT, samples + 1);
  }
  glDeleteQueries(2, this->Queries);
  this->Queries[0] = this->Queries[1] = 0;
  this->Counting = false;
  counts.Opaque = samples[0];
  counts.Translucent =
    samples[1] > this->CompositeSamples ? samples[1] - this->CompositeSamples : 0;
  counts.TranslucentMeasured = this->TranslucentMeasured;
  return counts;
}
