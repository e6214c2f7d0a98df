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

#include <sstream>
#include <stdexcept>
#include <string>

vtkStandardNewMacro(vtkNpzDEMReader);

namespace
{
// The surface of a validated grid, with its Elevation, LonLatBounds and Projection.
void FillOutput(vtkPolyData* output, const geoshaping::GeographicGrid& grid, int stride,
  const geoshaping::LocalProjection& projection)
{
  const geoshaping::SampleMesh mesh = geoshaping::dem_surface(grid, stride, projection);
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
  std::ostringstream text;
  text.precision(17);
  text << "local equirectangular about the grid centre, R = " << projection.earth_radius
       << " m, centre at " << projection.centre_easting << " E " << projection.centre_northing
       << " N; z = elevation (m); stride " << stride;
  about->InsertNextValue(text.str());
  output->GetFieldData()->AddArray(about);
}
} // namespace

vtkNpzDEMReader::vtkNpzDEMReader()
{
  this->SetNumberOfInputPorts(0);
  const geoshaping::LocalProjection defaults;
  this->CentreEasting = defaults.centre_easting;
  this->CentreNorthing = defaults.centre_northing;
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
    geoshaping::LocalProjection projection;
    projection.centre_easting = this->CentreEasting;
    projection.centre_northing = this->CentreNorthing;
    if (const char* why = geoshaping::validate(grid, this->Stride, projection); *why)
      throw std::runtime_error(why);
    FillOutput(output, grid, this->Stride, projection);
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
  os << indent << "CentreEasting: " << this->CentreEasting << "\n";
  os << indent << "CentreNorthing: " << this->CentreNorthing << "\n";
}
