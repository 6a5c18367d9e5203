// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the GL tests: scenes, image capture and comparison, and the
// comparison of read-back list/master textures with the double-precision reference.
#ifndef ClusteredLightingTestUtilities_h
#define ClusteredLightingTestUtilities_h

#include "ClusteredLightingImages.h"
#include "ClusteredLightingScenes.h"
#include "vtkClusteredLightingFarFieldBound.h"
#include "vtkClusteredLightingInspector.h"
#include "vtkClusteredLightingPass.h"
#include "vtkClusteredLightingReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStringOutputWindow.h"

#include <algorithm>
#include <cctype>
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

/// Everything VTK prints to its output window while this lives (errors of shaders that fail
/// to build, for one): Finish() puts the previous output window back and returns the text.
class OutputCapture
{
public:
  OutputCapture()
    : Previous(vtkOutputWindow::GetInstance())
  {
    vtkOutputWindow::SetInstance(this->Output);
  }
  ~OutputCapture() { this->Finish(); }
  OutputCapture(const OutputCapture&) = delete;
  OutputCapture& operator=(const OutputCapture&) = delete;

  std::string Finish()
  {
    if (this->Previous)
    {
      vtkOutputWindow::SetInstance(this->Previous);
      this->Previous = nullptr;
    }
    return this->Output->GetOutput();
  }

private:
  vtkNew<vtkStringOutputWindow> Output;
  vtkSmartPointer<vtkOutputWindow> Previous;
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

/// n seeded uniform lights in the box over AddTestScene, with the given parameters.
inline void MakeTestLights(vtkClusteredLightSet* lights, int n,
  const ClusteredLightingScenes::LightParameters& params, unsigned seed)
{
  const double lo[3] = { -3, -0.9, -3 }, hi[3] = { 3, 1.8, 3 };
  ClusteredLightingScenes::MakeLights(
    lights, n, ClusteredLightingScenes::Layout::Uniform, lo, hi, params, seed);
}

/// n seeded uniform lights over AddTestScene whose influence radius at the default cutoff
/// is `radius`.
inline void MakeTestLights(vtkClusteredLightSet* lights, int n, double radius, unsigned seed)
{
  ClusteredLightingScenes::LightParameters params;
  params.TargetRadius = radius;
  MakeTestLights(lights, n, params, seed);
}

/// n seeded uniform lights over AddTestScene as users write them (issue 11's dense scene):
/// VTK's inverse-square attenuation (1, 0, 8), no radius, `intensity` each.
inline void MakeUserLights(vtkClusteredLightSet* lights, int n, double intensity, unsigned seed)
{
  ClusteredLightingScenes::LightParameters params;
  params.Intensity = intensity;
  params.Quadratic = 8.0;
  MakeTestLights(lights, n, params, seed);
}

/// The brute-force image of the current scene; the pass is left in clustered mode,
/// rendered.
inline std::vector<float> CaptureBruteForce(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
  rw->Render();
  std::vector<float> brute = CapturePixels(rw);
  pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
  rw->Render();
  return brute;
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
    frame.Grid.NearVC, frame.Grid.GetMaxFragmentDepth(), &frame.DepthBounds);
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

/// The materials of a renderer's visible actors, as the far-field bound needs them.
inline std::vector<vtkClusteredLighting::FarFieldShadingPoint> CollectMaterials(vtkRenderer* ren)
{
  std::vector<vtkClusteredLighting::FarFieldShadingPoint> out;
  vtkActorCollection* actors = ren->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    if (!a->GetVisibility())
    {
      continue;
    }
    vtkProperty* p = a->GetProperty();
    double dc[3], sc[3];
    p->GetDiffuseColor(dc);
    p->GetSpecularColor(sc);
    vtkClusteredLighting::FarFieldShadingPoint m;
    m.Kd = p->GetDiffuse() * glm::dvec3(dc[0], dc[1], dc[2]);
    m.Ks = p->GetSpecular() * glm::dvec3(sc[0], sc[1], sc[2]);
    m.Power = p->GetSpecularPower();
    // The bound is linear in Kd and Ks with non-negative terms: materials of one specular
    // power merge into one with the largest Kd and Ks of each channel.
    auto same = std::find_if(out.begin(), out.end(),
      [&](const vtkClusteredLighting::FarFieldShadingPoint& o) { return o.Power == m.Power; });
    if (same == out.end())
    {
      out.push_back(m);
    }
    else
    {
      same->Kd = glm::max(same->Kd, m.Kd);
      same->Ks = glm::max(same->Ks, m.Ks);
    }
  }
  return out;
}

/**
 * A frame's far field as its build saw it (the near radii and the light tree, made again
 * from the snapshot's lights with the core's functions), for the stated bound. `frame`
 * must outlive it.
 */
struct SnapshotFarField
{
  explicit SnapshotFarField(const vtkClusteredLightingAssignmentSnapshot& frame)
    : Radii(vtkClusteredLighting::GetFarFieldNearRadii(frame.Lights))
    , Tree(vtkClusteredLighting::BuildFarFieldLightTree(frame.Lights, Radii))
    , Inputs{ &frame.FarField.Grid, &frame.Lights, &Radii, &Tree, frame.FarField.Grouping,
      frame.FarField.Order4Diffuse, frame.FarField.SpecularBins }
  {
  }
  SnapshotFarField(const SnapshotFarField&) = delete;
  SnapshotFarField& operator=(const SnapshotFarField&) = delete;

  const std::vector<double> Radii;
  const vtkClusteredLighting::FarFieldLightTree Tree;
  const vtkClusteredLighting::FarFieldBuildInputs Inputs;
};

/// The pass's DEBUG_NORMAL view of the window (view-space normals as colours, n * 0.5 +
/// 0.5), rendered and captured; the debug view is put back and the window rendered again.
inline std::vector<float> CaptureNormalView(vtkClusteredLightingPass* pass, vtkRenderWindow* rw)
{
  const int previous = pass->GetDebugView();
  pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NORMAL);
  rw->Render();
  std::vector<float> normals = CapturePixels(rw);
  pass->SetDebugView(previous);
  rw->Render();
  return normals;
}

/**
 * The far field's stated bound (vtkClusteredLightingFarFieldBound.h) at every pixel of a
 * renderer's viewport, largest channel, in colour units, row-major from the bottom (0 off
 * the geometry and without a far field). Positions come from `depth` (opaque surfaces),
 * normals from a DEBUG_NORMAL render (8-bit, so 5% is added), the material is the worst of
 * the renderer's actors (CollectMaterials, one per specular power). With raySamples > 0 the bound
 * is the largest over that many points along the ray up to the opaque surface, each with the
 * pixel's normal and its opposite (translucent layers in front). With `needed`, only the pixels it
 * marks (others stay 0). `normalView`, when given, is the caller's CaptureNormalView of
 * this frame (not rendered again).
 */
inline std::vector<double> ComputeFarFieldBounds(vtkClusteredLightingPass* pass,
  vtkRenderWindow* rw, vtkRenderer* ren, const vtkClusteredLightingAssignmentSnapshot& frame,
  const std::vector<float>& depth, int w, int h, const glm::dmat4& inverseVCDC, int raySamples,
  const std::vector<char>* needed = nullptr, const std::vector<float>* normalView = nullptr)
{
  std::vector<double> bounds(static_cast<std::size_t>(w) * h, 0.0);
  if (!frame.FarField.Active)
  {
    return bounds;
  }
  std::vector<float> rendered;
  if (!normalView)
  {
    rendered = CaptureNormalView(pass, rw);
  }
  const std::vector<float>& normals = normalView ? *normalView : rendered;

  const SnapshotFarField farField(frame);
  const vtkClusteredLighting::FarFieldBuildInputs& in = farField.Inputs;
  const std::vector<vtkClusteredLighting::FarFieldShadingPoint> materials = CollectMaterials(ren);
  const glm::dmat4 worldFromVC = glm::inverse(frame.WCVC);
  const glm::dmat3 directionToWorld(worldFromVC);
  const bool parallel = ren->GetActiveCamera()->GetParallelProjection() != 0;
  int x0, y0, ww, wh;
  ren->GetTiledSizeAndOrigin(&ww, &wh, &x0, &y0);
  const int windowWidth = rw->GetSize()[0];
  vtkSMPThreadLocal<vtkClusteredLighting::FarFieldBoundCache> caches;
  vtkSMPTools::For(0, h,
    [&](vtkIdType yBegin, vtkIdType yEnd)
    {
      vtkClusteredLighting::FarFieldBoundCache& cache = caches.Local();
      for (int y = static_cast<int>(yBegin); y < static_cast<int>(yEnd); ++y)
      {
        for (int x = 0; x < w; ++x)
        {
          const float z = depth[static_cast<std::size_t>(y) * w + x];
          if ((!(z < 1.0f) && raySamples <= 0) ||
            (needed && !(*needed)[static_cast<std::size_t>(y) * w + x]))
          {
            continue;
          }
          const std::size_t pi = 3 * (static_cast<std::size_t>(y + y0) * windowWidth + (x + x0));
          glm::dvec3 n(
            2.0 * normals[pi] - 1.0, 2.0 * normals[pi + 1] - 1.0, 2.0 * normals[pi + 2] - 1.0);
          n = glm::length(n) > 0.5 ? glm::normalize(n) : glm::dvec3(0.0, 0.0, 1.0);
          double bound = 0.0;
          const int samples = raySamples > 0 ? raySamples : 1;
          for (int k = 0; k < samples; ++k)
          {
            const double zk = raySamples > 0 ? z * (k + 1.0) / samples : z;
            const glm::dvec3 p = UnprojectPixel(x, y, zk, w, h, inverseVCDC);
            const glm::dvec3 v = parallel ? glm::dvec3(0.0, 0.0, 1.0) : -glm::normalize(p);
            for (int side = 0; side < (raySamples > 0 ? 2 : 1); ++side)
            {
              const glm::dvec3 nv = side ? -n : n;
              const glm::dvec3 r = 2.0 * glm::dot(nv, v) * nv - v;
              for (vtkClusteredLighting::FarFieldShadingPoint s : materials)
              {
                s.P = glm::dvec3(worldFromVC * glm::dvec4(p, 1.0));
                s.N = glm::normalize(directionToWorld * nv);
                s.R = glm::normalize(directionToWorld * r);
                const glm::dvec3 b = vtkClusteredLighting::ComputeFarFieldErrorBound(s, in, &cache);
                bound = std::max(bound, std::max(b.x, std::max(b.y, b.z)));
              }
            }
          }
          bounds[static_cast<std::size_t>(y) * w + x] = 1.05 * bound;
        }
      }
    });
  return bounds;
}

struct BruteForceCheck
{
  std::size_t Pixels = 0;
  std::size_t Violations = 0; ///< pixels whose error exceeds their derived tolerance
  double MaxError = 0.0;      ///< largest |clustered - brute force| (any channel)
  double MaxTolerance = 0.0;  ///< largest derived tolerance
  double MeanTail = 0.0;      ///< mean cutoff tail bound over geometry pixels
  double MeanFarField = 0.0;  ///< mean far-field bound over geometry pixels
  double MaxFarField = 0.0;   ///< largest far-field bound
  double WorstRatio = 0.0;    ///< largest error / tolerance (how close the tightest pixel is)
  ImageComparison Image;
};

/**
 * Renders the current scene with clustered shading and with brute force, and checks every
 * pixel: |clustered - brute| <= material * (sum of cut tails at the pixel) + the far
 * field's stated bound at the pixel (ComputeFarFieldBounds) + rounding. The tail is
 * computed in double precision from the depth buffer (opaque surface). With raySamples >
 * 0 both are instead maximized over that many points along the pixel ray up to the opaque
 * surface (for translucent surfaces in front of it). The far-field bound is computed only
 * where the error exceeds the rest of the tolerance (and on a sparse grid of pixels for
 * the printed statistics), since elsewhere no bound can fail the pixel; with
 * `tolerances` it is computed at every pixel, and each pixel's tolerance (in the
 * renderer's viewport, row by row) is returned there. The pass is left in clustered mode,
 * rendered.
 */
inline BruteForceCheck CheckAgainstBruteForce(vtkClusteredLightingPass* pass, vtkRenderWindow* rw,
  vtkRenderer* ren, double materialFactor, const char* what, int raySamples = 0,
  std::vector<double>* tolerances = nullptr)
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
  // The pass's state (and the frame state) is left in clustered mode.
  const std::vector<float> brute = CaptureBruteForce(pass, rw);
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
  // 1. Error and cutoff tail at every pixel.
  const std::size_t count = static_cast<std::size_t>(w) * h;
  std::vector<double> errors(count, 0.0), tails(count, 0.0);
  std::vector<char> onGeometry(count, 0);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const float z = depth[i];
      if (z < 1.0f || raySamples > 0)
      {
        const int n = raySamples > 0 ? raySamples : 1;
        for (int k = 0; k < n; ++k)
        {
          const double zk = raySamples > 0 ? z * (k + 1.0) / n : z;
          const glm::dvec3 p = UnprojectPixel(x, y, zk, w, h, inverse);
          const glm::dvec3 t =
            vtkClusteredLighting::ComputeCutoffTailBound(p, frame.Lights, centers, windowed);
          tails[i] = std::max(tails[i], std::max(t.x, std::max(t.y, t.z)) * materialFactor);
        }
        onGeometry[i] = 1;
      }
      const std::size_t pi = 3 * (static_cast<std::size_t>(y + y0) * windowWidth + (x + x0));
      for (int c = 0; c < 3; ++c)
      {
        errors[i] =
          std::max(errors[i], std::abs(double(clustered[pi + c]) - double(brute[pi + c])));
      }
    }
  }
  // 2. The far field's bound (costly: a pass over the light tree per point) where the
  // error exceeds the tail and rounding, and on every 8th pixel of every 8th row for the
  // statistics. Elsewhere a bound >= 0 cannot change the verdict.
  std::vector<char> needed(count, 0);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      needed[i] =
        (tolerances || errors[i] > tails[i] * 1.001 + rounding || (x % 8 == 0 && y % 8 == 0)) ? 1
                                                                                              : 0;
    }
  }
  const std::vector<double> farBounds =
    ComputeFarFieldBounds(pass, rw, ren, frame, depth, w, h, inverse, raySamples, &needed);
  // 3. The verdict per pixel.
  if (tolerances)
  {
    tolerances->assign(count, 0.0);
  }
  double tailSum = 0.0, farSum = 0.0;
  std::size_t geometry = 0, sampled = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (onGeometry[i])
      {
        tailSum += tails[i];
        ++geometry;
      }
      const double far = farBounds[i];
      if (x % 8 == 0 && y % 8 == 0 && onGeometry[i])
      {
        farSum += far;
        ++sampled;
      }
      out.MaxFarField = std::max(out.MaxFarField, far);
      const double tolerance = tails[i] * 1.001 + far + rounding;
      if (tolerances)
      {
        (*tolerances)[i] = tolerance;
      }
      const double err = errors[i];
      out.MaxError = std::max(out.MaxError, err);
      out.MaxTolerance = std::max(out.MaxTolerance, tolerance);
      out.WorstRatio = std::max(out.WorstRatio, err / tolerance);
      out.Violations += err > tolerance ? 1 : 0;
      if (err > tolerance && std::getenv("CL_VIOLATIONS") && out.Violations < 12)
      {
        std::printf("  violation at (%d, %d): error %.2f steps, tolerance %.2f (far field %.2f), "
                    "depth %.7f\n",
          x, y, err * 255, tolerance * 255, far * 255, double(depth[i]));
      }
      ++out.Pixels;
    }
  }
  if (const char* dir = std::getenv("CL_DEBUG_IMAGES"))
  {
    // Debugging aid: the two images and their difference (x 16) as PNG files.
    std::string name = what;
    for (char& ch : name)
    {
      ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    }
    std::vector<float> diff(clustered.size());
    for (std::size_t i = 0; i < diff.size(); ++i)
    {
      diff[i] = 16.0f * std::abs(clustered[i] - brute[i]);
    }
    const std::string base = std::string(dir) + "/" + name;
    ClusteredLightingImages::WriteRGBPNG(
      clustered, windowWidth, rw->GetSize()[1], base + "-clustered.png");
    ClusteredLightingImages::WriteRGBPNG(brute, windowWidth, rw->GetSize()[1], base + "-brute.png");
    ClusteredLightingImages::WriteRGBPNG(diff, windowWidth, rw->GetSize()[1], base + "-diff16.png");
  }
  out.MeanTail = geometry ? tailSum / geometry : 0.0;
  out.MeanFarField = sampled ? farSum / sampled : 0.0;
  std::printf("%s: clustered vs brute force: max error %.2f steps, RMSE %.5f, %.2f%% pixels over "
              "one step; derived tolerance up to %.2f steps (mean cutoff tail %.3f steps, "
              "far-field bound mean %.3f, max %.2f steps, on 1/64 of the pixels and wherever "
              "needed); %zu of %zu pixels over their tolerance (the closest at %.2f of it)\n",
    what, out.MaxError * 255.0, out.Image.RMSE, 100.0 * out.Image.FractionOverOneStep,
    out.MaxTolerance * 255.0, out.MeanTail * 255.0, out.MeanFarField * 255.0,
    out.MaxFarField * 255.0, out.Violations, out.Pixels, out.WorstRatio);
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
 * no NaN or Inf pixel. Returns the number of failed checks; `comparison`, when given,
 * receives the brute-force comparison.
 */
inline int CheckClusteredFrame(vtkClusteredLightingPass* pass, vtkRenderWindow* rw,
  vtkRenderer* ren, double materialFactor, const char* what, int raySamples = 0,
  BruteForceCheck* comparison = nullptr)
{
  int failed = 0;
  const auto assignment = CheckAssignment(pass, ren, what);
  failed += (assignment.FalseNegatives != 0 || assignment.MasterMismatches != 0) ? 1 : 0;
  const BruteForceCheck check =
    CheckAgainstBruteForce(pass, rw, ren, materialFactor, what, raySamples);
  failed += check.Violations != 0 ? 1 : 0;
  if (comparison)
  {
    *comparison = check;
  }
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
