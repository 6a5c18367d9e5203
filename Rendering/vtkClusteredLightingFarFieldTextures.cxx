// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightingFarFieldTextures.h"
#include "vtkClusteredLightingFarFieldBlocks.h" // for GetFarFieldBlocksToBuild
#include "vtkClusteredLightingGLHelpers.h"      // for vtkClusteredLightingReleaseObject

#include "vtkOpenGLRenderWindow.h"
#include "vtkSMPTools.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // for GL enums

#include <algorithm> // for std::min
#include <chrono>    // for timings

using namespace vtkClusteredLighting;

namespace
{
/// An RGBA32F texture of rw, edges clamped, with the given filter (the far field's
/// moments: Linear, trilinear; the lobe table: Nearest, read with texelFetch).
vtkTextureObject* NewRGBA32FTexture(vtkOpenGLRenderWindow* rw, int filter)
{
  vtkTextureObject* tex = vtkTextureObject::New();
  tex->SetContext(rw);
  tex->SetInternalFormat(GL_RGBA32F);
  tex->SetFormat(GL_RGBA);
  tex->SetDataType(GL_FLOAT);
  tex->SetMinificationFilter(filter);
  tex->SetMagnificationFilter(filter);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  tex->SetWrapR(vtkTextureObject::ClampToEdge);
  return tex;
}

}

//------------------------------------------------------------------------------
vtkClusteredLightingFarFieldTextures::UnpackScope::UnpackScope()
{
  for (int i = 0; i < 6; ++i)
  {
    glGetIntegerv(Names[i], &this->Saved[i]);
  }
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &this->SavedBuffer);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
}

vtkClusteredLightingFarFieldTextures::UnpackScope::~UnpackScope()
{
  for (int i = 0; i < 6; ++i)
  {
    glPixelStorei(Names[i], this->Saved[i]);
  }
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(this->SavedBuffer));
}

const unsigned int vtkClusteredLightingFarFieldTextures::UnpackScope::Names[6] = {
  GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS,
  GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT
};

//------------------------------------------------------------------------------
void vtkClusteredLightingFarFieldTextures::UploadBoxes(const UnpackScope&, vtkTextureObject* tex,
  const glm::ivec3& dims, int axis, int slabs, const float* texels,
  const std::vector<NodeBox>& boxes)
{
  if (boxes.empty())
  {
    return;
  }
  glm::ivec3 size = dims;
  size[axis] *= slabs;
  glPixelStorei(GL_UNPACK_ROW_LENGTH, size.x);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, size.y);
  tex->Activate();
  for (int slab = 0; slab < slabs; ++slab)
  {
    glm::ivec3 offset(0);
    offset[axis] = slab * dims[axis];
    for (const NodeBox& box : boxes)
    {
      const glm::ivec3 lo = box.Lo + offset;
      const glm::ivec3 n = box.Hi - box.Lo + 1;
      const std::size_t first =
        static_cast<std::size_t>((static_cast<std::int64_t>(lo.z) * size.y + lo.y) * size.x + lo.x);
      glTexSubImage3D(
        GL_TEXTURE_3D, 0, lo.x, lo.y, lo.z, n.x, n.y, n.z, GL_RGBA, GL_FLOAT, texels + 4 * first);
    }
  }
  tex->Deactivate();
  // Back to tightly packed rows, for the textures the same scope makes whole.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
}

//------------------------------------------------------------------------------
vtkClusteredLightingFarFieldTextures::~vtkClusteredLightingFarFieldTextures()
{
  this->Release(nullptr);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightingFarFieldTextures::Build(vtkOpenGLRenderWindow* rw,
  const FarFieldPlan& plan, const std::vector<PreparedLight>& lights,
  const std::vector<std::uint64_t>* needed)
{
  return this->Sum(rw, plan, lights, needed, true);
}

bool vtkClusteredLightingFarFieldTextures::Extend(vtkOpenGLRenderWindow* rw,
  const FarFieldPlan& plan, const std::vector<PreparedLight>& lights,
  const std::vector<std::uint64_t>& needed)
{
  return this->Sum(rw, plan, lights, &needed, false);
}

bool vtkClusteredLightingFarFieldTextures::IsMissingBlocks(
  const std::vector<std::uint64_t>& needed) const
{
  for (std::size_t b = 0; b < needed.size(); ++b)
  {
    if (needed[b] & ~(b < this->Built.size() ? this->Built[b] : std::uint64_t{ 0 }))
    {
      return true;
    }
  }
  return false;
}

bool vtkClusteredLightingFarFieldTextures::Sum(vtkOpenGLRenderWindow* rw, const FarFieldPlan& plan,
  const std::vector<PreparedLight>& lights, const std::vector<std::uint64_t>* needed, bool full)
{
  const auto t0 = std::chrono::steady_clock::now();
  const FarFieldGrid& grid = plan.Grid;
  const std::size_t blockCount = static_cast<std::size_t>(GetNumberOfFarFieldBlocks(grid));
  if (full || this->Built.size() != blockCount)
  {
    this->NearRadii = GetFarFieldNearRadii(lights);
    this->Tree = BuildFarFieldLightTree(lights, this->NearRadii);
    this->Built.assign(blockCount, 0);
  }
  const std::vector<double>& nearRadii = this->NearRadii;
  const FarFieldLightTree& tree = this->Tree;
  // The blocks to sum: those surfaces read (every block without `needed`) that this
  // light tree has not summed yet (vtkClusteredLightingFarFieldBlocks.h).
  const std::vector<std::uint64_t> all(needed ? 0 : blockCount, FarFieldAllNodes);
  const FarFieldBlockList list = GetFarFieldBlocksToBuild(needed ? *needed : all, this->Built);
  // The sums write every node of those blocks, the packing their texels; the others keep
  // what they held (stale or zero: finite, and read by no surface). Sized, not cleared
  // (rebuilt every frame for moving lights).
  const std::size_t nodes = static_cast<std::size_t>(grid.GetNumberOfNodes());
  this->Moments.resize(nodes * FarFieldFloatsPerNode);
  // Lights that share a colour need one channel: its sums only, 5 textures, 3 for an
  // order-2 diffuse, which reads only the moments of order 2 (FindFarFieldSharedColor).
  const bool oneChannel = plan.SharedColor != glm::dvec3(0.0);
  const int channel = oneChannel ? GetSharedColorChannel(plan.SharedColor) : -1;
  const int textures = oneChannel
    ? (plan.Order4Diffuse ? FarFieldSharedColorTextures : FarFieldOrder2SharedColorTextures)
    : (plan.Order4Diffuse ? FarFieldTextures : FarFieldOrder2Textures);
  // The packing fills every texture of its layout; the order-2 diffuse uploads the first.
  const int packed = oneChannel ? FarFieldSharedColorTextures : FarFieldTextures;
  for (int q = 0; q < FarFieldTextures; ++q)
  {
    std::vector<float>& t = this->Texels[static_cast<std::size_t>(q)];
    if (q < packed)
    {
      t.resize(4 * nodes);
    }
    else
    {
      std::vector<float>().swap(t);
    }
  }
  // The far specular's bins, where asked and the GPU's 3D textures are deep enough.
  const int slabs = GetFarSpecularBinSlabs(oneChannel);
  const int axis = GetFarSpecularBinAxis(grid.Dims);
  GLint deepest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &deepest);
  const bool bins = plan.SpecularBins &&
    static_cast<std::int64_t>(grid.Dims[static_cast<std::size_t>(axis)]) * slabs <= deepest;
  this->SpecularBinsAxis = axis;
  this->SpecularBinsTooDeep = plan.SpecularBins && !bins;
  if (bins)
  {
    this->Bins.resize(nodes * FarSpecularFloatsPerNode);
    this->BinTexels.resize(4 * nodes * static_cast<std::size_t>(slabs));
  }
  else
  {
    std::vector<float>().swap(this->Bins);
    std::vector<float>().swap(this->BinTexels);
  }
  if (list.Blocks.empty() && !full)
  {
    this->NodesBuilt = 0;
    this->BuildTime = 0.0;
    return true; // nothing new to sum or upload
  }
  const vtkIdType listed = static_cast<vtkIdType>(list.Blocks.size());
  // What each entry sums: a box of nodes, and their bits in the block.
  const glm::ivec3 dims(grid.Dims[0], grid.Dims[1], grid.Dims[2]);
  std::vector<NodeBox>& boxes = this->Boxes;
  boxes.resize(list.Blocks.size());
  this->NodesBuilt = 0;
  for (std::size_t at = 0; at < list.Blocks.size(); ++at)
  {
    const FarFieldEntryNodes entry =
      GetFarFieldEntryNodes(grid, &list, static_cast<std::int64_t>(at));
    NodeBox& box = boxes[at];
    box.Lo = entry.Lo();
    box.Hi = entry.Hi();
    this->Built[static_cast<std::size_t>(list.Blocks[at])] |=
      GetFarFieldLayerMask(entry.Axis, entry.LayerFirst, entry.LayerLast);
    const glm::ivec3 n = glm::max(box.Hi - box.Lo + 1, 0);
    this->NodesBuilt += static_cast<std::int64_t>(n.x) * n.y * n.z;
  }
  // Summed, then packed box by box (a row of up to 4 nodes along x at a time) while the
  // sums are in this thread's cache.
  vtkSMPTools::For(0, listed, 1,
    [&](vtkIdType b0, vtkIdType b1)
    {
      ComputeFarFieldMomentsForThisCPU(grid, lights, nearRadii, tree, plan.Grouping, b0, b1,
        this->Moments, channel, plan.Order4Diffuse, bins ? &this->Bins : nullptr, &list);
      for (vtkIdType at = b0; at < b1; ++at)
      {
        const NodeBox& box = boxes[static_cast<std::size_t>(at)];
        for (int k = box.Lo.z; k <= box.Hi.z; ++k)
        {
          for (int j = box.Lo.y; j <= box.Hi.y; ++j)
          {
            const std::size_t n0 = static_cast<std::size_t>(grid.NodeIndex(box.Lo.x, j, k));
            const std::size_t n1 = n0 + static_cast<std::size_t>(box.Hi.x - box.Lo.x + 1);
            if (oneChannel)
            {
              PackFarFieldTexelsOneChannel(this->Moments, channel, n0, n1, this->Texels);
            }
            else
            {
              PackFarFieldTexels(this->Moments, n0, n1, this->Texels);
            }
            if (bins)
            {
              PackFarSpecularBinTexels(
                this->Bins, channel, grid.Dims, axis, n0, n1, this->BinTexels);
            }
          }
        }
      }
    });
  // Boxes next to each other along x with the same rows are uploaded as one (the entries
  // come in block order, x fastest).
  std::size_t merged = 0;
  for (std::size_t at = 0; at < boxes.size(); ++at)
  {
    NodeBox& last = boxes[merged > 0 ? merged - 1 : 0];
    const NodeBox& box = boxes[at];
    if (glm::any(glm::lessThan(box.Hi, box.Lo)))
    {
      continue; // nothing summed (layers past the grid's end)
    }
    if (merged > 0 && last.Hi.x + 1 == box.Lo.x && last.Lo.y == box.Lo.y && last.Hi.y == box.Hi.y &&
      last.Lo.z == box.Lo.z && last.Hi.z == box.Hi.z)
    {
      last.Hi.x = box.Hi.x;
    }
    else
    {
      boxes[merged++] = box;
    }
  }
  boxes.resize(merged);

  bool ok = true;
  const bool resize = grid.Dims != this->Dims;
  const UnpackScope unpack; // until this function returns
  for (int q = 0; q < FarFieldTextures && ok; ++q)
  {
    vtkTextureObject*& tex = this->Textures[static_cast<std::size_t>(q)];
    if (resize || q >= textures)
    {
      vtkClusteredLightingReleaseObject(tex, rw);
    }
    if (q >= textures)
    {
      continue;
    }
    const float* texels = this->Texels[static_cast<std::size_t>(q)].data();
    if (tex && tex->GetHandle())
    {
      // The texture holds what the texels held before this build (uploaded whole when
      // made, then box by box as here): only the boxes summed now changed.
      UploadBoxes(unpack, tex, dims, 0, 1, texels, boxes);
      continue;
    }
    if (!tex)
    {
      tex = NewRGBA32FTexture(rw, vtkTextureObject::Linear);
    }
    ok = tex->Create3DFromRaw(static_cast<unsigned int>(grid.Dims[0]),
      static_cast<unsigned int>(grid.Dims[1]), static_cast<unsigned int>(grid.Dims[2]), 4,
      VTK_FLOAT, const_cast<float*>(texels));
  }
  // The bins' slab count changes with the shared colour, and with it the texture's size.
  const int binSlabs = bins ? slabs : 0;
  if (resize || binSlabs != this->SpecularBinSlabs)
  {
    vtkClusteredLightingReleaseObject(this->SpecularBins, rw);
  }
  this->SpecularBinSlabs = 0;
  if (ok && bins)
  {
    if (this->SpecularBins && this->SpecularBins->GetHandle())
    {
      UploadBoxes(unpack, this->SpecularBins, dims, axis, slabs, this->BinTexels.data(), boxes);
    }
    else
    {
      if (!this->SpecularBins)
      {
        this->SpecularBins = NewRGBA32FTexture(rw, vtkTextureObject::Linear);
      }
      std::array<int, 3> size = grid.Dims;
      size[static_cast<std::size_t>(axis)] *= slabs;
      ok = this->SpecularBins->Create3DFromRaw(static_cast<unsigned int>(size[0]),
        static_cast<unsigned int>(size[1]), static_cast<unsigned int>(size[2]), 4, VTK_FLOAT,
        this->BinTexels.data());
    }
    this->SpecularBinSlabs = ok ? slabs : 0;
  }
  // The lobe table: the same for every far field, made once.
  if (ok && !(this->LobeTable && this->LobeTable->GetHandle()))
  {
    if (!this->LobeTable)
    {
      this->LobeTable = NewRGBA32FTexture(rw, vtkTextureObject::Nearest);
    }
    ok = this->LobeTable->Create2DFromRaw(static_cast<unsigned int>(LobeTableCosines),
      static_cast<unsigned int>(LobeTableRows), 4, VTK_FLOAT,
      const_cast<float*>(GetLobeProjectionTable().Texels.data()));
  }
  this->Dims = ok ? grid.Dims : std::array<int, 3>{ { 0, 0, 0 } };
  this->SharedColor = ok ? plan.SharedColor : glm::dvec3(0.0);
  this->BuildTime =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return ok;
}

//------------------------------------------------------------------------------
void vtkClusteredLightingFarFieldTextures::Activate()
{
  for (vtkTextureObject* tex : this->Textures)
  {
    if (tex && tex->GetHandle())
    {
      tex->Activate();
    }
  }
  if (this->LobeTable && this->LobeTable->GetHandle())
  {
    this->LobeTable->Activate();
  }
  if (this->HasSpecularBins())
  {
    this->SpecularBins->Activate();
  }
}

void vtkClusteredLightingFarFieldTextures::Deactivate()
{
  for (vtkTextureObject* tex : this->Textures)
  {
    if (tex && tex->GetTextureUnit() >= 0)
    {
      tex->Deactivate();
    }
  }
  if (this->LobeTable && this->LobeTable->GetTextureUnit() >= 0)
  {
    this->LobeTable->Deactivate();
  }
  if (this->SpecularBins && this->SpecularBins->GetTextureUnit() >= 0)
  {
    this->SpecularBins->Deactivate();
  }
}

bool vtkClusteredLightingFarFieldTextures::HasSpecularBins() const
{
  return this->SpecularBins && this->SpecularBins->GetHandle();
}

int vtkClusteredLightingFarFieldTextures::GetSpecularBinsUnit() const
{
  return this->HasSpecularBins() ? this->SpecularBins->GetTextureUnit() : -1;
}

int vtkClusteredLightingFarFieldTextures::GetLobeTableUnit() const
{
  return this->LobeTable ? this->LobeTable->GetTextureUnit() : -1;
}

std::array<int, FarFieldTextures> vtkClusteredLightingFarFieldTextures::GetUnits() const
{
  std::array<int, FarFieldTextures> units;
  for (std::size_t q = 0; q < units.size(); ++q)
  {
    units[q] = this->Textures[q] ? this->Textures[q]->GetTextureUnit() : -1;
  }
  return units;
}

//------------------------------------------------------------------------------
std::uint64_t vtkClusteredLightingFarFieldTextures::GetBytes() const
{
  const bool table = this->LobeTable && this->LobeTable->GetHandle();
  const bool bins = this->HasSpecularBins();
  const int moments = this->GetNumberOfGLObjects() - (table ? 1 : 0) - (bins ? 1 : 0);
  const int binSlabs = bins ? GetFarSpecularBinSlabs(this->SharedColor != glm::dvec3(0.0)) : 0;
  return 16ull * static_cast<std::uint64_t>(moments + binSlabs) *
    static_cast<std::uint64_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2] +
    (table ? static_cast<std::uint64_t>(LobeTableBytes) : 0u);
}

int vtkClusteredLightingFarFieldTextures::GetNumberOfGLObjects() const
{
  int n = 0;
  for (vtkTextureObject* tex : this->Textures)
  {
    n += (tex && tex->GetHandle()) ? 1 : 0;
  }
  n += (this->LobeTable && this->LobeTable->GetHandle()) ? 1 : 0;
  n += this->HasSpecularBins() ? 1 : 0;
  return n;
}

void vtkClusteredLightingFarFieldTextures::GetGLObjectNames(
  std::vector<std::pair<unsigned int, unsigned int>>& names) const
{
  for (vtkTextureObject* tex : this->Textures)
  {
    if (tex && tex->GetHandle())
    {
      names.emplace_back(GL_TEXTURE, tex->GetHandle());
    }
  }
  if (this->LobeTable && this->LobeTable->GetHandle())
  {
    names.emplace_back(GL_TEXTURE, this->LobeTable->GetHandle());
  }
  if (this->HasSpecularBins())
  {
    names.emplace_back(GL_TEXTURE, this->SpecularBins->GetHandle());
  }
}

void vtkClusteredLightingFarFieldTextures::Release(vtkWindow* w)
{
  for (vtkTextureObject*& tex : this->Textures)
  {
    vtkClusteredLightingReleaseObject(tex, w);
  }
  vtkClusteredLightingReleaseObject(this->LobeTable, w);
  // The bins' arrays stay, as Moments does: given back and taken again (a pass switched
  // off and on), arrays this large move glibc's mmap threshold up and come back from the
  // heap, which keeps the memory (TestClusteredLightingSoak saw resident memory step up
  // by 12 to 15 MiB when they were given back here).
  vtkClusteredLightingReleaseObject(this->SpecularBins, w);
  this->SpecularBinSlabs = 0;
  std::vector<std::uint64_t>().swap(this->Built); // the next sums start over
  this->Dims = { { 0, 0, 0 } };
  this->SharedColor = glm::dvec3(0.0);
  for (std::vector<float>& t : this->Texels)
  {
    std::vector<float>().swap(t);
  }
}
