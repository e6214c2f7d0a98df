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
  rest_.resize(std::size_t(n));
  for (index_t v = 0; v < n; ++v)
    rest_[v] = Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]) - origin_;
  disp_.assign(std::size_t(n), Eigen::Vector3d::Zero());
  stamp_.assign(std::size_t(n), 0);
  sponsor_.assign(std::size_t(n), -1);
  pinned_.clear();
  frame_ = 0;
  moved_.clear();
  previously_moved_.clear();
  set_uniform_malleability(0.5);
}

namespace
{
template <class T>
std::size_t sanitize(const T* m, std::vector<float>& out)
{
  std::size_t bad = 0;
  for (std::size_t v = 0; v < out.size(); ++v)
  {
    const double x = double(m[v]);
    const double c = std::isnan(x) ? 0.0 : std::clamp(x, 0.0, 1.0);
    bad += (c != x);
    out[v] = float(c);
  }
  return bad;
}
} // namespace

std::size_t ChainMailDeformer::set_malleability(const float* m)
{
  const std::size_t bad = sanitize(m, malleability_);
  rebuild_ranks();
  return bad;
}

std::size_t ChainMailDeformer::set_malleability(const double* m)
{
  const std::size_t bad = sanitize(m, malleability_);
  rebuild_ranks();
  return bad;
}

void ChainMailDeformer::set_uniform_malleability(double m)
{
  const double c = std::isnan(m) ? 0.0 : std::clamp(m, 0.0, 1.0);
  malleability_.assign(rest_.size(), float(c));
  rebuild_ranks();
}

void ChainMailDeformer::rebuild_ranks()
{
  std::vector<float> distinct(malleability_);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  rank_.resize(malleability_.size());
  for (std::size_t v = 0; v < malleability_.size(); ++v)
    rank_[v] = index_t(
      std::lower_bound(distinct.begin(), distinct.end(), malleability_[v]) - distinct.begin());
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
  pinned_.assign(mask, mask + rest_.size());
}

void ChainMailDeformer::reset()
{
  for (index_t v : moved_)
    disp_[v].setZero();
  previously_moved_.swap(moved_);
  moved_.clear();
  if (++frame_ == 0) // wrapped: stale stamps could alias the new frame
  {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    frame_ = 1;
  }
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
  if (!rest_[grasp].allFinite())
  {
    result.message = "grasp vertex has a non-finite rest position";
    return result;
  }
  if (pinned(grasp))
  {
    result.message = "grasp vertex " + std::to_string(grasp) + " is pinned";
    return result;
  }
  disp_[grasp] = displacement;
  stamp_[grasp] = frame_;
  sponsor_[grasp] = -1;
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
  auto required_displacement = [&](index_t c, index_t s) -> Eigen::Vector3d {
    const Eigen::Vector3d o = rest_[c] - rest_[s];
    if (!o.allFinite())
      return Eigen::Vector3d::Zero();
    const Box b = displacement_bounds(o, params(c));
    return Eigen::Vector3d::Zero().cwiseMax(disp_[s] + b.lo).cwiseMin(disp_[s] + b.hi);
  };
  auto sponsor_neighbours = [&](index_t s) {
    for (const index_t* it = adj_.begin(s); it != adj_.end(s); ++it)
    {
      const index_t c = *it;
      if (stamp_[c] == frame_ || pinned(c))
        continue;
      double violation = 0.0;
      if constexpr (Queue::needs_violation)
        violation = required_displacement(c, s).norm();
      queue.push({ c, s }, rank_[c], violation);
    }
  };

  queue.clear();
  sponsor_neighbours(grasp);
  Candidate cand;
  while (queue.pop(cand))
  {
    ++result.examined;
    const index_t c = cand.vertex;
    if (stamp_[c] == frame_)
      continue;
    const Eigen::Vector3d target = required_displacement(c, cand.sponsor);
    if (target.isZero(0.0))
      continue;
    disp_[c] = target;
    stamp_[c] = frame_;
    sponsor_[c] = cand.sponsor;
    moved_.push_back(c);
    sponsor_neighbours(c);
  }
}

std::size_t ChainMailDeformer::memory_bytes() const
{
  return rest_.capacity() * sizeof(Eigen::Vector3d) + disp_.capacity() * sizeof(Eigen::Vector3d) +
    malleability_.capacity() * sizeof(float) + rank_.capacity() * sizeof(index_t) +
    pinned_.capacity() + stamp_.capacity() * sizeof(std::uint32_t) +
    sponsor_.capacity() * sizeof(index_t) +
    (moved_.capacity() + previously_moved_.capacity()) * sizeof(index_t) +
    adj_.offsets.capacity() * sizeof(std::int64_t) + adj_.neighbors.capacity() * sizeof(index_t);
}

} // namespace geoshaping
