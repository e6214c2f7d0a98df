#pragma once
// An elevation grid (a DEM: a NumPy .npz archive or a single-band raster, in
// longitude/latitude degrees or in a projected CRS) as a triangulated surface in metres
// (docs/painting.md, "Real topography"; docs/readers.md, "Elevation rasters"). The map
// projection is the caller's (a Projector): Filters/IO's vtkDEMProjection projects
// geographic grids with PROJ to the UTM zone of their centre and scales projected ones
// to metres, so the surface has the coordinates a geologist's data has. The core stays
// free of PROJ and of VTK; the .npz reader and the DEMSurface filter both end here.
#include "geoshaping/scenes/sample_scenes.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace geoshaping
{

struct ElevationGrid
{
  index_t rows = 0; // row r at y_first + r (y_last - y_first) / (rows - 1)
  index_t cols = 0; // column c at x_first + c (x_last - x_first) / (cols - 1)
  // rows * cols, row-major, metres; a non-finite value is "no data" (a hole).
  std::vector<double> elevation;
  // Map coordinates of the first and last column (x) and row (y), in either order:
  // degrees of longitude (x) and latitude (y) when `geographic`, else the CRS's units.
  // Image-ordered DEMs (matplotlib's Jacksboro DEM, GeoTIFFs) start with the northern row.
  double x_first = 0.0, x_last = 0.0, y_first = 0.0, y_last = 0.0;
  bool geographic = true;
};

// An image of samples as VTK stores one (vtkImageData): `values` has dims[0] * dims[1]
// entries, column index i fastest, at x = origin[0] + (i + offset) spacing[0] and
// y = origin[1] + (j + offset) spacing[1], offset 1/2 for cell data (pixels, as
// ParaView's GDALRasterReader gives them) and 0 for point data.
struct ImageSamples
{
  index_t dims[2] = { 0, 0 };
  double origin[2] = { 0.0, 0.0 };
  double spacing[2] = { 0.0, 0.0 };
  bool cell_centred = true;
  std::vector<double> values;
  std::vector<unsigned char> hidden; // empty, or one per value: nonzero = no data
  bool has_nodata = false;           // when true, a value equal to `nodata` is no data
  double nodata = 0.0;
};

// The image as a grid in the raster's own row order: row r is the image row with the
// r-th largest y (north first, as the file stores it: GDALRasterReader flips the rows so
// that y grows with j, this flips them back), column c is image column c. A hidden
// sample, one equal to `nodata`, or a non-finite one becomes NaN (no data). x_first,
// x_last, y_first, y_last are the coordinates of the first and last column and row, so
// dem_surface's linspace puts every sample where the image does (to rounding).
ElevationGrid grid_of_image(const ImageSamples& image, bool geographic);

// A band's no-data value as raster readers write it in text (GDALRasterReader's
// NO_DATA_VALUE: "-9999", "-3.4028234663852886e+38", "nan" when the band has none): one
// number (std::from_chars, so no locale), spaces around it allowed. False, `value`
// untouched, for anything else. "nan" gives NaN: NaN samples are no data in any case.
bool parse_nodata(const std::string& text, double* value);

// Projects `count` points, given as x (longitudes) and y (latitudes) in the grid's
// units, in place to metres (easting, northing). False when the projection fails.
using Projector = std::function<bool(std::size_t count, double* x, double* y)>;

// Why the grid cannot make a surface ("" when it can): fewer than 2 x 2 samples (after
// the stride), a size that does not match the elevations, non-finite bounds or spans, a
// zero span, latitudes outside [-90, 90] (geographic grids), a stride < 1, more than
// 2^31 - 1 vertices.
const char* validate(const ElevationGrid& grid, index_t stride);

// Every `stride`-th row and column (always starting at 0), as triangles: the quad of
// samples (r, c), (r, c+1), (r+1, c+1), (r+1, c) is split along its (r, c)-(r+1, c+1)
// diagonal (counter-clockwise in the (column, row) index plane, so the normals point
// down when the rows run north to south); the first triangles of every quad come first,
// then the second ones. A no-data sample (non-finite elevation) is left out with every
// triangle that uses it: a hole, never a spike. The kept samples are numbered in row-major
// order of the strided grid, at the projection of (x_c, y_r) (numpy.linspace of the
// bounds over the full grid); without holes, point (r, c) has id r * strided_cols + c.
// Empty, with `why` (if given) set, when validate() fails, every sample is no data, the
// projection fails or it gives a non-finite coordinate. One call of `project` with every
// kept sample.
SampleMesh dem_surface(
  const ElevationGrid& grid, index_t stride, const Projector& project, std::string* why = nullptr);

} // namespace geoshaping
