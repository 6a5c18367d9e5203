// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClusteredLightingFarFieldBound.h
 * @brief GL-free stated bound of the far field's error at a shaded point.
 *
 * The far field (vtkClusteredLightingFarField.h) shades a point from moments interpolated
 * between grid nodes that were built with a light tree (vtkClusteredLightingFarFieldTree.h).
 * ComputeFarFieldErrorBound gives, for one point, normal, view and material, a number the
 * error of the far field's diffuse and Phong specular provably does not exceed. Its terms:
 *
 *  1. Angular truncation: |sum_j g_j (q(t_j) - k(t_j))|, where g_j is light j's far part
 *     at the point, t_j the cosine to the normal (diffuse) or to the mirrored view
 *     (specular), k the true kernel (max(0, t), the Phong lobe with no light from behind
 *     the surface) and q its approximation (the diffuse to order 4, or 2 where the far
 *     field is of order 2, EvaluateFarDiffuseKernel; for the specular, two of order 2: the
 *     whole lobe's, and the projection of the lit-side lobe, a function of the direction
 *     rather than of t alone, with the table's coefficients,
 *     vtkClusteredLightingLobeProjection.h; ApplyFarLobe takes a value between the two, so
 *     the larger of their bounds holds). With the exact moments at the point, the kernel's
 *     estimate is sum_j g_j q(t_j), so this is its error exactly (a signed sum: the
 *     lights' errors partly cancel), not a bound of it.
 *  2. Interpolation and aggregation, source by source: the grid's value at the point is
 *     sum_c w_c (sum of the sources of corner c), the trilinear weights w_c of the 8
 *     corners and each corner's sources from the tree walk of its block. Grouping the
 *     lights into "atoms" (the largest groups taken whole at any corner, and the lights
 *     taken alone at every corner) splits the difference from the exact sum into one term
 *     per atom, each computed exactly: | sum_c w_c value_c(atom) - exact(atom) |. Their sum
 *     bounds the error of the interpolated moments whatever the lights' arrangement (the
 *     triangle inequality), and it keeps the centroid's cancellation inside each group.
 *     A group's value at a corner is what the build stored there: its centroid's terms
 *     plus its spread terms at the corner's block centre (ComputeGroupSpreadTerms).
 *  3. Clamping. The shading clamps its estimate into the interval the moments prove the
 *     true value lies in (ApplyMomentKernel). With exact moments that never adds error;
 *     with interpolated ones the interval itself moves, by at most what term 2 gives for
 *     the moments it is made of (S, V.D, D^T T D for D = N and D = R; for a Phong lobe the
 *     upper end depends on its power, as in ApplyMomentKernel), so the bound takes
 *     the larger of the unclamped bound and that shift. One end is a square root,
 *     (V.D + sqrt(S D^T T D)) / 2: a change d of the product moves it by at most
 *     GetSquareRootShift (about d / (2 sqrt(S D^T T D)) where d is small against the
 *     product, as it is wherever the far light is not faint), not sqrt(d). Until
 *     2026-11-28 the bound took sqrt(d), which made it 2 to 5 times larger on surfaces
 *     (docs/far-field.md, "The stated bound made tighter").
 *  5. The far specular's bins (FarFieldBuildInputs::SpecularBins, powers from
 *     FarSpecularBinsLeastPower on; vtkClusteredLightingFarSpecularBins.h). Their estimate
 *     is not linear in what the nodes hold, so it gets no bound of its own: the bins are
 *     interpolated at the point as the build and the shader have them (every corner's
 *     sources binned, a group at its centroid), and the bound of the moments' estimate
 *     (terms 1 to 3) grows by the distance between the two estimates, both clamped, at the
 *     point: the triangle inequality, exactly computed.
 *  4. Single precision: a relative 1e-3 of the far light (1.25 (kd + ks) sum g), which
 *     covers the node sums (up to 16,000 sources at 2^-24 each), the textures and the
 *     shader's arithmetic with float filtering weights. GPUs that filter with 8-bit
 *     weights add up to 3/512 of the spread of the 8 corner values (docs/far-field.md).
 *
 * The bound is for the Phong model (VTK's default lighting). With PBR the far field
 * carries the diffuse part only and the bound does not cover the far lights' PBR specular.
 * The refinement of the shading (the exact far sum where a pixel straddles saturation) only
 * makes the error smaller.
 */
#ifndef vtkClusteredLightingFarFieldBound_h
#define vtkClusteredLightingFarFieldBound_h

#include "vtkClusteredLightingFarFieldTree.h"

#include <algorithm> // for std::max
#include <array>     // for std::array
#include <cmath>     // for std::abs
#include <cstdint>   // for std::int64_t
#include <glm/glm.hpp>
#include <unordered_map> // for the block lists
#include <vector>        // for std::vector

namespace vtkClusteredLighting
{

/// A shaded point: where, how it faces, and its Phong material per colour channel.
struct FarFieldShadingPoint
{
  glm::dvec3 P = glm::dvec3(0.0);           ///< world position
  glm::dvec3 N = glm::dvec3(0.0, 0.0, 1.0); ///< unit normal (towards the viewer)
  glm::dvec3 R = glm::dvec3(0.0, 0.0, 1.0); ///< unit mirrored view direction
  glm::dvec3 Kd = glm::dvec3(1.0);          ///< diffuse colour x Diffuse
  glm::dvec3 Ks = glm::dvec3(0.0);          ///< specular colour x Specular
  double Power = 1.0;                       ///< specular power
};

/// What a far field was built from (the arguments of ComputeFarFieldMoments).
struct FarFieldBuildInputs
{
  const FarFieldGrid* Grid = nullptr;
  const std::vector<PreparedLight>* Lights = nullptr;
  const std::vector<double>* NearRadii = nullptr;
  const FarFieldLightTree* Tree = nullptr;
  double Grouping = 0.0;
  bool Order4Diffuse = true; ///< the diffuse's order the shading takes (FarFieldPlan)
  bool SpecularBins = false; ///< whether the shading's far specular takes the bins
};

namespace Detail
{
/// A source of a block's list: a tree node taken whole, or a light taken alone.
struct BoundSource
{
  int Group; ///< tree node, or -1
  int Light; ///< light index when Group is -1
};
} // namespace Detail

/// Block source lists kept between calls of ComputeFarFieldErrorBound for one build
/// (neighbouring points share blocks). Not thread-safe: one per thread.
struct FarFieldBoundCache
{
  std::unordered_map<std::int64_t, std::vector<Detail::BoundSource>> Lists;
};

namespace Detail
{
/// A point's two specular kernels, as ApplyFarLobe takes them: the zonal lobe's Legendre
/// coefficients, and the lit-side lobe's projection with its axis
/// (vtkClusteredLightingLobeProjection.h).
struct BoundLobe
{
  glm::dvec3 Zonal = glm::dvec3(0.0); ///< ComputeLobeKernel(power)
  LobeProjection K;
  glm::dvec3 X = glm::dvec3(0.0);
};
inline BoundLobe MakeBoundLobe(const FarFieldShadingPoint& s)
{
  BoundLobe b;
  b.Zonal = ComputeLobeKernel(s.Power);
  double c = 0.0;
  b.X = ComputeLobeAxis(s.N, s.R, c);
  b.K = LookupLobeProjection(c, s.Power);
  return b;
}

/// The quantities whose errors the bound needs, for one light's far part g (per unit
/// colour) from unit direction u: S, V.N, N^T T N, the diffuse kernel q_1(N.u) (to order 4
/// or 2, EvaluateFarDiffuseKernel), V.R, R^T T R, and the two specular estimates
/// ApplyFarLobe blends, q_n(R.u) (zonal) and the lit-side projection.
constexpr int BoundQuantities = 8;
inline void AddBoundQuantities(const FarFieldShadingPoint& s, bool order4, const BoundLobe& qn,
  const glm::dvec3& color, double g, const glm::dvec3& u, double* out)
{
  const double tn = glm::dot(s.N, u), tr = glm::dot(s.R, u);
  const glm::dvec3& qz = qn.Zonal;
  const double v[BoundQuantities] = { 1.0, tn, tn * tn, EvaluateFarDiffuseKernel(tn, order4), tr,
    tr * tr, qz.x + qz.y * tr + qz.z * 0.5 * (3.0 * tr * tr - 1.0),
    EvaluateLobeProjection(qn.K, qn.X, s.R, u) };
  for (int c = 0; c < 3; ++c)
  {
    for (int k = 0; k < BoundQuantities; ++k)
    {
      out[c * BoundQuantities + k] += color[c] * g * v[k];
    }
  }
}
/// The same quantities for moment terms dm (per unit colour, in the order of
/// ComputeFarFieldTerms: S, V, T as xx, yy, xy, xz, yz, trace T = S, then F), as a group's
/// spread terms (ComputeGroupSpreadTerms) add them: each quantity is linear in the moments.
inline void AddBoundMomentQuantities(const FarFieldShadingPoint& s, bool order4,
  const BoundLobe& qn, const glm::dvec3& color, const double (&dm)[FarFieldMomentsPerChannel],
  double* out)
{
  const glm::dvec3 V(dm[1], dm[2], dm[3]);
  const double zz = dm[0] - dm[4] - dm[5];
  const glm::dmat3 T(dm[4], dm[6], dm[7], dm[6], dm[5], dm[8], dm[7], dm[8], zz);
  const double vn = glm::dot(V, s.N), nn = glm::dot(s.N, T * s.N);
  const double vr = glm::dot(V, s.R), rr = glm::dot(s.R, T * s.R);
  const double v[BoundQuantities] = { dm[0], vn, nn, EstimateFarDiffuse(dm, s.N, vn, nn, order4),
    vr, rr, qn.Zonal.x * dm[0] + qn.Zonal.y * vr + qn.Zonal.z * 0.5 * (3.0 * rr - dm[0]),
    ApplyLobeProjectionToMoments(dm, qn.K, qn.X, s.R) };
  for (int c = 0; c < 3; ++c)
  {
    for (int k = 0; k < BoundQuantities; ++k)
    {
      out[c * BoundQuantities + k] += color[c] * v[k];
    }
  }
}
/// The most sqrt(y) can differ from sqrt(x) for y >= 0 within d of x >= 0:
/// max(sqrt(x + d) - sqrt(x), sqrt(x) - sqrt(max(x - d, 0))), in a form that keeps its
/// digits when d is much smaller than x (each difference as a quotient). Below d the
/// square root's slope grows without bound, so the shift is then up to sqrt(d); above it,
/// about d / (2 sqrt(x)).
inline double GetSquareRootShift(double x, double d)
{
  const double rx = std::sqrt(x);
  const double up = d > 0.0 ? d / (std::sqrt(x + d) + rx) : 0.0;
  const double fall = std::min(d, x);
  const double down = fall > 0.0 ? fall / (rx + std::sqrt(x - fall)) : 0.0;
  return std::max(up, down);
}
} // namespace Detail

/**
 * The stated bound (see the file description) at `count` shaded points that share one
 * position (points[k].P, the same for every k) and differ in normal, view or material:
 * bounds[k] is ComputeFarFieldErrorBound(points[k], in, cache), bit for bit (each point's
 * sums are taken in the same order). What depends on the position only (the corners'
 * sources, the atoms, every light's far part and direction at the corners and at the
 * point) is done once for all of them.
 */
inline void ComputeFarFieldErrorBounds(const FarFieldShadingPoint* points, int count,
  const FarFieldBuildInputs& in, FarFieldBoundCache* cache, glm::dvec3* bounds)
{
  if (count <= 0)
  {
    return;
  }
  const FarFieldGrid& g = *in.Grid;
  const std::vector<PreparedLight>& lights = *in.Lights;
  const std::vector<double>& radii = *in.NearRadii;
  const FarFieldLightTree& tree = *in.Tree;
  const FarFieldShadingPoint& s = points[0]; // the position all of them share
  const std::size_t n = static_cast<std::size_t>(count);
  const bool order4 = in.Order4Diffuse;
  std::vector<Detail::BoundLobe> qn(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    qn[k] = Detail::MakeBoundLobe(points[k]);
  }
  constexpr int Q = Detail::BoundQuantities;
  // Each atom's values: the points' 3 Q quantities one after the other.
  const std::size_t stride = std::size_t{ 3 } * Q * n;

  // The cell and weights, as InterpolateFarMoments.
  const glm::dvec3 u0 = (s.P - g.Origin) / g.Spacing;
  int base[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double c = std::min(std::max(u0[a], 0.0), static_cast<double>(g.Dims[a] - 1));
    base[a] = std::min(static_cast<int>(std::floor(c)), std::max(g.Dims[a] - 2, 0));
    t[a] = c - base[a];
  }

  // Each corner's sources, by block (corners of one block share them).
  using Source = Detail::BoundSource;
  struct Corner
  {
    glm::dvec3 Position;
    double Weight;
    const std::vector<Source>* List;
    glm::dvec3 BlockCenter; ///< where the build weighed its groups' spread
    glm::dvec3 Lo, Hi;      ///< the block's box
  };
  FarFieldBoundCache local;
  FarFieldBoundCache& lists = cache ? *cache : local;
  std::vector<Corner> corners;
  std::vector<int> stack;
  const std::array<int, 3> blocks = GetFarFieldBlocks(g);
  for (int corner = 0; corner < 8; ++corner)
  {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
    if (!(w > 0.0))
    {
      continue;
    }
    const int i = std::min(base[0] + di, g.Dims[0] - 1);
    const int j = std::min(base[1] + dj, g.Dims[1] - 1);
    const int k = std::min(base[2] + dk, g.Dims[2] - 1);
    const std::int64_t key =
      (static_cast<std::int64_t>(k / FarFieldBlockSize) * blocks[1] + j / FarFieldBlockSize) *
        blocks[0] +
      i / FarFieldBlockSize;
    glm::dvec3 lo, hi;
    GetFarFieldBlockBox(g, glm::ivec3(i, j, k), lo, hi);
    auto it = lists.Lists.find(key);
    if (it == lists.Lists.end())
    {
      std::vector<Source> sources;
      CollectFarFieldSources(
        tree, lights, radii, in.Grouping, lo, hi, stack,
        [&](int node) {
          sources.push_back(Source{ node, -1 });
        },
        [&](int light, bool) {
          sources.push_back(Source{ -1, light });
        });
      it = lists.Lists.emplace(key, std::move(sources)).first;
    }
    corners.push_back(Corner{ g.NodePosition(i, j, k), w, &it->second, 0.5 * (lo + hi), lo, hi });
  }

  // Atoms: the topmost groups taken whole at some corner; lights under none are alone.
  std::vector<int> groups;
  for (const Corner& c : corners)
  {
    for (const Source& src : *c.List)
    {
      if (src.Group >= 0)
      {
        groups.push_back(src.Group);
      }
    }
  }
  // Each tree node's atom: its topmost ancestor (itself included) taken whole at some
  // corner, or -1. Nodes are stored parent first (BuildTreeNode), so one pass down the
  // tree finds them all.
  std::vector<char> isGroup(tree.Nodes.size(), 0);
  for (int node : groups)
  {
    isGroup[static_cast<std::size_t>(node)] = 1;
  }
  std::vector<int> atomOfNode(tree.Nodes.size(), -1);
  for (std::size_t node = 0; node < tree.Nodes.size(); ++node)
  {
    const int parent = tree.Nodes[node].Parent;
    const int inherited = parent >= 0 ? atomOfNode[static_cast<std::size_t>(parent)] : -1;
    atomOfNode[node] = inherited >= 0 ? inherited : (isGroup[node] ? static_cast<int>(node) : -1);
  }
  // Atom key: tree node >= 0, or -1 - light.
  auto atomOfLight = [&](int light)
  {
    const int leaf = tree.LeafOf[static_cast<std::size_t>(light)];
    const int atom = leaf >= 0 ? atomOfNode[static_cast<std::size_t>(leaf)] : -1;
    return atom >= 0 ? atom : -1 - light;
  };
  // Each atom's slot, in order of first use: by node for groups, by light for the others.
  std::vector<int> nodeSlot(tree.Nodes.size(), -1), lightSlot(lights.size(), -1);
  std::size_t atoms = 0;
  std::vector<double> interpolated;
  auto slotIndex = [&](int key)
  {
    int& slot = key >= 0 ? nodeSlot[static_cast<std::size_t>(key)]
                         : lightSlot[static_cast<std::size_t>(-1 - key)];
    if (slot < 0)
    {
      slot = static_cast<int>(atoms++);
      interpolated.resize(stride * atoms, 0.0);
    }
    return static_cast<std::size_t>(slot);
  };

  // The interpolated grid value, atom by atom, and the float term's far light.
  glm::dvec3 farLightAtCorners(0.0);
  // A spot light at a corner within 1e-5 of its cone's cosine: the build's single
  // precision may have put the corner on either side of the edge (AccumulateSpotBlock),
  // so its far part there (g per unit colour, from u), taken as inside, counts in full for
  // each point's quantities.
  std::vector<double> edge(std::size_t{ 3 } * Q * n, 0.0);
  auto addEdge = [&](const Corner& c, const glm::dvec3& color, double g, const glm::dvec3& u)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      double scratch[3 * Q] = {};
      Detail::AddBoundQuantities(points[k], order4, qn[k], color, g, u, scratch);
      for (int q = 0; q < 3 * Q; ++q)
      {
        edge[std::size_t{ 3 } * Q * k + static_cast<std::size_t>(q)] +=
          c.Weight * std::abs(scratch[q]);
      }
    }
  };
  // The bins as the shader interpolates them (no spread terms: the build adds none).
  std::vector<double> bins(in.SpecularBins ? FarSpecularFloatsPerNode : 0, 0.0);
  for (const Corner& c : corners)
  {
    for (const Source& src : *c.List)
    {
      glm::dvec3 color, u;
      double far;
      int key;
      bool spread = false;
      double dm[FarFieldMomentsPerChannel];
      if (src.Group >= 0)
      {
        const FarFieldLightTree::Node& node = tree.Nodes[static_cast<std::size_t>(src.Group)];
        const glm::dvec3 v = node.Centroid - c.Position;
        const double d = glm::length(v);
        if (!(d > 0.0))
        {
          continue;
        }
        color = node.Color;
        far = EvaluateAttenuation(d, node.Attenuation);
        u = v / d;
        key = atomOfNode[static_cast<std::size_t>(src.Group)];
        // The group's spread terms, as the build adds them (at the block's centre).
        ComputeGroupSpreadTerms(node, c.BlockCenter, dm);
        spread = true;
        farLightAtCorners += c.Weight * color * std::abs(dm[0]);
      }
      else
      {
        const std::size_t l = static_cast<std::size_t>(src.Light);
        const PreparedLight& light = lights[l];
        if (light.IsSpot())
        {
          // One evaluation with the cone widened by the edge's margin: inside the cone it
          // is the light's far part (the same cosine and factor), within the margin a
          // value the build may or may not have stored, outside the cone 0.
          PreparedLight wider = light;
          wider.CosCone -= 1e-5;
          if (!ComputeFarContribution(wider, radii[l], c.Position, far, u))
          {
            continue;
          }
          const double cosine = -glm::dot(u, light.DirectionWC);
          if (cosine < light.CosCone + 1e-5)
          {
            addEdge(c, light.Color, far, u);
          }
          if (cosine < light.CosCone)
          {
            continue;
          }
        }
        else if (!ComputeFarContribution(light, radii[l], c.Position, far, u))
        {
          continue;
        }
        color = light.Color;
        key = atomOfLight(src.Light);
      }
      if (in.SpecularBins && src.Group >= 0)
      {
        // The parts the build's bins take (SplitGroupForFarSpecularBins), whole.
        SplitGroupForFarSpecularBins(
          tree, src.Group, c.Lo, c.Hi, in.Grouping, stack,
          [&](int part)
          {
            const FarFieldLightTree::Node& p = tree.Nodes[static_cast<std::size_t>(part)];
            const glm::dvec3 v = p.Centroid - c.Position;
            const double d = glm::length(v);
            if (d > 0.0)
            {
              AddToFarSpecularBins(c.Weight * p.Color, EvaluateAttenuation(d, p.Attenuation), v / d,
                bins.data(), std::max(0.0, 1.0 - GetFarSpecularGroupSpread(p) / (d * d)));
            }
          },
          [&](int light)
          {
            const PreparedLight& l = lights[static_cast<std::size_t>(light)];
            const glm::dvec3 v = l.PositionWC - c.Position;
            const double d = glm::length(v);
            if (d > 0.0)
            {
              AddToFarSpecularBins(
                c.Weight * l.Color, EvaluateAttenuation(d, l.Attenuation), v / d, bins.data());
            }
          });
      }
      else if (in.SpecularBins)
      {
        AddToFarSpecularBins(c.Weight * color, far, u, bins.data());
      }
      double* o = &interpolated[stride * slotIndex(key)];
      for (std::size_t k = 0; k < n; ++k, o += std::size_t{ 3 } * Q)
      {
        double scratch[3 * Q] = {};
        if (spread)
        {
          Detail::AddBoundMomentQuantities(points[k], order4, qn[k], color, dm, scratch);
        }
        Detail::AddBoundQuantities(points[k], order4, qn[k], color, far, u, scratch);
        for (int q = 0; q < 3 * Q; ++q)
        {
          o[q] += c.Weight * scratch[q];
        }
      }
      farLightAtCorners += c.Weight * color * far;
    }
  }

  // The exact values at the point, atom by atom; the angular term light by light. Every
  // light of the tree is in every corner's list, so its atom has a slot already; a spot
  // light whose cone reaches no corner's block gets one here (its grid value is 0).
  std::vector<double> exact(interpolated.size(), 0.0);
  std::vector<glm::dvec3> angularDiffuse(n, glm::dvec3(0.0)), angularZonal(n, glm::dvec3(0.0)),
    angularProjected(n, glm::dvec3(0.0));
  std::vector<glm::dvec3> exactNN(n, glm::dvec3(0.0)), exactRR(n, glm::dvec3(0.0));
  glm::dvec3 exactS(0.0); // the far light at the point: S exactly
  const std::size_t inTree = tree.Order.size();
  for (std::size_t q = 0; q < inTree + tree.Spots.size(); ++q)
  {
    const int l = q < inTree ? tree.Order[q] : tree.Spots[q - inTree];
    const std::size_t li = static_cast<std::size_t>(l);
    double far;
    glm::dvec3 u;
    if (!ComputeFarContribution(lights[li], radii[li], s.P, far, u))
    {
      continue;
    }
    const std::size_t index = slotIndex(atomOfLight(l));
    exact.resize(interpolated.size(), 0.0);
    double* o = &exact[stride * index];
    const glm::dvec3 g = lights[li].Color * far;
    for (std::size_t k = 0; k < n; ++k, o += std::size_t{ 3 } * Q)
    {
      const FarFieldShadingPoint& p = points[k];
      Detail::AddBoundQuantities(p, order4, qn[k], lights[li].Color, far, u, o);
      const double tn = glm::dot(p.N, u), tr = glm::dot(p.R, u);
      const double lobe = tn > 0.0 && tr > 0.0 ? std::pow(tr, p.Power) : 0.0;
      angularDiffuse[k] += g * (EvaluateFarDiffuseKernel(tn, order4) - std::max(0.0, tn));
      const glm::dvec3& qz = qn[k].Zonal;
      angularZonal[k] += g * (qz.x + qz.y * tr + qz.z * 0.5 * (3 * tr * tr - 1) - lobe);
      angularProjected[k] += g * (EvaluateLobeProjection(qn[k].K, qn[k].X, p.R, u) - lobe);
      exactNN[k] += g * tn * tn;
      exactRR[k] += g * tr * tr;
    }
    exactS += g;
  }

  for (std::size_t k = 0; k < n; ++k)
  {
    const FarFieldShadingPoint& p = points[k];
    glm::dvec3& bound = bounds[k];
    for (int ch = 0; ch < 3; ++ch)
    {
      double delta[Q] = {}, total[Q] = {}, grid[Q] = {};
      for (int q = 0; q < Q; ++q)
      {
        delta[q] = edge[std::size_t{ 3 } * Q * k + static_cast<std::size_t>(ch * Q + q)];
      }
      for (std::size_t a = 0; a < atoms; ++a)
      {
        for (int q = 0; q < Q; ++q)
        {
          const std::size_t at =
            stride * a + std::size_t{ 3 } * Q * k + static_cast<std::size_t>(ch * Q + q);
          delta[q] += std::abs(interpolated[at] - exact[at]);
          total[q] += exact[at];
          grid[q] += interpolated[at];
        }
      }
      const double dS = delta[0], dVN = delta[1], dNN = delta[2], dQd = delta[3];
      const double dVR = delta[4], dRR = delta[5], dQz = delta[6], dQp = delta[7];
      // How far the clamp interval of ApplyMomentKernel can move.
      auto upperShift = [&](double dV, double dD, double D)
      {
        const double x = std::max(exactS[ch] * D, 0.0);
        const double d = std::max(exactS[ch] * dD + D * dS + dS * dD, 0.0);
        return std::max(0.5 * (dV + Detail::GetSquareRootShift(x, d)), 0.25 * (dS + 2.0 * dV + dD));
      };
      // An estimate within dQ of the exact moments' one, e, clamped into an interval whose
      // ends lie within shiftLow and shiftHigh of the exact moments' [low, high]: its error
      // is at most |e - truth| + dQ where the clamp cannot act (e at least dQ inside the
      // interval's nearest possible ends), else also at most the ends' shift.
      auto clamped = [](double angular, double dQ, double e, double low, double high,
                       double shiftLow, double shiftHigh)
      {
        const double unclamped = std::abs(angular) + dQ;
        const bool inside = e - dQ >= low + shiftLow && e + dQ <= high - shiftHigh;
        return inside ? unclamped : std::max(unclamped, std::max(shiftLow, shiftHigh));
      };
      double low = 0.0, high = 0.0;
      ComputeMomentInterval(exactS[ch], total[1], exactNN[k][ch], false, 1.0, low, high);
      const double diffuseShiftLow = std::max(dVN, 0.5 * (dVN + dNN));
      const double diffuseShiftHigh = upperShift(dVN, dNN, exactNN[k][ch]);
      const double diffuse =
        clamped(angularDiffuse[k][ch], dQd, total[3], low, high, diffuseShiftLow, diffuseShiftHigh);
      // The blend weight ApplyFarLobe takes (ComputeLobeBlend of the clamped diffuse
      // estimate, V.N and N^T T N), over every value those may have: a clamp moves by at
      // most the most its value or its ends move; single precision adds its relative 1e-3.
      const double slack = 1e-3 * std::max(exactS[ch], farLightAtCorners[ch]);
      const double D0 = std::min(std::max(total[3], low), high);
      const double dD = std::max(dQd, std::max(diffuseShiftLow, diffuseShiftHigh)) + slack;
      // It grows with N^T T N and falls with D and V.N.
      const double dV = dVN + slack, dN = dNN + slack;
      const double blendLow =
        ComputeLobeBlend(D0 + dD, total[1] + dV, std::max(exactNN[k][ch] - dN, 0.0));
      const double blendHigh =
        ComputeLobeBlend(std::max(D0 - dD, 0.0), total[1] - dV, exactNN[k][ch] + dN);
      // The lobe's upper end as ApplyMomentKernel takes it for this power.
      const LobeUpperEnd end = GetLobeUpperEnd(p.Power);
      const double lobeShift = end == LobeUpperEnd::SecondMoment
        ? std::max(
            upperShift(dVR, dRR, exactRR[k][ch]), ComputeLobeQuadraticUpperShift(dS, dVR, dRR))
        : (end == LobeUpperEnd::Diffuse ? upperShift(dVR, dRR, exactRR[k][ch]) : dS);
      // ApplyFarLobe's result lies between its two clamped estimates: at most the larger
      // of their errors, or one's alone where the blend is surely 0 or 1.
      ComputeMomentInterval(exactS[ch], total[4], exactRR[k][ch], true, p.Power, low, high);
      const double zonalBound =
        clamped(angularZonal[k][ch], dQz, total[6], low, high, 0.0, lobeShift);
      const double projectedBound =
        clamped(angularProjected[k][ch], dQp, total[7], low, high, 0.0, lobeShift);
      double specular = blendHigh <= 0.0
        ? zonalBound
        : (blendLow >= 1.0 ? projectedBound : std::max(zonalBound, projectedBound));
      if (in.SpecularBins && p.Ks[ch] > 0.0 && p.Power >= FarSpecularBinsLeastPower)
      {
        // Term 5: ApplyFarLobe's estimate from the grid's moments (the quantities are
        // linear in them), against the bins', both clamped into the lobe's interval.
        double dLow = 0.0, dHigh = 0.0, sLow = 0.0, sHigh = 0.0;
        ComputeMomentInterval(grid[0], grid[1], grid[2], false, 1.0, dLow, dHigh);
        const double D = std::min(std::max(grid[3], dLow), dHigh);
        ComputeMomentInterval(grid[0], grid[4], grid[5], true, p.Power, sLow, sHigh);
        const double zonal = std::min(std::max(grid[6], sLow), sHigh);
        const double a = ComputeLobeBlend(D, grid[1], grid[2]);
        const double moments = std::min(std::max(zonal + a * (grid[7] - zonal), sLow), sHigh);
        const double fromBins = std::min(
          std::max(EvaluateFarSpecularBins(bins.data(), p.N, p.R, p.Power)[ch], sLow), sHigh);
        specular += std::abs(fromBins - moments);
      }
      const double precision =
        1e-3 * 1.25 * (p.Kd[ch] + p.Ks[ch]) * std::max(exactS[ch], farLightAtCorners[ch]);
      bound[ch] = p.Kd[ch] * diffuse + p.Ks[ch] * specular + precision;
    }
  }
}

/**
 * The stated bound (see the file description) of the far field's error at the shaded
 * point s, per colour channel, in the units of the light colours (multiply by 255 for
 * 8-bit steps). `cache` (optional) keeps the blocks' source lists for further calls on
 * the same build. Several points at one position: ComputeFarFieldErrorBounds.
 */
inline glm::dvec3 ComputeFarFieldErrorBound(
  const FarFieldShadingPoint& s, const FarFieldBuildInputs& in, FarFieldBoundCache* cache = nullptr)
{
  glm::dvec3 bound(0.0);
  ComputeFarFieldErrorBounds(&s, 1, in, cache, &bound);
  return bound;
}

/// ComputeFarFieldErrorBound summarized over probe points (SummarizeFarFieldErrorBound).
struct FarFieldBoundSummary
{
  double Max = 0.0;  ///< largest bound, 8-bit steps
  double Mean = 0.0; ///< mean over the probes of their largest bound, 8-bit steps
  int Probes = 0;    ///< points probed (each with 6 normals)
};

/// How many probe points SummarizeFarFieldErrorBound takes (8 to 256, see there).
inline int GetFarFieldBoundProbeCount(
  const FarFieldBuildInputs& in, double lightEvaluations = 16777216.0)
{
  if (!in.Grid || !in.Lights || !in.Tree || (in.Tree->Nodes.empty() && in.Tree->Spots.empty()))
  {
    return 0;
  }
  const double perProbe =
    6.0 * (static_cast<double>(in.Tree->Order.size() + in.Tree->Spots.size()) + 1.0);
  return static_cast<int>(std::min(256.0, std::max(8.0, std::floor(lightEvaluations / perProbe))));
}

/// The largest bound (8-bit steps, largest channel) at probe `i` over its 6 axis normals.
inline double ComputeFarFieldBoundAtProbe(const FarFieldBuildInputs& in, int i)
{
  auto halton = [](int n, int b)
  {
    double f = 1.0, r = 0.0;
    for (; n > 0; n /= b)
    {
      f /= b;
      r += f * (n % b);
    }
    return r;
  };
  const FarFieldGrid& g = *in.Grid;
  const glm::dvec3 lo = g.Origin + g.Spacing;
  const glm::dvec3 size = g.Spacing *
    glm::dvec3(std::max(g.Dims[0] - 3, 0), std::max(g.Dims[1] - 3, 0), std::max(g.Dims[2] - 3, 0));
  FarFieldShadingPoint s;
  s.P = lo + size * glm::dvec3(halton(i + 1, 2), halton(i + 1, 3), halton(i + 1, 5));
  // The 6 axis normals at one position: one call does the position's work once.
  FarFieldShadingPoint axes[6];
  for (int axis = 0; axis < 6; ++axis)
  {
    axes[axis] = s;
    axes[axis].N = glm::dvec3(0.0);
    axes[axis].N[axis % 3] = axis < 3 ? 1.0 : -1.0;
    axes[axis].R = axes[axis].N;
  }
  glm::dvec3 bounds[6];
  ComputeFarFieldErrorBounds(axes, 6, in, nullptr, bounds);
  double largest = 0.0;
  for (const glm::dvec3& bound : bounds)
  {
    const glm::dvec3 b = 255.0 * bound;
    largest = std::max(largest, std::max(b.x, std::max(b.y, b.z)));
  }
  return largest;
}

/// The summary of the probes' values (ComputeFarFieldBoundAtProbe), in probe order.
inline FarFieldBoundSummary SummarizeFarFieldBoundProbes(const std::vector<double>& values)
{
  FarFieldBoundSummary summary;
  summary.Probes = static_cast<int>(values.size());
  double sum = 0.0;
  for (double v : values)
  {
    summary.Max = std::max(summary.Max, v);
    sum += v;
  }
  summary.Mean = values.empty() ? 0.0 : sum / static_cast<double>(values.size());
  return summary;
}

/**
 * The stated bound for a white, fully diffuse surface (Kd 1, Ks 0) at probe points spread
 * through the grid's interior (a Halton sequence, deterministic), each with the 6 axis
 * normals, largest channel, in 8-bit steps. The number of probes keeps the work near
 * `lightEvaluations` light evaluations (8 to 256 probes). A summary, not a supremum: the
 * bound at a pixel depends on its position and normal (ComputeFarFieldErrorBound).
 * SummarizeFarFieldErrorBound runs the probes in order; the probes are independent, so a
 * caller may run ComputeFarFieldBoundAtProbe on several threads and combine the values
 * with SummarizeFarFieldBoundProbes (the same result, bit for bit).
 */
inline FarFieldBoundSummary SummarizeFarFieldErrorBound(
  const FarFieldBuildInputs& in, double lightEvaluations = 16777216.0)
{
  std::vector<double> values(
    static_cast<std::size_t>(GetFarFieldBoundProbeCount(in, lightEvaluations)));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    values[i] = ComputeFarFieldBoundAtProbe(in, static_cast<int>(i));
  }
  return SummarizeFarFieldBoundProbes(values);
}

} // namespace vtkClusteredLighting

#endif
