// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFarFieldTree.h
 * @brief GL-free far-field build: a light tree (Barnes-Hut) and the blocked node sums.
 *
 * The far field's grid nodes hold sums over every far-field light (vtkClusteredLightingFarField.h).
 * Summed one by one that is nodes x lights terms (46,000 nodes x 4,096 lights: 190 million);
 * the build here cuts it with a light tree and makes each term cheap.
 *
 * Light tree. A binary tree over the far-field lights (median split on the longest axis,
 * leaves of up to 8 lights). Each node knows its lights' box, summed colour, centroid
 * (weighted by summed colour), the covariance of their positions about it, largest near
 * radius and whether its lights share one attenuation: leaves from their lights, inner
 * nodes merged from their two children.
 *
 * Aggregation (Barnes-Hut). Seen from far enough, a group of lights is one light of the
 * summed colour at the centroid (the centroid cancels the first-order term of the error),
 * plus the second-order term of each moment, from the group's covariance
 * (ComputeGroupSpreadTerms). Without that term the error of a group of extent s seen from
 * distance D is about (s / D)^2 / 12 of its light and always of one sign (the attenuation
 * is convex: a group is brighter than its centroid alone), so the groups' errors add up
 * over the whole far field (1.3% of it with 65,536 lights); with it each group's moments
 * are 2x to 3x closer to its own sums even at extent = distance, and the grouped far
 * light stays within 0.13% of the exact sums. A group is taken whole for a block of nodes
 * when (AcceptFarFieldGroup)
 *  - its lights share one attenuation,
 *  - the block lies beyond every near radius in the group (so each light contributes its
 *    whole light there, no window), and
 *  - its extent (box diagonal) is below `grouping` times the distance from its centroid to
 *    the block.
 * The error this makes is part of the stated bound (vtkClusteredLightingFarFieldBound.h),
 * computed group by group, so `grouping` trades build time for accuracy without ever
 * making the bound false. Grouping 0 sums every light one by one.
 *
 * Spot lights (IsFarFieldSpot) are not in the tree: a group has no cone. Each is a source
 * of its own for every block that some point of its cone may reach (SpotConeMayReachBox),
 * summed with its spot factor, vectorized across the block's nodes like the other sources
 * (AccumulateSpotBlock; exponents that are not whole numbers up to 8 in double precision
 * with ComputeFarContribution). Each costs about 0.06 ms of the build at 32,768 nodes on
 * 2 threads (docs/far-field.md).
 *
 * Blocks. The tree is walked once per block of 4 x 4 x 4 nodes (CollectFarFieldSources),
 * giving one list of sources (groups and single lights, windowed where a node of the block
 * may lie inside the light's near radius) for all 64 nodes (the groups' spread terms,
 * small and smooth, are taken at the block's centre and added to each of its nodes), which
 * are then summed in single
 * precision in a loop the compiler vectorizes across the nodes (on x86-64 processors with
 * AVX2 or AVX-512, in a copy compiled for them: ComputeFarFieldMomentsForThisCPU). Positions
 * are taken relative to the block's centre before they become floats, so a scene far from
 * the origin keeps its precision. Blocks are independent: the caller splits them between
 * threads. A build may sum only some blocks, each only in some layers of its nodes
 * (FarFieldBlockList: those that surfaces read, vtkClusteredLightingFarFieldBlocks.h); a
 * node it sums gets exactly the value a whole build gives it (the walk takes the whole
 * block's box, and each node's terms are added in the same order).
 */
#ifndef vtkClusteredLightingFarFieldTree_h
#define vtkClusteredLightingFarFieldTree_h

#include "vtkClusteredLightingFarField.h"
#include "vtkClusteredLightingFarSpecularBins.h"
#include "vtkClusteredLightingSpotBounds.h"

#include <algorithm> // for std::nth_element
#include <array>     // for std::array
#include <cstddef>   // for std::ptrdiff_t
#include <cstdint>   // for std::int64_t
#include <glm/glm.hpp>
#include <limits> // for std::numeric_limits
#include <vector> // for std::vector

namespace vtkClusteredLighting
{

/// Radians by which the far-field build widens a spot light's cone when it chooses the
/// blocks of nodes the light is summed into (SpotConeMayReachBox): the sums themselves
/// test each node against the cone (AccumulateSpotBlock), so this only keeps the choice
/// conservative against rounding.
constexpr double FarFieldSpotConeSlack = 1e-6;

/// The light tree of the far-field build (see the file description).
struct FarFieldLightTree
{
  struct Node
  {
    glm::dvec3 Lo = glm::dvec3(0.0), Hi = glm::dvec3(0.0);
    glm::dvec3 Centroid = glm::dvec3(0.0);
    glm::dvec3 Color = glm::dvec3(0.0);
    glm::dvec3 Attenuation = glm::dvec3(0.0); ///< shared by its lights, if Uniform
    glm::dmat3 Spread = glm::dmat3(0.0);      ///< covariance of the positions about the centroid
    double MaxNearRadius = 0.0;
    bool Uniform = true;
    int First = 0, Count = 0; ///< range of Order
    int Left = -1, Right = -1, Parent = -1;
  };
  std::vector<Node> Nodes;         ///< Nodes[0] is the root
  std::vector<int> Order;          ///< light indices, each node's lights contiguous
  std::vector<int> LeafOf;         ///< per light: its leaf node, -1 for lights not in the tree
  std::vector<int> Spots;          ///< the spot lights with a far part (not in the tree)
  std::vector<SpotCone> SpotCones; ///< their cones widened by FarFieldSpotConeSlack
  int LeafSize = 8;
};

namespace Detail
{
/// A light of the tree being built: its position and index, kept together so that the
/// splits (std::nth_element) move 32 bytes, not whole PreparedLights.
struct TreeItem
{
  glm::dvec3 Position;
  int Light;
};

/// Builds the node of items [first, first + count) and its subtree. The statistics of an
/// inner node are merged from its two children (O(1) each); only leaves read their lights.
inline int BuildTreeNode(FarFieldLightTree& t, std::vector<TreeItem>& items,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii, int first,
  int count, int parent)
{
  const int index = static_cast<int>(t.Nodes.size());
  t.Nodes.emplace_back();
  FarFieldLightTree::Node n;
  n.First = first;
  n.Count = count;
  n.Parent = parent;
  if (count > t.LeafSize)
  {
    // Split at the median of the longest axis of the positions' box.
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int i = first; i < first + count; ++i)
    {
      lo = glm::min(lo, items[static_cast<std::size_t>(i)].Position);
      hi = glm::max(hi, items[static_cast<std::size_t>(i)].Position);
    }
    const glm::dvec3 extent = hi - lo;
    const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const int half = count / 2;
    std::nth_element(items.begin() + first, items.begin() + first + half,
      items.begin() + first + count,
      [axis](const TreeItem& a, const TreeItem& b) { return a.Position[axis] < b.Position[axis]; });
    n.Left = BuildTreeNode(t, items, lights, nearRadii, first, half, index);
    n.Right = BuildTreeNode(t, items, lights, nearRadii, first + half, count - half, index);
    const FarFieldLightTree::Node& l = t.Nodes[static_cast<std::size_t>(n.Left)];
    const FarFieldLightTree::Node& r = t.Nodes[static_cast<std::size_t>(n.Right)];
    n.Lo = glm::min(l.Lo, r.Lo);
    n.Hi = glm::max(l.Hi, r.Hi);
    n.Color = l.Color + r.Color;
    const double wl = l.Color.x + l.Color.y + l.Color.z, wr = r.Color.x + r.Color.y + r.Color.z;
    n.Centroid =
      wl + wr > 0.0 ? (wl * l.Centroid + wr * r.Centroid) / (wl + wr) : 0.5 * (n.Lo + n.Hi);
    // Parallel axes: each child's covariance about its own centroid, moved to the parent's.
    if (wl + wr > 0.0)
    {
      const glm::dvec3 dl = l.Centroid - n.Centroid, dr = r.Centroid - n.Centroid;
      n.Spread = (wl * (l.Spread + glm::outerProduct(dl, dl)) +
                   wr * (r.Spread + glm::outerProduct(dr, dr))) /
        (wl + wr);
    }
    n.MaxNearRadius = std::max(l.MaxNearRadius, r.MaxNearRadius);
    n.Attenuation = l.Attenuation;
    n.Uniform = l.Uniform && r.Uniform && l.Attenuation == r.Attenuation;
  }
  else
  {
    n.Lo = glm::dvec3(std::numeric_limits<double>::max());
    n.Hi = glm::dvec3(-std::numeric_limits<double>::max());
    double weight = 0.0;
    n.Attenuation =
      lights[static_cast<std::size_t>(items[static_cast<std::size_t>(first)].Light)].Attenuation;
    for (int i = first; i < first + count; ++i)
    {
      const int light = items[static_cast<std::size_t>(i)].Light;
      const PreparedLight& pl = lights[static_cast<std::size_t>(light)];
      n.Lo = glm::min(n.Lo, pl.PositionWC);
      n.Hi = glm::max(n.Hi, pl.PositionWC);
      n.Color += pl.Color;
      const double w = pl.Color.x + pl.Color.y + pl.Color.z;
      n.Centroid += w * pl.PositionWC;
      weight += w;
      n.MaxNearRadius = std::max(n.MaxNearRadius, nearRadii[static_cast<std::size_t>(light)]);
      n.Uniform = n.Uniform && pl.Attenuation == n.Attenuation;
      t.LeafOf[static_cast<std::size_t>(light)] = index;
    }
    n.Centroid = weight > 0.0 ? n.Centroid / weight : 0.5 * (n.Lo + n.Hi);
    if (weight > 0.0)
    {
      for (int i = first; i < first + count; ++i)
      {
        const PreparedLight& pl =
          lights[static_cast<std::size_t>(items[static_cast<std::size_t>(i)].Light)];
        const glm::dvec3 dx = pl.PositionWC - n.Centroid;
        n.Spread += (pl.Color.x + pl.Color.y + pl.Color.z) * glm::outerProduct(dx, dx);
      }
      n.Spread /= weight;
    }
  }
  t.Nodes[static_cast<std::size_t>(index)] = n;
  return index;
}
} // namespace Detail

/// The light tree over the lights with a far part (finite near radius) among `lights`,
/// spot lights apart (FarFieldLightTree::Spots).
inline FarFieldLightTree BuildFarFieldLightTree(
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii, int leafSize = 8)
{
  FarFieldLightTree t;
  t.LeafSize = std::max(1, leafSize);
  t.LeafOf.assign(lights.size(), -1);
  std::vector<Detail::TreeItem> items;
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    if (std::isinf(nearRadii[i]))
    {
      continue;
    }
    if (lights[i].IsSpot())
    {
      t.Spots.push_back(static_cast<int>(i));
      t.SpotCones.push_back(SpotCone(
        lights[i].PositionWC, lights[i].DirectionWC, lights[i].CosCone, FarFieldSpotConeSlack));
    }
    else
    {
      items.push_back(Detail::TreeItem{ lights[i].PositionWC, static_cast<int>(i) });
    }
  }
  if (!items.empty())
  {
    t.Nodes.reserve(4 * items.size() / static_cast<std::size_t>(t.LeafSize) + 2);
    Detail::BuildTreeNode(t, items, lights, nearRadii, 0, static_cast<int>(items.size()), -1);
  }
  t.Order.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    t.Order[i] = items[i].Light;
  }
  return t;
}

/// Whether tree node n is taken as one light for every point of the box [lo, hi] (see
/// the file description). Compares squared distances: the tree walk calls it for every node
/// it visits, once per block.
inline bool AcceptFarFieldGroup(
  const FarFieldLightTree::Node& n, const glm::dvec3& lo, const glm::dvec3& hi, double grouping)
{
  if (n.Count < 2 || !n.Uniform || !(grouping > 0.0))
  {
    return false;
  }
  const glm::dvec3 gap = glm::max(glm::max(n.Lo - hi, lo - n.Hi), glm::dvec3(0.0));
  const double boxDistance2 = glm::dot(gap, gap);
  if (!(boxDistance2 > 0.0) || boxDistance2 < n.MaxNearRadius * n.MaxNearRadius)
  {
    return false;
  }
  const glm::dvec3 toCentroid =
    glm::max(glm::max(lo - n.Centroid, n.Centroid - hi), glm::dvec3(0.0));
  const glm::dvec3 extent = n.Hi - n.Lo;
  return glm::dot(extent, extent) < grouping * grouping * glm::dot(toCentroid, toCentroid);
}

/**
 * A group's spread of directions for the far specular's bins
 * (vtkClusteredLightingFarSpecularBins.h): seen from distance r, its lights' unit
 * directions average to about (1 - tr(P Sigma P) / (2 r^2)) u (P the projection across
 * u, Sigma Node::Spread), taken as isotropic, (1 - tr(Sigma) / (3 r^2)) u: a bin's light
 * from a group is less concentrated than one light at its centroid. Returns tr(Sigma) / 3.
 */
inline double GetFarSpecularGroupSpread(const FarFieldLightTree::Node& n)
{
  return (n.Spread[0][0] + n.Spread[1][1] + n.Spread[2][2]) / 3.0;
}

/**
 * What one light of a group's summed colour at its centroid misses of the group's far
 * light at the point x: the second-order term of each moment, per unit colour, in the
 * order of ComputeFarFieldTerms (S, V, T as xx, yy, xy, xz, yz, then F). A moment h of a
 * light at y (v = y - x, r = |v|, u = v / r: h = f(r) for S, f(r) u for V, f(r) u u^T
 * for T, f the attenuation) averaged over the group's lights (weighted as the centroid,
 * covariance Sigma = Node::Spread) is h(centroid) + (1/2) tr(Hessian(h) Sigma) + ...
 * With sigma = u^T Sigma u, tau = tr Sigma and s = Sigma u (phi = f / r, psi = f / r^2):
 *
 *   dS = (1/2) [ f'' sigma + (f' / r) (tau - sigma) ]
 *   dV = (1/2) [ (phi'' r sigma + phi' (tau - sigma)) u + 2 phi' s ]
 *   dT = (1/2) [ (psi'' r^2 sigma + psi' r (tau - sigma)) u u^T
 *                + 2 psi' r (s u^T + u s^T) + 2 psi Sigma ]          (trace dT = dS)
 *
 * and for the fourth moments F (h = f(r) u u u u), whose derivatives have no short form,
 * the same term by second differences along the factors of Sigma (since 2026-12-06).
 *
 * A group seen from afar is brighter than its centroid alone (f is convex), so without
 * this term every group darkens the far field, by about (extent / distance)^2 / 12 of its
 * light, and the groups' errors add up instead of cancelling (1.3% of the whole far
 * field at 65,536 lights, 0.11% with it). The build adds it once per block, at the block's
 * centre (ComputeFarFieldMoments); the stated bound counts it exactly as the build does.
 */
constexpr double FarFieldSpreadStep = 0.5; ///< the fourth moments' difference step
inline void ComputeGroupSpreadTerms(const FarFieldLightTree::Node& n, const glm::dvec3& x,
  double (&dm)[FarFieldMomentsPerChannel], bool fourth = true)
{
  std::fill(dm, dm + FarFieldMomentsPerChannel, 0.0);
  const glm::dvec3 v = n.Centroid - x;
  const double r2 = glm::dot(v, v);
  const glm::dvec3& a = n.Attenuation;
  const double r = std::sqrt(r2);
  const double D = a.x + r * (a.y + r * a.z), D1 = a.y + 2.0 * a.z * r, D2 = 2.0 * a.z;
  if (!(r2 > 0.0) || !(D > 0.0))
  {
    return;
  }
  const glm::dvec3 u = v / r;
  const double f = 1.0 / D, f1 = -D1 / (D * D), f2 = (2.0 * D1 * D1 - D2 * D) / (D * D * D);
  const double phi1 = f1 / r - f / r2, phi2 = f2 / r - 2.0 * f1 / r2 + 2.0 * f / (r2 * r);
  const double psi = f / r2, psi1 = f1 / r2 - 2.0 * f / (r2 * r),
               psi2 = f2 / r2 - 4.0 * f1 / (r2 * r) + 6.0 * f / (r2 * r2);
  const glm::dmat3& C = n.Spread;
  const glm::dvec3 sv = C * u;
  const double sigma = glm::dot(u, sv), tau = C[0][0] + C[1][1] + C[2][2];
  dm[0] = 0.5 * (f2 * sigma + f1 / r * (tau - sigma));
  const glm::dvec3 dV = 0.5 * ((phi2 * r * sigma + phi1 * (tau - sigma)) * u + 2.0 * phi1 * sv);
  dm[1] = dV.x;
  dm[2] = dV.y;
  dm[3] = dV.z;
  const double along = 0.5 * (psi2 * r2 * sigma + psi1 * r * (tau - sigma));
  auto dT = [&](int i, int j)
  { return along * u[i] * u[j] + psi1 * r * (sv[i] * u[j] + u[i] * sv[j]) + psi * C[i][j]; };
  dm[4] = dT(0, 0);
  dm[5] = dT(1, 1);
  dm[6] = dT(0, 1);
  dm[7] = dT(0, 2);
  dm[8] = dT(1, 2);
  if (!fourth)
  {
    return;
  }
  // The fourth moments' term, (1/2) tr(Hessian(h) Sigma), by central differences: with
  // Sigma = sum_k l_k l_k^T (its LDL^T factors), it is (1/2) sum_k (l_k . grad)^2 h, each
  // a second difference along l_k with step FarFieldSpreadStep l_k.
  const double tiny = 1e-12 * tau;
  double L10 = 0.0, L20 = 0.0, L21 = 0.0;
  const double P0 = C[0][0];
  if (P0 > tiny)
  {
    L10 = C[0][1] / P0;
    L20 = C[0][2] / P0;
  }
  const double P1 = C[1][1] - L10 * L10 * P0;
  if (P1 > tiny)
  {
    L21 = (C[1][2] - L20 * L10 * P0) / P1;
  }
  const double P2 = C[2][2] - L20 * L20 * P0 - L21 * L21 * P1;
  const glm::dvec3 axes[3] = { std::sqrt(std::max(P0, 0.0)) * glm::dvec3(1.0, L10, L20),
    std::sqrt(std::max(P1, 0.0)) * glm::dvec3(0.0, 1.0, L21),
    std::sqrt(std::max(P2, 0.0)) * glm::dvec3(0.0, 0.0, 1.0) };
  // The fourth moments of one light of unit colour at offset y, times `scale`, added to
  // dm (ComputeFarMomentTerms' t[9] on).
  auto addFourth = [&](const glm::dvec3& y, double scale)
  {
    const double d = glm::length(y);
    const double q = a.x + d * (a.y + d * a.z);
    if (!(d > 0.0) || !(q > 0.0))
    {
      return;
    }
    double f[FarFieldMomentsPerChannel - FarFieldOrder2Moments];
    ComputeFarFourthMomentTerms(scale / q, y / d, f);
    for (int k = 0; k < FarFieldMomentsPerChannel - FarFieldOrder2Moments; ++k)
    {
      dm[FarFieldOrder2Moments + k] += f[k];
    }
  };
  const double h = FarFieldSpreadStep;
  int differences = 0;
  for (const glm::dvec3& l : axes)
  {
    if (glm::dot(l, l) > 0.0)
    {
      addFourth(v + h * l, 0.5 / (h * h));
      addFourth(v - h * l, 0.5 / (h * h));
      ++differences;
    }
  }
  // The centre's term of every second difference, once.
  if (differences > 0)
  {
    addFourth(v, -differences / (h * h));
  }
}

/**
 * Whether some point of the box [lo, hi] may lie inside the cone `cone` (false only where
 * the spot factor is 0 at every point of it): the box's bounding sphere against the cone
 * (SpotCone::MayReachBall).
 */
inline bool SpotConeMayReachBox(const SpotCone& cone, const glm::dvec3& lo, const glm::dvec3& hi)
{
  return cone.MayReachBall(0.5 * (lo + hi), 0.5 * glm::length(hi - lo));
}

/**
 * The sources of the far field for the nodes in the box [lo, hi]: walks the tree and
 * calls onGroup(node index) for each group taken whole (AcceptFarFieldGroup) and
 * onLight(light index, windowed) for each light taken alone, windowed when some point of
 * the box may lie inside its near radius; then onLight for each spot light whose cone may
 * reach the box (SpotConeMayReachBox). `stack` is scratch space.
 */
template <typename OnGroup, typename OnLight>
void CollectFarFieldSources(const FarFieldLightTree& tree, const std::vector<PreparedLight>& lights,
  const std::vector<double>& nearRadii, double grouping, const glm::dvec3& lo, const glm::dvec3& hi,
  std::vector<int>& stack, OnGroup onGroup, OnLight onLight)
{
  stack.clear();
  if (!tree.Nodes.empty())
  {
    stack.push_back(0);
  }
  while (!stack.empty())
  {
    const int index = stack.back();
    stack.pop_back();
    const FarFieldLightTree::Node& n = tree.Nodes[static_cast<std::size_t>(index)];
    if (AcceptFarFieldGroup(n, lo, hi, grouping))
    {
      onGroup(index);
      continue;
    }
    if (n.Left < 0)
    {
      for (int q = n.First; q < n.First + n.Count; ++q)
      {
        const int l = tree.Order[static_cast<std::size_t>(q)];
        const glm::dvec3& x = lights[static_cast<std::size_t>(l)].PositionWC;
        const double r = nearRadii[static_cast<std::size_t>(l)];
        const double d = glm::length(glm::max(glm::max(lo - x, x - hi), glm::dvec3(0.0)));
        onLight(l, r > 0.0 && d < r);
      }
      continue;
    }
    stack.push_back(n.Left);
    stack.push_back(n.Right);
  }
  for (std::size_t k = 0; k < tree.Spots.size(); ++k)
  {
    const int l = tree.Spots[k];
    const PreparedLight& spot = lights[static_cast<std::size_t>(l)];
    if (SpotConeMayReachBox(tree.SpotCones[k], lo, hi))
    {
      const glm::dvec3& x = spot.PositionWC;
      const double r = nearRadii[static_cast<std::size_t>(l)];
      const double d = glm::length(glm::max(glm::max(lo - x, x - hi), glm::dvec3(0.0)));
      onLight(l, r > 0.0 && d < r);
    }
  }
}

/**
 * The far specular's bins (vtkClusteredLightingFarSpecularBins.h) put a group's light in
 * the one bin of its centroid's direction: a group as wide as its distance (the moments'
 * grouping 1) spans 57 degrees, two bins. So they take a group whole only where its
 * extent is below this fraction of its distance, and its parts otherwise
 * (SplitGroupForFarSpecularBins): at 65,536 lights, 3 of 60,000 channel values more than 2
 * steps off with the groups whole, none with 0.5 (docs/far-field.md).
 */
constexpr double FarSpecularBinsGrouping = 0.5;

/**
 * The sources the far specular's bins take for tree node `node`, a group the moments take
 * whole for the box [lo, hi] (CollectFarFieldSources): onGroup(node index) for the group,
 * or its parts, each taken whole where AcceptFarFieldGroup accepts it at the smaller of
 * `grouping` and FarSpecularBinsGrouping, and onLight(light index) for the lights of
 * leaves it opens (beyond their near radii there, as the group is: taken whole).
 */
template <typename OnGroup, typename OnLight>
void SplitGroupForFarSpecularBins(const FarFieldLightTree& tree, int node, const glm::dvec3& lo,
  const glm::dvec3& hi, double grouping, std::vector<int>& stack, OnGroup onGroup, OnLight onLight)
{
  const double g = std::min(grouping, FarSpecularBinsGrouping);
  stack.clear();
  stack.push_back(node);
  while (!stack.empty())
  {
    const int index = stack.back();
    stack.pop_back();
    const FarFieldLightTree::Node& n = tree.Nodes[static_cast<std::size_t>(index)];
    if (AcceptFarFieldGroup(n, lo, hi, g))
    {
      onGroup(index);
    }
    else if (n.Left < 0)
    {
      for (int q = n.First; q < n.First + n.Count; ++q)
      {
        onLight(tree.Order[static_cast<std::size_t>(q)]);
      }
    }
    else
    {
      stack.push_back(n.Left);
      stack.push_back(n.Right);
    }
  }
}

/// Nodes per axis of a block of the builder (ComputeFarFieldMoments).
constexpr int FarFieldBlockSize = 4;
constexpr int FarFieldBlockNodes = FarFieldBlockSize * FarFieldBlockSize * FarFieldBlockSize;

/// Nodes of one layer of a block (4 x 4 nodes at one offset along an axis).
constexpr int FarFieldLayerNodes = FarFieldBlockSize * FarFieldBlockSize;
/// A block's layers along an axis as bits (bit l: the nodes at offset l): all of them.
constexpr unsigned char FarFieldAllLayers = (1u << FarFieldBlockSize) - 1u;

/**
 * The blocks a build sums (ComputeFarFieldMoments with a list) and, per block, the axis
 * its nodes are taken in layers along and the layers it needs (bits, FarFieldAllLayers
 * for all): a floor on a node plane is read from 2 of a block's 4 layers across it
 * (vtkClusteredLightingFarFieldBlocks.h). The sums cover the layers from the lowest set
 * bit to the highest.
 */
struct FarFieldBlockList
{
  std::vector<std::int64_t> Blocks;
  std::vector<unsigned char> Axis;
  std::vector<unsigned char> Layers;
};

/**
 * The offsets (di, dj, dk) in its block of the node the sums hold at n, when the block is
 * taken in layers along `axis`: n = (l * 4 + a) * 4 + b, with l the offset along `axis`
 * and a, b those along the other two axes (the higher axis as a). Along z this is the
 * order nodes are stored in, (dk * 4 + dj) * 4 + di; the sums' values do not depend on it
 * (each node's terms are added in the same order wherever it sits).
 */
inline glm::ivec3 GetFarFieldBlockNode(int n, int axis)
{
  const int l = n / FarFieldLayerNodes, a = (n / FarFieldBlockSize) % FarFieldBlockSize,
            b = n % FarFieldBlockSize;
  return axis == 0 ? glm::ivec3(l, b, a) : (axis == 1 ? glm::ivec3(b, l, a) : glm::ivec3(b, a, l));
}

/// The bit of node (di, dj, dk) of a block in the masks of nodes per block
/// (vtkClusteredLightingFarFieldBlocks.h): (dk * 4 + dj) * 4 + di.
inline int GetFarFieldBlockBit(int di, int dj, int dk)
{
  return (dk * FarFieldBlockSize + dj) * FarFieldBlockSize + di;
}

/// The lowest and highest set bit of a mask of layers (0 and -1 when none is set).
inline void GetFarFieldLayerRange(unsigned layers, int& first, int& last)
{
  first = 0;
  last = -1;
  for (int l = 0; l < FarFieldBlockSize; ++l)
  {
    if (layers & (1u << l))
    {
      first = last < 0 ? l : first;
      last = l;
    }
  }
}

/// Blocks per axis of a grid.
inline std::array<int, 3> GetFarFieldBlocks(const FarFieldGrid& grid)
{
  std::array<int, 3> b;
  for (int a = 0; a < 3; ++a)
  {
    b[a] = (grid.Dims[a] + FarFieldBlockSize - 1) / FarFieldBlockSize;
  }
  return b;
}

/// Number of blocks of a grid (the range of ComputeFarFieldMoments's block indices).
inline std::int64_t GetNumberOfFarFieldBlocks(const FarFieldGrid& grid)
{
  const std::array<int, 3> b = GetFarFieldBlocks(grid);
  return static_cast<std::int64_t>(b[0]) * b[1] * b[2];
}

/// The first node (i, j, k) of block b (block index x fastest, GetFarFieldBlocks).
inline glm::ivec3 GetFarFieldBlockFirstNode(const FarFieldGrid& grid, std::int64_t b)
{
  const std::array<int, 3> blocks = GetFarFieldBlocks(grid);
  const std::int64_t layer = static_cast<std::int64_t>(blocks[0]) * blocks[1];
  return glm::ivec3(static_cast<int>(b % blocks[0]), static_cast<int>((b % layer) / blocks[0]),
           static_cast<int>(b / layer)) *
    FarFieldBlockSize;
}

/// The nodes one entry of a block list sums (or, without a list, block `entry` of the
/// grid, every layer along z): its block's first node and extent within the grid, the
/// axis its layers run along, and the layers asked (LayerFirst to LayerLast, as the
/// entry's mask) of which those to LayerLastInGrid exist. The builder
/// (ComputeFarFieldMoments) and the textures' uploads both read it.
struct FarFieldEntryNodes
{
  glm::ivec3 FirstNode, Extent;
  int Axis, LayerFirst, LayerLast, LayerLastInGrid;
  /// Whether the entry sums no node (its layers lie past the grid's end).
  bool IsEmpty() const { return this->LayerFirst > this->LayerLastInGrid; }
  /// The box of nodes summed, inclusive (Hi below Lo along Axis when empty).
  glm::ivec3 Lo() const
  {
    glm::ivec3 lo = this->FirstNode;
    lo[this->Axis] += this->LayerFirst;
    return lo;
  }
  glm::ivec3 Hi() const
  {
    glm::ivec3 hi = this->FirstNode + this->Extent - 1;
    hi[this->Axis] = this->FirstNode[this->Axis] + this->LayerLastInGrid;
    return hi;
  }
};

inline FarFieldEntryNodes GetFarFieldEntryNodes(
  const FarFieldGrid& grid, const FarFieldBlockList* list, std::int64_t entry)
{
  const std::size_t e = static_cast<std::size_t>(entry);
  FarFieldEntryNodes r;
  r.FirstNode = GetFarFieldBlockFirstNode(grid, list ? list->Blocks[e] : entry);
  r.Extent = glm::min(glm::ivec3(FarFieldBlockSize),
    glm::ivec3(grid.Dims[0], grid.Dims[1], grid.Dims[2]) - r.FirstNode);
  r.Axis = list ? list->Axis[e] : 2;
  GetFarFieldLayerRange(list ? list->Layers[e] : FarFieldAllLayers, r.LayerFirst, r.LayerLast);
  r.LayerLastInGrid = std::min(r.LayerLast, r.Extent[r.Axis] - 1);
  return r;
}

/// The world box of the nodes of the block holding node (i, j, k).
inline void GetFarFieldBlockBox(
  const FarFieldGrid& grid, const glm::ivec3& node, glm::dvec3& lo, glm::dvec3& hi)
{
  const int i0 = node.x - node.x % FarFieldBlockSize, j0 = node.y - node.y % FarFieldBlockSize,
            k0 = node.z - node.z % FarFieldBlockSize;
  lo = grid.NodePosition(i0, j0, k0);
  hi = grid.NodePosition(std::min(i0 + FarFieldBlockSize, grid.Dims[0]) - 1,
    std::min(j0 + FarFieldBlockSize, grid.Dims[1]) - 1,
    std::min(k0 + FarFieldBlockSize, grid.Dims[2]) - 1);
}

namespace Detail
{
/// One source of a block (a light or a group), position relative to the block's centre.
struct FarFieldSource
{
  float X, Y, Z, R, G, B, A0, A1, A2, InverseNearRadius;
  float Spread; ///< a group's GetFarSpecularGroupSpread (0 for a light)
};

/// Unrolls the loop that follows whole. The loops over a node's moments must be: GCC
/// peels a loop of constant count completely only up to 16 iterations, and the 18 of the
/// fourth moments' layout left a loop inside the loop over the block's nodes, which then
/// did not vectorize (the node sums 13 times slower, since 2026-12-06).
#if defined(__GNUC__)
#define VTK_CLUSTERED_LIGHTING_UNROLL _Pragma("GCC unroll 64")
#else
#define VTK_CLUSTERED_LIGHTING_UNROLL
#endif

/// Sources of one block, structure of arrays, positions relative to the block's centre.
struct FarFieldSources
{
  std::vector<float> X, Y, Z, R, G, B, A0, A1, A2, InverseNearRadius, Spread;
  void Clear()
  {
    for (std::vector<float>* v :
      { &X, &Y, &Z, &R, &G, &B, &A0, &A1, &A2, &InverseNearRadius, &Spread })
    {
      v->clear();
    }
  }
  void Add(const glm::dvec3& relative, const glm::dvec3& color, const glm::dvec3& att,
    double inverseNearRadius, double spread = 0.0)
  {
    Spread.push_back(static_cast<float>(spread));
    X.push_back(static_cast<float>(relative.x));
    Y.push_back(static_cast<float>(relative.y));
    Z.push_back(static_cast<float>(relative.z));
    R.push_back(static_cast<float>(color.x));
    G.push_back(static_cast<float>(color.y));
    B.push_back(static_cast<float>(color.z));
    A0.push_back(static_cast<float>(att.x));
    A1.push_back(static_cast<float>(att.y));
    A2.push_back(static_cast<float>(att.z));
    InverseNearRadius.push_back(static_cast<float>(inverseNearRadius));
  }
  std::size_t Size() const { return X.size(); }
  FarFieldSource Get(std::size_t q) const
  {
    return FarFieldSource{ X[q], Y[q], Z[q], R[q], G[q], B[q], A0[q], A1[q], A2[q],
      InverseNearRadius[q], Spread[q] };
  }
};

/// The far light of one source at one node (offset (dx, dy, dz) from the node to the
/// source), as the terms it adds to each channel's moments per unit colour:
/// t = g (1, ux, uy, uz, ux ux, uy uy, ux uy, ux uz, uy uz, then the fourth-order
/// monomials of ComputeFarMomentTerms), u the unit direction and g the attenuation; Windowed: times
/// the far part 1 - W(d / r), with ir = 1 / r. A source on the node (d = 0) adds nothing, as in
/// ComputeFarContribution. Branch-free, so that the loops below vectorize (given -fno-math-errno
/// -fno-trapping-math, see CMakeLists.txt). Terms FarFieldOrder2Moments: the order-2
/// terms only (t[9] on are not written), for an order-2 far diffuse.
template <bool Windowed, int Terms = FarFieldMomentsPerChannel>
inline void ComputeFarFieldTerms(float dx, float dy, float dz, float a0, float a1, float a2,
  float ir, float (&t)[FarFieldMomentsPerChannel])
{
  const float d = std::sqrt(dx * dx + dy * dy + dz * dz);
  const float inv = 1.0f / (d + 1e-30f);
  const float notOnNode = std::min(d * 1e30f, 1.0f);
  float g = notOnNode / (a0 + d * (a1 + d * a2) + 1e-30f);
  if (Windowed)
  {
    const float x = d * ir, x2 = x * x;
    const float w = std::max(0.0f, 1.0f - x2 * x2);
    g *= 1.0f - w * w;
  }
  const float ux = dx * inv, uy = dy * inv, uz = dz * inv;
  const float gx = g * ux, gy = g * uy, gz = g * uz;
  const float gxx = gx * ux, gyy = gy * uy, gxy = gx * uy;
  t[0] = g;
  t[1] = gx;
  t[2] = gy;
  t[3] = gz;
  t[4] = gxx;
  t[5] = gyy;
  t[6] = gxy;
  t[7] = gx * uz;
  t[8] = gy * uz;
  if (Terms <= FarFieldOrder2Moments)
  {
    return;
  }
  t[9] = gxx * (ux * ux);
  t[10] = gxx * (ux * uy);
  t[11] = gxx * (uy * uy);
  t[12] = gxy * (uy * uy);
  t[13] = gyy * (uy * uy);
  t[14] = gxx * (ux * uz);
  t[15] = gxx * (uy * uz);
  t[16] = gyy * (ux * uz);
  t[17] = gyy * (uy * uz);
}

/**
 * Adds sources into the 54 moments of the block's nodes (node positions px, py, pz
 * relative to the block's centre). Two loop orders, the same sums:
 * - Lanes 0: source by source, each over all the block's nodes, the moments in memory
 *   (acc). Best where there are few vector registers (SSE2, AVX2).
 * - Lanes n: n nodes at a time, their moments kept in a local array while every source
 *   is added, so that most terms cost one multiply-add and no load or store. AVX-512's
 *   32 registers of 16 floats hold the 27 order-2 moments of the three channels, but not
 *   the 54 of order 4, so at order 4 the sources are swept twice: once for the order-2
 *   terms, once for the fourth moments, 27 rows each (AccumulateLanes). The second sweep
 *   computes each source's distance and attenuation again, and is still cheaper than
 *   spilling: the order-4 node sums took 25.9 to 26.8 ms against 34.1 to 36.6 in one
 *   sweep (ClusteredLightingFarFieldStudy --copies, 4,096 lights on the bunny, the whole
 *   grid on 2 threads, old and new builds alternated, 2026-12-07).
 */
/// Adds the far light of `src` at the node (px, py, pz) into column i of the moment rows
/// (channel-major, as the nodes store them): 54 rows, or with Channels 1 the 18 rows of
/// the one channel whose colour the source carries in R; terms First to Terms - 1 of each
/// channel, Stride rows apart (the rows hold term First first).
template <bool Windowed, int Columns, int Channels, int Terms, int First = 0,
  int Stride = FarFieldMomentsPerChannel>
inline void AddFarFieldSource(
  const FarFieldSource& src, float px, float py, float pz, float (*rows)[Columns], int i)
{
  float t[FarFieldMomentsPerChannel];
  ComputeFarFieldTerms<Windowed, Terms>(
    src.X - px, src.Y - py, src.Z - pz, src.A0, src.A1, src.A2, src.InverseNearRadius, t);
  VTK_CLUSTERED_LIGHTING_UNROLL
  for (int m = First; m < Terms; ++m)
  {
    rows[m - First][i] += src.R * t[m];
    if (Channels == 3)
    {
      rows[Stride + m - First][i] += src.G * t[m];
      rows[2 * Stride + m - First][i] += src.B * t[m];
    }
  }
}

/// AccumulateBlock's Lanes n order for terms First to Terms - 1 of each channel: their
/// rows of Lanes nodes held in a local array while every source is added.
template <bool Windowed, int Lanes, int Channels, int First, int Terms>
inline void AccumulateLanes(const FarFieldSources& s, const float* px, const float* py,
  const float* pz, float (*acc)[FarFieldBlockNodes], int first, int end)
{
  static_assert(FarFieldLayerNodes % Lanes == 0, "lanes must divide a layer");
  constexpr int M = FarFieldMomentsPerChannel, Stride = Terms - First;
  for (int i0 = first; i0 < end; i0 += Lanes)
  {
    float a[Channels * Stride][Lanes];
    for (int c = 0; c < Channels; ++c)
    {
      for (int m = 0; m < Stride; ++m)
      {
        std::copy(
          acc[c * M + First + m] + i0, acc[c * M + First + m] + i0 + Lanes, a[c * Stride + m]);
      }
    }
    for (std::size_t q = 0; q < s.Size(); ++q)
    {
      const FarFieldSource src = s.Get(q);
      for (int i = 0; i < Lanes; ++i)
      {
        AddFarFieldSource<Windowed, Lanes, Channels, Terms, First, Stride>(
          src, px[i0 + i], py[i0 + i], pz[i0 + i], a, i);
      }
    }
    for (int c = 0; c < Channels; ++c)
    {
      for (int m = 0; m < Stride; ++m)
      {
        std::copy(a[c * Stride + m], a[c * Stride + m] + Lanes, acc[c * M + First + m] + i0);
      }
    }
  }
}

template <bool Windowed, int Lanes, int Channels, int Terms>
inline void AccumulateBlock(const FarFieldSources& s, const float* px, const float* py,
  const float* pz, float (*acc)[FarFieldBlockNodes], int first = 0, int end = FarFieldBlockNodes)
{
  if constexpr (Lanes == 0)
  {
    for (std::size_t q = 0; q < s.Size(); ++q)
    {
      const FarFieldSource src = s.Get(q);
      for (int i = first; i < end; ++i)
      {
        AddFarFieldSource<Windowed, FarFieldBlockNodes, Channels, Terms>(
          src, px[i], py[i], pz[i], acc, i);
      }
    }
  }
  else if constexpr (Channels == 3 && Terms > FarFieldOrder2Moments)
  {
    // The order-2 terms and the fourth moments in two sweeps over the sources: 27 rows
    // each, held in registers, where the 54 of one sweep spilled (see above).
    AccumulateLanes<Windowed, Lanes, Channels, 0, FarFieldOrder2Moments>(
      s, px, py, pz, acc, first, end);
    AccumulateLanes<Windowed, Lanes, Channels, FarFieldOrder2Moments, Terms>(
      s, px, py, pz, acc, first, end);
  }
  else
  {
    AccumulateLanes<Windowed, Lanes, Channels, 0, Terms>(s, px, py, pz, acc, first, end);
  }
}

/// Spot lights' exponents the vectorized sums take: whole numbers up to this (VTK's
/// default is 1); others are summed in double precision with ComputeFarContribution.
constexpr int FarFieldVectorSpotExponent = 8;

/// Whether a spot light's exponent is one the vectorized sums take.
inline bool IsVectorSpotExponent(double e)
{
  return e >= 0.0 && e <= FarFieldVectorSpotExponent && e == std::floor(e);
}

/// Spot lights of one block (structure of arrays, positions relative to the block's
/// centre): a source's fields, and its unit axis, cos(cone) and exponent.
struct FarFieldSpotSources
{
  FarFieldSources Base;
  std::vector<float> AX, AY, AZ, CosCone, Exponent;
  void Clear()
  {
    Base.Clear();
    for (std::vector<float>* v : { &AX, &AY, &AZ, &CosCone, &Exponent })
    {
      v->clear();
    }
  }
  void Add(const glm::dvec3& relative, const glm::dvec3& color, const PreparedLight& l,
    double inverseNearRadius)
  {
    Base.Add(relative, color, l.Attenuation, inverseNearRadius);
    AX.push_back(static_cast<float>(l.DirectionWC.x));
    AY.push_back(static_cast<float>(l.DirectionWC.y));
    AZ.push_back(static_cast<float>(l.DirectionWC.z));
    CosCone.push_back(static_cast<float>(l.CosCone));
    Exponent.push_back(static_cast<float>(l.Exponent));
  }
  std::size_t Size() const { return Base.Size(); }
};

/// A spot light's cone in the vectorized sums: unit axis, cos(cone) and whole exponent.
struct VectorSpot
{
  float AX, AY, AZ, CosCone, Exponent;
};

/// VTK's spot factor at offset (dx, dy, dz) from a node to spot light s (see
/// AccumulateSpotBlock). Branch-free.
inline float ComputeVectorSpotFactor(float dx, float dy, float dz, const VectorSpot& s)
{
  const float d = std::sqrt(dx * dx + dy * dy + dz * dz);
  const float c = -(dx * s.AX + dy * s.AY + dz * s.AZ) / (d + 1e-30f);
  const float cc = std::min(c, 1.0f);
  float f = 1.0f;
  for (int k = 0; k < FarFieldVectorSpotExponent; ++k)
  {
    f *= static_cast<float>(k) < s.Exponent ? cc : 1.0f;
  }
  return c >= s.CosCone ? f : 0.0f;
}

/**
 * Adds spot lights into the moments of the block's nodes, source by source over the nodes
 * (vectorized across them): a source's terms (ComputeFarFieldTerms) times VTK's spot
 * factor, pow(c, e) for the cosine c = -u.axis from the axis to the node when c >=
 * cos(cone), else 0, the whole exponent e taken as up to FarFieldVectorSpotExponent
 * masked multiplies (branch-free). In single precision a node within about 1e-6 of a
 * cone's edge may fall on either side of it; the stated bound counts that
 * (ComputeFarFieldErrorBounds).
 */
template <bool Windowed, int Channels, int Terms>
inline void AccumulateSpotBlock(const FarFieldSpotSources& s, const float* px, const float* py,
  const float* pz, float (*acc)[FarFieldBlockNodes])
{
  constexpr int M = FarFieldMomentsPerChannel;
  for (std::size_t q = 0; q < s.Size(); ++q)
  {
    const FarFieldSource src = s.Base.Get(q);
    const VectorSpot spot{ s.AX[q], s.AY[q], s.AZ[q], s.CosCone[q], s.Exponent[q] };
    for (int i = 0; i < FarFieldBlockNodes; ++i)
    {
      const float dx = src.X - px[i], dy = src.Y - py[i], dz = src.Z - pz[i];
      float t[M];
      ComputeFarFieldTerms<Windowed, Terms>(
        dx, dy, dz, src.A0, src.A1, src.A2, src.InverseNearRadius, t);
      const float f = ComputeVectorSpotFactor(dx, dy, dz, spot);
      VTK_CLUSTERED_LIGHTING_UNROLL
      for (int m = 0; m < Terms; ++m)
      {
        const float v = f * t[m];
        acc[m][i] += src.R * v;
        if (Channels == 3)
        {
          acc[M + m][i] += src.G * v;
          acc[2 * M + m][i] += src.B * v;
        }
      }
    }
  }
}

/**
 * Adds sources (spot lights with `spot`, else plain sources) into the far specular's bins
 * of the block's nodes (vtkClusteredLightingFarSpecularBins.h): `bins` holds
 * FarSpecularFloatsPerNode rows of FarFieldBlockNodes floats. Source by source: each node's
 * far part, direction and bin in a loop that vectorizes, then, where every node of the
 * block puts the source in one bin (the rule for a source not too near the block), the
 * bin's 6 rows added to in a loop that vectorizes too, else node by node.
 */
template <bool Windowed>
inline void AccumulateSpecularBinsBlock(const FarFieldSources& s, const FarFieldSpotSources* spot,
  const float* px, const float* py, const float* pz, float* bins, float* scratch)
{
  constexpr std::ptrdiff_t L = FarFieldBlockNodes;
  // Per node: g, the direction sum's x, y, z, and the bin (as a float: exact to 2^24).
  // On the heap (`scratch`, 5 L floats), as the builder's other block arrays.
  float* g = scratch;
  float* gx = scratch + L;
  float* gy = scratch + 2 * L;
  float* gz = scratch + 3 * L;
  float* bin = scratch + 4 * L;
  for (std::size_t q = 0; q < s.Size(); ++q)
  {
    const FarFieldSource src = s.Get(q);
    for (int i = 0; i < L; ++i)
    {
      const float dx = src.X - px[i], dy = src.Y - py[i], dz = src.Z - pz[i];
      float t[FarFieldMomentsPerChannel];
      ComputeFarFieldTerms<Windowed, FarFieldOrder2Moments>(
        dx, dy, dz, src.A0, src.A1, src.A2, src.InverseNearRadius, t);
      const float f = spot ? ComputeVectorSpotFactor(dx, dy, dz,
                               VectorSpot{ spot->AX[q], spot->AY[q], spot->AZ[q], spot->CosCone[q],
                                 spot->Exponent[q] })
                           : 1.0f;
      // A group's directions spread about its centroid's: V shorter, as the bound has it.
      const float k =
        f * std::max(0.0f, 1.0f - src.Spread / (dx * dx + dy * dy + dz * dz + 1e-30f));
      g[i] = f * t[0];
      gx[i] = k * t[1];
      gy[i] = k * t[2];
      gz[i] = k * t[3];
      bin[i] = static_cast<float>(ComputeFarSpecularBin(dx, dy, dz));
    }
    int same = 1;
    for (int i = 0; i < L; ++i)
    {
      same &= bin[i] == bin[0] ? 1 : 0;
    }
    const float sum = src.R + src.G + src.B;
    auto add = [&](float* row, int i)
    {
      row[i] += src.R * g[i];
      row[L + i] += src.G * g[i];
      row[2 * L + i] += src.B * g[i];
      row[3 * L + i] += sum * gx[i];
      row[4 * L + i] += sum * gy[i];
      row[5 * L + i] += sum * gz[i];
    };
    auto rowOf = [&](int i)
    { return bins + static_cast<std::ptrdiff_t>(bin[i]) * FarSpecularBinFloats * L; };
    if (same)
    {
      float* row = rowOf(0);
      for (int i = 0; i < L; ++i)
      {
        add(row, i);
      }
    }
    else
    {
      for (int i = 0; i < L; ++i)
      {
        add(rowOf(i), i);
      }
    }
  }
}

/// ComputeFarFieldMoments for Channels 3 (every channel) or 1 (channel `channel` only),
/// Terms FarFieldMomentsPerChannel (order 4) or FarFieldOrder2Moments (F left 0).
template <int Lanes, int Channels, int Terms>
std::int64_t ComputeFarFieldMomentsOf(const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii,
  const FarFieldLightTree& tree, double grouping, std::int64_t b0, std::int64_t b1,
  std::vector<double>& moments, int channel, std::vector<float>* bins,
  const FarFieldBlockList* blockList)
{
  constexpr int Rows = Channels * FarFieldMomentsPerChannel;
  // Where the rows go in a node's moments (channel-major), and the sources' colours.
  const int first = Channels == 1 ? channel * FarFieldMomentsPerChannel : 0;
  auto colorOf = [channel](const glm::dvec3& c)
  { return Channels == 1 ? glm::dvec3(c[channel], 0.0, 0.0) : c; };
  Detail::FarFieldSources whole, windowed;
  Detail::FarFieldSources binWhole; // the bins' whole sources (SplitGroupForFarSpecularBins)
  std::vector<int> stack, binStack;
  float px[FarFieldBlockNodes], py[FarFieldBlockNodes], pz[FarFieldBlockNodes];
  float acc[Rows][FarFieldBlockNodes];
  // The groups' spread terms of a block. On the heap: ASan's fake stack does not keep the
  // 64-byte alignment GCC gives a local array in the AVX-512 copy (its zeroing crashed).
  std::vector<double> spread(FarFieldFloatsPerNode);
  Detail::FarFieldSpotSources spotsWhole, spotsWindowed; // vectorized spot lights
  std::vector<int> spots; // the other spot lights, summed apart in double precision
  // The far specular's bins of a block (on the heap, as `spread`).
  std::vector<float> binRows(
    bins ? std::size_t{ FarSpecularFloatsPerNode } * FarFieldBlockNodes : 0);
  std::vector<float> binScratch(bins ? std::size_t{ 5 } * FarFieldBlockNodes : 0);
  std::int64_t pairs = 0;
  for (std::int64_t entry = b0; entry < b1; ++entry)
  {
    // The layers to sum along the block's axis: from the lowest asked to the highest
    // (within the grid).
    const FarFieldEntryNodes entryNodes = GetFarFieldEntryNodes(grid, blockList, entry);
    const int i0 = entryNodes.FirstNode.x, j0 = entryNodes.FirstNode.y, k0 = entryNodes.FirstNode.z;
    const glm::ivec3 extent = entryNodes.Extent;
    const int axis = entryNodes.Axis;
    const int lFirst = entryNodes.LayerFirst, lLast = entryNodes.LayerLastInGrid;
    if (entryNodes.IsEmpty())
    {
      continue;
    }
    const int nodeFirst = lFirst * FarFieldLayerNodes, nodeEnd = (lLast + 1) * FarFieldLayerNodes;
    glm::dvec3 lo, hi;
    GetFarFieldBlockBox(grid, glm::ivec3(i0, j0, k0), lo, hi);
    const glm::dvec3 center = 0.5 * (lo + hi);
    for (int n = 0; n < FarFieldBlockNodes; ++n)
    {
      // Nodes past the grid's end repeat the last one (summed, not stored).
      const glm::ivec3 d = glm::min(GetFarFieldBlockNode(n, axis), extent - 1);
      const glm::dvec3 p = grid.NodePosition(i0 + d.x, j0 + d.y, k0 + d.z) - center;
      px[n] = static_cast<float>(p.x);
      py[n] = static_cast<float>(p.y);
      pz[n] = static_cast<float>(p.z);
    }
    whole.Clear();
    windowed.Clear();
    binWhole.Clear();
    spotsWhole.Clear();
    spotsWindowed.Clear();
    spots.clear();
    std::fill(spread.begin(), spread.end(), 0.0);
    CollectFarFieldSources(
      tree, lights, nearRadii, grouping, lo, hi, stack,
      [&](int node)
      {
        const FarFieldLightTree::Node& n = tree.Nodes[static_cast<std::size_t>(node)];
        whole.Add(n.Centroid - center, colorOf(n.Color), n.Attenuation, 0.0);
        if (bins)
        {
          SplitGroupForFarSpecularBins(
            tree, node, lo, hi, grouping, binStack,
            [&](int part)
            {
              const FarFieldLightTree::Node& p = tree.Nodes[static_cast<std::size_t>(part)];
              binWhole.Add(p.Centroid - center, colorOf(p.Color), p.Attenuation, 0.0,
                GetFarSpecularGroupSpread(p));
            },
            [&](int light)
            {
              const PreparedLight& l = lights[static_cast<std::size_t>(light)];
              binWhole.Add(l.PositionWC - center, colorOf(l.Color), l.Attenuation, 0.0);
            });
        }
        double dm[FarFieldMomentsPerChannel];
        ComputeGroupSpreadTerms(n, center, dm, Terms > FarFieldOrder2Moments);
        for (int c = 0; c < 3; ++c)
        {
          for (int m = 0; m < FarFieldMomentsPerChannel; ++m)
          {
            spread[c * FarFieldMomentsPerChannel + m] += n.Color[c] * dm[m];
          }
        }
      },
      [&](int light, bool isWindowed)
      {
        const PreparedLight& l = lights[static_cast<std::size_t>(light)];
        if (l.IsSpot())
        {
          if (IsVectorSpotExponent(l.Exponent))
          {
            (isWindowed ? spotsWindowed : spotsWhole)
              .Add(l.PositionWC - center, colorOf(l.Color), l,
                isWindowed ? 1.0 / nearRadii[static_cast<std::size_t>(light)] : 0.0);
          }
          else
          {
            spots.push_back(light);
          }
          return;
        }
        (isWindowed ? windowed : whole)
          .Add(l.PositionWC - center, colorOf(l.Color), l.Attenuation,
            isWindowed ? 1.0 / nearRadii[static_cast<std::size_t>(light)] : 0.0);
        if (bins && !isWindowed)
        {
          binWhole.Add(l.PositionWC - center, colorOf(l.Color), l.Attenuation, 0.0);
        }
      });
    for (auto& row : acc)
    {
      std::fill(row, row + FarFieldBlockNodes, 0.0f);
    }
    AccumulateBlock<false, Lanes, Channels, Terms>(whole, px, py, pz, acc, nodeFirst, nodeEnd);
    AccumulateBlock<true, Lanes, Channels, Terms>(windowed, px, py, pz, acc, nodeFirst, nodeEnd);
    AccumulateSpotBlock<false, Channels, Terms>(spotsWhole, px, py, pz, acc);
    AccumulateSpotBlock<true, Channels, Terms>(spotsWindowed, px, py, pz, acc);
    if (bins)
    {
      std::fill(binRows.begin(), binRows.end(), 0.0f);
      float* rows = binRows.data();
      float* scratch = binScratch.data();
      AccumulateSpecularBinsBlock<false>(binWhole, nullptr, px, py, pz, rows, scratch);
      AccumulateSpecularBinsBlock<true>(windowed, nullptr, px, py, pz, rows, scratch);
      AccumulateSpecularBinsBlock<false>(spotsWhole.Base, &spotsWhole, px, py, pz, rows, scratch);
      AccumulateSpecularBinsBlock<true>(
        spotsWindowed.Base, &spotsWindowed, px, py, pz, rows, scratch);
    }
    const std::int64_t sources = static_cast<std::int64_t>(
      whole.Size() + windowed.Size() + spotsWhole.Size() + spotsWindowed.Size() + spots.size());
    for (int n = nodeFirst; n < nodeEnd; ++n)
    {
      const glm::ivec3 d = GetFarFieldBlockNode(n, axis);
      if (glm::any(glm::greaterThanEqual(d, extent)))
      {
        continue; // past the grid's end
      }
      pairs += sources;
      const std::int64_t index = grid.NodeIndex(i0 + d.x, j0 + d.y, k0 + d.z);
      double* o = &moments[static_cast<std::size_t>(index) * FarFieldFloatsPerNode];
      for (int q = 0; q < Rows; ++q)
      {
        const int at = first + q;
        o[at] = acc[q][n] + spread[static_cast<std::size_t>(at)];
      }
      float* ob =
        bins ? &(*bins)[static_cast<std::size_t>(index) * FarSpecularFloatsPerNode] : nullptr;
      for (int bin = 0; ob && bin < FarSpecularBins; ++bin)
      {
        // A one-channel build's sources carry `channel`'s colour in R.
        auto row = [&](int q)
        {
          return binRows[static_cast<std::size_t>(bin * FarSpecularBinFloats + q) *
              FarFieldBlockNodes +
            static_cast<std::size_t>(n)];
        };
        float* o = ob + static_cast<std::ptrdiff_t>(bin) * FarSpecularBinFloats;
        for (int c = 0; c < 3; ++c)
        {
          o[c] = Channels == 3 ? row(c) : (c == channel ? row(0) : 0.0f);
          o[3 + c] = row(3 + c);
        }
      }
      // Spot lights: ComputeFarContribution at the node itself, as the bound takes them.
      const glm::dvec3 node = grid.NodePosition(i0 + d.x, j0 + d.y, k0 + d.z);
      for (int light : spots)
      {
        const PreparedLight& l = lights[static_cast<std::size_t>(light)];
        double far;
        glm::dvec3 u;
        if (ComputeFarContribution(l, nearRadii[static_cast<std::size_t>(light)], node, far, u))
        {
          const glm::dvec3 color = colorOf(l.Color);
          if (ob)
          {
            const glm::dvec3 binColor = Channels == 1
              ? glm::dvec3(channel == 0 ? color.x : 0.0, channel == 1 ? color.x : 0.0,
                  channel == 2 ? color.x : 0.0)
              : color;
            AddToFarSpecularBins(binColor, far, u, ob);
          }
          double t[FarFieldMomentsPerChannel];
          ComputeFarMomentTerms(1.0, u, t);
          for (int c = 0; c < Channels; ++c)
          {
            const double g = far * color[c];
            double* row = o + first + static_cast<std::ptrdiff_t>(c) * FarFieldMomentsPerChannel;
            for (int m = 0; m < Terms; ++m)
            {
              row[m] += g * t[m];
            }
          }
        }
      }
    }
  }
  return pairs;
}
} // namespace Detail

/**
 * The grid's node moments (FarFieldFloatsPerNode per node, channel-major, as
 * ComputeFarFieldMomentsExact gives them) with the light tree, a block at a time (see the
 * file description). Fills blocks [b0, b1) (block index x fastest, GetFarFieldBlocks), or
 * with `blockList` its entries b0 to b1 - 1, each only in its layers (those that surfaces
 * read, vtkClusteredLightingFarFieldBlocks.h: the same values there as a whole build);
 * `moments` must hold every node. Returns the
 * number of (node, source) pairs summed: the cost. Lanes picks the loop order of the sums
 * (Detail::AccumulateBlock); the default suits any processor. With `channel` 0, 1 or 2 only that
 * channel's 18 moments of each node are summed and written (the others are left as they are): a
 * third of the multiply-adds, for lights that share a colour (FindFarFieldSharedColor,
 * PackFarFieldTexelsOneChannel). With `order4` false the fourth moments are written as 0 and not
 * summed (an order-2 far diffuse reads none of them): half the multiply-adds. With `bins`
 * (FarSpecularFloatsPerNode per node, vtkClusteredLightingFarSpecularBins.h) the far specular's
 * bins of the same blocks are summed too (single precision: the texture's), from the same walk
 * (SplitGroupForFarSpecularBins: groups at most FarSpecularBinsGrouping as wide as they are
 * far, at their centroids, no spread term).
 */
template <int Lanes = 0>
std::int64_t ComputeFarFieldMoments(const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii,
  const FarFieldLightTree& tree, double grouping, std::int64_t b0, std::int64_t b1,
  std::vector<double>& moments, int channel = -1, bool order4 = true,
  std::vector<float>* bins = nullptr, const FarFieldBlockList* blockList = nullptr)
{
  constexpr int All = FarFieldMomentsPerChannel, Two = FarFieldOrder2Moments;
  if (channel >= 0 && channel < 3)
  {
    return order4 ? Detail::ComputeFarFieldMomentsOf<Lanes, 1, All>(grid, lights, nearRadii, tree,
                      grouping, b0, b1, moments, channel, bins, blockList)
                  : Detail::ComputeFarFieldMomentsOf<Lanes, 1, Two>(grid, lights, nearRadii, tree,
                      grouping, b0, b1, moments, channel, bins, blockList);
  }
  return order4 ? Detail::ComputeFarFieldMomentsOf<Lanes, 3, All>(
                    grid, lights, nearRadii, tree, grouping, b0, b1, moments, 0, bins, blockList)
                : Detail::ComputeFarFieldMomentsOf<Lanes, 3, Two>(
                    grid, lights, nearRadii, tree, grouping, b0, b1, moments, 0, bins, blockList);
}

// The node sums are arithmetic bound (per node and source: a square root, two divisions
// and 54 multiply-adds, vectorized across the block's nodes). ComputeFarFieldMomentsForThisCPU
// runs them in a copy compiled for the best instruction set the processor has, chosen at
// run time, so that code built for any x86-64 still runs everywhere:
// - AVX-512: 16 lanes, and 32 registers that hold a group of 16 nodes' 27 moments of
//   one sweep (Lanes 16; order 4 sweeps twice, see AccumulateBlock);
// - AVX2 and FMA: 8 lanes and fused multiply-adds instead of SSE2's 4 lanes (Lanes 0:
//   16 registers cannot hold the moments).
// `flatten` inlines the whole builder into each copy: no code compiled for one instruction
// set is shared with another path. Except under AddressSanitizer
// (scripts/run-sanitizers.sh), where the copies call the portable builder's functions
// (the same source, so the same memory accesses are checked): instrumented and flattened,
// the library's file that holds them compiled in 1,778 s and the core tests' in 896 s on
// the 2-core machine beside other jobs; the library's in 82 s without.
#if defined(__GNUC__) && defined(__x86_64__)
#define VTK_CLUSTERED_LIGHTING_VECTOR_BUILDS 1
#if defined(__SANITIZE_ADDRESS__)
#define VTK_CLUSTERED_LIGHTING_FLATTEN
#else
#define VTK_CLUSTERED_LIGHTING_FLATTEN , flatten
#endif
namespace Detail
{
__attribute__((target("avx2,fma") VTK_CLUSTERED_LIGHTING_FLATTEN)) inline std::int64_t
ComputeFarFieldMomentsAVX2(const FarFieldGrid& grid, const std::vector<PreparedLight>& lights,
  const std::vector<double>& nearRadii, const FarFieldLightTree& tree, double grouping,
  std::int64_t b0, std::int64_t b1, std::vector<double>& moments, int channel, bool order4,
  std::vector<float>* bins, const FarFieldBlockList* blockList)
{
  return ComputeFarFieldMoments<0>(
    grid, lights, nearRadii, tree, grouping, b0, b1, moments, channel, order4, bins, blockList);
}

__attribute__((
  target("avx512f,avx512vl,avx512dq,avx2,fma") VTK_CLUSTERED_LIGHTING_FLATTEN)) inline std::int64_t
ComputeFarFieldMomentsAVX512(const FarFieldGrid& grid, const std::vector<PreparedLight>& lights,
  const std::vector<double>& nearRadii, const FarFieldLightTree& tree, double grouping,
  std::int64_t b0, std::int64_t b1, std::vector<double>& moments, int channel, bool order4,
  std::vector<float>* bins, const FarFieldBlockList* blockList)
{
  return ComputeFarFieldMoments<16>(
    grid, lights, nearRadii, tree, grouping, b0, b1, moments, channel, order4, bins, blockList);
}
} // namespace Detail
#endif

/// The instruction sets the far-field build can use.
enum class FarFieldBuildCopy
{
  Portable, ///< the compiler's default for the target (SSE2 on x86-64)
  AVX2,     ///< AVX2 and FMA
  AVX512    ///< AVX-512 F, VL and DQ
};

/// Whether this processor can run `copy` of the far-field build.
inline bool CanRunFarFieldBuildCopy(FarFieldBuildCopy copy)
{
#ifdef VTK_CLUSTERED_LIGHTING_VECTOR_BUILDS
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  static const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") &&
    __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
  return copy == FarFieldBuildCopy::Portable || (copy == FarFieldBuildCopy::AVX2 && avx2) ||
    (copy == FarFieldBuildCopy::AVX512 && avx512);
#else
  return copy == FarFieldBuildCopy::Portable;
#endif
}

/// The copy ComputeFarFieldMomentsForThisCPU runs on this processor: the widest it can run.
inline FarFieldBuildCopy GetFarFieldBuildCopyForThisCPU()
{
  return CanRunFarFieldBuildCopy(FarFieldBuildCopy::AVX512)
    ? FarFieldBuildCopy::AVX512
    : (CanRunFarFieldBuildCopy(FarFieldBuildCopy::AVX2) ? FarFieldBuildCopy::AVX2
                                                        : FarFieldBuildCopy::Portable);
}

/// The name of a copy, for reports ("portable", "AVX2", "AVX-512").
inline const char* GetFarFieldBuildCopyName(FarFieldBuildCopy copy)
{
  return copy == FarFieldBuildCopy::AVX512
    ? "AVX-512"
    : (copy == FarFieldBuildCopy::AVX2 ? "AVX2" : "portable");
}

/// ComputeFarFieldMoments in the given copy (which the processor must be able to run:
/// CanRunFarFieldBuildCopy). The copies agree to float rounding (fused multiply-adds round
/// once instead of twice, and the AVX-512 copy adds in another order). `channel` as
/// ComputeFarFieldMoments (-1: every channel).
inline std::int64_t ComputeFarFieldMomentsWith(FarFieldBuildCopy copy, const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii,
  const FarFieldLightTree& tree, double grouping, std::int64_t b0, std::int64_t b1,
  std::vector<double>& moments, int channel = -1, bool order4 = true,
  std::vector<float>* bins = nullptr, const FarFieldBlockList* blockList = nullptr)
{
#ifdef VTK_CLUSTERED_LIGHTING_VECTOR_BUILDS
  if (copy == FarFieldBuildCopy::AVX512)
  {
    return Detail::ComputeFarFieldMomentsAVX512(
      grid, lights, nearRadii, tree, grouping, b0, b1, moments, channel, order4, bins, blockList);
  }
  if (copy == FarFieldBuildCopy::AVX2)
  {
    return Detail::ComputeFarFieldMomentsAVX2(
      grid, lights, nearRadii, tree, grouping, b0, b1, moments, channel, order4, bins, blockList);
  }
#endif
  (void)copy;
  return ComputeFarFieldMoments(
    grid, lights, nearRadii, tree, grouping, b0, b1, moments, channel, order4, bins, blockList);
}

/// ComputeFarFieldMoments in the widest copy this processor runs
/// (GetFarFieldBuildCopyForThisCPU).
inline std::int64_t ComputeFarFieldMomentsForThisCPU(const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii,
  const FarFieldLightTree& tree, double grouping, std::int64_t b0, std::int64_t b1,
  std::vector<double>& moments, int channel = -1, bool order4 = true,
  std::vector<float>* bins = nullptr, const FarFieldBlockList* blockList = nullptr)
{
  return ComputeFarFieldMomentsWith(GetFarFieldBuildCopyForThisCPU(), grid, lights, nearRadii, tree,
    grouping, b0, b1, moments, channel, order4, bins, blockList);
}

} // namespace vtkClusteredLighting

#endif
