#include "geoshaping/dem_surface.h"

#include <cmath>

namespace geoshaping
{

namespace
{
constexpr double degree = 3.14159265358979323846 / 180.0;

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

const char* validate(const GeographicGrid& g, index_t stride, const LocalProjection& p)
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
  if (g.lon_first == g.lon_last || g.lat_first == g.lat_last)
    return "the first and last longitudes, and latitudes, must differ";
  if (std::abs(g.lat_first) > 90.0 || std::abs(g.lat_last) > 90.0)
    return "latitudes must lie in [-90, 90]";
  if (!std::isfinite(p.centre_easting) || !std::isfinite(p.centre_northing) ||
      !(p.earth_radius > 0.0) || !std::isfinite(p.earth_radius))
    return "the projection's centre and Earth radius must be finite (radius > 0)";
  if (double(strided(g.rows, stride)) * double(strided(g.cols, stride)) > 2147483647.0)
    return "more than 2^31 - 1 vertices";
  // Finite bounds can still give infinite spacing or coordinates (longitudes -1e308 and
  // 1e308): the spans and the four corners must be finite (the other samples lie between).
  double x[4], y[4];
  for (int k = 0; k < 4; ++k)
    project(g, p, k & 1 ? g.lon_last : g.lon_first, k & 2 ? g.lat_last : g.lat_first, x[k], y[k]);
  if (!std::isfinite(g.lon_last - g.lon_first) || !std::isfinite(g.lat_last - g.lat_first) ||
      !std::isfinite(x[0] + x[1] + x[2] + x[3] + y[0] + y[1] + y[2] + y[3]))
    return "the bounds give infinite x or y: the projected coordinates must be finite";
  return "";
}

void project(
  const GeographicGrid& g, const LocalProjection& p, double lon, double lat, double& x, double& y)
{
  const double lon0 = 0.5 * (g.lon_first + g.lon_last);
  const double lat0 = 0.5 * (g.lat_first + g.lat_last);
  x = p.centre_easting + (lon - lon0) * degree * p.earth_radius * std::cos(lat0 * degree);
  y = p.centre_northing + (lat - lat0) * degree * p.earth_radius;
}

SampleMesh dem_surface(const GeographicGrid& g, index_t stride, const LocalProjection& p)
{
  SampleMesh mesh;
  if (*validate(g, stride, p))
    return mesh;
  const index_t rows = strided(g.rows, stride), cols = strided(g.cols, stride);
  mesh.xyz.reserve(3 * std::size_t(rows) * std::size_t(cols));
  for (index_t r = 0; r < rows; ++r)
  {
    const index_t gr = r * stride;
    for (index_t c = 0; c < cols; ++c)
    {
      const index_t gc = c * stride;
      double x, y;
      project(g, p, linspace(g.lon_first, g.lon_last, g.cols, gc),
        linspace(g.lat_first, g.lat_last, g.rows, gr), x, y);
      mesh.xyz.insert(mesh.xyz.end(),
        { x, y, g.elevation[std::size_t(gr) * std::size_t(g.cols) + std::size_t(gc)] });
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
