#include "geoshaping/scenes/layered_scene.h"

#include <cmath>

namespace geoshaping
{
namespace
{
bool finite_positive(double v)
{
  return std::isfinite(v) && v > 0.0;
}

// Appends an (nu x nv) triangle grid with corners a (u=0, v=0), a + du, a + dv.
void add_grid(LayeredScene& s, const Eigen::Vector3d& a, const Eigen::Vector3d& du,
  const Eigen::Vector3d& dv, double spacing, ScenePart part)
{
  const index_t nu = std::max<index_t>(2, index_t(std::ceil(du.norm() / spacing)) + 1);
  const index_t nv = std::max<index_t>(2, index_t(std::ceil(dv.norm() / spacing)) + 1);
  const index_t first = s.mesh.num_points();
  for (index_t j = 0; j < nv; ++j)
    for (index_t i = 0; i < nu; ++i)
    {
      const Eigen::Vector3d p = a + du * (double(i) / (nu - 1)) + dv * (double(j) / (nv - 1));
      s.mesh.xyz.insert(s.mesh.xyz.end(), { p.x(), p.y(), p.z() });
      s.part.push_back(int(part));
    }
  for (index_t j = 0; j + 1 < nv; ++j)
    for (index_t i = 0; i + 1 < nu; ++i)
    {
      const index_t v00 = first + j * nu + i, v10 = v00 + 1, v01 = v00 + nu, v11 = v01 + 1;
      s.mesh.connectivity.insert(s.mesh.connectivity.end(), { v00, v10, v11, v00, v11, v01 });
    }
}
} // namespace

const char* validate(const LayeredSceneParams& p)
{
  if (!finite_positive(p.length) || !finite_positive(p.width) || !finite_positive(p.spacing))
    return "length, width and spacing must be positive";
  if (!(p.dip_degrees > 0.0 && p.dip_degrees <= 90.0))
    return "the dip must be in (0, 90] degrees";
  if (!(p.bottom < p.horizon_lower - p.throw_height && p.horizon_lower < p.horizon_upper &&
        p.horizon_upper < p.top))
    return "need bottom < lower horizon - throw, lower < upper horizon < top";
  if (!std::isfinite(p.throw_height) || p.throw_height < 0.0 || !p.origin.allFinite())
    return "the throw must be finite and non-negative, the origin finite";
  const double run = (p.top - p.bottom) / std::tan(p.dip_degrees * M_PI / 180.0);
  if (!(p.fault_x > 0.0 && p.fault_x + run < p.length))
    return "the fault must cross the scene inside (0, length)";
  if (p.length * p.width / (p.spacing * p.spacing) > 5e8)
    return "too many vertices for the spacing";
  return "";
}

LayeredScene layered_fault_scene(const LayeredSceneParams& p)
{
  LayeredScene s;
  if (*validate(p))
    return s;
  const double cot = 1.0 / std::tan(p.dip_degrees * M_PI / 180.0);
  auto fault_x = [&](double z) { return p.fault_x + (p.top - z) * cot; };
  const Eigen::Vector3d dy(0.0, p.width, 0.0);
  const ScenePart parts[2] = { ScenePart::upper_horizon, ScenePart::lower_horizon };
  const double elevations[2] = { p.horizon_upper, p.horizon_lower };
  for (int h = 0; h < 2; ++h)
  {
    const double zf = elevations[h], zh = elevations[h] - p.throw_height;
    // Footwall block: from x = 0 to the fault at the footwall elevation.
    add_grid(s, p.origin + Eigen::Vector3d(0.0, 0.0, zf), Eigen::Vector3d(fault_x(zf), 0.0, 0.0),
      dy, p.spacing, parts[h]);
    // Hanging wall: from the fault at the dropped elevation to x = length.
    const double x0 = fault_x(zh);
    add_grid(s, p.origin + Eigen::Vector3d(x0, 0.0, zh), Eigen::Vector3d(p.length - x0, 0.0, 0.0),
      dy, p.spacing, parts[h]);
  }
  const Eigen::Vector3d top(fault_x(p.top), 0.0, p.top), bottom(fault_x(p.bottom), 0.0, p.bottom);
  add_grid(s, p.origin + top, bottom - top, dy, p.spacing, ScenePart::fault);
  s.mesh.cell_size = 3;
  return s;
}

} // namespace geoshaping
