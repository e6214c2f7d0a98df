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

void BucketFifoPriorityQueue::reset_ranks(index_t num_ranks)
{
  head_.assign(std::size_t(num_ranks), -1);
  tail_.assign(std::size_t(num_ranks), -1);
  clear();
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
