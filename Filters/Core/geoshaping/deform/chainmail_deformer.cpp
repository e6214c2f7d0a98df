#include "geoshaping/deform/chainmail_deformer.h"

#include "geoshaping/deform/valid_region.h"
#include "geoshaping/mesh/huge_pages.h"
#include "geoshaping/mesh/morton.h"
#include "geoshaping/mesh/prefetch.h"
#include "geoshaping/mesh/radix_sort.h"

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
// A per-vertex array in the caller's numbering brought into the deformer's (renumbered)
// layout: out[i] = f(values[outer_of[i]]).
template<class T, class S, class F>
void to_inner(std::vector<T>& out, const S* values, const std::vector<index_t>& outer_of, F f)
{
  fresh_huge(out, outer_of.size());
  out.resize(outer_of.size());
  for (std::size_t i = 0; i < outer_of.size(); ++i)
    out[i] = f(values[std::size_t(outer_of[i])]);
}
} // namespace

bool ChainMailDeformer::bounds(
  const double* xyz, index_t n, Eigen::Vector3d& lo, Eigen::Vector3d& hi)
{
  lo = hi = Eigen::Vector3d::Zero();
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
  return !first;
}

void ChainMailDeformer::set_mesh(const double* xyz, index_t n, Adjacency adjacency)
{
  Eigen::Vector3d lo, hi;
  bounds(xyz, n, lo, hi);
  set_mesh(xyz, n, std::move(adjacency), origin_of(lo, hi));
}

void ChainMailDeformer::set_mesh(
  const double* xyz, index_t n, Adjacency adjacency, const Eigen::Vector3d& origin)
{
  Adjacency adj = std::move(adjacency); // the internal copy replaces it below
  {
    std::lock_guard<std::mutex> lock(caller_adjacency_mutex());
    caller_adjacency_.reset();
  }
  Eigen::Vector3d lo, hi;
  bounds(xyz, n, lo, hi);
  origin_ = origin;

  // Internal order: Morton code of the rest position on a 2^21 lattice over the bounding
  // box (ties and non-finite positions by caller id, the latter last).
  const std::size_t un = std::size_t(std::max<index_t>(n, 0));
  std::vector<std::pair<std::uint64_t, index_t>> order;
  fresh_huge(order, un);
  order.resize(un);
  const Eigen::Vector3d extent = hi - lo;
  for (index_t v = 0; v < n; ++v)
  {
    const Eigen::Vector3d p(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    order[std::size_t(v)] = { morton_code(p, lo, extent), v };
  }
  {
    // Stable from the caller's order: the order of the (code, id) pairs.
    std::vector<std::pair<std::uint64_t, index_t>> scratch;
    radix_sort(order, scratch, [](const std::pair<std::uint64_t, index_t>& r) { return r.first; });
  }
  fresh_huge(inner_of_, un);
  inner_of_.resize(un);
  fresh_huge(outer_of_, un);
  outer_of_.resize(un);
  for (std::size_t i = 0; i < un; ++i)
  {
    outer_of_[i] = order[i].second;
    inner_of_[std::size_t(order[i].second)] = index_t(i);
  }
  std::vector<std::pair<std::uint64_t, index_t>>().swap(order);

  // Internal CSR: each row keeps the caller's neighbour order (the Priority and Max
  // Violation queues' tie order depends on it).
  // 32-bit row offsets: 4 billion neighbour entries is far beyond any mesh that fits
  // in memory next to them (checked).
  if (adj.neighbors.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("ChainMailDeformer: more than 2^32 adjacency entries");
  fresh_huge(offsets_, un + 1);
  offsets_.assign(un + 1, 0);
  fresh_huge(neighbors_, adj.neighbors.size());
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
  adj = Adjacency(); // freed before the nodes are made: a big mesh's peak is lower

  fresh_huge(nodes_, un);
  nodes_.resize(un);
  for (std::size_t i = 0; i < un; ++i)
  {
    const index_t v = outer_of_[i];
    nodes_[i].rest = Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]) - origin_;
    nodes_[i].stamp = 0;
    nodes_[i].rank = 0;
  }
  fresh_huge(slot_, un);
  slot_.assign(un, 0);
  pinned_.clear();
  pinned_inner_.clear();
  gid_.clear();
  ghost_.clear();
  committed_.clear();
  frame_ = 1; // stamps are 0: nothing has moved
  moved_.clear();
  previously_moved_.clear();
  moved_rec_.clear();
  moved_root_.clear();
  obstacles_.reset();
  sliding_.clear();
  rigid_of_.clear();
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
  rigid_of_.clear(); // the ranks changed: the rigid components may have
  rebuild_rank_params();
}

void ChainMailDeformer::rebuild_rank_params()
{
  rank_params_.resize(distinct_.size());
  rank_band_.resize(distinct_.size());
  for (std::size_t r = 0; r < distinct_.size(); ++r)
  {
    rank_band_[r] = priority_band(distinct_[r]);
    rank_params_[r] = region_params(transfer_(distinct_[r]));
  }
  // The transfer function is set every frame: keep the components while the rigid ranks
  // stay the same (O(ranks)).
  for (std::size_t r = 0; r < rank_params_.size() && !rigid_of_.empty(); ++r)
    if (r >= rank_rigid_.size() || rank_rigid_[r] != std::uint8_t(rank_params_[r].rigid()))
      rigid_of_.clear();
}

void ChainMailDeformer::set_pinned(const std::uint8_t* mask)
{
  rigid_of_.clear(); // pins are left out of the rigid components
  if (!mask)
  {
    pinned_.clear();
    pinned_inner_.clear();
    return;
  }
  pinned_.assign(mask, mask + nodes_.size());
  to_inner(pinned_inner_, mask, outer_of_, [](std::uint8_t m) { return m; });
}

void ChainMailDeformer::set_global_ids(const std::int64_t* gid)
{
  gid_.clear();
  if (gid)
    to_inner(gid_, gid, outer_of_, [](std::int64_t g) { return g; });
}

void ChainMailDeformer::set_owned(const std::uint8_t* mask)
{
  rigid_of_.clear(); // rigid_component_split() depends on the ghosts
  ghost_.clear();
  if (mask)
    to_inner(ghost_, mask, outer_of_, [](std::uint8_t m) { return m == 0; });
}

void ChainMailDeformer::reset()
{
  previously_moved_.swap(moved_);
  moved_.clear();
  moved_rec_.clear();
  moved_root_.clear();
  if (++frame_ == 0) // wrapped: stale stamps could alias the new frame
  {
    for (Node& node : nodes_)
      node.stamp = 0;
    std::fill(rigid_stamp_.begin(), rigid_stamp_.end(), 0u);
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
  begin_frame();
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
  move(index_t(g), displacement, -1);
  result.grasp_fraction = obstacles_ ? last_fraction_ : 1.0;
  switch (queue_kind_)
  {
    case QueueKind::fifo:
    case QueueKind::fifo_priority:
      end_superstep();
      for (SuperstepKey key; (key = pending()) != SuperstepQueue::none; end_superstep())
      {
        result.examined += superstep(key);
        ++result.supersteps;
      }
      result.threaded_supersteps = threaded_supersteps_;
      break;
    case QueueKind::priority:
      propagate(heap_, index_t(g), result);
      break;
    case QueueKind::max_violation:
      propagate(violation_, index_t(g), result);
      break;
  }
  result.ok = true;
  result.moved = moved_.size();
  result.blocked = blocked_;
  return result;
}

void ChainMailDeformer::begin_frame()
{
  reset();
  supersteps_.clear();
  superstep_ = 0;
  superstep_begin_ = 0;
  sorted_begin_ = sorted_end_ = 0;
  if (threaded_supersteps_ > 0 && !threads_paused_)
    backoff_ = 0; // the last frame ran threaded without a stall
  threads_paused_ = paused_frames_ > 0;
  paused_frames_ -= paused_frames_ > 0;
  threaded_supersteps_ = 0;
  blocked_ = 0;
  last_fraction_ = 1.0;
}

#if defined(__GNUC__)
__attribute__((always_inline)) // once per moved vertex: not worth a call
#endif
inline void
ChainMailDeformer::move(
  index_t i, const Eigen::Vector3d& d, index_t sponsor_slot, const SuperstepRoot& root, bool gate)
{
  nodes_[std::size_t(i)].stamp = frame_;
  prefetch_neighbour_records(std::size_t(i)); // the row was prefetched when i was queued
  slot_[std::size_t(i)] = index_t(moved_rec_.size());
  moved_rec_.push_back({ gate && obstacles_ ? admissible(i, d) : d, i, sponsor_slot });
  moved_root_.emplace_back(root);
  moved_.push_back(outer_of_[std::size_t(i)]);
}

void ChainMailDeformer::move_vertex(index_t v, const Eigen::Vector3d& d, const SuperstepRoot& root)
{
  move(index_t(inner(v)), d, -1, root);
}

void ChainMailDeformer::skip_to_superstep(std::uint32_t n)
{
  if (n < superstep_)
    throw std::invalid_argument("ChainMailDeformer: supersteps only go forward");
  superstep_ = n;
}

std::size_t ChainMailDeformer::superstep(const SuperstepKey& key)
{
  std::size_t begin, end;
  if (!supersteps_.pop(key, begin, end))
    return 0;
  const SuperstepRoot root = SuperstepQueue::root_of(key);
  const bool link = frame_kind_ == ValidRegionFrame::link;
  if (threaded_superstep(end - begin) && cores_free())
    return link ? examine_threaded<ValidRegionFrame::link>(begin, end, root)
                : examine_threaded<ValidRegionFrame::axes>(begin, end, root);
  return link ? examine<ValidRegionFrame::link>(begin, end, root)
              : examine<ValidRegionFrame::axes>(begin, end, root);
}

void ChainMailDeformer::end_superstep()
{
  if (!file_threaded_pushes())
  {
    if (queue_kind_ == QueueKind::fifo_priority)
      push_neighbours<true>();
    else
      push_neighbours<false>();
  }
  superstep_begin_ = moved_rec_.size();
  ++superstep_;
}

template<bool Banded>
void ChainMailDeformer::push_neighbours()
{
  // The sponsors in id order, so that each candidate's entries come in sponsor id order
  // (SuperstepQueue::open): the superstep's own moves are in id order (sort_moves()),
  // ghosts and aliases received after them may not be.
  // The own moves [first, sorted_end_) are known to be in order: only what came after
  // them is checked and sorted, then merged in.
  const std::size_t first = superstep_begin_, end = moved_rec_.size(), count = end - first;
  const std::uint32_t* order = nullptr;
  const std::size_t sorted = sorted_begin_ == first && sorted_end_ <= end ? sorted_end_ : first;
  if (!ids_sorted(sorted > first ? sorted - 1 : first, end))
  {
    sort_by_id(first, end, sorted);
    order = by_id_.data();
  }
  const std::uint8_t* const pins = pinned_inner_.empty() ? nullptr : pinned_inner_.data();
  const std::uint8_t* const ghosts = ghost_.empty() ? nullptr : ghost_.data();
  const Node* const nodes = nodes_.data();
  const std::uint32_t* const offsets = offsets_.data();
  const index_t* const neighbors = neighbors_.data();
  const std::uint32_t frame = frame_;
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t slot = first + (order ? order[k] : k);
    const index_t s = moved_rec_[slot].vertex;
    const index_t s_rank = nodes[s].rank;
    const std::uint32_t s_band = Banded ? rank_band_[std::size_t(s_rank)] : 0u;
    const std::uint32_t same = supersteps_.open(s_band, moved_root_[slot].get());
    for (std::uint32_t e = offsets[s], e_end = offsets[s + 1]; e < e_end; ++e)
    {
      const index_t c = neighbors[e];
      const Node& node = nodes[c];
      if (node.stamp == frame || (pins && pins[c]) || (ghosts && ghosts[c]))
        continue;
      // Downhill starts a root (ordered by the length of the move it asks of c), the
      // same band keeps the sponsor's, uphill takes the base.
      const std::uint32_t c_band =
        !Banded || node.rank == s_rank ? s_band : rank_band_[std::size_t(node.rank)];
      if (c_band == s_band)
        supersteps_.append(same, c, index_t(slot));
      else
        supersteps_.append(
          supersteps_.open(
            c_band, c_band < s_band
                      ? SuperstepRoot::entered(superstep_ + 1,
                          (frame_kind_ == ValidRegionFrame::link
                              ? required_displacement<ValidRegionFrame::link>(node, index_t(slot))
                              : required_displacement<ValidRegionFrame::axes>(node, index_t(slot)))
                            .squaredNorm(),
                          global_id_inner(c))
                      : SuperstepRoot{}),
          c, index_t(slot));
      prefetch(neighbors + offsets[c]); // read if c moves
    }
  }
  supersteps_.seal_in_push_order(superstep_ + 1);
}

bool ChainMailDeformer::ids_sorted(std::size_t begin, std::size_t end) const
{
  for (std::size_t slot = begin + 1; slot < end; ++slot)
    if (global_id_inner(moved_rec_[slot].vertex) < global_id_inner(moved_rec_[slot - 1].vertex))
      return false;
  return true;
}

void ChainMailDeformer::sort_by_id(std::size_t begin, std::size_t end, std::size_t sorted)
{
  by_id_key_.resize(end - begin);
  for (std::size_t slot = begin; slot < end; ++slot)
    by_id_key_[slot - begin] = { global_id_inner(moved_rec_[slot].vertex),
      std::uint32_t(slot - begin) };
  const auto middle = by_id_key_.begin() + std::ptrdiff_t(std::max(sorted, begin) - begin);
  std::sort(middle, by_id_key_.end());
  std::inplace_merge(by_id_key_.begin(), middle, by_id_key_.end());
  by_id_.resize(end - begin);
  for (std::size_t k = 0; k < by_id_.size(); ++k)
    by_id_[k] = by_id_key_[k].second;
}

void ChainMailDeformer::sort_moves(std::size_t begin)
{
  const std::size_t end = moved_rec_.size();
  if (end - begin > 1 && !ids_sorted(begin, end))
  {
    sort_by_id(begin, end, begin);
    moved_scratch_.assign(moved_rec_.begin() + std::ptrdiff_t(begin), moved_rec_.end());
    for (std::size_t k = 0; k < by_id_.size(); ++k)
    {
      const MovedRecord& r = moved_scratch_[by_id_[k]];
      moved_rec_[begin + k] = r;
      slot_[std::size_t(r.vertex)] = index_t(begin + k);
      moved_[begin + k] = outer_of_[std::size_t(r.vertex)];
    }
  }
  sorted_begin_ = begin;
  sorted_end_ = end;
  if (obstacles_)
    for (std::size_t slot = begin; slot < end; ++slot)
      moved_rec_[slot].disp = admissible(moved_rec_[slot].vertex, moved_rec_[slot].disp);
}

template<ValidRegionFrame Frame>
std::size_t ChainMailDeformer::examine(
  std::size_t begin, std::size_t end, const SuperstepRoot& root)
{
  // The group in push order: each candidate's entries in sponsor id order, and
  // candidates independent of one another (their sponsors moved in earlier
  // supersteps). A candidate takes the largest of its entries' targets, the first in
  // push order among exactly equal lengths (sponsor_wins()); only the order of the
  // moves differs from the (candidate id, sponsor id) order: sort_moves() restores
  // it, and gates them in it.
  const Candidate* const entries = supersteps_.entries();
  const std::size_t first = moved_rec_.size();
  for (std::size_t k = begin; k < end; ++k)
  {
    const Candidate& e = entries[k];
    const Node& c = nodes_[std::size_t(e.vertex)];
    if (c.stamp == frame_)
    {
      const std::size_t slot = std::size_t(slot_[std::size_t(e.vertex)]);
      if (slot < first) // moved in an earlier superstep
        continue;
      // Moved by an earlier entry of this superstep: the larger target wins.
      MovedRecord& r = moved_rec_[slot];
      const Eigen::Vector3d target = required_displacement<Frame>(c, e.sponsor);
      if (sponsor_wins(target, r.disp))
      {
        r.disp = target;
        r.sponsor_slot = e.sponsor;
      }
      continue;
    }
    const Eigen::Vector3d target = required_displacement<Frame>(c, e.sponsor);
    if (target.isZero(0.0))
      continue;
    move(e.vertex, target, e.sponsor, root, false);
  }
  sort_moves(first);
  return end - begin;
}

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

// Priority and Max Violation: one candidate at a time, its neighbours pushed at once.
template<ValidRegionFrame Frame, class Queue>
void ChainMailDeformer::propagate(Queue& queue, index_t grasp, FrameResult& result)
{
  auto sponsor_neighbours = [&](index_t s, index_t s_slot)
  {
    for (std::uint32_t e = offsets_[std::size_t(s)]; e < offsets_[std::size_t(s) + 1]; ++e)
    {
      const index_t c = neighbors_[e];
      const Node& node = nodes_[std::size_t(c)];
      if (node.stamp == frame_ || (!pinned_inner_.empty() && pinned_inner_[std::size_t(c)]))
        continue;
      double violation = 0.0;
      if constexpr (Queue::needs_violation)
        violation = required_displacement<Frame>(node, s_slot).norm();
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
    const Node& c = nodes_[std::size_t(cand.vertex)];
    if (c.stamp == frame_)
      continue;
    const Eigen::Vector3d target = required_displacement<Frame>(c, cand.sponsor);
    if (target.isZero(0.0))
      continue;
    const index_t slot = index_t(moved_rec_.size());
    move(cand.vertex, target, cand.sponsor);
    sponsor_neighbours(cand.vertex, slot);
  }
  result.examined = examined;
}

std::string ChainMailDeformer::set_obstacles(
  const double* xyz, std::size_t n, const std::int64_t* triangles, std::size_t num_triangles)
{
  auto obstacles = std::make_shared<Obstacles>();
  std::string error = obstacles->set(xyz, n, triangles, num_triangles, origin_);
  obstacles_.reset();
  if (error.empty())
    obstacles_ = std::move(obstacles);
  return error;
}

void ChainMailDeformer::set_sliding(const std::uint8_t* mask)
{
  rigid_of_.clear(); // sliding vertices are left out of the rigid components
  sliding_.clear();
  if (mask)
    to_inner(sliding_, mask, outer_of_, [](std::uint8_t m) { return std::uint8_t(m != 0); });
}

bool ChainMailDeformer::set_obstacle_clearance(double c)
{
  if (!(c >= 0.0) || !std::isfinite(c))
    return false;
  clearance_ = c;
  return true;
}

void ChainMailDeformer::build_rigid_components()
{
  // Connected components of the rigid, unpinned vertices over the edges between them.
  const std::size_t n = nodes_.size();
  rank_rigid_.resize(rank_params_.size());
  for (std::size_t r = 0; r < rank_params_.size(); ++r)
    rank_rigid_[r] = std::uint8_t(rank_params_[r].rigid());
  auto rigid = [&](std::size_t i)
  {
    return !rank_rigid_.empty() && rank_rigid_[std::size_t(nodes_[i].rank)] &&
           (pinned_inner_.empty() || !pinned_inner_[i]) && (sliding_.empty() || !sliding_[i]);
  };
  rigid_of_.assign(n, -1);
  rigid_first_.assign(1, 0);
  rigid_members_.clear();
  for (std::size_t seed = 0; seed < n; ++seed)
  {
    if (rigid_of_[seed] >= 0 || !rigid(seed))
      continue;
    const auto component = index_t(rigid_first_.size() - 1);
    rigid_of_[seed] = component;
    rigid_members_.push_back(index_t(seed));
    for (std::size_t k = rigid_first_.back(); k < rigid_members_.size(); ++k)
    {
      const auto v = std::size_t(rigid_members_[k]);
      for (std::uint32_t e = offsets_[v]; e < offsets_[v + 1]; ++e)
      {
        const auto c = std::size_t(neighbors_[e]);
        if (rigid_of_[c] < 0 && rigid(c))
        {
          rigid_of_[c] = component;
          rigid_members_.push_back(index_t(c));
        }
      }
    }
    rigid_first_.push_back(std::uint32_t(rigid_members_.size()));
  }
  // On a piece: a component holding an owned vertex and a ghost continues on another
  // piece (one made of ghosts only is another piece's, never gated here).
  rigid_split_ = false;
  for (std::size_t c = 0; c + 1 < rigid_first_.size() && !ghost_.empty() && !rigid_split_; ++c)
  {
    bool owned = false, ghost = false;
    for (std::uint32_t k = rigid_first_[c]; k < rigid_first_[c + 1]; ++k)
      (ghost_[std::size_t(rigid_members_[k])] ? ghost : owned) = true;
    rigid_split_ = owned && ghost;
  }
  rigid_stamp_.assign(rigid_first_.size() - 1, 0u);
  rigid_disp_.assign(rigid_first_.size() - 1, Eigen::Vector3d::Zero());
}

Eigen::Vector3d ChainMailDeformer::admissible(index_t i, const Eigen::Vector3d& d)
{
  if (!ghost_.empty() && ghost_[std::size_t(i)])
    return d; // a ghost moves by its owner's word, gated there
  double f = 1.0;
  if (!sliding_.empty() && sliding_[std::size_t(i)])
  {
    const Eigen::Vector3d u = obstacles_->slide(nodes_[std::size_t(i)].rest, d, f);
    last_fraction_ = f;
    blocked_ += f < 1.0;
    return u;
  }
  if (rigid_of_.empty())
    build_rigid_components();
  const index_t component = rigid_of_[std::size_t(i)];
  if (component < 0)
    f = obstacles_->admissible_fraction(nodes_[std::size_t(i)].rest, d, clearance_);
  else if (rigid_stamp_[std::size_t(component)] == frame_)
  {
    if (d == rigid_disp_[std::size_t(component)])
      return d; // the component's displacement, admissible for every member
    f = obstacles_->admissible_fraction(nodes_[std::size_t(i)].rest, d, clearance_);
  }
  else
  {
    for (std::uint32_t k = rigid_first_[std::size_t(component)];
         k < rigid_first_[std::size_t(component) + 1]; ++k)
      f = std::min(f, obstacles_->admissible_fraction(
                        nodes_[std::size_t(rigid_members_[k])].rest, d, clearance_));
    rigid_stamp_[std::size_t(component)] = frame_;
    rigid_disp_[std::size_t(component)] = f == 1.0 ? d : Eigen::Vector3d(f * d);
  }
  last_fraction_ = f;
  if (f == 1.0)
    return d;
  ++blocked_;
  return f * d;
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
         distinct_.capacity() * sizeof(float) + rank_params_.capacity() * sizeof(RegionParams) +
         pinned_.capacity() + pinned_inner_.capacity() +
         committed_.capacity() * sizeof(Eigen::Vector3d) +
         (moved_.capacity() + previously_moved_.capacity()) * sizeof(index_t) +
         moved_rec_.capacity() * sizeof(MovedRecord) + moved_root_.capacity() * sizeof(StoredRoot) +
         (inner_of_.capacity() + outer_of_.capacity()) * sizeof(index_t) +
         caller_adjacency_bytes() + offsets_.capacity() * sizeof(std::uint32_t) +
         neighbors_.capacity() * sizeof(index_t) + supersteps_.memory_bytes() +
         rank_band_.capacity() * sizeof(std::uint32_t) + gid_.capacity() * sizeof(std::int64_t) +
         ghost_.capacity() + (obstacles_ ? obstacles_->memory_bytes() : 0) +
         rigid_of_.capacity() * sizeof(index_t) + rigid_first_.capacity() * sizeof(std::uint32_t) +
         rigid_members_.capacity() * sizeof(index_t) +
         rigid_stamp_.capacity() * sizeof(std::uint32_t) +
         rigid_disp_.capacity() * sizeof(Eigen::Vector3d) + rank_rigid_.capacity() +
         sliding_.capacity() + threaded_bytes();
}

} // namespace geoshaping
