#include "geoshaping/candidate_queue.h"

#include <cstring>

namespace geoshaping
{

const char* queue_name(QueueKind kind)
{
  switch (kind)
  {
    case QueueKind::fifo:
      return "FIFO";
    case QueueKind::priority:
      return "Priority";
    case QueueKind::fifo_priority:
      return "FIFO Priority";
    case QueueKind::max_violation:
      return "Max Violation";
  }
  return "";
}

bool parse_queue_name(const char* name, QueueKind& kind)
{
  for (QueueKind k :
    { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority, QueueKind::max_violation })
  {
    if (name && std::strcmp(name, queue_name(k)) == 0)
    {
      kind = k;
      return true;
    }
  }
  return false;
}

bool HeapPriorityQueue::pop(Candidate& out)
{
  if (heap_.empty())
    return false;
  out = heap_.top().c;
  heap_.pop();
  return true;
}

bool MaxViolationQueue::pop(Candidate& out)
{
  if (heap_.empty())
    return false;
  out = heap_.top().c;
  heap_.pop();
  return true;
}

void BucketFifoPriorityQueue::reset_ranks(index_t num_ranks)
{
  head_.assign(std::size_t(num_ranks), -1);
  tail_.assign(std::size_t(num_ranks), -1);
  clear();
}

void BucketFifoPriorityQueue::push(Candidate c, index_t rank, double)
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

bool BucketFifoPriorityQueue::pop(Candidate& out)
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

void BucketFifoPriorityQueue::clear()
{
  // Only buckets still listed as active can be non-empty.
  while (!active_.empty())
  {
    head_[active_.top()] = -1;
    tail_[active_.top()] = -1;
    active_.pop();
  }
  pool_.clear();
}

} // namespace geoshaping
