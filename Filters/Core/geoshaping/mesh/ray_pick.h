#pragma once
// @brief The surface under a pixel on a distributed server (docs/interactor.md, "The pick"):
// each process meets the pixel's ray with the polygons of its piece (ray_pick), and the
// nearest of the processes' hits is the answer (nearer_hit, the reduction rule).
#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace geoshaping
{

// One process's answer: the ray's parameter t of the hit (origin + t direction), the point
// and the unit normal of the polygon there (its winding's side), the vertex of that polygon
// nearest the point (its index in the piece; the caller may name it by GlobalIds) and the
// process. hit false: the ray meets no polygon of the piece.
struct RayHit
{
  bool hit = false;
  double t = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::int64_t point_id = -1;
  int rank = -1;
};

// The nearest hit (least t >= 0) of the ray origin + t direction with the polygons of a
// piece: `xyz` 3 doubles a point, the polygons as CSR (`offsets`, size faces + 1, into
// `vertices`), each fanned into triangles (v0, vi, vi+1) and met by Moeller-Trumbore
// (both sides, edges included: a ray through a shared edge hits the polygon met first,
// the lower index). O(polygons); `direction` need not be unit. A zero direction or a
// degenerate triangle meets nothing.
RayHit ray_pick(const double* xyz, const std::vector<std::int64_t>& offsets,
  const std::vector<index_t>& vertices, const Eigen::Vector3d& origin,
  const Eigen::Vector3d& direction, int rank);

// The reduction across processes: a hit over none; the lesser t; on equal t (a ray through
// the seam, where both pieces hold the edge) the lower rank, so every process and every
// order of reduction agrees.
const RayHit& nearer_hit(const RayHit& a, const RayHit& b);

// A hit as 10 doubles for a collective (hit, t, point, normal, point id, rank) and back:
// point ids up to 2^53 travel exactly.
constexpr int ray_hit_doubles = 10;
void pack_ray_hit(const RayHit& h, double out[ray_hit_doubles]);
RayHit unpack_ray_hit(const double in[ray_hit_doubles]);

} // namespace geoshaping
