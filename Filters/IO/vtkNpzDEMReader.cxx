#include "vtkNpzDEMReader.h"

#include "vtkDEMProjection.h"
#include "vtkDEMSurfaceOutput.h"
#include "vtkNpzDEMParser.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <stdexcept>
#include <string>

vtkStandardNewMacro(vtkNpzDEMReader);

vtkNpzDEMReader::vtkNpzDEMReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkNpzDEMReader::~vtkNpzDEMReader()
{
  this->SetFileName(nullptr);
}

int vtkNpzDEMReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName: give the .npz DEM to read.");
    return 0;
  }
  // Every failure, std::bad_alloc included, is an error and an empty output.
  try
  {
    const vtkNpzArchive npz(vtkNpzReadFile(this->FileName));
    const geoshaping::ElevationGrid grid = vtkNpzDEMParse(npz);
    vtkDEMProjection projection(vtkDEMProjection::LonLatWgs84);
    vtkDEMSurfaceOutput(output, grid, this->Stride, projection);
    vtkNew<vtkDoubleArray> bounds;
    bounds->SetName("LonLatBounds");
    for (double v : { grid.x_first, grid.x_last, grid.y_first, grid.y_last })
      bounds->InsertNextValue(v);
    output->GetFieldData()->AddArray(bounds);
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro(<< this->FileName << ": " << e.what());
    return 0;
  }
  return 1;
}

void vtkNpzDEMReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Stride: " << this->Stride << "\n";
}
