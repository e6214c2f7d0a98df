// libFuzzer target: what vtkDEMSurfaceFilter (Filters/IO) parses and decides itself on a
// raster GDAL has read (the file's bytes are GDAL's): the CRS text of MAP_PROJECTION
// (vtkDEMProjection: PROJ, then type, units, prime meridian, UTM zone), the
// NO_DATA_VALUE text (geoshaping::parse_nodata), and a small image with no-data samples
// through geoshaping::grid_of_image and dem_surface.
//
// Input: the CRS text, a newline, the no-data text, a newline, then bytes: columns and
// rows (2 + byte % 15 each), stride (1 + byte % 3), flags (bit 0 point data, bit 1 use
// hidden marks), origin and spacing (4 signed bytes, scaled), then one signed byte per
// sample (127: NaN; a byte's low bit is its hidden mark when bit 1 is set), cycled.
#include "fuzz_require.h"
#include "vtkDEMProjection.h"

#include "geoshaping/scenes/dem_surface.h"

#include <cmath>
#include <cstdint>
#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t first = text.find('\n');
  const std::size_t second = first == std::string::npos ? first : text.find('\n', first + 1);
  if (second == std::string::npos || size - second - 1 < 8)
    return 0;
  const std::string crs = text.substr(0, first);
  const std::string nodata = text.substr(first + 1, second - first - 1);
  const std::uint8_t* b = data + second + 1;
  const std::size_t rest = size - second - 1;

  geoshaping::ImageSamples image;
  if (!nodata.empty())
  {
    if (!geoshaping::parse_nodata(nodata, &image.nodata))
      return 0; // refused with a message, as the filter does
    image.has_nodata = true;
  }
  image.dims[0] = 2 + b[0] % 15;
  image.dims[1] = 2 + b[1] % 15;
  const geoshaping::index_t stride = 1 + b[2] % 3;
  image.cell_centred = !(b[3] & 1);
  const bool hidden = b[3] & 2;
  image.origin[0] = double(std::int8_t(b[4])) * 1.5;
  image.origin[1] = double(std::int8_t(b[5])) * 0.75;
  image.spacing[0] = double(std::int8_t(b[6])) * 0.01;
  image.spacing[1] = double(std::int8_t(b[7])) * 0.01;
  const std::size_t n = std::size_t(image.dims[0]) * std::size_t(image.dims[1]);
  std::size_t finite = 0;
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::int8_t v = rest > 8 ? std::int8_t(b[8 + k % (rest - 8)]) : 0;
    image.values.push_back(v == 127 ? std::nan("") : double(v));
    if (hidden)
      image.hidden.push_back(v & 1);
  }
  try
  {
    vtkDEMProjection projection(crs);
    const geoshaping::ElevationGrid grid =
      geoshaping::grid_of_image(image, projection.IsGeographic());
    Require(grid.elevation.size() == n);
    if (*geoshaping::validate(grid, stride))
      return 0;
    projection.Prepare(grid);
    const geoshaping::index_t rows = (grid.rows - 1) / stride + 1;
    const geoshaping::index_t cols = (grid.cols - 1) / stride + 1;
    for (geoshaping::index_t r = 0; r < rows; ++r)
      for (geoshaping::index_t c = 0; c < cols; ++c)
        finite += std::isfinite(grid.elevation[std::size_t(r * stride * grid.cols + c * stride)]);
    std::string why;
    const geoshaping::SampleMesh mesh = geoshaping::dem_surface(
      grid, stride,
      [&projection](std::size_t count, double* x, double* y) { return projection(count, x, y); },
      &why);
    if (mesh.xyz.empty())
    {
      Require(!why.empty());
      return 0;
    }
    // One vertex per sample with data, none NaN; triangles of three distinct vertices.
    Require(mesh.num_points() == geoshaping::index_t(finite));
    for (const double v : mesh.xyz)
      Require(std::isfinite(v));
    Require(mesh.connectivity.size() % 3 == 0);
    Require(mesh.num_cells() <= 2 * std::size_t(rows - 1) * std::size_t(cols - 1));
    for (std::size_t t = 0; t < mesh.connectivity.size(); t += 3)
    {
      const auto* ids = &mesh.connectivity[t];
      for (int k = 0; k < 3; ++k)
        Require(ids[k] >= 0 && ids[k] < mesh.num_points());
      Require(ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2]);
    }
  }
  catch (const std::exception&)
  {
    return 0; // refused with a message: what the filter reports as an error
  }
  return 0;
}
