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
  down_.assign(n, std::numeric_limits<double>::quiet_NaN());
  cone_.begin(n);
  env_.begin(n);
}

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

  double lo, hi;
  std::vector<index_t> seeds, seeds_up, down;
  const auto prescan = [&](int axis)
  {
    seeds.clear();
    seeds_up.clear();
    for (index_t v : start)
      for (const index_t* m = adj.begin(v); m != adj.end(v); ++m)
      {
        if (!link_axis_slab(mesh, v, *m, axis, lo, hi))
          continue;
        const double w = u_[std::size_t(v)][axis] - u_[std::size_t(*m)][axis];
        const index_t high = w > hi ? v : (w < lo ? *m : -1);
        if (high < 0)
          continue;
        const index_t low = high == v ? *m : v;
        if (!is_fixed(high))
          seeds.push_back(low);
        if (!is_fixed(low))
          seeds_up.push_back(high);
      }
  };
  const double infinity = std::numeric_limits<double>::infinity();
  // One envelope run (D: sign +1, U: sign -1) into env_, y = sign u.
  const auto envelope = [&](int axis, double sign, std::vector<index_t>& from)
  {
    // Relaxes b's links into its free neighbours a: y_a <= y_b + ub(a, b) on y = s u.
    const auto links = [&](double s)
    {
      return [&, s](index_t b, double y, const auto& lower)
      {
        for (const index_t* it = adj.begin(b); it != adj.end(b); ++it)
          if (!is_fixed(*it) && link_axis_slab(mesh, *it, b, axis, lo, hi))
            lower(*it, y + (s > 0.0 ? hi : -lo));
      };
    };
    // The fixed vertices' cones on y' = -y, kept below top.
    const double cone_sign = -sign;
    const double top_here = top[axis][cone_sign > 0.0];
    cone_.begin(std::size_t(n_));
    std::vector<index_t> cone_seeds, owned_fixed;
    for (index_t f : fixed)
    {
      cone_.set(f, start_y(f, axis, cone_sign));
      cone_seeds.push_back(f);
      if (pieces_.owned(f))
        owned_fixed.push_back(f);
    }
    const auto cone_label = [&](index_t v)
    { return cone_.has(v) ? cone_.value[std::size_t(v)] : infinity; };
    supersteps_ += pieces_.correct(
      cone_, cone_label, links(cone_sign), [&](index_t, double cap) { return cap < top_here; },
      cone_seeds, owned_fixed, exchange);
    env_.begin(std::size_t(n_));
    const auto value = [&](index_t v)
    { return env_.has(v) ? env_.value[std::size_t(v)] : start_y(v, axis, sign); };
    for (index_t a : cone_.touched)
      if (!is_fixed(a) && cone_.value[std::size_t(a)] < -value(a))
        env_.set(a, -cone_.value[std::size_t(a)]);
    // Links the cones broke seed the min run too (the raised values are the same on
    // every copy: nothing to send first).
    for (index_t v : env_.touched)
      for (const index_t* m = adj.begin(v); m != adj.end(v); ++m)
      {
        if (!link_axis_slab(mesh, v, *m, axis, lo, hi))
          continue;
        const double yv = value(v), ym = value(*m);
        const double ub_vm = sign > 0.0 ? hi : -lo;
        const double ub_mv = sign > 0.0 ? -lo : hi;
        if (yv > ym + ub_vm && !is_fixed(v))
          from.push_back(*m);
        if (ym > yv + ub_mv && !is_fixed(*m))
          from.push_back(v);
      }
    supersteps_ += pieces_.correct(
      env_, value, links(sign), [](index_t, double) { return true; }, from, {}, exchange);
  };

  double squared = 0.0;
  std::vector<std::int64_t> worst_bits(3, bits(0.0));
  for (int axis = 0; axis < 3; ++axis)
  {
    if (zero[axis])
      continue;
    prescan(axis);
    envelope(axis, 1.0, seeds);
    down.clear();
    for (index_t v : env_.touched)
    {
      down.push_back(v);
      down_[std::size_t(v)] = env_.value[std::size_t(v)]; // y = u for sign +1
    }
    envelope(axis, -1.0, seeds_up);
    const auto combine = [&](index_t v)
    {
      const double old = u_[std::size_t(v)][axis];
      const double d = std::isnan(down_[std::size_t(v)]) ? old : down_[std::size_t(v)];
      const double u = env_.has(v) ? -env_.value[std::size_t(v)] : old;
      const double mid = d == u ? d : 0.5 * (d + u);
      if (is_fixed(v) || mid == old || !std::isfinite(mid))
        return;
      u_[std::size_t(v)][axis] = mid;
      if (!in_region_[std::size_t(v)])
        region_.push_back(v);
      if (in_region_[std::size_t(v)] != 2)
        changed_.push_back(v);
      in_region_[std::size_t(v)] = 2;
    };
    for (index_t v : down)
      combine(v);
    for (index_t v : env_.touched)
      combine(v);
    for (index_t v : down)
      down_[std::size_t(v)] = std::numeric_limits<double>::quiet_NaN();
    // E_link bound on this axis over the owned vertices' links (as LinkProjector: a link
    // between two region vertices once, at its end of lower global id).
    double worst = 0.0;
    for (index_t v : region_)
    {
      if (!pieces_.owned(v))
        continue;
      for (const index_t* m = adj.begin(v); m != adj.end(v); ++m)
        if (!(in_region_[std::size_t(*m)] && pieces_.gid(*m) < pieces_.gid(v)) &&
            link_axis_slab(mesh, v, *m, axis, lo, hi) && !(is_fixed(v) && is_fixed(*m)))
        {
          const double w = u_[std::size_t(v)][axis] - u_[std::size_t(*m)][axis];
          worst = std::max(worst, std::max(lo - w, w - hi));
        }
    }
    worst_bits[std::size_t(axis)] = bits(worst);
  }
  // Copies of a vertex follow it.
  for (const auto& [copy, rep] : pieces_.aliases())
    if (in_region_[std::size_t(rep)] == 2 && u_[std::size_t(copy)] != u_[std::size_t(rep)])
    {
      u_[std::size_t(copy)] = u_[std::size_t(rep)];
      if (!in_region_[std::size_t(copy)])
        region_.push_back(copy);
      if (in_region_[std::size_t(copy)] != 2)
        changed_.push_back(copy);
      in_region_[std::size_t(copy)] = 2;
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
