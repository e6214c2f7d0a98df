#include "geoshaping/link_projection.h"

#include "geoshaping/chainmail_deformer.h"
#include "geoshaping/valid_region.h"

#include <algorithm>
#include <cmath>

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
} // namespace

LinkProjector::LinkProjector(const LinkMesh& mesh)
  : mesh_(mesh)
  , u_(std::size_t(mesh.size()), Eigen::Vector3d::Zero())
  , var_of_(std::size_t(mesh.size()), -1)
  , expanded_(std::size_t(mesh.size()), 0)
{
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

bool LinkProjector::is_fixed(index_t v) const
{
  return v == grasp_ || mesh_.is_pinned(v);
}

// An edge whose slab is a single point: its ends must share one displacement (an end is
// rigid, or the edge has zero length).
bool LinkProjector::is_equality(index_t v, index_t n) const
{
  Eigen::Vector3d lo, hi;
  return link_slab(mesh_, v, n, lo, hi) && lo.isZero(0.0) && hi.isZero(0.0);
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
  vars_.push_back({ u_[v], is_fixed(v) ? 0.0 : 1.0, v });
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
  vars_.push_back({ Eigen::Vector3d::Zero(), 0.0, -1 });
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
    Eigen::Vector3d lo, hi;
    if (expanded_[*n] || !link_slab(mesh_, v, *n, lo, hi))
      continue;
    const index_t b = variable_for(*n);
    const index_t a = var_of_[v];
    if (a != b && !expanded_[*n])
      links_.push_back({ a, b, v, *n, lo, hi, Eigen::Vector3d::Zero() });
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
  double update = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double r = a.value[i] - b.value[i] + l.mu[i] * den;
    const double g = (r - std::min(std::max(r, l.lo[i]), l.hi[i])) / den;
    const double step = l.mu[i] - g;
    l.mu[i] = g;
    // A fixed end is never written, so it stays bit-identical.
    if (ia > 0.0)
      a.value[i] += ia * step;
    if (ib > 0.0)
      b.value[i] -= ib * step;
    update = std::max(update, std::abs(step) * std::max(ia, ib));
  }
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

// E_link over the swept links (unnormalised): each direction against its own box,
// exactly as link_distance() measures it.
double LinkProjector::max_violation() const
{
  auto directed = [&](index_t c, index_t s, const Eigen::Vector3d& r)
  {
    const Box box = displacement_bounds(mesh_.rest[c] - mesh_.rest[s], mesh_.params[c]);
    return (r - box.clamp(r)).norm();
  };
  double worst = 0.0;
  for (const Link& l : links_)
  {
    const Variable& a = vars_[l.a];
    const Variable& b = vars_[l.b];
    if (a.inverse_weight + b.inverse_weight == 0.0)
      continue;
    const Eigen::Vector3d r = a.value - b.value;
    worst = std::max({ worst, directed(l.c, l.s, r), directed(l.s, l.c, -r) });
  }
  return worst;
}

void LinkProjector::keep_best()
{
  best_.resize(vars_.size());
  for (std::size_t i = 0; i < vars_.size(); ++i)
    best_[i] = vars_[i].value;
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
  for (index_t v : start)
    variable_for(v);
  for (index_t v : start)
    if (!expanded_[v])
      expand(v);

  // Alternating projections do not decrease the violation monotonically (transient rises
  // of ~10% were measured), so the iterate with the least violation so far is returned:
  // more iterations never give a worse E_link.
  const double tol = options.tolerance * mesh_.scale();
  double best = 0.0;
  while (report.iterations < options.max_iterations)
  {
    const double update = sweep();
    ++report.iterations;
    const double violation = max_violation();
    report.converged = violation <= tol && update <= tol;
    if (report.iterations == 1 || violation < best || report.converged)
    {
      best = violation;
      keep_best();
      report.update = update / mesh_.scale();
    }
    if (report.converged || (options.stop && options.stop()))
      break;
  }
  report.violation = best / mesh_.scale();
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

ProjectionReport refine_links(LinkProjector& projector, const ChainMailDeformer& deformer,
  index_t grasp, int iterations, std::function<bool()> stop)
{
  Displacements values;
  values.reserve(deformer.moved().size());
  for (index_t v : deformer.moved())
    values.push_back(deformer.displacement(v));
  ProjectionOptions options;
  options.max_iterations = iterations;
  options.stop = std::move(stop);
  return projector.project(grasp, deformer.moved(), values, options);
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
  const ProjectionReport r = projector.project(grasp, vertices, values, options);
  if (report)
    *report = r;
  return projector.displacements();
}

} // namespace geoshaping
