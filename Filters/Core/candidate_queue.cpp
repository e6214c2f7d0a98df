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
  head_.assign(std::size_t(num_ranks), nullptr);
  tail_.assign(std::size_t(num_ranks), nullptr);
  used_.clear();
  clear();
}

void BucketFifoPriorityQueue::clear()
{
  for (index_t rank : used_)
    head_[std::size_t(rank)] = tail_[std::size_t(rank)] = nullptr;
  used_.clear();
  while (!active_.empty())
    active_.pop();
  front_ = nullptr;
  used_chunks_ = 0;
}

} // namespace geoshaping
