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
  std::vector<index_t> corners, candidates;
  std::vector<double> crossings;
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
    crossings.clear();
    candidates.clear();
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3)
    {
      double z = 0.0;
      if (plane_elevation(position(corners[t]), position(corners[t + 1]), position(corners[t + 2]),
            m.x(), m.y(), z))
      {
        crossings.push_back(z);
        candidates.push_back(index_t(t));
      }
    }
    const std::ptrdiff_t nearest = nearest_crossing(m.z(), crossings);
    if (nearest < 0)
    {
      ++pins.outside;
      continue;
    }
    ++pins.honoured;
    if (std::abs(crossings[std::size_t(nearest)] - m.z()) > tolerance)
      ++pins.off_surface;
    const std::size_t t = std::size_t(candidates[std::size_t(nearest)]);
    pins.vertices.insert(pins.vertices.end(), corners.begin() + std::ptrdiff_t(t),
      corners.begin() + std::ptrdiff_t(t + 3));
  }
  std::sort(pins.vertices.begin(), pins.vertices.end());
  pins.vertices.erase(std::unique(pins.vertices.begin(), pins.vertices.end()), pins.vertices.end());
  return pins;
}

} // namespace geoshaping
