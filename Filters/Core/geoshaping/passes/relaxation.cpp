#include "geoshaping/passes/relaxation.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"

#include <algorithm>
#include <limits>

namespace geoshaping
{

namespace
{
constexpr int max_halvings = 30;

bool holds_still(const LinkMesh& m, index_t v, index_t grasp)
{
  const ChainMailParams& p = m.params[std::size_t(v)];
  const bool point_region = p.stretch == 1.0 && p.compression == 1.0 && p.shear == 0.0;
  return v == grasp || m.is_pinned(v) || m.rigid[std::size_t(v)] || point_region;
}
} // namespace

Relaxer::Relaxer(const LinkMesh& mesh)
  : mesh_(mesh)
  , u_(std::size_t(mesh.size()), Eigen::Vector3d::Zero())
  , is_free_(std::size_t(mesh.size()), 0)
{
}

void Relaxer::clear()
{
  for (index_t v : touched_)
    u_[std::size_t(v)].setZero();
  for (index_t v : free_)
    is_free_[std::size_t(v)] = 0;
  touched_.clear();
  free_.clear();
  start_.clear();
  changed_.clear();
}

// One Gauss-Seidel update of v (relaxation.h); true when v moved.
bool Relaxer::update(index_t v, RelaxationReport& report)
{
  const Adjacency& adj = *mesh_.adjacency;
  const std::size_t vi = std::size_t(v);
  const Eigen::Vector3d current = u_[vi];
  const Eigen::Vector3d& xv = mesh_.rest[vi];
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Box box{ Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity()),
    Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()) };
  before_.clear();
  for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
  {
    const Eigen::Vector3d& un = u_[std::size_t(*n)];
    mean += un;
    before_.push_back(link_distance(mesh_, u_, v, *n));
    before_.push_back(link_distance(mesh_, u_, *n, v));
    report.link_checks += 2;
    const Eigen::Vector3d o = xv - mesh_.rest[std::size_t(*n)];
    if (mesh_.frame != ValidRegionFrame::axes || !o.allFinite())
      continue;
    // A satisfied direction is a slab on w = u_v - u_n; a violated one may move within
    // the budget, left to the check below.
    if (before_[before_.size() - 2] == 0.0)
    {
      const Box own = displacement_bounds(o, mesh_.params[vi]); // w in [lo, hi]
      box.lo = box.lo.cwiseMax(un + own.lo);
      box.hi = box.hi.cwiseMin(un + own.hi);
    }
    if (before_.back() == 0.0)
    {
      const Box their = displacement_bounds(-o, mesh_.params[std::size_t(*n)]); // -w in [lo, hi]
      box.lo = box.lo.cwiseMax(un - their.hi);
      box.hi = box.hi.cwiseMin(un - their.lo);
    }
  }
  const auto degree = adj.degree(v);
  if (degree == 0)
    return false;
  mean /= double(degree) + rest_tether;
  const Eigen::Vector3d q = mesh_.frame == ValidRegionFrame::axes ? box.clamp(mean) : mean;
  if (!q.allFinite())
    return false;
  // Tries current + t (q - current) for t = omega, 1, 1/2, 1/4, ...
  Eigen::Vector3d target = current + over_relaxation * (q - current);
  // With the Axes region a step beyond the box breaks a satisfied slab: start at q.
  int attempt = mesh_.frame == ValidRegionFrame::axes && box.clamp(target) != target ? 1 : 0;
  if (attempt == 1)
    target = q;
  for (; attempt <= max_halvings + 1; ++attempt)
  {
    if (target == current)
      break;
    u_[vi] = target;
    bool ok = true;
    std::size_t k = 0;
    for (const index_t* n = adj.begin(v); n != adj.end(v) && ok; ++n, k += 2)
    {
      report.link_checks += 2;
      ok = link_distance(mesh_, u_, v, *n) <= allowed(before_[k]) &&
           link_distance(mesh_, u_, *n, v) <= allowed(before_[k + 1]);
    }
    if (ok)
      return true;
    target = attempt == 0 ? q : Eigen::Vector3d(current + 0.5 * (target - current));
  }
  u_[vi] = current;
  ++report.rejected;
  return false;
}

RelaxationReport Relaxer::relax(index_t grasp, const std::vector<index_t>& vertices,
  const Displacements& values, const RelaxationOptions& options)
{
  clear();
  const index_t n = mesh_.size();
  for (std::size_t i = 0; i < vertices.size() && i < values.size(); ++i)
  {
    const index_t v = vertices[i];
    if (v < 0 || v >= n)
      continue;
    u_[std::size_t(v)] = values[i];
    touched_.push_back(v);
  }
  for (std::size_t i = 0; i < vertices.size() && i < values.size(); ++i)
  {
    const index_t v = vertices[i];
    if (v < 0 || v >= n || holds_still(mesh_, v, grasp) || !values[i].allFinite())
      continue;
    // A duplicate keeps its first place in the order (and the last value given).
    if (!is_free_[std::size_t(v)])
    {
      is_free_[std::size_t(v)] = 1;
      free_.push_back(v);
    }
  }
  RelaxationReport report;
  start_.reserve(free_.size());
  for (index_t v : free_)
    start_.push_back(u_[std::size_t(v)]);
  budget_ = 0.0;
  const Adjacency& adj = *mesh_.adjacency;
  for (index_t v : free_)
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      budget_ =
        std::max({ budget_, link_distance(mesh_, u_, v, *n), link_distance(mesh_, u_, *n, v) });
  const double tolerance = options.tolerance * mesh_.scale();
  const double growth = growth_threshold * mesh_.scale();
  for (int sweep = 0; sweep < options.iterations; ++sweep)
  {
    double largest = 0.0;
    frontier_.clear();
    for (index_t v : free_)
    {
      const Eigen::Vector3d before = u_[std::size_t(v)];
      if (!update(v, report))
        continue;
      const double step = (u_[std::size_t(v)] - before).cwiseAbs().maxCoeff();
      largest = std::max(largest, step);
      if (step > growth)
        frontier_.push_back(v);
    }
    report.updates += free_.size();
    // One more ring for the next sweep: the resting neighbours of the vertices that moved.
    for (index_t v : frontier_)
      for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
        if (!is_free_[std::size_t(*n)] && u_[std::size_t(*n)].isZero(0.0) &&
            !holds_still(mesh_, *n, grasp))
        {
          is_free_[std::size_t(*n)] = 1;
          free_.push_back(*n);
          start_.push_back(u_[std::size_t(*n)]);
          touched_.push_back(*n);
        }
    report.iterations = sweep + 1;
    report.update = largest / mesh_.scale();
    if (largest <= tolerance || (options.stop && options.stop()))
      break;
  }
  report.free = free_.size();
  for (std::size_t i = 0; i < free_.size(); ++i)
    if (u_[std::size_t(free_[i])] != start_[i])
      changed_.push_back(free_[i]);
  return report;
}

RelaxationReport relax_frame(Relaxer& relaxer, const ChainMailDeformer& deformer, index_t grasp,
  int iterations, std::function<bool()> stop)
{
  Displacements values;
  values.reserve(deformer.moved().size());
  for (index_t v : deformer.moved())
    values.push_back(deformer.displacement(v));
  RelaxationOptions options;
  options.iterations = iterations;
  options.stop = std::move(stop);
  return relaxer.relax(grasp, deformer.moved(), values, options);
}

} // namespace geoshaping
