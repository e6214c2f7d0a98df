#include "geoshaping/candidate_queue.h"

#include <algorithm>
#include <cstring>
#include <tuple>

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

void SuperstepQueue::seal(std::uint32_t generation)
{
  auto rank = [](const SuperstepEntry& e) {
    return std::make_tuple(e.band, e.root.generation, e.root.gid, e.candidate_gid, e.sponsor_gid);
  };
  std::sort(pool_.begin() + std::ptrdiff_t(sealed_), pool_.end(),
    [&](const SuperstepEntry& a, const SuperstepEntry& b) { return rank(a) < rank(b); });
  std::size_t begin = sealed_;
  while (begin < pool_.size())
  {
    const SuperstepEntry& first = pool_[begin];
    std::size_t end = begin + 1;
    while (end < pool_.size() && pool_[end].band == first.band && pool_[end].root == first.root)
      ++end;
    groups_.push({ key(first.band, first.root, generation), begin, end });
    begin = end;
  }
  sealed_ = pool_.size();
}

bool SuperstepQueue::pop(const SuperstepKey& k, std::size_t& begin, std::size_t& end)
{
  if (groups_.empty() || groups_.top().key != k)
    return false;
  begin = groups_.top().begin;
  end = groups_.top().end;
  groups_.pop();
  return true;
}

void SuperstepQueue::clear()
{
  pool_.clear();
  sealed_ = 0;
  groups_ = {};
}

} // namespace geoshaping
