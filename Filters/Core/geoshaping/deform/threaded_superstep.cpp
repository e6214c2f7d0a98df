// The threaded superstep (chainmail_deformer.h, "Threads"): examine() on several threads,
// bit for bit.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/worker_pool.h"
#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/mesh/prefetch.h"

#include <algorithm>
#include <atomic>
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
  // By internal id: the bits of the largest |u|^2 proposed for the vertex in the current
  // superstep (0: none; a proposal's |u|^2 > 0, and the bits of non-negative doubles are
  // in their order), and 1 + the first entry proposing it, 0 for none. Every vertex
  // claimed moves in that superstep, which sets both back to 0: all are 0 between
  // supersteps.
  std::vector<std::atomic<std::uint64_t>> longest;
  std::vector<std::atomic<std::uint32_t>> claim;
  struct Proposal
  {
    Eigen::Vector3d u;
    std::uint32_t entry;
    index_t vertex, sponsor;
  };
  struct Won // a winning proposal
  {
    std::int64_t gid;
    std::uint32_t proposal;
    index_t outer; // the vertex's caller id
    bool operator<(const Won& o) const { return gid < o.gid; }
  };
  struct alignas(64) Lane // one thread's
  {
    std::vector<Proposal> proposals;                       // in push order
    std::vector<Won> won;                                  // by global id
    std::vector<std::int64_t> samples;                     // of won's ids
    std::vector<Candidate> pushes;                         // FIFO: this range's pushes
    std::vector<std::pair<std::size_t, std::size_t>> runs; // step 3: each lane's range
    std::vector<std::int64_t> splitters;                   // step 3: all lanes' samples
  };
  std::vector<Lane> lanes;
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

void ChainMailDeformer::set_threads(int threads)
{
  const int n = threads > 0 ? threads : std::max(1, int(std::thread::hardware_concurrency()));
  if (n != threads_)
    threaded_.state.reset();
  threads_ = n;
  automatic_threads_ = threads <= 0;
  threads_paused_ = false;
  paused_frames_ = backoff_ = 0;
}

std::size_t ChainMailDeformer::threaded_bytes() const
{
  const Threaded* t = threaded_.state.get();
  if (!t)
    return 0;
  std::size_t bytes =
    t->claim.capacity() * sizeof(std::uint32_t) + t->longest.capacity() * sizeof(std::uint64_t);
  for (const Threaded::Lane& lane : t->lanes)
    bytes += lane.proposals.capacity() * sizeof(Threaded::Proposal) +
             lane.won.capacity() * sizeof(lane.won[0]) +
             lane.samples.capacity() * sizeof(std::int64_t) +
             lane.pushes.capacity() * sizeof(Candidate);
  return bytes;
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

namespace
{
// m = min(m, v) on claims, 0 standing for none.
inline void claim_first(std::atomic<std::uint32_t>& m, std::uint32_t v)
{
  std::uint32_t cur = m.load(std::memory_order_relaxed);
  while ((cur == 0 || v < cur) && !m.compare_exchange_weak(cur, v, std::memory_order_relaxed))
  {
  }
}

// m = max(m, v).
inline void claim_longest(std::atomic<std::uint64_t>& m, std::uint64_t v)
{
  std::uint64_t cur = m.load(std::memory_order_relaxed);
  while (v > cur && !m.compare_exchange_weak(cur, v, std::memory_order_relaxed))
  {
  }
}
} // namespace

template<ValidRegionFrame Frame>
std::size_t ChainMailDeformer::examine_threaded(
  std::size_t begin, std::size_t end, const SuperstepRoot& root)
{
  if (!threaded_.state)
    threaded_.state = std::make_unique<Threaded>(threads_);
  Threaded& th = *threaded_.state;
  if (th.claim.size() != nodes_.size())
  {
    std::vector<std::atomic<std::uint32_t>>(nodes_.size()).swap(th.claim);   // zeroed
    std::vector<std::atomic<std::uint64_t>>(nodes_.size()).swap(th.longest); // zeroed
  }
  const int threads = th.pool.size();
  const std::size_t first = moved_rec_.size(), count = end - begin;
  const bool push = queue_kind_ == QueueKind::fifo;
  const Candidate* const entries = supersteps_.entries();
  const std::uint8_t* const pins = pinned_inner_.empty() ? nullptr : pinned_inner_.data();
  moved_rec_.resize(first + count); // uninitialised
  moved_root_.resize(first + count);
  const StoredRoot stored_root(root);

  auto job = [&](int t)
  {
    Threaded::Lane& lane = th.lanes[std::size_t(t)];
    // 1. Proposals of the chunk: entries whose candidate did not move in an earlier
    //    superstep and whose target is not zero (those examine() would move, were they
    //    first), each raising its candidate's longest |u|^2 to its own.
    lane.proposals.clear();
    const std::size_t b = begin + count * std::size_t(t) / std::size_t(threads);
    const std::size_t e = begin + count * std::size_t(t + 1) / std::size_t(threads);
    for (std::size_t k = b; k < e; ++k)
    {
      const Candidate& entry = entries[k];
      const Node& c = nodes_[std::size_t(entry.vertex)];
      if (c.stamp == frame_)
        continue;
      const Eigen::Vector3d target = required_displacement<Frame>(c, entry.sponsor);
      if (target.isZero(0.0))
        continue;
      claim_longest(
        th.longest[std::size_t(entry.vertex)], bit_cast<std::uint64_t>(target.squaredNorm()));
      lane.proposals.push_back({ target, std::uint32_t(k + 1), entry.vertex, entry.sponsor });
    }
    th.pool.barrier();

    // 1b. The proposals as long as their candidate's longest claim it, the first in push
    //     order winning: examine()'s rule (sponsor_wins()).
    for (const Threaded::Proposal& p : lane.proposals)
      if (bit_cast<std::uint64_t>(p.u.squaredNorm()) ==
          th.longest[std::size_t(p.vertex)].load(std::memory_order_relaxed))
        claim_first(th.claim[std::size_t(p.vertex)], p.entry);
    th.pool.barrier();

    // 2. The winners, marked moved, in id order; samples of their ids for the ranges of
    //    step 3. (A loser reads its candidate's claim as the winner's entry or, once
    //    reset, 0: never its own.)
    lane.won.clear();
    for (std::size_t j = 0; j < lane.proposals.size(); ++j)
    {
      const Threaded::Proposal& p = lane.proposals[j];
      const std::size_t i = std::size_t(p.vertex);
      if (th.claim[i].load(std::memory_order_relaxed) != p.entry)
        continue;
      th.claim[i].store(0, std::memory_order_relaxed);
      th.longest[i].store(0, std::memory_order_relaxed);
      nodes_[i].stamp = frame_;
      lane.won.push_back({ global_id_inner(p.vertex), std::uint32_t(j), outer_of_[i] });
      prefetch_neighbour_records(i); // step 4 tests them, as after move()
    }
    std::sort(lane.won.begin(), lane.won.end());
    lane.samples.clear();
    const std::size_t n_won = lane.won.size(),
                      per_lane = std::min<std::size_t>(n_won, 16 * threads);
    for (std::size_t q = 0; q < per_lane; ++q)
      lane.samples.push_back(lane.won[(2 * q + 1) * n_won / (2 * per_lane)].gid);
    if (t == 0)
    {
      // Room for every proposal (the moves are fewer; moved_rec_ and moved_root_ were
      // sized before the run).
      std::size_t proposals = 0;
      for (const Threaded::Lane& l : th.lanes)
        proposals += l.proposals.size();
      moved_.resize(first + proposals);
    }
    th.pool.barrier();

    // 3. Thread t writes the moves whose ids lie in [splitter t - 1, splitter t) into the
    //    slots of their rank in id order, with the rest of what move() sets. Every thread
    //    takes the same splitters from the same samples.
    lane.splitters.clear();
    for (const Threaded::Lane& l : th.lanes)
      lane.splitters.insert(lane.splitters.end(), l.samples.begin(), l.samples.end());
    std::sort(lane.splitters.begin(), lane.splitters.end());
    const std::size_t n_samples = lane.splitters.size();
    auto splitter = [&](int q)
    {
      if (q <= 0)
        return std::numeric_limits<std::int64_t>::min();
      if (q >= threads || n_samples == 0)
        return std::numeric_limits<std::int64_t>::max();
      return lane.splitters[n_samples * std::size_t(q) / std::size_t(threads)];
    };
    const std::int64_t lo = splitter(t), hi = splitter(t + 1);
    const bool last = t + 1 == threads;
    std::size_t slot = first;
    auto& runs = lane.runs;
    runs.resize(std::size_t(threads));
    for (int u = 0; u < threads; ++u)
    {
      const auto& won = th.lanes[std::size_t(u)].won;
      auto key_less = [](const Threaded::Won& a, std::int64_t k) { return a.gid < k; };
      const std::size_t from =
        t == 0 ? 0
               : std::size_t(std::lower_bound(won.begin(), won.end(), lo, key_less) - won.begin());
      const std::size_t to =
        last ? won.size()
             : std::size_t(std::lower_bound(won.begin(), won.end(), hi, key_less) - won.begin());
      runs[std::size_t(u)] = { from, to };
      slot += from;
    }
    const std::size_t range_begin = slot;
    for (;; ++slot)
    {
      int best = -1;
      std::int64_t best_id = 0;
      for (int u = 0; u < threads; ++u)
      {
        const auto& run = runs[std::size_t(u)];
        if (run.first < run.second)
        {
          const std::int64_t id = th.lanes[std::size_t(u)].won[run.first].gid;
          if (best < 0 || id < best_id)
          {
            best = u;
            best_id = id;
          }
        }
      }
      if (best < 0)
        break;
      const Threaded::Lane& from = th.lanes[std::size_t(best)];
      const Threaded::Won& w = from.won[runs[std::size_t(best)].first++];
      const Threaded::Proposal& p = from.proposals[w.proposal];
      slot_[std::size_t(p.vertex)] = index_t(slot);
      moved_rec_[slot] = { p.u, p.vertex, p.sponsor };
      moved_root_[slot] = stored_root;
      moved_[slot] = w.outer;
    }
    const std::size_t range_end = slot;
    if (!push)
      return;
    th.pool.barrier();

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
        lane.pushes.push_back({ c, index_t(k) });
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
  if (automatic_threads_ && th.pool.stalled()) // busy: one thread a while (chainmail_deformer.h)
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
