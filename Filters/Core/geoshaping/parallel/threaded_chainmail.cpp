#include "geoshaping/parallel/threaded_chainmail.h"

#include "geoshaping/mesh/morton.h"
#include "geoshaping/parallel/in_process_exchange.h"
#include "geoshaping/parallel/thread_clock.h"

#include <algorithm>
#include <limits>
#include <thread>

namespace geoshaping
{

struct ThreadedChainMail::Piece
{
  ChainMailDeformer deformer;
  PartitionedChainMail partition{ deformer };
  std::vector<index_t> global; // local id -> the whole mesh's id
  FrameResult result;
  // The last frame's owned moves in run order: global id and slot of deformer.moved(),
  // run r at [run_offsets[r], run_offsets[r + 1]).
  std::vector<std::int64_t> keys;
  std::vector<std::uint32_t> slots;
  std::vector<std::size_t> run_offsets;
  std::vector<index_t> whole_slot; // by slot of deformer.moved(): the whole's, -1 a ghost
};

// Defaults measured on two cores (docs/benchmarks.md, "Threaded frame").
ThreadedChainMail::ThreadedChainMail()
  : threshold_(100000)
  , per_superstep_(256.0)
  , block_(4096)
{
}

ThreadedChainMail::~ThreadedChainMail() = default;

void ThreadedChainMail::set_threads(int threads)
{
  threads_ = std::max(0, threads);
}

int ThreadedChainMail::threads() const
{
  if (threads_ > 0)
    return threads_;
  return std::max(1, int(std::thread::hardware_concurrency()));
}

void ThreadedChainMail::set_block(index_t vertices)
{
  if (std::max<index_t>(1, vertices) != block_)
    built_for_ = nullptr;
  block_ = std::max<index_t>(1, vertices);
}

bool ThreadedChainMail::predicts_threaded(
  const ChainMailDeformer& whole, index_t grasp, const Eigen::Vector3d& displacement) const
{
  const QueueKind q = whole.queue();
  // The one-thread frame's refusals stay its own (the same messages, the same state).
  return threads() > 1 && (q == QueueKind::fifo || q == QueueKind::fifo_priority) &&
         !whole.obstacles() && last_moved_ > 0 && last_moved_ >= threshold_ &&
         double(last_moved_) >= per_superstep_ * double(last_supersteps_) && grasp >= 0 &&
         grasp < whole.size() && displacement.allFinite() && whole.rest_local(grasp).allFinite() &&
         !whole.pinned(grasp);
}

FrameResult ThreadedChainMail::deform(
  ChainMailDeformer& whole, index_t grasp, const Eigen::Vector3d& displacement)
{
  last_threaded_ = false;
  last_rounds_ = 0;
  FrameResult r;
  const bool threaded = predicts_threaded(whole, grasp, displacement);
  if (threaded)
  {
    const int pieces = threads();
    if (built_for_ != &whole || built_revision_ != whole.revision() || built_pieces_ != pieces)
      build(whole, pieces);
  }
  if (threaded && !pieces_.empty()) // a build the partition refused leaves no pieces
  {
    for (auto& piece : pieces_)
    {
      piece->deformer.set_transfer_function(whole.transfer_function());
      piece->deformer.set_queue(whole.queue());
      piece->deformer.set_valid_region_frame(whole.valid_region_frame());
    }
    const std::int64_t g = whole.global_id(grasp);
    const int count = int(pieces_.size());
    thread_seconds_.assign(std::size_t(count), 0.0);
    run_in_pieces(count,
      [&](int p, Exchange& exchange)
      {
        const double start = thread_cpu_seconds();
        Piece& piece = *pieces_[std::size_t(p)];
        piece.result = piece.partition.deform(g, displacement, exchange);
        if (!piece.result.ok) // the same on every piece
          return;
        const auto& moved = piece.deformer.moved();
        piece.keys.clear();
        piece.slots.clear();
        piece.run_offsets.assign(1, 0);
        for (const PartitionedChainMail::Run& run : piece.partition.runs())
        {
          for (std::uint32_t k = run.begin; k < run.end; ++k)
          {
            piece.keys.push_back(piece.deformer.global_id(moved[k]));
            piece.slots.push_back(k);
          }
          piece.run_offsets.push_back(piece.keys.size());
        }
        piece.whole_slot.assign(moved.size(), -1);
        exchange.all_gather({});
        // The supersteps split into `count` ranges of about equal moves; each thread
        // merges its range's runs and writes them into the whole deformer.
        const Share share = share_of(p, count);
        const std::size_t m = share.total, begin = share.begin, end = share.end;
        if (p == 0)
        {
          order_.resize(m);
          whole.begin_adopted_frame(m);
        }
        exchange.all_gather({});
        merge(whole, share);
        exchange.all_gather({});
        for (std::size_t k = begin; k < end; ++k)
        {
          const Piece& from = *pieces_[order_[k].first];
          const index_t s = from.deformer.moved_sponsor_slot(order_[k].second);
          if (s < 0 || from.whole_slot[std::size_t(s)] >= 0)
            whole.adopt_sponsor_slot(k, s < 0 ? -1 : from.whole_slot[std::size_t(s)]);
          else
            whole.adopt_sponsor(k, from.global[std::size_t(from.deformer.moved()[std::size_t(s)])]);
        }
        thread_seconds_[std::size_t(p)] = thread_cpu_seconds() - start;
      });
    if (pieces_[0]->result.ok)
    {
      r.ok = true;
      for (const auto& piece : pieces_)
      {
        r.moved += piece->result.moved;
        r.examined += piece->result.examined;
      }
      last_threaded_ = true;
      last_supersteps_ = pieces_[0]->partition.supersteps();
      last_rounds_ = pieces_[0]->partition.rounds();
      last_moved_ = r.moved;
      return r;
    }
  }
  r = whole.deform(grasp, displacement);
  last_supersteps_ = whole.superstep_index() > 0 ? whole.superstep_index() - 1 : 0;
  last_moved_ = r.ok ? r.moved : 0;
  return r;
}

ThreadedChainMail::Share ThreadedChainMail::share_of(int p, int count) const
{
  std::vector<std::pair<std::uint32_t, std::size_t>> steps; // (superstep, moves)
  for (const auto& piece : pieces_)
  {
    const auto& runs = piece->partition.runs();
    for (std::size_t r = 0; r < runs.size(); ++r)
      steps.emplace_back(runs[r].superstep, piece->run_offsets[r + 1] - piece->run_offsets[r]);
  }
  std::sort(steps.begin(), steps.end());
  Share share;
  for (const auto& step : steps)
    share.total += step.second;
  share.begin = share.end = share.total;
  if (share.total == 0)
    return share;
  // A superstep goes to the thread whose share of [0, total) holds its first move.
  std::size_t seen = 0;
  bool mine = false;
  for (std::size_t k = 0; k < steps.size(); seen += steps[k++].second)
  {
    if (k > 0 && steps[k].first == steps[k - 1].first)
      continue;
    const std::size_t t = seen * std::size_t(count) / share.total;
    if (t == std::size_t(p) && !mine)
    {
      mine = true;
      share.from_step = steps[k].first;
      share.begin = seen;
    }
    else if (t > std::size_t(p))
    {
      if (mine)
      {
        share.to_step = steps[k].first;
        share.end = seen;
      }
      return share;
    }
  }
  return share;
}

void ThreadedChainMail::merge(ChainMailDeformer& whole, const Share& share)
{
  // By superstep; inside one, the pieces' runs (each in global id order) merged by id.
  const std::size_t count = pieces_.size();
  std::vector<std::size_t> run(count), at(count), end(count);
  for (std::size_t p = 0; p < count; ++p)
  {
    const auto& runs = pieces_[p]->partition.runs();
    run[p] = std::size_t(
      std::lower_bound(runs.begin(), runs.end(), share.from_step,
        [](const PartitionedChainMail::Run& r, std::uint32_t step) { return r.superstep < step; }) -
      runs.begin());
  }
  std::size_t k = share.begin;
  for (;;)
  {
    std::uint32_t step = share.to_step;
    for (std::size_t p = 0; p < count; ++p)
    {
      const auto& runs = pieces_[p]->partition.runs();
      if (run[p] < runs.size())
        step = std::min(step, runs[run[p]].superstep);
    }
    if (step >= share.to_step)
      return;
    for (std::size_t p = 0; p < count; ++p)
    {
      const Piece& piece = *pieces_[p];
      const auto& runs = piece.partition.runs();
      at[p] = end[p] = 0;
      if (run[p] < runs.size() && runs[run[p]].superstep == step)
      {
        at[p] = piece.run_offsets[run[p]];
        end[p] = piece.run_offsets[run[p] + 1];
        ++run[p];
      }
    }
    for (;; ++k)
    {
      std::size_t best = count;
      for (std::size_t p = 0; p < count; ++p)
        if (at[p] < end[p] &&
            (best == count || pieces_[p]->keys[at[p]] < pieces_[best]->keys[at[best]]))
          best = p;
      if (best == count)
        break;
      Piece& from = *pieces_[best];
      const std::uint32_t slot = from.slots[at[best]++];
      order_[k] = { std::uint32_t(best), slot };
      from.whole_slot[slot] = index_t(k);
      whole.adopt_move(k, from.global[std::size_t(from.deformer.moved()[slot])],
        from.deformer.moved_displacement(slot), from.deformer.moved_root(slot));
    }
  }
}

void ThreadedChainMail::build(const ChainMailDeformer& whole, int pieces)
{
  pieces_.clear();
  built_for_ = &whole;
  built_pieces_ = pieces;
  built_revision_ = whole.revision();
  const index_t n = whole.size();
  if (n == 0)
    return;

  // Owners: blocks of the Morton order dealt in turn.
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = lo;
  bool first = true;
  for (index_t v = 0; v < n; ++v)
    if (whole.rest_local(v).allFinite())
    {
      lo = first ? whole.rest_local(v) : lo.cwiseMin(whole.rest_local(v));
      hi = first ? whole.rest_local(v) : hi.cwiseMax(whole.rest_local(v));
      first = false;
    }
  std::vector<std::pair<std::uint64_t, index_t>> order(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
    order[std::size_t(v)] = { morton_code(whole.rest_local(v), lo, hi - lo), v };
  std::sort(order.begin(), order.end());
  std::vector<int> owner(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < order.size(); ++k)
    owner[std::size_t(order[k].second)] = int((k / std::size_t(block_)) % std::size_t(pieces));
  std::vector<std::pair<std::uint64_t, index_t>>().swap(order);

  const Adjacency& adjacency = whole.adjacency(); // built once, before the threads read it
  for (int p = 0; p < pieces; ++p)
    pieces_.push_back(std::make_unique<Piece>());
  std::vector<std::string> refusals(static_cast<std::size_t>(pieces));
  run_in_pieces(pieces,
    [&](int p, Exchange& exchange)
    {
      Piece& piece = *pieces_[std::size_t(p)];
      // Local ids: the owned vertices, then their neighbours owned elsewhere (the ghosts).
      std::vector<index_t> local_of(static_cast<std::size_t>(n), -1);
      auto& global = piece.global;
      for (index_t v = 0; v < n; ++v)
        if (owner[std::size_t(v)] == p)
        {
          local_of[std::size_t(v)] = index_t(global.size());
          global.push_back(v);
        }
      const std::size_t owned = global.size();
      for (std::size_t l = 0; l < owned; ++l)
        for (const index_t* u = adjacency.begin(global[l]); u != adjacency.end(global[l]); ++u)
          if (local_of[std::size_t(*u)] < 0)
          {
            local_of[std::size_t(*u)] = index_t(global.size());
            global.push_back(*u);
          }
      const std::size_t local = global.size();
      Adjacency adj;
      adj.offsets.reserve(local + 1);
      adj.offsets.push_back(0);
      std::vector<double> xyz;
      xyz.reserve(3 * local);
      std::vector<std::int64_t> gid(local);
      std::vector<std::uint8_t> is_owned(local);
      std::vector<float> malleability(local);
      std::vector<std::uint8_t> pins(local);
      bool pinned = false;
      for (std::size_t l = 0; l < local; ++l)
      {
        const index_t v = global[l];
        for (const index_t* u = adjacency.begin(v); u != adjacency.end(v); ++u)
          if (local_of[std::size_t(*u)] >= 0)
            adj.neighbors.push_back(local_of[std::size_t(*u)]);
        std::sort(adj.neighbors.begin() + adj.offsets.back(), adj.neighbors.end());
        adj.offsets.push_back(std::int64_t(adj.neighbors.size()));
        const Eigen::Vector3d x = whole.origin() + whole.rest_local(v);
        xyz.insert(xyz.end(), x.data(), x.data() + 3);
        gid[l] = whole.global_id(v);
        is_owned[l] = l < owned;
        malleability[l] = whole.malleability(v);
        pins[l] = whole.pinned(v);
        pinned = pinned || pins[l];
      }
      refusals[std::size_t(p)] = piece.partition.set_piece(
        xyz.data(), index_t(local), std::move(adj), gid.data(), is_owned.data(), exchange);
      // The rest positions exactly (x above, rounded, only places the piece's layout):
      // the same arithmetic as the whole mesh's.
      for (std::size_t l = 0; l < local; ++l)
        piece.deformer.set_rest(index_t(l), whole.rest_local(global[l]), Eigen::Vector3d::Zero());
      piece.deformer.set_malleability(malleability.data());
      piece.deformer.set_pinned(pinned ? pins.data() : nullptr);
    });
  if (!refusals[0].empty()) // the same on every piece
    pieces_.clear();
}

} // namespace geoshaping
