// SPDX-License-Identifier: BSD-3-Clause
// What accuracy costs in time: the ClusteredLighting benchmark.
//
// Renders fixed, seeded scenes at 1024x768 (real meshes: the Stanford bunny Loop-subdivided
// to about 1.1 M triangles, and the KIT FZK-Haus interior) with uniform, clumped and "hard"
// (lights at and around the camera) layouts, and for each configuration measures:
//  - frame time (median, min, max over >= 10 frames after warm-up, GL finished before the
//    clock is read), split into light assignment and shading;
//  - lights evaluated per pixel against lights that really reach the pixel;
//  - image error against the exact reference (brute force: every light, no cutoff): max
//    abs error, RMSE and the share of pixels off by more than one 8-bit step;
//  - GPU memory of the light records, list and master textures.
// Knobs are swept one at a time from the default (cutoff, falloff, tiles, slices, slicing,
// bounds, Morton order, per-cluster culling, spot code, specular, static camera, error
// budget); peers are measured in the same run: brute force, and stock VTK 9.1 with the same
// lights as vtkLights (as far as it compiles in reasonable time). Writes results.csv,
// results.md, pareto.png, scaling.png and machine.txt.
//
//   ClusteredLightingBenchmark [--quick] [--output DIR] [--frames N] [--check]
//                              [--snapshot SCENE FILE [--view px py pz fx fy fz angle]]
//
// --quick finishes in under 2 minutes (small window, fewer configurations); --check
// validates the written CSV (well-formed, finite, error budgets met) and sets the exit code.
#include "ClusteredLightingImages.h"
#include "ClusteredLightingScenes.h"

#include "vtkAxis.h"
#include "vtkCamera.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDoubleArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkOBJImporter.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPen.h"
#include "vtkPlot.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkTextureObject.h"
#include "vtkVersion.h"
#include "vtkWindowToImageFilter.h"
#include "vtk_glew.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace ClusteredLightingScenes;

namespace
{
//------------------------------------------------------------------------------ options
struct Options
{
  bool Quick = false;
  bool Check = false;
  int Width = 1024, Height = 768;
  int Frames = 10;
  std::string Output = "benchmark-results";
  std::string SnapshotScene, SnapshotFile;
  std::vector<double> View; ///< optional camera for --snapshot: position, focal point, angle
};

//------------------------------------------------------------------------------ scenes
struct Scene
{
  std::string Name;
  double CameraPosition[3];
  double CameraFocalPoint[3];
  double ViewAngle;
  double LightBoxLo[3], LightBoxHi[3];
  double Radius;    ///< influence radius at the default cutoff
  double Intensity; ///< per light
};

const Scene BunnyScene = { "bunny", { 0.0, 1.6, 4.6 }, { 0.0, -0.3, 0.0 }, 40.0,
  { -3.0, -0.98, -3.0 }, { 3.0, 1.0, 3.0 }, 0.35, 1.0 };
// Standing in the kitchen of the ground floor, looking at the spiral staircase; lights in
// both storeys of the house.
const Scene HouseScene = { "house", { 1.5, 1.6, -1.5 }, { 10.0, 1.0, -9.0 }, 70.0,
  { 0.2, 0.05, -9.8 }, { 11.8, 5.5, -0.2 }, 1.0, 1.0 };

std::string HousePath()
{
  return DataPath("house.obj", CLUSTERED_LIGHTING_BUILD_DATA_DIR "/house.obj");
}

/// Fills the renderer with a scene's geometry; returns the number of triangles.
vtkIdType LoadScene(const Scene& scene, vtkRenderer* ren, vtkRenderWindow* rw, bool quick)
{
  if (scene.Name == "bunny")
  {
    vtkSmartPointer<vtkPolyData> bunny = LoadBunny(quick ? 0 : 2);
    if (!bunny)
    {
      return -1;
    }
    AddBunnyScene(ren, bunny);
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
  importer->SetRenderWindow(rw);
  importer->Update();
  vtkIdType triangles = 0;
  vtkActorCollection* actors = ren->GetActors();
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

void SetView(const Scene& scene, vtkRenderer* ren)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(scene.CameraPosition);
  cam->SetFocalPoint(scene.CameraFocalPoint);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(scene.ViewAngle);
  ren->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------ results
struct Row
{
  std::string Scene, Layout, Method, Sweep, Value;
  int Lights = 0;
  int Frames = 0;
  double MsMedian = NAN, MsMin = NAN, MsMax = NAN;
  double AssignMs = NAN, ShadeMs = NAN, FirstFrameMs = NAN;
  double Evaluated = NAN, Reached = NAN;
  double MaxError = NAN, RMSE = NAN, OverOneStep = NAN;
  double ListMiB = NAN, MasterMiB = NAN, LightsMiB = NAN;
  double Cutoff = NAN, Budget = NAN;
  std::string Note;
};

const char* CSVHeader = "scene,layout,lights,method,sweep,value,frames,ms_median,ms_min,ms_max,"
                        "assign_ms,shade_ms,first_frame_ms,evaluated_px,reached_px,max_error,"
                        "rmse,over_one_step,list_mib,master_mib,lights_mib,cutoff,budget,note";

std::string Num(double v, int precision = 4)
{
  if (std::isnan(v))
  {
    return "";
  }
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

//------------------------------------------------------------------------------ images
void CompareWithReference(const std::vector<float>& img, const std::vector<float>& ref, Row& row)
{
  if (img.size() != ref.size() || ref.empty())
  {
    return;
  }
  double maxErr = 0.0, sum = 0.0;
  std::size_t over = 0;
  const std::size_t pixels = ref.size() / 3;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(double(img[3 * p + c]) - double(ref[3 * p + c]));
      worst = std::max(worst, d);
      sum += d * d;
    }
    maxErr = std::max(maxErr, worst);
    over += worst > 1.5 / 255.0 ? 1 : 0;
  }
  row.MaxError = maxErr;
  row.RMSE = std::sqrt(sum / (3.0 * pixels));
  row.OverOneStep = double(over) / pixels;
}

//------------------------------------------------------------------------------ context
struct Context
{
  Options Opt;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkClusteredLightingPass> Pass;
  vtkNew<vtkClusteredLightSet> Lights;
  vtkNew<vtkLight> Headlight;
  std::vector<Row> Rows;
  Scene Current;
  std::string Layout;
  std::vector<float> Reference;        ///< brute-force image of the current lights at the view
  std::vector<unsigned char> Geometry; ///< pixels showing geometry at the view

  void ResetPassDefaults()
  {
    vtkClusteredLightingPass* p = this->Pass;
    p->SetCutoff(1.0 / 1024.0);
    p->SetErrorBudget(0.0);
    p->SetFalloff(vtkClusteredLightingPass::FALLOFF_HARD_CUT);
    p->SetTilesX(32);
    p->SetTilesY(16);
    p->SetSlices(32);
    p->SetSlicingScheme(vtkClusteredLightingPass::SLICING_AUTO);
    p->SetBoundsMethod(vtkClusteredLightingPass::BOUNDS_TANGENT);
    p->SetMortonOrder(true);
    p->SetPerClusterCulling(true);
    p->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
    p->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
  }

  double TimeFrame() { return TimeRender(this->Window); }

  /// Lights evaluated and reaching, averaged over geometry pixels (debug views).
  void MeasureCounts(Row& row)
  {
    this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT);
    this->Window->Render();
    const std::vector<float> ev = ClusteredLightingImages::CaptureRGB(this->Window);
    this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_REACHED_COUNT);
    this->Window->Render();
    const std::vector<float> re = ClusteredLightingImages::CaptureRGB(this->Window);
    this->Pass->SetDebugView(vtkClusteredLightingPass::DEBUG_NONE);
    double se = 0.0, sr = 0.0;
    std::size_t n = 0;
    for (std::size_t p = 0; p < this->Geometry.size(); ++p)
    {
      if (!this->Geometry[p])
      {
        continue;
      }
      auto byte = [](float v) { return static_cast<int>(std::lround(v * 255.0f)); };
      se += byte(ev[3 * p]) + 256 * byte(ev[3 * p + 1]);
      sr += byte(re[3 * p]) + 256 * byte(re[3 * p + 1]);
      ++n;
    }
    row.Evaluated = n ? se / n : NAN;
    row.Reached = n ? sr / n : NAN;
  }

  /**
   * Times `frames` frames (after two warm-up frames) with the camera orbiting one degree
   * per frame (or still), then, back at the view, the image error against the reference
   * and (clustered) the per-pixel counts.
   */
  Row Measure(const std::string& method, const std::string& sweep, const std::string& value,
    int frames, bool moving = true, bool counts = true)
  {
    Row row;
    row.Scene = this->Current.Name;
    row.Layout = this->Layout;
    row.Method = method;
    row.Sweep = sweep;
    row.Value = value;
    row.Lights = static_cast<int>(this->Lights->GetNumberOfLights());
    row.Frames = frames;
    SetView(this->Current, this->Renderer);
    const bool clustered = method == "clustered";
    this->Pass->SetMeasureTimings(clustered);
    row.FirstFrameMs = this->TimeFrame(); // shader compilation, assignment
    this->TimeFrame();
    std::vector<double> ms, assign, shade;
    for (int f = 0; f < frames; ++f)
    {
      if (moving)
      {
        this->Renderer->GetActiveCamera()->Azimuth(1.0);
        this->Renderer->ResetCameraClippingRange();
      }
      ms.push_back(this->TimeFrame());
      if (clustered)
      {
        assign.push_back(
          this->Pass->GetLastAssignmentUpdated() ? this->Pass->GetLastAssignmentTime() : 0.0);
        shade.push_back(this->Pass->GetLastShadingTime());
      }
    }
    this->Pass->SetMeasureTimings(false);
    row.MsMedian = Median(ms);
    row.MsMin = *std::min_element(ms.begin(), ms.end());
    row.MsMax = *std::max_element(ms.begin(), ms.end());
    if (clustered)
    {
      row.AssignMs = Median(assign);
      row.ShadeMs = Median(shade);
      row.ListMiB = this->Pass->GetListTextureBytes() / 1048576.0;
      row.MasterMiB = this->Pass->GetMasterTextureBytes() / 1048576.0;
      row.LightsMiB = this->Pass->GetLightBufferBytes() / 1048576.0;
      row.Cutoff = this->Pass->GetEffectiveCutoff();
      row.Budget = this->Pass->GetErrorBudget() > 0.0 ? this->Pass->GetErrorBudget() : NAN;
    }
    SetView(this->Current, this->Renderer);
    this->Window->Render();
    CompareWithReference(ClusteredLightingImages::CaptureRGB(this->Window), this->Reference, row);
    if (clustered && counts)
    {
      this->MeasureCounts(row);
    }
    std::printf("%-6s %-8s %6d %-9s %-9s %-14s %8.1f ms [%7.1f, %7.1f]  assign %6s  eval/px %6s "
                "reach/px %6s  max err %5s  rmse %7s\n",
      row.Scene.c_str(), row.Layout.c_str(), row.Lights, method.c_str(), sweep.c_str(),
      value.c_str(), row.MsMedian, row.MsMin, row.MsMax, Num(row.AssignMs, 3).c_str(),
      Num(row.Evaluated, 3).c_str(), Num(row.Reached, 3).c_str(),
      Num(row.MaxError * 255.0, 3).c_str(), Num(row.RMSE * 255.0, 3).c_str());
    std::fflush(stdout);
    this->Rows.push_back(row);
    return row;
  }

  /// Brute-force reference image at the view (no timing) and the geometry mask.
  void MakeReference()
  {
    SetView(this->Current, this->Renderer);
    this->Pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
    this->Window->Render();
    this->Reference = ClusteredLightingImages::CaptureRGB(this->Window);
    this->Pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
    int* size = this->Window->GetSize();
    std::vector<float> depth(static_cast<std::size_t>(size[0]) * size[1]);
    this->Window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth.data());
    this->Geometry.assign(depth.size(), 0);
    for (std::size_t i = 0; i < depth.size(); ++i)
    {
      this->Geometry[i] = depth[i] < 1.0f ? 1 : 0;
    }
  }

  void MakeLights(int n, const std::string& layout, unsigned seed = 7)
  {
    this->Layout = layout;
    LightParameters params;
    params.Intensity = this->Current.Intensity;
    params.TargetRadius = this->Current.Radius;
    using ClusteredLightingScenes::Layout;
    const Layout kind = layout == "clumped" ? Layout::Clumped
      : layout == "hard"                    ? Layout::Hard
                                            : Layout::Uniform;
    ClusteredLightingScenes::MakeLights(this->Lights, n, kind, this->Current.LightBoxLo,
      this->Current.LightBoxHi, params, seed, this->Current.CameraPosition);
  }

  /// Stock VTK 9.1: the same lights as vtkLights, no pass.
  void MeasureStock(int frames)
  {
    const vtkIdType n = this->Lights->GetNumberOfLights();
    std::vector<vtkSmartPointer<vtkLight>> added;
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
    this->Renderer->SetPass(nullptr);
    Row& row =
      (this->Measure("stock", "count", std::to_string(n), frames, true, false), this->Rows.back());
    row.Note = "first frame compiles VTK's unrolled per-light shader";
    for (auto& l : added)
    {
      this->Renderer->RemoveLight(l);
    }
    this->Renderer->SetPass(this->Pass);
  }
};

//------------------------------------------------------------------------------ plots
void SavePlot(vtkContextView* view, const std::string& path)
{
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(900, 600);
  view->GetRenderWindow()->SetMultiSamples(0);
  view->Render();
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(view->GetRenderWindow());
  w2i->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(w2i->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
}

void AddSeries(vtkChartXY* chart, const std::vector<std::pair<double, double>>& xy,
  const char* name, int type, const unsigned char rgb[3], float width = 2.0f)
{
  if (xy.empty())
  {
    return;
  }
  if (xy.size() < 2)
  {
    type = vtkChart::POINTS; // a line needs two points
  }
  vtkNew<vtkTable> table;
  vtkNew<vtkDoubleArray> x, y;
  x->SetName("x");
  y->SetName(name);
  for (const auto& p : xy)
  {
    x->InsertNextValue(p.first);
    y->InsertNextValue(p.second);
  }
  table->AddColumn(x);
  table->AddColumn(y);
  vtkPlot* plot = chart->AddPlot(type);
  plot->SetInputData(table, 0, 1);
  plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
  plot->SetWidth(width);
}

void WritePlots(const std::vector<Row>& rows, const std::string& dir)
{
  // 1. Error vs time for the knob sweeps of the main scene, with the Pareto front.
  {
    vtkNew<vtkContextView> view;
    view->GetRenderer()->SetBackground(1, 1, 1);
    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);
    chart->SetTitle(
      "bunny, 4,096 uniform lights: image error vs frame time (knobs swept one at a time)");
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("frame time (ms, median)");
    chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE vs exact reference (8-bit steps)");
    chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true); // error budgets cost 10-100x
    std::vector<std::pair<double, double>> points;
    for (const Row& r : rows)
    {
      if (r.Scene == "bunny" && r.Layout == "uniform" && r.Method == "clustered" &&
        r.Lights == 4096 && r.Sweep != "camera" && r.Sweep != "specular" && r.Sweep != "spots" &&
        !std::isnan(r.RMSE)) // the last two change the scene, not the trade-off
      {
        points.emplace_back(r.MsMedian, r.RMSE * 255.0);
      }
    }
    std::vector<std::pair<double, double>> front;
    std::vector<std::pair<double, double>> sorted = points;
    std::sort(sorted.begin(), sorted.end());
    double best = 1e300;
    for (const auto& p : sorted)
    {
      if (p.second < best)
      {
        front.push_back(p);
        best = p.second;
      }
    }
    const unsigned char gray[3] = { 90, 90, 90 }, red[3] = { 200, 40, 40 };
    AddSeries(chart, points, "configurations", vtkChart::POINTS, gray, 4.0f);
    AddSeries(chart, front, "Pareto front", vtkChart::LINE, red, 3.0f);
    chart->SetShowLegend(true);
    SavePlot(view, dir + "/pareto.png");
  }
  // 2. Frame time vs light count: stock VTK, brute force, clustered.
  {
    vtkNew<vtkContextView> view;
    view->GetRenderer()->SetBackground(1, 1, 1);
    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);
    chart->SetTitle("bunny, uniform lights: frame time vs light count");
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("lights");
    chart->GetAxis(vtkAxis::LEFT)->SetTitle("frame time (ms, median)");
    chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true);
    chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
    const char* methods[3] = { "stock", "brute", "clustered" };
    const char* names[3] = { "stock VTK 9.1 (vtkLights)", "brute force", "clustered" };
    const unsigned char colors[3][3] = { { 60, 60, 60 }, { 200, 40, 40 }, { 30, 90, 200 } };
    for (int m = 0; m < 3; ++m)
    {
      std::vector<std::pair<double, double>> xy;
      for (const Row& r : rows)
      {
        if (r.Scene == "bunny" && r.Layout == "uniform" && r.Method == methods[m] &&
          r.Sweep == "count")
        {
          xy.emplace_back(r.Lights, r.MsMedian);
        }
      }
      std::sort(xy.begin(), xy.end());
      AddSeries(chart, xy, names[m], vtkChart::LINE, colors[m]);
    }
    chart->SetShowLegend(true);
    SavePlot(view, dir + "/scaling.png");
  }
}

//------------------------------------------------------------------------------ output
void WriteCSV(const std::vector<Row>& rows, const std::string& path)
{
  std::ofstream out(path);
  out << CSVHeader << "\n";
  for (const Row& r : rows)
  {
    out << r.Scene << "," << r.Layout << "," << r.Lights << "," << r.Method << "," << r.Sweep << ","
        << r.Value << "," << r.Frames << "," << Num(r.MsMedian) << "," << Num(r.MsMin) << ","
        << Num(r.MsMax) << "," << Num(r.AssignMs) << "," << Num(r.ShadeMs) << ","
        << Num(r.FirstFrameMs) << "," << Num(r.Evaluated) << "," << Num(r.Reached) << ","
        << Num(r.MaxError) << "," << Num(r.RMSE) << "," << Num(r.OverOneStep) << ","
        << Num(r.ListMiB) << "," << Num(r.MasterMiB) << "," << Num(r.LightsMiB) << ","
        << Num(r.Cutoff) << "," << Num(r.Budget) << "," << r.Note << "\n";
  }
}

void WriteMarkdown(const std::vector<Row>& rows, const std::string& path)
{
  std::ofstream out(path);
  out << "| scene | layout | lights | method | knob | value | ms (median) | [min, max] | "
         "assign ms | evaluated/px | reaching/px | max err (steps) | RMSE (steps) | "
         "px > 1 step | list MiB |\n";
  out << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    out << "| " << r.Scene << " | " << r.Layout << " | " << r.Lights << " | " << r.Method << " | "
        << r.Sweep << " | " << r.Value << " | " << Num(r.MsMedian, 4) << " | [" << Num(r.MsMin, 4)
        << ", " << Num(r.MsMax, 4) << "] | " << Num(r.AssignMs, 3) << " | " << Num(r.Evaluated, 3)
        << " | " << Num(r.Reached, 3) << " | " << Num(r.MaxError * 255.0, 3) << " | "
        << Num(r.RMSE * 255.0, 3) << " | "
        << (std::isnan(r.OverOneStep) ? std::string() : Num(100.0 * r.OverOneStep, 3) + "%")
        << " | " << Num(r.ListMiB, 3) << " |\n";
  }
}

std::string ReadFirstLine(const char* path, const char* key)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.find(key) == 0)
    {
      return line.substr(line.find(':') + 1);
    }
  }
  return "?";
}

void WriteMachine(vtkRenderWindow* rw, const std::string& command, const std::string& path)
{
  std::ofstream out(path);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof(date), "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  out << "date: " << date << "\n";
  out << "command: " << command << "\n";
  out << "cpu:" << ReadFirstLine("/proc/cpuinfo", "model name") << "\n";
  out << "hardware threads: " << std::thread::hardware_concurrency() << "\n";
  out << "memory:" << ReadFirstLine("/proc/meminfo", "MemTotal") << "\n";
  out << "VTK: " << vtkVersion::GetVTKVersion() << "\n";
  if (vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(rw))
  {
    // The driver's own strings ("OpenGL vendor/renderer/version string: ...").
    std::istringstream caps(gl->ReportCapabilities());
    std::string line;
    while (std::getline(caps, line))
    {
      if (line.rfind("OpenGL vendor", 0) == 0 || line.rfind("OpenGL renderer", 0) == 0 ||
        line.rfind("OpenGL version", 0) == 0)
      {
        out << line << "\n";
      }
    }
    out << "GL_MAX_TEXTURE_SIZE: " << vtkTextureObject::GetMaximumTextureSize(gl) << "\n";
  }
  out << "window: " << rw->GetSize()[0] << "x" << rw->GetSize()[1] << "\n";
}

//------------------------------------------------------------------------------ check
int CheckCSV(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line != CSVHeader)
  {
    std::printf("check: bad or missing header in %s\n", path.c_str());
    return 1;
  }
  int failures = 0, rows = 0, clustered = 0, budgets = 0;
  while (std::getline(in, line))
  {
    ++rows;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
    {
      f.push_back(cell);
    }
    if (f.size() < 23)
    {
      std::printf("check: row %d has %zu fields\n", rows, f.size());
      ++failures;
      continue;
    }
    auto num = [&](int i) { return f[i].empty() ? NAN : std::atof(f[i].c_str()); };
    const double ms = num(7), maxErr = num(15), budget = num(22);
    if (!(ms > 0.0) || !std::isfinite(ms))
    {
      std::printf("check: row %d has no valid frame time\n", rows);
      ++failures;
    }
    if (f[3] == "clustered")
    {
      ++clustered;
      if (std::isnan(maxErr) || std::isnan(num(13)) || std::isnan(num(18)))
      {
        std::printf("check: clustered row %d lacks error, counts or memory\n", rows);
        ++failures;
      }
      if (!std::isnan(budget))
      {
        ++budgets;
        // The budget bounds the cut tails; the image also rounds to 8 bits (half a step).
        if (!(maxErr <= budget + 0.5 / 255.0 + 1e-9))
        {
          std::printf("check: row %d misses its error budget: %g > %g\n", rows, maxErr, budget);
          ++failures;
        }
      }
    }
  }
  std::printf("check: %d rows (%d clustered, %d with an error budget), %d problem(s)\n", rows,
    clustered, budgets, failures);
  return (failures == 0 && clustered > 0 && budgets > 0) ? 0 : 1;
}
} // namespace

//------------------------------------------------------------------------------ main
int main(int argc, char* argv[])
{
  Options opt;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--quick")
    {
      opt.Quick = true;
    }
    else if (a == "--check")
    {
      opt.Check = true;
    }
    else if (a == "--output" && i + 1 < argc)
    {
      opt.Output = argv[++i];
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      opt.Frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--snapshot" && i + 2 < argc)
    {
      opt.SnapshotScene = argv[++i];
      opt.SnapshotFile = argv[++i];
    }
    else if (a == "--view" && i + 7 < argc)
    {
      for (int k = 0; k < 7; ++k)
      {
        opt.View.push_back(std::atof(argv[++i]));
      }
    }
    else
    {
      std::fprintf(stderr, "unknown argument %s\n", argv[i]);
      return EXIT_FAILURE;
    }
  }
  if (opt.Quick)
  {
    opt.Width = 400;
    opt.Height = 300;
    opt.Frames = std::min(opt.Frames, 3);
  }
  vtksys::SystemTools::MakeDirectory(opt.Output);

  Context ctx;
  ctx.Opt = opt;
  ctx.Window->SetSize(opt.Width, opt.Height);
  ctx.Window->SetMultiSamples(0);
  ctx.Window->SetOffScreenRendering(1);
  ctx.Renderer->SetBackground(0.02, 0.02, 0.03);
  ctx.Renderer->AutomaticLightCreationOff();
  ctx.Window->AddRenderer(ctx.Renderer);
  ctx.Pass->AddLightSet(ctx.Lights);
  ctx.Renderer->SetPass(ctx.Pass);

  if (!opt.SnapshotScene.empty())
  {
    Scene s = opt.SnapshotScene == "house" ? HouseScene : BunnyScene;
    if (opt.View.size() == 7)
    {
      std::copy(opt.View.begin(), opt.View.begin() + 3, s.CameraPosition);
      std::copy(opt.View.begin() + 3, opt.View.begin() + 6, s.CameraFocalPoint);
      s.ViewAngle = opt.View[6];
    }
    ctx.Current = s;
    if (LoadScene(s, ctx.Renderer, ctx.Window, true) < 0)
    {
      return EXIT_FAILURE;
    }
    ctx.Headlight->SetLightTypeToHeadlight();
    ctx.Renderer->AddLight(ctx.Headlight);
    ctx.MakeLights(512, "uniform");
    SetView(s, ctx.Renderer);
    ctx.Window->Render();
    ClusteredLightingImages::WritePNG(ctx.Window, opt.SnapshotFile);
    return EXIT_SUCCESS;
  }

  const int F = opt.Frames;
  std::vector<const Scene*> scenes = { &BunnyScene };
  if (!opt.Quick)
  {
    scenes.push_back(&HouseScene);
  }
  for (const Scene* scene : scenes)
  {
    ctx.Renderer->RemoveAllViewProps();
    ctx.Current = *scene;
    const vtkIdType triangles = LoadScene(*scene, ctx.Renderer, ctx.Window, opt.Quick);
    if (triangles < 0)
    {
      std::fprintf(stderr, "scene %s: data missing (run scripts/install-deps.sh and build)\n",
        scene->Name.c_str());
      return EXIT_FAILURE;
    }
    std::printf("== scene %s: %lld triangles, %dx%d\n", scene->Name.c_str(),
      static_cast<long long>(triangles), opt.Width, opt.Height);
    const bool main = scene->Name == "bunny";

    // Light counts, with the brute-force and stock peers.
    const std::vector<int> counts = opt.Quick
      ? std::vector<int>{ 64, 1024, 4096 }
      : std::vector<int>{ 64, 256, 1024, 4096, 16384, 65536 };
    const std::vector<std::string> layouts = opt.Quick
      ? std::vector<std::string>{ "uniform" }
      : std::vector<std::string>{ "uniform", "clumped", "hard" };
    for (const std::string& layout : layouts)
    {
      for (int n : counts)
      {
        ctx.ResetPassDefaults();
        ctx.MakeLights(n, layout);
        const bool reference = n <= 16384;
        if (reference)
        {
          ctx.MakeReference();
        }
        else
        {
          ctx.Reference.clear();
        }
        ctx.Measure("clustered", "count", std::to_string(n), F);
        if (layout == "uniform" && n <= 16384)
        {
          // Brute force costs the same for every layout: measured once per count.
          const int bruteFrames = (n >= 16384 && !opt.Quick) ? 3 : (opt.Quick ? 1 : F);
          ctx.Pass->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
          ctx.Measure("brute", "count", std::to_string(n), bruteFrames, true, false);
          ctx.Pass->SetShadingMode(vtkClusteredLightingPass::SHADING_CLUSTERED);
        }
      }
    }
    if (main && !opt.Quick)
    {
      // The largest count the default grid holds with this GL_MAX_TEXTURE_SIZE. No brute-force
      // reference is feasible at this count (hours per frame here), so no error is reported.
      const vtkTypeInt64 largest = vtkClusteredLightingPass::GetMaximumNumberOfLights(32, 16, 32,
        vtkTextureObject::GetMaximumTextureSize(vtkOpenGLRenderWindow::SafeDownCast(ctx.Window)));
      ctx.ResetPassDefaults();
      ctx.MakeLights(static_cast<int>(largest), "uniform");
      ctx.Reference.clear();
      Row& row = (ctx.Measure("clustered", "count", std::to_string(largest), 3), ctx.Rows.back());
      row.Note = "largest the default grid holds; no brute-force reference at this count";
    }

    // Stock VTK 9.1 with the same lights as vtkLights (on the house too, where triangles
    // are large: the clustered/stock ratio depends on the mesh, see docs/benchmark).
    {
      const std::vector<int> stockCounts = opt.Quick ? std::vector<int>{ 8 }
        : main                                       ? std::vector<int>{ 1, 8, 64, 256 }
                                                     : std::vector<int>{ 1, 8 };
      for (int n : stockCounts)
      {
        ctx.ResetPassDefaults();
        ctx.MakeLights(n, "uniform");
        ctx.MakeReference();
        ctx.MeasureStock(opt.Quick ? 2 : F);
      }
    }

    // Knobs, one at a time from the default, at 4,096 uniform lights.
    if (main)
    {
      ctx.ResetPassDefaults();
      ctx.MakeLights(4096, "uniform");
      ctx.MakeReference();
      vtkClusteredLightingPass* p = ctx.Pass;
      auto sweep = [&](const std::string& knob, const std::string& value,
                     const std::function<void()>& apply, bool moving = true)
      {
        ctx.ResetPassDefaults();
        apply();
        ctx.Measure("clustered", knob, value, F, moving);
        ctx.ResetPassDefaults();
      };
      const std::vector<double> cutoffs = opt.Quick
        ? std::vector<double>{ 64, 1024 }
        : std::vector<double>{ 16, 64, 256, 1024, 4096 };
      for (double c : cutoffs)
      {
        sweep("cutoff", "1/" + Num(c, 5), [&] { p->SetCutoff(1.0 / c); });
      }
      sweep("bounds", "centre-depth quad",
        [&] { p->SetBoundsMethod(vtkClusteredLightingPass::BOUNDS_CENTER_DEPTH_QUAD); });
      if (!opt.Quick)
      {
        sweep("falloff", "windowed",
          [&] { p->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED); });
        sweep("tiles", "16x8",
          [&]
          {
            p->SetTilesX(16);
            p->SetTilesY(8);
          });
        sweep("tiles", "64x32",
          [&]
          {
            p->SetTilesX(64);
            p->SetTilesY(32);
          });
        sweep("slices", "16", [&] { p->SetSlices(16); });
        sweep("slices", "64", [&] { p->SetSlices(64); });
        sweep("slicing", "linear",
          [&] { p->SetSlicingScheme(vtkClusteredLightingPass::SLICING_LINEAR); });
        sweep("morton", "off", [&] { p->SetMortonOrder(false); });
        sweep("culling", "per-cluster off", [&] { p->SetPerClusterCulling(false); });
        sweep(
          "camera", "static", [] {}, false);
        // Effects a scene calls for: specular off, spot lights present.
        vtkActorCollection* actors = ctx.Renderer->GetActors();
        std::vector<double> specular;
        actors->InitTraversal();
        while (vtkActor* a = actors->GetNextActor())
        {
          specular.push_back(a->GetProperty()->GetSpecular());
        }
        sweep("specular", "off",
          [&]
          {
            actors->InitTraversal();
            while (vtkActor* a = actors->GetNextActor())
            {
              a->GetProperty()->SetSpecular(0.0);
            }
            ctx.MakeReference(); // the exact reference of this scene
          });
        actors->InitTraversal();
        for (double s : specular)
        {
          actors->GetNextActor()->GetProperty()->SetSpecular(s);
        }
        ctx.MakeReference();
        // The spot-cone code alone: one light becomes a spot light, so every shader gets
        // the cone code while the other 4,095 lights stay point lights.
        ctx.Lights->SetSpot(0, 0.0, -1.0, 0.0, 60.0, 1.0);
        ctx.MakeReference();
        sweep("spots", "1 spot light", [] {});
        for (vtkIdType i = 0; i < 4096; i += 10)
        {
          ctx.Lights->SetSpot(i, 0.0, -1.0, 0.0, 60.0, 1.0);
        }
        ctx.MakeReference();
        sweep("spots", "10% spot lights", [] {});
        ctx.MakeLights(4096, "uniform");
        ctx.MakeReference();
      }
      const std::vector<double> budgets =
        opt.Quick ? std::vector<double>{ 4 } : std::vector<double>{ 1, 4, 16 };
      for (double b : budgets)
      {
        sweep("budget", Num(b, 3) + "/255", [&] { p->SetErrorBudget(b / 255.0); });
      }
    }
  }

  std::string command;
  for (int i = 0; i < argc; ++i)
  {
    command +=
      (i ? " " : "") + std::string(argc && i == 0 ? "ClusteredLightingBenchmark" : argv[i]);
  }
  WriteMachine(ctx.Window, command, opt.Output + "/machine.txt");
  const std::string csv = opt.Output + "/results.csv";
  WriteCSV(ctx.Rows, csv);
  WriteMarkdown(ctx.Rows, opt.Output + "/results.md");
  WritePlots(ctx.Rows, opt.Output);
  std::printf("wrote %s, results.md, pareto.png, scaling.png\n", csv.c_str());
  return opt.Check ? CheckCSV(csv) : EXIT_SUCCESS;
}
