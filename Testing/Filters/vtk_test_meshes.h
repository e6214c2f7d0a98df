#pragma once
// VTK versions of the test meshes, shared by the filter tests, the stability suite and
// the filter benchmark. The triangulation is that of geoshaping::testing::triangle_grid.
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnstructuredGrid.h"

#include <functional>

namespace geoshaping::testing
{

// nx * ny triangle grid with spacing h at z = 0 starting at (x0, y0); points of `type`
// (VTK_FLOAT or VTK_DOUBLE) and, unless `malleability` is empty, a float point array
// "Malleability" holding malleability(i, j).
vtkSmartPointer<vtkPolyData> TriangleGridPolyData(int nx, int ny, double h,
  const std::function<double(int, int)>& malleability, int type = VTK_DOUBLE, double x0 = 0.0,
  double y0 = 0.0);

// nx * ny * nz points spaced h in double precision, each hexahedral block split into 6
// tetrahedra around its (0,0,0)-(1,1,1) diagonal; unless `malleability` is empty, a
// float point array "Malleability" holding malleability(i, j, k).
vtkSmartPointer<vtkUnstructuredGrid> TetSlabUnstructuredGrid(
  int nx, int ny, int nz, double h, const std::function<double(int, int, int)>& malleability);

} // namespace geoshaping::testing
