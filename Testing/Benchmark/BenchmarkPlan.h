// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BenchmarkPlan.h
 * @brief What the benchmark measures: scenes, light counts, peers and knobs, as data.
 *
 * The plan is a flat list of steps. Each step is one row of results: a scene, a light
 * layout and count, a method (clustered, brute force, stock VTK), the knob it changes from
 * the pass's defaults (sweep, value) and how it changes it. The runner
 * (ClusteredLightingBenchmark.cxx) walks the steps in order, loading a scene or making
 * lights only when they differ from the previous step's, and measures each one
 * (BenchmarkMeasure.h). Adding a row is adding a step here.
 */
#ifndef BenchmarkPlan_h
#define BenchmarkPlan_h

#include <functional>
#include <string>
#include <vector>

class vtkClusteredLightingPass;

namespace ClusteredLightingBenchmark
{
class Context;

/// A scene: geometry, camera, where the lights go and how bright they are.
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

const Scene& BunnyScene();
const Scene& HouseScene();

/// One measured row.
struct Step
{
  const Scene* Where = nullptr;
  std::string Layout = "uniform"; ///< uniform, clumped or hard
  int Lights = 4096;
  std::string Method = "clustered"; ///< clustered, brute or stock
  std::string Sweep = "count";      ///< the knob changed from the defaults
  std::string Value;
  int Frames = 10;
  int Warmup = 1;             ///< frames rendered after the first, before the timed ones
  bool Moving = true;         ///< orbit the camera (the assignment runs every frame)
  bool AnimateLights = false; ///< move every light a little each frame (lights change)
  bool Counts = true;         ///< lights evaluated/reaching per pixel (clustered only)
  bool Reference = true;      ///< compare with the exact (brute-force) image
  /// Changes the pass's options from the defaults (run after the defaults are set).
  std::function<void(vtkClusteredLightingPass*)> Apply;
  /// Changes the scene or the lights for this step and undoes it afterwards; the exact
  /// reference is rendered for the changed scene (ChangesScene names the change).
  std::function<void(Context&)> Setup, Teardown;
  std::string ChangesScene;
  std::string Note;

  /// "scene/layout/lights/method/sweep/value", what --filter matches.
  std::string GetId() const;
};

struct PlanOptions
{
  bool Quick = false;
  int Frames = 10;
  long long LargestLights = 0; ///< the most lights the default grid holds (0: skip that row)
};

/// Every step of a run, in order.
std::vector<Step> MakePlan(const PlanOptions& options);

} // namespace ClusteredLightingBenchmark

#endif
