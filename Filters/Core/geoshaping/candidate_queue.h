#pragma once
// Structures holding the (candidate, sponsor) pairs awaiting analysis.
#include "geoshaping/adjacency.h"

#include <functional>
#include <memory>
#include <queue>
#include <vector>

namespace geoshaping
{

enum class QueueKind
{
  fifo,          // first in, first out (Li & Brodlie)
  priority,      // lowest malleability first, ties in heap order (std::priority_queue)
  fifo_priority, // lowest malleability first, FIFO among equals (the paper's queue; default)
  max_violation  // largest constraint violation first (Schill's Enhanced ChainMail)
};

const char* queue_name(QueueKind kind);
// Parses "FIFO", "Priority", "FIFO Priority", "Max Violation"; returns false if unknown.
bool parse_queue_name(const char* name, QueueKind& kind);

struct Candidate
{
  index_t vertex;
  index_t sponsor;
};

// Every queue has push(candidate, rank, violation) / pop(out) / clear(). `rank` is the
// index of the candidate's malleability among the mesh's sorted distinct values, so
// rank order is malleability order and equal ranks are exactly equal malleability.

class FifoQueue
{
public:
  static constexpr bool needs_violation = false;
  static constexpr bool can_peek = true;
  void push(Candidate c, index_t, double) { items_.push_back(c); }
  bool pop(Candidate& out)
  {
    if (head_ == items_.size())
      return false;
    out = items_[head_++];
    return true;
  }
  bool peek(index_t k, Candidate& out) const
  {
    if (head_ + std::size_t(k) >= items_.size())
      return false;
    out = items_[head_ + std::size_t(k)];
    return true;
  }
  void clear()
  {
    items_.clear();
    head_ = 0;
  }

private:
  std::vector<Candidate> items_;
  std::size_t head_ = 0;
};

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

// FIFO-preserving priority queue. One FIFO per distinct malleability value (bucket
// indexed by rank), each a singly linked list of fixed-size chunks (64 candidates, 512
// bytes, filled and drained in order) taken from one pool, and a min-heap of the ranks
// whose bucket is non-empty. push: append to the bucket's tail chunk, O(1), plus one
// heap push when the bucket was empty; pop: front of the lowest non-empty bucket, O(1),
// plus one heap pop when it empties. With K distinct values among the queued candidates
// the cost is O(1) amortised per operation and O(log K) <= O(log n) in the worst case;
// order is exactly lowest malleability first, first in first out among equal values.
// Chunks keep each bucket contiguous, so the deformer can look a few entries ahead
// (peek) to prefetch. The pool is reused between frames, so a frame allocates nothing
// once warm.
class BucketFifoPriorityQueue
{
public:
  static constexpr bool needs_violation = false;
  static constexpr bool can_peek = true;
  static constexpr index_t chunk_size = 62; // a chunk is 512 bytes
  BucketFifoPriorityQueue() = default;
  // Copies keep the ranks, not the queued candidates or the pool (scratch of a frame).
  BucketFifoPriorityQueue(const BucketFifoPriorityQueue& o)
  {
    reset_ranks(index_t(o.head_.size()));
  }
  BucketFifoPriorityQueue& operator=(const BucketFifoPriorityQueue& o)
  {
    if (this != &o)
      reset_ranks(index_t(o.head_.size()));
    return *this;
  }
  BucketFifoPriorityQueue(BucketFifoPriorityQueue&&) = default;
  BucketFifoPriorityQueue& operator=(BucketFifoPriorityQueue&&) = default;
  void reset_ranks(index_t num_ranks);
  void push(Candidate c, index_t rank, double)
  {
    Chunk* t = tail_[std::size_t(rank)];
    if (!t) // first push to this rank this frame
    {
      t = new_chunk();
      head_[std::size_t(rank)] = tail_[std::size_t(rank)] = t;
      used_.push_back(rank);
      activate(rank);
    }
    else if (t->begin == t->end) // empty bucket (then head == tail): restart its chunk
    {
      t->begin = t->end = 0;
      activate(rank);
    }
    else if (t->end == chunk_size)
    {
      Chunk* n = new_chunk();
      t->next = n;
      tail_[std::size_t(rank)] = t = n;
    }
    t->items[t->end++] = c;
  }
  bool pop(Candidate& out)
  {
    Chunk* h = front_;
    if (!h)
      return false;
    out = h->items[h->begin++];
    if (h->begin == h->end)
    {
      if (h->next) // a full chunk drained: the next one is non-empty
        head_[std::size_t(rank_)] = front_ = h->next;
      else
        deactivate();
    }
    return true;
  }
  // The candidate `k` places behind the front of the lowest bucket, if it lies in the
  // same chunk (a hint for prefetching: later pushes may change what comes next).
  bool peek(index_t k, Candidate& out) const
  {
    if (!front_ || front_->begin + k >= front_->end)
      return false;
    out = front_->items[front_->begin + k];
    return true;
  }
  void clear();
  std::size_t memory_bytes() const
  {
    return pool_.size() * sizeof(Chunk) + (head_.capacity() + tail_.capacity()) * sizeof(Chunk*) +
           (used_.capacity() + active_.size()) * sizeof(index_t);
  }

private:
  struct Chunk
  {
    Chunk() {} // no zeroing of the items on allocation
    index_t begin, end;
    Chunk* next;
    Candidate items[chunk_size];
  };
  Chunk* new_chunk()
  {
    if (used_chunks_ == pool_.size())
      pool_.emplace_back(new Chunk);
    Chunk* ch = pool_[used_chunks_++].get();
    ch->begin = ch->end = 0;
    ch->next = nullptr;
    return ch;
  }
  // The front is the head chunk of the lowest non-empty rank (rank_), cached.
  void activate(index_t rank)
  {
    if (front_ && rank > rank_)
    {
      active_.push(rank);
      return;
    }
    if (front_)
      active_.push(rank_);
    rank_ = rank;
    front_ = head_[std::size_t(rank)];
  }
  void deactivate()
  {
    if (active_.empty())
    {
      front_ = nullptr;
      return;
    }
    rank_ = active_.top();
    active_.pop();
    front_ = head_[std::size_t(rank_)];
  }
  std::vector<std::unique_ptr<Chunk>> pool_; // stable addresses, reused between frames
  std::size_t used_chunks_ = 0;
  std::vector<Chunk*> head_, tail_; // per rank: first and last chunk, null before any push
  std::vector<index_t> used_;       // ranks with chunks this frame
  Chunk* front_ = nullptr;          // head chunk of rank_, null when the queue is empty
  index_t rank_ = 0;
  // The other non-empty ranks.
  std::priority_queue<index_t, std::vector<index_t>, std::greater<index_t>> active_;
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
