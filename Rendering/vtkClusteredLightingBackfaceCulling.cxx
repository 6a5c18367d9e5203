// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingBackfaceCulling.h"
#include "vtkClusteredLightingGLHelpers.h" // for vtkClusteredLightingHasShaderCode

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLState.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <cstring> // for std::strcmp
#include <vector>  // for std::vector

namespace
{
/// `m` (VTK's row-major matrix) as a GLM matrix.
glm::dmat4 ToGlm(const double m[16])
{
  glm::dmat4 g(1.0);
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      g[col][row] = m[4 * row + col];
    }
  }
  return g;
}

/// Whether `actor` draws its polydata as VTK's plain mapper does, unchanged: see the
/// class's list.
vtkPolyData* GetPlainOpaqueSurface(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkProperty* property = actor->GetProperty();
  if (!mapper || !property || std::strcmp(actor->GetClassName(), "vtkOpenGLActor") != 0 ||
    std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper") != 0 ||
    mapper->GetNumberOfClippingPlanes() > 0)
  {
    return nullptr;
  }
  if (vtkClusteredLightingHasShaderCode(actor))
  {
    return nullptr;
  }
  if (actor->HasTranslucentPolygonalGeometry() || property->GetOpacity() < 1.0 ||
    property->GetRepresentation() != VTK_SURFACE || property->GetBackfaceCulling() ||
    property->GetFrontfaceCulling() || actor->GetTexture() || property->GetNumberOfTextures() > 0)
  {
    return nullptr;
  }
  vtkPolyData* data = vtkPolyDataMapper::SafeDownCast(mapper)->GetInput();
  if (!data || data->GetNumberOfPolys() == 0 || data->GetNumberOfStrips() > 0 ||
    data->GetCellGhostArray() || !data->GetPoints())
  {
    return nullptr;
  }
  return data;
}

/// The map from world to clip coordinates of `ren`'s active camera.
glm::dmat4 ClipFromWorldOf(vtkRenderer* ren)
{
  return ToGlm(ren->GetActiveCamera()
                 ->GetCompositeProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1.0, 1.0)
                 ->GetData());
}

/// The face `actor`'s draws may cull (+1 GL_BACK, -1 GL_FRONT, 0 none) under the camera
/// `clipFromWorld`, with `closureOf(polydata)` giving its surface's closure: the class's
/// rules.
template <typename ClosureOf>
int DecideFace(vtkActor* actor, const glm::dmat4& clipFromWorld, ClosureOf&& closureOf)
{
  vtkPolyData* data = actor ? GetPlainOpaqueSurface(actor) : nullptr;
  if (!data)
  {
    return 0;
  }
  const glm::dmat4 clipFromModel = clipFromWorld * ToGlm(actor->GetMatrix()->GetData());
  if (!vtkClusteredLighting::IsBoxBeyondNearPlane(clipFromModel, data->GetBounds()))
  {
    return 0;
  }
  const vtkClusteredLighting::SurfaceClosure& closure = closureOf(data);
  return closure.Closed
    ? vtkClusteredLighting::ChooseCulledFace(closure.Orientation, glm::determinant(clipFromModel))
    : 0;
}
}

//------------------------------------------------------------------------------
vtkClusteredLighting::SurfaceClosure vtkClusteredLightingComputeSurfaceClosure(vtkPolyData* data)
{
  if (!data || !data->GetPoints() || !data->GetPolys())
  {
    return vtkClusteredLighting::SurfaceClosure();
  }
  vtkDataArray* coordinates = data->GetPoints()->GetData();
  const vtkIdType n = coordinates->GetNumberOfTuples();
  std::vector<double> points(static_cast<std::size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    coordinates->GetTuple(i, points.data() + 3 * i);
  }
  std::vector<std::int64_t> offsets{ 0 };
  std::vector<std::int64_t> connectivity;
  offsets.reserve(static_cast<std::size_t>(data->GetNumberOfPolys() + 1));
  connectivity.reserve(static_cast<std::size_t>(data->GetPolys()->GetNumberOfConnectivityIds()));
  vtkCellArray* polys = data->GetPolys();
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
  {
    connectivity.insert(connectivity.end(), ids, ids + size);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  return vtkClusteredLighting::ComputeSurfaceClosure(points.data(), n, offsets.data(),
    connectivity.data(), static_cast<std::int64_t>(offsets.size()) - 1);
}

//------------------------------------------------------------------------------
void vtkClusteredLightingBackfaceCulling::BeginFrame(
  const vtkRenderState* s, vtkOpenGLState* state, bool enabled)
{
  this->SetActive(false);
  this->Faces.clear();
  vtkRenderer* ren = s->GetRenderer();
  vtkCamera* camera = ren->GetActiveCamera();
  vtkRenderWindow* window = ren->GetRenderWindow();
  const bool stereo = window && window->GetStereoRender();
  this->CurrentView = View(ren, stereo ? camera->GetLeftEye() : 1);
  this->CurrentViewRender = ++this->ViewRenders[this->CurrentView];
  // Forget polydata that were deleted (their address may come back).
  for (auto it = this->Closures.begin(); it != this->Closures.end();)
  {
    it = it->second.Data ? std::next(it) : this->Closures.erase(it);
  }
  this->State = state;
  if (!enabled || !state)
  {
    return;
  }
  this->ClipFromWorld = ClipFromWorldOf(ren);
  // Decided at each prop's first draw, when its mapper has brought its input up to date.
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    this->Faces[s->GetPropArray()[i]] = Undecided;
  }
}

//------------------------------------------------------------------------------
int vtkClusteredLightingBackfaceCulling::Decide(vtkProp* prop)
{
  return DecideFace(vtkActor::SafeDownCast(prop), this->ClipFromWorld,
    [this](vtkPolyData* data) -> const vtkClusteredLighting::SurfaceClosure&
    { return this->GetClosure(data); });
}

//------------------------------------------------------------------------------
int vtkClusteredLightingChooseCulledFace(vtkActor* actor, vtkRenderer* ren)
{
  if (!actor || !ren || !ren->GetActiveCamera())
  {
    return 0;
  }
  vtkClusteredLighting::SurfaceClosure closure;
  return DecideFace(actor, ClipFromWorldOf(ren),
    [&closure](vtkPolyData* data) -> const vtkClusteredLighting::SurfaceClosure&
    {
      closure = vtkClusteredLightingComputeSurfaceClosure(data);
      return closure;
    });
}

//------------------------------------------------------------------------------
const vtkClusteredLighting::SurfaceClosure& vtkClusteredLightingBackfaceCulling::GetClosure(
  vtkPolyData* data)
{
  CachedClosure& cached = this->Closures[data];
  const vtkMTimeType time = data->GetMTime();
  const bool known = cached.Data == data;
  const bool firstView = known && cached.ChangedIn == this->CurrentView;
  if (known && cached.Time == time)
  {
    // A version seen before: tested, or left untested as animated until the view that
    // first saw it renders it again unchanged (other views take its decision).
    if (cached.Tested || !firstView || cached.ChangedAt == this->CurrentViewRender)
    {
      return cached.Closure;
    }
  }
  else
  {
    // A new version: modified again in the next render of the view that first saw the
    // last one (an animated mesh), it is not tested, and not culled.
    const bool changedAgain = firstView && cached.ChangedAt + 1 == this->CurrentViewRender;
    cached.Data = data;
    cached.Time = time;
    cached.ChangedIn = this->CurrentView;
    cached.ChangedAt = this->CurrentViewRender;
    if (changedAgain)
    {
      cached.Tested = false;
      cached.Closure = vtkClusteredLighting::SurfaceClosure();
      cached.Closure.Reason = "modified in consecutive renders";
      return cached.Closure;
    }
  }
  cached.Tested = true;

  cached.Closure = vtkClusteredLightingComputeSurfaceClosure(data);
  return cached.Closure;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingBackfaceCulling::SetActive(bool active)
{
  this->EndProp();
  this->Active = active;
}

//------------------------------------------------------------------------------
int vtkClusteredLightingBackfaceCulling::GetFace(vtkProp* prop)
{
  const auto it = this->Faces.find(prop);
  if (it == this->Faces.end())
  {
    return 0;
  }
  if (it->second == Undecided)
  {
    it->second = this->Decide(prop);
  }
  return it->second;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingBackfaceCulling::EndProp()
{
  if (this->Culled && this->State)
  {
    this->State->vtkglDisable(GL_CULL_FACE);
  }
  this->Culled = false;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingBackfaceCulling::Apply(vtkProp* prop)
{
  if (!this->Active || !this->State)
  {
    return;
  }
  int face = this->GetFace(prop);
  if (face != 0 && vtkClusteredLightingHasShaderCode(vtkActor::SafeDownCast(prop)))
  {
    // Shader code that appeared after the decision: a mapper moves VTK 9.0's deprecated
    // per-mapper replacements to its actor when it builds its shaders, at the draw, and
    // the prepass's reuse signature decides before any draw. Not culled from here on.
    face = 0;
    this->Faces[prop] = 0;
  }
  if (face != 0)
  {
    this->State->vtkglCullFace(face > 0 ? GL_BACK : GL_FRONT);
    this->State->vtkglEnable(GL_CULL_FACE);
    this->Culled = true;
  }
}

//------------------------------------------------------------------------------
int vtkClusteredLightingBackfaceCulling::GetNumberOfCulledProps() const
{
  int n = 0;
  for (const auto& face : this->Faces)
  {
    n += face.second != 0 && face.second != Undecided ? 1 : 0;
  }
  return n;
}
