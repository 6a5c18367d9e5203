// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingSurfaceBoxes.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::isfinite
#include <cstring>   // for std::strcmp

namespace
{
/// Whether the prop is an actor of VTK's own classes whose mapper draws its input as it
/// is, so that its cells' boxes hold every fragment it draws.
bool DrawsItsInput(vtkProp* prop)
{
  const char* actor = prop->GetClassName();
  if (std::strcmp(actor, "vtkOpenGLActor") != 0 && std::strcmp(actor, "vtkActor") != 0)
  {
    return false;
  }
  vtkMapper* mapper = static_cast<vtkActor*>(prop)->GetMapper();
  if (!mapper)
  {
    return false;
  }
  const char* name = mapper->GetClassName();
  return std::strcmp(name, "vtkOpenGLPolyDataMapper") == 0 ||
    std::strcmp(name, "vtkCompositePolyDataMapper2") == 0;
}

/**
 * World boxes, merged while small: consecutive cells of a mesh lie close together, so a
 * cell's box joins the current one while their union stays within `Size` on every axis
 * (a 1.1-million-triangle bunny would otherwise keep 53 MB of boxes). Merging only grows
 * boxes, so it never drops a node a surface reads; `Size` is a tenth of a far-field cell
 * or less at the default resolution (see AddProp).
 */
struct BoxMerger
{
  std::vector<glm::dvec3>& Boxes;
  double Size;
  glm::dvec3 Lo = glm::dvec3(0.0), Hi = glm::dvec3(-1.0);
  void Add(const glm::dvec3& lo, const glm::dvec3& hi)
  {
    const glm::dvec3 ulo = glm::min(this->Lo, lo), uhi = glm::max(this->Hi, hi);
    const glm::dvec3 extent = uhi - ulo;
    if (this->Lo.x <= this->Hi.x && extent.x <= this->Size && extent.y <= this->Size &&
      extent.z <= this->Size)
    {
      this->Lo = ulo;
      this->Hi = uhi;
      return;
    }
    this->Flush();
    this->Lo = lo;
    this->Hi = hi;
  }
  void Flush()
  {
    if (this->Lo.x <= this->Hi.x)
    {
      this->Boxes.push_back(this->Lo);
      this->Boxes.push_back(this->Hi);
    }
    this->Lo = glm::dvec3(0.0);
    this->Hi = glm::dvec3(-1.0);
  }
};

/// A box per cell of `cells` over the world points `world`: per pair of consecutive
/// points for lines (a polyline's segments), per triple for strips, per cell otherwise.
void AddCellBoxes(
  vtkCellArray* cells, int run, const std::vector<glm::dvec3>& world, BoxMerger& boxes)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return;
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n <= 0)
    {
      continue;
    }
    const vtkIdType span = run > 0 ? std::min<vtkIdType>(run, n) : n;
    for (vtkIdType first = 0; first == 0 || first + span <= n; ++first)
    {
      glm::dvec3 lo(world[static_cast<std::size_t>(ids[first])]), hi(lo);
      for (vtkIdType q = first + 1; q < first + span; ++q)
      {
        const glm::dvec3& p = world[static_cast<std::size_t>(ids[q])];
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
      boxes.Add(lo, hi);
      if (run <= 0 || span < run)
      {
        break;
      }
    }
  }
}

/// The boxes of one polydata's cells through `matrix` (null: identity).
void AddPolyDataBoxes(vtkPolyData* poly, vtkMatrix4x4* matrix, BoxMerger& boxes)
{
  vtkPoints* points = poly ? poly->GetPoints() : nullptr;
  if (!points || points->GetNumberOfPoints() == 0)
  {
    return;
  }
  const vtkIdType count = points->GetNumberOfPoints();
  std::vector<glm::dvec3> world(static_cast<std::size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[4] = { 0.0, 0.0, 0.0, 1.0 };
    points->GetPoint(i, p);
    if (matrix)
    {
      matrix->MultiplyPoint(p, p);
      const double w = p[3] != 0.0 ? p[3] : 1.0;
      p[0] /= w;
      p[1] /= w;
      p[2] /= w;
    }
    world[static_cast<std::size_t>(i)] = glm::dvec3(p[0], p[1], p[2]);
  }
  AddCellBoxes(poly->GetVerts(), 1, world, boxes);
  AddCellBoxes(poly->GetLines(), 2, world, boxes);
  AddCellBoxes(poly->GetPolys(), 0, world, boxes);
  AddCellBoxes(poly->GetStrips(), 3, world, boxes);
}

/// The newest MTime of what a prop's boxes are read from.
vtkMTimeType GetNewestMTime(vtkProp* prop)
{
  vtkMTimeType t = prop->GetRedrawMTime();
  if (vtkProp3D* p3 = vtkProp3D::SafeDownCast(prop))
  {
    t = std::max(t, p3->GetMatrix()->GetMTime());
  }
  if (vtkActor* actor = vtkActor::SafeDownCast(prop))
  {
    vtkMapper* mapper = actor->GetMapper();
    vtkDataObject* input =
      mapper && mapper->GetNumberOfInputPorts() > 0 && mapper->GetNumberOfInputConnections(0) > 0
      ? mapper->GetInputDataObject(0, 0)
      : nullptr;
    if (input)
    {
      t = std::max(t, input->GetMTime());
    }
  }
  return t;
}
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingSurfaceBoxes::Update(vtkRenderer* ren)
{
  std::vector<std::pair<const void*, vtkMTimeType>> signature;
  std::vector<vtkProp*> props;
  vtkPropCollection* all = ren->GetViewProps();
  vtkCollectionSimpleIterator pit;
  all->InitTraversal(pit);
  while (vtkProp* prop = all->GetNextProp(pit))
  {
    // Volumes are lit by their own mappers and never read the far field (and reading a
    // GPU volume mapper's bounds and times here changed its image by a step at one
    // pixel, TestClusteredLightingVolumes).
    if (prop->GetVisibility() && !prop->IsA("vtkVolume"))
    {
      prop->GetBounds(); // brings the mapper's input up to date
      props.push_back(prop);
      signature.emplace_back(prop, GetNewestMTime(prop));
    }
  }
  if (signature == this->Signature && this->Version > 0)
  {
    return false;
  }
  this->Signature = std::move(signature);
  this->Boxes.clear();
  this->Everywhere = false;
  for (vtkProp* prop : props)
  {
    this->AddProp(prop);
  }
  ++this->Version;
  return true;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingSurfaceBoxes::AddProp(vtkProp* prop)
{
  const double* b = prop->GetBounds();
  if (!b)
  {
    return; // draws nothing in world space (2D props)
  }
  if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
  {
    return; // empty
  }
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(b[i]))
    {
      this->Everywhere = true;
      return;
    }
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (actor && actor->GetProperty() &&
    (actor->GetProperty()->GetRenderLinesAsTubes() ||
      actor->GetProperty()->GetRenderPointsAsSpheres()))
  {
    this->Everywhere = true;
    return;
  }
  if (!DrawsItsInput(prop))
  {
    this->Boxes.emplace_back(b[0], b[2], b[4]);
    this->Boxes.emplace_back(b[1], b[3], b[5]);
    return;
  }
  vtkMatrix4x4* matrix = actor->GetMatrix();
  if (matrix && matrix->IsIdentity())
  {
    matrix = nullptr;
  }
  vtkMapper* mapper = actor->GetMapper();
  vtkDataObject* input =
    mapper->GetNumberOfInputConnections(0) > 0 ? mapper->GetInputDataObject(0, 0) : nullptr;
  // Cells merge into boxes up to 1/512 of the prop's diagonal: the default far field has
  // 32 to 60 cells across its region, which holds the prop.
  const double diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  BoxMerger merged{ this->Boxes, diagonal / 512.0 };
  if (vtkPolyData* poly = vtkPolyData::SafeDownCast(input))
  {
    AddPolyDataBoxes(poly, matrix, merged);
  }
  else if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (vtkPolyData* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        AddPolyDataBoxes(leaf, matrix, merged);
      }
      else if (it->GetCurrentDataObject())
      {
        // A leaf the mapper does not draw as polygons: the prop's bounds hold it.
        this->Boxes.emplace_back(b[0], b[2], b[4]);
        this->Boxes.emplace_back(b[1], b[3], b[5]);
      }
    }
  }
  else if (input)
  {
    this->Boxes.emplace_back(b[0], b[2], b[4]);
    this->Boxes.emplace_back(b[1], b[3], b[5]);
  }
  merged.Flush();
}
