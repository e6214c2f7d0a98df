#include "vtkNpzDEMReader.h"

#include "vtkGeoShapingAdapter.h"
#include "vtkNpzDEMParser.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include "geoshaping/dem_surface.h"

#include <stdexcept>
#include <string>

vtkStandardNewMacro(vtkNpzDEMReader);

namespace
{
// The surface of the grid, with its Elevation, LonLatBounds and Projection; throws with
// the reason when the grid or its projection cannot make one.
void FillOutput(vtkPolyData* output, const geoshaping::GeographicGrid& grid, int stride)
{
  if (const char* why = geoshaping::validate(grid, stride); *why)
    throw std::runtime_error(why);
  const vtkNpzUtmProjection utm(grid);
  std::string why;
  const geoshaping::SampleMesh mesh = geoshaping::dem_surface(
    grid, stride, [&utm](std::size_t n, double* x, double* y) { return utm(n, x, y); }, &why);
  if (mesh.xyz.empty())
    throw std::runtime_error(why);
  output->SetPoints(vtkGeoShapingAdapter::MakePoints(mesh.xyz));
  output->SetPolys(vtkGeoShapingAdapter::MakeCells(mesh.connectivity, 3));
  vtkNew<vtkDoubleArray> elevation;
  elevation->SetName("Elevation");
  elevation->SetNumberOfTuples(mesh.num_points());
  for (geoshaping::index_t i = 0; i < mesh.num_points(); ++i)
    elevation->SetValue(i, mesh.xyz[3 * std::size_t(i) + 2]);
  output->GetPointData()->AddArray(elevation);
  vtkNew<vtkDoubleArray> bounds;
  bounds->SetName("LonLatBounds");
  for (double v : { grid.lon_first, grid.lon_last, grid.lat_first, grid.lat_last })
    bounds->InsertNextValue(v);
  output->GetFieldData()->AddArray(bounds);
  vtkNew<vtkStringArray> about;
  about->SetName("Projection");
  about->InsertNextValue(
    utm.GetDescription() + "; z = elevation (m); stride " + std::to_string(stride));
  output->GetFieldData()->AddArray(about);
}
} // namespace

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
    const geoshaping::GeographicGrid grid = vtkNpzDEMParse(npz);
    FillOutput(output, grid, this->Stride);
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
