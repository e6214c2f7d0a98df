#pragma once
// A geographic elevation grid (a DEM in longitude/latitude degrees) as a triangulated
// surface in metres (docs/painting.md, "Real topography"). The map projection is the
// caller's (a Projector): vtkNpzDEMReader projects with PROJ to the grid's UTM zone, so
// the surface has the coordinates a geologist's data has. The core stays free of PROJ.
#include "geoshaping/sample_scenes.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace geoshaping
{

struct GeographicGrid
{
  index_t rows = 0; // latitudes: row r at lat_first + r (lat_last - lat_first) / (rows - 1)
  index_t cols = 0; // longitudes: column c at lon_first + c (lon_last - lon_first) / (cols - 1)
  std::vector<double> elevation; // rows * cols, row-major, metres
  // Degrees, of the first and last column and row. Either order: image-ordered DEMs
  // (matplotlib's Jacksboro DEM among them) start with the northern row.
  double lon_first = 0.0, lon_last = 0.0, lat_first = 0.0, lat_last = 0.0;
};

// Projects `count` points, given as longitudes in `x` and latitudes in `y` (degrees), in
// place to metres (easting, northing). False when the projection fails.
using Projector = std::function<bool(std::size_t count, double* x, double* y)>;

// Why the grid cannot make a surface ("" when it can): fewer than 2 x 2 samples (after
// the stride), a size that does not match the elevations, non-finite bounds or spans, a
// zero span, latitudes outside [-90, 90], a stride < 1, more than 2^31 - 1 vertices.
const char* validate(const GeographicGrid& grid, index_t stride);

// Every `stride`-th row and column (always starting at 0), as triangles: the quad of
// samples (r, c), (r, c+1), (r+1, c+1), (r+1, c) is split along its (r, c)-(r+1, c+1)
// diagonal (counter-clockwise in the (column, row) index plane, so the normals point
// down when the rows run north to south); the first triangles of every quad come first,
// then the second ones. Point (r, c) of the strided grid has id r * strided_cols + c, at
// the projection of (lon_c, lat_r) (numpy.linspace of the bounds over the full grid). A
// NaN elevation stays NaN. Empty, with `why` (if given) set, when validate() fails, the
// projection fails or it gives a non-finite coordinate. One call of `project` with every
// kept sample.
SampleMesh dem_surface(
  const GeographicGrid& grid, index_t stride, const Projector& project, std::string* why = nullptr);

} // namespace geoshaping
