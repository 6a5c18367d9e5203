// SPDX-License-Identifier: BSD-3-Clause
// What accuracy costs in time: the ClusteredLighting benchmark.
//
// Renders fixed, seeded scenes at 1024x768 (real meshes: the Stanford bunny Loop-subdivided
// to about 1.1 M triangles, and the KIT FZK-Haus interior) and measures, side by side in
// one run, every step of the plan (BenchmarkPlan.cxx: light counts and layouts, peers,
// knobs swept one at a time from the defaults) the way BenchmarkMeasure.h describes, then
// writes the report (BenchmarkReport.h): results.csv, results.md, pareto.png, scaling.png
// and machine.txt.
//
//   ClusteredLightingBenchmark [--quick] [--output DIR] [--frames N] [--check]
//                              [--filter REGEX] [--culling-floor] [--worst-pixels K]
//                              [--snapshot SCENE FILE [--view px py pz fx fy fz angle]]
//
// --quick finishes in under 2 minutes (small window, fewer steps); --check validates the
// written CSV (well-formed, finite, error budgets met) and sets the exit code; --filter
// measures only the steps whose id "scene/layout/lights/method/sweep/value" matches;
// --culling-floor also measures, on count rows, the lights per pixel that exact cell
// culling and the best possible list per cluster would walk (results.md's "Culling floor");
// --worst-pixels K prints, for each clustered row with a reference, its K pixels farthest
// from it: where they are and the far field's stated bound there (a diagnostic).
#include "BenchmarkMeasure.h"
#include "BenchmarkPlan.h"
#include "BenchmarkReport.h"
#include "ClusteredLightingImages.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtksys/SystemTools.hxx"

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

using namespace ClusteredLightingBenchmark;

namespace
{
struct Options
{
  bool Quick = false;
  bool Check = false;
  bool CullingFloor = false;
  int Width = 1024, Height = 768;
  int Frames = 10;
  int WorstPixels = 0;
  std::string Output = "benchmark-results";
  std::string Filter;
  std::string SnapshotScene, SnapshotFile;
  std::vector<double> View; ///< optional camera for --snapshot: position, focal point, angle
};

bool ParseOptions(int argc, char* argv[], Options& opt)
{
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
    else if (a == "--culling-floor")
    {
      opt.CullingFloor = true;
    }
    else if (a == "--output" && i + 1 < argc)
    {
      opt.Output = argv[++i];
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      opt.Frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--worst-pixels" && i + 1 < argc)
    {
      opt.WorstPixels = std::max(0, std::atoi(argv[++i]));
    }
    else if (a == "--filter" && i + 1 < argc)
    {
      opt.Filter = argv[++i];
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
      return false;
    }
  }
  if (opt.Quick)
  {
    opt.Width = 400;
    opt.Height = 300;
    opt.Frames = std::min(opt.Frames, 3);
  }
  return true;
}

/// One image of a scene with 512 lights and a headlight (for the docs).
int Snapshot(const Options& opt)
{
  Context ctx(opt.Width, opt.Height);
  Scene s = opt.SnapshotScene == "house" ? HouseScene() : BunnyScene();
  if (opt.View.size() == 7)
  {
    std::copy(opt.View.begin(), opt.View.begin() + 3, s.CameraPosition);
    std::copy(opt.View.begin() + 3, opt.View.begin() + 6, s.CameraFocalPoint);
    s.ViewAngle = opt.View[6];
  }
  if (ctx.LoadScene(s, true) < 0)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  ctx.GetRenderer()->AddLight(headlight);
  ctx.MakeLights(512, "uniform");
  ctx.SetView();
  ctx.GetWindow()->Render();
  ClusteredLightingImages::WritePNG(ctx.GetWindow(), opt.SnapshotFile);
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  Options opt;
  if (!ParseOptions(argc, argv, opt))
  {
    return EXIT_FAILURE;
  }
  if (!opt.SnapshotScene.empty())
  {
    return Snapshot(opt);
  }
  vtksys::SystemTools::MakeDirectory(opt.Output);

  Context ctx(opt.Width, opt.Height);
  ctx.SetMeasureCullingFloor(opt.CullingFloor);
  ctx.SetWorstPixels(opt.WorstPixels);
  PlanOptions planOptions;
  planOptions.Quick = opt.Quick;
  planOptions.Frames = opt.Frames;
  ctx.GetWindow()->Render(); // a context, for the texture limit
  planOptions.LargestLights = vtkClusteredLightingPass::GetMaximumNumberOfLights(32, 16, 32,
    vtkTextureObject::GetMaximumTextureSize(vtkOpenGLRenderWindow::SafeDownCast(ctx.GetWindow())));
  const std::regex filter(opt.Filter.empty() ? std::string(".*") : opt.Filter);
  const std::string probeAtStart = ProbeHost();

  std::vector<Row> rows;
  const Scene* loaded = nullptr;
  std::string lightsKey, referenceKey;
  for (const Step& step : MakePlan(planOptions))
  {
    if (!std::regex_search(step.GetId(), filter))
    {
      continue;
    }
    if (step.Where != loaded)
    {
      const long long triangles = ctx.LoadScene(*step.Where, opt.Quick);
      if (triangles < 0)
      {
        std::fprintf(stderr, "scene %s: data missing (run scripts/install-deps.sh and build)\n",
          step.Where->Name.c_str());
        return EXIT_FAILURE;
      }
      std::printf("== scene %s: %lld triangles, %dx%d\n", step.Where->Name.c_str(), triangles,
        opt.Width, opt.Height);
      loaded = step.Where;
      lightsKey.clear();
    }
    const std::string lights =
      step.Where->Name + "/" + step.Layout + "/" + std::to_string(step.Lights);
    if (lights != lightsKey)
    {
      ctx.MakeLights(step.Lights, step.Layout);
      lightsKey = lights;
      referenceKey.clear();
    }
    ctx.ResetPassDefaults();
    if (step.Setup)
    {
      step.Setup(ctx);
    }
    // The exact reference of the scene as this step sees it, rendered once per scene.
    const std::string reference = lights + "/" + step.ChangesScene;
    if (!step.Reference)
    {
      ctx.ClearReference();
      referenceKey.clear();
    }
    else if (reference != referenceKey)
    {
      ctx.MakeReference();
      referenceKey = reference;
    }
    if (step.Apply)
    {
      step.Apply(ctx.GetPass());
    }
    rows.push_back(ctx.Measure(step));
    if (step.Teardown)
    {
      step.Teardown(ctx);
      referenceKey.clear();
    }
    // Resets, and checks that no option this row set outlives it.
    const std::string unlike = ctx.CheckPassDefaults();
    if (!unlike.empty())
    {
      std::fprintf(stderr,
        "after %s, Context::ResetPassDefaults leaves the pass unlike a new one:\n%s",
        step.GetId().c_str(), unlike.c_str());
      return EXIT_FAILURE;
    }
  }

  std::string command = "ClusteredLightingBenchmark";
  for (int i = 1; i < argc; ++i)
  {
    command += std::string(" ") + argv[i];
  }
  WriteMachine(ctx.GetWindow(), command, opt.Output + "/machine.txt", probeAtStart, ProbeHost());
  const std::string csv = opt.Output + "/results.csv";
  WriteCSV(rows, csv);
  WriteMarkdown(rows, opt.Output + "/results.md");
  WritePlots(rows, opt.Output);
  std::printf("wrote %s, results.md, pareto.png, scaling.png\n", csv.c_str());
  return opt.Check ? CheckCSV(csv) : EXIT_SUCCESS;
}
