// SPDX-License-Identifier: BSD-3-Clause
// Far-field study: error against cost of ways to add back what the near radius cuts off,
// measured on the CPU (GL-free core, double precision) at points on the benchmark scenes'
// surfaces, before and independently of any GL code.
//
// For each scene and light set (the benchmark's, seeded) it samples points on the visible
// surfaces (area-weighted, inside the camera frustum) with their normals and materials,
// computes the exact image value (every light, VTK's formulas, diffuse and Phong specular,
// clamped, 8-bit) and the value of each candidate, and prints max, mean and RMSE of the
// differences in 8-bit steps (after rounding both to 8 bits, as images are) with the cost
// proxies: lights evaluated exactly per point (the near lights) and far-field nodes.
//
//   ClusteredLightingFarFieldStudy [--scene bunny|house|user|dense|ball] [--always-on]
//     [--lights N] [--samples S] [--cutoffs 1024,4096] [--nodes 32768] [--cells 2]
//     [--grouping 0.05] [--hierarchy 0.02,0.1] [--bounds] [--copies] [--worst K]
//     [--orders] [--order4-grid] [--blocks 255,2048] [--far-cutoffs] [--intensity I]
//     [--pass-region] [--at x,y,z,x,y,z,...] [--at-normals x,y,z,...]
//
// Rows: "cut at 1/c" (before the far field: every light cut at its cutoff radius); "far
// field" (design 1, the product's core code: PlanFarField, ComputeFarFieldMoments, the
// interpolated moments and clamped kernels) for each node budget, near radius in cells
// and grouping, at the first cutoff (with --far-cutoffs at each: a larger cutoff shortens
// the near radii and hands more of each light to the far field), with its build time and
// sources summed per node, and with --bounds the stated bound (ComputeFarFieldErrorBound)
// at every sample and channel against the actual error, and the summary of it over probe
// points that the pass reports and an error budget is held to (SummarizeFarFieldErrorBound), and
// with --copies the node sums' time in each copy of the build this processor runs (portable, AVX2,
// AVX-512: ComputeFarFieldMomentsWith), to order 4 and to order 2, side by side, best of 7 rounds
// that time each once,
// and with --worst K where the far field's error comes from (PrintWorstSamples: the kernels'
// angular truncation against the grid's interpolation, the image error with each removed, and the K
// worst samples taken apart), and with --orders as well what more angular resolution would buy: the
// kernels of orders 2 (the product's), 4, 6 and 8 applied to the exact moments at the point,
// clamped into the order-2 interval, with the grid's share as measured at order 2, and
// each with the far specular exact; with --order4-grid (and --worst) an order-4 far
// diffuse through the grid itself: each node's exact fourth-order moments (brute force
// over the lights) interpolated trilinearly beside the product's order-2 ones, with the
// product's far specular and with it exact; "hierarchy per point" (design 2: the light tree walked
// at each point, groups taken by their aggregation bound, each shaded exactly; the cost is the
// lights and groups evaluated per point, in the near/pt column); with --blocks, for each tolerance
// 1/t (colour units), the far parts summed to within half of it from bounds of blocks of 32 lights
// in Morton order (FarBlocksStudy.h, a design measured and not adopted): the work per point (block
// bounds and lights summed) against the far-field lights, and the largest error against the exact
// far sum. The far field's region is the samples' box; with --pass-region the pass's own (the
// visible props' bounds), so that the grid's nodes are the pass's. --at takes the surface
// points nearest to given world points as the samples instead of random ones (the points
// that the benchmark's --worst-pixels prints; implies --pass-region): with --worst their
// errors taken apart, with --specular-bins each point's error with the moments' far
// specular and with the bins; --at-normals replaces those points' normals, in turn (a
// silhouette's normal turned from the viewer, say). --scene ball is
// Examples/Python/user_lights.py's scene (--lights, --intensity as the example's). List
// options take comma-separated values.
#include "BenchmarkMeasure.h"
#include "BenchmarkPlan.h"
#include "ClusteredLightingScenes.h"
#include "FarBlocksStudy.h"
#include "SpecularBinsStudy.h"
#include "vtkClusteredLightingFarFieldBound.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace vtkClusteredLighting;
using namespace ClusteredLightingBenchmark;

namespace
{
struct Sample
{
  glm::dvec3 P, N, V; ///< position, unit normal (towards the viewer), unit direction to the eye
  glm::dvec3 Kd;      ///< diffuse colour x Diffuse
  double Ks = 0.0, Power = 1.0;
};

/// The renderer's actors as triangles (polygons fanned), with point normals and areas.
struct SurfaceTriangles
{
  struct Tri
  {
    vtkPolyData* Mesh;
    vtkDataArray* Normals;
    vtkIdType Ids[3];
    vtkProperty* Property;
  };
  std::vector<Tri> Tris;
  std::vector<double> Cumulative; ///< running sum of the triangles' areas
  std::vector<vtkSmartPointer<vtkPolyData>> Keep;

  explicit SurfaceTriangles(vtkRenderer* ren)
  {
    double total = 0.0;
    vtkActorCollection* actors = ren->GetActors();
    actors->InitTraversal();
    while (vtkActor* a = actors->GetNextActor())
    {
      vtkPolyData* in = vtkPolyData::SafeDownCast(a->GetMapper()->GetInputDataObject(0, 0));
      if (!in)
      {
        continue;
      }
      vtkNew<vtkPolyDataNormals> normals;
      normals->SetInputData(in);
      normals->SplittingOff();
      normals->ComputePointNormalsOn();
      normals->Update();
      vtkSmartPointer<vtkPolyData> mesh = normals->GetOutput();
      this->Keep.push_back(mesh);
      vtkCellArray* polys = mesh->GetPolys();
      vtkNew<vtkIdList> ids;
      for (polys->InitTraversal(); polys->GetNextCell(ids);)
      {
        for (vtkIdType t = 1; t + 1 < ids->GetNumberOfIds(); ++t) // fan
        {
          Tri tri{ mesh, mesh->GetPointData()->GetNormals(),
            { ids->GetId(0), ids->GetId(t), ids->GetId(t + 1) }, a->GetProperty() };
          const auto p = this->GetCorners(tri);
          total += 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
          this->Tris.push_back(tri);
          this->Cumulative.push_back(total);
        }
      }
    }
  }

  static std::array<glm::dvec3, 3> GetCorners(const Tri& tri)
  {
    std::array<glm::dvec3, 3> p;
    for (int k = 0; k < 3; ++k)
    {
      double q[3];
      tri.Mesh->GetPoint(tri.Ids[k], q);
      p[static_cast<std::size_t>(k)] = glm::dvec3(q[0], q[1], q[2]);
    }
    return p;
  }

  /// The sample at barycentric weights `w` of a triangle: point, interpolated normal
  /// (turned towards the eye, as VTK shades back faces), material.
  static Sample MakeSample(const Tri& tri, const double w[3], const glm::dvec3& eye)
  {
    const auto p = GetCorners(tri);
    Sample s;
    glm::dvec3 n(0.0);
    s.P = glm::dvec3(0.0);
    for (int k = 0; k < 3; ++k)
    {
      double nk[3];
      tri.Normals->GetTuple(tri.Ids[k], nk);
      s.P += w[k] * p[static_cast<std::size_t>(k)];
      n += w[k] * glm::dvec3(nk[0], nk[1], nk[2]);
    }
    s.V = glm::normalize(eye - s.P);
    s.N = glm::normalize(n);
    if (glm::dot(s.N, s.V) < 0.0)
    {
      s.N = -s.N;
    }
    double c[3];
    tri.Property->GetDiffuseColor(c);
    s.Kd = tri.Property->GetDiffuse() * glm::dvec3(c[0], c[1], c[2]);
    s.Ks = tri.Property->GetSpecular();
    s.Power = tri.Property->GetSpecularPower();
    return s;
  }
};

glm::dvec3 GetEye(vtkRenderer* ren)
{
  double eye[3];
  ren->GetActiveCamera()->GetPosition(eye);
  return glm::dvec3(eye[0], eye[1], eye[2]);
}

/**
 * --at: the surface points nearest to given world points (the benchmark's --worst-pixels
 * prints them), each the closest point of the closest triangle (projected into the
 * triangle's plane, or onto its nearest edge where the projection falls outside).
 */
std::vector<Sample> SampleSurfacesAt(vtkRenderer* ren, const std::vector<glm::dvec3>& points)
{
  const SurfaceTriangles surface(ren);
  const glm::dvec3 eye = GetEye(ren);
  std::vector<Sample> out;
  for (const glm::dvec3& x : points)
  {
    double best = 1e300, bestW[3] = { 1.0, 0.0, 0.0 };
    const SurfaceTriangles::Tri* bestTri = nullptr;
    for (const SurfaceTriangles::Tri& tri : surface.Tris)
    {
      const auto p = SurfaceTriangles::GetCorners(tri);
      const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
      const double nn = glm::dot(n, n);
      if (!(nn > 0.0))
      {
        continue;
      }
      const glm::dvec3 q = x - glm::dot(x - p[0], n) / nn * n;
      // Each corner's weight: the area opposite it over the whole, signed.
      double w[3] = { glm::dot(glm::cross(p[2] - p[1], q - p[1]), n) / nn,
        glm::dot(glm::cross(p[0] - p[2], q - p[2]), n) / nn, 0.0 };
      w[2] = 1.0 - w[0] - w[1];
      if (w[0] < 0.0 || w[1] < 0.0 || w[2] < 0.0)
      {
        // Outside: the nearest point of the nearest edge.
        double edgeBest = 1e300;
        for (int e = 0; e < 3; ++e)
        {
          const int a = e, b = (e + 1) % 3;
          const glm::dvec3 ab = p[static_cast<std::size_t>(b)] - p[static_cast<std::size_t>(a)];
          const double t = std::min(1.0,
            std::max(0.0,
              glm::dot(x - p[static_cast<std::size_t>(a)], ab) /
                std::max(glm::dot(ab, ab), 1e-300)));
          const double d = glm::length(x - (p[static_cast<std::size_t>(a)] + t * ab));
          if (d < edgeBest)
          {
            edgeBest = d;
            w[0] = w[1] = w[2] = 0.0;
            w[a] = 1.0 - t;
            w[b] = t;
          }
        }
      }
      const glm::dvec3 c = w[0] * p[0] + w[1] * p[1] + w[2] * p[2];
      const double d = glm::length(x - c);
      if (d < best)
      {
        best = d;
        std::copy(w, w + 3, bestW);
        bestTri = &tri;
      }
    }
    if (bestTri)
    {
      out.push_back(SurfaceTriangles::MakeSample(*bestTri, bestW, eye));
      std::printf("  --at (%.4g, %.4g, %.4g): surface point %.3g away, normal (%.3f, %.3f, %.3f)\n",
        x.x, x.y, x.z, best, out.back().N.x, out.back().N.y, out.back().N.z);
    }
  }
  return out;
}

/// Area-weighted points on the renderer's actors, inside the camera frustum, facing it.
std::vector<Sample> SampleSurfaces(vtkRenderer* ren, int count, unsigned seed)
{
  const SurfaceTriangles surface(ren);
  const std::vector<SurfaceTriangles::Tri>& tris = surface.Tris;
  const std::vector<double>& cumulative = surface.Cumulative;
  const double total = cumulative.empty() ? 0.0 : cumulative.back();
  const glm::dvec3 eye = GetEye(ren);
  vtkMatrix4x4* m =
    ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(1024.0 / 768.0, -1, 1);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Sample> out;
  for (int attempt = 0; attempt < 50 * count && static_cast<int>(out.size()) < count; ++attempt)
  {
    const double pick = U(rng) * total;
    const std::size_t t = std::min(tris.size() - 1,
      static_cast<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
    const SurfaceTriangles::Tri& tri = tris[t];
    double r1 = U(rng), r2 = U(rng);
    if (r1 + r2 > 1.0)
    {
      r1 = 1.0 - r1;
      r2 = 1.0 - r2;
    }
    const double w[3] = { 1.0 - r1 - r2, r1, r2 };
    const Sample s = SurfaceTriangles::MakeSample(tri, w, eye);
    double clip[4];
    const double hp[4] = { s.P.x, s.P.y, s.P.z, 1.0 };
    m->MultiplyPoint(hp, clip);
    if (!(clip[3] > 0.0) || std::abs(clip[0]) > clip[3] || std::abs(clip[1]) > clip[3] ||
      std::abs(clip[2]) > clip[3])
    {
      continue;
    }
    out.push_back(s);
  }
  return out;
}

/// VTK's diffuse + Phong specular of one light (unit colour) at a sample, per unit att.
glm::dvec2 Shade(const Sample& s, const glm::dvec3& toLight)
{
  const double df = std::max(0.0, glm::dot(s.N, toLight));
  if (!(df > 0.0))
  {
    return glm::dvec2(0.0);
  }
  const glm::dvec3 R = 2.0 * glm::dot(s.N, s.V) * s.N - s.V;
  const double rv = std::max(0.0, glm::dot(toLight, R));
  return glm::dvec2(df, s.Ks > 0.0 && rv > 0.0 ? std::pow(rv, s.Power) : 0.0);
}

/// The shaded value of one light (unit colour, unit attenuation) per channel.
glm::dvec3 ShadeValue(const Sample& s, const glm::dvec3& toLight)
{
  const glm::dvec2 sh = Shade(s, toLight);
  return sh.x * s.Kd + glm::dvec3(sh.y * s.Ks);
}

/// The near parts of the lights at a sample, each exact (the split window of a far-field
/// light applied); `count` grows by the lights evaluated.
glm::dvec3 SumNearParts(
  const std::vector<PreparedLight>& lights, const Sample& smp, std::int64_t& count)
{
  glm::dvec3 sum(0.0);
  for (const PreparedLight& l : lights)
  {
    const glm::dvec3 v = l.PositionWC - smp.P;
    const double d = glm::length(v);
    if (d < l.Radius)
    {
      const double w = l.FarField ? EvaluateSplitWindow(d / l.Radius) : 1.0;
      sum += l.Color * EvaluateAttenuation(d, l.Attenuation) * w * ShadeValue(smp, v / d);
      ++count;
    }
  }
  return sum;
}

int Quantize(double v)
{
  return static_cast<int>(std::lround(255.0 * std::min(1.0, std::max(0.0, v))));
}

struct Errors
{
  double Max = 0, Mean = 0, RMSE = 0, ContinuousMean = 0, SignedMean = 0;
  std::size_t Count = 0, OverTwo = 0;
  void Add(const glm::dvec3& exact, const glm::dvec3& approx)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double q = std::abs(Quantize(exact[c]) - Quantize(approx[c]));
      const double clampedExact = std::min(1.0, std::max(0.0, exact[c]));
      const double clampedApprox = std::min(1.0, std::max(0.0, approx[c]));
      this->Max = std::max(this->Max, q);
      this->OverTwo += q > 2.0 ? 1 : 0;
      this->Mean += q;
      this->RMSE += q * q;
      this->ContinuousMean += 255.0 * std::abs(clampedExact - clampedApprox);
      this->SignedMean += 255.0 * (clampedApprox - clampedExact);
      ++this->Count;
    }
  }
  void Print(const char* name, double nearPerPoint, long long nodes, double extra = 0.0,
    const char* extraName = nullptr) const
  {
    std::printf("%-44s max %5.0f (>2: %zu)  mean %6.3f  RMSE %6.3f  (continuous mean %6.3f, "
                "signed %+6.3f)  near/pt %7.2f",
      name, this->Max, this->OverTwo, this->Mean / this->Count, std::sqrt(this->RMSE / this->Count),
      this->ContinuousMean / this->Count, this->SignedMean / this->Count, nearPerPoint);
    if (nodes > 0)
    {
      std::printf("  nodes %lld", nodes);
    }
    if (extraName)
    {
      std::printf("  %s %.1f", extraName, extra);
    }
    std::printf("\n");
  }
};

/// Runs f(i) for i in [0, n) on all hardware threads.
template <typename F>
void ParallelFor(std::size_t n, F f)
{
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
  {
    pool.emplace_back(
      [&, t]()
      {
        for (std::size_t i = t; i < n; i += threads)
        {
          f(i);
        }
      });
  }
  for (auto& th : pool)
  {
    th.join();
  }
}

/// Orders of the angular expansion the --worst analysis compares (the product: 2).
constexpr int StudyOrders[] = { 2, 4, 6, 8 };
constexpr int LargestStudyOrder = 8;

/// P_0(t)..P_L(t).
std::array<double, LargestStudyOrder + 1> EvaluateLegendre(double t)
{
  std::array<double, LargestStudyOrder + 1> p{};
  p[0] = 1.0;
  p[1] = t;
  for (std::size_t l = 2; l <= LargestStudyOrder; ++l)
  {
    const double n = static_cast<double>(l);
    p[l] = ((2.0 * n - 1.0) * t * p[l - 1] - (n - 1.0) * p[l - 2]) / n;
  }
  return p;
}

/// Legendre coefficients k_0..k_L of max(0, t)^n on [-1, 1] (n = 1: the clamped cosine),
/// k_l = (2l + 1) / 2 * integral of max(0, t)^n P_l(t) dt, by the midpoint rule.
std::array<double, LargestStudyOrder + 1> ComputeLegendreKernel(double n)
{
  std::array<double, LargestStudyOrder + 1> k{};
  const int steps = 20000;
  for (int i = 0; i < steps; ++i)
  {
    const double t = (i + 0.5) / steps; // the kernel is 0 for t < 0
    const double f = std::pow(t, n) / steps;
    const auto p = EvaluateLegendre(t);
    for (std::size_t l = 0; l <= LargestStudyOrder; ++l)
    {
      k[l] += f * p[l];
    }
  }
  for (std::size_t l = 0; l <= LargestStudyOrder; ++l)
  {
    k[l] *= 0.5 * (2.0 * static_cast<double>(l) + 1.0);
  }
  return k;
}

/// The 15 monomials u_x^a u_y^b u_z^c of degree 4 (a + b + c = 4) and their multinomial
/// coefficients 4! / (a! b! c!), for the fourth-order moments of the far light.
struct Degree4
{
  int A, B, C;
  double Coefficient;
};
const std::array<Degree4, 15>& GetDegree4()
{
  static const std::array<Degree4, 15> terms = []
  {
    std::array<Degree4, 15> t{};
    const double f[5] = { 1, 1, 2, 6, 24 };
    int n = 0;
    for (int a = 4; a >= 0; --a)
    {
      for (int b = 4 - a; b >= 0; --b)
      {
        const int c = 4 - a - b;
        t[static_cast<std::size_t>(n++)] = { a, b, c, f[4] / (f[a] * f[b] * f[c]) };
      }
    }
    return t;
  }();
  return terms;
}

/// Exact fourth-order moments of the far light at every node (45 per node: 15 per channel,
/// sum g colour u^a), by brute force over the lights: the experiment of an order-4 far
/// diffuse through the grid (--order4-grid; not the product's). Stored as two node arrays
/// of FarFieldFloatsPerNode values each (the first 27 moments, then the other 18 and 9
/// zeros), so that InterpolateFarMoments interpolates them as the shader would.
std::array<std::vector<double>, 2> ComputeDegree4Nodes(const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& radii)
{
  const std::size_t nodes = static_cast<std::size_t>(grid.GetNumberOfNodes());
  std::array<std::vector<double>, 2> out;
  out[0].assign(nodes * FarFieldFloatsPerNode, 0.0);
  out[1].assign(nodes * FarFieldFloatsPerNode, 0.0);
  const auto& terms = GetDegree4();
  ParallelFor(static_cast<std::size_t>(grid.Dims[2]),
    [&](std::size_t k)
    {
      for (int j = 0; j < grid.Dims[1]; ++j)
      {
        for (int i = 0; i < grid.Dims[0]; ++i)
        {
          const glm::dvec3 p = grid.NodePosition(i, j, static_cast<int>(k));
          const std::size_t node =
            static_cast<std::size_t>(grid.NodeIndex(i, j, static_cast<int>(k)));
          double m[45] = {};
          for (std::size_t l = 0; l < lights.size(); ++l)
          {
            double far;
            glm::dvec3 u;
            if (!ComputeFarContribution(lights[l], radii[l], p, far, u))
            {
              continue;
            }
            const double px[5] = { 1, u.x, u.x * u.x, u.x * u.x * u.x, u.x * u.x * u.x * u.x };
            const double py[5] = { 1, u.y, u.y * u.y, u.y * u.y * u.y, u.y * u.y * u.y * u.y };
            const double pz[5] = { 1, u.z, u.z * u.z, u.z * u.z * u.z, u.z * u.z * u.z * u.z };
            for (std::size_t t = 0; t < terms.size(); ++t)
            {
              const double mono = far * px[terms[t].A] * py[terms[t].B] * pz[terms[t].C];
              for (int c = 0; c < 3; ++c)
              {
                m[static_cast<std::size_t>(c) * 15 + t] += lights[l].Color[c] * mono;
              }
            }
          }
          for (std::size_t q = 0; q < 45; ++q)
          {
            out[q / FarFieldFloatsPerNode]
               [node * FarFieldFloatsPerNode + q % FarFieldFloatsPerNode] = m[q];
          }
        }
      }
    });
  return out;
}

/// The far diffuse at order 4 from interpolated order-2 moments g and fourth-order ones
/// (ComputeDegree4Nodes, interpolated by InterpolateFarMoments): the order-2 estimate plus
/// k4 sum g P4(N.u), k4 = -3/32 for max(0, t), clamped into the order-2 interval.
glm::dvec3 EvaluateFarDiffuseOrder4(const std::array<double, FarFieldFloatsPerNode>& g,
  const FarFieldGrid& grid, const std::array<std::vector<double>, 2>& band4, const glm::dvec3& P,
  const glm::dvec3& N)
{
  const std::array<double, FarFieldFloatsPerNode> parts[2] = {
    InterpolateFarMoments(grid, band4[0], P), InterpolateFarMoments(grid, band4[1], P)
  };
  auto m4 = [&](std::size_t q)
  { return parts[q / FarFieldFloatsPerNode][q % FarFieldFloatsPerNode]; };
  const auto& terms = GetDegree4();
  const glm::dvec3 k = ComputeLobeKernel(1.0);
  glm::dvec3 out(0.0);
  for (int c = 0; c < 3; ++c)
  {
    const double* mc = &g[static_cast<std::size_t>(c) * FarFieldMomentsPerChannel];
    const double S = mc[0];
    double VN = 0.0, NTN = 0.0;
    ContractMoments(mc, N, VN, NTN);
    double N4 = 0.0;
    for (std::size_t q = 0; q < terms.size(); ++q)
    {
      N4 += terms[q].Coefficient * std::pow(N.x, terms[q].A) * std::pow(N.y, terms[q].B) *
        std::pow(N.z, terms[q].C) * m4(static_cast<std::size_t>(c) * 15 + q);
    }
    const double estimate = k.x * S + k.y * VN + k.z * 0.5 * (3.0 * NTN - S) +
      (-3.0 / 32.0) * (35.0 * N4 - 30.0 * NTN + 3.0 * S) / 8.0;
    double low = 0.0, high = 0.0;
    ComputeMomentInterval(S, VN, NTN, false, 1.0, low, high);
    out[c] = std::min(std::max(estimate, low), high);
  }
  return out;
}

/**
 * Where the far field's error comes from at the `count` samples of largest error (8-bit
 * steps, worst channel), and on average over all samples: the far parts shaded exactly
 * (the truth), the kernels applied to the exact moments at the point (the angular
 * truncation's share) and to the grid's interpolated moments (the grid's and the
 * grouping's share), diffuse and specular apart, in steps of that channel.
 */
void PrintWorstSamples(const std::vector<Sample>& samples, const std::vector<glm::dvec3>& exact,
  const std::vector<glm::dvec3>& approx, const std::vector<PreparedLight>& lights,
  const std::vector<double>& radii, const FarFieldGrid& grid, const std::vector<double>& values,
  int count, bool orders, const std::array<std::vector<double>, 2>* band4 = nullptr)
{
  struct Parts
  {
    glm::dvec3 TrueD{ 0.0 }, TrueS{ 0.0 }, PointD{ 0.0 }, PointS{ 0.0 }, GridD{ 0.0 }, GridS{ 0.0 };
    glm::dvec3 GridD4{ 0.0 };       ///< --order4-grid: the order-4 diffuse through the grid
    double Largest = 0.0;           ///< the largest single far part (unit colour, before shading)
    double Total = 0.0;             ///< the sum of far parts (unit colour)
    int Brightest = -1;             ///< the light of the largest far part
    double BrightestDistance = 0.0; ///< its distance over its near radius
    double GridSError = 0.0;        ///< (interpolated - exact) S at the point, over exact S
    double GridVNError = 0.0;       ///< (interpolated - exact) V.N at the point, over exact S
    /// Per order of StudyOrders: sum_l k_l sum_j g_j P_l(t_j), the kernels applied to the
    /// exact moments of that order at the point, clamped into the order-2 interval (which
    /// holds the truth whatever the order), diffuse and specular.
    std::array<glm::dvec3, std::size(StudyOrders)> OrderD{}, OrderS{};
  };
  std::vector<Parts> parts(samples.size());
  // The kernels' Legendre coefficients, per specular power of the samples.
  std::map<double, std::array<double, LargestStudyOrder + 1>> lobeKernels;
  const auto diffuseKernel = ComputeLegendreKernel(1.0);
  for (const Sample& smp : samples)
  {
    if (orders && !lobeKernels.count(smp.Power))
    {
      lobeKernels[smp.Power] = ComputeLegendreKernel(smp.Power);
    }
  }
  ParallelFor(samples.size(),
    [&](std::size_t i)
    {
      const Sample& smp = samples[i];
      const glm::dvec3 R = 2.0 * glm::dot(smp.N, smp.V) * smp.N - smp.V;
      Parts& q = parts[i];
      std::array<double, FarFieldFloatsPerNode> m{};
      // sum_j g_j colour_j P_l(t_j) for t = N.u and t = R.u, each order l.
      std::array<glm::dvec3, LargestStudyOrder + 1> sumN{}, sumR{};
      for (std::size_t l = 0; l < lights.size(); ++l)
      {
        double far;
        glm::dvec3 u;
        if (ComputeFarContribution(lights[l], radii[l], smp.P, far, u))
        {
          if (orders)
          {
            const auto pn = EvaluateLegendre(glm::dot(smp.N, u));
            const auto pr = EvaluateLegendre(glm::dot(R, u));
            for (std::size_t o = 0; o <= LargestStudyOrder; ++o)
            {
              sumN[o] += lights[l].Color * far * pn[o];
              sumR[o] += lights[l].Color * far * pr[o];
            }
          }
          const glm::dvec2 sh = Shade(smp, u);
          q.TrueD += lights[l].Color * far * sh.x;
          q.TrueS += lights[l].Color * far * sh.y;
          AccumulateFarMoments(lights[l].Color, far, u, m.data());
          q.Total += far;
          if (far > q.Largest)
          {
            q.Largest = far;
            q.Brightest = static_cast<int>(l);
            q.BrightestDistance = glm::length(lights[l].PositionWC - smp.P) / radii[l];
          }
        }
      }
      q.PointD = EvaluateFarDiffuse(m, smp.N);
      q.PointS = smp.Ks > 0.0 ? EvaluateFarSpecular(m, smp.N, R, smp.Power) : glm::dvec3(0.0);
      if (orders)
      {
        const auto& kd = diffuseKernel;
        const auto& ks = lobeKernels.at(smp.Power);
        for (int c = 0; c < 3; ++c)
        {
          // The order-2 interval of the exact moments holds the truth at every order.
          const double* mc = &m[static_cast<std::size_t>(c) * FarFieldMomentsPerChannel];
          double lowD = 0.0, highD = 0.0, lowS = 0.0, highS = 0.0;
          ApplyMomentKernel(mc, ComputeLobeKernel(1.0), smp.N, false, 1.0, &lowD, &highD);
          ApplyMomentKernel(mc, ComputeLobeKernel(smp.Power), R, true, smp.Power, &lowS, &highS);
          for (std::size_t o = 0; o < std::size(StudyOrders); ++o)
          {
            double d = 0.0, sp = 0.0;
            for (int l = 0; l <= StudyOrders[o]; ++l)
            {
              d += kd[static_cast<std::size_t>(l)] * sumN[static_cast<std::size_t>(l)][c];
              sp += ks[static_cast<std::size_t>(l)] * sumR[static_cast<std::size_t>(l)][c];
            }
            q.OrderD[o][c] = std::min(std::max(d, lowD), highD);
            q.OrderS[o][c] = smp.Ks > 0.0 ? std::min(std::max(sp, lowS), highS) : 0.0;
          }
        }
      }
      const auto g = InterpolateFarMoments(grid, values, smp.P);
      q.GridD = EvaluateFarDiffuse(g, smp.N);
      if (band4)
      {
        q.GridD4 = EvaluateFarDiffuseOrder4(g, grid, *band4, smp.P, smp.N);
      }
      q.GridS = smp.Ks > 0.0 ? EvaluateFarSpecular(g, smp.N, R, smp.Power) : glm::dvec3(0.0);
      double total = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        const std::size_t o = static_cast<std::size_t>(c) * FarFieldMomentsPerChannel;
        total += m[o];
        q.GridSError += g[o] - m[o];
        for (int a = 0; a < 3; ++a)
        {
          q.GridVNError += (g[o + 1 + a] - m[o + 1 + a]) * smp.N[a];
        }
      }
      q.GridSError = total > 0.0 ? q.GridSError / total : 0.0;
      q.GridVNError = total > 0.0 ? q.GridVNError / total : 0.0;
    });
  // One pass over the samples: their image errors (for the worst), each share's mean
  // |error|, the grid's relative errors, and the image error with one share removed: the
  // far specular exact, the far diffuse kernel exact, and both (only the grid's
  // interpolation and grouping left).
  std::vector<std::pair<int, std::size_t>> order;
  double kernelD = 0.0, kernelS = 0.0, gridD = 0.0, gridS = 0.0, sError = 0.0, vnError = 0.0;
  Errors perfectSpecular, perfectDiffuseKernel, onlyGrid, grid4, grid4SpecularExact;
  std::array<Errors, std::size(StudyOrders)> byOrder, byOrderSpecularExact;
  std::array<double, std::size(StudyOrders)> orderKernelD{}, orderKernelS{};
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const Sample& smp = samples[i];
    const Parts& p = parts[i];
    int q = 0;
    for (int c = 0; c < 3; ++c)
    {
      q = std::max(q, std::abs(Quantize(exact[i][c]) - Quantize(approx[i][c])));
      kernelD += std::abs(p.PointD[c] - p.TrueD[c]) * smp.Kd[c];
      kernelS += std::abs(p.PointS[c] - p.TrueS[c]) * smp.Ks;
      gridD += std::abs(p.GridD[c] - p.PointD[c]) * smp.Kd[c];
      gridS += std::abs(p.GridS[c] - p.PointS[c]) * smp.Ks;
    }
    order.emplace_back(q, i);
    sError += p.GridSError;
    vnError += p.GridVNError;
    const glm::dvec3 nearPart = approx[i] - p.GridD * smp.Kd - p.GridS * smp.Ks;
    const glm::dvec3 diffuseKernelExact = (p.GridD - p.PointD + p.TrueD) * smp.Kd;
    perfectSpecular.Add(exact[i], nearPart + p.GridD * smp.Kd + p.TrueS * smp.Ks);
    perfectDiffuseKernel.Add(exact[i], nearPart + diffuseKernelExact + p.GridS * smp.Ks);
    onlyGrid.Add(exact[i], nearPart + diffuseKernelExact + (p.GridS - p.PointS + p.TrueS) * smp.Ks);
    if (band4)
    {
      grid4.Add(exact[i], nearPart + p.GridD4 * smp.Kd + p.GridS * smp.Ks);
      grid4SpecularExact.Add(exact[i], nearPart + p.GridD4 * smp.Kd + p.TrueS * smp.Ks);
    }
    for (std::size_t o = 0; orders && o < std::size(StudyOrders); ++o)
    {
      // The grid's and the grouping's share as measured at order 2, the kernels' at order o.
      byOrder[o].Add(exact[i],
        nearPart + (p.GridD - p.PointD + p.OrderD[o]) * smp.Kd +
          (p.GridS - p.PointS + p.OrderS[o]) * smp.Ks);
      byOrderSpecularExact[o].Add(
        exact[i], nearPart + (p.GridD - p.PointD + p.OrderD[o]) * smp.Kd + p.TrueS * smp.Ks);
      for (int c = 0; c < 3; ++c)
      {
        orderKernelD[o] += std::abs(p.OrderD[o][c] - p.TrueD[c]) * smp.Kd[c];
        orderKernelS[o] += std::abs(p.OrderS[o][c] - p.TrueS[c]) * smp.Ks;
      }
    }
  }
  for (std::size_t o = 0; orders && o < std::size(StudyOrders); ++o)
  {
    char name[96];
    std::snprintf(name, sizeof(name), "    kernels of order %d, clamped", StudyOrders[o]);
    byOrder[o].Print(name, 0.0, 0);
    std::snprintf(name, sizeof(name), "      the diffuse's alone, far specular exact");
    byOrderSpecularExact[o].Print(name, 0.0, 0);
    std::printf("      mean |kernel error| in steps: diffuse %.3f, specular %.3f\n",
      orderKernelD[o] * 255.0 / (3.0 * samples.size()),
      orderKernelS[o] * 255.0 / (3.0 * samples.size()));
  }
  if (band4)
  {
    grid4.Print("    order-4 diffuse through the grid", 0.0, 0);
    grid4SpecularExact.Print("      and the far specular exact", 0.0, 0);
  }
  perfectSpecular.Print("    far specular exact", 0.0, 0);
  perfectDiffuseKernel.Print("    far diffuse kernel exact", 0.0, 0);
  onlyGrid.Print("    both kernels exact (grid only)", 0.0, 0);
  std::printf("    the grid's mean relative error at the points: S %+.3f%%, V.N %+.3f%% of S\n",
    100.0 * sError / parts.size(), 100.0 * vnError / parts.size());
  const double per = 255.0 / (3.0 * samples.size());
  std::printf("    mean |error| in steps: kernel diffuse %.3f, kernel specular %.3f, grid diffuse "
              "%.3f, grid specular %.3f\n",
    kernelD * per, kernelS * per, gridD * per, gridS * per);
  std::sort(order.begin(), order.end(), std::greater<std::pair<int, std::size_t>>());
  for (int w = 0; w < count && w < static_cast<int>(order.size()); ++w)
  {
    const std::size_t i = order[static_cast<std::size_t>(w)].second;
    const Sample& smp = samples[i];
    const Parts& p = parts[i];
    int c = 0;
    for (int k = 1; k < 3; ++k)
    {
      c = std::abs(approx[i][k] - exact[i][k]) > std::abs(approx[i][c] - exact[i][c]) ? k : c;
    }
    const double kd = smp.Kd[c] * 255.0, ks = smp.Ks * 255.0;
    std::printf("    #%d err %d (ch %d): exact %.2f approx %.2f | far diffuse true %.2f point "
                "%.2f grid %.2f | far specular (n %g) true %.2f point %.2f grid %.2f | far "
                "total %.3g, largest %.3g at d/r %.2f, N.L %.2f\n",
      w, order[static_cast<std::size_t>(w)].first, c, 255.0 * exact[i][c], 255.0 * approx[i][c],
      kd * p.TrueD[c], kd * p.PointD[c], kd * p.GridD[c], smp.Power, ks * p.TrueS[c],
      ks * p.PointS[c], ks * p.GridS[c], p.Total, p.Largest, p.BrightestDistance,
      p.Brightest >= 0
        ? glm::dot(
            smp.N, glm::normalize(lights[static_cast<std::size_t>(p.Brightest)].PositionWC - smp.P))
        : 0.0);
  }
}

/**
 * --specular-bins K1,K2,...: the far specular from K directional bins per node
 * (SpecularBinsStudy.h), each bin's light summed exactly at every node (brute force over
 * the lights) and interpolated trilinearly, against the product's far specular, with the
 * product's far diffuse and near parts unchanged; also the bins summed at the point itself
 * (the bins' angular error without the grid's).
 */
void PrintSpecularBins(const std::vector<Sample>& samples, const std::vector<glm::dvec3>& exact,
  const std::vector<glm::dvec3>& approx, const std::vector<PreparedLight>& lights,
  const std::vector<double>& radii, const FarFieldGrid& grid, const std::vector<double>& values,
  const std::vector<double>& binCounts, const std::vector<float>& productBins, bool eachPoint)
{
  std::vector<SpecularBinTable> tables;
  for (double k : binCounts)
  {
    tables.emplace_back(static_cast<int>(k));
  }
  const std::size_t nodes = static_cast<std::size_t>(grid.GetNumberOfNodes());
  std::vector<std::vector<double>> nodeBins(tables.size());
  for (std::size_t s = 0; s < tables.size(); ++s)
  {
    nodeBins[s].assign(nodes * tables[s].Count() * SpecularBinFloats, 0.0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  ParallelFor(static_cast<std::size_t>(grid.Dims[2]),
    [&](std::size_t k)
    {
      for (int j = 0; j < grid.Dims[1]; ++j)
      {
        for (int i = 0; i < grid.Dims[0]; ++i)
        {
          const glm::dvec3 p = grid.NodePosition(i, j, static_cast<int>(k));
          const std::size_t node =
            static_cast<std::size_t>(grid.NodeIndex(i, j, static_cast<int>(k)));
          for (std::size_t l = 0; l < lights.size(); ++l)
          {
            double far;
            glm::dvec3 u;
            if (ComputeFarContribution(lights[l], radii[l], p, far, u))
            {
              for (std::size_t s = 0; s < tables.size(); ++s)
              {
                AddToSpecularBins(tables[s], lights[l].Color, far, u,
                  &nodeBins[s][node * tables[s].Count() * SpecularBinFloats]);
              }
            }
          }
        }
      }
    });
  std::printf("    specular bins summed at the nodes in %.1f s (brute force)\n",
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  struct Parts
  {
    glm::dvec3 TrueS{ 0.0 }, GridD{ 0.0 }, GridS{ 0.0 }, Product{ 0.0 }, ProductOnExact{ 0.0 };
    std::vector<glm::dvec3> PointBins, GridBins, GridShared;
  };
  std::vector<Parts> parts(samples.size());
  ParallelFor(samples.size(),
    [&](std::size_t i)
    {
      const Sample& smp = samples[i];
      Parts& q = parts[i];
      if (!(smp.Ks > 0.0))
      {
        q.PointBins.assign(tables.size(), glm::dvec3(0.0));
        q.GridBins = q.PointBins;
        q.GridShared = q.PointBins;
        const auto g = InterpolateFarMoments(grid, values, smp.P);
        q.GridD = EvaluateFarDiffuse(g, smp.N);
        return;
      }
      const glm::dvec3 R = 2.0 * glm::dot(smp.N, smp.V) * smp.N - smp.V;
      std::vector<std::vector<double>> pointBins(tables.size());
      for (std::size_t s = 0; s < tables.size(); ++s)
      {
        pointBins[s].assign(tables[s].Count() * SpecularBinFloats, 0.0);
      }
      for (std::size_t l = 0; l < lights.size(); ++l)
      {
        double far;
        glm::dvec3 u;
        if (ComputeFarContribution(lights[l], radii[l], smp.P, far, u))
        {
          q.TrueS += lights[l].Color * far * Shade(smp, u).y;
          for (std::size_t s = 0; s < tables.size(); ++s)
          {
            AddToSpecularBins(tables[s], lights[l].Color, far, u, pointBins[s].data());
          }
        }
      }
      const auto g = InterpolateFarMoments(grid, values, smp.P);
      q.GridD = EvaluateFarDiffuse(g, smp.N);
      q.GridS = EvaluateFarSpecular(g, smp.N, R, smp.Power);
      const auto pb = InterpolateFarSpecularBins(grid, productBins, smp.P);
      q.Product = EvaluateFarSpecular(g, smp.N, R, smp.Power, true, pb.data());
      glm::dvec3 low(0.0), high(0.0);
      for (int c = 0; c < 3; ++c)
      {
        ApplyFarLobe(&g[static_cast<std::size_t>(c) * FarFieldMomentsPerChannel], smp.N, R,
          smp.Power, &low[c], &high[c]);
      }
      for (std::size_t s = 0; s < tables.size(); ++s)
      {
        std::vector<double> gb(tables[s].Count() * SpecularBinFloats);
        InterpolateNodeValues(grid, nodeBins[s], gb.size(), smp.P, gb.data());
        q.PointBins.push_back(glm::clamp(
          EvaluateSpecularBins(tables[s], pointBins[s].data(), smp.N, R, smp.Power), low, high));
        q.GridBins.push_back(
          glm::clamp(EvaluateSpecularBins(tables[s], gb.data(), smp.N, R, smp.Power), low, high));
        q.GridShared.push_back(
          glm::clamp(EvaluateSpecularBinsSharedDirection(tables[s], gb.data(), smp.N, R, smp.Power),
            low, high));
        if (tables[s].Count() == FarSpecularBins)
        {
          // The same cells in the same order: the product's evaluation of these bins.
          double pbins[FarSpecularFloatsPerNode];
          for (int b = 0; b < FarSpecularBins; ++b)
          {
            const double* from = &gb[static_cast<std::size_t>(b) * SpecularBinFloats];
            double* to = pbins + b * FarSpecularBinFloats;
            for (int c = 0; c < 3; ++c)
            {
              to[c] = from[4 * c];
              to[3 + c] = from[1 + c] + from[5 + c] + from[9 + c];
            }
          }
          q.ProductOnExact =
            glm::clamp(EvaluateFarSpecularBins(pbins, smp.N, R, smp.Power), low, high);
        }
      }
    });
  const double per = 255.0 / (3.0 * samples.size());
  Errors product, productExact;
  double productKernel = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const Parts& p = parts[i];
    const glm::dvec3 rest = approx[i] - p.GridS * samples[i].Ks;
    product.Add(exact[i], approx[i]);
    productExact.Add(exact[i], rest + p.TrueS * samples[i].Ks);
    for (int c = 0; c < 3; ++c)
    {
      productKernel += std::abs(p.GridS[c] - p.TrueS[c]) * samples[i].Ks;
    }
  }
  Errors productBinsErrors;
  double productBinsKernel = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const Parts& p = parts[i];
    const glm::dvec3 withBins = approx[i] + (p.Product - p.GridS) * samples[i].Ks;
    productBinsErrors.Add(exact[i], withBins);
    for (int c = 0; c < 3; ++c)
    {
      productBinsKernel += std::abs(p.Product[c] - p.TrueS[c]) * samples[i].Ks;
    }
    if (eachPoint)
    {
      // --at: each point's error in steps, per channel, with the moments and with the bins.
      const glm::dvec3 a = 255.0 * (approx[i] - exact[i]), b = 255.0 * (withBins - exact[i]);
      const glm::dvec3 t = 255.0 * samples[i].Ks * p.TrueS, g = 255.0 * samples[i].Ks * p.GridS,
                       q = 255.0 * samples[i].Ks * p.Product;
      std::printf("    point %zu: exact (%.2f, %.2f, %.2f)\n", i, 255.0 * exact[i].x,
        255.0 * exact[i].y, 255.0 * exact[i].z);
      std::printf("    point %zu: error with the moments (%+.2f, %+.2f, %+.2f), with the bins "
                  "(%+.2f, %+.2f, %+.2f); far specular true (%.2f, %.2f, %.2f), moments (%.2f, "
                  "%.2f, %.2f), bins (%.2f, %.2f, %.2f)\n",
        i, a.x, a.y, a.z, b.x, b.y, b.z, t.x, t.y, t.z, g.x, g.y, g.z, q.x, q.y, q.z);
    }
  }
  productBinsErrors.Print("    the product's bins (tree build)", 0.0, 0);
  Errors onExact;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    onExact.Add(exact[i], approx[i] + (parts[i].ProductOnExact - parts[i].GridS) * samples[i].Ks);
  }
  onExact.Print("    the product's evaluation, exact bins", 0.0, 0);
  std::printf("      mean |far specular error| %.3f steps\n", productBinsKernel * per);
  product.Print("    the product's far specular", 0.0, 0);
  std::printf("      mean |far specular error| %.3f steps\n", productKernel * per);
  productExact.Print("    the far specular exact", 0.0, 0);
  for (std::size_t s = 0; s < tables.size(); ++s)
  {
    Errors point, grid2, shared;
    double pointError = 0.0, gridError = 0.0, gridSigned = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      const Parts& p = parts[i];
      const glm::dvec3 rest = approx[i] - p.GridS * samples[i].Ks;
      point.Add(exact[i], rest + p.PointBins[s] * samples[i].Ks);
      grid2.Add(exact[i], rest + p.GridBins[s] * samples[i].Ks);
      shared.Add(exact[i], rest + p.GridShared[s] * samples[i].Ks);
      for (int c = 0; c < 3; ++c)
      {
        pointError += std::abs(p.PointBins[s][c] - p.TrueS[c]) * samples[i].Ks;
        gridError += std::abs(p.GridBins[s][c] - p.TrueS[c]) * samples[i].Ks;
        gridSigned += (p.GridBins[s][c] - p.TrueS[c]) * samples[i].Ks;
      }
    }
    char name[96];
    std::snprintf(name, sizeof(name), "    %zu bins, summed at the point", tables[s].Count());
    point.Print(name, 0.0, 0);
    std::snprintf(name, sizeof(name), "    %zu bins, through the grid", tables[s].Count());
    grid2.Print(name, 0.0, 0);
    std::snprintf(name, sizeof(name), "    %zu bins, one direction per bin", tables[s].Count());
    shared.Print(name, 0.0, 0);
    std::printf("      mean |far specular error| %.3f steps at the point, %.3f through the grid "
                "(signed %+.3f)\n",
      pointError * per, gridError * per, gridSigned * per);
  }
}
}

int main(int argc, char* argv[])
{
  std::string sceneName = "bunny";
  int lightsCount = 4096, samplesCount = 20000;
  std::vector<double> cutoffs = { 1.0 / 1024, 1.0 / 4096 };
  std::vector<double> nodeTargets = { 32768 };
  std::vector<double> cellsPerRadius = { 2.0 };
  std::vector<double> groupings = { 0.05 };
  std::vector<double> hierarchyEpsilons;
  std::vector<double> blockTolerances;
  bool orders = false;
  bool order4Grid = false;
  bool bounds = false;
  bool farCutoffs = false;
  bool copies = false;
  int worst = -1;
  std::vector<double> specularBins;
  std::vector<double> atPoints;
  std::vector<double> atNormals;
  bool passRegion = false;
  double intensity = -1.0;
  auto parseList = [](const char* text, double (*f)(double))
  {
    std::vector<double> out;
    for (const char* c = text; *c; ++c)
    {
      out.push_back(f(std::strtod(c, const_cast<char**>(&c))));
      if (!*c)
      {
        break;
      }
    }
    return out;
  };
  auto same = [](double v) { return v; };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--scene" && value)
    {
      sceneName = argv[++i];
    }
    else if (a == "--lights" && value)
    {
      lightsCount = std::atoi(argv[++i]);
    }
    else if (a == "--samples" && value)
    {
      samplesCount = std::atoi(argv[++i]);
    }
    else if (a == "--cutoffs" && value)
    {
      cutoffs = parseList(argv[++i], [](double v) { return 1.0 / v; });
    }
    else if (a == "--nodes" && value)
    {
      nodeTargets = parseList(argv[++i], same);
    }
    else if (a == "--cells" && value)
    {
      cellsPerRadius = parseList(argv[++i], same);
    }
    else if (a == "--grouping" && value)
    {
      groupings = parseList(argv[++i], same);
    }
    else if (a == "--hierarchy" && value)
    {
      hierarchyEpsilons = parseList(argv[++i], same);
    }
    else if (a == "--orders")
    {
      orders = true;
    }
    else if (a == "--order4-grid")
    {
      order4Grid = true;
    }
    else if (a == "--blocks" && value)
    {
      blockTolerances = parseList(argv[++i], [](double v) { return 1.0 / v; });
    }
    else if (a == "--always-on")
    {
      // 300 of VTK's default lights: attenuation (1, 0, 0), intensity 1, white.
      sceneName += "+always-on";
    }
    else if (a == "--bounds")
    {
      bounds = true;
    }
    else if (a == "--far-cutoffs")
    {
      farCutoffs = true;
    }
    else if (a == "--copies")
    {
      copies = true;
    }
    else if (a == "--intensity" && value)
    {
      // Every light's intensity (the benchmark's always-on layout: 0.005).
      intensity = std::atof(argv[++i]);
    }
    else if (a == "--specular-bins" && value)
    {
      specularBins = parseList(argv[++i], same);
    }
    else if (a == "--worst" && value)
    {
      worst = std::atoi(argv[++i]);
    }
    else if (a == "--at" && value)
    {
      atPoints = parseList(argv[++i], same);
      passRegion = true;
    }
    else if (a == "--at-normals" && value)
    {
      atNormals = parseList(argv[++i], same);
    }
    else if (a == "--pass-region")
    {
      passRegion = true;
    }
    else
    {
      std::fprintf(stderr, "unknown or incomplete option %s\n", a.c_str());
      return EXIT_FAILURE;
    }
  }
  if (atPoints.size() % 3 != 0)
  {
    std::fprintf(stderr, "--at takes x,y,z triples\n");
    return EXIT_FAILURE;
  }
  if (cutoffs.empty() || nodeTargets.empty() || cellsPerRadius.empty())
  {
    std::fprintf(stderr, "--cutoffs, --nodes and --cells need at least one value\n");
    return EXIT_FAILURE;
  }
  Context ctx(1024, 768);
  const Scene& scene = sceneName.rfind("house", 0) == 0 ? HouseScene() : BunnyScene();
  if (ctx.LoadScene(scene, true) < 0)
  {
    std::fprintf(stderr, "scene data missing\n");
    return EXIT_FAILURE;
  }
  ctx.MakeLights(lightsCount, "uniform");
  vtkClusteredLightSet* set = ctx.GetLights();
  if (sceneName.rfind("user", 0) == 0)
  {
    // 4,096 lights as a new user writes them: attenuation (0, 0, 20), intensity 0.02.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (vtkIdType i = 0; i < set->GetNumberOfLights(); ++i)
    {
      set->SetIntensity(i, 0.02);
      set->SetAttenuation(i, 0.0, 0.0, 20.0);
    }
  }
  if (sceneName.rfind("dense", 0) == 0)
  {
    // 2,000 lights as a new user writes them: attenuation (1, 0, 8), intensity 1, no radius.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    set->SetNumberOfLights(2000);
    for (vtkIdType i = 0; i < 2000; ++i)
    {
      set->SetPosition(i, -3 + 6 * U(rng), -0.98 + 2.0 * U(rng), -3 + 6 * U(rng));
      set->SetColor(i, U(rng), U(rng), U(rng));
      set->SetIntensity(i, 1.0);
      set->SetAttenuation(i, 1.0, 0.0, 8.0);
    }
  }
  if (sceneName.find("+always-on") != std::string::npos)
  {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    set->SetNumberOfLights(300);
    for (vtkIdType i = 0; i < 300; ++i)
    {
      set->SetPosition(i, -3 + 6 * U(rng), -0.98 + 2.0 * U(rng), -3 + 6 * U(rng));
      set->SetColor(i, 1, 1, 1);
      set->SetIntensity(i, 1.0);
      set->SetAttenuation(i, 1.0, 0.0, 0.0);
    }
  }
  if (sceneName.rfind("ball", 0) == 0)
  {
    // Examples/Python/user_lights.py's scene and lights (intensity 0.02 before --intensity).
    ctx.GetRenderer()->RemoveAllViewProps();
    ClusteredLightingScenes::AddBallScene(ctx.GetRenderer());
    ClusteredLightingScenes::MakeBallLights(set, lightsCount, 0.02, nullptr);
    double first[3] = { 0.0, 0.0, 0.0 };
    if (lightsCount > 0)
    {
      set->GetPosition(0, first);
    }
    std::printf("ball: first light at (%.6f, %.6f, %.6f)\n", first[0], first[1], first[2]);
  }
  if (intensity >= 0.0)
  {
    for (vtkIdType i = 0; i < set->GetNumberOfLights(); ++i)
    {
      set->SetIntensity(i, intensity);
    }
  }
  if (sceneName.rfind("ball", 0) != 0)
  {
    ctx.SetView(); // the ball's camera is the example's
  }
  std::vector<LightSource> sources(static_cast<std::size_t>(set->GetNumberOfLights()));
  for (vtkIdType i = 0; i < set->GetNumberOfLights(); ++i)
  {
    LightSource& s = sources[static_cast<std::size_t>(i)];
    double v[3];
    set->GetPosition(i, v);
    s.PositionWC = glm::dvec3(v[0], v[1], v[2]);
    set->GetColor(i, v);
    s.Color = glm::dvec3(v[0], v[1], v[2]);
    s.Intensity = set->GetIntensity(i);
    set->GetAttenuation(i, v);
    s.Attenuation = glm::dvec3(v[0], v[1], v[2]);
  }
  std::vector<Sample> samples;
  if (atPoints.empty())
  {
    samples = SampleSurfaces(ctx.GetRenderer(), samplesCount, 3);
  }
  else
  {
    std::vector<glm::dvec3> points;
    for (std::size_t k = 0; k < atPoints.size(); k += 3)
    {
      points.emplace_back(atPoints[k], atPoints[k + 1], atPoints[k + 2]);
    }
    samples = SampleSurfacesAt(ctx.GetRenderer(), points);
    for (std::size_t k = 0; k + 2 < atNormals.size() && k / 3 < samples.size(); k += 3)
    {
      samples[k / 3].N =
        glm::normalize(glm::dvec3(atNormals[k], atNormals[k + 1], atNormals[k + 2]));
      std::printf("  sample %zu: normal (%.3f, %.3f, %.3f), N.V %.3f\n", k / 3, samples[k / 3].N.x,
        samples[k / 3].N.y, samples[k / 3].N.z, glm::dot(samples[k / 3].N, samples[k / 3].V));
    }
  }
  std::printf("scene %s: %zu lights, %zu surface samples\n", sceneName.c_str(), sources.size(),
    samples.size());

  // Exact values, and each light's contribution for reuse.
  const PreparedLights exactLights = PrepareLights(sources, LightPreparationOptions{ 1e-9, false });
  std::vector<glm::dvec3> exact(samples.size());
  ParallelFor(samples.size(),
    [&](std::size_t i)
    {
      const Sample& s = samples[i];
      glm::dvec3 sum(0.0);
      for (const PreparedLight& l : exactLights.Lights)
      {
        const glm::dvec3 v = l.PositionWC - s.P;
        const double d = glm::length(v);
        const glm::dvec2 sh = Shade(s, v / d);
        sum += l.Color * EvaluateAttenuation(d, l.Attenuation) * (sh.x * s.Kd + sh.y * s.Ks);
      }
      exact[i] = sum;
    });

  glm::dvec3 lo(1e300), hi(-1e300);
  if (passRegion)
  {
    // The pass's region: the visible props' bounds (vtkClusteredLightingPass).
    double b[6];
    ctx.GetRenderer()->ComputeVisiblePropBounds(b);
    lo = glm::dvec3(b[0], b[2], b[4]);
    hi = glm::dvec3(b[1], b[3], b[5]);
  }
  else
  {
    // The samples' box: the visible surfaces inside the frustum.
    for (const Sample& s : samples)
    {
      lo = glm::min(lo, s.P);
      hi = glm::max(hi, s.P);
    }
  }
  // The region as the pass adopts it: the box grown by FarFieldRegionMargin, the grid's
  // node planes through the box's lower corner (vtkClusteredLightingAssigner).
  const glm::dvec3 anchor = lo, grow = FarFieldRegionMargin * (hi - lo);
  lo -= grow;
  hi += grow;

  // Today: every light cut at its cutoff radius.
  for (double cutoff : cutoffs)
  {
    const PreparedLights prepared =
      PrepareLights(sources, LightPreparationOptions{ cutoff, false });
    Errors e;
    double near = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      glm::dvec3 sum(0.0);
      for (const PreparedLight& l : prepared.Lights)
      {
        const glm::dvec3 v = l.PositionWC - samples[i].P;
        const double d = glm::length(v);
        if (d < l.Radius)
        {
          sum += l.Color * EvaluateAttenuation(d, l.Attenuation) * ShadeValue(samples[i], v / d);
          near += 1.0;
        }
      }
      e.Add(exact[i], sum);
    }
    char name[128];
    std::snprintf(name, sizeof(name), "cut at 1/%g", 1.0 / cutoff);
    e.Print(name, near / samples.size(), 0);
  }

  // Design 1 (the product): near part exact, far field on the grid (PlanFarField,
  // ComputeFarFieldMoments), at the first cutoff (--far-cutoffs: at each).
  const PreparedLights base = PrepareLights(sources, LightPreparationOptions{ cutoffs[0], false });
  for (std::size_t ci = 0; ci < (farCutoffs ? cutoffs.size() : 1); ++ci)
  {
    const PreparedLights atCutoff =
      ci == 0 ? base : PrepareLights(sources, LightPreparationOptions{ cutoffs[ci], false });
    for (double target : nodeTargets)
    {
      for (double cells : cellsPerRadius)
      {
        for (double grouping : groupings)
        {
          std::vector<PreparedLight> lights = atCutoff.Lights;
          const FarFieldPlan plan = PlanFarField(lights, lo, hi,
            FarFieldOptions{ true, cells, static_cast<std::int64_t>(target), grouping }, anchor);
          const std::vector<double> radii = GetFarFieldNearRadii(lights);
          const FarFieldGrid& grid = plan.Grid;
          const auto t0 = std::chrono::steady_clock::now();
          const FarFieldLightTree tree = BuildFarFieldLightTree(lights, radii);
          std::vector<double> values(
            static_cast<std::size_t>(grid.GetNumberOfNodes()) * FarFieldFloatsPerNode);
          const std::array<int, 3> blocks = GetFarFieldBlocks(grid);
          const std::int64_t slab = static_cast<std::int64_t>(blocks[0]) * blocks[1];
          std::atomic<std::int64_t> pairs(0);
          ParallelFor(static_cast<std::size_t>(blocks[2]),
            [&](std::size_t k)
            {
              pairs += ComputeFarFieldMomentsForThisCPU(grid, lights, radii, tree, grouping,
                static_cast<std::int64_t>(k) * slab, static_cast<std::int64_t>(k + 1) * slab,
                values);
            });
          const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
              .count();
          // --specular-bins: the product's bins, built again with the moments and timed.
          std::vector<float> productBins;
          if (!specularBins.empty())
          {
            std::vector<double> again(values.size());
            productBins.assign(
              static_cast<std::size_t>(grid.GetNumberOfNodes()) * FarSpecularFloatsPerNode, 0.0f);
            const auto t1 = std::chrono::steady_clock::now();
            ParallelFor(static_cast<std::size_t>(blocks[2]),
              [&](std::size_t k)
              {
                ComputeFarFieldMomentsForThisCPU(grid, lights, radii, tree, grouping,
                  static_cast<std::int64_t>(k) * slab, static_cast<std::int64_t>(k + 1) * slab,
                  again, -1, true, &productBins);
              });
            std::printf("    build with the far specular's bins %.1f ms (without %.1f ms)\n",
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1)
                .count(),
              ms);
          }
          Errors e;
          std::vector<glm::dvec3> approx(samples.size());
          double near = 0.0, sumBound = 0.0, maxBound = 0.0, maxRatio = 0.0;
          std::size_t violations = 0;
          for (std::size_t i = 0; i < samples.size(); ++i)
          {
            const Sample& smp = samples[i];
            std::int64_t count = 0;
            glm::dvec3 sum = SumNearParts(lights, smp, count);
            near += static_cast<double>(count);
            if (plan.Active)
            {
              const auto m = InterpolateFarMoments(grid, values, smp.P);
              const glm::dvec3 R = 2.0 * glm::dot(smp.N, smp.V) * smp.N - smp.V;
              sum += EvaluateFarDiffuse(m, smp.N) * smp.Kd +
                (smp.Ks > 0.0 ? EvaluateFarSpecular(m, smp.N, R, smp.Power) * smp.Ks
                              : glm::dvec3(0.0));
              if (bounds)
              {
                // The stated bound per channel, against the actual (unrounded) error.
                FarFieldShadingPoint sp;
                sp.P = smp.P;
                sp.N = smp.N;
                sp.R = R;
                sp.Kd = smp.Kd;
                sp.Ks = glm::dvec3(smp.Ks);
                sp.Power = smp.Power;
                const glm::dvec3 b = ComputeFarFieldErrorBound(
                  sp, FarFieldBuildInputs{ &grid, &lights, &radii, &tree, grouping });
                for (int c = 0; c < 3; ++c)
                {
                  const double err = std::abs(sum[c] - exact[i][c]);
                  violations += err > b[c] * (1.0 + 1e-9) + 1e-12 ? 1 : 0;
                  maxRatio = std::max(maxRatio, b[c] > 0.0 ? err / b[c] : 0.0);
                  sumBound += 255.0 * b[c];
                  maxBound = std::max(maxBound, 255.0 * b[c]);
                }
              }
            }
            e.Add(exact[i], sum);
            approx[i] = sum;
          }
          if (worst >= 0 && plan.Active)
          {
            std::array<std::vector<double>, 2> band4;
            if (order4Grid)
            {
              band4 = ComputeDegree4Nodes(grid, lights, radii);
            }
            PrintWorstSamples(samples, exact, approx, lights, radii, grid, values, worst, orders,
              order4Grid ? &band4 : nullptr);
          }
          if (!specularBins.empty() && plan.Active)
          {
            PrintSpecularBins(samples, exact, approx, lights, radii, grid, values, specularBins,
              productBins, !atPoints.empty());
          }
          char name[160];
          if (farCutoffs)
          {
            std::snprintf(name, sizeof(name),
              "far field at 1/%g: %g nodes, h %.3g, r <= %g h, grouping %g", 1.0 / cutoffs[ci],
              target, grid.Spacing, cells, grouping);
          }
          else
          {
            std::snprintf(name, sizeof(name), "far field: %g nodes, h %.3g, r <= %g h, grouping %g",
              target, grid.Spacing, cells, grouping);
          }
          e.Print(name, near / samples.size(), grid.GetNumberOfNodes(), ms, "build ms");
          std::printf("    sources per node %.1f",
            static_cast<double>(pairs.load()) / std::max<std::int64_t>(grid.GetNumberOfNodes(), 1));
          if (copies)
          {
            // The same sums (the tree is built) in each copy, taking turns, best of 7 rounds.
            const FarFieldBuildCopy all[] = { FarFieldBuildCopy::Portable, FarFieldBuildCopy::AVX2,
              FarFieldBuildCopy::AVX512 };
            // Each copy also with the order-2 diffuse's sums (no fourth moments).
            double best[2][3] = { { 1e300, 1e300, 1e300 }, { 1e300, 1e300, 1e300 } };
            std::vector<double> scratch(values.size());
            for (int round = 0; round < 7; ++round)
            {
              for (int c = 0; c < 6; ++c)
              {
                if (!CanRunFarFieldBuildCopy(all[c % 3]))
                {
                  continue;
                }
                const auto c0 = std::chrono::steady_clock::now();
                ParallelFor(static_cast<std::size_t>(blocks[2]),
                  [&](std::size_t k)
                  {
                    ComputeFarFieldMomentsWith(all[c % 3], grid, lights, radii, tree, grouping,
                      static_cast<std::int64_t>(k) * slab, static_cast<std::int64_t>(k + 1) * slab,
                      scratch, -1, c < 3);
                  });
                double& b = best[c / 3][c % 3];
                b = std::min(b,
                  std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c0)
                    .count());
              }
            }
            std::printf("; node sums ms (best of 7, %u threads):",
              std::max(1u, std::thread::hardware_concurrency()));
            for (int c = 0; c < 3; ++c)
            {
              if (CanRunFarFieldBuildCopy(all[c]))
              {
                std::printf(" %s %.2f (order 2: %.2f)", GetFarFieldBuildCopyName(all[c]),
                  best[0][c], best[1][c]);
              }
            }
          }
          if (bounds)
          {
            std::printf("; bound per point and channel: mean %.3f, max %.3f steps; error / bound "
                        "<= %.3f; %zu above the bound",
              sumBound / (3.0 * samples.size()), maxBound, maxRatio, violations);
            if (plan.Active)
            {
              const FarFieldBoundSummary summary = SummarizeFarFieldErrorBound(
                FarFieldBuildInputs{ &grid, &lights, &radii, &tree, grouping });
              std::printf(
                "; the pass's summary over %d probes: %.3f steps", summary.Probes, summary.Max);
            }
          }
          std::printf("\n");
        }
      }
    }
  }

  // The exact far sums by blocks of 32 lights (FarBlocksStudy.h), at the first node target:
  // the lights in Morton order, as the pass stores them, split as the pass splits them.
  for (double tau : blockTolerances)
  {
    std::vector<PreparedLight> lights =
      PrepareLights(sources, LightPreparationOptions{ cutoffs[0], true }).Lights;
    PlanFarField(lights, lo, hi,
      FarFieldOptions{ true, cellsPerRadius[0], static_cast<std::int64_t>(nodeTargets[0]), 1.0 },
      anchor);
    const std::vector<ClusteredLightingStudy::FarBlock> blocks =
      ClusteredLightingStudy::ComputeFarBlocks(lights);
    std::size_t farLights = 0;
    for (const PreparedLight& l : lights)
    {
      farLights += l.FarField ? 1 : 0;
    }
    std::vector<double> work(samples.size()), error(samples.size());
    ParallelFor(samples.size(),
      [&](std::size_t i)
      {
        const Sample& smp = samples[i];
        const glm::dvec3 ks(smp.Ks);
        glm::dvec3 d, sp, de, se;
        ClusteredLightingStudy::FarBlockSumStatistics st;
        ClusteredLightingStudy::SumFarPartsByBlocks(
          lights, blocks, smp.P, smp.N, smp.V, smp.Power, smp.Kd, ks, tau, d, sp, &st);
        ClusteredLightingStudy::SumFarPartsExactly(lights, smp.P, smp.N, smp.V, smp.Power, de, se);
        se = smp.Ks > 0.0 ? se : glm::dvec3(0.0);
        const glm::dvec3 diff = glm::abs((d - de) * smp.Kd + (sp - se) * ks);
        error[i] = std::max(std::max(diff.x, diff.y), diff.z);
        work[i] = st.BlocksVisited + st.LightsSummed;
      });
    double meanWork = 0.0, worstError = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      meanWork += work[i] / samples.size();
      worstError = std::max(worstError, error[i]);
    }
    std::printf("blocks of 32, tolerance 1/%g: %.0f evaluations per point for %zu far-field "
                "lights (%.1f%%; %zu blocks), largest error %.3f of tolerance / 2\n",
      1.0 / tau, meanWork, farLights, 100.0 * meanWork / std::max<std::size_t>(farLights, 1),
      blocks.size(), worstError / (0.5 * tau));
  }

  // Design 2 (a light hierarchy evaluated per point, Lightcuts-style): the same near parts;
  // the far parts from the light tree walked at each point, a group taken as one light when
  // AcceptFarFieldGroup takes it with grouping `epsilon` (extent / distance), each taken
  // light shaded exactly. Its cost is the lights and groups evaluated per point.
  for (double epsilon : hierarchyEpsilons)
  {
    std::vector<PreparedLight> lights = base.Lights;
    PlanFarField(lights, lo, hi,
      FarFieldOptions{ true, cellsPerRadius[0], static_cast<std::int64_t>(nodeTargets[0]), 0.0 },
      anchor);
    const std::vector<double> radii = GetFarFieldNearRadii(lights);
    const FarFieldLightTree tree = BuildFarFieldLightTree(lights, radii);
    Errors e;
    std::atomic<std::int64_t> evaluations(0);
    std::vector<glm::dvec3> values(samples.size());
    ParallelFor(samples.size(),
      [&](std::size_t i)
      {
        const Sample& smp = samples[i];
        std::int64_t count = 0;
        glm::dvec3 sum = SumNearParts(lights, smp, count);
        std::vector<int> stack;
        if (!tree.Nodes.empty())
        {
          stack.push_back(0);
        }
        while (!stack.empty())
        {
          const FarFieldLightTree::Node& n = tree.Nodes[static_cast<std::size_t>(stack.back())];
          stack.pop_back();
          const glm::dvec3 v = n.Centroid - smp.P;
          const double d = glm::length(v);
          if (AcceptFarFieldGroup(n, smp.P, smp.P, epsilon))
          {
            sum += n.Color * EvaluateAttenuation(d, n.Attenuation) * ShadeValue(smp, v / d);
            ++count;
            continue;
          }
          if (n.Left < 0)
          {
            for (int q = n.First; q < n.First + n.Count; ++q)
            {
              const std::size_t l =
                static_cast<std::size_t>(tree.Order[static_cast<std::size_t>(q)]);
              double far;
              glm::dvec3 u;
              if (ComputeFarContribution(lights[l], radii[l], smp.P, far, u))
              {
                sum += lights[l].Color * far * ShadeValue(smp, u);
              }
              ++count;
            }
            continue;
          }
          stack.push_back(n.Left);
          stack.push_back(n.Right);
        }
        values[i] = sum;
        evaluations += count;
      });
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      e.Add(exact[i], values[i]);
    }
    char name[160];
    std::snprintf(name, sizeof(name), "hierarchy per point: epsilon %g", epsilon);
    e.Print(name, static_cast<double>(evaluations.load()) / samples.size(), 0);
  }
  return EXIT_SUCCESS;
}
