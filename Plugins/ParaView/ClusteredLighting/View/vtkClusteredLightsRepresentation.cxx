// SPDX-License-Identifier: BSD-3-Clause
#include "vtkClusteredLightsRepresentation.h"

#include "vtkAlgorithmOutput.h"
#include "vtkAppendPolyData.h"
#include "vtkClusteredLightSet.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPVClusteredLightingView.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkView.h"

#include <cstring>

vtkStandardNewMacro(vtkClusteredLightsRepresentation);

//------------------------------------------------------------------------------
vtkClusteredLightsRepresentation::vtkClusteredLightsRepresentation() = default;

//------------------------------------------------------------------------------
vtkClusteredLightsRepresentation::~vtkClusteredLightsRepresentation()
{
  if (this->LightingView)
  {
    this->LightingView->RemoveLightSet(this->LightSet);
  }
}

//------------------------------------------------------------------------------
int vtkClusteredLightsRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  // Any data object is accepted here so that a wrong type is reported by RequestData()
  // with an error that says what to do; ParaView's domain offers the representation for
  // vtkPolyData and composite data sets. The input is optional: rendering-only processes
  // have none.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkClusteredLightsRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Points->Initialize();
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    vtkPolyData* polyData = vtkPolyData::SafeDownCast(input);
    vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(input);
    if (polyData)
    {
      CopyOwnedPoints(polyData, this->Points);
    }
    else if (composite)
    {
      // Every block's points, with the point arrays that all blocks have.
      vtkNew<vtkAppendPolyData> append;
      vtkSmartPointer<vtkCompositeDataIterator> blocks;
      blocks.TakeReference(composite->NewIterator());
      for (blocks->InitTraversal(); !blocks->IsDoneWithTraversal(); blocks->GoToNextItem())
      {
        vtkPolyData* block = vtkPolyData::SafeDownCast(blocks->GetCurrentDataObject());
        if (!block)
        {
          vtkErrorMacro("Clustered Lights needs polygonal blocks (vtkPolyData), not "
            << blocks->GetCurrentDataObject()->GetClassName()
            << ": no lights. Apply Extract Surface first.");
          append->RemoveAllInputs();
          break;
        }
        vtkNew<vtkPolyData> points;
        CopyOwnedPoints(block, points);
        append->AddInputData(points);
      }
      if (append->GetNumberOfInputConnections(0) > 0)
      {
        append->Update();
        this->Points->ShallowCopy(append->GetOutput());
      }
    }
    else if (input)
    {
      vtkErrorMacro("Clustered Lights needs polygonal data (vtkPolyData), not "
        << input->GetClassName() << ": no lights. Apply Extract Surface first.");
    }
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkClusteredLightsRepresentation::CopyOwnedPoints(vtkPolyData* input, vtkPolyData* output)
{
  // Only the points and their arrays become lights: the cells are not delivered.
  vtkPoints* points = input->GetPoints();
  vtkPointData* pointData = input->GetPointData();
  vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
  if (ghosts && ghosts->GetNumberOfTuples() != n)
  {
    ghosts = nullptr; // not a ghost array of these points: ignored
  }
  vtkNew<vtkIdList> owned;
  if (ghosts)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (!(ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT))
      {
        owned->InsertNextId(i);
      }
    }
  }
  if (!ghosts || owned->GetNumberOfIds() == n)
  {
    if (points)
    {
      output->SetPoints(points);
    }
    output->GetPointData()->ShallowCopy(pointData);
    return;
  }
  // A point that another piece owns too (ParaView's ghost points) is one light, not one
  // per piece: keep the owned points only.
  vtkNew<vtkPoints> ownedPoints;
  ownedPoints->SetDataType(points->GetDataType());
  points->GetPoints(owned, ownedPoints);
  output->SetPoints(ownedPoints);
  vtkPointData* out = output->GetPointData();
  out->CopyAllocate(pointData, owned->GetNumberOfIds());
  for (vtkIdType i = 0; i < owned->GetNumberOfIds(); ++i)
  {
    out->CopyData(pointData, owned->GetId(i), i);
  }
  out->RemoveArray(vtkDataSetAttributes::GhostArrayName());
}

//------------------------------------------------------------------------------
int vtkClusteredLightsRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* requestType, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(requestType, inInfo, outInfo))
  {
    return 0; // hidden
  }
  if (requestType == vtkPVView::REQUEST_UPDATE())
  {
    if (!this->LightingView && !this->WarnedAboutView)
    {
      vtkWarningMacro("Clustered Lights light only a Clustered Lighting view, not a "
        << (this->GetView() ? this->GetView()->GetClassName() : "null view")
        << ": these lights light nothing here.");
      this->WarnedAboutView = true;
    }
    vtkPVView::SetPiece(inInfo, this, this->Points);
    // Gather the pieces of every data rank and give the whole to every rendering rank.
    vtkPVRenderView::SetDeliverToAllProcesses(inInfo, this, true);
  }
  else if (requestType == vtkPVView::REQUEST_RENDER())
  {
    vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this);
    this->LightSet->SetInputConnection(producer);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkClusteredLightsRepresentation::SetVisibility(bool visible)
{
  this->Superclass::SetVisibility(visible);
  this->LightSet->SetEnabled(visible);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightsRepresentation::AddToView(vtkView* view)
{
  // ParaView adds every representation type of a source to the view, shown or not: a
  // hidden one in another view is normal, so the warning waits for a visible update.
  vtkPVClusteredLightingView* lightingView = vtkPVClusteredLightingView::SafeDownCast(view);
  if (lightingView)
  {
    lightingView->AddLightSet(this->LightSet);
    this->LightingView = lightingView;
  }
  return this->Superclass::AddToView(view);
}

//------------------------------------------------------------------------------
bool vtkClusteredLightsRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVClusteredLightingView* lightingView = vtkPVClusteredLightingView::SafeDownCast(view);
  if (lightingView)
  {
    lightingView->RemoveLightSet(this->LightSet);
    if (this->LightingView == lightingView)
    {
      this->LightingView = nullptr;
    }
  }
  return this->Superclass::RemoveFromView(view);
}

//------------------------------------------------------------------------------
const char* vtkClusteredLightsRepresentation::ArrayName(const char* name)
{
  return (name && std::strcmp(name, NoneArrayName()) == 0) ? nullptr : name;
}

//------------------------------------------------------------------------------
// Array names and defaults go to the light set, one line each.
void vtkClusteredLightsRepresentation::SetColorArrayName(const char* name)
{
  this->LightSet->SetColorArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetIntensityArrayName(const char* name)
{
  this->LightSet->SetIntensityArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetAttenuationArrayName(const char* name)
{
  this->LightSet->SetAttenuationArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetRadiusArrayName(const char* name)
{
  this->LightSet->SetRadiusArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetSpotDirectionArrayName(const char* name)
{
  this->LightSet->SetSpotDirectionArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetConeAngleArrayName(const char* name)
{
  this->LightSet->SetConeAngleArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetExponentArrayName(const char* name)
{
  this->LightSet->SetExponentArrayName(ArrayName(name));
}
void vtkClusteredLightsRepresentation::SetDefaultColor(double r, double g, double b)
{
  this->LightSet->SetDefaultColor(r, g, b);
}
void vtkClusteredLightsRepresentation::SetDefaultIntensity(double intensity)
{
  this->LightSet->SetDefaultIntensity(intensity);
}
void vtkClusteredLightsRepresentation::SetDefaultAttenuation(double a0, double a1, double a2)
{
  this->LightSet->SetDefaultAttenuation(a0, a1, a2);
}
void vtkClusteredLightsRepresentation::SetDefaultRadius(double radius)
{
  this->LightSet->SetDefaultRadius(radius);
}
void vtkClusteredLightsRepresentation::SetDefaultSpotDirection(double x, double y, double z)
{
  this->LightSet->SetDefaultSpotDirection(x, y, z);
}
void vtkClusteredLightsRepresentation::SetDefaultConeAngle(double angle)
{
  this->LightSet->SetDefaultConeAngle(angle);
}
void vtkClusteredLightsRepresentation::SetDefaultExponent(double exponent)
{
  this->LightSet->SetDefaultExponent(exponent);
}

//------------------------------------------------------------------------------
vtkClusteredLightSet* vtkClusteredLightsRepresentation::GetLightSet()
{
  return this->LightSet;
}

//------------------------------------------------------------------------------
vtkIdType vtkClusteredLightsRepresentation::GetNumberOfLights()
{
  this->LightSet->UpdateLights();
  return this->LightSet->GetNumberOfLights();
}

//------------------------------------------------------------------------------
void vtkClusteredLightsRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightSet: " << this->LightSet.GetPointer() << "\n";
  os << indent << "LightingView: " << this->LightingView.GetPointer() << "\n";
}
