// libFuzzer target: the .npz DEM reading of vtkNpzDEMReader (Filters/IO) on any bytes:
// the zip archive, its inflated .npy entries, the grid check and, for a grid that passes
// it, the surface the reader builds (geoshaping::dem_surface).
#include "fuzz_require.h"
#include "vtkDEMProjection.h"
#include "vtkNpzDEMParser.h"

#include "geoshaping/scenes/dem_surface.h"

#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  geoshaping::ElevationGrid grid;
  try
  {
    const vtkNpzArchive npz(std::vector<char>(data, data + size));
    grid = vtkNpzDEMParse(npz);
  }
  catch (const std::exception&)
  {
    return 0; // refused with a message: what the reader reports as an error
  }
  Require(grid.rows >= 0 && grid.cols >= 0);
  Require(grid.elevation.size() == std::size_t(grid.rows) * std::size_t(grid.cols));
  // The surface of large grids (a few KB of zeros deflate to millions of samples) is
  // linear work the fuzzer need not repeat: built for grids up to 65,536 samples.
  const bool small = grid.elevation.size() <= 65536;
  for (const geoshaping::index_t stride : { 1, 2 })
  {
    if (*geoshaping::validate(grid, stride) || !small)
      continue;
    // As the reader: the grid's UTM zone through PROJ; a projection that fails or gives
    // infinite coordinates is an empty mesh with a reason, never non-finite points.
    vtkDEMProjection utm(vtkDEMProjection::LonLatWgs84);
    utm.Prepare(grid);
    std::string why;
    const geoshaping::SampleMesh mesh = geoshaping::dem_surface(
      grid, stride, [&utm](std::size_t n, double* x, double* y) { return utm(n, x, y); }, &why);
    if (mesh.xyz.empty())
    {
      Require(!why.empty());
      continue;
    }
    const std::size_t rows = std::size_t(grid.rows - 1) / stride + 1;
    const std::size_t cols = std::size_t(grid.cols - 1) / stride + 1;
    // NaN elevations are holes: fewer points and triangles, none of them NaN.
    Require(mesh.xyz.size() <= 3 * rows * cols);
    Require(mesh.connectivity.size() <= 6 * (rows - 1) * (cols - 1));
    for (const double v : mesh.xyz)
      Require(std::isfinite(v));
    for (const auto id : mesh.connectivity)
      Require(id >= 0 && id < mesh.num_points());
  }
  return 0;
}
