#include "vtkFaultStepHorizonSource.h"

#include "vtkGeoShapingAdapter.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMalleabilityPaintFilter.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include "geoshaping/scenes/sample_scenes.h"

vtkStandardNewMacro(vtkFaultStepHorizonSource);

vtkFaultStepHorizonSource::vtkFaultStepHorizonSource()
{
  this->SetNumberOfInputPorts(0);
  const geoshaping::FaultStepParams defaults;
  this->Length = defaults.length;
  this->Width = defaults.width;
  this->Throw = defaults.throw_height;
  this->StepRun = defaults.step_run;
  this->StepPosition = defaults.step_position;
  this->Spacing = defaults.spacing;
  this->Thickness = defaults.thickness;
  this->Layers = defaults.layers;
}

int vtkFaultStepHorizonSource::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPointSet");
  return 1;
}

int vtkFaultStepHorizonSource::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* current = info->Get(vtkDataObject::DATA_OBJECT());
  const bool slab = this->OutputMeshType == SLAB;
  if (current && current->IsA(slab ? "vtkUnstructuredGrid" : "vtkPolyData"))
  {
    return 1;
  }
  vtkSmartPointer<vtkDataObject> output;
  if (slab)
    output = vtkSmartPointer<vtkUnstructuredGrid>::New();
  else
    output = vtkSmartPointer<vtkPolyData>::New();
  info->Set(vtkDataObject::DATA_OBJECT(), output);
  return 1;
}

int vtkFaultStepHorizonSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  if (!output)
  {
    vtkErrorMacro("No output data object.");
    return 0;
  }
  geoshaping::FaultStepParams p;
  p.length = this->Length;
  p.width = this->Width;
  p.throw_height = this->Throw;
  p.step_run = this->StepRun;
  p.step_position = this->StepPosition;
  p.spacing = this->Spacing;
  p.thickness = this->Thickness;
  p.layers = this->Layers;
  p.origin = Eigen::Vector3d(this->Origin[0], this->Origin[1], this->Origin[2]);
  if (*geoshaping::validate(p))
  {
    vtkErrorMacro("Cannot make the fault-step horizon: " << geoshaping::validate(p) << ".");
    return 1;
  }
  const bool slab = this->OutputMeshType == SLAB;
  const geoshaping::SampleMesh mesh =
    slab ? geoshaping::fault_step_slab(p) : geoshaping::fault_step_horizon(p);

  vtkSmartPointer<vtkPoints> points = vtkGeoShapingAdapter::MakePoints(mesh.xyz);
  vtkSmartPointer<vtkCellArray> cells =
    vtkGeoShapingAdapter::MakeCells(mesh.connectivity, mesh.cell_size);

  vtkNew<vtkPolyData> surface;
  vtkNew<vtkUnstructuredGrid> volume;
  vtkPointSet* result = surface;
  if (slab)
  {
    volume->SetPoints(points);
    volume->SetCells(VTK_TETRA, cells);
    result = volume;
  }
  else
  {
    surface->SetPoints(points);
    surface->SetPolys(cells);
  }

  if (this->PaintFigure5C)
  {
    vtkNew<vtkMalleabilityPaintFilter> paint;
    paint->SetInputData(result);
    paint->SetInitialMalleability(geoshaping::fault_step_red);
    paint->SetFalloff(vtkMalleabilityPaintFilter::CONSTANT);
    paint->SetDistanceMode(vtkMalleabilityPaintFilter::EUCLIDEAN);
    for (const geoshaping::Dab& d : geoshaping::fault_step_painting(p, this->BorderWidth))
      paint->AddDab(d.center.x(), d.center.y(), d.center.z(), d.radius, d.value, d.strength);
    paint->Update();
    output->ShallowCopy(paint->GetOutputDataObject(0));
  }
  else
  {
    output->ShallowCopy(result);
  }
  return 1;
}

void vtkFaultStepHorizonSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OutputMeshType: " << (this->OutputMeshType == SLAB ? "Slab" : "Surface") << "\n";
  os << indent << "Length: " << this->Length << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Throw: " << this->Throw << "\n";
  os << indent << "StepRun: " << this->StepRun << "\n";
  os << indent << "StepPosition: " << this->StepPosition << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "Layers: " << this->Layers << "\n";
  os << indent << "Origin: " << this->Origin[0] << " " << this->Origin[1] << " " << this->Origin[2]
     << "\n";
  os << indent << "PaintFigure5C: " << this->PaintFigure5C << "\n";
  os << indent << "BorderWidth: " << this->BorderWidth << "\n";
}
