#include "geoshaping/parallel/partitioned_chainmail.h"

#include "geoshaping/mesh/bit_cast.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace geoshaping
{

namespace
{
// The global id of the marker record that leads a run-ahead superstep's frontier.
constexpr std::int64_t round_marker = std::numeric_limits<std::int64_t>::min();

std::int64_t bits(double x)
{
  return bit_cast<std::int64_t>(x);
}

double from_bits(std::int64_t b)
{
  return bit_cast<double>(b);
}
} // namespace

std::string PartitionedChainMail::set_piece(const double* xyz, index_t n, Adjacency adjacency,
  const std::int64_t* gid, const std::uint8_t* owned, Exchange& exchange)
{
  const int pieces = exchange.pieces(), me = exchange.piece();

  // The whole mesh's origin: the centre of the union of the pieces' bounding boxes.
  Eigen::Vector3d lo, hi;
  const bool any = ChainMailDeformer::bounds(xyz, n, lo, hi);
  const bool reserved = std::find(gid, gid + n, round_marker) != gid + n;
  const auto boxes = exchange.all_gather({ any, bits(lo.x()), bits(lo.y()), bits(lo.z()),
    bits(hi.x()), bits(hi.y()), bits(hi.z()), reserved });
  bool first = true;
  for (const auto& b : boxes)
    if (b[7])
      return "global id " + std::to_string(round_marker) + " is reserved";
  for (const auto& b : boxes)
  {
    if (!b[0])
      continue;
    const Eigen::Vector3d l(from_bits(b[1]), from_bits(b[2]), from_bits(b[3]));
    const Eigen::Vector3d h(from_bits(b[4]), from_bits(b[5]), from_bits(b[6]));
    lo = first ? l : lo.cwiseMin(l);
    hi = first ? h : hi.cwiseMax(h);
    first = false;
  }
  if (first)
    lo = hi = Eigen::Vector3d::Zero();
  // A point may appear several times in a piece (the same global id): the first owned
  // copy (else the first) stands for it, with the union of the copies' neighbours; the
  // other copies are isolated ghosts that move with it.
  local_of_.clear();
  local_of_.reserve(std::size_t(n));
  std::vector<index_t> rep(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
  {
    const auto [it, fresh] = local_of_.emplace(gid[v], v);
    if (!fresh && owned[v] && !owned[it->second])
      it->second = v;
  }
  std::vector<std::uint8_t> is_owned(static_cast<std::size_t>(n), 0);
  aliases_.clear();
  for (index_t v = 0; v < n; ++v)
  {
    rep[std::size_t(v)] = local_of_[gid[v]];
    if (rep[std::size_t(v)] != v)
      aliases_.emplace(rep[std::size_t(v)], v);
    else
      is_owned[std::size_t(v)] = owned[v] != 0;
  }
  if (!aliases_.empty())
  {
    std::vector<std::vector<index_t>> rows{ static_cast<std::size_t>(n) };
    for (index_t v = 0; v < n; ++v)
      for (const index_t* it = adjacency.begin(v); it != adjacency.end(v); ++it)
        if (rep[std::size_t(*it)] != rep[std::size_t(v)])
          rows[std::size_t(rep[std::size_t(v)])].push_back(rep[std::size_t(*it)]);
    adjacency.neighbors.clear();
    for (index_t v = 0; v < n; ++v)
    {
      auto& row = rows[std::size_t(v)];
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
      adjacency.neighbors.insert(adjacency.neighbors.end(), row.begin(), row.end());
      adjacency.offsets[std::size_t(v) + 1] = std::int64_t(adjacency.neighbors.size());
    }
  }
  deformer_.set_mesh(xyz, n, std::move(adjacency), ChainMailDeformer::origin_of(lo, hi));
  deformer_.set_global_ids(gid);
  deformer_.set_owned(is_owned.data());
  owned = is_owned.data();

  // Who holds which of my owned vertices as a ghost: every piece's ghost ids.
  std::vector<std::int64_t> ghosts;
  for (index_t v = 0; v < n; ++v)
    if (rep[std::size_t(v)] == v && !owned[v])
      ghosts.push_back(gid[v]);
  const auto all_ghosts = exchange.all_gather(ghosts);
  std::vector<std::vector<index_t>> held_by{ std::size_t(pieces) }; // my owned, per piece
  for (int q = 0; q < pieces; ++q)
    if (q != me)
      for (std::int64_t g : all_ghosts[std::size_t(q)])
      {
        const auto it = local_of_.find(g);
        if (it != local_of_.end() && owned[it->second])
          held_by[std::size_t(q)].push_back(it->second);
      }
  // counts[p][q]: how many of q's ghosts p owns.
  std::vector<std::int64_t> mine(static_cast<std::size_t>(pieces), 0);
  for (int q = 0; q < pieces; ++q)
    mine[std::size_t(q)] = std::int64_t(held_by[std::size_t(q)].size());
  const auto counts = exchange.all_gather(mine);
  for (int p = 0; p < pieces; ++p)
  {
    std::int64_t owners = 0;
    for (int q = 0; q < pieces; ++q)
      owners += counts[std::size_t(q)][std::size_t(p)];
    if (owners != std::int64_t(all_ghosts[std::size_t(p)].size()))
      return "piece " + std::to_string(p) +
             " holds ghost points that are owned by no piece or by several";
  }

  send_to_.clear();
  receive_from_.clear();
  std::vector<std::vector<std::uint32_t>> subs{ std::size_t(n) };
  for (int q = 0; q < pieces; ++q)
  {
    if (!held_by[std::size_t(q)].empty())
    {
      for (index_t v : held_by[std::size_t(q)])
        subs[std::size_t(v)].push_back(std::uint32_t(send_to_.size()));
      send_to_.push_back(q);
    }
    if (counts[std::size_t(q)][std::size_t(me)] > 0)
      receive_from_.push_back(q);
  }
  subscriber_offsets_.assign(std::size_t(n) + 1, 0);
  subscribers_.clear();
  for (std::size_t v = 0; v < subs.size(); ++v)
  {
    subscribers_.insert(subscribers_.end(), subs[v].begin(), subs[v].end());
    subscriber_offsets_[v + 1] = std::uint32_t(subscribers_.size());
  }
  outbox_.assign(send_to_.size(), {});
  return {};
}

void PartitionedChainMail::holders(std::int64_t gid, std::vector<index_t>& out) const
{
  const auto it = local_of_.find(gid);
  if (it == local_of_.end())
    return;
  out.push_back(it->second);
  const auto range = aliases_.equal_range(it->second);
  for (auto a = range.first; a != range.second; ++a)
    out.push_back(a->second);
}

bool PartitionedChainMail::fill_outbox()
{
  for (auto& box : outbox_)
    box.clear();
  bool any = false;
  const auto& moved = deformer_.moved();
  for (std::size_t k = deformer_.superstep_begin(); k < moved.size(); ++k)
  {
    const index_t v = moved[k];
    const std::uint32_t first = subscriber_offsets_[std::size_t(v)];
    const std::uint32_t last = subscriber_offsets_[std::size_t(v) + 1];
    if (first == last || !deformer_.owned(v)) // most moves: held by no other piece
      continue;
    const Eigen::Vector3d& d = deformer_.displacement(v);
    for (std::uint32_t i = first; i < last; ++i)
      outbox_[subscribers_[i]].push_back(
        { deformer_.global_id(v), { d.x(), d.y(), d.z() }, deformer_.root(v) });
    any = true;
  }
  return any;
}

void PartitionedChainMail::trade(Exchange& exchange, bool marked)
{
  if (marked)
    for (auto& box : outbox_)
      if (!box.empty())
        box.insert(box.begin(),
          { round_marker, { 0.0, 0.0, 0.0 }, { deformer_.superstep_index(), 0, round_marker } });
  for (const auto& box : exchange.exchange(send_to_, outbox_, receive_from_))
    for (const MovedVertex& m : box)
    {
      if (m.gid == round_marker)
      {
        deformer_.skip_to_superstep(m.root.generation);
        continue;
      }
      const auto it = local_of_.find(m.gid);
      if (it != local_of_.end() && !deformer_.owned(it->second))
        deformer_.move_vertex(
          it->second, { m.displacement[0], m.displacement[1], m.displacement[2] }, m.root);
    }
}

void PartitionedChainMail::move_aliases()
{
  if (aliases_.empty())
    return;
  const auto& moved = deformer_.moved();
  const std::size_t end = moved.size();
  for (std::size_t k = deformer_.superstep_begin(); k < end; ++k)
  {
    const index_t v = moved[k];
    const auto range = aliases_.equal_range(v);
    for (auto it = range.first; it != range.second; ++it)
      deformer_.move_vertex(it->second, deformer_.displacement(v), deformer_.root(v));
  }
}

FrameResult PartitionedChainMail::deform(
  std::int64_t grasp, const Eigen::Vector3d& displacement, Exchange& exchange)
{
  FrameResult result;
  supersteps_ = 0;
  deformer_.begin_frame();
  const QueueKind q = deformer_.queue();
  if (q != QueueKind::fifo && q != QueueKind::fifo_priority)
  {
    result.message = std::string("the ") + queue_name(q) +
                     " queue is sequential: a partitioned mesh needs FIFO or FIFO Priority";
    return result;
  }
  if (!displacement.allFinite())
  {
    result.message = "displacement is not finite";
    return result;
  }
  // The grasp's owner tells everyone what it found: 1 fine, 2 pinned, 3 non-finite.
  index_t g = -1;
  std::int64_t state = 0;
  const auto it = local_of_.find(grasp);
  if (it != local_of_.end() && deformer_.owned(it->second))
  {
    g = it->second;
    state = deformer_.pinned(g) ? 2 : (deformer_.rest_local(g).allFinite() ? 1 : 3);
  }
  // With obstacles, a rigid component continued on another piece would need the
  // smallest fraction over all its members (see the header): refused on every piece.
  const bool split = deformer_.obstacles() && deformer_.rigid_component_split();
  std::int64_t owners = 0, found = 0, splits = 0;
  for (const auto& s : exchange.all_gather({ state, split }))
  {
    owners += s[0] != 0;
    found = s[0] ? s[0] : found;
    splits += s[1];
  }
  const std::string id = std::to_string(grasp);
  if (splits > 0)
    result.message = "with obstacles, a rigid region split across pieces would stop as one "
                     "only with every piece's part of it: keep each rigid region on one piece";
  else if (owners != 1)
    result.message = "grasp global id " + id + " is owned by " + std::to_string(owners) + " pieces";
  else if (found == 2)
    result.message = "grasp global id " + id + " is pinned";
  else if (found == 3)
    result.message = "grasp global id " + id + " has a non-finite rest position";
  if (!result.message.empty())
    return result;

  if (g >= 0)
  {
    deformer_.move_vertex(g, displacement);
    if (deformer_.obstacles())
      result.grasp_fraction = deformer_.last_fraction();
  }
  rounds_ = 0;
  fill_outbox();
  trade(exchange, false);
  move_aliases();
  deformer_.end_superstep();
  const std::size_t me = std::size_t(exchange.piece());
  for (;;)
  {
    // The lowest key anywhere, the lowest on the other pieces, the superstep reached.
    SuperstepKey key = SuperstepQueue::none, others = SuperstepQueue::none;
    std::uint64_t reached = 0;
    const auto states =
      exchange.all_round_states({ deformer_.pending(), deformer_.superstep_index() });
    for (std::size_t q = 0; q < states.size(); ++q)
    {
      key = std::min(key, states[q].pending);
      if (q != me)
        others = std::min(others, states[q].pending);
      reached = std::max(reached, states[q].superstep);
    }
    deformer_.skip_to_superstep(std::uint32_t(reached));
    if (key == SuperstepQueue::none)
      break;
    ++rounds_;
    bool ended = false; // the last superstep run ahead was ended here (it sent nothing)
    bool loud = false;
    if (deformer_.pending() == key)
    {
      result.examined += deformer_.superstep(key);
      loud = fill_outbox();
      // Alone with the lowest key: on to the next while nothing needs sending.
      while (!loud && key < others)
      {
        move_aliases();
        deformer_.end_superstep();
        const SuperstepKey next = deformer_.pending();
        if (!(next < others))
        {
          ended = true;
          break;
        }
        result.examined += deformer_.superstep(next);
        loud = fill_outbox();
      }
    }
    else
      fill_outbox(); // empties the outboxes: nothing moved here
    trade(exchange, loud && deformer_.superstep_index() > reached);
    if (!ended)
    {
      move_aliases();
      deformer_.end_superstep();
    }
  }
  supersteps_ = deformer_.superstep_index() - 1;
  result.ok = true;
  for (index_t v : deformer_.moved())
    result.moved += deformer_.owned(v);
  result.blocked = deformer_.blocked();
  return result;
}

} // namespace geoshaping
