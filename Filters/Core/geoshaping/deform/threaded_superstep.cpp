// The threaded superstep (chainmail_deformer.h, "Threads"; docs/deformer.md): examine() on
// several threads, bit for bit.
//
// Invariants, and why no atomics are needed:
// - Ownership. Thread t alone reads and writes what belongs to the candidates whose global
//   ids lie in [splitters[t], splitters[t + 1]): their best_of entries and their nodes'
//   stamps until the barrier. The ranges are disjoint, so no location is written by two
//   threads or written by one while another reads it before the barrier.
// - The barrier orders the rest: after it every move of the superstep is stamped and every
//   lane's winners are counted, which is all that the slots and the pushes read of other
//   threads' work. ThreadSanitizer checks this (Testing/run-sanitizer-tests.sh).
// - best_of is all 0 between supersteps (each proposed-to vertex moves and is reset), so a
//   superstep never reads a stale index.
// Cost of a superstep of C entries and W moves on T threads: each thread reads all C
// entries and the global id of each candidate, examines its own (about C / T), sorts its
// about W / T winners; one barrier, plus the pool's start and end of the run; the caller
// alone samples 16 T entries for the splitters and, under FIFO, files the pushes.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/worker_pool.h"
#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/mesh/prefetch.h"

#include <algorithm>
#include <limits>
#include <thread>

namespace geoshaping
{

struct ChainMailDeformer::Threaded
{
  explicit Threaded(int threads)
    : pool(threads)
    , lanes(std::size_t(threads))
  {
  }
  WorkerPool pool;
  // By internal id: 1 + the index in its owner's `best` of the longest move proposed for
  // the vertex in the current superstep, 0 for none. Only the vertex's owner (the thread
  // whose range of global ids holds it) reads or writes it, and every vertex proposed to
  // moves in that superstep, which sets it back to 0: all are 0 between supersteps.
  std::vector<std::uint32_t> best_of;
  struct Best // the longest move proposed to a vertex so far, the first in push order
  {
    Eigen::Vector3d u;
    double length2;
    index_t vertex, sponsor;
  };
  struct Won // a winning proposal
  {
    std::int64_t gid;
    std::uint32_t best;
    index_t outer; // the vertex's caller id
    bool operator<(const Won& o) const { return gid < o.gid; }
  };
  struct alignas(64) Lane // one thread's
  {
    std::vector<Best> best;        // the vertices of its range proposed to, first seen first
    std::vector<Won> won;          // by global id
    std::vector<Candidate> pushes; // FIFO: the neighbours of its moves
  };
  std::vector<Lane> lanes;
  std::vector<std::int64_t> splitters; // thread t owns global ids [splitters[t], splitters[t + 1])
  // The superstep whose pushes the lanes hold: frame, superstep, moved_rec_'s size.
  std::uint32_t pushed_frame = 0, pushed_superstep = 0;
  std::size_t pushed_end = 0;
};

ChainMailDeformer::ThreadedHandle::ThreadedHandle() = default;
ChainMailDeformer::ThreadedHandle::ThreadedHandle(const ThreadedHandle&) {}
ChainMailDeformer::ThreadedHandle& ChainMailDeformer::ThreadedHandle::operator=(
  const ThreadedHandle&)
{
  state.reset();
  return *this;
}
ChainMailDeformer::ThreadedHandle::~ThreadedHandle() = default;

namespace
{
int hardware_threads()
{
  return std::max(1, int(std::thread::hardware_concurrency()));
}
} // namespace

void ChainMailDeformer::set_threads(int threads, ThreadUse use)
{
  const int n = threads > 0 ? threads : hardware_threads();
  if (n == threads_ && use == thread_use_)
    return; // keeps the pool and what the stalls taught
  if (n != threads_)
    threaded_.state.reset();
  threads_ = n;
  thread_use_ = use;
  threads_paused_ = false;
  paused_frames_ = backoff_ = 0;
}

std::size_t ChainMailDeformer::threaded_bytes() const
{
  const Threaded* t = threaded_.state.get();
  if (!t)
    return 0;
  std::size_t bytes =
    t->best_of.capacity() * sizeof(std::uint32_t) + t->splitters.capacity() * sizeof(std::int64_t);
  for (const Threaded::Lane& lane : t->lanes)
    bytes += lane.best.capacity() * sizeof(Threaded::Best) +
             lane.won.capacity() * sizeof(lane.won[0]) + lane.pushes.capacity() * sizeof(Candidate);
  return bytes;
}

bool ChainMailDeformer::cores_free()
{
  if (thread_use_ == ThreadUse::always)
    return true;
  if (load_frame_ != frame_)
  {
    load_frame_ = frame_;
    const int others =
      WorkerPool::others_running(threaded_.state ? &threaded_.state->pool : nullptr);
    cores_taken_ = WorkerPool::cores_short(others, hardware_threads(), threads_);
  }
  return !cores_taken_;
}

bool ChainMailDeformer::file_threaded_pushes()
{
  Threaded* t = threaded_.state.get();
  if (!t || t->pushed_frame != frame_ || t->pushed_superstep != superstep_ ||
      t->pushed_end != moved_rec_.size())
    return false;
  t->pushed_frame = 0;
  const std::uint32_t group = supersteps_.open(0, moved_root_[superstep_begin_].get());
  for (const Threaded::Lane& lane : t->lanes)
    supersteps_.append(group, lane.pushes.data(), lane.pushes.size());
  supersteps_.seal_in_push_order(superstep_ + 1);
  return true;
}

template<ValidRegionFrame Frame>
std::size_t ChainMailDeformer::examine_threaded(
  std::size_t begin, std::size_t end, const SuperstepRoot& root)
{
  if (!threaded_.state)
    threaded_.state = std::make_unique<Threaded>(threads_);
  Threaded& th = *threaded_.state;
  if (th.best_of.size() != nodes_.size())
    th.best_of.assign(nodes_.size(), 0);
  const int threads = th.pool.size();
  const std::size_t first = moved_rec_.size(), count = end - begin;
  const bool push = queue_kind_ == QueueKind::fifo;
  const Candidate* const entries = supersteps_.entries();
  const std::uint8_t* const pins = pinned_inner_.empty() ? nullptr : pinned_inner_.data();
  moved_rec_.resize(first + count); // uninitialised
  moved_root_.resize(first + count);
  moved_.resize(first + count);
  const StoredRoot stored_root(root);

  // The owners' ranges of global ids, from the ids of evenly spaced entries, so that each
  // thread examines about as many entries. Any splitters give the same moves, slots and
  // pushes; they only balance the work.
  th.splitters.clear();
  const std::size_t samples = 16 * std::size_t(threads);
  for (std::size_t q = 0; q < samples; ++q)
    th.splitters.push_back(
      global_id_inner(entries[begin + (2 * q + 1) * count / (2 * samples)].vertex));
  std::sort(th.splitters.begin(), th.splitters.end());
  for (int t = 1; t < threads; ++t)
    th.splitters[std::size_t(t)] = th.splitters[std::size_t(t) * samples / std::size_t(threads)];
  th.splitters.resize(std::size_t(threads) + 1);
  th.splitters.front() = std::numeric_limits<std::int64_t>::min();
  th.splitters.back() = std::numeric_limits<std::int64_t>::max();

  auto job = [&](int t)
  {
    Threaded::Lane& lane = th.lanes[std::size_t(t)];
    const std::int64_t lo = th.splitters[std::size_t(t)], hi = th.splitters[std::size_t(t) + 1];
    // 1. The entries whose candidate c this thread owns, in push order: for an entry
    //    whose c did not move in an earlier superstep and whose target is not zero,
    //    keep it if it is longer than every earlier one of c's (examine()'s rule,
    //    sponsor_wins(): the longest move wins, the first in push order among equal
    //    lengths). No other thread touches c.
    lane.best.clear();
    for (std::size_t k = begin; k < end; ++k)
    {
      const Candidate& entry = entries[k];
      const std::int64_t gid = global_id_inner(entry.vertex);
      if (gid < lo || gid >= hi)
        continue;
      const Node& c = nodes_[std::size_t(entry.vertex)];
      if (c.stamp == frame_)
        continue;
      const Eigen::Vector3d target = required_displacement<Frame>(c, entry.sponsor);
      if (target.isZero(0.0))
        continue;
      const double length2 = target.squaredNorm();
      std::uint32_t& b = th.best_of[std::size_t(entry.vertex)];
      if (b == 0)
      {
        lane.best.emplace_back();
        b = std::uint32_t(lane.best.size());
      }
      else if (!(length2 > lane.best[b - 1].length2))
        continue;
      // Field by field: a record staged on the stack stalls store forwarding.
      Threaded::Best& best = lane.best[b - 1];
      best.u = target;
      best.length2 = length2;
      best.vertex = entry.vertex;
      best.sponsor = entry.sponsor;
    }

    // 2. Each proposed-to vertex moves: marked moved, its winners put in global id order.
    lane.won.clear();
    for (std::size_t j = 0; j < lane.best.size(); ++j)
    {
      const std::size_t i = std::size_t(lane.best[j].vertex);
      th.best_of[i] = 0;
      nodes_[i].stamp = frame_;
      Threaded::Won& w = lane.won.emplace_back();
      w.gid = global_id_inner(index_t(i));
      w.best = std::uint32_t(j);
      w.outer = outer_of_[i];
      prefetch_neighbour_records(i); // step 4 tests them, as after move()
    }
    std::sort(lane.won.begin(), lane.won.end());
    th.pool.barrier(); // every move of the superstep is marked and counted

    // 3. The moves of this range into the slots of their rank in id order (the ranges
    //    are in id order), with the rest of what move() sets: sort_moves()'s order.
    std::size_t slot = first;
    for (int u = 0; u < t; ++u)
      slot += th.lanes[std::size_t(u)].won.size();
    const std::size_t range_begin = slot;
    for (const Threaded::Won& w : lane.won)
    {
      const Threaded::Best& p = lane.best[w.best];
      slot_[std::size_t(p.vertex)] = index_t(slot);
      MovedRecord& r = moved_rec_[slot];
      r.disp = p.u;
      r.vertex = p.vertex;
      r.sponsor_slot = p.sponsor;
      moved_root_[slot] = stored_root;
      moved_[slot] = w.outer;
      ++slot;
    }
    const std::size_t range_end = slot;
    if (!push)
      return;

    // 4. FIFO: the neighbours of the range, as push_neighbours() queues them.
    lane.pushes.clear();
    for (std::size_t k = range_begin; k < range_end; ++k)
    {
      const index_t s = moved_rec_[k].vertex;
      for (std::uint32_t x = offsets_[std::size_t(s)]; x < offsets_[std::size_t(s) + 1]; ++x)
      {
        const index_t c = neighbors_[x];
        if (nodes_[std::size_t(c)].stamp == frame_ || (pins && pins[c]))
          continue;
        Candidate& pushed = lane.pushes.emplace_back();
        pushed.vertex = c;
        pushed.sponsor = index_t(k);
        prefetch(neighbors_.data() + offsets_[std::size_t(c)]); // read if c moves
      }
    }
  };
  th.pool.run(job);
  std::size_t moves = 0;
  for (const Threaded::Lane& l : th.lanes)
    moves += l.won.size();
  moved_rec_.resize(first + moves);
  moved_.resize(first + moves);
  moved_root_.resize(first + moves);
  sorted_begin_ = first;
  sorted_end_ = moved_rec_.size();
  if (push && moved_rec_.size() > first)
  {
    th.pushed_frame = frame_;
    th.pushed_superstep = superstep_;
    th.pushed_end = moved_rec_.size();
  }
  ++threaded_supersteps_;
  if (thread_use_ == ThreadUse::when_cores_free &&
      th.pool.stalled()) // busy: one thread a while (chainmail_deformer.h)
  {
    threads_paused_ = true;
    backoff_ = std::min<std::uint32_t>(64, std::max<std::uint32_t>(1, 2 * backoff_));
    paused_frames_ = backoff_;
  }
  return count;
}

template std::size_t ChainMailDeformer::examine_threaded<ValidRegionFrame::axes>(
  std::size_t, std::size_t, const SuperstepRoot&);
template std::size_t ChainMailDeformer::examine_threaded<ValidRegionFrame::link>(
  std::size_t, std::size_t, const SuperstepRoot&);

} // namespace geoshaping
