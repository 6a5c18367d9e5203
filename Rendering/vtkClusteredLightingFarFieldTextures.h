// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkClusteredLightingFarFieldTextures
 * @brief   the far field of one renderer's lights: build on the CPU, 3D textures for shading
 *
 * Private to the module; owned by vtkClusteredLightingAssigner next to the light records.
 * What the far field is, why, and its error bound: Rendering/Core/vtkClusteredLightingFarField.h
 * and docs/far-field.md.
 *
 * Build (only when the lights, the far-field options or the region change; a moving camera
 * never rebuilds it, the far field lives in world space): the node values are summed on
 * the CPU with the light tree (ComputeFarFieldMomentsForThisCPU: blocks of 4 x 4 x 4 nodes,
 * single precision, vectorized, in a copy for AVX2 or AVX-512 where the processor has
 * them), the blocks split between threads with vtkSMPTools, then packed (in parallel,
 * into buffers kept from build to build) and uploaded. Only the nodes that surfaces read
 * are summed and packed, when the caller says which (vtkClusteredLightingFarFieldBlocks.h,
 * vtkClusteredLightingPass::FarFieldSkipEmptyBlocks); Extend adds those of surfaces that
 * moved or appeared, with the same lights. A texture is uploaded whole when it is made
 * (the first build, a new grid size, a new number of textures or bin slabs); after that
 * only the boxes of nodes each build summed (glTexSubImage3D, boxes of a block's layers,
 * merged along x), read in place from the packed buffers.
 *
 * GL objects: 14 3D textures, RGBA32F, of the grid's dimensions (54 moments per node, 224
 * bytes with the padding), linear filtering (the shading code's trilinear interpolation),
 * clamped to edge; an order-2 far diffuse (FarFieldPlan::Order4Diffuse off) reads and
 * keeps the first 7 (the order-2 moments, 112 bytes). When the far-field lights share a
 * colour (FarFieldPlan::SharedColor, FindFarFieldSharedColor) the far field is one channel
 * times that colour: 5 textures (18 moments per node, 80 bytes; 3 and 48 at order 2), the
 * others released (their units -1), and the node sums run for that channel only (a third
 * of the multiply-adds). Beside them, made at the
 * first build and kept: the Phong far specular's table (GetLobeProjectionTable, one RGBA32F
 * 2D texture of 65 x 66 texels, 68,640 bytes, read with texelFetch). With
 * FarFieldPlan::SpecularBins, the far specular's bins (vtkClusteredLightingFarSpecularBins.h)
 * are summed with the moments and uploaded as one more RGBA32F 3D texture, its 52 slabs
 * (26 with a shared colour) stacked along the grid's shallowest axis (832 or 416 bytes per
 * node), where the GPU's 3D textures are large enough (GL_MAX_3D_TEXTURE_SIZE, 2,048 on
 * llvmpipe: a grid up to 39 nodes along its shallowest axis, 78 with a shared colour; the
 * default 32,768 nodes are at most 32 along it); otherwise none, and
 * GetSpecularBinsTooDeep says so.
 *
 * @sa vtkClusteredLightingAssigner
 */
#ifndef vtkClusteredLightingFarFieldTextures_h
#define vtkClusteredLightingFarFieldTextures_h

#include "vtkClusteredLightingFarFieldTree.h" // for FarFieldPlan, the light tree (Rendering/Core)

#include <array>   // for std::array
#include <cstdint> // for std::int64_t, std::uint64_t
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkClusteredLightingFarFieldTextures
{
public:
  vtkClusteredLightingFarFieldTextures() = default;
  ~vtkClusteredLightingFarFieldTextures();

  /**
   * Sums the far field of `lights` (PreparedLight::FarField ones) on the plan's grid and
   * uploads it: the nodes marked in `needed` (a mask per block of nodes,
   * vtkClusteredLightingFarFieldBlocks.h: those the surfaces read, taken in layers of
   * their blocks), every node when `needed` is null. Returns false on a GL failure. BuildTime (ms)
   * covers the sums and upload.
   */
  bool Build(vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::FarFieldPlan& plan,
    const std::vector<vtkClusteredLighting::PreparedLight>& lights,
    const std::vector<std::uint64_t>* needed = nullptr);
  /**
   * The same lights and plan as the last Build: sums the nodes marked in `needed` that no
   * build since then has summed (surfaces that moved or appeared) and uploads. Nothing to
   * sum: returns true and uploads nothing.
   */
  bool Extend(vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::FarFieldPlan& plan,
    const std::vector<vtkClusteredLighting::PreparedLight>& lights,
    const std::vector<std::uint64_t>& needed);
  /// Whether `needed` marks a node that the builds since the last Build have not summed.
  bool IsMissingBlocks(const std::vector<std::uint64_t>& needed) const;
  /// Nodes summed by the last Build or Extend.
  std::int64_t GetNodesBuilt() const { return this->NodesBuilt; }

  double GetBuildTime() const { return this->BuildTime; }
  /// The shared colour of the last build ((0, 0, 0): three channels, 14 textures or 7).
  const glm::dvec3& GetSharedColor() const { return this->SharedColor; }
  /// The light tree and near radii of the last build (for its error bound).
  const vtkClusteredLighting::FarFieldLightTree& GetTree() const { return this->Tree; }
  const std::vector<double>& GetNearRadii() const { return this->NearRadii; }

  ///@{
  /// Bind the textures for the shading pass; units (-1 when not bound) in texture order.
  void Activate();
  void Deactivate();
  std::array<int, vtkClusteredLighting::FarFieldTextures> GetUnits() const;
  /// Unit of the lobe table's texture (-1 when not bound).
  int GetLobeTableUnit() const;
  /// Unit of the far specular's bins (-1 when not bound or not built).
  int GetSpecularBinsUnit() const;
  ///@}

  /// Whether the last build made the far specular's bins, and whether they were asked for
  /// and left out because the grid was too deep for the GPU's 3D textures.
  bool HasSpecularBins() const;
  bool GetSpecularBinsTooDeep() const { return this->SpecularBinsTooDeep; }
  /// The grid axis the bins' slabs are stacked along (GetFarSpecularBinAxis).
  int GetSpecularBinsAxis() const { return this->SpecularBinsAxis; }

  std::uint64_t GetBytes() const;
  int GetNumberOfGLObjects() const;
  void GetGLObjectNames(std::vector<std::pair<unsigned int, unsigned int>>& names) const;
  void Release(vtkWindow* w);

private:
  vtkClusteredLightingFarFieldTextures(const vtkClusteredLightingFarFieldTextures&) = delete;
  void operator=(const vtkClusteredLightingFarFieldTextures&) = delete;
  /// Nodes [Lo, Hi] of the grid (inclusive; per axis).
  struct NodeBox
  {
    glm::ivec3 Lo, Hi;
  };
  /**
   * The pixel-unpack state a build's uploads need (no unpack buffer, no skips, alignment
   * 4, tightly packed rows), set once for all its textures: saved when made, restored
   * when destroyed.
   */
  class UnpackScope
  {
  public:
    UnpackScope();
    ~UnpackScope();
    UnpackScope(const UnpackScope&) = delete;
    void operator=(const UnpackScope&) = delete;

  private:
    static const unsigned int Names[6];
    int Saved[6] = {};
    int SavedBuffer = 0;
  };
  /**
   * Uploads the boxes of nodes `boxes` of `texels` (RGBA, 4 floats per texel) into the 3D
   * texture `tex`, already made: a grid of `dims` nodes stacked `slabs` times along `axis`
   * (the far specular's bins; 1 for the moments), each box once per slab. The texels are
   * read in place (the unpack row length and image height span the whole texture while it
   * uploads, then are set back to 0); `scope` holds the rest of the unpack state.
   */
  static void UploadBoxes(const UnpackScope& scope, vtkTextureObject* tex, const glm::ivec3& dims,
    int axis, int slabs, const float* texels, const std::vector<NodeBox>& boxes);
  /// Build (full: a new light tree, nothing summed yet) and Extend.
  bool Sum(vtkOpenGLRenderWindow* rw, const vtkClusteredLighting::FarFieldPlan& plan,
    const std::vector<vtkClusteredLighting::PreparedLight>& lights,
    const std::vector<std::uint64_t>* needed, bool full);

  std::array<vtkTextureObject*, vtkClusteredLighting::FarFieldTextures> Textures{};
  vtkTextureObject* LobeTable = nullptr;    ///< the lit-side lobe's coefficients
  vtkTextureObject* SpecularBins = nullptr; ///< the far specular's bins, slabs along z
  std::vector<float> Bins;                  ///< their node sums, reused as Moments
  std::vector<float> BinTexels;             ///< packed, reused
  bool SpecularBinsTooDeep = false;
  int SpecularBinsAxis = 2;
  int SpecularBinSlabs = 0;   ///< slabs of the bins' texture (0: none made)
  std::vector<NodeBox> Boxes; ///< the last build's, reused
  std::array<int, 3> Dims = { { 0, 0, 0 } };
  std::vector<double> Moments; ///< node sums, reused from build to build (animated lights)
  std::array<std::vector<float>, vtkClusteredLighting::FarFieldTextures> Texels; ///< packed, reused
  std::vector<std::uint64_t> Built; ///< per block: its nodes summed for the current lights
  std::int64_t NodesBuilt = 0;
  std::vector<double> NearRadii;
  vtkClusteredLighting::FarFieldLightTree Tree;
  glm::dvec3 SharedColor = glm::dvec3(0.0);
  double BuildTime = 0.0;
};

#endif
