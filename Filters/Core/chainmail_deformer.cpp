#include "geoshaping/chainmail_deformer.h"

#include "geoshaping/valid_region.h"

#include <algorithm>
#include <cmath>

namespace geoshaping
{

void ChainMailDeformer::set_mesh(const double* xyz, index_t n, Adjacency adjacency)
{
  adj_ = std::move(adjacency);
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
  state_.resize(std::size_t(n));
  for (index_t v = 0; v < n; ++v)
  {
    state_[v].rest = Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]) - origin_;
    state_[v].disp.setZero();
  }
  tags_.assign(std::size_t(n), VertexTag{ 0, 0, 0.0f, -1 });
  pinned_.clear();
  committed_.clear();
  frame_ = 0;
  moved_.clear();
  previously_moved_.clear();
  set_uniform_malleability(0.5);
}

namespace
{
double sanitize(double x)
{
  return std::isnan(x) ? 0.0 : std::clamp(x, 0.0, 1.0);
}
} // namespace

template <class T>
std::size_t ChainMailDeformer::assign_malleability(const T* m)
{
  std::size_t bad = 0;
  for (std::size_t v = 0; v < tags_.size(); ++v)
  {
    const double x = double(m[v]);
    const double c = sanitize(x);
    bad += (c != x);
    tags_[v].malleability = float(c);
  }
  rebuild_ranks();
  return bad;
}

std::size_t ChainMailDeformer::set_malleability(const float* m) { return assign_malleability(m); }

std::size_t ChainMailDeformer::set_malleability(const double* m) { return assign_malleability(m); }

void ChainMailDeformer::set_uniform_malleability(double m)
{
  for (VertexTag& t : tags_)
    t.malleability = float(sanitize(m));
  rebuild_ranks();
}

void ChainMailDeformer::rebuild_ranks()
{
  std::vector<float> distinct(tags_.size());
  for (std::size_t v = 0; v < tags_.size(); ++v)
    distinct[v] = tags_[v].malleability;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  for (VertexTag& t : tags_)
    t.rank = index_t(
      std::lower_bound(distinct.begin(), distinct.end(), t.malleability) - distinct.begin());
  num_ranks_ = std::max<index_t>(1, index_t(distinct.size()));
  buckets_.reset_ranks(num_ranks_);
}

void ChainMailDeformer::set_pinned(const std::uint8_t* mask)
{
  if (!mask)
  {
    pinned_.clear();
    return;
  }
  pinned_.assign(mask, mask + state_.size());
}

void ChainMailDeformer::reset()
{
  for (index_t v : moved_)
    state_[v].disp.setZero();
  previously_moved_.swap(moved_);
  moved_.clear();
  if (++frame_ == 0) // wrapped: stale stamps could alias the new frame
  {
    for (VertexTag& t : tags_)
      t.stamp = 0;
    frame_ = 1;
  }
}

void ChainMailDeformer::commit()
{
  if (committed_.empty() && !moved_.empty())
    committed_.assign(state_.size(), Eigen::Vector3d::Zero());
  for (index_t v : moved_)
  {
    VertexState& s = state_[std::size_t(v)];
    s.rest += s.disp;
    committed_[std::size_t(v)] += s.disp;
    s.disp.setZero();
  }
}

void ChainMailDeformer::set_rest(
  index_t v, const Eigen::Vector3d& rest_local, const Eigen::Vector3d& offset)
{
  if (committed_.empty())
    committed_.assign(state_.size(), Eigen::Vector3d::Zero());
  state_[std::size_t(v)].rest = rest_local;
  committed_[std::size_t(v)] = offset;
}

FrameResult ChainMailDeformer::deform(index_t grasp, const Eigen::Vector3d& displacement)
{
  reset();
  FrameResult result;
  if (grasp < 0 || grasp >= size())
  {
    result.message = "grasp vertex " + std::to_string(grasp) + " is outside [0, " +
      std::to_string(size()) + ")";
    return result;
  }
  if (!displacement.allFinite())
  {
    result.message = "displacement is not finite";
    return result;
  }
  if (!state_[grasp].rest.allFinite())
  {
    result.message = "grasp vertex has a non-finite rest position";
    return result;
  }
  if (pinned(grasp))
  {
    result.message = "grasp vertex " + std::to_string(grasp) + " is pinned";
    return result;
  }
  state_[grasp].disp = displacement;
  tags_[grasp].stamp = frame_;
  tags_[grasp].sponsor = -1;
  moved_.push_back(grasp);
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

template <class Queue>
void ChainMailDeformer::propagate(Queue& queue, index_t grasp, FrameResult& result)
{
  // Where candidate c must move given sponsor s: the nearest point of the box to its
  // rest position, in displacements u[s] + [lo - o, hi - o] (valid_region.h).
  auto required_displacement = [&](const VertexState& c, float m, const VertexState& s) {
    const Eigen::Vector3d o = c.rest - s.rest;
    if (!o.allFinite())
      return Eigen::Vector3d::Zero().eval();
    const Box b = displacement_bounds(o, transfer_(m));
    return Eigen::Vector3d::Zero().cwiseMax(s.disp + b.lo).cwiseMin(s.disp + b.hi).eval();
  };
  auto sponsor_neighbours = [&](index_t s) {
    for (const index_t* it = adj_.begin(s); it != adj_.end(s); ++it)
    {
      const index_t c = *it;
      const VertexTag& tag = tags_[c];
      if (tag.stamp == frame_ || pinned(c))
        continue;
      double violation = 0.0;
      if constexpr (Queue::needs_violation)
        violation = required_displacement(state_[c], tag.malleability, state_[s]).norm();
      queue.push({ c, s }, tag.rank, violation);
    }
  };

  queue.clear();
  sponsor_neighbours(grasp);
  Candidate cand;
  while (queue.pop(cand))
  {
    ++result.examined;
    VertexTag& tag = tags_[cand.vertex];
    if (tag.stamp == frame_)
      continue;
    VertexState& c = state_[cand.vertex];
    const Eigen::Vector3d target = required_displacement(c, tag.malleability, state_[cand.sponsor]);
    if (target.isZero(0.0))
      continue;
    c.disp = target;
    tag.stamp = frame_;
    tag.sponsor = cand.sponsor;
    moved_.push_back(cand.vertex);
    sponsor_neighbours(cand.vertex);
  }
}

std::size_t ChainMailDeformer::memory_bytes() const
{
  return state_.capacity() * sizeof(VertexState) + tags_.capacity() * sizeof(VertexTag) +
    pinned_.capacity() + committed_.capacity() * sizeof(Eigen::Vector3d) + (moved_.capacity() + previously_moved_.capacity()) * sizeof(index_t) +
    adj_.offsets.capacity() * sizeof(std::int64_t) + adj_.neighbors.capacity() * sizeof(index_t) +
    buckets_.memory_bytes();
}

} // namespace geoshaping
