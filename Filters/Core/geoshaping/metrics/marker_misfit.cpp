#include "geoshaping/metrics/marker_misfit.h"
#include "geoshaping/mesh/triangle_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace geoshaping
{

std::ptrdiff_t nearest_crossing(double marker_z, const std::vector<double>& crossings)
{
  std::ptrdiff_t nearest = crossings.empty() ? -1 : 0;
  for (std::size_t i = 1; i < crossings.size(); ++i)
    if (std::abs(crossings[i] - marker_z) < std::abs(crossings[std::size_t(nearest)] - marker_z))
      nearest = std::ptrdiff_t(i);
  return nearest;
}

double vertical_misfit(double marker_z, const std::vector<double>& crossings, bool& inside)
{
  const std::ptrdiff_t nearest = nearest_crossing(marker_z, crossings);
  inside = nearest >= 0;
  return inside ? crossings[std::size_t(nearest)] - marker_z : 0.0;
}

bool plane_elevation(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
  double x, double y, double& z)
{
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const double px = x - a.x(), py = y - a.y();
  const double det = e1.x() * e2.y() - e1.y() * e2.x();
  if (det == 0.0)
    return false;
  const double u = (px * e2.y() - py * e2.x()) / det;
  const double v = (e1.x() * py - e1.y() * px) / det;
  z = a.z() + u * e1.z() + v * e2.z();
  return true;
}

double normal_misfit(const Eigen::Vector3d& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const Eigen::Vector3d up = n.z() < 0.0 ? Eigen::Vector3d(-n) : n;
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  const Eigen::Vector3d d = closest_point_on_triangle(m - a, o, b - a, c - a) - (m - a);
  const double side = d.dot(up);
  const double distance = d.norm();
  return side < 0.0 ? -distance : distance;
}

MisfitSummary summarize_misfit(
  const std::vector<double>& misfit, const std::vector<unsigned char>& inside)
{
  MisfitSummary s;
  double sum_squares = 0.0;
  for (std::size_t i = 0; i < misfit.size(); ++i)
  {
    if (!inside[i])
      continue;
    ++s.inside;
    sum_squares += misfit[i] * misfit[i];
    s.max = std::max(s.max, std::abs(misfit[i]));
  }
  s.rms = s.inside > 0 ? std::sqrt(sum_squares / double(s.inside)) : 0.0;
  return s;
}

} // namespace geoshaping
