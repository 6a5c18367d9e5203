// SPDX-License-Identifier: BSD-3-Clause
// Soak test: 2,000 frames (800 under AddressSanitizer) in a small window (96x72 and two other
// sizes) with everything a long-running application does to the pass changing under it. The
// schedule repeats every 200 frames (so the state at the end of every period is the same):
//  - clustered lights move every frame; the light set is resized 8 times per period
//    (40 to 600 lights), and for 10 frames one of its lights is invalid (NaN position,
//    Inf intensity, negative attenuation or a colour beyond the float range, in turn);
//  - renderer vtkLights are added and removed (1 to 5) and moved;
//  - the window is resized; the pass is switched off (renderer->SetPass(nullptr)) for 20
//    frames and on again; the grid (TilesX/TilesY/Slices) changes 5 times and the far
//    field's resolution with it (512 to 32,768 nodes: the lights have no radius, so the
//    far field is rebuilt every frame they move; 90% of the soak's time under
//    AddressSanitizer, when every frame built 32,768 nodes); brute-force shading and
//    every debug view are used;
//  - the depth prepass (with depth-aware clusters) is drawn in 40 frames of every 50
//    and not in the other 10, on a fixed schedule. AutomaticDepthPrepass is off here:
//    its choice follows the machine's timing, and which shader variants a run compiles
//    after the warm-up must not (TestClusteredLightingAutomaticPrepass tests the choice).
// Checks:
//  - no GL error after any frame (glGetError);
//  - no NaN or Inf pixel (DEBUG_NON_FINITE view, every 100 frames, half of them while an
//    invalid light is present, in brute force), and zero false negatives of the
//    assignment (6 times);
//  - exactly one warning per invalid-light episode (the pass reports a problem once while
//    it persists), naming the light, and no error;
//  - no growth after the warm-up (the first 2 periods, in which every shader variant,
//    texture size, grid and window size has been used twice): the pass's GL objects and
//    every GL object of the context (a census asked of GL) are the same at the end as
//    after the warm-up, and so is memory, read two ways:
//
//  * Resident memory (/proc/self/statm): the least of the last 3 period ends may exceed
//    the least of the first 3 period ends after the warm-up by at most 8 MiB. Resident
//    memory moves in steps that are not leaks: glibc's arenas keep the high-water mark of
//    their fragmentation (the light set and the textures are reallocated 8 times per
//    period, at up to 4 MiB), and code pages of the libraries are faulted in as rarer
//    paths first run. Measured on llvmpipe in 10 runs of 2,000 frames: -1.0 to +3.8 MiB
//    between those windows; in a 6,000-frame run +3.3 MiB, reached by frame 1,800 and
//    flat from there to 6,000 (it converges; a leak would keep growing). Since the depth
//    prepass (its programs and depth readback): +3.3 to +5.1 MiB in 24 runs, the step
//    again between frames 1,600 and 1,800. 8 MiB is 1.6 times the largest. A leak of
//    7 KiB per frame (light records of 110 lights) exceeds it. Since 2026-12-06 the
//    windows' least values are compared, not their largest: the far field's arrays are
//    twice as large (its fourth moments), and period ends then swung by up to 12 MiB from
//    one period to the next as glibc gave memory back and took it again (the largest of
//    the windows differed by -6.5 to +8.7 MiB in 7 runs, one over the tolerance). A leak
//    never gives memory back, so it raises the least value as much as the largest.
//    Since 2026-12-07 glibc's mmap threshold is pinned (mallopt) for the soak: the far
//    specular's bins added arrays and a texture of tens of MiB, and the threshold, which
//    glibc raises to each large block freed, then moved them to the heap after a few
//    periods: a one-off step, +9 to +15 MiB in 4 of 6 runs (-5 to 0 in the others), flat
//    after it, the heap in use as flat as before. Pinned: +0.05 and +0.08 MiB in 2 runs.
//  * Heap in use (glibc's mallinfo2: bytes allocated and not freed, blind to
//    fragmentation), per period after the warm-up: the median of the periods' growth (8
//    in CI) at most 16 KiB (80 bytes per frame). The schedule repeats every period, so a
//    leak of the pass grows the heap in every period; the median ignores a one-off
//    allocation in a few periods that is not the pass's. Measured: 4 to 5 KiB per
//    period, all of it from resizing the window, which grows the heap by the same amount
//    with no pass at all (stock VTK on Xlib without an interactor); with the window size
//    fixed the heap grows by less than 0.2 KiB per period. One-off steps: +188 KiB in
//    one period in 3 runs of 6 (none in 6 more, slowed by tracing allocations; never
//    again in later periods), which failed the total-growth check (128 KiB over 1,600
//    frames) this replaces. A leak of one 128-byte block per frame fails: median
//    +32.5 KiB (measured).
//  GL objects leaked once per period are caught exactly by the census. Under
//  AddressSanitizer (scripts/run-sanitizers.sh) the two memory checks are skipped: the
//  allocator is ASan's (mallinfo2 does not see it) and freed blocks are held in its
//  256 MiB quarantine, so resident memory grows by design; LeakSanitizer checks the heap
//  there instead.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingScenes.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <malloc.h> // for mallinfo2
#include <map>

namespace
{
constexpr int Period = 200;
constexpr int WarmUpPeriods = 2;
constexpr long long ResidentTolerance = 8LL << 20;
constexpr long long HeapTolerancePerPeriod = 16LL << 10;
#if defined(__SANITIZE_ADDRESS__)
constexpr bool MemoryChecks = false;
// Under AddressSanitizer the soak runs about 6x slower (141 s for 800 frames against
// 23 s for 2,000, measured alone; still the longest test of the sanitizer stage) and
// skips the memory checks, the only ones that need many periods. The schedule repeats every period,
// so 4 periods (the warm-up and 2 more) run every path of it twice after the warm-up, and each of
// the 4 kinds of invalid light (one per period, in turn) once.
constexpr int DefaultFrames = 800;
#else
constexpr bool MemoryChecks = true;
constexpr int DefaultFrames = 2000;
#endif

/// Bytes of heap in use (glibc: all arenas, plus blocks served by mmap).
long long HeapInUse()
{
  const struct mallinfo2 mi = mallinfo2();
  return static_cast<long long>(mi.uordblks + mi.hblkhd);
}

int Status = EXIT_SUCCESS;
int FailureReports = 0;

void Fail(const std::string& what)
{
  Status = EXIT_FAILURE;
  if (++FailureReports <= 20)
  {
    std::printf("FAILED: %s\n", what.c_str());
  }
}

/// Number of live GL objects of each kind (objects re-created since get new names).
std::map<unsigned int, std::size_t> CountByKind(const ClusteredLightingTest::GLNames& names)
{
  std::map<unsigned int, std::size_t> counts;
  for (const auto& n : names)
  {
    ++counts[n.first];
  }
  return counts;
}

std::string DescribeCounts(const std::map<unsigned int, std::size_t>& counts)
{
  std::string out;
  for (const auto& kv : counts)
  {
    out += " " + std::to_string(kv.second) + " " + ClusteredLightingTest::GLKindName(kv.first);
  }
  return out;
}
}

int TestClusteredLightingSoak(int, char*[])
{
  using namespace ClusteredLightingTest;
  // CLUSTERED_LIGHTING_SOAK_FRAMES runs a longer soak by hand (whole periods; CI: 2,000,
  // 800 under AddressSanitizer).
  const char* framesEnv = std::getenv("CLUSTERED_LIGHTING_SOAK_FRAMES");
  const int Frames = framesEnv
    ? std::max(MemoryChecks ? 8 : 4, std::atoi(framesEnv) / Period) * Period
    : DefaultFrames;
  // Resident memory follows what is allocated only with glibc's mmap threshold pinned at
  // its default (128 KiB): left to move, it rises to the size of each large block freed
  // (up to 32 MiB), and large blocks allocated after that (the far field's arrays, the
  // driver's texture storage, re-specified at 5 sizes per period) come from the heap,
  // which keeps their memory when they are freed (see the file description).
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  ren->AutomaticLightCreationOff();
  SetUpTestScene(renWin, ren, 96, 72, 16);

  vtkNew<vtkClusteredLightSet> lights;
  std::vector<std::array<double, 3>> base;
  auto makeLights = [&](int n)
  {
    MakeTestLights(lights, n, 0.7, 17);
    base.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
    {
      lights->GetPosition(i, base[static_cast<std::size_t>(i)].data());
    }
  };

  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  // The far specular's bins (off by default): their texture and arrays soak too, rebuilt
  // with the far field every frame.
  pass->FarFieldSpecularBinsOn();
  vtkNew<MessageCollector> messages;
  messages->Watch(pass);
  ren->SetPass(pass);
  std::vector<vtkSmartPointer<vtkLight>> rendererLights;

  const int lightCounts[8] = { 300, 450, 600, 150, 600, 40, 300, 500 };
  const int windowSizes[3][2] = { { 96, 72 }, { 80, 60 }, { 112, 84 } };
  const int grids[5][3] = { { 32, 16, 32 }, { 8, 4, 8 }, { 16, 16, 64 }, { 1, 1, 1 },
    { 24, 12, 20 } };
  const int farFieldResolutions[5] = { 4096, 32768, 512, 4096, 8192 };
  const int debugViews[5] = { vtkClusteredLightingPass::DEBUG_CLUSTER_INDEX,
    vtkClusteredLightingPass::DEBUG_HEAT_MAP, vtkClusteredLightingPass::DEBUG_EVALUATED_COUNT,
    vtkClusteredLightingPass::DEBUG_REACHED_COUNT, vtkClusteredLightingPass::DEBUG_NON_FINITE };

  std::vector<long long> rssAtPeriodEnd, heapAtPeriodEnd;
  int warnings = 0, warningsNamingTheLight = 0, errorMessages = 0;
  GLNames censusAfterWarmUp;
  int passObjectsAfterWarmUp = -1;
  int expectedWarnings = 0, glErrors = 0, nonFiniteChecks = 0, assignmentChecks = 0;
  int farFieldMisses = 0; // frames drawn without the far field at its scheduled resolution
  std::size_t nonFinitePixels = 0;
  const auto start = std::chrono::steady_clock::now();

  for (int frame = 0; frame < Frames; ++frame)
  {
    const int t = frame % Period;
    const int period = frame / Period;

    // Clustered lights: resized 8 times per period, moving every frame.
    const int n = lightCounts[t / 25];
    if (lights->GetNumberOfLights() != n)
    {
      makeLights(n);
    }
    for (int i = frame % 3; i < n; i += 3)
    {
      const auto& b = base[static_cast<std::size_t>(i)];
      const double phase = 0.05 * frame + i;
      lights->SetPosition(i, b[0] + 0.3 * std::sin(phase), b[1], b[2] + 0.3 * std::cos(phase));
    }
    // One invalid light for 10 frames per period.
    const bool invalid = t >= 150 && t < 160;
    if (invalid)
    {
      const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
      switch (period % 4)
      {
        case 0:
          lights->SetPosition(0, nan, 0.0, 0.0);
          break;
        case 1:
          lights->SetIntensity(0, inf);
          break;
        case 2:
          lights->SetAttenuation(0, -1.0, 0.0, 1.0);
          break;
        default:
          lights->SetColor(0, 1e300, 1.0, 1.0);
          break;
      }
      // The pass warns once per problem, not every frame it persists.
      expectedWarnings += t == 150 ? 1 : 0;
    }
    else if (t == 160)
    {
      makeLights(n); // restores light 0
    }

    // Renderer lights: 1 to 5, added and removed, moving.
    const std::size_t wanted = static_cast<std::size_t>((t / 10) % 5 + 1);
    while (rendererLights.size() < wanted)
    {
      vtkNew<vtkLight> l;
      l->SetLightTypeToSceneLight();
      l->SetPositional(true);
      l->SetConeAngle(rendererLights.size() % 2 ? 35.0 : 180.0);
      l->SetFocalPoint(0.0, -1.0, 0.0);
      l->SetAttenuationValues(1.0, 0.0, 3.0);
      ren->AddLight(l);
      rendererLights.emplace_back(l);
    }
    while (rendererLights.size() > wanted)
    {
      ren->RemoveLight(rendererLights.back());
      rendererLights.pop_back();
    }
    for (std::size_t k = 0; k < rendererLights.size(); ++k)
    {
      const double a = 0.07 * frame + 1.3 * static_cast<double>(k);
      rendererLights[k]->SetPosition(2.0 * std::cos(a), 0.8, 2.0 * std::sin(a));
    }

    // Window size, pass on/off, grid, shading mode, debug views.
    const int* size = windowSizes[(t / 20) % 3];
    if (renWin->GetSize()[0] != size[0] || renWin->GetSize()[1] != size[1])
    {
      renWin->SetSize(size[0], size[1]);
    }
    const bool on = !(t >= 100 && t < 120);
    ren->SetPass(on ? pass.GetPointer() : nullptr);
    const int* grid = grids[t / 40];
    pass->SetTilesX(grid[0]);
    pass->SetTilesY(grid[1]);
    pass->SetSlices(grid[2]);
    pass->SetFarFieldResolution(farFieldResolutions[t / 40]);
    pass->SetShadingMode(t % 40 >= 32 ? vtkClusteredLightingPass::SHADING_BRUTE_FORCE
                                      : vtkClusteredLightingPass::SHADING_CLUSTERED);
    pass->SetDebugView(
      t >= 60 && t < 90 ? debugViews[(t - 60) / 6] : vtkClusteredLightingPass::DEBUG_NONE);
    // A fixed heat-map scale: the heat map scaled to the data renders a counting frame
    // first, whose shader programs VTK's shader cache adds as new light counts appear
    // (heap growth that is the cache's, not a leak); TestClusteredLightingUsability
    // checks that mode.
    pass->SetHeatMapMaximum(64.0);
    const bool prepass = t % 50 < 40;
    pass->AutomaticDepthPrepassOff();
    pass->SetDepthPrepass(prepass);
    pass->SetDepthAwareClusters(prepass);

    renWin->Render();
    std::string first;
    const int errors = CountGLErrors(renWin, &first);
    if (errors)
    {
      glErrors += errors;
      Fail("frame " + std::to_string(frame) + ": GL error " + first);
    }
    if (on && invalid && pass->GetNumberOfRejectedLights() != 1)
    {
      Fail("frame " + std::to_string(frame) + ": the invalid light was not rejected");
    }
    if (on && pass->GetShadingMode() == vtkClusteredLightingPass::SHADING_CLUSTERED &&
      pass->GetFarFieldResolutionInUse() != farFieldResolutions[t / 40])
    {
      ++farFieldMisses;
    }

    // NaN / Inf pixels every 100 frames (every other one while a light is invalid).
    if (on && frame % 100 == 55)
    {
      const std::size_t bad = CountNonFinitePixels(pass, renWin);
      ++nonFiniteChecks;
      nonFinitePixels += bad;
      if (bad)
      {
        Fail("frame " + std::to_string(frame) + ": " + std::to_string(bad) + " non-finite pixels");
      }
    }
    // The assignment stays exact under all this churn.
    if (on && frame % 250 == 125 &&
      pass->GetShadingMode() == vtkClusteredLightingPass::SHADING_CLUSTERED)
    {
      const auto cmp = CheckAssignment(pass, ren, ("frame " + std::to_string(frame)).c_str());
      ++assignmentChecks;
      if (cmp.FalseNegatives != 0 || cmp.MasterMismatches != 0)
      {
        Fail("frame " + std::to_string(frame) + ": false negatives in the assignment");
      }
    }

    if (t == Period - 1)
    {
      rssAtPeriodEnd.push_back(ResidentBytes());
      heapAtPeriodEnd.push_back(HeapInUse());
      std::printf("frame %4d: resident %.2f MiB, heap in use %.1f KiB, pass GL objects %d, %d "
                  "lights\n",
        frame + 1, rssAtPeriodEnd.back() / 1048576.0, heapAtPeriodEnd.back() / 1024.0,
        pass->GetNumberOfGLObjects(), pass->GetNumberOfClusteredLights());
      // Count the pass's messages and forget them (keeping them would grow the heap).
      warnings += static_cast<int>(messages->Warnings.size());
      for (const std::string& w : messages->Warnings)
      {
        warningsNamingTheLight += w.find("light 0") != std::string::npos ? 1 : 0;
      }
      errorMessages += static_cast<int>(messages->Errors.size());
      for (std::size_t i = 0; i < std::min<std::size_t>(messages->Errors.size(), 3); ++i)
      {
        std::printf("  error: %s\n", messages->Errors[i].c_str());
      }
      messages->Clear();
      if (period + 1 == WarmUpPeriods)
      {
        censusAfterWarmUp = TakeGLNameCensus(renWin);
        passObjectsAfterWarmUp = pass->GetNumberOfGLObjects();
      }
    }
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d frames in %.1f s (%.1f ms per frame, including checks)\n", Frames, seconds,
    1000.0 * seconds / Frames);

  // GL objects: the pass's own count and the whole context, as after the warm-up.
  const GLNames censusEnd = TakeGLNameCensus(renWin);
  std::printf("GL objects: pass %d after warm-up, %d at the end; context %zu after warm-up, %zu "
              "at the end\n",
    passObjectsAfterWarmUp, pass->GetNumberOfGLObjects(), censusAfterWarmUp.size(),
    censusEnd.size());
  if (pass->GetNumberOfGLObjects() != passObjectsAfterWarmUp ||
    passObjectsAfterWarmUp != ClusteredLightingTest::GLObjectsPerRenderer(pass))
  {
    Fail("the pass's GL objects changed after the warm-up");
  }
  std::printf("GL objects by kind: after warm-up%s; at the end%s\n",
    DescribeCounts(CountByKind(censusAfterWarmUp)).c_str(),
    DescribeCounts(CountByKind(censusEnd)).c_str());
  if (CountByKind(censusAfterWarmUp) != CountByKind(censusEnd))
  {
    Fail("the number of GL objects in the context changed after the warm-up");
  }

  // Memory: the first 3 period ends after the warm-up against the last 3 (resident, the
  // least of each), and each period's growth after the warm-up (heap in use).
  const auto firstWindow = rssAtPeriodEnd.begin() + WarmUpPeriods - 1;
  const long long early = *std::min_element(firstWindow, firstWindow + 3);
  const long long late = *std::min_element(rssAtPeriodEnd.end() - 3, rssAtPeriodEnd.end());
  std::vector<long long> heapGrowths;
  for (std::size_t p = WarmUpPeriods; p < heapAtPeriodEnd.size(); ++p)
  {
    heapGrowths.push_back(heapAtPeriodEnd[p] - heapAtPeriodEnd[p - 1]);
  }
  std::vector<long long> sorted = heapGrowths;
  std::sort(sorted.begin(), sorted.end());
  const long long medianHeapGrowth =
    (sorted[(sorted.size() - 1) / 2] + sorted[sorted.size() / 2]) / 2;
  std::string growths;
  for (const long long g : heapGrowths)
  {
    char kib[32];
    std::snprintf(kib, sizeof(kib), " %+.1f", g / 1024.0);
    growths += kib;
  }
  std::printf("resident memory: %.2f MiB after the warm-up, %.2f MiB at the end: %+.2f MiB "
              "(tolerance %.0f MiB); heap in use %+.1f KiB in all, per period (KiB):%s; "
              "median %+.1f KiB (tolerance %.0f KiB)%s\n",
    early / 1048576.0, late / 1048576.0, (late - early) / 1048576.0, ResidentTolerance / 1048576.0,
    (heapAtPeriodEnd.back() - heapAtPeriodEnd[WarmUpPeriods - 1]) / 1024.0, growths.c_str(),
    medianHeapGrowth / 1024.0, HeapTolerancePerPeriod / 1024.0,
    MemoryChecks ? "" : "; not checked under AddressSanitizer");
  if (MemoryChecks && late - early > ResidentTolerance)
  {
    Fail("resident memory grew beyond the tolerance");
  }
  if (MemoryChecks && medianHeapGrowth > HeapTolerancePerPeriod)
  {
    Fail("the heap in use grew in most periods beyond the tolerance");
  }

  // Messages: one warning per invalid-light episode, naming the light; no error.
  std::printf("%d GL errors, %zu non-finite pixels in %d checks, %d assignment checks, %d "
              "warnings (%d expected), %d errors\n",
    glErrors, nonFinitePixels, nonFiniteChecks, assignmentChecks, warnings, expectedWarnings,
    errorMessages);
  if (warnings != expectedWarnings || warningsNamingTheLight != expectedWarnings ||
    errorMessages != 0)
  {
    Fail("unexpected warnings or errors from the pass");
  }
  std::printf(
    "%d clustered frames without the far field at its scheduled resolution\n", farFieldMisses);
  if (farFieldMisses != 0)
  {
    Fail("the far field was not in use at the resolution asked for");
  }
  // One non-finite check per 100 frames; an assignment check per 250 frames unless the
  // frame renders in brute force (at most half of them).
  if (nonFiniteChecks != Frames / 100 || assignmentChecks < Frames / 500)
  {
    Fail("fewer checks than scheduled");
  }
  return Status;
}
