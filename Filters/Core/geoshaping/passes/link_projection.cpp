#include "geoshaping/passes/link_projection.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"
#include "geoshaping/mesh/enum_names.h"
#include "geoshaping/mesh/prefetch.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace geoshaping
{

namespace
{
// Both directions of the edge (c, s) as one slab on u_c - u_s; false when the rest
// offset is not finite (no constraint, as in the deformer).
bool link_slab(const LinkMesh& m, index_t c, index_t s, Eigen::Vector3d& lo, Eigen::Vector3d& hi)
{
  const Eigen::Vector3d o = m.rest[std::size_t(c)] - m.rest[std::size_t(s)];
  if (!o.allFinite())
    return false;
  const Box cs = displacement_bounds(o, m.params[std::size_t(c)]);
  const Box sc = displacement_bounds(-o, m.params[std::size_t(s)]);
  lo = cs.lo.cwiseMax(-sc.hi);
  hi = cs.hi.cwiseMin(-sc.lo);
  return true;
}

// link_slab on one axis only (the envelope works axis by axis): the same numbers as
// displacement_bounds, a third of the work. `o` is rest_c - rest_s, finite.
inline void axis_slab(const Eigen::Vector3d& o, const ChainMailParams& pc,
  const ChainMailParams& ps, int i, double& lo, double& hi)
{
  const Eigen::Vector3d a = o.cwiseAbs();
  const double side = a.sum() - a[i]; // S_i = sum_{j != i} |o_j|
  // c w.r.t. s on o, and s w.r.t. c on -o (negated), as in displacement_bounds.
  const double oi = o[i];
  const double c_near = (pc.compression - 1.0) * oi, c_far = (pc.stretch - 1.0) * oi;
  const double s_near = (ps.compression - 1.0) * -oi, s_far = (ps.stretch - 1.0) * -oi;
  const double c_lo = (oi >= 0.0 ? c_near : c_far) - pc.shear * side;
  const double c_hi = (oi >= 0.0 ? c_far : c_near) + pc.shear * side;
  const double s_lo = (-oi >= 0.0 ? s_near : s_far) - ps.shear * side;
  const double s_hi = (-oi >= 0.0 ? s_far : s_near) + ps.shear * side;
  lo = std::max(c_lo, -s_hi);
  hi = std::min(c_hi, -s_lo);
}

bool axis_slab(const LinkMesh& m, index_t c, index_t s, int i, double& lo, double& hi)
{
  const Eigen::Vector3d o = m.rest[std::size_t(c)] - m.rest[std::size_t(s)];
  if (!o.allFinite())
    return false;
  axis_slab(o, m.params[std::size_t(c)], m.params[std::size_t(s)], i, lo, hi);
  return true;
}
} // namespace

struct LinkProjector::Factor
{
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  std::vector<index_t> col;  // per variable: its column, -1 when fixed
  std::vector<index_t> free; // per column: its variable
  // What the factorisation was built for: a later call with the same region, sets and
  // links reuses it.
  index_t grasp = -1;
  double rho = 0.0;
  std::vector<index_t> region, var_of;
  std::vector<std::pair<index_t, index_t>> links;
  bool valid = false;
  Eigen::Matrix<double, Eigen::Dynamic, 3> rhs, x;
};

LinkProjector::LinkProjector(const LinkMesh& mesh)
  : mesh_(mesh)
  , u_(std::size_t(mesh.size()), Eigen::Vector3d::Zero())
  , var_of_(std::size_t(mesh.size()), -1)
  , expanded_(std::size_t(mesh.size()), 0)
  , factor_(std::make_unique<Factor>())
{
}

LinkProjector::~LinkProjector() = default;

// The feasible set of w = u_c - u_s for both directions of the edge; false when the rest
// offset is not finite (no constraint, as in the deformer).
bool LinkProjector::constraint(index_t c, index_t s, Constraint& C) const
{
  if (!link_slab(mesh_, c, s, C.lo, C.hi))
    return false;
  const Eigen::Vector3d o = mesh_.rest[std::size_t(c)] - mesh_.rest[std::size_t(s)];
  const ChainMailParams& pc = mesh_.params[std::size_t(c)];
  const ChainMailParams& ps = mesh_.params[std::size_t(s)];
  const double l = o.norm();
  if (mesh_.frame == ValidRegionFrame::link)
  {
    // Both cylinders have the axis of o (s's region is on -w around -o): intersect the
    // along-link intervals and take the smaller radius.
    C.e = l > 0.0 ? Eigen::Vector3d(o / l) : Eigen::Vector3d::Zero();
    C.along_lo = std::max(pc.compression, ps.compression) - 1.0;
    C.along_hi = std::min(pc.stretch, ps.stretch) - 1.0;
    C.radius = std::min(pc.shear, ps.shear) * l;
    C.along_lo *= l;
    C.along_hi *= l;
    const auto rigid = [](const ChainMailParams& p)
    { return p.stretch == 1.0 && p.compression == 1.0 && p.shear == 0.0; };
    C.point = l == 0.0 || rigid(pc) || rigid(ps) ||
              (C.along_lo == 0.0 && C.along_hi == 0.0 && C.radius == 0.0);
  }
  else
    C.point = C.lo.isZero(0.0) && C.hi.isZero(0.0);
  return true;
}

// The nearest point of C to w: per-axis clamp (Axes), or the cylinder's closed form
// (valid_region.h) with the intersected bounds (Link).
Eigen::Vector3d LinkProjector::project_onto(const Constraint& C, const Eigen::Vector3d& w) const
{
  if (C.point)
    return Eigen::Vector3d::Zero();
  if (mesh_.frame != ValidRegionFrame::link)
    return w.cwiseMax(C.lo).cwiseMin(C.hi);
  const double a = w.dot(C.e);
  const Eigen::Vector3d p = w - a * C.e;
  const double r = p.norm();
  const double a_in = std::min(std::max(a, C.along_lo), C.along_hi);
  const double shrink = r > C.radius ? C.radius / r : 1.0;
  if (a_in == a && shrink == 1.0)
    return w;
  return a_in * C.e + shrink * p;
}

void LinkProjector::clear()
{
  for (index_t v : region_)
  {
    u_[v].setZero();
    var_of_[v] = -1;
    expanded_[v] = 0;
  }
  region_.clear();
  changed_.clear();
  vars_.clear();
  links_.clear();
}

inline bool LinkProjector::is_fixed(index_t v) const
{
  return v == grasp_ || mesh_.is_pinned(v);
}

// An edge whose feasible set is a single point: its ends must share one displacement (an
// end is rigid, or the edge has zero length).
bool LinkProjector::is_equality(index_t v, index_t n) const
{
  Constraint C;
  return constraint(v, n, C) && C.point;
}

bool LinkProjector::joins_free_neighbour(index_t v) const
{
  const Adjacency& adj = *mesh_.adjacency;
  for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
    if (!is_fixed(*n) && is_equality(v, *n))
      return true;
  return false;
}

index_t LinkProjector::variable_for(index_t v)
{
  if (var_of_[v] >= 0)
    return var_of_[v];
  if (!is_fixed(v) && joins_free_neighbour(v))
    return make_equal_set(v);
  const index_t id = index_t(vars_.size());
  vars_.push_back({ u_[v], is_fixed(v) ? 0.0 : 1.0, v, u_[v] });
  var_of_[v] = id;
  region_.push_back(v);
  return id;
}

// One variable for the free vertices joined to `seed` by equality edges, at the mean of
// their start (the projection onto V); all its members' links are added at once.
index_t LinkProjector::make_equal_set(index_t seed)
{
  const Adjacency& adj = *mesh_.adjacency;
  const index_t id = index_t(vars_.size());
  vars_.push_back({ Eigen::Vector3d::Zero(), 0.0, -1, Eigen::Vector3d::Zero() });
  queue_.assign(1, seed);
  var_of_[seed] = id;
  for (std::size_t q = 0; q < queue_.size(); ++q)
  {
    const index_t v = queue_[q];
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      if (var_of_[*n] < 0 && !is_fixed(*n) && is_equality(v, *n))
      {
        var_of_[*n] = id;
        queue_.push_back(*n);
      }
  }
  const std::vector<index_t> members(queue_);
  // A set that already moves as one keeps its value bit for bit.
  bool same = true;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (index_t v : members)
  {
    same = same && u_[v] == u_[seed];
    sum += u_[v];
  }
  vars_[id].value = same ? u_[seed] : Eigen::Vector3d(sum / double(members.size()));
  vars_[id].start = vars_[id].value;
  vars_[id].inverse_weight = 1.0 / double(members.size());
  region_.insert(region_.end(), members.begin(), members.end());
  for (index_t v : members)
    expand(v);
  return id;
}

// Adds the links from `v` to every neighbour whose own links are not in yet. `v` is
// marked last: a set created on the way expands its members, which then add their
// links to `v` themselves.
void LinkProjector::expand(index_t v)
{
  const Adjacency& adj = *mesh_.adjacency;
  for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
  {
    Constraint C;
    if (expanded_[*n] || !constraint(v, *n, C))
      continue;
    const index_t b = variable_for(*n);
    const index_t a = var_of_[v];
    if (a != b && !expanded_[*n])
    {
      const Eigen::Vector3d w = vars_[a].value - vars_[b].value;
      links_.push_back(
        { a, b, v, *n, C, Eigen::Vector3d::Zero(), project_onto(C, w), Eigen::Vector3d::Zero() });
    }
  }
  expanded_[v] = 1;
}

// One Dykstra step on link k; returns the largest coordinate change it made.
double LinkProjector::relax(std::size_t k)
{
  Link& l = links_[k];
  Variable& a = vars_[l.a];
  Variable& b = vars_[l.b];
  const double ia = a.inverse_weight, ib = b.inverse_weight, den = ia + ib;
  if (den == 0.0)
    return 0.0;
  const Eigen::Vector3d r = a.value - b.value + l.mu * den;
  const Eigen::Vector3d g = (r - project_onto(l.C, r)) / den;
  const Eigen::Vector3d step = l.mu - g;
  l.mu = g;
  // A fixed end is never written, so it stays bit-identical.
  if (ia > 0.0)
    a.value += ia * step;
  if (ib > 0.0)
    b.value -= ib * step;
  const double update = step.cwiseAbs().maxCoeff() * std::max(ia, ib);
  if (update == 0.0)
    return 0.0;
  // expand() may grow links_ and vars_: nothing above is used after it.
  const index_t va = ia > 0.0 ? a.vertex : -1, vb = ib > 0.0 ? b.vertex : -1;
  if (va >= 0 && !expanded_[va])
    expand(va);
  if (vb >= 0 && !expanded_[vb])
    expand(vb);
  return update;
}

// Gauss-Seidel in the order the links were added (outward from the start), which carries
// a correction outward in one sweep; appended links join the same sweep.
double LinkProjector::sweep()
{
  double update = 0.0;
  for (std::size_t k = 0; k < links_.size(); ++k)
    update = std::max(update, relax(k));
  return update;
}

// Distance of w = u_c - u_s to c's own region w.r.t. s, exactly as link_distance()
// measures it (the frame's box or cylinder).
double LinkProjector::directed(index_t c, index_t s, const Eigen::Vector3d& w) const
{
  return region_distance(mesh_.frame, mesh_.rest[c] - mesh_.rest[s], mesh_.params[c], w);
}

double LinkProjector::violation(const Link& l, const Eigen::Vector3d& w) const
{
  if (vars_[l.a].inverse_weight + vars_[l.b].inverse_weight == 0.0)
    return 0.0;
  return std::max(directed(l.c, l.s, w), directed(l.s, l.c, -w));
}

// E_link over the swept links (unnormalised): each direction against its own region.
double LinkProjector::max_violation() const
{
  double worst = 0.0;
  for (const Link& l : links_)
    worst = std::max(worst, violation(l, vars_[l.a].value - vars_[l.b].value));
  return worst;
}

// E_link over the links not yet in: those between a region vertex whose links were never
// added (a ring vertex) and a neighbour that is not expanded either (outside the region:
// at rest). Only ring vertices that moved can violate them. Appends to `grow` (when
// given) the vertices with such a link violated by more than `tol`.
double LinkProjector::pending_violation(double tol, std::vector<index_t>* grow)
{
  const Adjacency& adj = *mesh_.adjacency;
  double worst = 0.0;
  for (index_t v : region_)
  {
    const Variable& var = vars_[std::size_t(var_of_[v])];
    if (expanded_[v] || var.inverse_weight == 0.0 || var.value == var.start)
      continue;
    double mine = 0.0;
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
    {
      if (expanded_[*n] || !mesh_.rest[v].allFinite() || !mesh_.rest[*n].allFinite())
        continue;
      const Eigen::Vector3d r =
        var.value - (var_of_[*n] >= 0 ? vars_[std::size_t(var_of_[*n])].value : u_[*n]);
      mine = std::max({ mine, directed(v, *n, r), directed(*n, v, -r) });
    }
    worst = std::max(worst, mine);
    if (grow && mine > tol)
      grow->push_back(v);
  }
  return worst;
}

void LinkProjector::keep_best()
{
  best_.resize(vars_.size());
  for (std::size_t i = 0; i < vars_.size(); ++i)
    best_[i] = vars_[i].value;
}

void LinkProjector::run_dykstra(const ProjectionOptions& options, ProjectionReport& report)
{
  // Alternating projections do not decrease the violation monotonically (transient rises
  // of ~10% were measured), so the iterate with the least violation so far is returned:
  // more iterations never give a worse E_link.
  const double tol = options.tolerance * mesh_.scale();
  while (report.iterations < options.max_iterations)
  {
    const double update = sweep();
    if (finish_iteration(report, max_violation(), update, tol, options))
      break;
  }
}

// (Re)builds M + rho D^T D over the free variables and factorises it, unless the
// factorisation of the previous call was built for the same variables and links.
bool LinkProjector::factorise(double rho)
{
  Factor& f = *factor_;
  const bool same = f.valid && f.grasp == grasp_ && f.rho == rho && f.region == region_ &&
                    f.links.size() == links_.size() &&
                    std::equal(links_.begin(), links_.end(), f.links.begin(),
                      [](const Link& l, const std::pair<index_t, index_t>& p)
                      { return l.a == p.first && l.b == p.second; }) &&
                    std::equal(region_.begin(), region_.end(), f.var_of.begin(),
                      [this](index_t v, index_t var) { return var_of_[v] == var; });
  if (same)
    return false;
  f.col.assign(vars_.size(), -1);
  f.free.clear();
  for (std::size_t i = 0; i < vars_.size(); ++i)
    if (vars_[i].inverse_weight > 0.0)
    {
      f.col[i] = index_t(f.free.size());
      f.free.push_back(index_t(i));
    }
  const Eigen::Index n = Eigen::Index(f.free.size());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(std::size_t(n) + 4 * links_.size());
  for (Eigen::Index j = 0; j < n; ++j)
    t.emplace_back(j, j, 1.0 / vars_[std::size_t(f.free[std::size_t(j)])].inverse_weight);
  for (const Link& l : links_)
  {
    const index_t ca = f.col[std::size_t(l.a)], cb = f.col[std::size_t(l.b)];
    if (ca >= 0)
      t.emplace_back(ca, ca, rho);
    if (cb >= 0)
      t.emplace_back(cb, cb, rho);
    if (ca >= 0 && cb >= 0)
    {
      t.emplace_back(ca, cb, -rho);
      t.emplace_back(cb, ca, -rho);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  f.ldlt.compute(A);
  f.valid = f.ldlt.info() == Eigen::Success;
  f.grasp = grasp_;
  f.rho = rho;
  f.region = region_;
  f.var_of.resize(region_.size());
  for (std::size_t i = 0; i < region_.size(); ++i)
    f.var_of[i] = var_of_[region_[i]];
  f.links.resize(links_.size());
  for (std::size_t k = 0; k < links_.size(); ++k)
    f.links[k] = { links_[k].a, links_[k].b };
  f.rhs.resize(n, 3);
  return true;
}

void LinkProjector::run_admm(const ProjectionOptions& options, ProjectionReport& report)
{
  const double tol = options.tolerance * mesh_.scale();
  // rho balances the weights M (1, or the size of a rigid set) against the links: a
  // large rigid set needs a stiffer link penalty to be moved by its links. Measured to
  // 1e-10 L on the test scenes (sets of a few vertices): rho 10 in 1,064-1,788
  // iterations, 100 in 1,231-7,057, 1 in 10,660-18,124; on the fault step (a rigid set of
  // 1,708 vertices) 1 stalls at 0.19 L after 3,000 iterations, 413-17,000 reach 1e-4 L
  // in 600-1,000. Hence rho = 10 sqrt(largest weight).
  double heaviest = 1.0;
  for (const Variable& v : vars_)
    if (v.inverse_weight > 0.0)
      heaviest = std::max(heaviest, 1.0 / v.inverse_weight);
  const double rho =
    (options.rho > 0.0 ? options.rho : 10.0 * std::sqrt(heaviest)) * options.rho_scale;
  const double alpha = 1.6; // over-relaxation (Boyd et al. 2011, section 3.4.3)
  Factor& f = *factor_;
  bool refactor = true;
  std::vector<index_t> grow;
  while (report.iterations < options.max_iterations)
  {
    if (refactor)
    {
      report.factorisations += factorise(rho) ? 1 : 0;
      refactor = false;
      if (!f.valid) // cannot happen for M + rho L (SPD); keep the start
        break;
    }
    // x = (M + rho D^T D)^-1 (M z + rho D^T (y - lambda - c))
    for (std::size_t j = 0; j < f.free.size(); ++j)
    {
      const Variable& v = vars_[std::size_t(f.free[j])];
      f.rhs.row(Eigen::Index(j)) = v.start.transpose() / v.inverse_weight;
    }
    for (const Link& l : links_)
    {
      const index_t ca = f.col[std::size_t(l.a)], cb = f.col[std::size_t(l.b)];
      const Eigen::Vector3d t = l.y - l.lambda;
      if (ca >= 0)
        f.rhs.row(ca) += rho * (cb >= 0 ? t : Eigen::Vector3d(t + vars_[l.b].value)).transpose();
      if (cb >= 0)
        f.rhs.row(cb) -= rho * (ca >= 0 ? t : Eigen::Vector3d(t - vars_[l.a].value)).transpose();
    }
    f.x = f.ldlt.solve(f.rhs);
    double update = 0.0;
    for (std::size_t j = 0; j < f.free.size(); ++j)
    {
      Variable& v = vars_[std::size_t(f.free[j])];
      const Eigen::Vector3d x = f.x.row(Eigen::Index(j)).transpose();
      if (!x.allFinite())
        continue; // cannot happen; never let a NaN in
      update = std::max(update, (x - v.value).cwiseAbs().maxCoeff());
      v.value = x;
    }
    double violation = 0.0;
    for (Link& l : links_)
    {
      const Variable& a = vars_[l.a];
      const Variable& b = vars_[l.b];
      if (a.inverse_weight + b.inverse_weight == 0.0)
        continue;
      const Eigen::Vector3d w = a.value - b.value;
      violation = std::max(violation, this->violation(l, w));
      const Eigen::Vector3d relaxed = alpha * w + (1.0 - alpha) * l.y;
      const Eigen::Vector3d y = project_onto(l.C, relaxed + l.lambda);
      l.lambda += relaxed - y;
      l.y = y;
    }
    grow.clear();
    violation = std::max(violation, pending_violation(tol, &grow));
    if (finish_iteration(report, violation, update, tol, options))
      break;
    // Ring vertices pushed against links that are not in yet: add their links (the
    // region grows where the projection pushes) and refactorise; every 10 iterations
    // only, so that a region growing ring by ring does not refactorise every iteration.
    if (!grow.empty() && (report.iterations % 10 == 0 || report.iterations == 1))
    {
      for (index_t v : grow)
        if (!expanded_[v])
          expand(v);
      refactor = true;
    }
  }
}

// The label of v in the current envelope run on y = sign u (its start until the run sets
// it). env_label_ holds every vertex's as a value of u: within a call u on the running
// axis outside the runs (what the scan and the check read, one dense load), the labels
// during a run; 0 between calls.
inline double LinkProjector::envelope_value(index_t v, int, double sign) const
{
  return sign * env_label_[v];
}

inline void LinkProjector::envelope_touch(index_t v, double value)
{
  if (!env_set_[v])
  {
    env_set_[v] = 1;
    env_touched_.push_back(v);
  }
  env_label_[v] = value;
}

// Labels the last run set go back to u on `axis` (u_ is what the runs started from, or the
// combine's result after the last run).
void LinkProjector::envelope_end_run(int axis)
{
  for (index_t v : env_touched_)
  {
    env_label_[v] = u_[v][axis];
    env_set_[v] = 0;
  }
  env_touched_.clear();
}

// Every label u on `axis`: the region's (set on another axis) from u_, every other
// vertex's is 0 (rest).
void LinkProjector::envelope_begin_axis(int axis)
{
  for (index_t v : region_)
    env_label_[v] = u_[v][axis];
}

void LinkProjector::envelope_end_call()
{
  for (index_t v : region_)
    env_label_[v] = 0.0;
}

// The links of v, cached on first use and kept across calls (the mesh's rest, params and
// pins are constant for the projector's life): per neighbour a with a finite rest offset,
// a's id (~id when a is pinned), and per axis i the slab [lo, hi] of u_a - u_v
// (axis_slab(a, v), the bounds the passes relax with) as up = hi and dn = -lo. Returns
// v's slots: `count` from `first`.
inline LinkProjector::LinkRange LinkProjector::envelope_links(index_t v)
{
  const LinkRange r = env_links_[std::size_t(v)];
  return r.first >= 0 ? r : fill_links(v);
}

LinkProjector::LinkRange LinkProjector::fill_links(index_t v)
{
  const Adjacency& adj = *mesh_.adjacency;
  const std::size_t first = env_nbr_.size();
  const Eigen::Vector3d& rest = mesh_.rest[std::size_t(v)];
  const ChainMailParams& pv = mesh_.params[std::size_t(v)];
  for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
  {
    const Eigen::Vector3d o = mesh_.rest[std::size_t(*n)] - rest;
    if (!o.allFinite())
      continue;
    env_nbr_.push_back(mesh_.is_pinned(*n) ? ~*n : *n);
    const ChainMailParams& pn = mesh_.params[std::size_t(*n)];
    for (int i = 0; i < 3; ++i)
      if (env_cache_axes_ & (1 << i))
      {
        double lo, hi;
        axis_slab(o, pn, pv, i, lo, hi);
        env_up_[i].push_back(hi);
        env_dn_[i].push_back(-lo);
      }
  }
  const LinkRange r{ std::int32_t(first), std::int32_t(env_nbr_.size() - first) };
  env_links_[std::size_t(v)] = r;
  env_cached_.push_back(v);
  return r;
}

// Fills the links of list[i], the loads of the later vertices of `list` started ahead of
// their turn: 32 ahead the cache entry, 24 ahead (when not cached) the adjacency row, rest
// position and parameters, 16 ahead the neighbour list, 8 ahead the neighbours' rest
// positions and parameters. On a grasp's first frame these are cold (the frame read none
// of them), and a fill of one vertex at a time waits for each load in turn, four deep.
void LinkProjector::fill_links_ahead(const std::vector<index_t>& list, std::size_t i)
{
  const Adjacency& adj = *mesh_.adjacency;
  const std::size_t n = list.size();
  const auto cold = [&](std::size_t j) { return env_links_[std::size_t(list[j])].first < 0; };
  if (i + 32 < n)
    prefetch(&env_links_[std::size_t(list[i + 32])]);
  if (i + 24 < n && cold(i + 24))
  {
    const std::size_t w = std::size_t(list[i + 24]);
    prefetch(&adj.offsets[w]);
    prefetch(&mesh_.rest[w]);
    prefetch(&mesh_.params[w]);
  }
  if (i + 16 < n && cold(i + 16))
    prefetch(adj.begin(list[i + 16]));
  if (i + 8 < n && cold(i + 8))
    for (const index_t* m = adj.begin(list[i + 8]); m != adj.end(list[i + 8]); ++m)
    {
      prefetch(&mesh_.rest[std::size_t(*m)]);
      prefetch(&mesh_.params[std::size_t(*m)]);
    }
  envelope_links(list[i]);
}

// The passes' priority queue: a radix heap (Ahuja, Mehlhorn, Orlin and Tarjan 1990) on the
// leading bits of the labels. Dijkstra pops labels in increasing order and pushes none
// below the last popped (weights >= 0), so a monotone queue suffices: an entry sits in
// bucket floor(log2(key ^ last)) + 1 and moves only to lower buckets; push is O(1), pop
// amortised O(1). The key keeps the sign, the exponent and the 16 leading bits of the
// significand: labels within a relative 2^-16 of each other share a key and pop in any
// order among themselves (the result does not depend on the order, link_projection.h),
// and an entry moves at most 28 times. Fewer bits move entries less but pop more labels
// out of order: once a cone's labels are large against its slabs it pops in any order
// (docs/benchmarks.md, "The envelope refinement").
namespace
{
// Order-preserving map of a double onto its 28 leading bits (-0 taken as +0; no NaN
// reaches here): a non-decreasing function of y.
std::uint64_t radix_key(double y)
{
  std::uint64_t bits;
  const double z = y + 0.0;
  std::memcpy(&bits, &z, sizeof bits);
  return ((bits >> 63) ? ~bits : bits | (std::uint64_t(1) << 63)) >> 36;
}

int radix_bucket(std::uint64_t x)
{
  return x == 0 ? 0 : 64 - __builtin_clzll(x);
}
} // namespace

void LinkProjector::envelope_push(double y, index_t v)
{
  const std::uint64_t k = radix_key(y);
  env_buckets_[std::size_t(radix_bucket(k ^ env_last_))].push_back({ k, y, v });
  ++env_queued_count_;
}

// Pops an entry with the least key (ties in any order).
LinkProjector::RadixEntry LinkProjector::envelope_pop()
{
  if (env_buckets_[0].empty())
  {
    std::size_t i = 1;
    while (env_buckets_[i].empty())
      ++i;
    std::vector<RadixEntry>& from = env_buckets_[i];
    std::uint64_t least = from.front().key;
    for (const RadixEntry& e : from)
      least = std::min(least, e.key);
    env_last_ = least;
    for (const RadixEntry& e : from)
      env_buckets_[std::size_t(radix_bucket(e.key ^ env_last_))].push_back(e);
    from.clear();
  }
  const RadixEntry e = env_buckets_[0].back();
  env_buckets_[0].pop_back();
  --env_queued_count_;
  return e;
}

void LinkProjector::envelope_reset_queue()
{
  for (std::vector<RadixEntry>& b : env_buckets_)
    b.clear();
  env_queued_count_ = 0;
  env_last_ = 0;
}

template<class Label, class Relax, class Visit>
void LinkProjector::envelope_dijkstra(int axis, double sign, Label label, Relax relax, Visit visit)
{
  const std::vector<double>& ub = sign > 0.0 ? env_up_[axis] : env_dn_[axis];
  while (env_queued_count_ > 0)
  {
    const RadixEntry e = envelope_pop();
    const index_t b = e.vertex;
    const double y = e.value;
    // The next pops' links, started ahead (their order is known within bucket 0).
    const std::vector<RadixEntry>& next = env_buckets_[0];
    if (next.size() >= 2)
      prefetch(&env_links_[std::size_t(next[next.size() - 2].vertex)]);
    if (!next.empty())
    {
      const LinkRange n = env_links_[std::size_t(next.back().vertex)];
      if (n.first >= 0)
      {
        prefetch(&env_nbr_[std::size_t(n.first)]);
        prefetch(&ub[std::size_t(n.first)]);
      }
    }
    if (y != label(b))
      continue; // lowered again since it was pushed
    const LinkRange r = envelope_links(b);
    visit(b, y, r);
    const std::int32_t first = r.first, last = first + r.count;
    const index_t* nbr = env_nbr_.data(); // stable until the next envelope_links()
    const double* w = ub.data();
    for (std::int32_t k = first; k < last; ++k)
    {
      const index_t a = nbr[k];
      if (a < 0 || a == grasp_)
        continue; // pinned (stored as ~id) or grasped
      relax(a, y + w[k]);
    }
  }
}

// Min-plus label correction on y = sign u (axis `axis`): y_a <= y_b + ub(a, b) on every
// link, ub = hi_ab (sign +1) or -lo_ab (sign -1), lowering free vertices only, from `seeds`
// (popped in increasing y: each vertex is settled about once, Dijkstra's order). The
// result does not depend on the order (docs/error-metrics.md): it is the greatest
// configuration below the start that satisfies the links out of every seed and every
// lowered vertex.
void LinkProjector::envelope_min_pass(int axis, double sign, std::vector<index_t>& seeds)
{
  envelope_reset_queue();
  for (index_t s : seeds)
    envelope_push(envelope_value(s, axis, sign), s);
  envelope_dijkstra(
    axis, sign, [&](index_t v) { return envelope_value(v, axis, sign); },
    [&](index_t a, double cap)
    {
      if (cap < envelope_value(a, axis, sign))
      {
        envelope_touch(a, sign * cap);
        envelope_push(cap, a);
      }
    },
    [](index_t, double, LinkRange) {});
}

// The cones of the fixed vertices on y = sign u: c(a) = min_f (y_f + d(f, a)) by Dijkstra
// on labels of their own (a cone must pass vertices that are already above it), pruned
// where c >= the largest y of every vertex (beyond, the cone lowers nothing: weights >= 0);
// raise(a, c(a)) then takes y_a = min(y_a, c(a)) on free vertices (EnvelopeAxis).
template<class Raise>
void LinkProjector::envelope_cone(
  int axis, double sign, const std::vector<index_t>& fixed, Raise raise)
{
  env_check_.clear();
  if (fixed.empty())
    return;
  double top = 0.0; // every vertex outside the region is at rest
  for (index_t v : region_)
    top = std::max(top, sign * u_[v][axis]);
  env_cone_touched_.clear();
  envelope_reset_queue();
  const double none = std::numeric_limits<double>::infinity();
  const auto cone = [&](index_t v) { return env_cone_[v]; };
  const auto set = [&](index_t v, double c)
  {
    if (env_cone_[v] == none)
      env_cone_touched_.push_back(v);
    env_cone_[v] = c;
    envelope_push(c, v);
  };
  // Which raised vertices may have a broken link (EnvelopeAxis::direction then checks
  // their links exactly): b, popped at its final cone label c_b (its last pop), is raised
  // to y_b = -c_b on the run's y = -sign u when that is above its start. A link to a
  // breaks y_b <= fl(y_a + w) (w: the cone's weight, the run's ub(b, a)) only if it
  // breaks it with any lower bound of a's final label: its start when a is fixed, else
  // -min(c_a, top) (c_a only falls, a free vertex ends at max(start, -c_a) and no start
  // is below -top). It breaks y_a <= fl(y_b + w') (w': the run's ub(a, b)) only if a ends
  // at its start (a raised a checks that link as its own first kind) and a is free.
  // Breaks are rare (the cone's labels satisfy the links up to rounding) and the test
  // reads no label of the run: this replaces a pass over every raised vertex's links.
  std::size_t filled = 0; // env_cone_touched_[0, filled) have their links: filled ahead
  const auto visit = [&](index_t b, double c, LinkRange r)
  {
    // Each vertex is popped some time after its first label (the cone grows by rings):
    // when the start's links were not all cached (a new grasp, a first frame), the
    // cone's are filled in the order of the first labels, 32 behind the newest.
    while (env_cold_ && filled + 32 < env_cone_touched_.size())
      fill_links_ahead(env_cone_touched_, filled++);
    const double yb = -c;
    if (is_fixed(b) || !(yb > -sign * env_label_[b]))
      return;
    // Read after the fill above, which may grow (and move) the link arrays.
    const double* w = (sign > 0.0 ? env_up_ : env_dn_)[axis].data();
    const double* w_other = (sign > 0.0 ? env_dn_ : env_up_)[axis].data();
    for (std::int32_t k = r.first; k < r.first + r.count; ++k)
    {
      const index_t slot = env_nbr_[std::size_t(k)];
      const index_t a = slot < 0 ? ~slot : slot;
      const bool a_fixed = slot < 0 || a == grasp_;
      const double ya = -sign * env_label_[a];
      const double low = a_fixed ? ya : -std::min(std::min(cone(a), c + w[k]), top);
      // w' >= 0: ya <= yb keeps the second (and leaves w' unread: a cold array here).
      if (yb > low + w[k] || (!a_fixed && ya > yb && ya > yb + w_other[k]))
      {
        env_check_.push_back(b);
        return;
      }
    }
  };
  for (index_t f : fixed)
    set(f, envelope_value(f, axis, sign));
  envelope_dijkstra(
    axis, sign, cone,
    [&](index_t a, double cap)
    {
      if (cap < cone(a) && cap < top)
        set(a, cap);
    },
    visit);
  for (index_t a : env_cone_touched_)
  {
    raise(a, env_cone_[a]);
    env_cone_[a] = none;
  }
}

// The whole mesh for EnvelopeAxis: links from the cache (slot k of v holds the slab of
// u_m - u_v as [-dn, up], so lo <= u_v - u_m <= hi is [-up, dn] exactly: axis_slab is
// antisymmetric), labels in env_value_ (as u), runs on the radix heap. A link between two
// region vertices is read once, from its end of lower index.
struct LinkProjector::EnvelopeNet
{
  LinkProjector& p;
  const std::vector<index_t>& fixed;

  bool is_fixed(index_t v) const { return p.is_fixed(v); }
  double u(index_t v, int) const { return p.env_label_[v]; }
  double start_u(index_t v, int axis) const { return p.u_[v][axis]; }
  void begin_axis(int axis) { p.envelope_begin_axis(axis); }
  void end_runs(int axis) { p.envelope_end_run(axis); }
  template<class F>
  void for_each_scanned(F f) const
  {
    for (index_t v : p.region_)
      f(v);
  }
  template<class F>
  void for_each_checked(F f) const
  {
    for_each_scanned(f);
  }
  bool scanned_from(index_t m, index_t v) const { return p.expanded_[m] && m < v; }
  bool checked_from(index_t m, index_t v) const { return scanned_from(m, v); }
  template<class F>
  void for_each_link(index_t v, int axis, F f) const
  {
    const LinkRange r = p.envelope_links(v);
    const std::int32_t first = r.first, last = first + r.count;
    const double* up = p.env_up_[axis].data();
    const double* dn = p.env_dn_[axis].data();
    const index_t* nbr = p.env_nbr_.data();
    for (std::int32_t k = first; k < last; ++k)
    {
      const index_t m = nbr[k] < 0 ? ~nbr[k] : nbr[k];
      f(m, -up[k], dn[k], nbr[k] < 0 || m == p.grasp_);
    }
  }
  void begin_run(int axis, double) { p.envelope_end_run(axis); }
  double label(index_t v, int axis, double sign) const { return p.envelope_value(v, axis, sign); }
  void set_label(index_t v, int, double sign, double y) { p.envelope_touch(v, sign * y); }
  const std::vector<index_t>& touched() const { return p.env_touched_; }
  const std::vector<index_t>& raised_to_check() const { return p.env_check_; }
  template<class F>
  void cone(int axis, double sign, F raise)
  {
    p.envelope_cone(axis, sign, fixed, raise);
  }
  void min_pass(int axis, double sign, std::vector<index_t>& seeds)
  {
    p.envelope_min_pass(axis, sign, seeds);
  }
  void change(index_t v, int axis, double value)
  {
    p.u_[v][axis] = value;
    p.env_label_[v] = value; // read as its U label no more (combined once)
    mark_changed(p.expanded_[v], v, p.region_, p.changed_);
  }
};

void LinkProjector::run_envelope(
  const std::vector<index_t>& start, const ProjectionOptions& options, ProjectionReport& report)
{
  const index_t n = mesh_.size();
  if (env_label_.size() != std::size_t(n))
  {
    // Every vertex at rest, no cone, no link cached; each call puts back what it set.
    env_axis_.resize(std::size_t(n));
    env_label_.assign(std::size_t(n), 0.0);
    env_set_.assign(std::size_t(n), 0);
    env_cone_.assign(std::size_t(n), std::numeric_limits<double>::infinity());
    env_links_.assign(std::size_t(n), LinkRange{ -1, 0 });
    env_cached_.clear();
  }
  const Adjacency& adj = *mesh_.adjacency;
  // expanded_ marks region_ membership here (1) and a changed vertex (2); clear() resets it.
  for (index_t v : start)
    if (!expanded_[v])
    {
      expanded_[v] = 1;
      region_.push_back(v);
    }
  // The axes to run: those on which some start value is non-zero (on the others rest
  // satisfies every link and nothing moves; a vertex a later axis adds to the region is
  // at rest on the other axes).
  env_axes_ = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (index_t v : region_)
      if (u_[v][axis] != 0.0)
      {
        env_axes_ |= 1 << axis;
        break;
      }
  // The link cache grows with the vertices the calls reach and holds the axes the calls
  // ran; past a bound proportional to this call's start, or without an axis this call
  // runs, it is dropped, so its memory stays O(displaced).
  const bool too_big = env_cached_.size() > 8 * region_.size() + 65536;
  if (too_big || (env_axes_ & ~env_cache_axes_))
  {
    for (index_t v : env_cached_)
      env_links_[v].first = -1;
    env_cached_.clear();
    env_nbr_.clear();
    for (int i = 0; i < 3; ++i)
    {
      env_up_[i].clear();
      env_dn_[i].clear();
    }
    env_cache_axes_ = too_big ? env_axes_ : env_cache_axes_ | env_axes_;
  }
  // Room for the links of about twice the start's vertices (the D and U runs reach
  // ~1.6x at the paper's scale): the slots are not moved while the cache grows.
  const std::size_t slots =
    adj.offsets.empty() ? 0
                        : std::size_t(adj.offsets.back()) / std::size_t(std::max<index_t>(n, 1));
  const std::size_t room = env_nbr_.size() + 2 * (slots + 1) * region_.size();
  if (env_nbr_.capacity() < room)
  {
    env_nbr_.reserve(room);
    for (int i = 0; i < 3; ++i)
      if (env_cache_axes_ & (1 << i))
      {
        env_up_[i].reserve(room);
        env_dn_[i].reserve(room);
      }
  }
  std::vector<index_t> fixed;
  if (grasp_ >= 0)
    fixed.push_back(grasp_);
  if (!mesh_.pinned.empty())
    for (index_t v : region_)
    {
      if (v != grasp_ && mesh_.is_pinned(v))
        fixed.push_back(v);
      for (const index_t* m = adj.begin(v); m != adj.end(v); ++m)
        if (!expanded_[*m] && mesh_.is_pinned(*m))
          fixed.push_back(*m);
    }
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());

  const std::size_t cached = env_cached_.size();
  if (env_axes_)
    for (std::size_t i = 0; i < region_.size(); ++i)
      fill_links_ahead(region_, i); // the first axis's scan reads them all
  env_cold_ = env_cached_.size() > cached;
  EnvelopeNet net{ *this, fixed };
  double squared = 0.0; // sum over the axes of the squared largest slab distance
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!(env_axes_ & (1 << axis)))
      continue; // every value 0 on this axis: rest satisfies every link, nothing to do
    const double worst = env_axis_.run(net, axis);
    squared += worst * worst;
  }
  envelope_end_call();
  report.iterations = 1;
  const double violation = std::sqrt(squared) / mesh_.scale();
  report.violation = violation;
  report.update = 0.0;
  report.converged = violation <= options.tolerance;
}

ProjectionReport LinkProjector::project(index_t grasp, const std::vector<index_t>& vertices,
  const Displacements& values, const ProjectionOptions& options)
{
  clear();
  const index_t n = mesh_.size();
  grasp_ = grasp >= 0 && grasp < n ? grasp : -1;
  std::vector<index_t> start;
  start.reserve(vertices.size() + 1);
  for (std::size_t i = 0; i < vertices.size() && i < values.size(); ++i)
    if (vertices[i] >= 0 && vertices[i] < n)
    {
      u_[vertices[i]] = values[i];
      start.push_back(vertices[i]);
    }
  ProjectionReport report;
  if (options.max_iterations <= 0)
  {
    region_ = start; // so the next call resets them
    report.region = region_.size();
    return report;
  }
  if (grasp_ >= 0)
    start.push_back(grasp_);
  if (options.solver == ProjectionSolver::envelope && mesh_.frame == ValidRegionFrame::axes)
  {
    run_envelope(start, options, report);
    report.region = region_.size();
    return report;
  }
  for (index_t v : start)
    variable_for(v);
  for (index_t v : start)
    if (!expanded_[v])
      expand(v);

  // The start (averaged over each rigid set: its projection onto V) is the first
  // candidate, so no number of iterations returns a larger E_link than it.
  best_violation_ = max_violation();
  best_update_ = 0.0;
  keep_best();
  if (options.solver != ProjectionSolver::admm) // dykstra, or envelope in the Link frame
    run_dykstra(options, report);
  else
    run_admm(options, report);
  report.violation = best_violation_ / mesh_.scale();
  report.update = best_update_ / mesh_.scale();
  // A variable created after the kept iterate was still at its start then.
  for (index_t v : region_)
  {
    const std::size_t var = std::size_t(var_of_[v]);
    if (var >= best_.size() || best_[var] == u_[v])
      continue;
    changed_.push_back(v);
    u_[v] = best_[var];
  }
  report.region = region_.size();
  report.links = links_.size();
  return report;
}

bool LinkProjector::finish_iteration(ProjectionReport& report, double violation, double update,
  double tol, const ProjectionOptions& options)
{
  ++report.iterations;
  report.converged = violation <= tol && update <= tol;
  if (violation < best_violation_ || report.converged)
  {
    best_violation_ = violation;
    best_update_ = update;
    keep_best();
  }
  return report.converged || (options.stop && options.stop());
}

bool link_axis_slab(const LinkMesh& mesh, index_t c, index_t s, int axis, double& lo, double& hi)
{
  return axis_slab(mesh, c, s, axis, lo, hi);
}

void LinkProjector::assign(const std::vector<index_t>& vertices, const Displacements& values,
  const std::vector<index_t>& changed)
{
  clear();
  for (std::size_t i = 0; i < vertices.size() && i < values.size(); ++i)
  {
    u_[std::size_t(vertices[i])] = values[i];
    region_.push_back(vertices[i]);
  }
  changed_ = changed;
}

const char* solver_name(ProjectionSolver solver)
{
  static constexpr EnumName names[] = { { int(ProjectionSolver::admm), "ADMM" },
    { int(ProjectionSolver::dykstra), "Dykstra" },
    { int(ProjectionSolver::envelope), "Envelope" } };
  return name_of(names, int(solver));
}

ProjectionReport refine_links(LinkProjector& projector, const ChainMailDeformer& deformer,
  index_t grasp, const ProjectionOptions& options)
{
  Displacements values;
  values.reserve(deformer.moved().size());
  for (index_t v : deformer.moved())
    values.push_back(deformer.displacement(v));
  return projector.project(grasp, deformer.moved(), values, options);
}

ProjectionReport refine_links(LinkProjector& projector, const ChainMailDeformer& deformer,
  index_t grasp, int iterations, std::function<bool()> stop)
{
  ProjectionOptions options;
  options.max_iterations = iterations;
  options.stop = std::move(stop);
  return refine_links(projector, deformer, grasp, options);
}

Displacements reference_configuration(const LinkMesh& mesh, index_t grasp,
  const Displacements& start, ProjectionReport* report, const ProjectionOptions& options)
{
  std::vector<index_t> vertices;
  Displacements values;
  for (index_t v = 0; v < mesh.size() && std::size_t(v) < start.size(); ++v)
    if (!start[v].isZero(0.0))
    {
      vertices.push_back(v);
      values.push_back(start[v]);
    }
  LinkProjector projector(mesh);
  ProjectionReport r = projector.project(grasp, vertices, values, options);
  if (!r.converged && options.finish && options.max_iterations > 0)
  {
    // The finish: the capped result x is within the solver's residual of the projection
    // and violates its links by little; project x itself (the envelope in the Axes frame,
    // exact in one pass; in the Link frame ADMM at 100x rho from a start that is nearly
    // feasible, then Dykstra if that is capped too).
    // The start of a finish: the projector's last result, its non-zero displacements.
    const auto restart_from_result = [&]
    {
      vertices.clear();
      values.clear();
      const Displacements x = projector.displacements();
      for (index_t v : projector.region())
        if (!x[std::size_t(v)].isZero(0.0))
        {
          vertices.push_back(v);
          values.push_back(x[std::size_t(v)]);
        }
    };
    restart_from_result();
    ProjectionOptions finish = options;
    ProjectionReport f;
    if (mesh.frame != ValidRegionFrame::link)
    {
      finish.solver = ProjectionSolver::envelope;
      f = projector.project(grasp, vertices, values, finish);
    }
    else
    {
      // ADMM again from x with a 100x stiffer rho: x is nearly feasible, and a stiff
      // penalty takes the violation down in few iterations (equal malleability, Link:
      // 1.26e-5 L after 5,000 iterations at the default rho; from there 90 iterations at
      // 100x reach 4e-7 L, where 20,000 Dykstra sweeps stopped at 1.66e-6 L). Dykstra
      // (up to 4 max_iterations sweeps) only if that is capped too.
      finish.solver = ProjectionSolver::admm;
      finish.rho_scale = 100.0 * options.rho_scale;
      f = projector.project(grasp, vertices, values, finish);
      r.factorisations += f.factorisations;
      if (!f.converged)
      {
        restart_from_result();
        ProjectionOptions last = options;
        last.solver = ProjectionSolver::dykstra;
        // Dykstra's tail is linear too (fault step, Link: 1.7e-5 -> 2.1e-6 L in 5,000 sweeps).
        last.max_iterations =
          options.max_iterations > (1 << 28) ? options.max_iterations : 4 * options.max_iterations;
        const int admm_iterations = f.iterations;
        f = projector.project(grasp, vertices, values, last);
        f.iterations += admm_iterations;
      }
    }
    r.iterations += f.iterations;
    r.finish_iterations = f.iterations;
    r.violation = f.violation;
    r.update = f.update;
    r.converged = f.converged;
    r.region = std::max(r.region, f.region);
    r.links = std::max(r.links, f.links);
  }
  if (report)
    *report = r;
  return projector.displacements();
}

} // namespace geoshaping
