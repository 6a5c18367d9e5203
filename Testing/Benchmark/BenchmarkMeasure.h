// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BenchmarkMeasure.h
 * @brief How the benchmark measures one step: frame times, counts, error, memory.
 *
 * Context holds one offscreen window with one renderer, the clustered pass and one light
 * set. For each step (BenchmarkPlan.h) it:
 *  - times the frames: two warm-up frames (shader compilation, first assignment), then
 *    `frames` frames with the camera orbiting one degree per frame (so the assignment runs
 *    every frame) or still; each frame ends with glFinish before the clock is read; the
 *    pass's own timers (MeasureTimings) split assignment from shading;
 *  - back at the view, compares the image with the exact reference (brute force: every
 *    light, no cutoff) in 8-bit steps (max, RMSE, share of pixels off by more than one,
 *    and the signed mean: a bias, which RMSE does not show);
 *  - counts, exactly per fragment with the pass's debug views, the lights the shader
 *    evaluates per pixel and the ones that really reach it (closer than the radius,
 *    inside the cone), averaged over the pixels that show geometry;
 *  - reads the GPU memory the pass holds.
 */
#ifndef BenchmarkMeasure_h
#define BenchmarkMeasure_h

#include "BenchmarkPlan.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <string>
#include <vector>

namespace ClusteredLightingBenchmark
{

/// One row of results (NaN: not measured).
struct Row
{
  std::string Scene, Layout, Method, Sweep, Value;
  int Lights = 0;
  int Frames = 0;
  double MsMedian = NAN, MsMin = NAN, MsMax = NAN;
  /// Median frame time of the frames that measured the pass's parts (MeasureTimings:
  /// a glFinish between the parts); the timed frames above run without it.
  double InstrumentedMs = NAN;
  /// Median CPU time of the rendering thread in a timed frame (what it costs to issue
  /// the frame: VTK's and the pass's own work, the driver's front end; a GPU driver's
  /// worker threads and llvmpipe's rasterizer threads are not counted).
  double CpuMs = NAN;
  double AssignMs = NAN, LightUpdateMs = NAN, ShadeMs = NAN, FirstFrameMs = NAN;
  /// Lights evaluated and reaching per pixel of geometry, from the evaluated-count and
  /// reached-count debug images; in a multisampled window from the pass's own counts of
  /// one sample per pixel (GetMeanLightsEvaluatedPerPixel, GetMeanLightsReachingPerPixel),
  /// since the resolved image averages an edge pixel's encoded counts.
  double Evaluated = NAN, Reached = NAN;
  /// Lights evaluated per pixel if every pixel cost as much as the most evaluated pixel of
  /// its 8x4 tile: a GPU shades fragments in groups of 32 (on NVIDIA's, 8 quads of 2x2)
  /// that step through the loops together, so a group takes as long as its slowest
  /// fragment. A model (the rasterizer's grouping is not known): its ratio to Evaluated
  /// says how much divergent loops could cost there, from an image any renderer gives.
  /// Not measured in multisampled windows.
  double EvaluatedIn32 = NAN;
  /// With --culling-floor (count rows, single-sampled windows): per pixel of geometry,
  /// the lights of its cluster in the double-precision reference assignment (exact cell
  /// culling) and those reaching some fragment of its cluster (what any list per cluster
  /// must hold: the floor of Evaluated at these clusters; MeasureClusterCullingFloor).
  double CellsPerPixel = NAN, FloorPerPixel = NAN;
  double PrepassMs = NAN, ShadedPerVisible = NAN; ///< depth prepass; fragments shaded per pixel
  double OpaqueShadedPerVisible = NAN;            ///< the opaque draws' part of ShadedPerVisible
  double FarBuildMs = NAN;    ///< the far field's last build (every frame when lights move)
  double FarBoundSteps = NAN; ///< the far field's stated bound (ComputeFarFieldErrorBound)
  double FarNodes = NAN;      ///< the far field's resolution in use (an error budget chooses it)
  double FarNodesBuilt = NAN; ///< nodes a frame's far-field build summed (0: none rebuilt)
  double MaxError = NAN, RMSE = NAN, OverOneStep = NAN;
  double SignedError = NAN; ///< mean of (image - reference): negative = darker than exact
  double ListMiB = NAN, MasterMiB = NAN, LightsMiB = NAN;
  double Cutoff = NAN, Budget = NAN;
  double FarCutoff = NAN; ///< the split lights' cutoff (GetEffectiveFarFieldCutoff)
  double BudgetMet = NAN; ///< 1: the pass met the budget (GetFarFieldErrorBudgetMet), 0: it warned
  std::string Note;
};

class Context
{
public:
  Context(int width, int height);

  /// Loads a scene's geometry (quick: the bunny without subdivision); returns its
  /// triangle count, or -1 if its data is missing.
  long long LoadScene(const Scene& scene, bool quick);
  /**
   * Fills the light set for a step (seeded: the same lights every run). Layouts uniform,
   * clumped and hard use the scene's lights (attenuation for its radius at the default
   * cutoff); two more are lights as users write them (issue 11):
   *  - dense: inverse-square lights with attenuation (1, 0, 8), intensity 1, no radius;
   *  - always-on: n positional vtkLights of the renderer (not the light set) with VTK's
   *    default attenuation (1, 0, 0), which never falls off, intensity 0.005 each (at
   *    VTK's default 1, 300 of them turn every pixel white in both images).
   */
  void MakeLights(int n, const std::string& layout);
  /// The exact reference image of the current lights at the scene's view.
  void MakeReference();
  void ClearReference() { this->Reference.clear(); }
  /// Sets every option the plan's knobs touch back to the pass's default.
  void ResetPassDefaults();
  /// ResetPassDefaults, then the options (PrintSelf's lines) where it left the pass unlike
  /// a new one, other than AutomaticDepthPrepass; empty if none. A knob a row sets and the
  /// reset forgets would leak into every later row.
  std::string CheckPassDefaults();
  /// Measures one step with the current scene, lights and pass options.
  Row Measure(const Step& step);

  vtkRenderWindow* GetWindow() { return this->Window; }
  vtkRenderer* GetRenderer() { return this->Renderer; }
  vtkClusteredLightingPass* GetPass() { return this->Pass; }
  vtkClusteredLightSet* GetLights() { return this->Lights; }
  const Scene* GetScene() const { return this->Current; }
  void SetView();
  /// Count rows also measure the culling floor (Row::FloorPerPixel). Default is off: the
  /// reference assignment takes seconds at thousands of lights.
  void SetMeasureCullingFloor(bool on) { this->MeasureFloor = on; }
  /// Clustered rows with a reference also print their `k` worst pixels (--worst-pixels):
  /// where they are, their error and the far field's stated bound there. Default is 0.
  void SetWorstPixels(int k) { this->WorstPixels = k; }

private:
  void MeasureCullingFloor(Row& row);
  void MeasureCounts(Row& row);
  void PrintWorstPixels(
    const Row& row, const std::vector<float>& img, const std::vector<double>& pixelErrors);
  void NudgeLights(int frame);
  void AddStockLights(std::vector<vtkSmartPointer<vtkLight>>& added);
  void RemoveRendererLights();

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkClusteredLightingPass> Pass;
  vtkNew<vtkClusteredLightSet> Lights;
  const Scene* Current = nullptr;
  std::string Layout;
  std::vector<float> Reference;        ///< exact image of the current lights at the view
  std::vector<unsigned char> Geometry; ///< pixels that show geometry at the view
  double Nudged = 0.0;                 ///< how far NudgeLights moved the lights
  bool MeasureFloor = false;
  int WorstPixels = 0;
  std::vector<vtkSmartPointer<vtkLight>> RendererLights; ///< the "always-on" layout's lights
};

/// Max error, RMSE, share of pixels off by more than one 8-bit step and signed mean error
/// (negative: darker than the reference), into row.
void CompareWithReference(const std::vector<float>& img, const std::vector<float>& ref, Row& row);

/// Median of a list (0 for an empty one).
double Median(std::vector<double> v);

} // namespace ClusteredLightingBenchmark

#endif
