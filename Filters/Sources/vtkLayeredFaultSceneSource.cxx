#include "vtkLayeredFaultSceneSource.h"

#include "vtkGeoShapingAdapter.h"

#include "vtkCellArray.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "geoshaping/scenes/layered_scene.h"

#include <algorithm>

vtkStandardNewMacro(vtkLayeredFaultSceneSource);

vtkLayeredFaultSceneSource::vtkLayeredFaultSceneSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkLayeredFaultSceneSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  geoshaping::LayeredSceneParams p;
  p.length = this->Length;
  p.width = this->Width;
  p.fault_x = this->FaultX;
  p.dip_degrees = this->DipDegrees;
  p.top = this->Top;
  p.bottom = this->Bottom;
  p.horizon_upper = this->HorizonUpper;
  p.horizon_lower = this->HorizonLower;
  p.throw_height = this->Throw;
  p.spacing = this->Spacing;
  p.origin = Eigen::Vector3d(this->Origin[0], this->Origin[1], this->Origin[2]);
  if (*geoshaping::validate(p))
  {
    vtkErrorMacro("Cannot make the layered fault scene: " << geoshaping::validate(p) << ".");
    return 1;
  }
  const geoshaping::LayeredScene scene = geoshaping::layered_fault_scene(p);
  output->SetPoints(vtkGeoShapingAdapter::MakePoints(scene.mesh.xyz));
  output->SetPolys(vtkGeoShapingAdapter::MakeCells(scene.mesh.connectivity, 3));
  vtkNew<vtkIntArray> part;
  part->SetName("Part");
  part->SetNumberOfTuples(vtkIdType(scene.part.size()));
  std::copy(scene.part.begin(), scene.part.end(), part->GetPointer(0));
  output->GetPointData()->AddArray(part);
  return 1;
}

void vtkLayeredFaultSceneSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Length: " << this->Length << " Width: " << this->Width << "\n";
  os << indent << "FaultX: " << this->FaultX << " DipDegrees: " << this->DipDegrees << "\n";
  os << indent << "Top: " << this->Top << " Bottom: " << this->Bottom << "\n";
  os << indent << "HorizonUpper: " << this->HorizonUpper << " HorizonLower: " << this->HorizonLower
     << " Throw: " << this->Throw << "\n";
  os << indent << "Spacing: " << this->Spacing << " Origin: " << this->Origin[0] << " "
     << this->Origin[1] << " " << this->Origin[2] << "\n";
}
