#pragma once
// VTK versions of the test meshes, shared by the filter tests, the stability suite and
// the filter benchmark. The triangulation is that of geoshaping::testing::triangle_grid.
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>

namespace geoshaping::testing
{

// nx * ny triangle grid with spacing h at z = 0 starting at (x0, y0); points of `type`
// (VTK_FLOAT or VTK_DOUBLE) and, unless `malleability` is empty, a float point array
// "Malleability" holding malleability(i, j).
vtkSmartPointer<vtkPolyData> TriangleGridPolyData(int nx, int ny, double h,
  const std::function<double(int, int)>& malleability, int type = VTK_DOUBLE, double x0 = 0.0,
  double y0 = 0.0);

} // namespace geoshaping::testing
