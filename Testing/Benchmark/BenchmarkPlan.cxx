// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkPlan.h"

#include "BenchmarkMeasure.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkClusteredLightingBackfaceCulling.h"
#include "vtkMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

namespace ClusteredLightingBenchmark
{

//------------------------------------------------------------------------------
const Scene& BunnyScene()
{
  static const Scene s = { "bunny", { 0.0, 1.6, 4.6 }, { 0.0, -0.3, 0.0 }, 40.0,
    { -3.0, -0.98, -3.0 }, { 3.0, 1.0, 3.0 }, 0.35, 1.0 };
  return s;
}

// Standing in the kitchen of the ground floor, looking at the spiral staircase; lights in
// both storeys of the house.
const Scene& HouseScene()
{
  static const Scene s = { "house", { 1.5, 1.6, -1.5 }, { 10.0, 1.0, -9.0 }, 70.0,
    { 0.2, 0.05, -9.8 }, { 11.8, 5.5, -0.2 }, 1.0, 1.0 };
  return s;
}

//------------------------------------------------------------------------------
std::string Step::GetId() const
{
  return this->Where->Name + "/" + this->Layout + "/" + std::to_string(this->Lights) + "/" +
    this->Method + "/" + this->Sweep + "/" + this->Value;
}

namespace
{
std::string Fraction(double denominator)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "1/%g", denominator);
  return buf;
}

/// Every actor's specular coefficient set to 0, and back (a step that changes the scene).
void SwitchSpecular(Context& ctx, bool off)
{
  static std::vector<double> saved;
  vtkActorCollection* actors = ctx.GetRenderer()->GetActors();
  actors->InitTraversal();
  std::size_t i = 0;
  if (off)
  {
    saved.clear();
  }
  while (vtkActor* a = actors->GetNextActor())
  {
    if (off)
    {
      saved.push_back(a->GetProperty()->GetSpecular());
      a->GetProperty()->SetSpecular(0.0);
    }
    else if (i < saved.size())
    {
      a->GetProperty()->SetSpecular(saved[i++]);
    }
  }
}

/// VTK's own face culling set by hand on the actors whose faces the pass's
/// AutomaticBackfaceCulling culls (vtkClusteredLightingChooseCulledFace: its rules, under
/// the camera of the row's setup): stock VTK with the culling a user who knows the
/// meshes sets, beside the pass. Returns the actors culled, to switch back.
std::vector<vtkSmartPointer<vtkActor>> CullClosedMeshesByHand(Context& ctx)
{
  std::vector<vtkSmartPointer<vtkActor>> culled;
  vtkRenderer* ren = ctx.GetRenderer();
  vtkActorCollection* actors = ren->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    const int face = vtkClusteredLightingChooseCulledFace(a, ren);
    if (face != 0)
    {
      if (face > 0)
      {
        a->GetProperty()->BackfaceCullingOn();
      }
      else
      {
        a->GetProperty()->FrontfaceCullingOn();
      }
      culled.emplace_back(a);
    }
  }
  std::printf("culled by hand: %zu of %d actors\n", culled.size(), actors->GetNumberOfItems());
  return culled;
}

/// Every actor forced opaque, and back (a step that changes the scene).
void SwitchOpaque(Context& ctx, bool on)
{
  vtkActorCollection* actors = ctx.GetRenderer()->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->SetForceOpaque(on);
  }
}

/// Every actor made PBR with the given metallic factor and roughness, and back to its own
/// interpolation (a step that changes the scene).
void SwitchPbr(Context& ctx, bool on, double metallic = 0.0, double roughness = 0.5)
{
  static std::vector<int> saved;
  vtkActorCollection* actors = ctx.GetRenderer()->GetActors();
  actors->InitTraversal();
  std::size_t i = 0;
  if (on)
  {
    saved.clear();
  }
  while (vtkActor* a = actors->GetNextActor())
  {
    if (on)
    {
      saved.push_back(a->GetProperty()->GetInterpolation());
      a->GetProperty()->SetInterpolationToPBR();
      a->GetProperty()->SetMetallic(metallic);
      a->GetProperty()->SetRoughness(roughness);
    }
    else if (i < saved.size())
    {
      a->GetProperty()->SetInterpolation(saved[i++]);
    }
  }
}

// Rows of `from` with NearFieldBudget 4, 8 (the default) and 16: lights per point
// evaluated exactly, against what the far field adds back (docs/far-field.md).
void AddNearBudgetRows(const Step& from, std::vector<Step>& plan)
{
  for (double budget : { 4.0, 8.0, 16.0 })
  {
    Step s = from;
    s.Sweep = "near budget";
    s.Value = std::to_string(static_cast<int>(budget));
    s.Apply = [budget](vtkClusteredLightingPass* p) { p->SetNearFieldBudget(budget); };
    plan.push_back(s);
  }
}
// The same step without the exact far sums near saturation (FarFieldTolerance 1).
Step WithoutExactFarSums(const Step& from)
{
  Step t = from;
  t.Sweep = "far tolerance";
  t.Value = "1 (no exact sums)";
  t.Apply = [](vtkClusteredLightingPass* p) { p->SetFarFieldTolerance(1.0); };
  return t;
}

// The same step with the far diffuse to order 2 (FarFieldOrder4Diffuse off): what the
// order-4 diffuse costs (twice the far field's texture reads and node sums) and buys.
Step WithOrder2Diffuse(const Step& from)
{
  Step t = from;
  t.Sweep = "far field";
  t.Value = "order-2 diffuse";
  t.Apply = [](vtkClusteredLightingPass* p) { p->SetFarFieldOrder4Diffuse(false); };
  return t;
}

// The same step with the far specular from directional bins (FarFieldSpecularBins on):
// what they cost (a texture of 26 or 52 slabs read per specular fragment, their sums in
// each build) and buy.
Step WithSpecularBins(const Step& from)
{
  Step t = from;
  t.Sweep = "far field";
  t.Value = "specular bins";
  t.Apply = [](vtkClusteredLightingPass* p) { p->SetFarFieldSpecularBins(true); };
  return t;
}

// The same step with a finer far field and the same near radii: `cells` grid spacings per
// near radius (FarFieldCellsPerRadius, default 2) at (cells / 2)^3 times the default
// resolution, so that every light keeps the near radius the default gives it (the same
// lights walked per pixel) while the far parts are interpolated from nodes closer
// together; with or without the far specular's bins. Issue 11's 2-step target at 65,536
// lights (docs/far-field.md, "The 65,536-light image within 2 steps").
Step WithFinerFarField(const Step& from, double cells, bool bins)
{
  Step t = from;
  const int nodes =
    static_cast<int>(std::lround(32768.0 * (cells / 2.0) * (cells / 2.0) * (cells / 2.0)));
  char value[96];
  std::snprintf(value, sizeof(value), "%g cells per radius at %d nodes%s", cells, nodes,
    bins ? " with specular bins" : "");
  t.Sweep = "far field";
  t.Value = value;
  t.Apply = [cells, nodes, bins](vtkClusteredLightingPass* p)
  {
    p->SetFarFieldCellsPerRadius(cells);
    p->SetFarFieldResolution(nodes);
    p->SetFarFieldSpecularBins(bins);
  };
  return t;
}

// The same step with the pass's default choice of the prepass (AutomaticDepthPrepass, off
// in every other row so that it times the mode it names): its trial runs in the warm-up
// frames (3 settle frames, 4 with the prepass, 4 without), so the timed frames show the
// choice it made.
void MakeAutomatic(Step& step)
{
  step.Warmup = 12;
  step.Apply = [](vtkClusteredLightingPass* p) { p->SetAutomaticDepthPrepass(true); };
}

// The same step with the exact far sums near saturation taken at any light count
// (FarFieldExactSumLimit), for the counts above their default limit.
Step ExactFarSumsAtAnyCount(const Step& from)
{
  Step e = from;
  e.Sweep = "exact far sums";
  e.Value = "at any light count";
  e.Apply = [](vtkClusteredLightingPass* p) { p->SetFarFieldExactSumLimit(VTK_INT_MAX); };
  return e;
}
}

//------------------------------------------------------------------------------
std::vector<Step> MakePlan(const PlanOptions& options)
{
  const bool quick = options.Quick;
  const int F = options.Frames;
  std::vector<Step> plan;
  std::vector<const Scene*> scenes = { &BunnyScene() };
  if (!quick)
  {
    scenes.push_back(&HouseScene());
  }
  for (const Scene* scene : scenes)
  {
    const bool main = scene == &BunnyScene();
    Step base;
    base.Where = scene;
    base.Frames = F;

    // Light counts, with the brute-force peer (the same shading code, every light for
    // every fragment; it costs the same for every layout, so it is measured once).
    const std::vector<int> counts = quick ? std::vector<int>{ 64, 1024, 4096 }
                                          : std::vector<int>{ 64, 256, 1024, 4096, 16384, 65536 };
    const std::vector<std::string> layouts = quick
      ? std::vector<std::string>{ "uniform" }
      : std::vector<std::string>{ "uniform", "clumped", "hard" };
    for (const std::string& layout : layouts)
    {
      for (int n : counts)
      {
        Step s = base;
        s.Layout = layout;
        s.Lights = n;
        s.Value = std::to_string(n);
        // Brute force takes seconds to minutes per frame: a reference up to 16,384 lights,
        // and one at 65,536 uniform lights (about 4 minutes, rendered once).
        s.Reference = n <= 16384 || (layout == "uniform" && n == 65536);
        plan.push_back(s);
        if (n == 65536 && layout != "uniform" && !quick)
        {
          Step e = ExactFarSumsAtAnyCount(s);
          e.Frames = 2; // seconds per frame on llvmpipe
          plan.push_back(e);
        }
        if (layout == "uniform" && n == 16384 && !quick)
        {
          // What the exact far sums cost below their limit.
          plan.push_back(WithoutExactFarSums(s));
        }
        if (layout == "uniform" && n == 65536 && !quick)
        {
          // The default refines the far field of still lights (FarFieldRefineStillLights);
          // the rows of this block measure the settings they name, unrefined, beginning
          // with the options' own settings (what moving lights get).
          const std::size_t first = plan.size();
          Step unrefined = s;
          unrefined.Sweep = "far field";
          unrefined.Value = "not refined";
          plan.push_back(unrefined);
          // The far field's resolution where it holds most of the light (the same
          // reference): finer grids give shorter near radii, so fewer lights walked per
          // pixel; what they do to accuracy is measured (docs/far-field.md).
          for (int nodes : { 65536, 131072, 262144 })
          {
            Step r = s;
            r.Sweep = "far field";
            r.Value = std::to_string(nodes) + " nodes";
            r.Apply = [nodes](vtkClusteredLightingPass* p) { p->SetFarFieldResolution(nodes); };
            plan.push_back(r);
          }
          // An error budget here: it takes the finest grid (whose near field is the
          // cheapest) and cannot meet 4 steps by the resolution (the pass warns); what
          // that does to the error against the same reference.
          Step b = s;
          b.Sweep = "budget";
          b.Value = "4/255";
          b.Apply = [](vtkClusteredLightingPass* p) { p->SetErrorBudget(4.0 / 255.0); };
          plan.push_back(b);
          // The far diffuse to order 2 against the same reference (issue 11's 2-step target
          // at 65,536 lights: docs/far-field.md).
          plan.push_back(WithOrder2Diffuse(s));
          // The far specular from bins (the rest of the 2-step target).
          plan.push_back(WithSpecularBins(s));
          // A finer far field with the same near radii, with and without the bins.
          plan.push_back(WithFinerFarField(s, 3.0, false));
          plan.push_back(WithFinerFarField(s, 2.5, true));
          plan.push_back(WithFinerFarField(s, 3.0, true));
          // What the exact far sums near saturation would cost here, above their default
          // limit (FarFieldExactSumLimit): 93% of an H200's frame, for the same error
          // (docs/far-field.md, "The exact far sums on a GPU").
          plan.push_back(ExactFarSumsAtAnyCount(s));
          // A list texture a quarter the size (32 MiB instead of 128 MiB, one bit per
          // light and cluster): ruled out on a GPU as the cause of the 65,536-light frame
          // (docs/benchmark/2026-11-27/gpu-h200-exact-sums).
          Step q = s;
          q.Sweep = "tiles";
          q.Value = "16x8";
          q.Apply = [](vtkClusteredLightingPass* p)
          {
            p->SetTilesX(16);
            p->SetTilesY(8);
          };
          plan.push_back(q);
          for (std::size_t k = first; k < plan.size(); ++k)
          {
            const std::function<void(vtkClusteredLightingPass*)> apply = plan[k].Apply;
            plan[k].Apply = [apply](vtkClusteredLightingPass* p)
            {
              if (apply)
              {
                apply(p);
              }
              p->SetFarFieldRefineStillLights(false);
            };
          }
        }
        if (layout == "uniform" && n <= 16384)
        {
          s.Method = "brute";
          s.Frames = (n >= 16384 && !quick) ? 3 : (quick ? 1 : F);
          s.Counts = false;
          s.Apply = [](vtkClusteredLightingPass* p)
          { p->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE); };
          plan.push_back(s);
        }
      }
    }
    // Lights as users write them (issue 11), each with its brute-force peer: 2,000 dense
    // inverse-square lights (attenuation (1, 0, 8), intensity 1, no radius), and 300
    // vtkLights of the renderer with VTK's default attenuation (1, 0, 0).
    if (main && !quick)
    {
      static const char* const layouts[2] = { "dense", "always-on" };
      static const int lights[2] = { 2000, 300 };
      for (int k = 0; k < 2; ++k)
      {
        Step s = base;
        s.Layout = layouts[k];
        s.Lights = lights[k];
        s.Value = std::to_string(lights[k]);
        plan.push_back(s);
        AddNearBudgetRows(s, plan);
        if (k == 0)
        {
          // What the exact far sums near saturation cost, and what they buy.
          plan.push_back(WithoutExactFarSums(s));
        }
        // Always-on lights are where the far diffuse's order counts most.
        plan.push_back(WithOrder2Diffuse(s));
        // The pass's default, which chooses the prepass by timing.
        Step automatic = s;
        automatic.Sweep = "depth";
        automatic.Value = "automatic";
        MakeAutomatic(automatic);
        plan.push_back(automatic);
        s.Method = "brute";
        s.Counts = false;
        s.Apply = [](vtkClusteredLightingPass* p)
        { p->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE); };
        plan.push_back(s);
      }
    }
    // Animated lights: every light moves every frame, so they are read, prepared and
    // uploaded every frame on top of the view's assignment (light_update_ms).
    if (main)
    {
      // A fixed array: GCC 12 warns (-Wfree-nonheap-object) on a vector grown here.
      const long long animated[3] = { 4096, 65536, options.LargestLights };
      const int rows = quick ? 1 : (options.LargestLights > 0 ? 3 : 2);
      for (int k = 0; k < rows; ++k)
      {
        const long long n = animated[k];
        Step s = base;
        s.Lights = static_cast<int>(n);
        s.Sweep = "lights";
        s.Value = "animated";
        s.AnimateLights = true;
        s.Counts = true; // measured with the lights back where the reference was rendered
        s.Reference = n <= 16384;
        s.Frames = n > 16384 ? 3 : base.Frames;
        plan.push_back(s);
        // The rebuild with the far diffuse to order 2 (the fourth moments double the node
        // sums).
        if (!quick && n <= 65536)
        {
          Step order2 = WithOrder2Diffuse(s);
          order2.Sweep = "lights";
          order2.Value = "animated (order-2 diffuse)";
          plan.push_back(order2);
          Step bins = WithSpecularBins(s);
          bins.Sweep = "lights";
          bins.Value = "animated (specular bins)";
          plan.push_back(bins);
        }
        // Every block of the grid summed (FarFieldSkipEmptyBlocks off): what summing only
        // the nodes surfaces read saves in each rebuild.
        if (!quick)
        {
          Step everyBlock = s;
          everyBlock.Value = "animated (every block)";
          everyBlock.Apply = [](vtkClusteredLightingPass* p)
          { p->SetFarFieldSkipEmptyBlocks(false); };
          plan.push_back(everyBlock);
          // In a multisampled window, as VTK's default asks for (8 samples): the surfaces'
          // blocks and those the prepass's recorded fragments reach (fragments shaded at
          // their pixels' centres, off their surfaces), against the window's own reference.
          Step multisampled = s;
          multisampled.Value = "animated (8 samples)";
          multisampled.ChangesScene = "8 samples";
          multisampled.Setup = [](Context& ctx) { ctx.GetWindow()->SetMultiSamples(8); };
          multisampled.Teardown = [](Context& ctx) { ctx.GetWindow()->SetMultiSamples(0); };
          plan.push_back(multisampled);
        }
        // Lights moving under a still camera: the prepass's depths are copied back
        // (ReuseDepthPrepass), and only the lights are assigned again.
        if (!quick && k == 0)
        {
          Step still = s;
          still.Value = "animated (camera static)";
          still.Moving = false;
          plan.push_back(still);
        }
        // With an error budget, which chooses the far field's resolution (once: moving
        // lights keep it), so what the budget costs in each frame's rebuild.
        for (double b : { 1.0, 4.0 })
        {
          if (quick || n > 65536)
          {
            break;
          }
          Step budget = s;
          budget.Sweep = "budget";
          char value[48];
          std::snprintf(value, sizeof(value), "%g/255 animated", b);
          budget.Value = value;
          budget.Apply = [b](vtkClusteredLightingPass* p) { p->SetErrorBudget(b / 255.0); };
          plan.push_back(budget);
        }
      }
      // The same with white lights: the far field's build sums one channel
      // (FarFieldSharedColor).
      for (int k = 0; k < std::min(rows, 2); ++k)
      {
        const int n = static_cast<int>(animated[k]);
        Step s = base;
        s.Lights = n;
        s.Sweep = "light colour";
        s.Value = "white animated";
        s.AnimateLights = true;
        s.Reference = n <= 16384;
        s.Frames = n > 16384 ? 3 : base.Frames;
        s.ChangesScene = "white lights";
        s.Setup = [n](Context& ctx)
        {
          for (vtkIdType i = 0; i < n; ++i)
          {
            ctx.GetLights()->SetColor(i, 1.0, 1.0, 1.0);
          }
        };
        s.Teardown = [n](Context& ctx) { ctx.MakeLights(n, "uniform"); };
        plan.push_back(s);
        // Still white lights at 65,536, with a reference, without the exact far sums near
        // saturation (the default above FarFieldExactSumLimit) and with them: where the
        // time of white lights goes (docs/far-field.md).
        for (bool exact : { false, true })
        {
          if (n > 16384)
          {
            Step still = s;
            still.AnimateLights = false;
            still.Reference = true;
            still.Frames = 2;
            still.Value = exact ? "white exact far sums" : "white";
            if (exact)
            {
              still.Apply = [](vtkClusteredLightingPass* p)
              { p->SetFarFieldExactSumLimit(VTK_INT_MAX); };
            }
            plan.push_back(still);
          }
        }
      }
    }
    if (main && !quick && options.LargestLights > 0)
    {
      Step s = base;
      s.Lights = static_cast<int>(options.LargestLights);
      s.Value = std::to_string(options.LargestLights);
      s.Frames = 3;
      s.Reference = false; // hours per frame here
      s.Note = "largest the default grid holds; no brute-force reference at this count";
      plan.push_back(s);
    }

    // Stock VTK 9.1 with the same lights as vtkLights (on the house too, where triangles
    // are large: the clustered/stock ratio depends on the mesh, see docs/benchmark).
    const std::vector<int> stockCounts = quick ? std::vector<int>{ 1, 8 }
      : main                                   ? std::vector<int>{ 1, 8, 64, 256 }
                                               : std::vector<int>{ 1, 8 };
    for (int n : stockCounts)
    {
      Step s = base;
      s.Lights = n;
      s.Value = std::to_string(n);
      s.Method = "stock";
      s.Frames = quick ? 2 : F;
      s.Counts = false;
      s.Note = "first frame compiles VTK's unrolled per-light shader";
      plan.push_back(s);
    }
    // Stock VTK with the closed meshes' hidden faces culled by hand (vtkProperty's
    // culling), as the pass culls them itself: the same images, beside the rows above (on
    // every scene: the Floors table takes its base frame from them).
    for (int n : !quick ? std::vector<int>{ 1, 8 } : std::vector<int>{})
    {
      Step s = base;
      s.Lights = n;
      s.Method = "stock";
      s.Sweep = "culling";
      s.Value = "back faces culled by hand (" + std::to_string(n) + ")";
      s.Frames = F;
      s.Counts = false;
      s.Reference = false;
      auto culled = std::make_shared<std::vector<vtkSmartPointer<vtkActor>>>();
      s.Setup = [culled](Context& ctx) { *culled = CullClosedMeshesByHand(ctx); };
      s.Teardown = [culled](Context&)
      {
        for (vtkActor* a : *culled)
        {
          a->GetProperty()->BackfaceCullingOff();
          a->GetProperty()->FrontfaceCullingOff();
        }
        culled->clear();
      };
      plan.push_back(s);
    }

    // The depth prepass and depth-aware clusters (on by default), off one by one at 4,096
    // uniform lights, on every scene: their gain depends on the scene's depth complexity.
    // Both off at 64 and 1,024 lights too: the prepass costs a geometry pass whatever the
    // lights, and with few lights per pixel it saves less than that (docs/depth.md).
    const auto turnBothOff = [](vtkClusteredLightingPass* p)
    {
      p->SetDepthPrepass(false);
      p->SetDepthAwareClusters(false);
    };
    auto bothOff = [&](int lights)
    {
      Step off = base;
      off.Lights = lights;
      off.Sweep = "depth";
      off.Value = "prepass and depth-aware off";
      off.Apply = turnBothOff;
      plan.push_back(off);
    };
    if (!quick)
    {
      for (int n : { 64, 1024 })
      {
        bothOff(n);
      }
      // The brute-force peer draws the prepass too (no hidden fragment is shaded), so it
      // got faster where much is hidden when the prepass came: without it, the same row.
      Step brute = base;
      brute.Lights = 1024;
      brute.Method = "brute";
      brute.Sweep = "depth";
      brute.Value = "prepass and depth-aware off";
      brute.Frames = 3;
      brute.Counts = false;
      brute.Apply = [turnBothOff](vtkClusteredLightingPass* p)
      {
        p->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE);
        turnBothOff(p);
      };
      plan.push_back(brute);
    }
    // The prepass chosen by timing (AutomaticDepthPrepass, off in every other row).
    auto automatic = [&](int lights)
    {
      Step a = base;
      a.Lights = lights;
      a.Sweep = "depth";
      a.Value = "automatic";
      MakeAutomatic(a);
      plan.push_back(a);
    };
    for (int n :
      quick ? std::vector<int>{ base.Lights } : std::vector<int>{ 64, 1024, base.Lights })
    {
      automatic(n);
    }
    // A multisampled window, as VTK's default asks for (8 samples): its depth cannot be
    // read back, so the depth-aware clusters are off and only the prepass is left; the
    // default, both off, and the prepass chosen by timing, each against the window's own
    // exact reference.
    if (!quick)
    {
      for (int n : { 1024, base.Lights })
      {
        for (const char* variant : { "", " both off", " automatic" })
        {
          Step m = base;
          m.Lights = n;
          m.Sweep = "window";
          m.Value = std::string("8 samples") + variant;
          m.ChangesScene = "8 samples";
          m.Setup = [](Context& ctx) { ctx.GetWindow()->SetMultiSamples(8); };
          m.Teardown = [](Context& ctx) { ctx.GetWindow()->SetMultiSamples(0); };
          const std::string v = variant;
          if (v == " both off")
          {
            m.Apply = turnBothOff;
          }
          else if (v == " automatic")
          {
            MakeAutomatic(m);
          }
          plan.push_back(m);
        }
      }
    }
    auto depthRows = [&]()
    {
      bothOff(base.Lights);
      Step prepassOnly = base;
      prepassOnly.Sweep = "depth";
      prepassOnly.Value = "prepass only";
      prepassOnly.Apply = [](vtkClusteredLightingPass* p) { p->SetDepthAwareClusters(false); };
      plan.push_back(prepassOnly);
    };
    depthRows();
    // What translucency costs (issue 12: its fragments, VTK's compositing, the clusters
    // kept in front of the opaque surfaces): the house, whose windows are 23 translucent
    // actors, with every actor opaque, clustered and brute force (docs/depth.md).
    if (!quick && base.Where == &HouseScene())
    {
      for (const char* method : { "clustered", "brute" })
      {
        Step o = base;
        o.Method = method;
        o.Sweep = "translucency";
        o.Value = "all opaque";
        o.ChangesScene = "all opaque";
        o.Setup = [](Context& ctx) { SwitchOpaque(ctx, true); };
        o.Teardown = [](Context& ctx) { SwitchOpaque(ctx, false); };
        if (o.Method == "brute")
        {
          o.Frames = 3;
          o.Counts = false;
          o.Apply = [](vtkClusteredLightingPass* p)
          { p->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE); };
        }
        plan.push_back(o);
      }
    }
    // Finer screen tiles, on every scene: fewer lights walked per pixel, for a costlier
    // assignment (issue 12; docs/depth.md says what they buy in time).
    if (!quick)
    {
      for (const auto& t : { std::array<int, 2>{ 48, 24 }, std::array<int, 2>{ 64, 32 },
             std::array<int, 2>{ 64, 48 }, std::array<int, 2>{ 128, 96 } })
      {
        Step s = base;
        s.Sweep = "tiles";
        s.Value = std::to_string(t[0]) + "x" + std::to_string(t[1]);
        s.Apply = [t](vtkClusteredLightingPass* p)
        {
          p->SetTilesX(t[0]);
          p->SetTilesY(t[1]);
        };
        plan.push_back(s);
      }
    }
    // The near field's budget on every scene: lights per point evaluated exactly, against
    // what the far field adds back (docs/far-field.md).
    if (!quick)
    {
      AddNearBudgetRows(base, plan);
    }
    // Closed opaque surfaces' hidden faces drawn (AutomaticBackfaceCulling off) on every
    // scene: what culling them saves (the log's "culled" column counts the props culled).
    {
      Step drawn = base;
      drawn.Sweep = "culling";
      drawn.Value = "automatic back-face culling off";
      drawn.Apply = [](vtkClusteredLightingPass* p) { p->SetAutomaticBackfaceCulling(false); };
      plan.push_back(drawn);
    }
    // The default frame without its far field, on every scene: every light cut where the
    // default cuts the split lights (FarFieldCutoff), so the walk is the default's and the
    // difference in time is the far field's (its build, texture reads and kernels). The
    // Floors table takes it from here; its error is what the far field buys.
    {
      Step cut = base;
      cut.Sweep = "far field";
      cut.Value = "off at default radii";
      cut.Apply = [](vtkClusteredLightingPass* p)
      {
        p->SetContributionCutoff(p->GetFarFieldCutoff());
        p->SetFarField(false);
      };
      plan.push_back(cut);
    }
    // The default with the far diffuse to order 2, on every scene.
    plan.push_back(WithOrder2Diffuse(base));
    plan.push_back(WithSpecularBins(base));
    // The finer far field that holds 65,536 lights within 2 steps, at the default's count:
    // what it costs where the default already meets its targets.
    if (!quick)
    {
      plan.push_back(WithFinerFarField(base, 3.0, true));
    }
    if (!main)
    {
      continue;
    }
    // Knobs, one at a time from the default, at 4,096 uniform lights.
    auto knob = [&](const std::string& sweep, const std::string& value,
                  std::function<void(vtkClusteredLightingPass*)> apply)
    {
      Step s = base;
      s.Sweep = sweep;
      s.Value = value;
      s.Apply = std::move(apply);
      plan.push_back(s);
      return &plan.back();
    };
    const std::vector<double> cutoffs =
      quick ? std::vector<double>{ 64, 1024 } : std::vector<double>{ 16, 64, 256, 1024, 4096 };
    for (double c : cutoffs)
    {
      // Every light's cutoff, the split lights' too (FarFieldCutoff 0): 1/1024 is the
      // default before FarFieldCutoff (2026-12-06), 1/256 today's default frame.
      knob("cutoff", Fraction(c),
        [c](vtkClusteredLightingPass* p)
        {
          p->SetCutoff(1.0 / c);
          p->SetFarFieldCutoff(0.0);
        });
    }
    // The far field (docs/far-field.md): off is the cut tails of earlier versions.
    knob("far field", "off", [](vtkClusteredLightingPass* p) { p->SetFarField(false); });
    if (!quick)
    {
      for (int nodes : { 8192, 131072 })
      {
        knob("far field", std::to_string(nodes) + " nodes",
          [nodes](vtkClusteredLightingPass* p) { p->SetFarFieldResolution(nodes); });
      }
      knob("near budget", "64", [](vtkClusteredLightingPass* p) { p->SetNearFieldBudget(64.0); });
    }
    knob("bounds", "centre-depth quad",
      [](vtkClusteredLightingPass* p)
      { p->SetBoundsMethod(vtkClusteredLightingPass::BOUNDS_CENTER_DEPTH_QUAD); });
    if (!quick)
    {
      knob("falloff", "windowed",
        [](vtkClusteredLightingPass* p)
        { p->SetFalloff(vtkClusteredLightingPass::FALLOFF_WINDOWED); });
      knob("tiles", "16x8",
        [](vtkClusteredLightingPass* p)
        {
          p->SetTilesX(16);
          p->SetTilesY(8);
        });
      knob("slices", "16", [](vtkClusteredLightingPass* p) { p->SetSlices(16); });
      knob("slices", "64", [](vtkClusteredLightingPass* p) { p->SetSlices(64); });
      knob("slicing", "linear",
        [](vtkClusteredLightingPass* p)
        { p->SetSlicingScheme(vtkClusteredLightingPass::SLICING_LINEAR); });
      knob("morton", "off", [](vtkClusteredLightingPass* p) { p->SetMortonOrder(false); });
      knob("culling", "per-cluster off",
        [](vtkClusteredLightingPass* p) { p->SetPerClusterCulling(false); });
      knob("camera", "static", nullptr)->Moving = false;
      // The depth prepass copied back on still frames (ReuseDepthPrepass), and what saving
      // its depths costs the frames that draw it: both rows with the reuse off.
      knob("camera", "static, prepass reuse off",
        [](vtkClusteredLightingPass* p) { p->SetReuseDepthPrepass(false); })
        ->Moving = false;
      knob("prepass reuse", "off",
        [](vtkClusteredLightingPass* p) { p->SetReuseDepthPrepass(false); });
      // Effects a scene calls for: specular off, spot lights present (each with the exact
      // reference of its own scene).
      Step* specular = knob("specular", "off", nullptr);
      specular->ChangesScene = "specular off";
      specular->Setup = [](Context& ctx) { SwitchSpecular(ctx, true); };
      specular->Teardown = [](Context& ctx) { SwitchSpecular(ctx, false); };
      // The spot-cone code alone: one light becomes a spot light, so every shader gets the
      // cone code while the other 4,095 lights stay point lights.
      Step* oneSpot = knob("spots", "1 spot light", nullptr);
      oneSpot->ChangesScene = "1 spot light";
      oneSpot->Setup = [](Context& ctx) { ctx.GetLights()->SetSpot(0, 0.0, -1.0, 0.0, 60.0, 1.0); };
      oneSpot->Teardown = [](Context& ctx) { ctx.MakeLights(4096, "uniform"); };
      Step* tenth = knob("spots", "10% spot lights", nullptr);
      tenth->ChangesScene = "10% spot lights";
      tenth->Setup = [](Context& ctx)
      {
        for (vtkIdType i = 0; i < 4096; i += 10)
        {
          ctx.GetLights()->SetSpot(i, 0.0, -1.0, 0.0, 60.0, 1.0);
        }
      };
      tenth->Teardown = [](Context& ctx) { ctx.MakeLights(4096, "uniform"); };
      // The same spot lights assigned by their spheres (SpotConeCulling off): what cone
      // culling saves, side by side.
      const Step spots = *tenth; // knob() may move the plan's steps
      Step* tenthSpheres = knob("spots", "10% spot lights (cone culling off)",
        [](vtkClusteredLightingPass* p) { p->SetSpotConeCulling(false); });
      tenthSpheres->ChangesScene = spots.ChangesScene;
      tenthSpheres->Setup = spots.Setup;
      tenthSpheres->Teardown = spots.Teardown;
      // The renderer's FXAA and SSAO, which the pass's own steps apply as the renderer does
      // (docs/guide.md), beside stock VTK with 8 lights and the same option: what each costs
      // through the pass. Under SSAO the pass draws no depth prepass.
      for (const bool ssao : { false, true })
      {
        const auto set = [ssao](Context& ctx, bool on)
        {
          vtkRenderer* ren = ctx.GetRenderer();
          ssao ? ren->SetUseSSAO(on) : ren->SetUseFXAA(on);
        };
        Step* option = knob("renderer", ssao ? "SSAO" : "FXAA", nullptr);
        option->ChangesScene = ssao ? "SSAO" : "FXAA";
        option->Setup = [set](Context& ctx) { set(ctx, true); };
        option->Teardown = [set](Context& ctx) { set(ctx, false); };
        Step stock = *option;
        stock.Lights = 8;
        stock.Method = "stock";
        stock.Counts = false;
        stock.Reference = false;
        stock.ChangesScene.clear();
        plan.push_back(stock);
      }
      // White lights (VTK's default colour): the far field is one channel times the colour
      // (FarFieldSharedColor), side by side with the same lights kept in three channels.
      for (bool shared : { true, false })
      {
        Step* white = knob("light colour", shared ? "white" : "white (shared colour off)",
          [shared](vtkClusteredLightingPass* p) { p->SetFarFieldSharedColor(shared); });
        white->ChangesScene = "white lights";
        white->Setup = [](Context& ctx)
        {
          for (vtkIdType i = 0; i < 4096; ++i)
          {
            ctx.GetLights()->SetColor(i, 1.0, 1.0, 1.0);
          }
        };
        white->Teardown = [](Context& ctx) { ctx.MakeLights(4096, "uniform"); };
      }
      // PBR actors (VTK's isotropic terms), a plastic and a metal: the default
      // FarFieldTolerance (the far light bracketed from the moments, summed exactly where
      // the bracket is wider) and 1 (the moments' estimate alone), each against the exact
      // reference of its own scene (docs/far-field.md, "PBR actors").
      struct PbrMaterialRow
      {
        const char* Name;
        double Metallic, Roughness;
      };
      for (const PbrMaterialRow& m :
        { PbrMaterialRow{ "PBR plastic", 0.0, 0.5 }, PbrMaterialRow{ "PBR metal", 1.0, 0.4 } })
      {
        for (double tolerance : { 2.0 / 255.0, 1.0 })
        {
          Step* pbr =
            knob("material", std::string(m.Name) + (tolerance < 1.0 ? "" : " far tolerance 1"),
              [tolerance](vtkClusteredLightingPass* p) { p->SetFarFieldTolerance(tolerance); });
          pbr->ChangesScene = m.Name;
          pbr->Frames = std::min(F, 3);
          pbr->Setup = [m](Context& ctx) { SwitchPbr(ctx, true, m.Metallic, m.Roughness); };
          pbr->Teardown = [](Context& ctx) { SwitchPbr(ctx, false); };
        }
        // The peer: brute force on the same PBR actors.
        Step brute = plan.back();
        brute.Method = "brute";
        brute.Value = m.Name;
        brute.Counts = false;
        brute.Apply = [](vtkClusteredLightingPass* p)
        { p->SetShadingMode(vtkClusteredLightingPass::SHADING_BRUTE_FORCE); };
        plan.push_back(brute);
      }
    }
    const std::vector<double> budgets =
      quick ? std::vector<double>{ 4 } : std::vector<double>{ 1, 4, 16 };
    for (double b : budgets)
    {
      char value[32];
      std::snprintf(value, sizeof(value), "%g/255", b);
      knob("budget", value, [b](vtkClusteredLightingPass* p) { p->SetErrorBudget(b / 255.0); });
    }
  }
  return plan;
}

} // namespace ClusteredLightingBenchmark
