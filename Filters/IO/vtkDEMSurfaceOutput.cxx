#include "vtkDEMSurfaceOutput.h"

#include "vtkDEMProjection.h"
#include "vtkGeoShapingAdapter.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <stdexcept>
#include <string>

void vtkDEMSurfaceOutput(vtkPolyData* output, const geoshaping::ElevationGrid& grid, int stride,
  vtkDEMProjection& projection)
{
  if (const char* why = geoshaping::validate(grid, stride); *why)
    throw std::runtime_error(why);
  projection.Prepare(grid);
  std::string why;
  const geoshaping::SampleMesh mesh = geoshaping::dem_surface(
    grid, stride,
    [&projection](std::size_t n, double* x, double* y) { return projection(n, x, y); }, &why);
  if (mesh.xyz.empty())
    throw std::runtime_error(why);
  output->SetPoints(vtkGeoShapingAdapter::MakePoints(mesh.xyz));
  output->SetPolys(vtkGeoShapingAdapter::MakeCells(mesh.connectivity, 3));
  vtkNew<vtkDoubleArray> elevation;
  elevation->SetName("Elevation");
  elevation->SetNumberOfTuples(mesh.num_points());
  for (geoshaping::index_t i = 0; i < mesh.num_points(); ++i)
    elevation->SetValue(i, mesh.xyz[3 * std::size_t(i) + 2]);
  output->GetPointData()->SetScalars(elevation); // shown coloured by it
  vtkNew<vtkStringArray> about;
  about->SetName("Projection");
  about->InsertNextValue(
    projection.GetDescription() +
    (projection.IsGeographic() ? ", reprojected from longitude/latitude" : "") +
    "; z = elevation (m); stride " + std::to_string(stride));
  output->GetFieldData()->AddArray(about);
}
