/**
 * @file   vtkDEMSurfaceOutput.h
 * @brief  The one way an elevation grid becomes GeoShaping's DEM surface, shared by
 *         vtkNpzDEMReader and vtkDEMSurfaceFilter.
 *
 * Contract: checks the grid (geoshaping::validate), prepares `projection` for it, builds
 * the surface (geoshaping::dem_surface: no-data samples left out with their triangles)
 * and fills `output` with double-precision points in metres, the triangles, the point
 * array `Elevation` (= z) and the string field `Projection` (the output's coordinates,
 * whether they were reprojected from longitude/latitude, "z = elevation (m)" and the
 * stride). Throws std::runtime_error with the reason, leaving `output` untouched.
 */
#ifndef vtkDEMSurfaceOutput_h
#define vtkDEMSurfaceOutput_h

#include "geoshaping/scenes/dem_surface.h"

class vtkDEMProjection;
class vtkPolyData;

void vtkDEMSurfaceOutput(vtkPolyData* output, const geoshaping::ElevationGrid& grid, int stride,
  vtkDEMProjection& projection);

#endif
// VTK-HeaderTest-Exclude: vtkDEMSurfaceOutput.h
