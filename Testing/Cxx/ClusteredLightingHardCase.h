// SPDX-License-Identifier: BSD-3-Clause
// Shared by the hard-case tests: what every case checks, and scene helpers.
#ifndef ClusteredLightingHardCase_h
#define ClusteredLightingHardCase_h

#include "ClusteredLightingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkClusteredLightSet.h"
#include "vtkCubeSource.h"
#include "vtkMatrix4x4.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <random>

namespace ClusteredLightingTest
{

/**
 * Renders the current frame and checks what every hard case must satisfy:
 *  1. zero false negatives of the GPU list/master textures against the double-precision
 *     reference (false-positive rate printed);
 *  2. clustered matches brute force at every pixel within the derived cutoff bound;
 *  3. no NaN or Inf pixel;
 *  4. at least minLitPixels pixels change by more than 2 steps when the light sets are
 *     disabled (the case really lights something; 0 for lights that must not show).
 * Returns the number of failed checks.
 */
inline int RunHardCase(vtkClusteredLightingPass* pass, vtkRenderWindow* rw, vtkRenderer* ren,
  const std::string& name, std::size_t minLitPixels = 1, double material = 1.0)
{
  rw->Render();
  int failed = 0;
  if (pass->GetNumberOfClusteredLights() > 0)
  {
    const auto a = CheckAssignment(pass, ren, name.c_str());
    failed += (a.FalseNegatives != 0 || a.MasterMismatches != 0) ? 1 : 0;
  }
  const auto b = CheckAgainstBruteForce(pass, rw, ren, material, name.c_str());
  failed += b.Violations != 0 ? 1 : 0;
  const std::size_t nonFinite = CountNonFinitePixels(pass, rw);
  failed += nonFinite != 0 ? 1 : 0;
  rw->Render();
  const std::vector<float> lit = CapturePixels(rw);
  // Reference without the case's lights: one zero-intensity light keeps the pass (and
  // VTK's lit shading path) active, so only the lights' contribution differs.
  std::vector<int> enabled;
  const int sets = pass->GetNumberOfLightSets();
  for (int i = 0; i < sets; ++i)
  {
    enabled.push_back(pass->GetLightSet(i)->GetEnabled());
    pass->GetLightSet(i)->EnabledOff();
  }
  vtkNew<vtkClusteredLightSet> dark;
  dark->SetNumberOfLights(1);
  dark->SetIntensity(0, 0.0);
  pass->AddLightSet(dark);
  rw->Render();
  const std::vector<float> unlit = CapturePixels(rw);
  pass->RemoveLightSet(dark);
  for (int i = 0; i < sets; ++i)
  {
    pass->GetLightSet(i)->SetEnabled(enabled[static_cast<std::size_t>(i)] != 0);
  }
  rw->Render();
  std::size_t litPixels = 0;
  for (std::size_t p = 0; p + 2 < lit.size(); p += 3)
  {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      d = std::max(d, std::abs(double(lit[p + c]) - double(unlit[p + c])));
    }
    litPixels += d > 2.0 / 255.0 ? 1 : 0;
  }
  failed += litPixels < minLitPixels ? 1 : 0;
  std::printf("[%s] %s (%d clustered lights, %d assigned, %zu lit pixels, %zu non-finite)\n",
    failed ? "FAIL" : "PASS", name.c_str(), pass->GetNumberOfClusteredLights(),
    pass->GetNumberOfAssignedLights(), litPixels, nonFinite);
  return failed;
}

/// World position of a view-coordinate point for the camera's current view.
inline void ViewToWorld(vtkCamera* camera, const double vc[3], double wc[3])
{
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(camera->GetModelViewTransformMatrix(), inverse);
  const double in[4] = { vc[0], vc[1], vc[2], 1.0 };
  double out[4];
  inverse->MultiplyPoint(in, out);
  for (int i = 0; i < 3; ++i)
  {
    wc[i] = out[i] / out[3];
  }
}

/// A closed room (a cube seen from inside; VTK lights back faces) with three spheres.
inline void AddRoom(vtkRenderer* ren, double size = 10.0, const double center[3] = nullptr)
{
  const double c[3] = { center ? center[0] : 0.0, center ? center[1] : 0.0,
    center ? center[2] : 0.0 };
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(c[0], c[1], c[2]);
  cube->SetXLength(size);
  cube->SetYLength(size);
  cube->SetZLength(size);
  vtkNew<vtkPolyDataMapper> cubeMapper;
  cubeMapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> room;
  room->SetMapper(cubeMapper);
  room->GetProperty()->SetColor(0.8, 0.8, 0.8);
  ren->AddActor(room);
  const double spheres[3][4] = { { 0, 0, -2, 1.0 }, { 2, -1, -3.5, 0.8 }, { -2.5, 1, -1, 0.6 } };
  for (const auto& s : spheres)
  {
    vtkNew<vtkSphereSource> src;
    src->SetCenter(c[0] + s[0] * size / 10, c[1] + s[1] * size / 10, c[2] + s[2] * size / 10);
    src->SetRadius(s[3] * size / 10);
    src->SetThetaResolution(32);
    src->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(src->GetOutputPort());
    vtkNew<vtkActor> a;
    a->SetMapper(m);
    ren->AddActor(a);
  }
}

/// The hard-case window: 160 x 120, no multisampling, `ren` without VTK's automatic
/// headlight, showing AddRoom's room.
inline void SetUpRoomWindow(vtkRenderWindow* renWin, vtkRenderer* ren)
{
  renWin->SetSize(160, 120);
  renWin->SetMultiSamples(0);
  ren->AutomaticLightCreationOff();
  renWin->AddRenderer(ren);
  AddRoom(ren);
}

/**
 * Light i of `lights` at p whose influence radius at the pass's cutoff is exactly `radius`:
 * attenuation (1, 0, k) with k = (intensity / cutoff - 1) / radius^2, so the light is at the
 * cutoff right at its radius and its tail beyond is small. radius 0 sets an explicit
 * radius of 0 (a valid light that reaches nothing).
 */
inline void SetLight(vtkClusteredLightSet* lights, vtkIdType i, const double p[3], double radius,
  double intensity = 1.0, double cutoff = 1.0 / 1024.0)
{
  lights->SetPosition(i, p[0], p[1], p[2]);
  lights->SetColor(i, 1.0, 0.9, 0.7);
  lights->SetIntensity(i, intensity);
  if (radius > 0.0)
  {
    lights->SetAttenuation(i, 1.0, 0.0, (intensity / cutoff - 1.0) / (radius * radius));
    lights->UnsetRadius(i);
  }
  else
  {
    lights->SetAttenuation(i, 1.0, 0.0, 1.0);
    lights->SetRadius(i, 0.0);
  }
}

/// n seeded lights inside the room (size, centre) with influence radius `radius`.
inline void MakeRoomLights(vtkClusteredLightSet* lights, int n, double radius, unsigned seed,
  double size = 10.0, const double center[3] = nullptr, double intensity = 3.0)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-0.48, 0.48);
  lights->SetNumberOfLights(n);
  for (int i = 0; i < n; ++i)
  {
    const double p[3] = { (center ? center[0] : 0.0) + size * U(rng),
      (center ? center[1] : 0.0) + size * U(rng), (center ? center[2] : 0.0) + size * U(rng) };
    SetLight(lights, i, p, radius, intensity);
    lights->SetColor(i, 0.5 + U(rng), 0.5 + U(rng), 0.5 + U(rng));
  }
}

} // namespace ClusteredLightingTest

#endif
