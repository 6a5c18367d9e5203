// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the GL tests: scenes, image capture and comparison, and the
// comparison of read-back list/master textures with the double-precision reference.
#ifndef ClusteredLightingTestUtilities_h
#define ClusteredLightingTestUtilities_h

#include "ClusteredLightingImages.h"
#include "ClusteredLightingScenes.h"
#include "vtkClusteredLightingInspector.h"
#include "vtkClusteredLightingPass.h"
#include "vtkClusteredLightingReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace ClusteredLightingTest
{

/// Collects the error and warning messages an object emits (they are not printed, so
/// ctest's "ERR|" failure pattern does not fire on expected errors).
class MessageCollector : public vtkCommand
{
public:
  static MessageCollector* New() { return new MessageCollector; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string msg = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(msg);
  }
  void Watch(vtkObject* o)
  {
    o->AddObserver(vtkCommand::ErrorEvent, this);
    o->AddObserver(vtkCommand::WarningEvent, this);
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

/// Records the fragment shader source of every program a mapper draws with
/// (vtkCommand::UpdateShaderEvent passes the program) and counts distinct programs.
class ShaderRecorder : public vtkCommand
{
public:
  static ShaderRecorder* New() { return new ShaderRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    vtkShaderProgram* program = static_cast<vtkShaderProgram*>(data);
    if (program && program->GetFragmentShader())
    {
      this->LastFragmentSource = program->GetFragmentShader()->GetSource();
      this->Programs.insert(program);
    }
  }
  std::string LastFragmentSource;
  std::set<vtkShaderProgram*> Programs;
};

/// Adds a square floor in the z = 0 plane, from -halfSize to halfSize in x and y, with
/// resolution x resolution quads; returns its actor (held by the renderer).
inline vtkActor* AddFloor(vtkRenderer* ren, double halfSize, int resolution = 1)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-halfSize, -halfSize, 0);
  plane->SetPoint1(halfSize, -halfSize, 0);
  plane->SetPoint2(-halfSize, halfSize, 0);
  plane->SetResolution(resolution, resolution);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ren->AddActor(actor);
  return actor;
}

/// RGB pixels of the window's back buffer as floats in [0, 1] (render first).
inline std::vector<float> CapturePixels(vtkRenderWindow* rw)
{
  return ClusteredLightingImages::CaptureRGB(rw);
}

/// A floor and a shiny sphere (Diffuse 1 + Specular 0.4 at most, for CheckAgainstBruteForce).
inline void AddTestScene(vtkRenderer* ren, int resolution = 24)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3, -1, -3);
  plane->SetPoint1(3, -1, -3);
  plane->SetPoint2(-3, -1, 3);
  plane->SetResolution(8, 8);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> floor;
  floor->SetMapper(planeMapper);
  floor->GetProperty()->SetColor(0.8, 0.8, 0.8);
  ren->AddActor(floor);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(sphereMapper);
  ball->SetScale(1.5);
  ball->GetProperty()->SetColor(0.9, 0.7, 0.5);
  ball->GetProperty()->SetSpecular(0.4);
  ball->GetProperty()->SetSpecularPower(20);
  ren->AddActor(ball);
}

/// The usual test window: size, no multisampling, a dark background, one renderer
/// showing AddTestScene from the usual camera.
inline void SetUpTestScene(
  vtkRenderWindow* rw, vtkRenderer* ren, int width, int height, int sphereResolution = 24)
{
  rw->SetSize(width, height);
  rw->SetMultiSamples(0);
  ren->SetBackground(0.05, 0.05, 0.08);
  rw->AddRenderer(ren);
  AddTestScene(ren, sphereResolution);
  ren->GetActiveCamera()->SetPosition(0.5, 2.5, 7.0);
  ren->GetActiveCamera()->SetFocalPoint(0.0, -0.3, 0.0);
  ren->ResetCameraClippingRange();
}

/// n seeded uniform lights over AddTestScene whose influence radius at the default cutoff
/// is `radius`.
inline void MakeTestLights(vtkClusteredLightSet* lights, int n, double radius, unsigned seed)
{
  ClusteredLightingScenes::LightParameters params;
  params.TargetRadius = radius;
  const double lo[3] = { -3, -0.9, -3 }, hi[3] = { 3, 1.8, 3 };
  ClusteredLightingScenes::MakeLights(
    lights, n, ClusteredLightingScenes::Layout::Uniform, lo, hi, params, seed);
}

/// Renders the scene with VTK's own lighting (no pass), then with `pass`; returns both
/// images (the pass stays set).
inline void RenderStockThenClustered(vtkRenderWindow* rw, vtkRenderer* ren,
  vtkClusteredLightingPass* pass, std::vector<float>& stock, std::vector<float>& clustered)
{
  ren->SetPass(nullptr);
  rw->Render();
  stock = CapturePixels(rw);
  ren->SetPass(pass);
  rw->Render();
  clustered = CapturePixels(rw);
}

struct ImageComparison
{
  double MaxAbsError = 0.0;
  double RMSE = 0.0;
  double FractionOverOneStep = 0.0; ///< share of pixels off by more than 1/255 in a channel
  std::size_t Pixels = 0;
};

inline ImageComparison CompareImages(const std::vector<float>& a, const std::vector<float>& b)
{
  ImageComparison c;
  if (a.size() != b.size() || a.empty())
  {
    c.MaxAbsError = 1e30;
    return c;
  }
  double sum = 0.0;
  std::size_t over = 0;
  c.Pixels = a.size() / 3;
  for (std::size_t p = 0; p < c.Pixels; ++p)
  {
    double worst = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double d = std::abs(double(a[3 * p + k]) - double(b[3 * p + k]));
      worst = std::max(worst, d);
      sum += d * d;
    }
    c.MaxAbsError = std::max(c.MaxAbsError, worst);
    over += worst > 1.5 / 255.0 ? 1 : 0;
  }
  c.RMSE = std::sqrt(sum / (3.0 * c.Pixels));
  c.FractionOverOneStep = double(over) / c.Pixels;
  return c;
}

inline void PrintComparison(const char* what, const ImageComparison& c)
{
  std::printf("%s: max abs error %.5f (%.2f steps), RMSE %.6f, pixels over one step %.4f%%\n", what,
    c.MaxAbsError, c.MaxAbsError * 255.0, c.RMSE, 100.0 * c.FractionOverOneStep);
}

/// Compares the GPU assignment of the last render with the double-precision reference.
inline vtkClusteredLighting::AssignmentComparison CheckAssignment(
  vtkClusteredLightingPass* pass, vtkRenderer* ren, const char* what)
{
  vtkClusteredLighting::AssignmentComparison cmp;
  vtkClusteredLightingInspector inspect(pass);
  const vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(ren);
  std::vector<std::uint32_t> list, master;
  if (!frame.Valid || (frame.Layout.Batches == 0 && !frame.Lights.empty()) ||
    !inspect.ReadBackAssignment(ren, list, master))
  {
    std::printf("%s: no clustered assignment to check (render in clustered mode first)\n", what);
    cmp.FalseNegatives = ~0ull;
    return cmp;
  }
  const auto ref = vtkClusteredLighting::ComputeReferenceAssignment(
    vtkClusteredLightingInspector::ComputeLightsVC(frame), frame.Grid, frame.VCDC,
    frame.Grid.NearVC, frame.Grid.GetMaxFragmentDepth());
  cmp = vtkClusteredLighting::CompareWithReference(ref, list, master, frame.Layout, frame.Grid);
  std::printf("%s: %llu reference pairs, %llu GPU pairs, false negatives %llu, "
              "false-positive rate %.3f, master mismatches %llu%s%s\n",
    what, static_cast<unsigned long long>(cmp.ReferencePairs),
    static_cast<unsigned long long>(cmp.GPUPairs),
    static_cast<unsigned long long>(cmp.FalseNegatives), cmp.GetFalsePositiveRate(),
    static_cast<unsigned long long>(cmp.MasterMismatches),
    cmp.FirstFalseNegative.empty() ? "" : ", first: ", cmp.FirstFalseNegative.c_str());
  return cmp;
}

/// Window depth ([0,1], 1 = background) of a renderer's viewport, row-major from bottom.
inline std::vector<float> CaptureDepth(vtkRenderWindow* rw, vtkRenderer* ren, int& w, int& h)
{
  int x0, y0;
  ren->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  std::vector<float> z(static_cast<std::size_t>(w) * h);
  rw->GetZbufferData(x0, y0, x0 + w - 1, y0 + h - 1, z.data());
  return z;
}

/// View-space point of pixel (x, y) of a viewport at window depth z.
inline glm::dvec3 UnprojectPixel(
  int x, int y, double z, int w, int h, const glm::dmat4& inverseVCDC)
{
  const glm::dvec4 ndc(2.0 * (x + 0.5) / w - 1.0, 2.0 * (y + 0.5) / h - 1.0, 2.0 * z - 1.0, 1.0);
  const glm::dvec4 p = inverseVCDC * ndc;
  return glm::dvec3(p) / p.w;
}

struct BruteForceCheck
{
  std::size_t Pixels = 0;
  std::size_t Violations = 0; ///< pixels whose error exceeds their derived tolerance
  double MaxError = 0.0;      ///< largest |clustered - brute force| (any channel)
  double MaxTolerance = 0.0;  ///< largest derived tolerance
  double MeanTail = 0.0;      ///< mean cutoff tail bound over geometry pixels
  ImageComparison Image;
};

/**
 * Renders the current scene with clustered shading and with brute force, and checks every
 * pixel: |clustered - brute| <= material * (sum of cut tails at the pixel) + rounding.
 * The tail is computed in double precision from the depth buffer (opaque surface). With
 * raySamples > 0 the tail is instead maximized over that many points along the pixel ray
 * up to the opaque surface (for translucent surfaces in front of it). The pass is left
 * in clustered mode, rendered.
 */
inline BruteForceCheck CheckAgainstBruteForce(vtkClusteredLightingPass* pass, vtkRenderWindow* rw,
  vtkRenderer* ren, double materialFactor, const char* what, int raySamples = 0)
{
  BruteForceCheck out;
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
  rw->Render();
  const std::vector<float> clustered = CapturePixels(rw);
  vtkClusteredLightingInspector inspect(pass);
  vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(ren);
  // Surface positions come from the depth buffer. At far/near ratios beyond 1e3 a 24-bit
  // depth quantum spans a large depth interval, so they are taken from one more render
  // with near = far / 1e3 (the test scenes have no geometry closer than that); the light
  // records (view coordinates) do not depend on the clipping range.
  vtkCamera* camera = ren->GetActiveCamera();
  double range[2];
  camera->GetClippingRange(range);
  int w = 0, h = 0;
  std::vector<float> depth;
  if (range[1] / range[0] > 1e3)
  {
    // Fragments up to GetMaxFragmentDepth() can show in the extreme render.
    camera->SetClippingRange(range[1] / 1e3, frame.Grid.GetMaxFragmentDepth());
    rw->Render();
    depth = CaptureDepth(rw, ren, w, h);
    frame.VCDC = inspect.GetFrame(ren).VCDC;
    camera->SetClippingRange(range);
  }
  else
  {
    depth = CaptureDepth(rw, ren, w, h);
  }
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
  rw->Render();
  const std::vector<float> brute = CapturePixels(rw);
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
  rw->Render(); // leave the pass's state (and the frame state) in clustered mode
  out.Image = CompareImages(clustered, brute);

  int x0, y0, ww, wh;
  ren->GetTiledSizeAndOrigin(&ww, &wh, &x0, &y0);
  const int windowWidth = rw->GetSize()[0];
  std::vector<glm::dvec3> centers;
  for (const auto& l : vtkClusteredLightingInspector::ComputeLightsVC(frame))
  {
    centers.push_back(l.CenterVC);
  }
  const bool windowed = pass->GetFalloff() == vtkClusteredLightingPass::FALLOFF_WINDOWED;
  const glm::dmat4 inverse = glm::inverse(frame.VCDC);
  const double rounding = 1.5 / 255.0;
  double tailSum = 0.0;
  std::size_t geometry = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const float z = depth[static_cast<std::size_t>(y) * w + x];
      double tail = 0.0;
      if (z < 1.0f || raySamples > 0)
      {
        const int n = raySamples > 0 ? raySamples : 1;
        for (int k = 0; k < n; ++k)
        {
          const double zk = raySamples > 0 ? z * (k + 1.0) / n : z;
          const glm::dvec3 p = UnprojectPixel(x, y, zk, w, h, inverse);
          const glm::dvec3 t =
            vtkClusteredLighting::ComputeCutoffTailBound(p, frame.Lights, centers, windowed);
          tail = std::max(tail, std::max(t.x, std::max(t.y, t.z)) * materialFactor);
        }
        tailSum += tail;
        ++geometry;
      }
      const double tolerance = tail * 1.001 + rounding;
      const std::size_t pi = 3 * (static_cast<std::size_t>(y + y0) * windowWidth + (x + x0));
      double err = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        err = std::max(err, std::abs(double(clustered[pi + c]) - double(brute[pi + c])));
      }
      out.MaxError = std::max(out.MaxError, err);
      out.MaxTolerance = std::max(out.MaxTolerance, tolerance);
      out.Violations += err > tolerance ? 1 : 0;
      if (err > tolerance && std::getenv("CL_VIOLATIONS") && out.Violations < 12)
      {
        std::printf("  violation at (%d, %d): error %.2f steps, tolerance %.2f, depth %.7f\n", x, y,
          err * 255, tolerance * 255, double(z));
      }
      ++out.Pixels;
    }
  }
  out.MeanTail = geometry ? tailSum / geometry : 0.0;
  std::printf("%s: clustered vs brute force: max error %.2f steps, RMSE %.5f, %.2f%% pixels over "
              "one step; derived tolerance up to %.2f steps (mean cutoff tail %.3f steps); "
              "%zu of %zu pixels over their tolerance\n",
    what, out.MaxError * 255.0, out.Image.RMSE, 100.0 * out.Image.FractionOverOneStep,
    out.MaxTolerance * 255.0, out.MeanTail * 255.0, out.Violations, out.Pixels);
  return out;
}

/// Number of pixels whose lit colour is NaN or Inf (DEBUG_NON_FINITE view).
inline std::size_t CountNonFinitePixels(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  const int previous = pass->GetDebugView();
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NON_FINITE);
  rw->Render();
  const std::vector<float> px = CapturePixels(rw);
  pass->SetDebugView(previous);
  std::size_t n = 0;
  for (std::size_t i = 0; i < px.size(); i += 3)
  {
    n += (px[i] > 0.99f && px[i + 1] < 0.01f && px[i + 2] < 0.01f) ? 1 : 0;
  }
  return n;
}

/**
 * The checks every clustered frame must pass (after a render): zero false negatives and
 * master mismatches of the GPU assignment against the double-precision reference; every
 * pixel within the derived bound of brute force (CheckAgainstBruteForce, same arguments);
 * no NaN or Inf pixel. Returns the number of failed checks.
 */
inline int CheckClusteredFrame(vtkClusteredLightingPass* pass, vtkRenderWindow* rw,
  vtkRenderer* ren, double materialFactor, const char* what, int raySamples = 0)
{
  int failed = 0;
  const auto assignment = CheckAssignment(pass, ren, what);
  failed += (assignment.FalseNegatives != 0 || assignment.MasterMismatches != 0) ? 1 : 0;
  failed +=
    CheckAgainstBruteForce(pass, rw, ren, materialFactor, what, raySamples).Violations != 0 ? 1 : 0;
  const std::size_t nonFinite = CountNonFinitePixels(pass, rw);
  if (nonFinite != 0)
  {
    std::printf("%s: %zu non-finite pixels\n", what, nonFinite);
    ++failed;
  }
  return failed;
}

/**
 * Ends an image test: compares the window's last image with the test's baseline
 * (vtkRegressionTestImage) and combines it with the other checks' failure count.
 */
inline int FinishImageTest(int argc, char* argv[], vtkRenderWindow* rw, int failed)
{
  const int retVal = vtkRegressionTestImage(rw);
  if (retVal == vtkRegressionTester::DO_INTERACTOR)
  {
    return EXIT_SUCCESS;
  }
  return (retVal == vtkRegressionTester::PASSED && failed == 0) ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace ClusteredLightingTest

#endif
