// SPDX-License-Identifier: BSD-3-Clause
// The far field's region (FarFieldRegion): the grid covers the visible props' bounds and
// the region an application gives (their union). ParaView renders a piece of the data on
// each rank and gives every rank the bounds of all of it, so that they build the same far
// field; a prop that comes and goes (a selection's highlight) must then move nothing.
// Lights as users write them (inverse-square, no radius) over the test scene. Checks that
//  - a region equal to the visible props' bounds renders the same image, bit for bit, as
//    no region;
//  - without a region, a small prop far from the scene moves the grid (the image of the
//    scene changes): this is what a region is for;
//  - with a region that holds that prop, adding and removing it changes nothing, bit for
//    bit, and the frame with the coarser grid of the larger region is within the stated
//    bound of brute force at every pixel, with zero false negatives (CheckClusteredFrame);
//  - a region smaller than the geometry still covers the geometry (the union), and an
//    empty region is no region; PrintSelf names the region.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkClusteredLightingPass.h"

#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

double MaxDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  return ClusteredLightingTest::CompareImages(a, b).MaxAbsError;
}

std::string Spacing(vtkClusteredLightingPass* pass)
{
  std::ostringstream os;
  os << "grid spacing " << pass->GetFarFieldGridSpacing() << ", "
     << pass->GetFarFieldDimensions()[0] << "x" << pass->GetFarFieldDimensions()[1] << "x"
     << pass->GetFarFieldDimensions()[2];
  return os.str();
}
}

int TestClusteredLightingFarFieldRegion(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 240, 180);
  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, 400, 0.03, 5);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);

  // 1. No region, then the visible props' bounds as the region: the same grid.
  rw->Render();
  const std::vector<float> plain = ClusteredLightingTest::CapturePixels(rw);
  const double plainSpacing = pass->GetFarFieldGridSpacing();
  std::printf("no region: %s\n", Spacing(pass).c_str());
  Check(pass->GetNumberOfFarFieldLights() == 400 && plainSpacing > 0.0 &&
      pass->GetNumberOfPackedFarFieldLights() == 0,
    "the far field holds every light, none packed closer than its grid resolves");
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  pass->SetFarFieldRegion(bounds);
  rw->Render();
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), plain) == 0.0 &&
      pass->GetFarFieldGridSpacing() == plainSpacing,
    "the visible props' bounds as the region: the same image, bit for bit");

  // 2. No region: a small prop far from the scene (off screen) moves the grid.
  const double empty[6] = { 1, -1, 1, -1, 1, -1 };
  pass->SetFarFieldRegion(empty);
  vtkNew<vtkSphereSource> farSource;
  farSource->SetCenter(30.0, 8.0, -25.0);
  farSource->SetRadius(0.2);
  vtkNew<vtkPolyDataMapper> farMapper;
  farMapper->SetInputConnection(farSource->GetOutputPort());
  vtkNew<vtkActor> farProp;
  farProp->SetMapper(farMapper);
  ren->AddActor(farProp);
  rw->Render();
  std::printf("no region, a far prop: %s\n", Spacing(pass).c_str());
  Check(pass->GetFarFieldGridSpacing() > plainSpacing &&
      MaxDifference(ClusteredLightingTest::CapturePixels(rw), plain) > 0.0,
    "without a region a far prop moves the grid and changes the image");
  ren->RemoveActor(farProp);
  rw->Render();
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), plain) == 0.0,
    "without it again: the first image (the grid follows the props)");

  // 3. A region that holds the far prop: adding and removing it changes nothing.
  const double region[6] = { -40.0, 40.0, -10.0, 20.0, -40.0, 10.0 };
  pass->SetFarFieldRegion(region);
  rw->Render();
  const std::vector<float> withRegion = ClusteredLightingTest::CapturePixels(rw);
  std::printf("a region of 80 x 30 x 50: %s\n", Spacing(pass).c_str());
  Check(pass->GetFarFieldGridSpacing() > plainSpacing, "the region sets a coarser grid");
  ren->AddActor(farProp);
  rw->Render();
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), withRegion) == 0.0,
    "with a region, the far prop changes nothing, bit for bit");
  ren->RemoveActor(farProp);
  rw->Render();
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), withRegion) == 0.0,
    "with a region, removing it changes nothing, bit for bit");
  Check(pass->GetNumberOfPackedFarFieldLights() == 0,
    "the lights span several cells of the coarser grid: none packed");
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "large region") == 0,
    "the coarser grid is within its stated bound of brute force at every pixel");

  // 4. A region inside the geometry: the union still covers the geometry (the same grid
  // as no region); an empty region is no region.
  const double inside[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  pass->SetFarFieldRegion(inside);
  rw->Render();
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), plain) == 0.0,
    "a region inside the geometry: the geometry's grid, bit for bit");
  std::ostringstream printed;
  pass->Print(printed);
  Check(printed.str().find("FarFieldRegion: -0.5 0.5 -0.5 0.5 -0.5 0.5") != std::string::npos,
    "PrintSelf names the region");
  pass->SetFarFieldRegion(empty);
  rw->Render();
  std::ostringstream printedEmpty;
  pass->Print(printedEmpty);
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), plain) == 0.0 &&
      printedEmpty.str().find("FarFieldRegion: (none") != std::string::npos,
    "an empty region is no region");
  // 5. A region that is not finite is ignored, said once: the props' grid, bit for bit.
  const std::size_t warningsBefore = messages->Warnings.size();
  const double inf = std::numeric_limits<double>::infinity();
  const double infinite[6] = { -inf, inf, -inf, inf, -inf, inf };
  pass->SetFarFieldRegion(infinite);
  rw->Render();
  rw->Render();
  Check(MaxDifference(ClusteredLightingTest::CapturePixels(rw), plain) == 0.0 &&
      messages->Warnings.size() == warningsBefore + 1 &&
      messages->Warnings.back().find("is not finite") != std::string::npos,
    "an infinite region is ignored, with one warning");
  messages->Warnings.pop_back();
  pass->SetFarFieldRegion(empty);

  Check(messages->Errors.empty() && messages->Warnings.empty(), "nothing reported");

  // 6. A region 4,000 wide (a ground plane under the scene, or a data set's bounds): the
  // 400 lights fall into a cell or two of its grid, whose nodes would miss their far
  // parts (the scene tens of steps too dark before 2026-12-06), so they keep near radii
  // the grid resolves (RaiseUnresolvedNearRadii), and the pass says once why clustering
  // culls little.
  const double huge[6] = { -2000.0, 2000.0, -10.0, 10.0, -2000.0, 2000.0 };
  pass->SetFarFieldRegion(huge);
  rw->Render();
  std::printf("a region of 4000 x 20 x 4000: %s, %d of the lights packed\n", Spacing(pass).c_str(),
    pass->GetNumberOfPackedFarFieldLights());
  Check(pass->GetNumberOfPackedFarFieldLights() == 400, "the lights are packed under the grid");
  ClusteredLightingTest::BruteForceCheck packed;
  Check(ClusteredLightingTest::CheckClusteredFrame(pass, rw, ren, 1.4, "packed", 0, &packed) == 0 &&
      packed.MaxError <= 2.0 / 255.0,
    "the packed lights' frame is within its stated bound and 2 steps of brute force");
  bool packedWarning = !messages->Warnings.empty();
  for (const std::string& w : messages->Warnings)
  {
    packedWarning =
      packedWarning && w.find("packed closer than the far field's grid") != std::string::npos;
  }
  Check(messages->Errors.empty() && packedWarning,
    "the one thing reported: the lights are packed under the large region's grid");
  return ClusteredLightingTest::CheckStatus();
}
