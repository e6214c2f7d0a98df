#include "geoshaping/mesh/ray_pick.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace geoshaping
{
namespace
{
Eigen::Vector3d at(const double* xyz, std::int64_t v)
{
  return Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
}

// Moeller-Trumbore: t of the ray's hit with triangle (a, b, c), or false.
bool hit_triangle(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c, double& t)
{
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0.0)
    return false;
  const double inv = 1.0 / det;
  const Eigen::Vector3d s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0.0 || u > 1.0)
    return false;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0.0 || u + v > 1.0)
    return false;
  t = e2.dot(q) * inv;
  return t >= 0.0;
}
}

RayHit ray_pick(const double* xyz, const std::vector<std::int64_t>& offsets,
  const std::vector<index_t>& vertices, const Eigen::Vector3d& origin,
  const Eigen::Vector3d& direction, int rank)
{
  RayHit best;
  best.rank = rank;
  if (!direction.allFinite() || direction.squaredNorm() == 0.0 || !origin.allFinite())
    return best;
  std::size_t face = 0, corner = 0;
  for (std::size_t f = 0; f + 1 < offsets.size(); ++f)
  {
    const std::int64_t first = offsets[f], end = offsets[f + 1];
    for (std::int64_t i = first + 1; i + 1 < end; ++i)
    {
      const Eigen::Vector3d a = at(xyz, vertices[first]), b = at(xyz, vertices[i]),
                            c = at(xyz, vertices[i + 1]);
      double t;
      if (hit_triangle(origin, direction, a, b, c, t) && (!best.hit || t < best.t))
      {
        best.hit = true;
        best.t = t;
        face = f;
        corner = std::size_t(i);
      }
    }
  }
  if (!best.hit)
    return best;
  const std::int64_t first = offsets[face];
  const std::int64_t tri[3] = { vertices[first], vertices[corner], vertices[corner + 1] };
  best.point = origin + best.t * direction;
  const Eigen::Vector3d a = at(xyz, tri[0]);
  best.normal = (at(xyz, tri[1]) - a).cross(at(xyz, tri[2]) - a).normalized();
  double nearest = -1.0;
  for (std::int64_t v : tri)
  {
    const double d2 = (at(xyz, v) - best.point).squaredNorm();
    if (nearest < 0.0 || d2 < nearest)
    {
      nearest = d2;
      best.point_id = v;
    }
  }
  return best;
}

const RayHit& nearer_hit(const RayHit& a, const RayHit& b)
{
  if (a.hit != b.hit)
    return a.hit ? a : b;
  if (!a.hit || a.t != b.t)
    return a.t <= b.t ? a : b;
  return a.rank <= b.rank ? a : b;
}

void pack_ray_hit(const RayHit& h, double out[ray_hit_doubles])
{
  const double v[ray_hit_doubles] = { h.hit ? 1.0 : 0.0, h.t, h.point.x(), h.point.y(), h.point.z(),
    h.normal.x(), h.normal.y(), h.normal.z(), double(h.point_id), double(h.rank) };
  std::copy(v, v + ray_hit_doubles, out);
}

RayHit unpack_ray_hit(const double in[ray_hit_doubles])
{
  RayHit h;
  h.hit = in[0] != 0.0;
  h.t = in[1];
  h.point = Eigen::Vector3d(in[2], in[3], in[4]);
  h.normal = Eigen::Vector3d(in[5], in[6], in[7]);
  h.point_id = std::int64_t(in[8]);
  h.rank = int(in[9]);
  return h;
}

} // namespace geoshaping
