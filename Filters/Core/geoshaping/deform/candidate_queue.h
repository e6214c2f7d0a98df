#pragma once
// Structures holding the (candidate, sponsor) pairs awaiting analysis.
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/mesh/bit_cast.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <queue>
#include <vector>

namespace geoshaping
{

enum class QueueKind
{
  fifo,          // breadth first in supersteps (Li & Brodlie; SuperstepQueue, band 0)
  priority,      // lowest malleability first, ties in heap order (std::priority_queue)
  fifo_priority, // lowest malleability first, supersteps among equals (the paper's queue,
                 // SuperstepQueue; the default)
  max_violation  // largest constraint violation first (Schill's Enhanced ChainMail)
};

const char* queue_name(QueueKind kind);

struct Candidate
{
  index_t vertex;
  index_t sponsor;
};

// The sequential queues (Priority, Max Violation) have push(candidate, rank, violation)
// / pop(out) / clear(). `rank` is the index of the candidate's malleability among the
// mesh's sorted distinct values, so rank order is malleability order and equal ranks are
// exactly equal malleability.

// A binary heap of candidates on one key: the top is the entry `Before` orders first;
// entries with equal keys come out in whatever order the heap leaves them.
template<class Key, class Before>
class KeyedHeap
{
public:
  void push_keyed(Candidate c, Key key) { heap_.push({ key, c }); }
  bool pop(Candidate& out)
  {
    if (heap_.empty())
      return false;
    out = heap_.top().c;
    heap_.pop();
    return true;
  }
  void clear() { heap_ = {}; }

private:
  struct Item
  {
    Key key;
    Candidate c;
  };
  struct Later // std::priority_queue puts the "largest" on top: invert Before
  {
    bool operator()(const Item& a, const Item& b) const { return Before()(b.key, a.key); }
  };
  std::priority_queue<Item, std::vector<Item>, Later> heap_;
};

// Like the paper's STL priority queue: lowest rank first, equal ranks in heap order
// (the "vein" artefact).
class HeapPriorityQueue : public KeyedHeap<index_t, std::less<index_t>>
{
public:
  static constexpr bool needs_violation = false;
  static constexpr bool can_peek = false;
  void push(Candidate c, index_t rank, double) { push_keyed(c, rank); }
};

// The superstep order of FIFO and FIFO Priority (docs/deformer.md, "Order"): the order
// of its groups does not depend on the order in which they are filled, so a partitioned
// mesh gives the same result as one piece. An entry is (candidate c, sponsor s) in the
// group of the key
//
//   (band, root, generation)
//
// - band = c's malleability (FIFO: 0 for all): lowest first;
// - root = where propagation entered c's band region. An entry into a lower band than
//   its sponsor's starts a root (its generation, the length of the move it asks of c,
//   c's id: SuperstepRoot::entered, longest first); into the same band it keeps the
//   sponsor's root; into a higher band, and from the grasp, the base root (0, 0, 0),
//   which comes first. A region entered downhill at several places is so filled from
//   the first entry alone, as FIFO Priority's sequential queue does (it drains a lower
//   band before moving anything else): a rigid region moves as one.
// - generation = 1 + the superstep in which s moved (the grasp moves in superstep 0).
//
// A superstep takes the group of the lowest pending key, its entries in the order they
// were appended (the queue sorts no entry; see open() for how the deformer gets the
// (candidate id, sponsor id) order's result from that). The entries a superstep creates
// all have generation t + 1 for superstep t, while its own group has generation
// g <= t: they never join the superstep that creates them, so the deformer files them
// after it (seal_in_push_order).
//
// band = priority_band(m) (below): m quantised to a fixed number of levels, a function of
// the value alone, so pieces with different sets of malleability values agree on it.
//
// Cost: a frame of P appended entries in S supersteps with R distinct (band, root)s
// costs O(P + S + H log R) expected time (hash look-ups), H <= P being the number of
// times a chain goes on the heap (once per (band, root) when each superstep continues
// its own chain, the common case). Memory is 8 P bytes (the pool), plus 12 bytes per
// entry of the largest generation outside its first group (side buffer), 20 per group
// of the largest generation, 40 per pending group and ~80 per (band, root). How, for the
// k entries of one generation in G groups:
//
// 1. open() finds the generation's group of a (band, root): the first group opened with
//    one comparison, the others by a linear scan up to 8 groups, past that by a hash
//    map. append() writes the first group's (vertex, sponsor) pairs, 8 bytes each,
//    straight into the pool and the others' into a side buffer.
// 2. seal_in_push_order() files the first group in place and moves the others after it
//    by a stable counting sort of the side buffer on the group, O(k + G).
// 3. Groups are chained per (band, root) in filing order, which is their key order
//    since generations only grow; a binary heap holds the chains, whose order is their
//    (band, root) and never changes. A superstep continuing its own chain (the common
//    case) pops and files without heap work; a new (band, root) costs a hash-map insert
//    and O(log C) for C chains with pending groups.
//
// The pool holds the whole frame's entries (groups pop in key order, not in filing
// order); pool, side buffer and heap keep their capacity between frames.
struct SuperstepRoot
{
  std::uint32_t generation = 0; // 0: the base root
  std::uint64_t order = 0;      // roots of one (band, generation) pop by (order, gid)
  std::int64_t gid = 0;
  bool operator==(const SuperstepRoot& o) const
  {
    return generation == o.generation && order == o.order && gid == o.gid;
  }
  // The root an entry (c, s) into a lower band starts (docs/deformer.md, "Order"):
  // generation 1 + the superstep of s's move, order ~bits(|u|^2) for the move u the
  // entry asks of c (the bits of a double >= 0 grow with it, so the longest move comes
  // first), gid c's global id (exactly equal lengths only).
  static SuperstepRoot entered(std::uint32_t generation, double length_squared, std::int64_t gid)
  {
    return { generation, ~bit_cast<std::uint64_t>(length_squared), gid };
  }
};

// FIFO Priority's band of a malleability m in [0, 1]: rigid (m = 0, +0 or -0) alone in band
// 0, then 64 levels of width 1/64, the last one closed:
//
//   band(0) = 0,   band(m) = 1 + min(63, floor(64 m))   for m in (0, 1]
//
// Values of one band are equal for the order (first in, first out among them); the valid
// region still uses the exact value. Bands are monotone in m, so malleabilities at least
// 1/64 apart keep the exact order bit for bit (painted tiles, palette colours, the
// scenes); a smooth brush's many values fall into 65 bands instead of one band each,
// which keeps supersteps large (docs/deformer.md, "Bands").
constexpr std::uint32_t priority_levels = 64;
inline std::uint32_t priority_band(float m)
{
  if (!(m > 0.0f))
    return 0;
  const float scaled = m * float(priority_levels);
  return 1 + (scaled >= float(priority_levels - 1) ? priority_levels - 1 : std::uint32_t(scaled));
}

// (band, root, generation) as four words compared in lexicographic order (band and the
// root's generation, its order, its gid, the generation), so pieces can reduce it as
// plain integers.
using SuperstepKey = std::array<std::uint64_t, 4>;

class SuperstepQueue
{
public:
  static constexpr SuperstepKey none = { ~std::uint64_t(0), ~std::uint64_t(0), ~std::uint64_t(0),
    ~std::uint64_t(0) };
  static SuperstepKey key(std::uint32_t band, const SuperstepRoot& root, std::uint32_t generation)
  {
    return { std::uint64_t(band) << 32 | root.generation, root.order,
      std::uint64_t(root.gid) ^ (std::uint64_t(1) << 63), generation };
  }
  static SuperstepRoot root_of(const SuperstepKey& k)
  {
    return { std::uint32_t(k[0]), k[1], std::int64_t(k[2] ^ (std::uint64_t(1) << 63)) };
  }
  // (vertex, sponsor) pairs appended to the group of their (band, root) and filed by
  // seal_in_push_order() into one group per (band, root), each in push order. A caller
  // that pushes each candidate's entries in sponsor id order and examines a group's
  // candidates independently of one another (ChainMailDeformer: it orders a superstep's
  // moves by id afterwards) gets the result of the (candidate id, sponsor id) order.
  // open() gives the generation's group of a (band, root): the first opened (most often
  // the only one) is written in place, the others go through a side buffer.
  std::uint32_t open(std::uint32_t band, const SuperstepRoot& root)
  {
    const ChainKey k{ std::uint64_t(band) << 32 | root.generation, root.order,
      std::uint64_t(root.gid) ^ (std::uint64_t(1) << 63) }; // key()'s first three words
    if (open_.empty())
    {
      open_begin_ = pool_.size();
      open_.push_back(k);
      return 0;
    }
    return open_[0] == k ? 0 : open_group(k);
  }
  void append(std::uint32_t group, index_t vertex, index_t sponsor)
  {
    if (group == 0)
      pool_.push_back({ vertex, sponsor });
    else
      side_.push_back({ { vertex, sponsor }, group });
  }
  // n entries of one group at once: append(group, c[i].vertex, c[i].sponsor) for each i.
  void append(std::uint32_t group, const Candidate* c, std::size_t n)
  {
    if (group == 0)
      pool_.insert(pool_.end(), c, c + n);
    else
      for (std::size_t i = 0; i < n; ++i)
        side_.push_back({ c[i], group });
  }
  // Files the entries appended since the last call as `generation`, which must exceed
  // the previous one's since clear() (std::invalid_argument otherwise; nothing is
  // checked or filed when nothing was appended).
  void seal_in_push_order(std::uint32_t generation);
  // The lowest pending key, `none` when nothing is pending (drops finished chains: not
  // safe to call from two threads at once).
  SuperstepKey top() const
  {
    drop_done_chains();
    return heap_.empty() ? none : groups_[chains_[heap_.front()].head].key;
  }
  // Removes the group `key` if it is the lowest: its entries are entries()[begin, end),
  // in push order, valid until the next append().
  bool pop(const SuperstepKey& key, std::size_t& begin, std::size_t& end);
  const Candidate* entries() const { return pool_.data(); }
  // Empties the queue, keeping the buffers.
  void clear();
  std::size_t memory_bytes() const
  {
    return pool_.capacity() * sizeof(Candidate) + groups_.capacity() * sizeof(Group) +
           free_.capacity() * sizeof(std::uint32_t) + chains_.capacity() * sizeof(Chain) +
           heap_.capacity() * sizeof(std::uint32_t) + offsets_.capacity() * sizeof(std::uint32_t) +
           side_.capacity() * sizeof(SideEntry) + open_.capacity() * sizeof(ChainKey) +
           chain_of_.memory_bytes() + open_of_.memory_bytes();
  }

private:
  static constexpr std::uint32_t nil = ~std::uint32_t(0);
  struct Group
  {
    SuperstepKey key;
    std::uint32_t begin, end; // in pool_, which holds fewer than 2^32 entries (checked)
    std::uint32_t next;       // the chain's next group, nil at its tail
  };
  // The groups of one (band, root) in filing order, which is their key order: a generation
  // filed exceeds every earlier one. Chains differ in (band, root), so their order
  // does not change as they pop: a binary heap of chains on (band, root).
  struct ChainKey
  {
    std::uint64_t band_generation, order, gid; // key()'s first three words
    bool operator==(const ChainKey& o) const
    {
      return band_generation == o.band_generation && order == o.order && gid == o.gid;
    }
  };
  // ChainKey -> id by open addressing (linear probing, at most half full): no allocation
  // per key, and clear() is O(1) (an epoch stamp per slot), which matters when a smooth
  // paint makes a (band, root) for most moved vertices. Expected O(1) per operation.
  class KeyTable
  {
  public:
    std::uint32_t find(const ChainKey& k) const;      // nil when absent
    void insert(const ChainKey& k, std::uint32_t id); // k must be absent
    void clear();
    std::size_t size() const { return size_; }
    std::size_t memory_bytes() const { return slots_.capacity() * sizeof(Slot); }

  private:
    struct Slot
    {
      ChainKey key;
      std::uint32_t id, epoch; // the slot is used iff epoch == epoch_
    };
    std::size_t home(const ChainKey& k) const
    {
      std::uint64_t h =
        (k.band_generation * 0x9e3779b97f4a7c15ULL + k.order) * 0x9e3779b97f4a7c15ULL + k.gid;
      h ^= h >> 32;
      h *= 0xd6e8feb86659fd93ULL;
      return std::size_t(h ^ (h >> 32)) & (slots_.size() - 1);
    }
    std::vector<Slot> slots_; // a power of two, or empty
    std::size_t size_ = 0;
    std::uint32_t epoch_ = 1;
  };
  struct Chain
  {
    ChainKey key;
    std::uint32_t head, tail; // in groups_; head nil: no pending group
    bool in_heap;
  };
  struct Later // for the std:: heap functions on chain ids: the lowest (band, root) on top
  {
    const std::vector<Chain>* chains;
    bool operator()(std::uint32_t a, std::uint32_t b) const
    {
      const ChainKey& x = (*chains)[a].key;
      const ChainKey& y = (*chains)[b].key;
      return x.band_generation != y.band_generation ? x.band_generation > y.band_generation
             : x.order != y.order                   ? x.order > y.order
                                                    : x.gid > y.gid;
    }
  };
  void file(const Group& g);
  // A chain whose last group popped stays on the heap until it is found on top with
  // none filed meanwhile: the next superstep most often refills it (same band and root).
  void drop_done_chains() const;
  std::vector<Candidate> pool_;
  std::vector<Group> groups_;               // pending groups and free slots
  std::vector<std::uint32_t> free_;         // free slots of groups_
  mutable std::vector<Chain> chains_;       // by chain id, the frame's (band, root)s
  mutable std::vector<std::uint32_t> heap_; // chains with pending groups, a heap on Later
  KeyTable chain_of_;                       // chains_ by key
  std::uint32_t open_group(const ChainKey& k);
  struct SideEntry
  {
    Candidate c;
    std::uint32_t group;
  };
  std::vector<ChainKey> open_;         // open(): the (band, root)s of the generation
  std::size_t open_begin_ = 0;         // its first entry in pool_
  std::vector<SideEntry> side_;        // its entries of groups other than the first
  std::vector<std::uint32_t> offsets_; // seal_in_push_order's counting sort
  KeyTable open_of_;                   // open_ by key, when large
  std::uint32_t last_ = nil;           // the chain popped or filed to last (most often the next)
  std::uint32_t sealed_generation_ = 0;
};

// Enhanced ChainMail order: the candidate whose rest position lies farthest outside its
// valid region (at the time it is queued) comes out first; ties in heap order.
class MaxViolationQueue : public KeyedHeap<double, std::greater<double>>
{
public:
  static constexpr bool needs_violation = true;
  static constexpr bool can_peek = false;
  void push(Candidate c, index_t, double violation) { push_keyed(c, violation); }
};

} // namespace geoshaping
