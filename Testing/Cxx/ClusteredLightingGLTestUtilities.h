// SPDX-License-Identifier: BSD-3-Clause
// Helpers for the reliability tests: GL object censuses (asked of GL itself, independent
// of the pass's own bookkeeping), GL errors, a small lit scene, and resident memory.
#ifndef ClusteredLightingGLTestUtilities_h
#define ClusteredLightingGLTestUtilities_h

#include "vtkClusteredLightingInspector.h"
#include "vtkClusteredLightingPass.h"

#include "vtkActor.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtk_glew.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h> // for sysconf
#include <utility>
#include <vector>

namespace ClusteredLightingTest
{

/// (kind, name) pairs; kind is GL_TEXTURE, GL_BUFFER, GL_FRAMEBUFFER, GL_RENDERBUFFER or
/// GL_VERTEX_ARRAY.
using GLNames = std::set<std::pair<unsigned int, unsigned int>>;

inline const char* GLKindName(unsigned int kind)
{
  switch (kind)
  {
    case GL_TEXTURE:
      return "texture";
    case GL_BUFFER:
      return "buffer";
    case GL_FRAMEBUFFER:
      return "framebuffer";
    case GL_RENDERBUFFER:
      return "renderbuffer";
    case GL_VERTEX_ARRAY:
      return "vertex array";
    default:
      return "?";
  }
}

/// Whether `name` is a live object of `kind` in the current context (asks GL).
inline bool IsLiveGLName(unsigned int kind, unsigned int name)
{
  switch (kind)
  {
    case GL_TEXTURE:
      return glIsTexture(name) == GL_TRUE;
    case GL_BUFFER:
      return glIsBuffer(name) == GL_TRUE;
    case GL_FRAMEBUFFER:
      return glIsFramebuffer(name) == GL_TRUE;
    case GL_RENDERBUFFER:
      return glIsRenderbuffer(name) == GL_TRUE;
    case GL_VERTEX_ARRAY:
      return glIsVertexArray(name) == GL_TRUE;
    default:
      return false;
  }
}

constexpr unsigned int CensusMaxName = 1u << 16;

/// Every live texture, buffer, framebuffer, renderbuffer and vertex-array name in
/// [1, CensusMaxName] of the window's context, found by asking GL about each name.
inline GLNames TakeGLNameCensus(vtkRenderWindow* rw)
{
  rw->MakeCurrent();
  GLNames live;
  for (unsigned int kind :
    { GL_TEXTURE, GL_BUFFER, GL_FRAMEBUFFER, GL_RENDERBUFFER, GL_VERTEX_ARRAY })
  {
    for (unsigned int name = 1; name <= CensusMaxName; ++name)
    {
      if (IsLiveGLName(kind, name))
      {
        live.emplace(kind, name);
      }
    }
  }
  return live;
}

/// GL objects one renderer's assignment holds: 10 (light data and view textures and
/// buffers, the list and master textures, framebuffers, vertex array), plus the far field's
/// 14 moment textures (three channels to order 4, since 2026-12-06) and its specular table
/// while the renderer's lights have a far field (vtkClusteredLightingLobeProjection.h),
/// plus the cluster-depth and cluster-rectangle textures while its clusters are
/// depth-aware, plus the copy of the prepass's depths (a framebuffer and a renderbuffer)
/// while they are kept for the next frame.
constexpr int AssignmentGLObjects = 10;
constexpr int FarFieldGLObjects = 15;
constexpr int FarSpecularBinsGLObjects = 1; ///< with a specular the bins serve
constexpr int DepthAwareGLObjects = 2;
constexpr int SavedDepthGLObjects = 2;

/// The far field's GL objects for the pass's last render: the specular table and the
/// moment textures, 14 for three channels, 5 for lights that share a colour, 7 and 3 with
/// the diffuse to order 2 (FarFieldOrder4Diffuse off), and the far specular's bins when
/// they were used (FarFieldSpecularBins).
inline int FarFieldGLObjectsOf(vtkClusteredLightingPass* pass)
{
  const bool order4 = pass->GetFarFieldOrder4Diffuse();
  return 1 + (pass->GetFarFieldSpecularBinsUsed() ? 1 : 0) +
    (pass->GetFarFieldSharedColorUsed() ? (order4 ? 5 : 3) : (order4 ? 14 : 7));
}

/// GL objects per renderer for the lights the pass last rendered.
inline int GLObjectsPerRenderer(vtkClusteredLightingPass* pass)
{
  return AssignmentGLObjects +
    (pass->GetNumberOfFarFieldLights() > 0 ? FarFieldGLObjectsOf(pass) : 0) +
    (pass->GetDepthAwareClustersUsed() ? DepthAwareGLObjects : 0) +
    (pass->GetDepthPrepassKept() ? SavedDepthGLObjects : 0);
}

/// The pass's own list of its GL objects (all renderers).
inline GLNames PassGLNames(vtkClusteredLightingPass* pass)
{
  std::vector<std::pair<unsigned int, unsigned int>> v;
  vtkClusteredLightingInspector(pass).GetGLObjectNames(v);
  return GLNames(v.begin(), v.end());
}

inline GLNames Minus(const GLNames& a, const GLNames& b)
{
  GLNames out;
  for (const auto& n : a)
  {
    if (!b.count(n))
    {
      out.insert(n);
    }
  }
  return out;
}

inline GLNames Union(GLNames a, const GLNames& b)
{
  a.insert(b.begin(), b.end());
  return a;
}

inline std::string Describe(const GLNames& names)
{
  std::ostringstream os;
  os << names.size() << " {";
  for (const auto& n : names)
  {
    os << " " << GLKindName(n.first) << " " << n.second;
  }
  os << " }";
  return os.str();
}

/// Exit status of the test process: EXIT_FAILURE once any Check() failed.
inline int& CheckStatus()
{
  static int status = EXIT_SUCCESS;
  return status;
}

/// Prints "ok: what" or "FAILED: what" and records a failure in CheckStatus().
inline void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok)
  {
    CheckStatus() = EXIT_FAILURE;
  }
}

/**
 * Checks that two censuses hold the same GL objects: textures, buffers and framebuffers
 * name for name, vertex arrays by count. VTK's mappers replace their VAO (new name)
 * whenever their shader program changes (vtkOpenGLVertexArrayObject::ShaderProgramChanged),
 * which the pass's shader code causes; a VAO of the pass that survived would still add one.
 */
inline void CheckSameGLObjects(const GLNames& got, const GLNames& want, const std::string& what)
{
  GLNames extra, missing;
  std::size_t vaosGot = 0, vaosWant = 0;
  for (const auto& n : got)
  {
    vaosGot += n.first == GL_VERTEX_ARRAY ? 1 : 0;
    if (n.first != GL_VERTEX_ARRAY && !want.count(n))
    {
      extra.insert(n);
    }
  }
  for (const auto& n : want)
  {
    vaosWant += n.first == GL_VERTEX_ARRAY ? 1 : 0;
    if (n.first != GL_VERTEX_ARRAY && !got.count(n))
    {
      missing.insert(n);
    }
  }
  Check(extra.empty() && missing.empty() && vaosGot == vaosWant,
    what + " (live GL objects: " + std::to_string(got.size()) + "; extra " + Describe(extra) +
      ", missing " + Describe(missing) + ", vertex arrays " + std::to_string(vaosGot) + " of " +
      std::to_string(vaosWant) + ")");
}

/// Every pending GL error of the window's context (0 when there is none).
inline int CountGLErrors(vtkRenderWindow* rw, std::string* first = nullptr)
{
  rw->MakeCurrent();
  int n = 0;
  for (GLenum e = glGetError(); e != GL_NO_ERROR && n < 64; e = glGetError())
  {
    if (n == 0 && first)
    {
      std::ostringstream os;
      os << "0x" << std::hex << e;
      *first = os.str();
    }
    ++n;
  }
  return n;
}

/// Resident set size of this process in bytes (/proc/self/statm, second field).
inline long long ResidentBytes()
{
  std::ifstream statm("/proc/self/statm");
  long long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<long long>(sysconf(_SC_PAGESIZE));
}

} // namespace ClusteredLightingTest

#endif
