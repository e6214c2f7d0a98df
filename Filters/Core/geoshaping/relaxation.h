#pragma once
// Relaxation of a ChainMail result: constrained Laplacian fairing of the displaced soft
// region (issue 15, "smooth results as an option"; docs/deformer.md, "Relaxation").
#include "geoshaping/error_metrics.h"

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
// relief is kept) by Gauss-Seidel sweeps of the Dirichlet energy
//
//   E_D(u) = sum over edges (a, b) of |u_a - u_b|^2,
//
// minimised over the free vertices F = the start's displaced vertices that are neither
// the grasp, nor pinned, nor rigid (malleability 0, or params t = k = 1, h = 0), each kept
// inside its valid regions. Every other vertex is fixed: grasp, pins and rigid regions
// stay bit for bit as given, vertices outside the start stay at rest, so the relaxed
// region never grows beyond the displaced one.
//
// Update of a free vertex v with neighbours N(v) (all of them, fixed or free, at their
// current values): E_D restricted to u_v is |N(v)| |u_v - m|^2 + const with the umbrella
// target m = mean_{n in N(v)} u_n, an isotropic quadratic, so its minimiser over a convex
// set C is the Euclidean projection of m onto C. C is where the links of v stay as good
// as the rule below asks. For each neighbour n there are two directed links (v w.r.t. n
// with v's params, n w.r.t. v with n's params, valid_region.h), each with its distance
// d to its region (link_distance). The rule, with B = the largest d over the links of F
// in the start (E_link of the start, in mesh units):
//
//   a link with d = 0 (satisfied) must keep d = 0;
//   a violated link may take any d <= max(its d, B).
//
// So every link ChainMail satisfied stays satisfied and E_link never grows, while the
// links ChainMail left violated (it guarantees only the sponsor links) do not freeze the
// vertices at their ends. Per frame of the valid region:
//
// - Axes: a satisfied direction is a slab per axis on w = u_v - u_n; their intersection is
//   a box in u_v containing the current u_v, and q = clamp(m, box) is the exact
//   minimiser over it (the violated links are left to the check).
// - Link: the cylinders of different links intersect in no closed form; q = m.
//
// Acceptance, the projection back ("after each smoothing step the links are checked",
// with link_distance itself, so rounding cannot break the rule): q is taken if every link
// of v obeys the rule, otherwise q is halved toward the current u_v (at most 30 times)
// and the current value is kept if no halving passes. Each link's distance is convex in
// u_v and the current point passes, so the accepted points of the segment form an
// interval from the current point, along which E_D decreases (convex, least at q). Hence
// after every single update: the rule holds for every link of the mesh, and E_D never
// grows (equality only when v does not move).
//
// Why the result stays faceted in places: ChainMail leaves each vertex on the border of
// its sponsor's region, so a convex ridge at the steepest allowed slope cannot be lowered
// without breaking a satisfied link; the relaxation rounds the concave creases and the
// violated (rigid/soft) borders, and lowers E_D, but keeps what the satisfied links pin.
//
// A sweep visits F in the order of the start list (for a ChainMail frame: the order of
// moving, outward from the grasp). The run stops after `iterations` sweeps, when the
// largest coordinate change of a sweep is <= tolerance * L (L the mean edge length), or
// when `stop` returns true (asked after every sweep). Repeated sweeps converge toward
// the constrained harmonic field: the least-E_D shape inside the valid regions with the
// grasp, pins, rigid parts and the border of the displaced region fixed.
//
// Tetrahedral meshes are relaxed the same way (the edge graph Laplacian).
//
// Cost: per sweep O(sum of the degrees of F), at most 31 link checks per edge; memory
// O(n) scratch allocated once by the constructor, each call resets only what the
// previous one touched. Never O(mesh) per call.
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
  std::size_t free = 0;        // |F|
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
  double budget_ = 0.0; // the start's largest link distance over the free vertices' links
};

// The relaxation after a deformer's frame (its moved vertices and their displacements).
RelaxationReport relax_frame(Relaxer& relaxer, const ChainMailDeformer& deformer, index_t grasp,
  int iterations, std::function<bool()> stop = {});

} // namespace geoshaping
