// SPDX-License-Identifier: BSD-3-Clause
// Hard cases of light placement, each checked by RunHardCase (zero false negatives
// against the double-precision reference, clustered vs brute force within the derived
// cutoff bound, no NaN/Inf pixel):
//  camera inside a light's sphere; light straddling the near plane; centre behind the
//  camera but sphere reaching in front; entirely behind the camera; beyond the far plane;
//  straddling the far plane; radius covering the whole frustum; radius under one pixel;
//  radius 0; lights exactly on tile and slice boundaries (centres on them, and spheres
//  whose exact bounds end exactly on them); every light in one cluster; spot cones of 0.1
//  and 89.9 degrees; 48 spot lights assigned by their cones (the same image without).
#include "ClusteredLightingHardCase.h"

#include "vtkClusteredLightingSphereBounds.h"

#include <cmath>
#include <random>

using namespace ClusteredLightingTest;

namespace
{
struct Fixture
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkClusteredLightSet> Lights;
  vtkNew<vtkClusteredLightingPass> Pass;
  vtkNew<vtkSphereSource> NearSphere;
  vtkNew<vtkPolyDataMapper> NearMapper;
  vtkNew<vtkActor> NearActor;
  Fixture()
  {
    this->Window->SetSize(160, 120);
    this->Window->SetMultiSamples(0);
    this->Renderer->AutomaticLightCreationOff();
    this->Window->AddRenderer(this->Renderer);
    AddRoom(this->Renderer);
    this->Pass->AddLightSet(this->Lights);
    this->Renderer->SetPass(this->Pass);
    this->Reset();
    // A small sphere right in front of the camera, for lights near the near plane.
    const double vc[3] = { -0.25, -0.1, -1.0 };
    double wc[3];
    ViewToWorld(this->Renderer->GetActiveCamera(), vc, wc);
    this->NearSphere->SetCenter(wc);
    this->NearSphere->SetRadius(0.3);
    this->NearSphere->SetThetaResolution(24);
    this->NearSphere->SetPhiResolution(24);
    this->NearMapper->SetInputConnection(this->NearSphere->GetOutputPort());
    this->NearActor->SetMapper(this->NearMapper);
    this->Renderer->AddActor(this->NearActor);
  }
  /// Back to the initial camera and no lights.
  void Reset()
  {
    this->Lights->SetNumberOfLights(0);
    vtkCamera* cam = this->Renderer->GetActiveCamera();
    cam->SetPosition(0.3, 0.2, 3.0);
    cam->SetFocalPoint(0, 0, -2);
    cam->SetViewUp(0, 1, 0);
    cam->SetViewAngle(60);
    // The back wall of the room is at view depth ~8.
    cam->SetClippingRange(0.5, 9.0);
  }
  /// Places light i at view coordinates vc.
  void PlaceVC(vtkIdType i, double x, double y, double z, double radius, double intensity = 3.0)
  {
    const double vc[3] = { x, y, z };
    double wc[3];
    ViewToWorld(this->Renderer->GetActiveCamera(), vc, wc);
    SetLight(this->Lights, i, wc, radius, intensity);
  }
  int Run(const std::string& name, std::size_t minLit = 20)
  {
    return RunHardCase(this->Pass, this->Window, this->Renderer, name, minLit);
  }
};
}

int TestClusteredLightingHardCasesPlacement(int, char*[])
{
  int failures = 0;
  const double nearVC = 0.5, farVC = 9.0;
  // One window for every case: destroying a window and creating another reopens the X
  // display, which fails on a server that resets when its last client leaves (see
  // Display.ReopenAfterLastClient).
  Fixture f;
  {
    f.Lights->SetNumberOfLights(1);
    f.PlaceVC(0, 0.1, -0.05, 0.2, 8.0);
    failures += f.Run("camera inside a light's sphere");
    f.PlaceVC(0, -0.2, 0.1, -nearVC, 1.5);
    failures += f.Run("light centred on the near plane (straddling it)");
    f.PlaceVC(0, -0.1, 0.0, 0.6, 4.0);
    failures += f.Run("centre behind the camera, sphere reaching in front");
    f.PlaceVC(0, 0.0, 0.0, 4.0, 1.5);
    failures += f.Run("light entirely behind the camera", 0);
    f.Window->Render();
    failures += f.Pass->GetNumberOfAssignedLights() == 0 ? 0 : 1;
    f.PlaceVC(0, 0.0, 0.0, -farVC - 3.0, 2.0);
    failures += f.Run("light beyond the far plane", 0);
    failures += f.Pass->GetNumberOfAssignedLights() == 0 ? 0 : 1;
    f.PlaceVC(0, 2.5, 1.5, -7.5, 2.0); // depth 5.5 to 9.5: inside the room, across the far plane
    failures += f.Run("light straddling the far plane");
    f.PlaceVC(0, 0.0, 0.0, -3.0, 50.0);
    failures += f.Run("radius covering the whole frustum");
    f.PlaceVC(0, 0.3, 0.2, -2.9, 1e-3); // projects to a fraction of a pixel
    failures += f.Run("radius under one pixel", 0);
    f.PlaceVC(0, 0.3, 0.2, -2.9, 0.0);
    failures += f.Run("radius 0", 0);
  }
  {
    // Exact tile and slice boundaries of the frame's own grid.
    f.Reset();
    f.Window->Render(); // establishes the grid and matrices
    const vtkClusteredLightingAssignmentSnapshot frame =
      vtkClusteredLightingInspector(f.Pass).GetFrame(f.Renderer);
    const auto& g = frame.Grid;
    const glm::dmat4 inverse = glm::inverse(frame.VCDC);
    auto unproject = [&](double ndcX, double ndcY, double depth)
    {
      // Point of NDC (x, y) at view depth `depth`: intersect the pixel ray with z = -depth.
      const glm::dvec4 a = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
      const glm::dvec4 b = inverse * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
      const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
      const double t = (-depth - pa.z) / (pb.z - pa.z);
      return pa + t * (pb - pa);
    };
    std::vector<glm::dvec4> lights; // VC centre + radius
    for (int k = 1; k < 6; ++k)
    {
      const double ndcX = 2.0 * (4 * k) / g.TilesX - 1.0;
      const double ndcY = 2.0 * (2 * k) / g.TilesY - 1.0;
      const double depth = vtkClusteredLighting::ComputeSliceBoundary(3 * k, g);
      lights.emplace_back(unproject(ndcX, ndcY, depth), 0.3); // centre on three boundaries
      // A sphere whose exact right bound ends exactly on a tile edge and whose far depth
      // ends exactly on a slice boundary: solve r by bisection on the core's exact bounds.
      const glm::dvec3 c = unproject(ndcX - 0.13, ndcY, depth * 0.93);
      double lo = 0.0, hi = depth;
      for (int it = 0; it < 200; ++it)
      {
        const double r = 0.5 * (lo + hi);
        const auto b =
          vtkClusteredLighting::ComputeSphereScreenBounds(c, r, frame.VCDC, g.NearVC, g.FarVC);
        (b.NDCMax.x < ndcX ? lo : hi) = r;
      }
      lights.emplace_back(c, lo);
      const glm::dvec3 c2 = unproject(ndcX - 0.5, ndcY + 0.1, depth - 0.25);
      lights.emplace_back(c2, depth - (-c2.z)); // far extent exactly on the slice boundary
    }
    f.Lights->SetNumberOfLights(static_cast<vtkIdType>(lights.size()));
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
      f.PlaceVC(static_cast<vtkIdType>(i), lights[i].x, lights[i].y, lights[i].z, lights[i].w);
    }
    // Tiny lights: an assignment-precision case (the reference check is its point).
    failures += f.Run("lights on tile and slice boundaries (centres and exact bounds)", 0);
  }
  {
    f.Reset();
    const int n = 1024;
    f.Lights->SetNumberOfLights(n);
    const double p[3] = { 0.1, 0.1, -0.8 }; // 0.2 in front of the room's central sphere
    for (int i = 0; i < n; ++i)
    {
      SetLight(f.Lights, i, p, 0.6, 0.01);
      f.Lights->SetColor(i, (i % 3) / 2.0, ((i / 3) % 3) / 2.0, 1.0);
    }
    failures += f.Run("1024 lights in one cluster");
  }
  {
    f.Reset();
    f.Lights->SetNumberOfLights(4);
    const double target[3] = { 0, 0, -2 };
    const double pos[4][3] = { { 0, 3, -2 }, { 1, 2.5, -1 }, { -3, 2, -2 }, { 2, 3, -3 } };
    const double cones[4] = { 0.1, 0.1, 89.9, 89.9 };
    for (int i = 0; i < 4; ++i)
    {
      SetLight(f.Lights, i, pos[i], 20.0, 3.0);
      f.Lights->SetSpot(
        i, target[0] - pos[i][0], target[1] - pos[i][1], target[2] - pos[i][2], cones[i], 1.0);
    }
    failures += f.Run("spot cones of 0.1 and 89.9 degrees");
  }
  {
    // Spot lights assigned by their cones (SpotConeCulling): cones of 0.1 to 89.9
    // degrees in every direction, some aimed at the camera, one with the camera inside its
    // cone (apex just behind the camera). Besides RunHardCase's checks (the reference keeps
    // every cluster a sampled point of a cone falls in: Core.SpotBounds.*), the image is
    // the same bit for bit with the option off, where the lists hold the whole spheres.
    f.Reset();
    const int n = 48;
    f.Lights->SetNumberOfLights(n);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> U(-0.45, 0.45);
    const double cones[8] = { 0.1, 5.0, 15.0, 30.0, 45.0, 60.0, 75.0, 89.9 };
    const double* eye = f.Renderer->GetActiveCamera()->GetPosition();
    for (int i = 0; i < n; ++i)
    {
      const double p[3] = { 10.0 * U(rng), 10.0 * U(rng), 10.0 * U(rng) };
      SetLight(f.Lights, i, p, 3.0 + 6.0 * (U(rng) + 0.45), 3.0);
      f.Lights->SetColor(i, 0.6 + U(rng), 0.6 + U(rng), 0.6 + U(rng));
      double axis[3] = { U(rng), U(rng), U(rng) };
      if (i % 6 == 0)
      {
        for (int a = 0; a < 3; ++a)
        {
          axis[a] = eye[a] - p[a]; // aimed at the camera
        }
      }
      f.Lights->SetSpot(i, axis[0], axis[1], axis[2], cones[i % 8], 1.0 + (i % 3));
    }
    // Light 0: apex just behind the camera, the camera inside its cone, along the view.
    f.PlaceVC(0, 0.05, 0.0, 0.3, 12.0);
    const double* view = f.Renderer->GetActiveCamera()->GetDirectionOfProjection();
    f.Lights->SetSpot(0, view[0], view[1], view[2], 30.0, 1.0);
    failures += f.Run("48 spot lights culled by their cones");
    f.Window->Render();
    const std::vector<float> on = CapturePixels(f.Window);
    const auto pairsOn = CheckAssignment(f.Pass, f.Renderer, "spot cones culled");
    f.Pass->SpotConeCullingOff();
    f.Window->Render();
    const std::vector<float> off = CapturePixels(f.Window);
    const auto pairsOff = CheckAssignment(f.Pass, f.Renderer, "spot cones not culled");
    f.Pass->SpotConeCullingOn();
    const bool same = on == off;
    const bool fewer = pairsOff.FalseNegatives == 0 &&
      static_cast<double>(pairsOn.GPUPairs) < 0.7 * static_cast<double>(pairsOff.GPUPairs);
    std::printf("[%s] spot cone culling: %llu GPU pairs, %llu without; images %s\n",
      same && fewer ? "PASS" : "FAIL", static_cast<unsigned long long>(pairsOn.GPUPairs),
      static_cast<unsigned long long>(pairsOff.GPUPairs), same ? "the same" : "differ");
    failures += same && fewer ? 0 : 1;
  }
  std::printf("%d failed check(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
