#pragma once
// Relaxation of a ChainMail result: constrained Laplacian fairing of the displaced soft
// region ("smooth results as an option"; docs/deformer.md, "Relaxation").
#include "geoshaping/metrics/error_metrics.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace geoshaping
{

class ChainMailDeformer;

// ChainMail moves each vertex to the nearest point of one valid region, so on a triangle
// grid the result is faceted (ridges, saw-tooth "teeth" along diagonals). The relaxation
// smooths the displacement field u = x - x0 (not the positions: the rest shape's own
// relief is kept) by Gauss-Seidel sweeps, over-relaxed, of the energy
//
//   E(u) = sum over edges (a, b) of |u_a - u_b|^2  +  alpha sum over v in F of |u_v|^2
//
// (the Dirichlet energy E_D plus a weak tether to rest, alpha = rest_tether), minimised
// over the free vertices F, each kept inside its valid regions. Every other vertex is
// fixed: grasp, pins and rigid vertices (malleability 0, or params t = k = 1, h = 0) stay
// bit for bit as given. F starts as the start's displaced vertices that are none of
// those, and grows by one ring per sweep: after a sweep, the resting neighbours (again
// neither grasp, pinned nor rigid) of every vertex of F that moved more than
// growth_threshold * L in it join F. Why grow: ChainMail leaves every vertex on the
// border of its sponsor's region, so its facets are at the steepest slope the links
// allow and meet the rest at a staircase along the diagonals (the "teeth"). Lowering a
// facet would break a satisfied link (below); what rounds the shape is the rest beyond
// the border rising toward its neighbours, ring after ring, which then lets the facets
// above it leave their steepest slope. Why the tether: without it nothing holds the
// grown region, and the least-E_D shape is the whole soft sheet translated with the
// grasp; with it the relaxed displacement decays away from the grasp over about
// sqrt(degree / alpha) edges (~17 on a triangle grid), and growth stops where it falls
// below the threshold.
//
// Update of a free vertex v with neighbours N(v) (all of them, fixed or free, at their
// current values): E restricted to u_v is (|N(v)| + alpha) |u_v - m|^2 + const with
// m = sum_{n in N(v)} u_n / (|N(v)| + alpha), an isotropic quadratic, so its minimiser
// over a convex set C is the Euclidean projection q of m onto C. C is where the links of
// v stay as good as the rule below asks. For each neighbour n there are two directed
// links (v w.r.t. n with v's params, n w.r.t. v with n's params, valid_region.h), each
// with its distance d to its region (link_distance). The rule, with B = the largest d
// over the links of the initial F in the start (E_link of the start, in mesh units):
//
//   a link with d = 0 (satisfied) must keep d = 0;
//   a violated link may take any d <= max(its d, B).
//
// So every link ChainMail satisfied stays satisfied and E_link never grows, while the
// links ChainMail left violated (it guarantees only the sponsor links) do not freeze the
// vertices at their ends. Per valid-region shape:
//
// - Axes: a satisfied direction is a slab per axis on w = u_v - u_n; their intersection is
//   a box in u_v containing the current u_v, and q = clamp(m, box) is the exact
//   minimiser over it (the violated links are left to the check).
// - Link: the cylinders of different links intersect in no closed form; q = m.
//
// Acceptance, the projection back ("after each smoothing step the links are checked",
// with link_distance itself, so rounding cannot break the rule): the update tries
// u_v = c + t (q - c), c the current value, for t = omega (over_relaxation), then 1,
// 1/2, 1/4, ... (30 halvings), and takes the first that obeys the rule for every link of
// v; none passing keeps c. Each link's distance is convex in u_v and c passes, so the
// passing t form an interval from 0. Along the ray E is a parabola least at
// t* = (m - c).(q - c) / |q - c|^2 >= 1 (q is the projection of m onto a convex set
// holding c), so E(t) < E(0) for 0 < t < 2 t*, which holds every t tried (omega < 2).
// Hence after every single update: the rule holds for every link of the mesh, and E
// never grows (equality only when v does not move).
//
// A sweep visits F in the order of the start list (for a ChainMail frame: the order of
// moving, outward from the grasp). The run stops after `iterations` sweeps, when the
// largest coordinate change of a sweep is <= tolerance * L (L the mean edge length), or
// when `stop` returns true (asked after every sweep). Repeated sweeps converge toward
// the least-E shape inside the valid regions with the grasp, pins and rigid parts fixed.
//
// Tetrahedral meshes are relaxed the same way (the edge graph Laplacian).
//
// Cost: per sweep O(sum of the degrees of F), at most 31 link checks per edge, with F at
// most the displaced region grown by one ring per sweep so far; memory O(n) scratch
// allocated once by the constructor, each call resets only what the previous one
// touched. Never O(mesh) per call (unless the sweeps reach the whole mesh).

// A free vertex that moves more than this (times L) in a sweep brings its resting
// neighbours into F for the next sweep.
constexpr double growth_threshold = 1e-3;
// The over-relaxation factor omega of each update (successive over-relaxation; 1.9
// reached the smoothest Figure 5D in 100 sweeps of 1.5, 1.7, 1.9).
constexpr double over_relaxation = 1.9;
// The weight alpha of the tether to rest (relative to the unit weight of an edge).
constexpr double rest_tether = 0.02;

struct RelaxationOptions
{
  int iterations = 0;      // sweeps; 0 leaves the start exactly as given
  double tolerance = 1e-9; // relative to the mean edge length
  std::function<bool()> stop;
};

struct RelaxationReport
{
  int iterations = 0;          // sweeps run
  double update = 0.0;         // largest coordinate change in the last sweep, / L
  std::size_t free = 0;        // |F| at the end (it grows ring by ring)
  std::size_t updates = 0;     // vertex updates (|F| per sweep): the work done
  std::size_t rejected = 0;    // updates where no halving passed (the vertex stayed)
  std::size_t link_checks = 0; // link_distance evaluations
};

class Relaxer
{
public:
  explicit Relaxer(const LinkMesh& mesh); // `mesh` must outlive the relaxer

  // Relaxes the start configuration given sparsely (`vertices` with their `values`,
  // parallel arrays, every other vertex at rest) with `grasp` fixed.
  RelaxationReport relax(index_t grasp, const std::vector<index_t>& vertices,
    const Displacements& values, const RelaxationOptions& options);

  // The result for every vertex (dense; the start outside the free set).
  const Displacements& displacements() const { return u_; }
  const Eigen::Vector3d& displacement(index_t v) const { return u_[std::size_t(v)]; }
  // The free vertices whose result differs from the start (a subset of the start list):
  // what a caller mirroring the start must rewrite.
  const std::vector<index_t>& changed() const { return changed_; }
  // A caller's correction of the result at v, one of changed() (the obstacle gate of
  // FramePasses); v stays in changed().
  void correct(index_t v, const Eigen::Vector3d& u) { u_[std::size_t(v)] = u; }

private:
  bool update(index_t v, RelaxationReport& report);
  void clear();
  // A link's distance may not grow beyond this: 0 when satisfied, else the budget.
  double allowed(double before) const { return before == 0.0 ? 0.0 : std::max(before, budget_); }

  const LinkMesh& mesh_;
  Displacements u_;                   // dense
  std::vector<index_t> touched_;      // vertices with a value set by the last call
  std::vector<index_t> free_;         // F, in sweep order
  std::vector<std::uint8_t> is_free_; // dense: 1 on F
  Displacements start_;               // per free vertex: its start value
  std::vector<double> before_;        // scratch: link distances before an update
  std::vector<index_t> changed_;
  std::vector<index_t> frontier_; // scratch: free vertices that moved more than growth
  double budget_ = 0.0;           // the start's largest link distance over the free vertices' links
};

// The relaxation after a deformer's frame (its moved vertices and their displacements).
RelaxationReport relax_frame(Relaxer& relaxer, const ChainMailDeformer& deformer, index_t grasp,
  int iterations, std::function<bool()> stop = {});

} // namespace geoshaping
