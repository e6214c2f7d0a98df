#pragma once
// Projection of a configuration onto the set satisfying every ChainMail link: the
// reference of E_ref and the optional refinement pass (DESIGN.md section 6).
#include "geoshaping/error_metrics.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace geoshaping
{

// The feasible set F: every directed edge (c, s) keeps c in its valid region w.r.t. s
// with c's own params, the grasp g at its given displacement and pinned vertices at
// rest. In displacements u = x - x0 both directions of an edge are one slab per axis
// on the difference u_c - u_s (valid_region.h, o = x0_c - x0_s):
//
//   [lo, hi] = [lo_cs, hi_cs] ∩ [-hi_sc, -lo_sc],
//   (lo_cs, hi_cs) = displacement_bounds(o, p_c),  (lo_sc, hi_sc) = displacement_bounds(-o, p_s)
//
// which always contains 0 (k <= 1 <= t, h >= 0), so rest is feasible apart from the
// grasp. F is convex, and the point of F nearest a start z (least total squared movement
// sum_v |u_v - z_v|^2) is found by Dykstra's alternating projection onto the slabs
// (Hildreth's method): per link and axis a correction mu, and in each Gauss-Seidel
// sweep, with ia, ib the inverse weights of the ends (0 for a fixed end):
//
//   r = (u_a - u_b) + mu (ia + ib);  g = (r - clamp(r, lo, hi)) / (ia + ib)
//   u_a += ia (mu - g);  u_b -= ib (mu - g);  mu = g
//
// A rigid vertex (t = k = 1, h = 0) makes every one of its links an equality (its slab
// is the point 0), and so does a zero-length edge. F therefore lies in the subspace V
// where the free vertices joined by equality edges share one displacement: a rigid
// region moves with its one-ring. The projection first averages the start over each
// such set (the exact projection onto V, which changes nothing in the nearest point of
// F), then treats the set as one variable of weight = its size. Rigid regions thus
// translate as one from the first sweep on (E_rigid = 0, FIFO ripples removed), and the
// slow diffusion of equalities through alternating projections is avoided. Grasped and
// pinned vertices stay their own fixed variables; their equality links pull the
// neighbouring set onto them in one step.
//
// Only the region reached by the start is swept: the vertices displaced in the start,
// their links, and a neighbour's links once that neighbour moves (the region grows by
// one ring at a time), so the cost follows the displaced region, never the mesh.
//
// Stopping rule: after each sweep, stop when both
//   violation = E_link over the swept links with a free end: max over both directions of
//               the distance to the valid region (link_distance), and
//   update    = the largest change of a coordinate during the sweep
// are <= tolerance * L (L the mean edge length), or after max_iterations sweeps.
// Alternating projections do not decrease the violation monotonically, so the result is
// the iterate of least violation among the sweeps run (the last one when converged):
// more iterations never return a larger E_link. A link between two fixed vertices cannot
// change and is not counted; when the fixed vertices make F empty the violation stalls,
// the cap ends the run and `converged` is false (the corrections grow with the
// iterations but stay finite).
struct ProjectionOptions
{
  int max_iterations = 1000000;
  double tolerance = 1e-9; // relative to the mean edge length
  // Asked after every sweep; true ends the run as the cap does (e.g. a user's abort).
  std::function<bool()> stop;
};

struct ProjectionReport
{
  int iterations = 0;     // sweeps run
  double violation = 0.0; // E_link of the result (0 when no sweep ran)
  double update = 0.0;    // largest coordinate change in the sweep that gave the result, / L
  bool converged = false;
  std::size_t region = 0; // vertices with a variable (the displaced region + one ring)
  std::size_t links = 0;  // links swept
};

// Holds O(n) scratch allocated once; each call costs time and memory proportional to
// the region it sweeps and resets only what the previous call touched.
class LinkProjector
{
public:
  explicit LinkProjector(const LinkMesh& mesh); // `mesh` must outlive the projector

  // Projects the start configuration given sparsely (`vertices` with their `values`,
  // every other vertex at rest) with `grasp` and the mesh's pinned vertices fixed.
  // 0 sweeps leave the start exactly as given.
  ProjectionReport project(index_t grasp, const std::vector<index_t>& vertices,
    const Displacements& values, const ProjectionOptions& options);

  // The result for every vertex (dense; at rest outside region()).
  const Displacements& displacements() const { return u_; }
  const Eigen::Vector3d& displacement(index_t v) const { return u_[std::size_t(v)]; }
  // Every vertex the last call touched (a superset of the start and of changed()).
  const std::vector<index_t>& region() const { return region_; }
  // Vertices whose result differs from the start: what a caller mirroring the start
  // must rewrite. Fixed vertices never appear: they are left bit-identical.
  const std::vector<index_t>& changed() const { return changed_; }

private:
  struct Variable
  {
    Eigen::Vector3d value;
    double inverse_weight; // 1 / members; 0 when fixed
    index_t vertex;        // the vertex of a singleton, -1 for a rigid set
  };
  struct Link
  {
    index_t a, b; // variables; the constraint is lo <= value_a - value_b <= hi
    index_t c, s; // the edge's vertices, a's and b's
    Eigen::Vector3d lo, hi, mu;
  };

  void clear();
  bool is_fixed(index_t v) const;
  bool is_equality(index_t v, index_t n) const;
  bool joins_free_neighbour(index_t v) const;
  index_t variable_for(index_t v);
  index_t make_equal_set(index_t seed);
  void expand(index_t v);
  double relax(std::size_t k);
  double sweep();
  double max_violation() const;
  void keep_best();

  const LinkMesh& mesh_;
  index_t grasp_ = -1;
  Displacements u_;                    // dense
  std::vector<index_t> var_of_;        // -1 outside the region
  std::vector<std::uint8_t> expanded_; // links to every neighbour added
  std::vector<index_t> region_, changed_, queue_;
  std::vector<Variable> vars_;
  Displacements best_; // per variable: the iterate with the least violation so far
  std::vector<Link> links_;
};

// The refinement pass: `iterations` sweeps starting from the deformer's last frame
// (its moved vertices and their displacements), grasp and pins fixed. Stops earlier
// once converged with the default tolerance, or when `stop` (if given) returns true.
// Read the result from the projector; write back projector.changed() (plus the frame's
// moved vertices).
ProjectionReport refine_links(LinkProjector& projector, const ChainMailDeformer& deformer,
  index_t grasp, int iterations, std::function<bool()> stop = {});

// The reference configuration of E_ref: the point of F nearest `start` (dense, e.g. the
// ChainMail result, or rest with the grasp at its displacement), run to convergence.
Displacements reference_configuration(const LinkMesh& mesh, index_t grasp,
  const Displacements& start, ProjectionReport* report = nullptr,
  const ProjectionOptions& options = {});

} // namespace geoshaping
