// Shared by the marker tests: markers as points, and markers sampled on a real CRESCENT
// surface (read in place from GEOSHAPING_CFM_DIR) and moved along z by known amounts.
#pragma once

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

namespace markers_testing
{
using Xyz = std::vector<std::array<double, 3>>;

// The points `xyz` (double), no cells.
vtkSmartPointer<vtkPolyData> Points(const Xyz& xyz);

// `count` markers at random points (seeded by `seed`) of random triangles of `surface`:
// barycentric coordinates uniform on the triangle, shrunk to `shrink` of it about its
// centroid (1: the whole triangle). The first `onSurface` lie on it; the others are moved
// along z by dz uniform in +-0.1 of the surface's first edge.
struct Samples
{
  Xyz xyz;
  std::vector<double> dz;
  double edge = 0.0; // the length of the first cell's first edge
  vtkSmartPointer<vtkPolyData> surface;
  double size = 0.0; // the surface's bounding box diagonal
};
Samples SampleMarkers(vtkPolyData* surface, unsigned seed, int count, int onSurface, double shrink);

// The same on the Cascadia subduction interface (CRESCENT, CC BY 4.0, read in place);
// `surface` null when the file `path` is absent.
Samples SampleCascadia(unsigned seed, int count, int onSurface, double shrink, std::string& path);
}
