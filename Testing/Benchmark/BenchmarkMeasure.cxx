// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkMeasure.h"

#include "ClusteredLightingImages.h"
#include "ClusteredLightingScenes.h"
#include "ClusteredLightingTestUtilities.h"
#include "vtkClusteredLightingInspector.h"

#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkMapper.h"
#include "vtkOBJImporter.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <sstream>

namespace ClusteredLightingBenchmark
{

namespace
{
std::string HousePath()
{
  return ClusteredLightingScenes::DataPath(
    "house.obj", CLUSTERED_LIGHTING_BUILD_DATA_DIR "/house.obj");
}

std::string Num(double v)
{
  if (std::isnan(v))
  {
    return "";
  }
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}
}

//------------------------------------------------------------------------------
// CPU time of the calling thread, ms (POSIX; the benchmark runs on Linux).
double ThreadCpuMs()
{
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

//------------------------------------------------------------------------------
double Median(std::vector<double> v)
{
  return ClusteredLightingScenes::Median(std::move(v));
}

//------------------------------------------------------------------------------
// The row's error statistics against the reference; with `perPixel`, each pixel's largest
// channel error too (colour units).
void CompareWithReference(const std::vector<float>& img, const std::vector<float>& ref, Row& row,
  std::vector<double>* perPixel = nullptr)
{
  if (img.size() != ref.size() || ref.empty())
  {
    return;
  }
  if (perPixel)
  {
    perPixel->resize(ref.size() / 3);
  }
  double maxErr = 0.0, sum = 0.0, signedSum = 0.0;
  std::size_t over = 0;
  const std::size_t pixels = ref.size() / 3;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double signedDiff = double(img[3 * p + c]) - double(ref[3 * p + c]);
      const double d = std::abs(signedDiff);
      worst = std::max(worst, d);
      sum += d * d;
      signedSum += signedDiff;
    }
    maxErr = std::max(maxErr, worst);
    over += worst > 1.5 / 255.0 ? 1 : 0;
    if (perPixel)
    {
      (*perPixel)[p] = worst;
    }
  }
  row.MaxError = maxErr;
  row.RMSE = std::sqrt(sum / (3.0 * pixels));
  row.OverOneStep = double(over) / pixels;
  row.SignedError = signedSum / (3.0 * pixels);
}

//------------------------------------------------------------------------------
Context::Context(int width, int height)
{
  this->Window->SetSize(width, height);
  this->Window->SetMultiSamples(0);
  this->Window->SetOffScreenRendering(1);
  this->Renderer->SetBackground(0.02, 0.02, 0.03);
  this->Renderer->AutomaticLightCreationOff();
  this->Window->AddRenderer(this->Renderer);
  this->Pass->AddLightSet(this->Lights);
  this->Renderer->SetPass(this->Pass);
}

//------------------------------------------------------------------------------
long long Context::LoadScene(const Scene& scene, bool quick)
{
  this->Renderer->RemoveAllViewProps();
  this->Current = &scene;
  this->Reference.clear();
  if (scene.Name == "bunny")
  {
    vtkSmartPointer<vtkPolyData> bunny = ClusteredLightingScenes::LoadBunny(quick ? 0 : 2);
    if (!bunny)
    {
      return -1;
    }
    ClusteredLightingScenes::AddBunnyScene(this->Renderer, bunny);
    return bunny->GetNumberOfPolys() + 2;
  }
  const std::string obj = HousePath();
  if (!vtksys::SystemTools::FileExists(obj))
  {
    return -1;
  }
  vtkNew<vtkOBJImporter> importer;
  importer->SetFileName(obj.c_str());
  const std::string mtl = obj.substr(0, obj.size() - 4) + ".mtl";
  importer->SetFileNameMTL(mtl.c_str());
  importer->SetRenderWindow(this->Window);
  importer->Update();
  long long triangles = 0;
  vtkActorCollection* actors = this->Renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    if (vtkPolyData* pd = vtkPolyData::SafeDownCast(a->GetMapper()->GetInputDataObject(0, 0)))
    {
      triangles += pd->GetNumberOfPolys();
    }
    a->GetProperty()->SetSpecular(0.0);
  }
  return triangles;
}

//------------------------------------------------------------------------------
void Context::SetView()
{
  vtkCamera* cam = this->Renderer->GetActiveCamera();
  cam->SetPosition(this->Current->CameraPosition);
  cam->SetFocalPoint(this->Current->CameraFocalPoint);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(this->Current->ViewAngle);
  this->Renderer->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
void Context::MakeLights(int n, const std::string& layout)
{
  this->RemoveRendererLights();
  this->Layout = layout;
  ClusteredLightingScenes::LightParameters params;
  params.Intensity = this->Current->Intensity;
  params.TargetRadius = this->Current->Radius;
  if (layout == "dense")
  {
    params.Intensity = 1.0;
    params.Quadratic = 8.0;
  }
  using ClusteredLightingScenes::Layout;
  const Layout kind = layout == "clumped" ? Layout::Clumped
    : layout == "hard"                    ? Layout::Hard
                                          : Layout::Uniform;
  ClusteredLightingScenes::MakeLights(this->Lights, n, kind, this->Current->LightBoxLo,
    this->Current->LightBoxHi, params, 7, this->Current->CameraPosition);
  if (layout == "always-on")
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      this->Lights->SetIntensity(i, 0.005);
      this->Lights->SetAttenuation(i, 1.0, 0.0, 0.0);
    }
    this->AddStockLights(this->RendererLights);
    this->Lights->SetNumberOfLights(0);
  }
}

//------------------------------------------------------------------------------
void Context::RemoveRendererLights()
{
  for (auto& l : this->RendererLights)
  {
    this->Renderer->RemoveLight(l);
  }
  this->RendererLights.clear();
}

//------------------------------------------------------------------------------
void Context::ResetPassDefaults()
{
  vtkClusteredLightingPass* p = this->Pass;
  p->SetCutoff(1.0 / 1024.0);
  p->SetFarFieldCutoff(1.0 / 256.0);
  p->SetErrorBudget(0.0);
  p->SetFarField(true);
  p->SetFarFieldResolution(32768);
  p->SetFarFieldCellsPerRadius(2.0);
  p->SetFarFieldTolerance(2.0 / 255.0);
  p->SetFarFieldExactSumLimit(16384);
  p->SetFarFieldGrouping(1.0);
  p->SetFarFieldSharedColor(true);
  p->SetFarFieldOrder4Diffuse(true);
  p->SetFarFieldSpecularBins(false);
  p->SetFarFieldSkipEmptyBlocks(true);
  p->SetFarFieldRefineStillLights(true);
  p->SetFarFieldRefineLeastLights(16384);
  p->SetNearFieldBudget(8.0);
  p->SetFalloff(vtkClusteredLightingPass::FALLOFF_HARD_CUT);
  p->SetTilesX(32);
  p->SetTilesY(16);
  p->SetSlices(32);
  p->SetSlicingScheme(vtkClusteredLightingPass::SLICING_AUTO);
  p->SetBoundsMethod(vtkClusteredLightingPass::BOUNDS_TANGENT);
  p->SetMortonOrder(true);
  p->SetPerClusterCulling(true);
  p->SetSpotConeCulling(true);
  p->SetAutomaticBackfaceCulling(true);
  p->SetDepthPrepass(true);
  p->SetDepthAwareClusters(true);
  p->SetAutomaticDepthPrepass(false); // rows time the options as set; "automatic" rows turn it on
  p->SetReuseDepthPrepass(true);
  p->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
  p->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
}

//------------------------------------------------------------------------------
std::string Context::CheckPassDefaults()
{
  // The options as PrintSelf lists them, from ShadingMode to the last render's statistics,
  // less the effective cutoffs (results).
  auto options = [](vtkClusteredLightingPass* pass)
  {
    std::ostringstream all;
    pass->PrintSelf(all, vtkIndent());
    std::istringstream lines(all.str());
    std::vector<std::string> out;
    bool inside = false;
    for (std::string line; std::getline(lines, line);)
    {
      inside = inside || line.find("ShadingMode:") != std::string::npos;
      if (line.find("Last render:") != std::string::npos)
      {
        break;
      }
      if (inside && line.find("EffectiveCutoff:") == std::string::npos &&
        line.find("EffectiveFarFieldCutoff:") == std::string::npos)
      {
        out.push_back(line);
      }
    }
    return out;
  };
  this->ResetPassDefaults();
  vtkNew<vtkClusteredLightingPass> fresh;
  // Set apart on purpose: rows time the options as set (AutomaticDepthPrepass).
  fresh->SetAutomaticDepthPrepass(false);
  const std::vector<std::string> ours = options(this->Pass), theirs = options(fresh);
  std::string differences;
  for (std::size_t i = 0; i < std::max(ours.size(), theirs.size()); ++i)
  {
    const std::string a = i < ours.size() ? ours[i] : "", b = i < theirs.size() ? theirs[i] : "";
    if (a != b)
    {
      differences += "  reset: " + a + "\n  fresh: " + b + "\n";
    }
  }
  return differences;
}

//------------------------------------------------------------------------------
void Context::MakeReference()
{
  this->SetView();
  const int mode = this->Pass->GetShadingMode();
  this->Pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
  this->Window->Render();
  this->Reference = ClusteredLightingImages::CaptureRGB(this->Window);
  this->Pass->SetShadingMode(mode);
  int* size = this->Window->GetSize();
  std::vector<float> depth(static_cast<std::size_t>(size[0]) * size[1]);
  this->Window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth.data());
  this->Geometry.assign(depth.size(), 0);
  for (std::size_t i = 0; i < depth.size(); ++i)
  {
    this->Geometry[i] = depth[i] < 1.0f ? 1 : 0;
  }
}

//------------------------------------------------------------------------------
// A diagnostic: the k pixels farthest from the reference (largest channel), each with its
// place (pixel, depth, world point and normal), its channels against the reference, and
// the far field's stated bound there (the GL tests' per-pixel bound,
// ClusteredLightingTestUtilities.h), which tells the far field's error from the rest.
void Context::PrintWorstPixels(
  const Row& row, const std::vector<float>& img, const std::vector<double>& pixelErrors)
{
  const int* size = this->Window->GetSize();
  const std::size_t pixels = img.size() / 3;
  if (pixels != static_cast<std::size_t>(size[0]) * size[1] || pixelErrors.size() != pixels)
  {
    return;
  }
  std::vector<std::pair<double, std::size_t>> errors(pixels);
  std::size_t overTwo = 0;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    errors[p] = { pixelErrors[p], p };
    overTwo += pixelErrors[p] > 2.5 / 255.0 ? 1 : 0;
  }
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(this->WorstPixels), pixels);
  std::partial_sort(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(k), errors.end(),
    [](const auto& a, const auto& b) { return a.first > b.first; });

  vtkClusteredLightingInspector inspect(this->Pass);
  const vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(this->Renderer);
  int w = 0, h = 0;
  const std::vector<float> depth =
    ClusteredLightingTest::CaptureDepth(this->Window, this->Renderer, w, h);
  const std::vector<float> normals =
    ClusteredLightingTest::CaptureNormalView(this->Pass, this->Window);
  std::vector<char> needed(pixels, 0);
  for (std::size_t i = 0; i < k; ++i)
  {
    needed[errors[i].second] = 1;
  }
  const glm::dmat4 inverse = glm::inverse(frame.VCDC);
  const std::vector<double> bounds = ClusteredLightingTest::ComputeFarFieldBounds(
    this->Pass, this->Window, this->Renderer, frame, depth, w, h, inverse, 0, &needed, &normals);
  const glm::dmat4 worldFromVC = glm::inverse(frame.WCVC);
  std::printf("  worst pixels of %s/%s/%d/%s/%s/%s (8-bit steps; world point, view normal; "
              "%zu pixels more than 2 steps off):\n",
    row.Scene.c_str(), row.Layout.c_str(), row.Lights, row.Method.c_str(), row.Sweep.c_str(),
    row.Value.c_str(), overTwo);
  for (std::size_t i = 0; i < k; ++i)
  {
    const std::size_t p = errors[i].second;
    const int x = static_cast<int>(p % static_cast<std::size_t>(w));
    const int y = static_cast<int>(p / static_cast<std::size_t>(w));
    const glm::dvec3 vc = ClusteredLightingTest::UnprojectPixel(x, y, depth[p], w, h, inverse);
    const glm::dvec3 wc(worldFromVC * glm::dvec4(vc, 1.0));
    std::printf("    (%d, %d) depth %.6f: clustered %.1f %.1f %.1f, reference %.1f %.1f %.1f, "
                "bound %.2f; at (%.4g, %.4g, %.4g) normal (%.3f, %.3f, %.3f)\n",
      x, y, double(depth[p]), 255.0 * img[3 * p], 255.0 * img[3 * p + 1], 255.0 * img[3 * p + 2],
      255.0 * this->Reference[3 * p], 255.0 * this->Reference[3 * p + 1],
      255.0 * this->Reference[3 * p + 2], 255.0 * bounds[p], wc.x, wc.y, wc.z,
      2.0 * normals[3 * p] - 1.0, 2.0 * normals[3 * p + 1] - 1.0, 2.0 * normals[3 * p + 2] - 1.0);
  }
  std::fflush(stdout);
}

//------------------------------------------------------------------------------
void Context::MeasureCounts(Row& row)
{
  this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
  this->Window->Render();
  if (this->Window->GetMultiSamples() > 1)
  {
    // A multisampled window's image is resolved: an edge pixel's encoded count
    // (R + 256 G) would be averaged with the background's. The pass reads one sample of
    // each pixel itself; its reaching count is the same frame's blue channel (saturating at
    // 255). Per-pixel maxima over 8x4 tiles need the pixels: not measured here.
    row.Evaluated = this->Pass->GetMeanLightsEvaluatedPerPixel();
    row.Reached = this->Pass->GetMeanLightsReachingPerPixel();
    row.EvaluatedIn32 = NAN;
    this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
    return;
  }
  const std::vector<float> ev = ClusteredLightingImages::CaptureRGB(this->Window);
  this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_REACHED_COUNT);
  this->Window->Render();
  const std::vector<float> re = ClusteredLightingImages::CaptureRGB(this->Window);
  this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  auto count = [](const std::vector<float>& img, std::size_t p)
  {
    auto byte = [](float v) { return static_cast<int>(std::lround(v * 255.0f)); };
    return byte(img[3 * p]) + 256 * byte(img[3 * p + 1]);
  };
  double se = 0.0, sr = 0.0;
  std::size_t n = 0;
  for (std::size_t p = 0; p < this->Geometry.size(); ++p)
  {
    if (this->Geometry[p])
    {
      se += count(ev, p);
      sr += count(re, p);
      ++n;
    }
  }
  row.Evaluated = n ? se / n : NAN;
  row.Reached = n ? sr / n : NAN;
  // Each geometry pixel at the most evaluated geometry pixel of its 8x4 tile.
  const int* size = this->Window->GetSize();
  const int w = size[0], h = size[1];
  double s32 = 0.0;
  for (int y0 = 0; y0 < h; y0 += 4)
  {
    for (int x0 = 0; x0 < w; x0 += 8)
    {
      int most = 0, pixels = 0;
      for (int y = y0; y < std::min(y0 + 4, h); ++y)
      {
        for (int x = x0; x < std::min(x0 + 8, w); ++x)
        {
          const std::size_t p =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
          if (p < this->Geometry.size() && this->Geometry[p])
          {
            most = std::max(most, count(ev, p));
            ++pixels;
          }
        }
      }
      s32 += static_cast<double>(most) * pixels;
    }
  }
  row.EvaluatedIn32 = n ? s32 / n : NAN;
  if (this->MeasureFloor)
  {
    this->MeasureCullingFloor(row);
  }
}

//------------------------------------------------------------------------------
// The culling floor of the last assignment, from its snapshot (the pass's test hook) and
// the window's depth: the reference assignment in double precision, cut to the frame's
// depth-aware clusters, and per pixel the lights that reach its cluster's fragments.
void Context::MeasureCullingFloor(Row& row)
{
  vtkClusteredLightingInspector inspect(this->Pass);
  const vtkClusteredLightingAssignmentSnapshot frame = inspect.GetFrame(this->Renderer);
  if (!frame.Valid)
  {
    return;
  }
  const int* size = this->Window->GetSize();
  std::vector<float> depth(static_cast<std::size_t>(size[0]) * static_cast<std::size_t>(size[1]));
  this->Window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth.data());
  const vtkClusteredLighting::DepthImage image{ depth.data(), size[0], size[1] };
  const std::vector<vtkClusteredLighting::ReferenceLight> lights =
    vtkClusteredLightingInspector::ComputeLightsVC(frame);
  const vtkClusteredLighting::ReferenceAssignment ref =
    vtkClusteredLighting::ComputeReferenceAssignment(lights, frame.Grid, frame.VCDC,
      frame.Grid.NearVC, frame.Grid.GetMaxFragmentDepth(),
      frame.DepthBounds.Valid ? &frame.DepthBounds : nullptr);
  const vtkClusteredLighting::ClusterCullingFloor floor =
    vtkClusteredLighting::MeasureClusterCullingFloor(image, frame.VCDC, frame.Grid, lights, ref);
  if (floor.Pixels > 0)
  {
    row.CellsPerPixel = floor.Cells;
    row.FloorPerPixel = floor.Floor;
    std::printf("  culling floor: %.3f lights per pixel in exact cells, %.3f reaching some "
                "fragment of the cluster, %.3f reaching the pixel (the pass counted %.3f "
                "evaluated, %.3f reaching)\n",
      floor.Cells, floor.Floor, floor.Reaching, row.Evaluated, row.Reached);
  }
}

//------------------------------------------------------------------------------
// Stock VTK 9.1: the same lights as vtkLights of the renderer.
void Context::AddStockLights(std::vector<vtkSmartPointer<vtkLight>>& added)
{
  const vtkIdType n = this->Lights->GetNumberOfLights();
  for (vtkIdType i = 0; i < n; ++i)
  {
    vtkNew<vtkLight> l;
    l->SetLightTypeToSceneLight();
    l->SetPositional(true);
    l->SetConeAngle(180.0);
    double v[3];
    this->Lights->GetPosition(i, v);
    l->SetPosition(v);
    this->Lights->GetColor(i, v);
    l->SetColor(v);
    l->SetIntensity(this->Lights->GetIntensity(i));
    this->Lights->GetAttenuation(i, v);
    l->SetAttenuationValues(v);
    this->Renderer->AddLight(l);
    added.emplace_back(l);
  }
}

//------------------------------------------------------------------------------
// Animated lights: every light moves by a millimetre-scale offset that depends on the
// frame (frame -1 puts them back), so all of them change every frame.
void Context::NudgeLights(int frame)
{
  vtkClusteredLightSet* lights = this->Lights;
  const double delta = frame < 0 ? -this->Nudged : 1e-3 * ((frame % 2) ? 1.0 : -1.0);
  this->Nudged += delta;
  for (vtkIdType i = 0; i < lights->GetNumberOfLights(); ++i)
  {
    double p[3];
    lights->GetPosition(i, p);
    lights->SetPosition(i, p[0] + delta, p[1], p[2]);
  }
}

//------------------------------------------------------------------------------
Row Context::Measure(const Step& step)
{
  Row row;
  row.Scene = this->Current->Name;
  row.Layout = this->Layout;
  row.Method = step.Method;
  row.Sweep = step.Sweep;
  row.Value = step.Value;
  row.Lights = static_cast<int>(this->Lights->GetNumberOfLights() + this->RendererLights.size());
  row.Frames = step.Frames;
  row.Note = step.Note;
  const bool clustered = step.Method == "clustered";
  const bool stock = step.Method == "stock";
  std::vector<vtkSmartPointer<vtkLight>> stockLights;
  if (stock)
  {
    this->AddStockLights(stockLights);
    this->Renderer->SetPass(nullptr);
  }
  this->SetView();
  row.FirstFrameMs = ClusteredLightingScenes::TimeRender(this->Window); // shaders, assignment
  for (int f = 0; f < step.Warmup; ++f)
  {
    ClusteredLightingScenes::TimeRender(this->Window);
  }
  // The timed frames run as an application's would. The pass's timings of its parts
  // (MeasureTimings) put a glFinish between the parts and read an occlusion query back,
  // which stalls a GPU's pipeline, so they come from as many frames again, rendered
  // after the timed ones with MeasureTimings on; their median frame time is reported
  // too (InstrumentedMs), which shows what the stalls cost.
  const auto frame = [&](int f)
  {
    if (step.Moving)
    {
      this->Renderer->GetActiveCamera()->Azimuth(1.0);
      this->Renderer->ResetCameraClippingRange();
    }
    if (step.AnimateLights)
    {
      this->NudgeLights(f);
    }
    return ClusteredLightingScenes::TimeRender(this->Window);
  };
  std::vector<double> ms, cpu, instrumented, assign, update, shade, prepass, shaded, opaqueShaded,
    farBuild, farNodesBuilt;
  for (int f = 0; f < step.Frames; ++f)
  {
    const double cpu0 = ThreadCpuMs();
    ms.push_back(frame(f));
    cpu.push_back(ThreadCpuMs() - cpu0);
  }
  if (clustered)
  {
    this->Pass->SetMeasureTimings(true);
    for (int f = 0; f < step.Frames; ++f)
    {
      instrumented.push_back(frame(f));
      assign.push_back(
        this->Pass->GetLastAssignmentUpdated() ? this->Pass->GetLastAssignmentTime() : 0.0);
      update.push_back(this->Pass->GetLastLightUpdateTime());
      shade.push_back(this->Pass->GetLastShadingTime());
      prepass.push_back(this->Pass->GetLastDepthPrepassTime());
      shaded.push_back(this->Pass->GetShadedFragmentsPerVisiblePixel());
      opaqueShaded.push_back(this->Pass->GetShadedOpaqueFragmentsPerVisiblePixel());
      farBuild.push_back(this->Pass->GetLastFarFieldBuildTime());
      farNodesBuilt.push_back(static_cast<double>(this->Pass->GetNumberOfFarFieldNodesBuilt()));
    }
    this->Pass->SetMeasureTimings(false);
  }
  if (step.AnimateLights)
  {
    this->NudgeLights(-1); // back where the reference was rendered
  }
  row.MsMedian = Median(ms);
  row.CpuMs = Median(cpu);
  row.MsMin = *std::min_element(ms.begin(), ms.end());
  row.MsMax = *std::max_element(ms.begin(), ms.end());
  if (clustered)
  {
    row.InstrumentedMs = Median(instrumented);
    row.AssignMs = Median(assign);
    row.LightUpdateMs = Median(update);
    row.ShadeMs = Median(shade);
    row.PrepassMs = Median(prepass);
    if (this->Pass->GetAutomaticDepthPrepass())
    {
      std::ostringstream note;
      note << "trial: with / without prepass " << this->Pass->GetDepthPrepassTrialRatio()
           << "; chose " << (this->Pass->GetDepthPrepassUsed() ? "prepass" : "no prepass");
      row.Note = note.str();
    }
    row.ShadedPerVisible = Median(shaded);
    row.OpaqueShadedPerVisible = Median(opaqueShaded);
    if (this->Pass->GetNumberOfFarFieldLights() > 0)
    {
      row.FarBuildMs = Median(farBuild);
      row.FarBoundSteps = this->Pass->ComputeFarFieldErrorBound(); // in steps
      row.FarNodes = this->Pass->GetFarFieldResolutionInUse();
      row.FarNodesBuilt = Median(farNodesBuilt);
    }
    row.ListMiB = this->Pass->GetListTextureBytes() / 1048576.0;
    row.MasterMiB = this->Pass->GetMasterTextureBytes() / 1048576.0;
    row.LightsMiB = this->Pass->GetLightBufferBytes() / 1048576.0;
    row.Cutoff = this->Pass->GetEffectiveCutoff();
    row.FarCutoff = this->Pass->GetEffectiveFarFieldCutoff();
    row.Budget = this->Pass->GetErrorBudget() > 0.0 ? this->Pass->GetErrorBudget() : NAN;
    row.BudgetMet =
      std::isnan(row.Budget) ? NAN : (this->Pass->GetFarFieldErrorBudgetMet() ? 1 : 0);
  }
  this->SetView();
  this->Window->Render();
  const std::vector<float> image = ClusteredLightingImages::CaptureRGB(this->Window);
  const bool worst = clustered && this->WorstPixels > 0 && !this->Reference.empty();
  std::vector<double> pixelErrors;
  CompareWithReference(image, this->Reference, row, worst ? &pixelErrors : nullptr);
  if (worst)
  {
    this->PrintWorstPixels(row, image, pixelErrors);
  }
  if (clustered && step.Counts)
  {
    this->MeasureCounts(row);
  }
  if (stock)
  {
    for (auto& l : stockLights)
    {
      this->Renderer->RemoveLight(l);
    }
    this->Renderer->SetPass(this->Pass);
  }
  std::printf(
    "%-6s %-8s %6d %-9s %-9s %-14s %8.1f ms [%7.1f, %7.1f]  cpu %6s  instrumented %6s  assign %6s  "
    "lights %6s  "
    "eval/px %6s (in 32s %6s) reach/px %6s  max err %5s  rmse %7s  signed %7s  prepass %6s  "
    "shaded/px %5s (opaque %5s)  far build %6s bound %5s nodes %6s (built %6s)  culled %3s\n",
    row.Scene.c_str(), row.Layout.c_str(), row.Lights, row.Method.c_str(), row.Sweep.c_str(),
    row.Value.c_str(), row.MsMedian, row.MsMin, row.MsMax, Num(row.CpuMs).c_str(),
    Num(row.InstrumentedMs).c_str(), Num(row.AssignMs).c_str(), Num(row.LightUpdateMs).c_str(),
    Num(row.Evaluated).c_str(), Num(row.EvaluatedIn32).c_str(), Num(row.Reached).c_str(),
    Num(row.MaxError * 255.0).c_str(), Num(row.RMSE * 255.0).c_str(),
    Num(row.SignedError * 255.0).c_str(), Num(row.PrepassMs).c_str(),
    Num(row.ShadedPerVisible).c_str(), Num(row.OpaqueShadedPerVisible).c_str(),
    Num(row.FarBuildMs).c_str(), Num(row.FarBoundSteps).c_str(),
    (std::isnan(row.FarNodes) ? std::string() : std::to_string(std::llround(row.FarNodes))).c_str(),
    (std::isnan(row.FarNodesBuilt) ? std::string()
                                   : std::to_string(std::llround(row.FarNodesBuilt)))
      .c_str(),
    stock ? "" : std::to_string(this->Pass->GetNumberOfBackfaceCulledProps()).c_str());
  std::fflush(stdout);
  return row;
}

} // namespace ClusteredLightingBenchmark
