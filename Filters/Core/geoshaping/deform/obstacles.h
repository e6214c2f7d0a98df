#pragma once
// Obstacle surfaces a deformation may not cross (docs/obstacles.md).
#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace geoshaping
{

/**
 * @brief Triangles that a moving vertex may not cross, in an AABB tree built once.
 *
 * Contract. A vertex moves along the straight segment from its rest position p to
 * p + w. admissible_fraction(p, w) is the largest f in [0, 1] such that the segment
 * p -> p + f w obeys the rule below (and f = 1, exactly, when the whole segment does):
 * the caller moves the vertex by f w, "the last admissible point of its segment".
 *
 * The rule, with clearance c >= 0 (scene units) and the stand-off g (below):
 *
 * - Crossing (every vertex). Triangle T = (a, b, c) with normal n = (b - a) x (c - a)
 *   and s(x) = n.(x - a). The segment [p, q] crosses T when s(p) and s(q) have strictly
 *   opposite signs and the line pq meets the closed triangle: with the edge function
 *   E(u, v) = ((u - p) x (v - p)).(q - p), the three values E(a, b), E(b, c), E(c, a)
 *   are all >= 0 or all <= 0. E(u, v) is evaluated with (u, v) in increasing vertex index
 *   order and negated for the other order, so the two triangles of a shared edge see
 *   bit-identical opposite values: a segment through an edge or a vertex crosses every
 *   triangle around it, and none slips between two triangles of a sheet (watertight).
 *   Sheets touching at one point: a segment through the point crosses both. Touching is
 *   not crossing: a segment that starts or ends on the plane of T (s = 0) does not
 *   cross it, so a vertex lying on an obstacle leaves it to either side.
 *   The segment meets the plane at t = s(p) / (s(p) - s(q)); the vertex stops at
 *   perpendicular distance g before it: f = max(0, t - g |n| / |s(p) - s(q)|),
 *   since s(p + f w) = s(p) (1 - f / t) and |s(p) - s(q)| t / |n| is p's distance to
 *   the plane. The minimum over the crossed triangles is the first crossing.
 * - Clearance (c > 0, for a vertex whose rest position is at least c from every
 *   triangle). The segment may not come closer than c to any triangle: with r = c + g,
 *   f = max(0, tau) where tau is the first s in [0, 1] with dist(p + s w, T) <= r,
 *   so the vertex stops at distance r >= c. The r-neighbourhood of T is the union of
 *   the slab |n.(x - a)| / |n| <= r over T (entered through its faces, when the entry
 *   point projects into the closed triangle), the three cylinders of radius r around
 *   the edges (entry: the smaller root of |m + s w_perp|^2 = r^2 with m, w_perp the
 *   parts of p - u, w across the edge, when the point projects onto the edge) and the
 *   three balls of radius r at the vertices (the smaller root of |p - u + s w|^2 = r^2);
 *   each piece is convex and the slab's side walls and the cylinders' caps lie in the
 *   cylinders and balls, so tau is the smallest of these entries (0 when p is within r
 *   already). Crossing T needs passing at distance 0 < c, so the crossing rule holds.
 *   A vertex that starts closer than c keeps only the crossing rule.
 * - Sliding (slide(), for a vertex on an obstacle, flagged by the caller). Its target
 *   p + w is replaced by the obstacle point nearest to it, P(p + w): the vertex stays on
 *   the obstacle surface while it moves along it. Its straight path p -> P(p + s w) obeys
 *   the crossing rule with "on the plane" widened to within g of it (both ends lie on
 *   the surface, where the sign of s is rounding); s = 1 when it does, else the last clear
 *   s of a bisection to 2^-40 from s = 0 (clear: nothing is nearer p than P(p)) and 1.
 *
 * g = 1e-9 times the diagonal of the obstacles' bounding box: far above the rounding of
 * the positions (1e-16 of their magnitude), so a stopped vertex lies strictly on its
 * side of the plane and, once an edit makes it the rest position, cannot cross later.
 *
 * Cost: set() builds the tree in O(T log T) for T triangles; a query visits the nodes
 * whose box (grown by r) the segment meets, O(log T) for a segment short against the
 * obstacle, plus the exact tests of the triangles in those leaves.
 */
class Obstacles
{
public:
  // n points (xyz triples, any frame) and `triangles` vertex index triples into them; the
  // triangles are stored relative to `origin` (the deformer's local origin). Points with
  // equal coordinates are merged first, so sheets given separately that touch at a
  // point or along an edge share its vertices and the edge rule above joins them.
  // Returns "" or why the set is refused (a non-finite point, an index outside [0, n),
  // no triangle); a refused set is empty.
  std::string set(const double* xyz, std::size_t n, const std::int64_t* triangles,
    std::size_t num_triangles, const Eigen::Vector3d& origin);
  bool empty() const { return tri_.empty(); }
  std::size_t size() const { return tri_.size(); }

  // The rule above, for a vertex at rest at p (local) displaced by w, with the clearance
  // c >= 0 (scene units).
  double admissible_fraction(
    const Eigen::Vector3d& p, const Eigen::Vector3d& w, double clearance = 0.0) const;
  // The sliding rule above: the displacement of a vertex at rest at p (local) sliding
  // toward p + w, and in `fraction` the s it reached (1: all of w).
  Eigen::Vector3d slide(const Eigen::Vector3d& p, const Eigen::Vector3d& w, double& fraction) const;
  // Distance from p (local) to the nearest triangle (infinite when empty); the nearest
  // point in `closest` when given.
  double distance(const Eigen::Vector3d& p, Eigen::Vector3d* closest = nullptr) const;

  std::size_t memory_bytes() const;

private:
  struct Node
  {
    Eigen::Vector3d lo, hi;
    std::int32_t left = -1, right = -1; // children; -1 for a leaf
    std::uint32_t first = 0, count = 0; // leaf: order_[first, first + count)
  };
  std::int32_t build(std::uint32_t first, std::uint32_t count);
  // `touch`: the distance to a plane within which an end counts as on it (0: exactly).
  double first_crossing(
    const Eigen::Vector3d& p, const Eigen::Vector3d& w, double touch = 0.0) const;
  double first_contact(const Eigen::Vector3d& p, const Eigen::Vector3d& w, double r) const;
  template<class Visit>
  void visit_segment(
    const Eigen::Vector3d& p, const Eigen::Vector3d& w, double r, double& best, Visit visit) const;

  std::vector<Eigen::Vector3d> points_;          // local
  std::vector<std::array<std::int64_t, 3>> tri_; // vertex indices
  std::vector<std::uint32_t> order_;             // triangles in tree order
  std::vector<Node> nodes_;
  double gap_ = 0.0;
};

} // namespace geoshaping
