#include "geoshaping/dem_surface.h"

#include <cmath>

namespace geoshaping
{

namespace
{
index_t strided(index_t n, index_t stride)
{
  return (n - 1) / stride + 1;
}

// numpy.linspace(lo, hi, n)[i]: lo + i * step, the last one exactly hi.
double linspace(double lo, double hi, index_t n, index_t i)
{
  return i == n - 1 ? hi : lo + double(i) * ((hi - lo) / double(n - 1));
}
} // namespace

const char* validate(const GeographicGrid& g, index_t stride)
{
  if (stride < 1)
    return "the stride must be at least 1";
  if (g.rows < 2 || g.cols < 2 || g.elevation.size() != std::size_t(g.rows) * std::size_t(g.cols))
    return "the grid must have at least 2 x 2 samples and rows x cols elevations";
  if (strided(g.rows, stride) < 2 || strided(g.cols, stride) < 2)
    return "the stride leaves fewer than 2 x 2 samples";
  for (double v : { g.lon_first, g.lon_last, g.lat_first, g.lat_last })
    if (!std::isfinite(v))
      return "the longitude/latitude bounds must be finite";
  // Finite bounds can still give an infinite span (longitudes -1e308 and 1e308).
  if (!std::isfinite(g.lon_last - g.lon_first) || !std::isfinite(g.lat_last - g.lat_first))
    return "the longitude/latitude spans must be finite";
  if (g.lon_first == g.lon_last || g.lat_first == g.lat_last)
    return "the first and last longitudes, and latitudes, must differ";
  if (std::abs(g.lat_first) > 90.0 || std::abs(g.lat_last) > 90.0)
    return "latitudes must lie in [-90, 90]";
  if (double(strided(g.rows, stride)) * double(strided(g.cols, stride)) > 2147483647.0)
    return "more than 2^31 - 1 vertices";
  return "";
}

SampleMesh dem_surface(
  const GeographicGrid& g, index_t stride, const Projector& project, std::string* why)
{
  SampleMesh mesh;
  auto fail = [&](const char* reason)
  {
    if (why)
      *why = reason;
    return SampleMesh();
  };
  if (const char* invalid = validate(g, stride); *invalid)
    return fail(invalid);
  const index_t rows = strided(g.rows, stride), cols = strided(g.cols, stride);
  const std::size_t n = std::size_t(rows) * std::size_t(cols);
  std::vector<double> x(n), y(n);
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c)
    {
      const std::size_t k = std::size_t(r) * std::size_t(cols) + std::size_t(c);
      x[k] = linspace(g.lon_first, g.lon_last, g.cols, c * stride);
      y[k] = linspace(g.lat_first, g.lat_last, g.rows, r * stride);
    }
  if (!project || !project(n, x.data(), y.data()))
    return fail("the map projection failed");
  mesh.xyz.reserve(3 * n);
  for (index_t r = 0; r < rows; ++r)
  {
    const std::size_t gr = std::size_t(r * stride);
    for (index_t c = 0; c < cols; ++c)
    {
      const std::size_t k = std::size_t(r) * std::size_t(cols) + std::size_t(c);
      if (!std::isfinite(x[k]) || !std::isfinite(y[k]))
        return fail("the projection gives infinite or undefined x or y");
      mesh.xyz.insert(mesh.xyz.end(),
        { x[k], y[k], g.elevation[gr * std::size_t(g.cols) + std::size_t(c * stride)] });
    }
  }
  const std::size_t quads = std::size_t(rows - 1) * std::size_t(cols - 1);
  mesh.connectivity.resize(6 * quads);
  index_t* first = mesh.connectivity.data();
  index_t* second = first + 3 * quads;
  for (index_t r = 0; r + 1 < rows; ++r)
  {
    for (index_t c = 0; c + 1 < cols; ++c)
    {
      const index_t a = r * cols + c, b = a + 1, d = a + cols, e = d + 1;
      *first++ = a, *first++ = b, *first++ = e;
      *second++ = a, *second++ = e, *second++ = d;
    }
  }
  return mesh;
}

} // namespace geoshaping
