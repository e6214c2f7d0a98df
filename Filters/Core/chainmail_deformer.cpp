#include "geoshaping/chainmail_deformer.h"

#include "geoshaping/valid_region.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace geoshaping
{

namespace
{
// Spreads the low 21 bits of x so that two zero bits separate each (Morton interleave).
std::uint64_t spread3(std::uint64_t x)
{
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}
} // namespace

void ChainMailDeformer::set_mesh(const double* xyz, index_t n, Adjacency adjacency)
{
  const Adjacency adj = std::move(adjacency); // the internal copy replaces it below
  {
    std::lock_guard<std::mutex> lock(caller_adjacency_mutex());
    caller_adjacency_.reset();
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.0), hi = lo;
  bool first = true;
  for (index_t v = 0; v < n; ++v)
  {
    const Eigen::Vector3d p(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    if (!p.allFinite())
      continue;
    lo = first ? p : lo.cwiseMin(p);
    hi = first ? p : hi.cwiseMax(p);
    first = false;
  }
  origin_ = 0.5 * (lo + hi);

  // Internal order: Morton code of the rest position on a 2^21 lattice over the bounding
  // box (ties and non-finite positions by caller id, the latter last).
  const std::size_t un = std::size_t(std::max<index_t>(n, 0));
  std::vector<std::pair<std::uint64_t, index_t>> order(un);
  const Eigen::Vector3d extent = hi - lo;
  for (index_t v = 0; v < n; ++v)
  {
    const Eigen::Vector3d p(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    std::uint64_t code = ~std::uint64_t(0);
    if (p.allFinite())
    {
      code = 0;
      for (int i = 0; i < 3; ++i)
      {
        const double f = extent[i] > 0.0 ? (p[i] - lo[i]) / extent[i] : 0.0;
        const auto q = std::uint64_t(std::clamp(f, 0.0, 1.0) * double(0x1fffff));
        code |= spread3(q) << i;
      }
    }
    order[std::size_t(v)] = { code, v };
  }
  std::sort(order.begin(), order.end());
  inner_of_.resize(un);
  outer_of_.resize(un);
  for (std::size_t i = 0; i < un; ++i)
  {
    outer_of_[i] = order[i].second;
    inner_of_[std::size_t(order[i].second)] = index_t(i);
  }
  std::vector<std::pair<std::uint64_t, index_t>>().swap(order);

  // Internal CSR: each row keeps the caller's neighbour order (it decides queue order).
  // 32-bit row offsets: 4 billion neighbour entries is far beyond any mesh that fits
  // in memory next to them (checked).
  if (adj.neighbors.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("ChainMailDeformer: more than 2^32 adjacency entries");
  offsets_.assign(un + 1, 0);
  neighbors_.resize(adj.neighbors.size());
  const bool has_adjacency = adj.size() == n;
  for (std::size_t i = 0; i < un; ++i)
  {
    const index_t v = outer_of_[i];
    std::uint32_t k = offsets_[i];
    if (has_adjacency)
      for (const index_t* it = adj.begin(v); it != adj.end(v); ++it)
        neighbors_[k++] = inner_of_[std::size_t(*it)];
    offsets_[i + 1] = k;
  }
  neighbors_.resize(offsets_[un]);

  nodes_.resize(un);
  for (std::size_t i = 0; i < un; ++i)
  {
    const index_t v = outer_of_[i];
    nodes_[i].rest = Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]) - origin_;
    nodes_[i].stamp = 0;
    nodes_[i].rank = 0;
  }
  slot_.assign(un, 0);
  pinned_.clear();
  pinned_inner_.clear();
  committed_.clear();
  frame_ = 1; // stamps are 0: nothing has moved
  moved_.clear();
  previously_moved_.clear();
  moved_rec_.clear();
  set_uniform_malleability(0.5);
}

template<class T>
std::size_t ChainMailDeformer::assign_malleability(const T* m)
{
  std::size_t bad = 0;
  std::vector<float> values(nodes_.size());
  for (std::size_t v = 0; v < values.size(); ++v)
  {
    const double x = double(m[v]);
    const double c = clean_malleability(x);
    bad += (c != x);
    values[v] = float(c);
  }
  rebuild_ranks(values);
  return bad;
}

std::size_t ChainMailDeformer::set_malleability(const float* m)
{
  return assign_malleability(m);
}

std::size_t ChainMailDeformer::set_malleability(const double* m)
{
  return assign_malleability(m);
}

void ChainMailDeformer::set_uniform_malleability(double m)
{
  distinct_.assign(nodes_.empty() ? 0 : 1, float(clean_malleability(m)));
  for (Node& node : nodes_)
    node.rank = 0;
  finish_ranks();
}

void ChainMailDeformer::set_transfer_function(const TransferFunction& tf)
{
  transfer_ = tf;
  rebuild_rank_params();
}

// malleability(v) is distinct_[rank]: the value stored, except that -0 and +0 share a
// rank (and so read back as whichever of the two sorted first).
void ChainMailDeformer::rebuild_ranks(const std::vector<float>& values)
{
  distinct_ = values;
  std::sort(distinct_.begin(), distinct_.end());
  distinct_.erase(std::unique(distinct_.begin(), distinct_.end()), distinct_.end());
  distinct_.shrink_to_fit();
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    nodes_[i].rank = index_t(
      std::lower_bound(distinct_.begin(), distinct_.end(), values[std::size_t(outer_of_[i])]) -
      distinct_.begin());
  finish_ranks();
}

void ChainMailDeformer::finish_ranks()
{
  num_ranks_ = std::max<index_t>(1, index_t(distinct_.size()));
  buckets_.reset_ranks(num_ranks_);
  rebuild_rank_params();
}

void ChainMailDeformer::rebuild_rank_params()
{
  rank_params_.resize(distinct_.size());
  for (std::size_t r = 0; r < distinct_.size(); ++r)
  {
    // The same arithmetic as displacement_bounds() on transfer_(m).
    const ChainMailParams p = transfer_(distinct_[r]);
    rank_params_[r] = { p.stretch - 1.0, p.compression - 1.0, p.shear };
  }
}

void ChainMailDeformer::set_pinned(const std::uint8_t* mask)
{
  if (!mask)
  {
    pinned_.clear();
    pinned_inner_.clear();
    return;
  }
  pinned_.assign(mask, mask + nodes_.size());
  pinned_inner_.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    pinned_inner_[i] = pinned_[std::size_t(outer_of_[i])];
}

void ChainMailDeformer::reset()
{
  previously_moved_.swap(moved_);
  moved_.clear();
  moved_rec_.clear();
  if (++frame_ == 0) // wrapped: stale stamps could alias the new frame
  {
    for (Node& node : nodes_)
      node.stamp = 0;
    frame_ = 1;
  }
}

void ChainMailDeformer::commit()
{
  if (committed_.empty() && !moved_.empty())
    committed_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  for (std::size_t slot = 0; slot < moved_rec_.size(); ++slot)
  {
    MovedRecord& r = moved_rec_[slot];
    nodes_[std::size_t(r.vertex)].rest += r.disp;
    committed_[std::size_t(moved_[slot])] += r.disp;
    r.disp.setZero();
  }
}

void ChainMailDeformer::set_rest(
  index_t v, const Eigen::Vector3d& rest_local, const Eigen::Vector3d& offset)
{
  if (committed_.empty())
    committed_.assign(nodes_.size(), Eigen::Vector3d::Zero());
  nodes_[inner(v)].rest = rest_local;
  committed_[std::size_t(v)] = offset;
}

FrameResult ChainMailDeformer::deform(index_t grasp, const Eigen::Vector3d& displacement)
{
  reset();
  FrameResult result;
  if (grasp < 0 || grasp >= size())
  {
    result.message =
      "grasp vertex " + std::to_string(grasp) + " is outside [0, " + std::to_string(size()) + ")";
    return result;
  }
  if (!displacement.allFinite())
  {
    result.message = "displacement is not finite";
    return result;
  }
  if (!rest_local(grasp).allFinite())
  {
    result.message = "grasp vertex has a non-finite rest position";
    return result;
  }
  if (pinned(grasp))
  {
    result.message = "grasp vertex " + std::to_string(grasp) + " is pinned";
    return result;
  }
  const std::size_t g = inner(grasp);
  nodes_[g].stamp = frame_;
  slot_[g] = 0;
  moved_rec_.push_back({ displacement, index_t(g), -1 });
  moved_.push_back(grasp);
  grasp = index_t(g);
  switch (queue_kind_)
  {
    case QueueKind::fifo:
      propagate(fifo_, grasp, result);
      break;
    case QueueKind::priority:
      propagate(heap_, grasp, result);
      break;
    case QueueKind::fifo_priority:
      propagate(buckets_, grasp, result);
      break;
    case QueueKind::max_violation:
      propagate(violation_, grasp, result);
      break;
  }
  result.ok = true;
  result.moved = moved_.size();
  return result;
}

namespace
{
// displacement_bounds() (valid_region.h) with the transfer function's values evaluated
// once per malleability rank: the same operations in the same order, so bit-identical.
template<class Params>
inline void bounds(
  const Eigen::Vector3d& o, const Params& p, Eigen::Vector3d& lo_out, Eigen::Vector3d& hi_out)
{
  const Eigen::Vector3d a = o.cwiseAbs();
  const Eigen::Vector3d s(a.y() + a.z(), a.x() + a.z(), a.x() + a.y());
  for (int i = 0; i < 3; ++i)
  {
    const double near = p.compression1 * o[i];
    const double far = p.stretch1 * o[i];
    const double lo = o[i] >= 0.0 ? near : far;
    const double hi = o[i] >= 0.0 ? far : near;
    lo_out[i] = lo - p.shear * s[i];
    hi_out[i] = hi + p.shear * s[i];
  }
}
} // namespace

// How far ahead in the queue the adjacency row is prefetched (measured: 8-32 alike;
// prefetching the neighbours' records as well did not help).
constexpr index_t prefetch_distance = 8;

template<class Queue>
void ChainMailDeformer::propagate(Queue& queue, index_t grasp, FrameResult& result)
{
  // The frame is a template argument: the axes loop is the same code as before the
  // option existed.
  if (frame_kind_ == ValidRegionFrame::link)
    propagate<ValidRegionFrame::link>(queue, grasp, result);
  else
    propagate<ValidRegionFrame::axes>(queue, grasp, result);
}

template<ValidRegionFrame Frame, class Queue>
void ChainMailDeformer::propagate(Queue& queue, index_t grasp, FrameResult& result)
{
  Node* const nodes = nodes_.data();
  const RankParams* const params = rank_params_.data();
  const std::uint32_t* const offsets = offsets_.data();
  const index_t* const neighbors = neighbors_.data();
  const std::uint8_t* const pinned = pinned_inner_.empty() ? nullptr : pinned_inner_.data();
  const std::uint32_t frame = frame_;

  // Where candidate c must move given sponsor s: the nearest point of the region to its
  // rest position. Axes: in displacements u[s] + [lo - o, hi - o] (valid_region.h).
  // Link: u[s] + the projection of -u[s] onto the cylinder, exactly u[s] when c is rigid
  // (required_displacement() in valid_region.h, with the per-rank parameters).
  auto required_displacement = [&](const Node& c, const Node& s, const Eigen::Vector3d& su)
  {
    const Eigen::Vector3d o = c.rest - s.rest;
    if (!o.allFinite())
      return Eigen::Vector3d::Zero().eval();
    const RankParams& p = params[c.rank];
    if constexpr (Frame == ValidRegionFrame::link)
    {
      if (p.stretch1 == 0.0 && p.compression1 == 0.0 && p.shear == 0.0)
        return su;
      return (su + link_displacement_projection(o, p.stretch1, p.compression1, p.shear, -su))
        .eval();
    }
    else
    {
      Eigen::Vector3d lo, hi;
      bounds(o, p, lo, hi);
      return Eigen::Vector3d::Zero().cwiseMax(su + lo).cwiseMin(su + hi).eval();
    }
  };
  auto sponsor_neighbours = [&](index_t s, index_t s_slot)
  {
    const index_t* const end = neighbors + offsets[s + 1];
    for (const index_t* it = neighbors + offsets[s]; it != end; ++it)
    {
      const index_t c = *it;
      const Node& node = nodes[c];
      if (node.stamp == frame || (pinned && pinned[c]))
        continue;
      double violation = 0.0;
      if constexpr (Queue::needs_violation)
        violation =
          required_displacement(node, nodes[s], moved_rec_[std::size_t(s_slot)].disp).norm();
      queue.push({ c, s_slot }, node.rank, violation);
    }
  };

  queue.clear();
  sponsor_neighbours(grasp, 0);
  std::size_t examined = 0;
  Candidate cand;
  while (queue.pop(cand))
  {
    ++examined;
    if constexpr (Queue::can_peek)
    {
      // The adjacency row of a candidate a few places behind, read if it moves.
      Candidate ahead;
#if defined(__GNUC__)
      if (queue.peek(prefetch_distance, ahead))
        __builtin_prefetch(neighbors + offsets[ahead.vertex]);
#endif
    }
    Node& c = nodes[cand.vertex];
    if (c.stamp == frame)
      continue;
    const MovedRecord& s = moved_rec_[std::size_t(cand.sponsor)];
    const Eigen::Vector3d target = required_displacement(c, nodes[s.vertex], s.disp);
    if (target.isZero(0.0))
      continue;
    const index_t slot = index_t(moved_rec_.size());
    c.stamp = frame;
    slot_[std::size_t(cand.vertex)] = slot;
    moved_rec_.push_back({ target, cand.vertex, cand.sponsor });
    moved_.push_back(outer_of_[std::size_t(cand.vertex)]);
    sponsor_neighbours(cand.vertex, slot);
  }
  result.examined = examined;
}

std::mutex& ChainMailDeformer::caller_adjacency_mutex()
{
  static std::mutex m;
  return m;
}

const Adjacency& ChainMailDeformer::adjacency() const
{
  std::lock_guard<std::mutex> lock(caller_adjacency_mutex());
  if (!caller_adjacency_)
  {
    // The internal rows keep each caller row's order: mapping back gives the input.
    auto adj = std::make_shared<Adjacency>();
    const std::size_t n = nodes_.size();
    adj->offsets.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v)
    {
      const std::size_t i = inner(index_t(v));
      adj->offsets[v + 1] = adj->offsets[v] + std::int64_t(offsets_[i + 1] - offsets_[i]);
    }
    adj->neighbors.resize(neighbors_.size());
    for (std::size_t v = 0; v < n; ++v)
    {
      const std::size_t i = inner(index_t(v));
      std::int64_t k = adj->offsets[v];
      for (std::uint32_t e = offsets_[i]; e < offsets_[i + 1]; ++e)
        adj->neighbors[std::size_t(k++)] = outer_of_[std::size_t(neighbors_[e])];
    }
    caller_adjacency_ = std::move(adj);
  }
  return *caller_adjacency_;
}

std::size_t ChainMailDeformer::caller_adjacency_bytes() const
{
  std::lock_guard<std::mutex> lock(caller_adjacency_mutex());
  if (!caller_adjacency_)
    return 0;
  return caller_adjacency_->offsets.capacity() * sizeof(std::int64_t) +
         caller_adjacency_->neighbors.capacity() * sizeof(index_t);
}

std::size_t ChainMailDeformer::memory_bytes() const
{
  return nodes_.capacity() * sizeof(Node) + slot_.capacity() * sizeof(index_t) +
         distinct_.capacity() * sizeof(float) + rank_params_.capacity() * sizeof(RankParams) +
         pinned_.capacity() + pinned_inner_.capacity() +
         committed_.capacity() * sizeof(Eigen::Vector3d) +
         (moved_.capacity() + previously_moved_.capacity()) * sizeof(index_t) +
         moved_rec_.capacity() * sizeof(MovedRecord) +
         (inner_of_.capacity() + outer_of_.capacity()) * sizeof(index_t) +
         caller_adjacency_bytes() + offsets_.capacity() * sizeof(std::uint32_t) +
         neighbors_.capacity() * sizeof(index_t) + buckets_.memory_bytes();
}

} // namespace geoshaping
