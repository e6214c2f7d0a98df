#include "geoshaping/parallel/partitioned_envelope.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/mesh/bit_cast.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping
{

namespace
{
std::int64_t bits(double x)
{
  return bit_cast<std::int64_t>(x);
}

double from_bits(std::int64_t b)
{
  return bit_cast<double>(b);
}
} // namespace

void PartitionedEnvelope::set_piece(
  const ChainMailDeformer& deformer, const LinkMesh& mesh, Exchange& exchange)
{
  n_ = deformer.size();
  const std::size_t n = std::size_t(n_);
  std::vector<std::int64_t> gid(n);
  std::vector<std::uint8_t> owned(n);
  for (index_t v = 0; v < n_; ++v)
  {
    gid[std::size_t(v)] = deformer.global_id(v);
    owned[std::size_t(v)] = deformer.owned(v);
  }
  pieces_.set_piece(n_, gid.data(), owned.data(), exchange);

  // The whole mesh's mean edge length (it only scales the report): each edge counted by
  // the owner of its end of lower global id.
  double sum = 0.0;
  std::int64_t count = 0;
  const Adjacency& adj = *mesh.adjacency;
  for (index_t v = 0; v < n_; ++v)
  {
    if (!pieces_.owned(v))
      continue;
    for (const index_t* m = adj.begin(v); m != adj.end(v); ++m)
    {
      if (pieces_.gid(*m) <= pieces_.gid(v))
        continue;
      const double l = (mesh.rest[std::size_t(v)] - mesh.rest[std::size_t(*m)]).norm();
      if (std::isfinite(l))
      {
        sum += l;
        ++count;
      }
    }
  }
  double total = 0.0;
  std::int64_t edges = 0;
  for (const auto& s : exchange.all_gather({ bits(sum), count }))
  {
    total += from_bits(s[0]);
    edges += s[1];
  }
  scale_ = edges > 0 && total > 0.0 ? total / double(edges) : 1.0;

  u_.assign(n, Eigen::Vector3d::Zero());
  in_region_.assign(n, 0);
  region_.clear();
  changed_.clear();
  axis_.resize(n);
  cone_.begin(n);
  env_.begin(n);
}

// The piece for EnvelopeAxis: links read from the adjacency (link_axis_slab), labels in
// SparseLabels, runs by PartitionedLabels::correct across the pieces. The scan reads every
// link of the piece's copies of the start (S); the check the owned region vertices' links,
// a link between two region vertices once, at its end of lower global id.
struct PartitionedEnvelope::Net
{
  PartitionedEnvelope& p;
  const LinkMesh& mesh;
  Exchange& exchange;
  const std::vector<index_t>& start;
  const std::vector<index_t>& fixed;
  const double (&top)[3][2]; // [axis][sign > 0]: the largest start y over S

  bool is_fixed(index_t v) const { return p.is_fixed(v); }
  double u(index_t v, int axis) const { return p.u_[std::size_t(v)][axis]; }
  double start_u(index_t v, int axis) const { return u(v, axis); }
  void begin_axis(int) {}
  void end_runs(int) {}
  template<class F>
  void for_each_scanned(F f) const
  {
    for (index_t v : start)
      f(v);
  }
  template<class F>
  void for_each_checked(F f) const
  {
    for (index_t v : p.region_)
      if (p.pieces_.owned(v))
        f(v);
  }
  bool scanned_from(index_t, index_t) const { return false; }
  bool checked_from(index_t m, index_t v) const
  {
    return p.in_region_[std::size_t(m)] && p.pieces_.gid(m) < p.pieces_.gid(v);
  }
  template<class F>
  void for_each_link(index_t v, int axis, F f) const
  {
    const Adjacency& adj = *mesh.adjacency;
    double lo, hi;
    for (const index_t* m = adj.begin(v); m != adj.end(v); ++m)
      if (link_axis_slab(mesh, v, *m, axis, lo, hi))
        f(*m, lo, hi, p.is_fixed(*m));
  }
  void begin_run(int, double) { p.env_.begin(std::size_t(p.n_)); }
  double label(index_t v, int axis, double sign) const
  {
    return p.env_.has(v) ? p.env_.value[std::size_t(v)] : p.start_y(v, axis, sign);
  }
  void set_label(index_t v, int, double, double y) { p.env_.set(v, y); }
  const std::vector<index_t>& touched() const { return p.env_.touched; }
  const std::vector<index_t>& raised_to_check() const { return touched(); }
  // Relaxes b's links into its free neighbours a: y_a <= y_b + ub(a, b) on y = sign u.
  auto relax(int axis, double sign) const
  {
    return [this, axis, sign](index_t b, double y, const auto& lower)
    {
      const Adjacency& adj = *mesh.adjacency;
      double lo, hi;
      for (const index_t* it = adj.begin(b); it != adj.end(b); ++it)
        if (!p.is_fixed(*it) && link_axis_slab(mesh, *it, b, axis, lo, hi))
          lower(*it, y + (sign > 0.0 ? hi : -lo));
    };
  }
  // The fixed vertices' cones, kept below top.
  template<class F>
  void cone(int axis, double sign, F raise)
  {
    const double top_here = top[axis][sign > 0.0];
    SparseLabels& cone = p.cone_;
    cone.begin(std::size_t(p.n_));
    std::vector<index_t> seeds, owned_fixed;
    for (index_t f : fixed)
    {
      cone.set(f, p.start_y(f, axis, sign));
      seeds.push_back(f);
      if (p.pieces_.owned(f))
        owned_fixed.push_back(f);
    }
    const auto label = [&](index_t v)
    { return cone.has(v) ? cone.value[std::size_t(v)] : std::numeric_limits<double>::infinity(); };
    p.supersteps_ += p.pieces_.correct(
      cone, label, relax(axis, sign), [&](index_t, double cap) { return cap < top_here; }, seeds,
      owned_fixed, exchange);
    for (index_t a : cone.touched)
      raise(a, cone.value[std::size_t(a)]);
  }
  void min_pass(int axis, double sign, std::vector<index_t>& seeds)
  {
    // The labels the cones raised are the same on every copy: nothing to send first.
    p.supersteps_ += p.pieces_.correct(
      p.env_, [&](index_t v) { return label(v, axis, sign); }, relax(axis, sign),
      [](index_t, double) { return true; }, seeds, {}, exchange);
  }
  void change(index_t v, int axis, double value)
  {
    p.u_[std::size_t(v)][axis] = value;
    mark_changed(p.in_region_[std::size_t(v)], v, p.region_, p.changed_);
  }
};

bool PartitionedEnvelope::is_fixed(index_t v) const
{
  return v == grasp_ || mesh_->is_pinned(v);
}

ProjectionReport PartitionedEnvelope::project(const LinkMesh& mesh, std::int64_t grasp,
  const std::vector<index_t>& vertices, const Displacements& values,
  const ProjectionOptions& options, Exchange& exchange)
{
  mesh_ = &mesh;
  supersteps_ = 0;
  changed_total_ = 0;
  for (index_t v : region_)
  {
    u_[std::size_t(v)].setZero();
    in_region_[std::size_t(v)] = 0;
  }
  region_.clear();
  changed_.clear();
  grasp_ = grasp >= 0 ? pieces_.local(grasp) : -1;
  const auto enter = [&](index_t v)
  {
    if (!in_region_[std::size_t(v)])
    {
      in_region_[std::size_t(v)] = 1;
      region_.push_back(v);
    }
  };
  for (std::size_t i = 0; i < vertices.size() && i < values.size(); ++i)
    if (vertices[i] >= 0 && vertices[i] < n_)
    {
      u_[std::size_t(vertices[i])] = values[i];
      enter(vertices[i]);
    }
  if (grasp_ >= 0)
    enter(grasp_);
  // S (start + grasp) by the copy that stands for each vertex; aliases follow at the end.
  std::vector<index_t> start;
  for (index_t v : region_)
  {
    if (pieces_.stands_for_itself(v))
      start.push_back(v);
  }
  const Adjacency& adj = *mesh.adjacency;

  // The fixed vertices' labels this piece sets first: the grasp (every copy), and the
  // owned pins in S or next to it (their owner holds their ring).
  std::vector<index_t> fixed;
  if (grasp_ >= 0)
    fixed.push_back(grasp_);
  if (!mesh.pinned.empty())
  {
    std::vector<index_t> near;
    for (index_t v : start)
    {
      near.push_back(v);
      near.insert(near.end(), adj.begin(v), adj.end(v));
    }
    for (index_t p : near)
      if (p != grasp_ && pieces_.owned(p) && mesh.is_pinned(p))
        fixed.push_back(p);
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  }

  // Reductions: per axis whether S is all zero, and top for both signs.
  std::vector<std::int64_t> mine;
  for (int axis = 0; axis < 3; ++axis)
  {
    bool zero = true;
    double top_plus = 0.0, top_minus = 0.0;
    for (index_t v : start)
    {
      const double x = u_[std::size_t(v)][axis];
      zero = zero && x == 0.0;
      top_plus = std::max(top_plus, x);
      top_minus = std::max(top_minus, -x);
    }
    mine.insert(mine.end(), { zero ? 1 : 0, bits(top_plus), bits(top_minus) });
  }
  bool zero[3] = { true, true, true };
  double top[3][2] = { { 0.0, 0.0 }, { 0.0, 0.0 }, { 0.0, 0.0 } }; // [axis][sign > 0]
  for (const auto& p : exchange.all_gather(mine))
    for (int axis = 0; axis < 3; ++axis)
    {
      zero[axis] = zero[axis] && p[std::size_t(3 * axis)] != 0;
      top[axis][1] = std::max(top[axis][1], from_bits(p[std::size_t(3 * axis + 1)]));
      top[axis][0] = std::max(top[axis][0], from_bits(p[std::size_t(3 * axis + 2)]));
    }

  Net net{ *this, mesh, exchange, start, fixed, top };
  std::vector<std::int64_t> worst_bits(3, bits(0.0));
  for (int axis = 0; axis < 3; ++axis)
    if (!zero[axis])
      worst_bits[std::size_t(axis)] = bits(axis_.run(net, axis));
  // Copies of a vertex follow it.
  for (const auto& [copy, rep] : pieces_.aliases())
    if (in_region_[std::size_t(rep)] == 2 && u_[std::size_t(copy)] != u_[std::size_t(rep)])
    {
      u_[std::size_t(copy)] = u_[std::size_t(rep)];
      mark_changed(in_region_[std::size_t(copy)], copy, region_, changed_);
    }

  std::int64_t changed_owned = 0, region_owned = 0;
  for (index_t v : region_)
    if (pieces_.owned(v))
    {
      ++region_owned;
      changed_owned += in_region_[std::size_t(v)] == 2;
    }
  worst_bits.push_back(changed_owned);
  worst_bits.push_back(region_owned);
  double worst[3] = { 0.0, 0.0, 0.0 };
  std::int64_t changed_total = 0, region_total = 0;
  for (const auto& p : exchange.all_gather(worst_bits))
  {
    for (int axis = 0; axis < 3; ++axis)
      worst[axis] = std::max(worst[axis], from_bits(p[std::size_t(axis)]));
    changed_total += p[3];
    region_total += p[4];
  }
  double squared = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    squared += worst[axis] * worst[axis];
  changed_total_ = std::size_t(changed_total);
  ProjectionReport report;
  report.iterations = 1;
  report.violation = std::sqrt(squared) / scale_;
  report.converged = report.violation <= options.tolerance;
  report.region = std::size_t(region_total);
  return report;
}

} // namespace geoshaping
