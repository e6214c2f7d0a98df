#include "geoshaping/scenes/dem_surface.h"

#include <charconv>
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

ElevationGrid grid_of_image(const ImageSamples& image, bool geographic)
{
  ElevationGrid g;
  g.geographic = geographic;
  g.cols = image.dims[0];
  g.rows = image.dims[1];
  const std::size_t n = std::size_t(image.dims[0] > 0 ? image.dims[0] : 0) *
                        std::size_t(image.dims[1] > 0 ? image.dims[1] : 0);
  // A size that does not match is left for validate() to name (no elevations).
  if (n == 0 || image.values.size() != n || (!image.hidden.empty() && image.hidden.size() != n))
    return g;
  const double offset = image.cell_centred ? 0.5 : 0.0;
  const auto at = [&](int axis, index_t k)
  { return image.origin[axis] + (double(k) + offset) * image.spacing[axis]; };
  g.x_first = at(0, 0);
  g.x_last = at(0, g.cols - 1);
  // Row r is image row j = rows - 1 - r when y grows with j (north first either way).
  const bool flip = image.spacing[1] > 0.0;
  g.y_first = at(1, flip ? g.rows - 1 : 0);
  g.y_last = at(1, flip ? 0 : g.rows - 1);
  g.elevation.resize(n);
  for (index_t r = 0; r < g.rows; ++r)
  {
    const std::size_t j = std::size_t(flip ? g.rows - 1 - r : r);
    for (index_t c = 0; c < g.cols; ++c)
    {
      const std::size_t k = j * std::size_t(g.cols) + std::size_t(c);
      const double v = image.values[k];
      const bool none = (!image.hidden.empty() && image.hidden[k]) ||
                        (image.has_nodata && v == image.nodata) || !std::isfinite(v);
      g.elevation[std::size_t(r) * std::size_t(g.cols) + std::size_t(c)] = none ? NAN : v;
    }
  }
  return g;
}

bool parse_nodata(const std::string& text, double* value)
{
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
    return false;
  const std::size_t end = text.find_last_not_of(" \t\r\n") + 1;
  double v = 0.0;
  const auto [stop, error] = std::from_chars(text.data() + first, text.data() + end, v);
  if (error != std::errc() || stop != text.data() + end)
    return false;
  *value = v;
  return true;
}

const char* validate(const ElevationGrid& g, index_t stride)
{
  if (stride < 1)
    return "the stride must be at least 1";
  if (g.rows < 2 || g.cols < 2 || g.elevation.size() != std::size_t(g.rows) * std::size_t(g.cols))
    return "the grid must have at least 2 x 2 samples and rows x cols elevations";
  if (strided(g.rows, stride) < 2 || strided(g.cols, stride) < 2)
    return "the stride leaves fewer than 2 x 2 samples";
  for (double v : { g.x_first, g.x_last, g.y_first, g.y_last })
    if (!std::isfinite(v))
      return "the bounds of the grid's columns and rows must be finite";
  // Finite bounds can still give an infinite span (longitudes -1e308 and 1e308).
  if (!std::isfinite(g.x_last - g.x_first) || !std::isfinite(g.y_last - g.y_first))
    return "the column and row spans must be finite";
  if (g.x_first == g.x_last || g.y_first == g.y_last)
    return "the coordinates of the first and last columns, and rows, must differ";
  if (g.geographic && (std::abs(g.y_first) > 90.0 || std::abs(g.y_last) > 90.0))
    return "latitudes must lie in [-90, 90]";
  if (double(strided(g.rows, stride)) * double(strided(g.cols, stride)) > 2147483647.0)
    return "more than 2^31 - 1 vertices";
  return "";
}

SampleMesh dem_surface(
  const ElevationGrid& g, index_t stride, const Projector& project, std::string* why)
{
  auto fail = [&](const char* reason)
  {
    if (why)
      *why = reason;
    return SampleMesh();
  };
  if (const char* invalid = validate(g, stride); *invalid)
    return fail(invalid);
  const index_t rows = strided(g.rows, stride), cols = strided(g.cols, stride);
  const auto z = [&](index_t r, index_t c)
  { return g.elevation[std::size_t(r * stride) * std::size_t(g.cols) + std::size_t(c * stride)]; };
  // Ids of the kept samples, -1 for no data.
  std::vector<index_t> id(std::size_t(rows) * std::size_t(cols), -1);
  std::vector<double> x, y;
  x.reserve(id.size());
  y.reserve(id.size());
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c)
      if (std::isfinite(z(r, c)))
      {
        id[std::size_t(r) * std::size_t(cols) + std::size_t(c)] = index_t(x.size());
        x.push_back(linspace(g.x_first, g.x_last, g.cols, c * stride));
        y.push_back(linspace(g.y_first, g.y_last, g.rows, r * stride));
      }
  if (x.empty())
    return fail("every sample is no data");
  if (!project || !project(x.size(), x.data(), y.data()))
    return fail("the map projection failed");
  SampleMesh mesh;
  mesh.xyz.reserve(3 * x.size());
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c)
      if (const index_t k = id[std::size_t(r) * std::size_t(cols) + std::size_t(c)]; k >= 0)
      {
        if (!std::isfinite(x[std::size_t(k)]) || !std::isfinite(y[std::size_t(k)]))
          return fail("the projection gives infinite or undefined x or y");
        mesh.xyz.insert(mesh.xyz.end(), { x[std::size_t(k)], y[std::size_t(k)], z(r, c) });
      }
  const std::size_t quads = std::size_t(rows - 1) * std::size_t(cols - 1);
  std::vector<index_t> second;
  second.reserve(3 * quads);
  mesh.connectivity.reserve(6 * quads);
  for (index_t r = 0; r + 1 < rows; ++r)
    for (index_t c = 0; c + 1 < cols; ++c)
    {
      const std::size_t a = std::size_t(r) * std::size_t(cols) + std::size_t(c), d = a + cols;
      const index_t ka = id[a], kb = id[a + 1], kd = id[d], ke = id[d + 1];
      if (ka >= 0 && kb >= 0 && ke >= 0)
        mesh.connectivity.insert(mesh.connectivity.end(), { ka, kb, ke });
      if (ka >= 0 && ke >= 0 && kd >= 0)
        second.insert(second.end(), { ka, ke, kd });
    }
  mesh.connectivity.insert(mesh.connectivity.end(), second.begin(), second.end());
  return mesh;
}

} // namespace geoshaping
