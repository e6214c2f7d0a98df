#include "geoshaping/deform/candidate_queue.h"
#include "geoshaping/mesh/enum_names.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace geoshaping
{

const char* queue_name(QueueKind kind)
{
  static constexpr EnumName names[] = { { int(QueueKind::fifo), "FIFO" },
    { int(QueueKind::priority), "Priority" }, { int(QueueKind::fifo_priority), "FIFO Priority" },
    { int(QueueKind::max_violation), "Max Violation" } };
  return name_of(names, int(kind));
}

std::uint32_t SuperstepQueue::open_group(const ChainKey& k)
{
  constexpr std::size_t scan = 8; // groups looked up by a linear scan, more by hash
  if (open_.size() <= scan)
  {
    for (std::size_t g = 1; g < open_.size(); ++g)
      if (open_[g] == k)
        return std::uint32_t(g);
  }
  else
  {
    for (std::size_t g = open_of_.size(); g < open_.size(); ++g)
      open_of_.insert(open_[g], std::uint32_t(g));
    const std::uint32_t found = open_of_.find(k);
    if (found != nil)
      return found;
  }
  open_.push_back(k);
  return std::uint32_t(open_.size() - 1);
}

void SuperstepQueue::seal_in_push_order(std::uint32_t generation)
{
  if (open_.empty())
    return;
  if (pool_.size() == open_begin_ && side_.empty())
  {
    open_.clear(); // opened, nothing appended
    return;
  }
  if (generation <= sealed_generation_)
    throw std::invalid_argument("SuperstepQueue: generations must be sealed in increasing order");
  sealed_generation_ = generation;
  const std::size_t begin = open_begin_, end = pool_.size() + side_.size();
  if (end > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("SuperstepQueue: more than 2^32 entries in a frame");
  auto file_open = [&](std::size_t g, std::size_t b, std::size_t e)
  {
    if (b < e)
      file({ { open_[g].band_generation, open_[g].order, open_[g].gid, generation },
        std::uint32_t(b), std::uint32_t(e) });
  };
  file_open(0, begin, pool_.size());
  if (!side_.empty())
  {
    // The other groups after it, by a stable counting sort of the side buffer.
    const std::size_t n = open_.size();
    offsets_.assign(n + 1, 0);
    for (const SideEntry& e : side_)
      ++offsets_[e.group + 1];
    offsets_[1] = std::uint32_t(pool_.size());
    for (std::size_t g = 2; g <= n; ++g)
      offsets_[g] += offsets_[g - 1];
    const std::size_t side_begin = pool_.size();
    pool_.resize(end);
    for (const SideEntry& e : side_)
      pool_[offsets_[e.group]++] = e.c;
    // offsets_[g] is now group g's end.
    for (std::size_t g = 1; g < n; ++g)
      file_open(g, g == 1 ? side_begin : offsets_[g - 1], offsets_[g]);
    side_.clear();
  }
  open_.clear();
  open_of_.clear();
}

void SuperstepQueue::file(const Group& g)
{
  const ChainKey ck{ g.key[0], g.key[1], g.key[2] };
  std::uint32_t c = last_;
  if (c == nil || !(chains_[c].key == ck))
  {
    // A root made in this generation (a downhill entry) has no chain yet: seal files each
    // (band, root) of a generation once.
    const bool new_root = std::uint32_t(ck.band_generation) == g.key[3];
    c = new_root ? nil : chain_of_.find(ck);
    if (c == nil)
    {
      c = std::uint32_t(chains_.size());
      chains_.push_back({ ck, nil, nil, false });
      chain_of_.insert(ck, c);
    }
  }
  std::uint32_t slot;
  if (free_.empty())
  {
    slot = std::uint32_t(groups_.size());
    groups_.push_back(g);
  }
  else
  {
    slot = free_.back();
    free_.pop_back();
    groups_[slot] = g;
  }
  groups_[slot].next = nil;
  Chain& chain = chains_[c];
  (chain.head == nil ? chain.head : groups_[chain.tail].next) = slot;
  chain.tail = slot;
  if (!chain.in_heap)
  {
    chain.in_heap = true;
    heap_.push_back(c);
    std::push_heap(heap_.begin(), heap_.end(), Later{ &chains_ });
  }
  last_ = c;
}

std::uint32_t SuperstepQueue::KeyTable::find(const ChainKey& k) const
{
  if (size_ == 0)
    return nil;
  for (std::size_t i = home(k);; i = (i + 1) & (slots_.size() - 1))
  {
    const Slot& s = slots_[i];
    if (s.epoch != epoch_)
      return nil;
    if (s.key == k)
      return s.id;
  }
}

void SuperstepQueue::KeyTable::insert(const ChainKey& k, std::uint32_t id)
{
  if (2 * (size_ + 1) > slots_.size())
  {
    std::vector<Slot> old(std::max<std::size_t>(64, 2 * slots_.size()));
    old.swap(slots_);
    const std::uint32_t live = epoch_;
    epoch_ = 1;
    size_ = 0;
    for (const Slot& s : old)
      if (s.epoch == live)
        insert(s.key, s.id);
  }
  std::size_t i = home(k);
  while (slots_[i].epoch == epoch_)
    i = (i + 1) & (slots_.size() - 1);
  slots_[i] = { k, id, epoch_ };
  ++size_;
}

void SuperstepQueue::KeyTable::clear()
{
  if (size_ == 0)
    return;
  size_ = 0;
  if (++epoch_ == 0) // after 2^32 - 1 clears: no stale stamp may match
  {
    for (Slot& s : slots_)
      s.epoch = 0;
    epoch_ = 1;
  }
}

void SuperstepQueue::drop_done_chains() const
{
  while (!heap_.empty() && chains_[heap_.front()].head == nil)
  {
    chains_[heap_.front()].in_heap = false;
    std::pop_heap(heap_.begin(), heap_.end(), Later{ &chains_ });
    heap_.pop_back();
  }
}

bool SuperstepQueue::pop(const SuperstepKey& k, std::size_t& begin, std::size_t& end)
{
  drop_done_chains();
  if (heap_.empty())
    return false;
  const std::uint32_t c = heap_.front();
  Chain& chain = chains_[c];
  const Group& g = groups_[chain.head];
  if (g.key != k)
    return false;
  begin = g.begin;
  end = g.end;
  free_.push_back(chain.head);
  chain.head = g.next;
  last_ = c;
  return true;
}

void SuperstepQueue::clear()
{
  pool_.clear();
  groups_.clear();
  free_.clear();
  chains_.clear();
  heap_.clear();
  chain_of_.clear();
  open_.clear();
  side_.clear();
  open_of_.clear();
  last_ = nil;
  sealed_generation_ = 0;
}

} // namespace geoshaping
