#pragma once
// Structures holding the (candidate, sponsor) pairs awaiting analysis.
#include "geoshaping/adjacency.h"

#include <functional>
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
  void push(Candidate c, index_t, double) { items_.push_back(c); }
  bool pop(Candidate& out)
  {
    if (head_ == items_.size())
      return false;
    out = items_[head_++];
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
template <class Key, class Before>
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
  void push(Candidate c, index_t rank, double) { push_keyed(c, rank); }
};

// FIFO-preserving priority queue. One FIFO per distinct malleability value (bucket
// indexed by rank), kept as singly linked lists threaded through one pooled array, and
// a min-heap of the ranks whose bucket is non-empty. push: append to the bucket, O(1),
// plus one heap push when the bucket was empty; pop: front of the lowest non-empty
// bucket, O(1), plus one heap pop when it empties. With K distinct values among the
// queued candidates the cost is O(1) amortised per operation and O(log K) <= O(log n)
// in the worst case; order is exactly lowest malleability first, first in first out
// among equal values. The pool is reused between frames, so a frame allocates nothing
// once warm.
class BucketFifoPriorityQueue
{
public:
  static constexpr bool needs_violation = false;
  void reset_ranks(index_t num_ranks);
  void push(Candidate c, index_t rank, double)
  {
    const index_t node = index_t(pool_.size());
    pool_.push_back({ c, -1 });
    if (head_[rank] < 0)
    {
      head_[rank] = node;
      active_.push(rank);
    }
    else
    {
      pool_[tail_[rank]].next = node;
    }
    tail_[rank] = node;
  }
  bool pop(Candidate& out)
  {
    if (active_.empty())
      return false;
    const index_t rank = active_.top();
    const index_t node = head_[rank];
    out = pool_[node].c;
    head_[rank] = pool_[node].next;
    if (head_[rank] < 0)
    {
      tail_[rank] = -1;
      active_.pop();
    }
    return true;
  }
  void clear();
  std::size_t memory_bytes() const
  {
    return pool_.capacity() * sizeof(Node) + (head_.capacity() + tail_.capacity()) * sizeof(index_t);
  }

private:
  struct Node
  {
    Candidate c;
    index_t next;
  };
  std::vector<Node> pool_;
  std::vector<index_t> head_, tail_; // per rank; -1 when empty
  std::priority_queue<index_t, std::vector<index_t>, std::greater<index_t>> active_;
};

// Enhanced ChainMail order: the candidate whose rest position lies farthest outside its
// valid region (at the time it is queued) comes out first; ties in heap order.
class MaxViolationQueue : public KeyedHeap<double, std::greater<double>>
{
public:
  static constexpr bool needs_violation = true;
  void push(Candidate c, index_t, double violation) { push_keyed(c, violation); }
};

} // namespace geoshaping
