#include "geoshaping/metrics/marker_pins.h"
#include "geoshaping/metrics/marker_misfit.h"

#include <algorithm>
#include <cmath>

namespace geoshaping
{

MarkerPins pin_markers(const double* markers, std::size_t count,
  const std::function<void(const Eigen::Vector3d&, std::vector<index_t>&)>& crossed,
  const std::function<Eigen::Vector3d(index_t)>& position, double tolerance)
{
  MarkerPins pins;
  std::vector<index_t> corners;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Eigen::Vector3d m(markers + 3 * i);
    if (!m.allFinite())
    {
      ++pins.non_finite;
      continue;
    }
    corners.clear();
    crossed(m, corners);
    double z = 0.0;
    const std::ptrdiff_t t =
      nearest_crossed_triangle(m, corners.data(), corners.size(), position, z);
    if (t < 0)
    {
      ++pins.outside;
      continue;
    }
    ++pins.honoured;
    if (std::abs(z - m.z()) > tolerance)
      ++pins.off_surface;
    pins.vertices.insert(pins.vertices.end(), corners.begin() + t, corners.begin() + t + 3);
  }
  std::sort(pins.vertices.begin(), pins.vertices.end());
  pins.vertices.erase(std::unique(pins.vertices.begin(), pins.vertices.end()), pins.vertices.end());
  return pins;
}

std::ptrdiff_t nearest_crossed_triangle(const Eigen::Vector3d& m, const index_t* corners,
  std::size_t count, const std::function<Eigen::Vector3d(index_t)>& position, double& z)
{
  // Kept between calls: a frame asks once per marker, without allocating.
  thread_local std::vector<double> crossings;
  thread_local std::vector<std::ptrdiff_t> candidates;
  crossings.clear();
  candidates.clear();
  for (std::size_t t = 0; t + 2 < count; t += 3)
  {
    double elevation = 0.0;
    if (plane_elevation(position(corners[t]), position(corners[t + 1]), position(corners[t + 2]),
          m.x(), m.y(), elevation))
    {
      crossings.push_back(elevation);
      candidates.push_back(std::ptrdiff_t(t));
    }
  }
  const std::ptrdiff_t nearest = nearest_crossing(m.z(), crossings);
  if (nearest < 0)
    return -1;
  z = crossings[std::size_t(nearest)];
  return candidates[std::size_t(nearest)];
}

MisfitSummary mapped_vertical_misfit(
  const MarkerCrossingMap& map, const std::function<Eigen::Vector3d(index_t)>& position)
{
  std::vector<double> misfit(map.size(), 0.0);
  std::vector<unsigned char> inside(map.size(), 0);
  for (std::size_t i = 0; i < map.size(); ++i)
  {
    const Eigen::Vector3d m(map.xyz.data() + 3 * i);
    double z = 0.0;
    if (nearest_crossed_triangle(
          m, map.corners.data() + map.first[i], map.first[i + 1] - map.first[i], position, z) >= 0)
    {
      misfit[i] = z - m.z();
      inside[i] = 1;
    }
  }
  return summarize_misfit(misfit, inside);
}

} // namespace geoshaping
