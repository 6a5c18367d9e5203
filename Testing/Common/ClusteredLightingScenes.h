// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ClusteredLightingScenes.h
 * @brief Reproducible scenes for the examples, the benchmark and the image tests.
 *
 * Meshes are real data installed by scripts/install-deps.sh (Debian packages):
 *  - the Stanford bunny (glmark2-data: /usr/share/glmark2/models/bunny.obj, 69,666
 *    triangles), optionally Loop-subdivided (2 levels: about 1.1 M triangles);
 *  - the KIT FZK-Haus interior (assimp-testmodels: AC14-FZK-Haus.ifc, converted to OBJ by
 *    `assimp export`, see scripts/prepare-data.sh).
 * Light layouts are seeded (std::mt19937), so every run places the same lights
 * (MakeBallLights: the vtkRandomSequence it is given).
 */
#ifndef ClusteredLightingScenes_h
#define ClusteredLightingScenes_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkClusteredLightSet.h"
#include "vtkIdList.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPointSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRandomSequence.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace ClusteredLightingScenes
{

/// Path of a data file: $CLUSTERED_LIGHTING_DATA/<name> if set, else the default.
inline std::string DataPath(const char* name, const char* fallback)
{
  if (const char* dir = std::getenv("CLUSTERED_LIGHTING_DATA"))
  {
    const std::string p = std::string(dir) + "/" + name;
    if (vtksys::SystemTools::FileExists(p))
    {
      return p;
    }
  }
  return fallback;
}

inline std::string BunnyPath()
{
  return DataPath("bunny.obj", "/usr/share/glmark2/models/bunny.obj");
}

/// The Stanford bunny with normals, Loop-subdivided `levels` times (0: 69,666 triangles).
inline vtkSmartPointer<vtkPolyData> LoadBunny(int levels = 0)
{
  const std::string path = BunnyPath();
  if (!vtksys::SystemTools::FileExists(path))
  {
    return nullptr;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(reader->GetOutputPort());
  vtkSmartPointer<vtkAlgorithm> last = clean;
  vtkNew<vtkLoopSubdivisionFilter> subdivide;
  if (levels > 0)
  {
    subdivide->SetNumberOfSubdivisions(levels);
    subdivide->SetInputConnection(clean->GetOutputPort());
    last = subdivide;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(last->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

/// Bunny (bounds about [-1,1]^3) standing on a 6 x 6 floor at y = -1.
inline void AddBunnyScene(vtkRenderer* ren, vtkPolyData* bunny)
{
  vtkNew<vtkPolyDataMapper> bunnyMapper;
  bunnyMapper->SetInputData(bunny);
  vtkNew<vtkActor> bunnyActor;
  bunnyActor->SetMapper(bunnyMapper);
  bunnyActor->GetProperty()->SetColor(0.85, 0.85, 0.8);
  bunnyActor->GetProperty()->SetSpecular(0.3);
  bunnyActor->GetProperty()->SetSpecularPower(20);
  ren->AddActor(bunnyActor);

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3, -1, -3);
  plane->SetPoint1(3, -1, -3);
  plane->SetPoint2(-3, -1, 3);
  plane->SetResolution(1, 1);
  vtkNew<vtkPolyDataNormals> planeNormals;
  planeNormals->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(planeNormals->GetOutputPort());
  vtkNew<vtkActor> floor;
  floor->SetMapper(planeMapper);
  floor->GetProperty()->SetColor(0.7, 0.7, 0.7);
  ren->AddActor(floor);
}

enum class Layout
{
  Uniform, ///< uniform scatter in a box
  Clumped, ///< Gaussian clumps around 32 seeds
  Hard     ///< uniform, plus lights at, around and behind the camera and on the planes
};

struct LightParameters
{
  double Intensity = 1.0;
  double Quadratic = 0.0;       ///< attenuation (1, 0, Quadratic); 0 derives it from Radius
  double TargetRadius = 0.35;   ///< influence radius the attenuation is chosen for
  double Cutoff = 1.0 / 1024.0; ///< the pass's cutoff the radius refers to
};

/// Attenuation (1, 0, k) whose influence radius at the cutoff is TargetRadius.
inline double QuadraticForRadius(const LightParameters& p)
{
  if (p.Quadratic > 0.0)
  {
    return p.Quadratic;
  }
  return (p.Intensity / p.Cutoff - 1.0) / (p.TargetRadius * p.TargetRadius);
}

/**
 * Fills `lights` with n seeded lights inside box [lo, hi] (xyz). Colors are saturated
 * random hues. For Layout::Hard, `eye` is the camera position: an eighth of the lights
 * go near and around it (some containing it).
 */
inline void MakeLights(vtkClusteredLightSet* lights, int n, Layout layout, const double lo[3],
  const double hi[3], const LightParameters& params, unsigned int seed = 1,
  const double* eye = nullptr)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  lights->SetNumberOfLights(n);
  const double k = QuadraticForRadius(params);
  std::vector<std::array<double, 3>> seeds(32);
  for (auto& s : seeds)
  {
    for (int a = 0; a < 3; ++a)
    {
      s[a] = lo[a] + U(rng) * (hi[a] - lo[a]);
    }
  }
  std::normal_distribution<double> G(0.0, 1.0);
  for (int i = 0; i < n; ++i)
  {
    double p[3];
    for (int a = 0; a < 3; ++a)
    {
      p[a] = lo[a] + U(rng) * (hi[a] - lo[a]);
    }
    if (layout == Layout::Clumped)
    {
      const auto& s = seeds[static_cast<std::size_t>(i) % seeds.size()];
      for (int a = 0; a < 3; ++a)
      {
        p[a] = std::min(hi[a], std::max(lo[a], s[a] + 0.08 * (hi[a] - lo[a]) * G(rng)));
      }
    }
    else if (layout == Layout::Hard && eye && i % 8 == 0)
    {
      const double scale = params.TargetRadius * (0.2 + 1.8 * U(rng));
      for (int a = 0; a < 3; ++a)
      {
        p[a] = eye[a] + scale * (2.0 * U(rng) - 1.0);
      }
    }
    lights->SetPosition(i, p[0], p[1], p[2]);
    // Saturated hue.
    const double h = 6.0 * U(rng);
    const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
    double rgb[3] = { 0, 0, 0 };
    const int sector = static_cast<int>(h);
    const int order[6][3] = { { 0, 1, 2 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 1, 0 }, { 2, 0, 1 },
      { 0, 2, 1 } };
    rgb[order[sector % 6][0]] = 1.0;
    rgb[order[sector % 6][1]] = x;
    lights->SetColor(i, 0.3 + 0.7 * rgb[0], 0.3 + 0.7 * rgb[1], 0.3 + 0.7 * rgb[2]);
    lights->SetIntensity(i, params.Intensity);
    lights->SetAttenuation(i, 1.0, 0.0, k);
  }
}

/**
 * n seeded lights hovering over surfaces: half over the 6 x 6 floor at y = -1, half over
 * `mesh` (area-weighted random triangles), each at a height in [hMin, hMax] along the
 * surface normal. Attenuation as MakeLights.
 */
inline void MakeSurfaceLights(vtkClusteredLightSet* lights, int n, vtkPolyData* mesh, double hMin,
  double hMax, const LightParameters& params, unsigned int seed = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double lo[3] = { -3, -1, -3 }, hi[3] = { 3, -1, 3 };
  MakeLights(lights, n, Layout::Uniform, lo, hi, params, seed); // colors, attenuation
  // Area-weighted triangle table of the mesh.
  std::vector<std::array<vtkIdType, 3>> tris;
  std::vector<double> cumulative;
  vtkCellArray* polys = mesh->GetPolys();
  vtkNew<vtkIdList> ids;
  double total = 0.0;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    if (ids->GetNumberOfIds() != 3)
    {
      continue;
    }
    double a[3], b[3], c[3];
    mesh->GetPoint(ids->GetId(0), a);
    mesh->GetPoint(ids->GetId(1), b);
    mesh->GetPoint(ids->GetId(2), c);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2],
                 cz = u[0] * v[1] - u[1] * v[0];
    total += 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
    tris.push_back({ ids->GetId(0), ids->GetId(1), ids->GetId(2) });
    cumulative.push_back(total);
  }
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  for (int i = 0; i < n; ++i)
  {
    const double h = hMin + (hMax - hMin) * U(rng);
    double p[3];
    if (i % 2 == 0 || tris.empty() || !normals)
    {
      p[0] = -3.0 + 6.0 * U(rng);
      p[1] = -1.0 + h;
      p[2] = -3.0 + 6.0 * U(rng);
    }
    else
    {
      const double pick = U(rng) * total;
      const std::size_t t = static_cast<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
      const auto& tri = tris[std::min(t, tris.size() - 1)];
      double r1 = U(rng), r2 = U(rng);
      if (r1 + r2 > 1.0)
      {
        r1 = 1.0 - r1;
        r2 = 1.0 - r2;
      }
      const double w[3] = { 1.0 - r1 - r2, r1, r2 };
      double nrm[3] = { 0, 0, 0 };
      p[0] = p[1] = p[2] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        double q[3], nk[3];
        mesh->GetPoint(tri[k], q);
        normals->GetTuple(tri[k], nk);
        for (int a = 0; a < 3; ++a)
        {
          p[a] += w[k] * q[a];
          nrm[a] += w[k] * nk[a];
        }
      }
      const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
      for (int a = 0; a < 3; ++a)
      {
        p[a] += h * nrm[a] / (len > 0 ? len : 1.0);
      }
    }
    lights->SetPosition(i, p[0], p[1], p[2]);
  }
}

/**
 * Examples/Python/user_lights.py's scene: a ball of radius 0.6 (64 x 48 facets, colour
 * (0.9, 0.85, 0.8), Specular 0.5) on a floor 8 x 8 at y = -1 (64 x 64 quads, grey 0.8, no
 * specular), both of specular power 20, seen from (0, 1.5, 6) towards (0, -0.3, 0).
 */
inline void AddBallScene(vtkRenderer* ren)
{
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-4, -1, -4);
  floor->SetPoint1(4, -1, -4);
  floor->SetPoint2(-4, -1, 4);
  floor->SetResolution(64, 64);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(0.6);
  ball->SetThetaResolution(64);
  ball->SetPhiResolution(48);
  const struct
  {
    vtkPolyDataAlgorithm* Source;
    double Color[3];
    double Specular;
  } parts[] = { { floor, { 0.8, 0.8, 0.8 }, 0.0 }, { ball, { 0.9, 0.85, 0.8 }, 0.5 } };
  for (const auto& part : parts)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(part.Source->GetOutputPort());
    mapper->Update();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(part.Color[0], part.Color[1], part.Color[2]);
    actor->GetProperty()->SetSpecular(part.Specular);
    actor->GetProperty()->SetSpecularPower(20.0);
    ren->AddActor(actor);
  }
  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetPosition(0, 1.5, 6);
  camera->SetFocalPoint(0, -0.3, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30.0);
  ren->ResetCameraClippingRange();
}

/**
 * The lights of AddBallScene as user_lights.py writes them: `count` white points of a
 * vtkPointSource of radius 3, VTK's inverse-square attenuation (1, 0, 8), `intensity`
 * each. `random` draws the points (nullptr: VTK's global sequence, which gives the
 * example's points when nothing drew from it before).
 */
inline void MakeBallLights(
  vtkClusteredLightSet* lights, int count, double intensity, vtkRandomSequence* random)
{
  vtkNew<vtkPointSource> points;
  points->SetNumberOfPoints(count);
  points->SetRadius(3.0);
  points->SetRandomSequence(random);
  points->Update();
  lights->SetNumberOfLights(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[3];
    points->GetOutput()->GetPoint(i, p);
    lights->SetPosition(i, p[0], p[1], p[2]);
    lights->SetColor(i, 1.0, 1.0, 1.0);
    lights->SetIntensity(i, intensity);
    lights->SetAttenuation(i, 1.0, 0.0, 8.0);
  }
}

/// Wall-clock milliseconds of one synchronous render (GL work finished).
inline double TimeRender(vtkRenderWindow* rw)
{
  const auto t0 = std::chrono::steady_clock::now();
  rw->Render();
  rw->WaitForCompletion();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

} // namespace ClusteredLightingScenes

#endif
