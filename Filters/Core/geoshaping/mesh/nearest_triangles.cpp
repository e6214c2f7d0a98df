#include "geoshaping/mesh/nearest_triangles.h"

#include "geoshaping/mesh/triangle_geometry.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace geoshaping
{

void keep_nearest(
  std::vector<Eigen::Vector3d>& triangles, const Eigen::Vector3d& p, std::size_t max_triangles)
{
  const std::size_t n = triangles.size() / 3;
  std::vector<std::pair<double, std::size_t>> order(n);
  for (std::size_t t = 0; t < n; ++t)
  {
    const Eigen::Vector3d q =
      closest_point_on_triangle(p, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
    const double d = (q - p).squaredNorm();
    order[t] = { d == d ? d : std::numeric_limits<double>::infinity(), t };
  }
  const std::size_t k = std::min(max_triangles, n);
  std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(k), order.end());
  order.resize(k);
  std::sort(order.begin(), order.end());
  std::vector<Eigen::Vector3d> kept;
  kept.reserve(3 * k);
  for (const auto& [d, t] : order)
  {
    kept.insert(kept.end(), triangles.begin() + std::ptrdiff_t(3 * t),
      triangles.begin() + std::ptrdiff_t(3 * t + 3));
  }
  triangles = std::move(kept);
}

} // namespace geoshaping
