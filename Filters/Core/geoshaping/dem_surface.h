#pragma once
// A geographic elevation grid (a DEM in longitude/latitude degrees) as a triangulated
// surface in metres: a local equirectangular projection about the grid's centre,
// offset to a UTM-sized position, so that the surface has the coordinates a geologist's
// data has (docs/painting.md, "Real topography").
//
//   x = E0 + R cos(lat0) (lon - lon0) pi/180,   y = N0 + R (lat - lat0) pi/180,   z = elevation
//
// with (lon0, lat0) the centre of the full grid, R = 6,371,008.8 m (mean Earth radius)
// and (E0, N0) the easting/northing given to the centre. Good to about 0.1 % in
// distances over a 30 km tile: enough to shape a surface, not a survey-grade UTM
// conversion.
#include "geoshaping/sample_scenes.h"

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

struct LocalProjection
{
  double centre_easting = 745000.0; // m, where UTM zone 16N puts the Jacksboro DEM
  double centre_northing = 4055000.0;
  double earth_radius = 6371008.8;
};

// Why the grid cannot make a surface ("" when it can): fewer than 2 x 2 samples (after
// the stride), a size that does not match the elevations, non-finite bounds or a zero
// span, latitudes outside [-90, 90], a stride < 1, a non-finite projection, or bounds
// that project to infinite coordinates (longitudes -1e308 and 1e308: finite, but not
// their span).
const char* validate(const GeographicGrid& grid, index_t stride, const LocalProjection& p);

// Every `stride`-th row and column (always starting at 0), as triangles: the quad of
// samples (r, c), (r, c+1), (r+1, c+1), (r+1, c) is split along its (r, c)-(r+1, c+1)
// diagonal (counter-clockwise in the (column, row) index plane, so the normals point
// down when the rows run north to south); the first triangles of every quad come first, then the
// second ones. Point (r, c) of the strided grid has id r * strided_cols + c. A NaN elevation stays
// NaN. Empty when validate() fails.
SampleMesh dem_surface(const GeographicGrid& grid, index_t stride, const LocalProjection& p);

// The projection of one longitude/latitude (degrees) about the centre of `grid`.
void project(const GeographicGrid& grid, const LocalProjection& p, double lon, double lat,
  double& x, double& y);

} // namespace geoshaping
