// SPDX-License-Identifier: BSD-3-Clause
// Warning floods (issue 14, item 3): what the pass says about invalid lights.
//  - 1,000 lights at NaN in one set give DefaultMaximumProblemsPerSource warnings naming
//    lights 0, 1, 2, ... in numeric order (not "light 0", "light 1", "light 10", "light
//    100", ...), then one "... and 990 more problems in vtkClusteredLightSet ..." line;
//    on the pass's WarningEvent observers and, line for line, on the set's;
//  - nothing more while the problems persist (still frames, a light fixed, other lights
//    changed); a newly broken light is reported, alone;
//  - the cap is per source: a second set and the renderer's vtkLights get their own lines,
//    and a set hears only its own problems;
//  - an input that is not a vtkPolyData reaches the set's ErrorEvent observer once over
//    several renders.
// Needs the pass to summarize problems with vtkClusteredLightingMessages.h and to raise
// them on the sets (vtkClusteredLightSet::ReportProblem).
#include "ClusteredLightingHardCase.h"

#include "vtkClusteredLightingMessages.h"

#include "vtkClusteredLightSet.h"
#include "vtkImageData.h"
#include "vtkLight.h"

#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace ClusteredLightingTest;

namespace
{
int Status = EXIT_SUCCESS;

void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok)
  {
    Status = EXIT_FAILURE;
  }
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

std::string First(const std::vector<std::string>& messages)
{
  return messages.empty() ? std::string("(none)") : messages.front();
}

// How the pass names a set in its messages.
std::string NameOf(vtkClusteredLightSet* set)
{
  std::ostringstream os;
  os << "vtkClusteredLightSet " << static_cast<const void*>(set);
  return os.str();
}

// Whether message k of `messages` (from `first` on) names light k of `set`, k < count.
bool NamesLightsInOrder(const std::vector<std::string>& messages, std::size_t first,
  vtkClusteredLightSet* set, std::size_t count)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    if (first + k >= messages.size() ||
      !Contains(messages[first + k], NameOf(set) + " light " + std::to_string(k) + ":"))
    {
      return false;
    }
  }
  return true;
}
} // namespace

int TestClusteredLightingMessages(int, char*[])
{
  const std::size_t cap = vtkClusteredLighting::DefaultMaximumProblemsPerSource;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkRenderWindow> renWin;
  vtkNew<vtkRenderer> ren;
  SetUpRoomWindow(renWin, ren);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0.3, 0.2, 3.0);
  cam->SetFocalPoint(0, 0, -2);
  cam->SetClippingRange(0.5, 9.0);

  // 1,000 lights at NaN, then 12 valid ones.
  vtkNew<vtkClusteredLightSet> flood;
  MakeRoomLights(flood, 1012, 2.5, 5);
  for (vtkIdType i = 0; i < 1000; ++i)
  {
    flood->SetPosition(i, nan, 0.0, 0.0);
  }
  vtkNew<vtkClusteredLightingPass> pass;
  vtkNew<MessageCollector> onPass, onFlood;
  onPass->Watch(pass);
  onFlood->Watch(flood);
  pass->AddLightSet(flood);
  ren->SetPass(pass);
  renWin->Render();

  std::printf("%zu warnings on the pass, %zu on the set; first: %s\nlast: %s\n",
    onPass->Warnings.size(), onFlood->Warnings.size(), First(onPass->Warnings).c_str(),
    onPass->Warnings.empty() ? "(none)" : onPass->Warnings.back().c_str());
  Check(onPass->Warnings.size() == cap + 1,
    "1,000 bad lights: " + std::to_string(cap) + " warnings and one summary on the pass (got " +
      std::to_string(onPass->Warnings.size()) + ")");
  Check(NamesLightsInOrder(onPass->Warnings, 0, flood, cap),
    "they name lights 0, 1, 2, ... in numeric order");
  Check(!onPass->Warnings.empty() &&
      Contains(
        onPass->Warnings.back(), "... and " + std::to_string(1000 - cap) + " more problems") &&
      Contains(onPass->Warnings.back(), "(lights " + std::to_string(cap) + " to 999)"),
    "the last line summarizes the other " + std::to_string(1000 - cap));
  bool sameOnSet = onFlood->Warnings.size() == onPass->Warnings.size();
  for (std::size_t k = 0; sameOnSet && k < onPass->Warnings.size(); ++k)
  {
    // The set's copy carries the same text after its own prefix.
    const std::string& line = onPass->Warnings[k];
    const std::size_t start = line.find("vtkClusteredLightSet 0x") != std::string::npos
      ? line.find("vtkClusteredLightSet 0x")
      : line.find("... and");
    sameOnSet = start != std::string::npos &&
      Contains(onFlood->Warnings[k], line.substr(start, line.find_last_not_of("\n") - start + 1));
  }
  Check(sameOnSet, "the set's WarningEvent observer gets the same lines");
  Check(pass->GetNumberOfRejectedLights() == 1000 && pass->GetNumberOfClusteredLights() == 12,
    "all 1,000 are rejected and counted, the 12 valid lights render");

  // Once per problem episode.
  onPass->Clear();
  onFlood->Clear();
  renWin->Render();
  cam->Azimuth(5.0);
  renWin->Render();
  flood->SetPosition(3, 0.0, 0.0, -2.0); // fixed
  flood->SetColor(1005, 0.2, 0.9, 0.4);  // a valid light changes
  renWin->Render();
  Check(onPass->Warnings.empty() && onFlood->Warnings.empty(),
    "nothing more while the problems persist (got " + std::to_string(onPass->Warnings.size()) +
      ": " + First(onPass->Warnings) + ")");
  flood->SetIntensity(1010, -1.0); // newly broken
  renWin->Render();
  Check(onPass->Warnings.size() == 1 && Contains(onPass->Warnings[0], " light 1010:") &&
      onFlood->Warnings.size() == 1,
    "a newly broken light is reported alone, on the pass and the set: " + First(onPass->Warnings));

  // Per source: a second set and the renderer's vtkLights.
  onPass->Clear();
  onFlood->Clear();
  vtkNew<vtkClusteredLightSet> other;
  MakeRoomLights(other, 40, 2.5, 6);
  for (vtkIdType i = 0; i < 25; ++i)
  {
    other->SetColor(i, -1.0, 0.5, 0.5);
  }
  vtkNew<MessageCollector> onOther;
  onOther->Watch(other);
  pass->AddLightSet(other);
  for (int i = 0; i < 13; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetPositional(true);
    light->SetPosition(nan, 0.0, 0.0);
    ren->AddLight(light);
  }
  renWin->Render();
  std::size_t fromOther = 0, fromLights = 0, summaries = 0;
  for (const std::string& w : onPass->Warnings)
  {
    fromOther += Contains(w, NameOf(other) + " light ") ? 1 : 0;
    fromLights += Contains(w, "vtkLight ") ? 1 : 0;
    summaries += Contains(w, "... and ") ? 1 : 0;
  }
  std::printf("second set and 13 vtkLights: %zu warnings (%zu of the set, %zu of vtkLights, %zu "
              "summaries)\n",
    onPass->Warnings.size(), fromOther, fromLights, summaries);
  Check(fromOther == cap && fromLights == cap && summaries == 2 &&
      onPass->Warnings.size() == 2 * cap + 2,
    "the cap is per source: the second set and the vtkLights get their own lines and summary");
  Check(onOther->Warnings.size() == cap + 1 && NamesLightsInOrder(onOther->Warnings, 0, other, cap),
    "the second set hears its own problems, in order");
  Check(onFlood->Warnings.empty(), "the first set hears nothing of the others");

  // An input that is not a vtkPolyData: the set's ErrorEvent, once.
  vtkNew<vtkClusteredLightSet> wrong;
  vtkNew<MessageCollector> onWrong;
  onWrong->Watch(wrong);
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 2);
  wrong->SetInputDataObject(image);
  pass->AddLightSet(wrong);
  for (int i = 0; i < 3; ++i)
  {
    renWin->Render();
  }
  Check(onWrong->Errors.size() == 1 && Contains(onWrong->Errors[0], "vtkImageData"),
    "an image input: one error on the set's ErrorEvent observer over 3 renders: " +
      First(onWrong->Errors));
  return Status;
}
