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
//   ClusteredLightingFarFieldStudy [--scene bunny|house|dense] [--lights N] [--samples S]
//
// Candidates: "cut" (today: every light cut at its cutoff radius), "far field" (near part
// windowed at the near radius plus the far field on a grid of spacing h, order-2 moments,
// trilinear), with and without the far specular, for several near radii and spacings; and
// "hierarchy" (design 2: the far part of groups of lights from an octree, chosen per point
// by an error bound, evaluated like lights), whose cost is the number of groups per point.
#include "BenchmarkMeasure.h"
#include "BenchmarkPlan.h"
#include "ClusteredLightingScenes.h"
#include "vtkClusteredLightingFarField.h"

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
#include <chrono>
#include <cstdio>
#include <cstdlib>
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

/// Area-weighted points on the renderer's actors, inside the camera frustum, facing it.
std::vector<Sample> SampleSurfaces(vtkRenderer* ren, int count, unsigned seed)
{
  struct Tri
  {
    vtkPolyData* Mesh;
    vtkDataArray* Normals;
    vtkIdType Ids[3];
    vtkProperty* Property;
  };
  std::vector<Tri> tris;
  std::vector<double> cumulative;
  std::vector<vtkSmartPointer<vtkPolyData>> keep;
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
    keep.push_back(mesh);
    vtkCellArray* polys = mesh->GetPolys();
    vtkNew<vtkIdList> ids;
    for (polys->InitTraversal(); polys->GetNextCell(ids);)
    {
      for (vtkIdType t = 1; t + 1 < ids->GetNumberOfIds(); ++t) // fan
      {
        Tri tri{ mesh, mesh->GetPointData()->GetNormals(),
          { ids->GetId(0), ids->GetId(t), ids->GetId(t + 1) }, a->GetProperty() };
        double p[3][3];
        for (int k = 0; k < 3; ++k)
        {
          mesh->GetPoint(tri.Ids[k], p[k]);
        }
        const glm::dvec3 u(p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]);
        const glm::dvec3 v(p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]);
        total += 0.5 * glm::length(glm::cross(u, v));
        tris.push_back(tri);
        cumulative.push_back(total);
      }
    }
  }
  vtkCamera* cam = ren->GetActiveCamera();
  double eyeD[3];
  cam->GetPosition(eyeD);
  const glm::dvec3 eye(eyeD[0], eyeD[1], eyeD[2]);
  vtkMatrix4x4* m = cam->GetCompositeProjectionTransformMatrix(1024.0 / 768.0, -1, 1);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Sample> out;
  for (int attempt = 0; attempt < 50 * count && static_cast<int>(out.size()) < count; ++attempt)
  {
    const double pick = U(rng) * total;
    const std::size_t t = std::min(tris.size() - 1,
      static_cast<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
    const Tri& tri = tris[t];
    double r1 = U(rng), r2 = U(rng);
    if (r1 + r2 > 1.0)
    {
      r1 = 1.0 - r1;
      r2 = 1.0 - r2;
    }
    const double w[3] = { 1.0 - r1 - r2, r1, r2 };
    glm::dvec3 p(0.0), n(0.0);
    for (int k = 0; k < 3; ++k)
    {
      double q[3], nk[3];
      tri.Mesh->GetPoint(tri.Ids[k], q);
      tri.Normals->GetTuple(tri.Ids[k], nk);
      p += w[k] * glm::dvec3(q[0], q[1], q[2]);
      n += w[k] * glm::dvec3(nk[0], nk[1], nk[2]);
    }
    double clip[4];
    const double hp[4] = { p.x, p.y, p.z, 1.0 };
    m->MultiplyPoint(hp, clip);
    if (!(clip[3] > 0.0) || std::abs(clip[0]) > clip[3] || std::abs(clip[1]) > clip[3] ||
      std::abs(clip[2]) > clip[3])
    {
      continue;
    }
    Sample s;
    s.P = p;
    s.V = glm::normalize(eye - p);
    s.N = glm::normalize(n);
    if (glm::dot(s.N, s.V) < 0.0)
    {
      s.N = -s.N; // VTK flips back faces
    }
    double c[3];
    tri.Property->GetDiffuseColor(c);
    s.Kd = tri.Property->GetDiffuse() * glm::dvec3(c[0], c[1], c[2]);
    s.Ks = tri.Property->GetSpecular();
    s.Power = tri.Property->GetSpecularPower();
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

int Quantize(double v)
{
  return static_cast<int>(std::lround(255.0 * std::min(1.0, std::max(0.0, v))));
}

struct Errors
{
  double Max = 0, Mean = 0, RMSE = 0, ContinuousMean = 0;
  std::size_t Count = 0;
  void Add(const glm::dvec3& exact, const glm::dvec3& approx)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double q = std::abs(Quantize(exact[c]) - Quantize(approx[c]));
      const double clampedExact = std::min(1.0, std::max(0.0, exact[c]));
      const double clampedApprox = std::min(1.0, std::max(0.0, approx[c]));
      this->Max = std::max(this->Max, q);
      this->Mean += q;
      this->RMSE += q * q;
      this->ContinuousMean += 255.0 * std::abs(clampedExact - clampedApprox);
      ++this->Count;
    }
  }
  void Print(const char* name, double nearPerPoint, long long nodes, double extra = 0.0,
    const char* extraName = nullptr) const
  {
    std::printf("%-44s max %5.0f  mean %6.3f  RMSE %6.3f  (continuous mean %6.3f)  near/pt %7.2f",
      name, this->Max, this->Mean / this->Count, std::sqrt(this->RMSE / this->Count),
      this->ContinuousMean / this->Count, nearPerPoint);
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

std::vector<double> NodeMomentsParallel(const FarFieldGrid& grid,
  const std::vector<PreparedLight>& lights, const std::vector<double>& nearRadii)
{
  std::vector<double> m(
    static_cast<std::size_t>(grid.GetNumberOfNodes()) * FarFieldFloatsPerNode, 0.0);
  ParallelFor(static_cast<std::size_t>(grid.Dims[2]),
    [&](std::size_t k)
    {
      for (int j = 0; j < grid.Dims[1]; ++j)
      {
        for (int i = 0; i < grid.Dims[0]; ++i)
        {
          const glm::dvec3 p = grid.NodePosition(i, j, static_cast<int>(k));
          double* o = &m[static_cast<std::size_t>(grid.NodeIndex(i, j, static_cast<int>(k))) *
            FarFieldFloatsPerNode];
          for (std::size_t l = 0; l < lights.size(); ++l)
          {
            double far;
            glm::dvec3 toLight;
            if (IsFarFieldLight(lights[l]) &&
              ComputeFarContribution(lights[l], nearRadii[l], p, far, toLight))
            {
              AccumulateFarMoments(lights[l].Color, far, toLight, o);
            }
          }
        }
      }
    });
  return m;
}
}

int main(int argc, char* argv[])
{
  std::string sceneName = "bunny";
  int lightsCount = 4096, samplesCount = 20000;
  std::vector<double> cutoffs = { 1.0 / 256, 1.0 / 1024, 1.0 / 4096 };
  std::vector<double> cellsPerRadius = { 2.0, 3.0, 4.0, 6.0 };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--scene" && i + 1 < argc)
    {
      sceneName = argv[++i];
    }
    else if (a == "--lights" && i + 1 < argc)
    {
      lightsCount = std::atoi(argv[++i]);
    }
    else if (a == "--samples" && i + 1 < argc)
    {
      samplesCount = std::atoi(argv[++i]);
    }
    else if (a == "--cutoffs" && i + 1 < argc)
    {
      cutoffs.clear();
      for (const char* c = argv[++i]; *c; ++c)
      {
        cutoffs.push_back(1.0 / std::strtod(c, const_cast<char**>(&c)));
        if (!*c)
        {
          break;
        }
      }
    }
    else if (a == "--cells" && i + 1 < argc)
    {
      cellsPerRadius.clear();
      for (const char* c = argv[++i]; *c; ++c)
      {
        cellsPerRadius.push_back(std::strtod(c, const_cast<char**>(&c)));
        if (!*c)
        {
          break;
        }
      }
    }
  }
  Context ctx(1024, 768);
  const Scene& scene = sceneName == "house" ? HouseScene() : BunnyScene();
  if (ctx.LoadScene(scene, true) < 0)
  {
    std::fprintf(stderr, "scene data missing\n");
    return EXIT_FAILURE;
  }
  ctx.MakeLights(lightsCount, "uniform");
  vtkClusteredLightSet* set = ctx.GetLights();
  if (sceneName == "dense")
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
  ctx.SetView();
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
  const std::vector<Sample> samples = SampleSurfaces(ctx.GetRenderer(), samplesCount, 3);
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
  for (const Sample& s : samples)
  {
    lo = glm::min(lo, s.P);
    hi = glm::max(hi, s.P);
  }

  for (double cutoff : cutoffs)
  {
    const PreparedLights prepared =
      PrepareLights(sources, LightPreparationOptions{ cutoff, false });
    std::vector<double> radii(prepared.Lights.size());
    double meanRadius = 0.0;
    for (std::size_t l = 0; l < radii.size(); ++l)
    {
      radii[l] = prepared.Lights[l].Radius;
      meanRadius += std::min(radii[l], 1e6);
    }
    meanRadius /= std::max<std::size_t>(radii.size(), 1);
    // Today: cut at the radius.
    {
      Errors e;
      double near = 0.0;
      for (std::size_t i = 0; i < samples.size(); ++i)
      {
        const Sample& s = samples[i];
        glm::dvec3 sum(0.0);
        for (const PreparedLight& l : prepared.Lights)
        {
          const glm::dvec3 v = l.PositionWC - s.P;
          const double d = glm::length(v);
          if (d < l.Radius)
          {
            const glm::dvec2 sh = Shade(s, v / d);
            sum += l.Color * EvaluateAttenuation(d, l.Attenuation) * (sh.x * s.Kd + sh.y * s.Ks);
            near += 1.0;
          }
        }
        e.Add(exact[i], sum);
      }
      char name[128];
      std::snprintf(name, sizeof(name), "cutoff 1/%g (r %.3f): cut", 1.0 / cutoff, meanRadius);
      e.Print(name, near / samples.size(), 0);
    }
    for (double cells : cellsPerRadius)
    {
      const double h = meanRadius / cells;
      const FarFieldGrid grid = ComputeFarFieldGrid(lo, hi, h, 4000000);
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<double> moments = NodeMomentsParallel(grid, prepared.Lights, radii);
      const double buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      Errors withSpec, noSpec;
      double near = 0.0;
      for (std::size_t i = 0; i < samples.size(); ++i)
      {
        const Sample& s = samples[i];
        glm::dvec3 sum(0.0);
        for (const PreparedLight& l : prepared.Lights)
        {
          const glm::dvec3 v = l.PositionWC - s.P;
          const double d = glm::length(v);
          if (d < l.Radius)
          {
            const glm::dvec2 sh = Shade(s, v / d);
            sum += l.Color * EvaluateAttenuation(d, l.Attenuation) *
              EvaluateSplitWindow(d / l.Radius) * (sh.x * s.Kd + sh.y * s.Ks);
            near += 1.0;
          }
        }
        const auto m = InterpolateFarMoments(grid, moments, s.P);
        const glm::dvec3 diffuse = EvaluateFarDiffuse(m, s.N) * s.Kd;
        const glm::dvec3 R = 2.0 * glm::dot(s.N, s.V) * s.N - s.V;
        const glm::dvec3 specular =
          s.Ks > 0.0 ? EvaluateFarSpecular(m, R, s.Power) * s.Ks : glm::dvec3(0.0);
        noSpec.Add(exact[i], sum + diffuse);
        withSpec.Add(exact[i], sum + diffuse + specular);
      }
      char name[128];
      std::snprintf(name, sizeof(name), "cutoff 1/%g: far field h = r/%g", 1.0 / cutoff, cells);
      withSpec.Print(name, near / samples.size(), grid.GetNumberOfNodes(), buildMs, "build ms");
      std::snprintf(
        name, sizeof(name), "cutoff 1/%g: far field h = r/%g, no far spec", 1.0 / cutoff, cells);
      noSpec.Print(name, near / samples.size(), grid.GetNumberOfNodes());
    }
  }
  return EXIT_SUCCESS;
}
