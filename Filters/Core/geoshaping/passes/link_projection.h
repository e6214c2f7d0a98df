#pragma once
// Projection of a configuration onto the set satisfying every ChainMail link: the
// reference of E_ref and the optional refinement pass (docs/design.md, Error against run time).
#include "geoshaping/metrics/error_metrics.h"
#include "geoshaping/passes/envelope_axis.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
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
// grasp. With the Link region (LinkMesh::frame, valid_region.h) c's cylinder around o and
// s's cylinder around -o (on -w) share the axis e = o / |o|, so both directions are one
// cylinder on w: along e [max(k_c, k_s) - 1, min(t_c, t_s) - 1] |o|, radius
// min(h_c, h_s) |o|, projected onto in closed form; everything below holds for either
// shape (the per-axis clamp is the box's projection). F is convex, and the point of F nearest a
// start z (least total squared movement sum_v |u_v - z_v|^2) is found by Dykstra's alternating
// projection onto the slabs (Hildreth's method): per link and axis a correction mu, and in each
// Gauss-Seidel sweep, with ia, ib the inverse weights of the ends (0 for a fixed end):
//
//   r = (u_a - u_b) + mu (ia + ib);  g = (r - P(r)) / (ia + ib)   (P: clamp, or cylinder)
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
// Neither solver decreases the violation monotonically, so the result is the iterate of
// least violation among the start (averaged over the rigid sets) and the iterations run
// (the last one when converged): more iterations never return a larger E_link. A link between two
// fixed vertices cannot change and is not counted; when the fixed vertices make F empty the
// violation stalls, the cap ends the run and `converged` is false (the corrections grow with the
// iterations but stay finite).
// Which algorithm projects (docs/error-metrics.md, "The refinement pass"):
// - admm (default): the alternating direction method of multipliers with one sparse
//   Cholesky factorisation of the region's link-graph Laplacian (below): converges where
//   Dykstra stalls (a large rigid set moved by its links).
// - dykstra: the Gauss-Seidel Dykstra/Hildreth sweeps above. One sweep is cheaper than
//   one ADMM iteration and needs no factorisation, so a handful of sweeps is a cheap way
//   to take the worst links down.
// - envelope: not the nearest point but a feasible one, exactly and in one pass (below);
//   the Axes region only (with the Link region it runs Dykstra). The filter's refinement
//   uses it by default (vtkChainMailDeformationFilter::RefinementSolver).
enum class ProjectionSolver
{
  admm = 0,
  dykstra = 1,
  envelope = 2
};
// "ADMM", "Dykstra", "Envelope" (the plugin's RefinementSolver entries).
const char* solver_name(ProjectionSolver solver);

// Envelope (Axes region). Per axis i every link is a difference constraint
//   lo_ab <= u_a - u_b <= hi_ab   (lo <= 0 <= hi, both directions intersected, above),
// i.e. u_a <= u_b + hi_ab and u_b <= u_a - lo_ab: an edge-weighted directed graph with
// weights >= 0 (no negative cycle, so F restricted to an axis is never empty without
// fixed vertices). Such a set is a lattice: the componentwise min and max of two
// feasible configurations are feasible. With fixed vertices f (grasp, pins) at values
// v_f, the greatest feasible configuration below a start z is
//
//   z'   = max(z, max_f (v_f - d(a, f)))      (the lower cones of the fixed vertices)
//   D(a) = min_b (z'_b + d(b, a))             (min-plus: b over every vertex)
//
// with d(b, a) the shortest path from b to a under the weights w(b -> a) = hi_ab. D
// satisfies every constraint (the triangle inequality of d), D <= z', and D(f) = v_f
// when the fixed values are consistent (v_f - v_g <= d(g, f) for every pair; always
// with the grasp alone). The least feasible configuration above z, U, is the same on -z.
// The result is (D + U) / 2 per axis: feasible (F is convex), symmetric in the
// direction of the pull, equal to z wherever z already satisfies its links around,
// exact on fixed vertices (v + v) / 2 = v, and rigid sets (w = 0 both ways) get one
// value bit for bit. Both are label-correcting Dijkstra runs seeded only by the vertices
// with a violated link (or by the fixed vertices for the cones): a vertex's value
// changes only when a neighbour forces it, so the cost is O(r) for the r vertices that
// change and their neighbours (a radix heap on the labels' 28 leading bits: Dijkstra pops
// labels in increasing order, so each entry only moves down its buckets), never O(mesh).
// The order of the relaxations does not change the result, bit for bit: a pass ends at
// the greatest y <= its start with y_a <= fl(y_b + ub(a, b)) for every link out of a seed
// or a lowered vertex b (by induction over the assignments, any order's labels stay
// above every such y, and the end state is one), so Dijkstra's order is only a matter
// of speed (a FIFO order pops more vertices: docs/error-metrics.md, "Where the
// envelope's time goes").
// Each link's slab on each axis that runs is computed once, when a pass first reaches the
// link's vertex (axis_slab, cached per vertex in flat arrays and kept across calls: the
// mesh is constant for the projector's life). The cache holds only the axes its calls
// ran (a pull along z fills a third); a call on another axis, or a cache past 8x the
// start + 65,536 vertices, drops it, so its memory stays O(displaced). The dense scratch
// (labels as values of u, cone labels, link ranges, D, marks: 33 bytes per mesh vertex)
// is allocated by the first call and reset sparsely after each run and call. The D run's
// check of the links its cone's raise broke (by rounding only) reads only the vertices
// the cone flags at their last pop (envelope_cone).
// It is not the projection (E_ref measures how far it lies from it, docs/report.md); with
// inconsistent fixed values (F empty) the conflicting links stay violated and
// `converged` is false.
// At the paper's scale the envelope reaches E_link 0 where Dykstra and ADMM stall, their
// grown region being smaller than the feasible configurations' support; figures and cost
// in docs/error-metrics.md ("Where the envelope's time goes") and docs/benchmarks.md
// ("The envelope refinement").
// A Link-region envelope: a difference constraint bounds u_a - u_b on one world axis, so
// the only inner approximations of a link's cylinder that keep the lattice are boxes
// aligned with the world axes (the largest cube around 0: half-side
// min(r / sqrt(3), min(along_hi, -along_lo) / |e|_1)); a box aligned with the link is
// not (its faces mix the axes). Such an envelope is feasible for the cylinders but
// depends on how each link sits against the world axes: not rotation invariant, which
// is what the Link region is for, and tighter than the cylinder. Not implemented.

// ADMM. With x the free variables (weights m: 1, or the size of a rigid set), z their
// start, and for link k the difference w_k = D_k x + c_k (c_k: the fixed end's value),
// the projection is  min_x 1/2 sum_i m_i |x_i - z_i|^2  subject to  w_k in C_k,  with
// C_k the link's feasible set (box with the Axes region, the intersection of both
// directions' cylinders with the Link region, which share the axis e = o / |o|:
// along-link [max(k_c, k_s) - 1, min(t_c, t_s) - 1] l, radius min(h_c, h_s) l). Splitting
// y_k = w_k with scaled multipliers lambda_k and over-relaxation alpha = 1.6, one
// iteration is
//
//   x      = (M + rho D^T D)^-1 (M z + rho D^T (y - lambda - c))   (3 right-hand sides)
//   w~     = alpha (D x + c) + (1 - alpha) y
//   y      = P_C(w~ + lambda)                                     (per link, closed form)
//   lambda = lambda + w~ - y
//
// M + rho D^T D is the weighted graph Laplacian of the region's links plus M: symmetric
// positive definite, factorised once (Eigen::SimplicialLDLT, AMD ordering) per region
// and reused by every iteration, and by the next call when the region is the same.
// x converges to the projection (the problem is strongly convex). The stopping rule is
// the one above with update = the largest change of x in the iteration. rho = 10
// sqrt(largest weight): a large rigid set needs a stiffer penalty (measurements beside
// the code).
// The region starts as the start vertices and their one-ring; when the result moves a
// ring vertex (whose own links are not in yet) so that one of those links is violated,
// its links are added (checked every 10 iterations), the factorisation is redone and the
// iterations go on from the current multipliers: the region grows only where the
// projection pushes, so the cost follows the displaced region.
// Cost per iteration O(nnz of the factor) ~ O(r log r) for a surface region of r
// vertices, plus one factorisation (~O(r^1.5)) per growth of the region.
// Measured (docs/report.md, docs/error-metrics.md): ADMM converges where Dykstra stalls
// (fault step: 1e-4 L in ~1,000 iterations against Dykstra's 0.05 L after 20,000 sweeps)
// but its tail is linear and slow: alone it does not reach 1e-6 L on every scene within
// the report's cap of 5,000 (reference_configuration's finish does, below; all eight report
// references converge), and an ADMM iteration costs several Dykstra sweeps, so ADMM computes
// the references and the filter refines with the envelope (Dykstra on request). Polishing
// (an exact solve on the guessed active set, as OSQP does) was tried and rejected: the
// guessed sets gave inconsistent or wrong-signed multipliers on the test and report scenes.
struct ProjectionOptions
{
  int max_iterations = 1000000;
  double tolerance = 1e-9; // relative to the mean edge length
  ProjectionSolver solver = ProjectionSolver::admm;
  double rho = 0.0;       // ADMM penalty; 0: 10 sqrt(the largest weight, a rigid set's size)
  double rho_scale = 1.0; // multiplies the penalty (reference_configuration's Link finish: 100)
  // reference_configuration only: when the solver stops unconverged, project its result
  // (see there).
  bool finish = true;
  // Asked after every sweep; true ends the run as the cap does (e.g. a user's abort).
  std::function<bool()> stop;
};

struct ProjectionReport
{
  int iterations = 0;     // sweeps run
  double violation = 0.0; // E_link of the result (0 when no sweep ran)
  double update = 0.0;    // largest coordinate change in the sweep that gave the result, / L
  bool converged = false;
  std::size_t region = 0;    // vertices with a variable (the displaced region + one ring)
  std::size_t links = 0;     // links swept
  int factorisations = 0;    // ADMM: sparse factorisations done (0 when one was reused)
  int finish_iterations = 0; // reference_configuration: iterations of the finish (0: none)
};

// Holds O(n) scratch allocated once; each call costs time and memory proportional to
// the region it sweeps and resets only what the previous call touched.
class LinkProjector
{
public:
  explicit LinkProjector(const LinkMesh& mesh); // `mesh` must outlive the projector
  ~LinkProjector();
  LinkProjector(const LinkProjector&) = delete;
  LinkProjector& operator=(const LinkProjector&) = delete;

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
  // A caller's correction of the result at v, one of changed() (the obstacle gate of
  // FramePasses); v stays in changed().
  void correct(index_t v, const Eigen::Vector3d& u) { u_[std::size_t(v)] = u; }

  // A result computed elsewhere taken as this call's (the partitioned envelope,
  // partitioned_envelope.h): `vertices` at `values`, every other vertex at rest;
  // region() = vertices, changed() = `changed` (a subset). O(vertices + the last region).
  void assign(const std::vector<index_t>& vertices, const Displacements& values,
    const std::vector<index_t>& changed);

private:
  struct Variable
  {
    Eigen::Vector3d value;
    double inverse_weight; // 1 / members; 0 when fixed
    index_t vertex;        // the vertex of a singleton, -1 for a rigid set
    Eigen::Vector3d start; // the value it was created with (z of the projection)
  };
  // The feasible set of a link on w = value_a - value_b: both directions' regions.
  struct Constraint
  {
    Eigen::Vector3d lo, hi; // Axes: the box
    Eigen::Vector3d e;      // Link: unit axis, along-link interval, radius
    double along_lo = 0.0, along_hi = 0.0, radius = 0.0;
    bool point = false; // the single point 0 (an equality)
  };
  struct Link
  {
    index_t a, b; // variables; the constraint is value_a - value_b in C
    index_t c, s; // the edge's vertices, a's and b's
    Constraint C;
    Eigen::Vector3d mu;        // Dykstra correction
    Eigen::Vector3d y, lambda; // ADMM split variable and scaled multiplier
  };

  void clear();
  bool is_fixed(index_t v) const;
  bool constraint(index_t c, index_t s, Constraint& C) const;
  Eigen::Vector3d project_onto(const Constraint& C, const Eigen::Vector3d& w) const;
  bool is_equality(index_t v, index_t n) const;
  bool joins_free_neighbour(index_t v) const;
  index_t variable_for(index_t v);
  index_t make_equal_set(index_t seed);
  void expand(index_t v);
  double relax(std::size_t k);
  double sweep();
  double directed(index_t c, index_t s, const Eigen::Vector3d& w) const;
  // The violation of link l at w = value_a - value_b: the worse of its two directions,
  // each against its own region; 0 for a link between two fixed variables.
  double violation(const Link& l, const Eigen::Vector3d& w) const;
  double max_violation() const;
  double pending_violation(double tol, std::vector<index_t>* grow);
  void keep_best();
  // Ends an iteration of either solver: counts it, decides convergence (violation and
  // update both <= tol), keeps the iterate of least violation; true when the run is over
  // (converged, or options.stop says so).
  bool finish_iteration(ProjectionReport& report, double violation, double update, double tol,
    const ProjectionOptions& options);
  void run_dykstra(const ProjectionOptions& options, ProjectionReport& report);
  void run_admm(const ProjectionOptions& options, ProjectionReport& report);
  void run_envelope(
    const std::vector<index_t>& start, const ProjectionOptions& options, ProjectionReport& report);
  // The whole mesh as EnvelopeAxis's Net (envelope_axis.h).
  struct EnvelopeNet;
  void envelope_min_pass(int axis, double sign, std::vector<index_t>& seeds);
  // Calls raise(a, c) for each vertex a with a cone label c, after the run.
  template<class Raise>
  void envelope_cone(int axis, double sign, const std::vector<index_t>& fixed, Raise raise);
  // The Dijkstra loop both share: pops the queue in increasing label, skips stale
  // entries (value != label(b)), and offers each free, non-grasped neighbour a of b the
  // label value(b) + ub(b, a) through relax(a, cap).
  // visit(b, value(b), b's links) is called at each current pop, before the relaxations.
  template<class Label, class Relax, class Visit>
  void envelope_dijkstra(int axis, double sign, Label label, Relax relax, Visit visit);
  double envelope_value(index_t v, int axis, double sign) const;
  void envelope_touch(index_t v, double value);
  struct LinkRange
  {
    std::int32_t first; // -1: not cached yet
    std::int32_t count;
  };
  LinkRange envelope_links(index_t v);
  LinkRange fill_links(index_t v);
  void fill_links_ahead(const std::vector<index_t>& list, std::size_t i);
  struct RadixEntry
  {
    std::uint64_t key; // radix_key(value): the label's leading bits, order-preserving
    double value;
    index_t vertex;
  };
  void envelope_push(double y, index_t v);
  RadixEntry envelope_pop();
  void envelope_reset_queue();
  bool factorise(double rho);

  const LinkMesh& mesh_;
  index_t grasp_ = -1;
  Displacements u_;                    // dense
  std::vector<index_t> var_of_;        // -1 outside the region
  std::vector<std::uint8_t> expanded_; // links to every neighbour added
  std::vector<index_t> region_, changed_, queue_;
  std::vector<Variable> vars_;
  Displacements best_; // per variable: the iterate with the least violation so far
  std::vector<Link> links_;
  double best_violation_ = 0.0;
  double best_update_ = 0.0;

  // Envelope scratch (dense, allocated on first use): the current run's label of every
  // vertex as a value of u on its axis (the start where the run has not set it: one load
  // per label), which vertices the run set and their list; the per-axis step (D per
  // vertex, the seeds).
  EnvelopeAxis env_axis_;
  std::vector<double> env_label_;
  std::vector<std::uint8_t> env_set_;
  std::vector<index_t> env_touched_;
  void envelope_begin_axis(int axis);
  void envelope_end_run(int axis);
  void envelope_end_call();
  std::vector<double> env_cone_; // the fixed vertices' cones (+infinity where none)
  std::vector<index_t> env_cone_touched_;
  std::vector<index_t> env_check_; // raised vertices whose links may be broken (envelope_cone)
  // The link cache of one call (envelope_links): per vertex reached its first slot (-1:
  // none yet) and slot count (dense, side by side: one load), and per slot the neighbour
  // (~id when it is pinned: no array of flags to load) and, per active axis, the slab
  // bounds the passes relax with.
  std::vector<LinkRange> env_links_;
  std::vector<index_t> env_cached_, env_nbr_;
  std::vector<double> env_up_[3], env_dn_[3];
  int env_axes_ = 0;       // bit i: axis i runs in this call
  int env_cache_axes_ = 0; // bit i: the link cache holds axis i's bounds
  bool env_cold_ = false;  // this call filled links of the start: the cone fills ahead
  // The passes' radix heap: 65 buckets, the last key popped, the entries queued.
  std::vector<RadixEntry> env_buckets_[65];
  std::uint64_t env_last_ = 0;
  std::size_t env_queued_count_ = 0;

  // ADMM: free variables' columns, the factorisation and what it was built for.
  struct Factor;
  std::unique_ptr<Factor> factor_;
};

// One axis of a link's feasible set (Axes region): lo <= u_c[axis] - u_s[axis] <= hi, both
// directions intersected, exactly the numbers the envelope uses; false when the rest
// offset is not finite (no constraint). For the partitioned envelope.
bool link_axis_slab(const LinkMesh& mesh, index_t c, index_t s, int axis, double& lo, double& hi);

// The refinement pass: at most `options.max_iterations` iterations (RefinementIterations)
// starting from the deformer's last frame (its moved vertices and their displacements),
// grasp and pins fixed; stops earlier once converged to `options.tolerance`
// (RefinementTolerance), or when `options.stop` (if given) returns true. Read the result
// from the projector; write back projector.changed() (plus the frame's moved vertices).
ProjectionReport refine_links(LinkProjector& projector, const ChainMailDeformer& deformer,
  index_t grasp, const ProjectionOptions& options);
// The same with the default tolerance and solver.
ProjectionReport refine_links(LinkProjector& projector, const ChainMailDeformer& deformer,
  index_t grasp, int iterations, std::function<bool()> stop = {});

// The reference configuration of E_ref: the point of F nearest `start` (dense, e.g. the
// ChainMail result, or rest with the grasp at its displacement), run to convergence.
// ADMM's tail is linear and slow (the fault step stops at 2e-6 L Axes, 2e-5 L Link after
// 5,000 iterations; residual balancing of rho, Boyd et al. 3.4.1, was measured worse:
// 0.013 L in 5,000 on the same scene, so rho stays fixed). When the cap ends the run
// unconverged and options.finish is set, the result x (within the solver's residual of the
// projection P(z), links violated by about that much) is itself projected: the envelope in
// the Axes region (exactly feasible, one pass); with the Link region ADMM again from x with
// rho_scale 100 (up to max_iterations; a stiff penalty from a nearly feasible start takes
// the violation down fast: equal malleability, Link, 1.26e-5 L after 5,000 iterations at
// the default rho, then 4e-7 L after 90 at 100x, where the earlier finish, 20,000 Dykstra
// sweeps, stopped at 1.66e-6 L), then Dykstra (up to 4 max_iterations sweeps) only if
// that is capped too. Why the default rho is slow there: with most links on their
// cylinder's surface the primal residual falls slowly at rho 10 (5,000 iterations:
// rho 3 2.4e-4 L, 10 1.3e-5 L, 30 4e-6 L; rho 100 converges in 4,197, 300 in 3,666), while
// the stiffer rho were slower on the rigid-set scenes it was chosen on. The returned point
// is then feasible to the tolerance and |result - P(z)| <= |result - x| + |x - P(z)|: the
// finish's own move (about the residual it removed) plus ADMM's distance to P(z);
// report->converged says whether E_link reached the tolerance, report->finish_iterations
// what it took (ADMM iterations plus Dykstra sweeps).
Displacements reference_configuration(const LinkMesh& mesh, index_t grasp,
  const Displacements& start, ProjectionReport* report = nullptr,
  const ProjectionOptions& options = {});

} // namespace geoshaping
