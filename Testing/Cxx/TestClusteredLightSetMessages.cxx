// SPDX-License-Identifier: BSD-3-Clause
// What a light set tells its observers (issue 14, items 3 and 4):
//  - every per-light and bulk setter called on a set with an input warns, naming the
//    setter and saying that the input defines the lights; once while the same input
//    stays connected, again for a new input; never without an input, and the input still
//    wins at the next update;
//  - ReportProblem() reaches the set's WarningEvent observers and prints nothing;
//  - an input that is not a vtkPolyData is an error of the set itself (its ErrorEvent
//    observers, not only the executive's), given once while it persists, also over
//    several renders through the pass, and again after the input was fixed and broken.
#include "ClusteredLightingTestUtilities.h"

#include "vtkClusteredLightSet.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkOutputWindow.h"
#include "vtkPointSource.h"
#include "vtkStringOutputWindow.h"

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

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

vtkSmartPointer<vtkPointSource> MakeCloud(int points)
{
  auto cloud = vtkSmartPointer<vtkPointSource>::New();
  cloud->SetNumberOfPoints(points);
  cloud->SetRadius(2.0);
  return cloud;
}

vtkSmartPointer<vtkDoubleArray> MakeArray(int components, vtkIdType tuples, double value)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  a->Fill(value);
  return a;
}

struct Setter
{
  const char* Name;
  std::function<void(vtkClusteredLightSet*)> Call;
};

// Every method that changes lights, with arguments valid for a set of 5 lights.
std::vector<Setter> Setters()
{
  return {
    { "SetPosition", [](vtkClusteredLightSet* s) { s->SetPosition(1, 9, 9, 9); } },
    { "SetColor", [](vtkClusteredLightSet* s) { s->SetColor(1, 0.1, 0.2, 0.3); } },
    { "SetIntensity", [](vtkClusteredLightSet* s) { s->SetIntensity(1, 0.5); } },
    { "SetAttenuation", [](vtkClusteredLightSet* s) { s->SetAttenuation(1, 1, 0, 2); } },
    { "SetRadius", [](vtkClusteredLightSet* s) { s->SetRadius(1, 0.5); } },
    { "UnsetRadius", [](vtkClusteredLightSet* s) { s->UnsetRadius(1); } },
    { "SetSpot", [](vtkClusteredLightSet* s) { s->SetSpot(1, 0, 0, -1, 30, 2); } },
    { "SetPointLight", [](vtkClusteredLightSet* s) { s->SetPointLight(1); } },
    { "SetNumberOfLights", [](vtkClusteredLightSet* s) { s->SetNumberOfLights(3); } },
    { "AddLight", [](vtkClusteredLightSet* s) { s->AddLight(1, 2, 3); } },
    { "RemoveAllLights", [](vtkClusteredLightSet* s) { s->RemoveAllLights(); } },
    { "SetPositions", [](vtkClusteredLightSet* s) { s->SetPositions(MakeArray(3, 5, 1.0)); } },
    { "SetColors", [](vtkClusteredLightSet* s) { s->SetColors(MakeArray(3, 5, 0.5)); } },
    { "SetIntensities", [](vtkClusteredLightSet* s) { s->SetIntensities(MakeArray(1, 5, 0.5)); } },
    { "SetAttenuations",
      [](vtkClusteredLightSet* s) { s->SetAttenuations(MakeArray(3, 5, 1.0)); } },
    { "SetRadii", [](vtkClusteredLightSet* s) { s->SetRadii(MakeArray(1, 5, 1.0)); } },
    { "SetSpotDirections",
      [](vtkClusteredLightSet* s) { s->SetSpotDirections(MakeArray(3, 5, 1.0)); } },
    { "SetConeAngles", [](vtkClusteredLightSet* s) { s->SetConeAngles(MakeArray(1, 5, 30.0)); } },
    { "SetExponents", [](vtkClusteredLightSet* s) { s->SetExponents(MakeArray(1, 5, 2.0)); } },
  };
}

void TestSettersOnASetWithAnInput()
{
  using ClusteredLightingTest::MessageCollector;
  // Each setter on its own, on a set with a freshly connected input: one warning that
  // names it; the input defines the lights again at the next update.
  for (const Setter& setter : Setters())
  {
    vtkNew<vtkClusteredLightSet> set;
    vtkNew<MessageCollector> messages;
    messages->Watch(set);
    vtkSmartPointer<vtkPointSource> cloud = MakeCloud(5);
    set->SetInputConnection(cloud->GetOutputPort());
    set->UpdateLights();
    setter.Call(set);
    const bool warned = messages->Warnings.size() == 1 &&
      Contains(messages->Warnings[0], std::string(setter.Name) + "()") &&
      Contains(messages->Warnings[0], "the input defines the lights") &&
      Contains(messages->Warnings[0], "vtkPointSource");
    Check(warned,
      std::string(setter.Name) + " on a set with an input warns, naming the setter: " +
        (messages->Warnings.empty() ? "(no warning)" : messages->Warnings[0]));
    // The input is read again (it changed) and replaces the edit.
    cloud->Modified();
    set->UpdateLights();
    double p[3], q[3];
    cloud->GetOutput()->GetPoint(1, q);
    set->GetPosition(1, p);
    Check(set->GetNumberOfLights() == 5 && p[0] == q[0] && p[1] == q[1] && p[2] == q[2] &&
        messages->Errors.empty(),
      std::string(setter.Name) + ": the input defines the lights again at the next update");
  }

  // Once while the same input stays connected: every other setter after the first is
  // silent, also after the input was read again.
  {
    vtkNew<vtkClusteredLightSet> set;
    vtkNew<MessageCollector> messages;
    messages->Watch(set);
    vtkSmartPointer<vtkPointSource> cloud = MakeCloud(5);
    set->SetInputConnection(cloud->GetOutputPort());
    set->UpdateLights();
    for (int round = 0; round < 3; ++round)
    {
      for (const Setter& setter : Setters())
      {
        setter.Call(set);
      }
      cloud->Modified();
      set->UpdateLights();
    }
    Check(messages->Warnings.size() == 1,
      "one warning for 3 rounds of every setter while the same input stays connected (got " +
        std::to_string(messages->Warnings.size()) + ")");

    // A new input is a new episode.
    vtkSmartPointer<vtkPointSource> other = MakeCloud(5);
    set->SetInputConnection(other->GetOutputPort());
    set->SetColor(0, 1, 0, 0);
    set->SetColor(0, 0, 1, 0);
    Check(messages->Warnings.size() == 2, "a new input warns again, once");

    // Disconnected: the setters work without a warning, and the edit stays.
    set->UpdateLights();
    set->SetInputConnection(nullptr);
    const std::size_t before = messages->Warnings.size();
    for (const Setter& setter : Setters())
    {
      if (setter.Name != std::string("RemoveAllLights") &&
        setter.Name != std::string("SetNumberOfLights"))
      {
        setter.Call(set);
      }
    }
    set->SetColor(0, 0.25, 0.5, 0.75);
    set->UpdateLights();
    double c[3];
    set->GetColor(0, c);
    Check(messages->Warnings.size() == before && c[0] == 0.25 && c[1] == 0.5 && c[2] == 0.75,
      "a disconnected set takes every setter without a warning and keeps the edits");

    // SetInputData: the same rule.
    vtkNew<vtkPolyData> data;
    data->DeepCopy(cloud->GetOutput());
    set->SetInputData(data);
    set->SetIntensity(0, 2.0);
    Check(messages->Warnings.size() == before + 1 &&
        Contains(messages->Warnings.back(), "SetIntensity()"),
      "a set fed with SetInputData warns too");
  }

  // A set that never had an input: no warning at all.
  {
    vtkNew<vtkClusteredLightSet> set;
    vtkNew<MessageCollector> messages;
    messages->Watch(set);
    set->SetNumberOfLights(5);
    for (const Setter& setter : Setters())
    {
      setter.Call(set);
    }
    Check(messages->Warnings.empty() && messages->Errors.empty(),
      "a set without an input takes every setter without a message");
  }
}

void TestReportProblem()
{
  using ClusteredLightingTest::MessageCollector;
  vtkNew<vtkStringOutputWindow> output;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(output);

  vtkNew<vtkClusteredLightSet> set;
  set->ReportProblem("light 3: nothing anyone sees");
  Check(output->GetOutput().empty(), "ReportProblem without an observer prints nothing");

  vtkNew<MessageCollector> messages;
  messages->Watch(set);
  set->ReportProblem("vtkClusteredLightSet 0x1 light 3: position (nan, 0, 0) is not finite");
  set->ReportProblem(nullptr);
  Check(messages->Warnings.size() == 1 && messages->Errors.empty() &&
      Contains(messages->Warnings[0], "light 3: position (nan, 0, 0) is not finite") &&
      Contains(messages->Warnings[0], "vtkClusteredLightSet ("),
    "ReportProblem reaches the set's WarningEvent observer: " +
      (messages->Warnings.empty() ? std::string("(nothing)") : messages->Warnings[0]));
  Check(output->GetOutput().empty(), "and prints nothing");

  vtkObject::GlobalWarningDisplayOff();
  set->ReportProblem("light 4: off");
  vtkObject::GlobalWarningDisplayOn();
  Check(messages->Warnings.size() == 1, "no event while the global warning display is off");
  vtkOutputWindow::SetInstance(previous);
}

void TestInputThatIsNotPolyData()
{
  using ClusteredLightingTest::MessageCollector;
  vtkNew<vtkClusteredLightSet> set;
  vtkNew<MessageCollector> onSet;
  onSet->Watch(set);
  vtkNew<MessageCollector> onExecutive;
  onExecutive->Watch(set->GetExecutive());

  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 2);
  set->SetInputDataObject(image);
  for (int i = 0; i < 3; ++i)
  {
    set->UpdateLights();
  }
  const bool named = onSet->Errors.size() == 1 && Contains(onSet->Errors[0], "vtkImageData") &&
    Contains(onSet->Errors[0], "vtkPolyData");
  Check(named,
    "an image input is an error of the set (its ErrorEvent observer), naming both types: " +
      (onSet->Errors.empty() ? std::string("(no error on the set)") : onSet->Errors[0]));
  Check(onExecutive->Errors.empty(), "the executive reports nothing itself");
  Check(set->GetNumberOfLights() == 0, "and the set holds no lights");
  image->Modified();
  set->UpdateLights();
  Check(onSet->Errors.size() == 1, "given once while it persists (input modified, updated again)");

  // Fixed, then broken again: a new episode.
  vtkSmartPointer<vtkPointSource> cloud = MakeCloud(4);
  set->SetInputConnection(cloud->GetOutputPort());
  set->UpdateLights();
  Check(onSet->Errors.size() == 1 && set->GetNumberOfLights() == 4,
    "a polydata input brings the lights back without an error");
  set->SetInputDataObject(image);
  set->UpdateLights();
  Check(onSet->Errors.size() == 2 && set->GetNumberOfLights() == 0,
    "the image again: reported again, no lights");

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, cloud->GetOutput());
  set->SetInputDataObject(blocks);
  set->UpdateLights();
  Check(onSet->Errors.size() == 3 && Contains(onSet->Errors.back(), "vtkMultiBlockDataSet") &&
      set->GetNumberOfLights() == 0,
    "a multiblock input is an error naming its type, not a silent read of one block");
  Check(onExecutive->Errors.empty(), "still nothing from the executive");
}

void TestInputThatIsNotPolyDataWhileRendering()
{
  using ClusteredLightingTest::MessageCollector;
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(64, 48);
  renWin->SetMultiSamples(0);
  vtkNew<vtkRenderer> ren;
  renWin->AddRenderer(ren);
  ClusteredLightingTest::AddTestScene(ren, 8);
  vtkNew<vtkClusteredLightSet> set;
  vtkNew<MessageCollector> onSet;
  onSet->Watch(set);
  vtkNew<MessageCollector> onExecutive;
  onExecutive->Watch(set->GetExecutive());
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 2);
  set->SetInputDataObject(image);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(set);
  ren->SetPass(pass);
  for (int i = 0; i < 4; ++i)
  {
    renWin->Render();
  }
  Check(onSet->Errors.size() == 1 && onExecutive->Errors.empty(),
    "4 renders with an image input: one error, on the set (got " +
      std::to_string(onSet->Errors.size()) + " on the set, " +
      std::to_string(onExecutive->Errors.size()) + " on the executive)");
}
} // namespace

int TestClusteredLightSetMessages(int, char*[])
{
  TestSettersOnASetWithAnInput();
  TestReportProblem();
  TestInputThatIsNotPolyData();
  TestInputThatIsNotPolyDataWhileRendering();
  return Status;
}
