// SPDX-License-Identifier: BSD-3-Clause
// Hardware selection and picking through the pass: VTK's pickers and ParaView's selections
// render ids with a vtkHardwareSelector, which a renderer hands its props to only in its
// own render steps. Until 2026-11-28 the pass rendered a selection as a lit frame: every
// selection came back empty and vtkPropPicker picked nothing.
//
// A floor, an opaque sphere and a translucent one, lit by 300 lights as users write them
// (inverse-square, no radius) and one positional vtkLight, the pass at its defaults (depth
// prepass, depth-aware clusters). Against the same renderer without the pass, it checks:
// cell and point selections of the whole view and of a small area (every prop, every id),
// vtkPropPicker at five pixels (the prop and the position), a pick list that leaves a
// prop out, and vtkCellPicker's hardware-selection step (vtkRenderer::PickProp); then that
// a frame after the selections is the same bit for bit as before them, and that nothing
// was reported.
#include "ClusteredLightingGLTestUtilities.h"
#include "ClusteredLightingTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkPropPicker.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

namespace
{
using ClusteredLightingTest::Check;

/// What a selection found: the ids of each prop (by its index among the renderer's
/// actors).
using Found = std::map<int, std::set<vtkIdType>>;

Found Select(vtkRenderer* ren, int association, const unsigned int area[4])
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(ren);
  selector->SetArea(area[0], area[1], area[2], area[3]);
  selector->SetFieldAssociation(association);
  vtkSmartPointer<vtkSelection> result;
  result.TakeReference(selector->Select());
  Found found;
  vtkActorCollection* actors = ren->GetActors();
  for (unsigned int n = 0; result && n < result->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = result->GetNode(n);
    vtkProp* prop = vtkProp::SafeDownCast(node->GetProperties()->Get(vtkSelectionNode::PROP()));
    const int index = prop ? actors->IsItemPresent(prop) - 1 : -1;
    std::set<vtkIdType>& ids = found[index];
    vtkIdTypeArray* list = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    for (vtkIdType i = 0; list && i < list->GetNumberOfTuples(); ++i)
    {
      ids.insert(list->GetValue(i));
    }
  }
  return found;
}

std::string Describe(const Found& found)
{
  std::string s;
  for (const auto& it : found)
  {
    s += " prop " + std::to_string(it.first) + ": " + std::to_string(it.second.size()) + " ids;";
  }
  return s.empty() ? " nothing" : s;
}

/// What a vtkPropPicker finds at a pixel: the prop's index (-1: none) and the position.
struct Pick
{
  int Prop = -1;
  double Position[3] = { 0, 0, 0 };
};

Pick PickAt(vtkRenderer* ren, double x, double y, vtkActor* onlyFrom = nullptr)
{
  vtkNew<vtkPropPicker> picker;
  if (onlyFrom)
  {
    picker->PickFromListOn();
    picker->AddPickList(onlyFrom);
  }
  Pick p;
  if (picker->Pick(x, y, 0.0, ren))
  {
    p.Prop = ren->GetActors()->IsItemPresent(picker->GetActor()) - 1;
  }
  picker->GetPickPosition(p.Position);
  return p;
}

/// Everything a selection finds, rendered once without the pass and once with it.
struct Selections
{
  Found Cells, Points, SmallArea;
  Pick Picks[5], FromList;
  int PickedProp = -1;
};

Selections SelectAll(vtkRenderWindow* rw, vtkRenderer* ren, vtkActor* listed)
{
  rw->Render();
  Selections s;
  const int* size = rw->GetSize();
  const unsigned int whole[4] = { 0, 0, static_cast<unsigned int>(size[0] - 1),
    static_cast<unsigned int>(size[1] - 1) };
  const unsigned int small[4] = { 90, 60, 130, 90 };
  s.Cells = Select(ren, vtkDataObject::FIELD_ASSOCIATION_CELLS, whole);
  s.Points = Select(ren, vtkDataObject::FIELD_ASSOCIATION_POINTS, whole);
  s.SmallArea = Select(ren, vtkDataObject::FIELD_ASSOCIATION_CELLS, small);
  // The opaque sphere covers this pixel; the pick list holds only the floor. (VTK 9.1's
  // renderer keeps the list's address after the pick, and a later selection would read
  // the deleted list: the next pick, without a list, clears it.)
  s.FromList = PickAt(ren, 120, 100, listed);
  const double pixels[5][2] = { { 120, 100 }, { 60, 40 }, { 200, 110 }, { 150, 150 }, { 5, 195 } };
  for (int i = 0; i < 5; ++i)
  {
    s.Picks[i] = PickAt(ren, pixels[i][0], pixels[i][1]);
  }
  vtkAssemblyPath* path = ren->PickProp(120, 100);
  s.PickedProp =
    path ? ren->GetActors()->IsItemPresent(path->GetLastNode()->GetViewProp()) - 1 : -1;
  return s;
}
}

int TestClusteredLightingSelection(int, char*[])
{
  vtkNew<vtkRenderWindow> rw;
  vtkNew<vtkRenderer> ren;
  ClusteredLightingTest::SetUpTestScene(rw, ren, 240, 200);
  vtkActorCollection* actors = ren->GetActors();
  vtkActor* floor = vtkActor::SafeDownCast(actors->GetItemAsObject(0));
  vtkNew<vtkSphereSource> glassSource;
  glassSource->SetCenter(1.6, 0.2, 1.2);
  glassSource->SetRadius(0.6);
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(glassSource->GetOutputPort());
  vtkNew<vtkActor> glass;
  glass->SetMapper(glassMapper);
  glass->GetProperty()->SetOpacity(0.4);
  ren->AddActor(glass);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(180.0);
  light->SetPosition(0.0, 2.0, 2.0);
  light->SetAttenuationValues(1.0, 0.0, 0.5);
  ren->AddLight(light);
  ren->ResetCameraClippingRange();

  const Selections stock = SelectAll(rw, ren, floor);

  vtkNew<vtkClusteredLightSet> lights;
  ClusteredLightingTest::MakeUserLights(lights, 300, 0.05, 7);
  vtkNew<vtkClusteredLightingPass> pass;
  pass->AddLightSet(lights);
  ren->SetPass(pass);
  vtkNew<ClusteredLightingTest::MessageCollector> messages;
  messages->Watch(pass);
  rw->Render();
  rw->Render();
  Check(pass->GetDepthPrepassUsed() && pass->GetDepthAwareClustersUsed(),
    "the pass renders with its prepass and depth-aware clusters");
  const std::vector<float> before = ClusteredLightingTest::CapturePixels(rw);

  const Selections clustered = SelectAll(rw, ren, floor);
  std::printf("cells without the pass:%s\ncells with the pass:%s\n", Describe(stock.Cells).c_str(),
    Describe(clustered.Cells).c_str());
  Check(stock.Cells.size() == 3, "without the pass, a cell selection finds all three props");
  Check(clustered.Cells == stock.Cells, "cell selection: the same props and cells");
  Check(!stock.Points.empty() && clustered.Points == stock.Points,
    "point selection: the same props and points");
  Check(!stock.SmallArea.empty() && clustered.SmallArea == stock.SmallArea,
    "a small area: the same props and cells (" + Describe(clustered.SmallArea) + ")");
  for (int i = 0; i < 5; ++i)
  {
    const Pick& a = stock.Picks[i];
    const Pick& b = clustered.Picks[i];
    const double d = std::hypot(
      a.Position[0] - b.Position[0], a.Position[1] - b.Position[1], a.Position[2] - b.Position[2]);
    std::printf("pick %d: prop %d at (%.4f, %.4f, %.4f) without the pass, prop %d with it, "
                "%.2g apart\n",
      i, a.Prop, a.Position[0], a.Position[1], a.Position[2], b.Prop, d);
    Check(a.Prop == b.Prop && d < 1e-6, "vtkPropPicker " + std::to_string(i) + ": the same");
  }
  Check(stock.Picks[0].Prop == 1 && stock.Picks[4].Prop == -1,
    "the picks cover the opaque sphere and the background");
  Check(stock.FromList.Prop == clustered.FromList.Prop && stock.FromList.Prop != 1,
    "a pick list: the sphere it leaves out is not picked, with or without the pass");
  Check(stock.PickedProp == 1 && clustered.PickedProp == stock.PickedProp,
    "vtkRenderer::PickProp: the same prop");

  rw->Render();
  const std::vector<float> after = ClusteredLightingTest::CapturePixels(rw);
  const auto cmp = ClusteredLightingTest::CompareImages(after, before);
  ClusteredLightingTest::PrintComparison("after the selections vs before", cmp);
  Check(cmp.MaxAbsError == 0.0, "a frame after the selections is the same bit for bit");
  Check(messages->Errors.empty() && messages->Warnings.empty(), "nothing reported");
  return ClusteredLightingTest::CheckStatus();
}
