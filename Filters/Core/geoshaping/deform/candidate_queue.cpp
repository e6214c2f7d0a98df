#include "geoshaping/deform/candidate_queue.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

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

namespace
{
// The full key of an entry, ties (duplicate ids on a piece) by vertex and sponsor.
inline bool before(const SuperstepEntry& a, const SuperstepEntry& b)
{
  return std::tie(a.band, a.root.generation, a.root.gid, a.candidate_gid, a.sponsor_gid, a.vertex,
           a.sponsor) < std::tie(b.band, b.root.generation, b.root.gid, b.candidate_gid,
                          b.sponsor_gid, b.vertex, b.sponsor);
}

// Sizes a scratch buffer to at least n (its tail beyond n is left as it is).
template<class T>
void grow(std::vector<T>& v, std::size_t n)
{
  if (v.size() < n)
    v.resize(n);
}

int bit_width(std::uint64_t x)
{
  int n = 0;
  for (; x; x >>= 1)
    ++n;
  return n;
}
} // namespace

bool SuperstepQueue::sort_cheaply()
{
  const std::size_t k = pending_.size();
  if (k > std::numeric_limits<std::uint32_t>::max())
    return false;
  std::uint32_t min_order = pending_[0].order, max_order = min_order;
  std::int64_t min_id = pending_[0].candidate_gid, max_id = min_id;
  for (const SuperstepEntry& e : pending_)
  {
    min_order = std::min(min_order, e.order);
    max_order = std::max(max_order, e.order);
    min_id = std::min(min_id, e.candidate_gid);
    max_id = std::max(max_id, e.candidate_gid);
  }
  const int id_bits = bit_width(std::uint64_t(max_id) - std::uint64_t(min_id));
  const int bits = id_bits + bit_width(max_order - min_order);
  if (bits > 64)
    return false;
  grow(words_, k);
  for (std::size_t i = 0; i < k; ++i)
  {
    const SuperstepEntry& e = pending_[i];
    const std::uint64_t order = e.order - min_order;
    words_[i] = { (id_bits < 64 ? order << id_bits : 0) |
                    (std::uint64_t(e.candidate_gid) - std::uint64_t(min_id)),
      std::uint32_t(i) };
  }
  // Insertion sort while it makes few moves (a generation comes nearly sorted: the
  // neighbours of vertices taken in id order); past the budget a radix sort of all.
  std::size_t moves = 0, i = 1;
  for (const std::size_t budget = 4 * k; i < k && moves <= budget; ++i)
    for (std::size_t j = i; j > 0 && words_[j].key < words_[j - 1].key; --j, ++moves)
      std::swap(words_[j], words_[j - 1]);
  if (i < k)
  {
    // LSD radix sort: ceil(bits / 11) stable counting passes of equal width (at most
    // 2^11 counters), a pass skipped when its digit is the same in all words.
    const int passes = (bits + 10) / 11;
    const int width = passes ? (bits + passes - 1) / passes : 0;
    const std::uint64_t mask = (std::uint64_t(1) << width) - 1;
    grow(scratch_, k);
    count_.resize(std::size_t(1) << width);
    for (int shift = 0; shift < bits; shift += width)
    {
      std::fill(count_.begin(), count_.end(), 0);
      for (std::size_t w = 0; w < k; ++w)
        ++count_[(words_[w].key >> shift) & mask];
      if (count_[(words_[0].key >> shift) & mask] == k)
        continue;
      std::uint32_t sum = 0;
      for (std::uint32_t& c : count_)
        sum += std::exchange(c, sum);
      for (std::size_t w = 0; w < k; ++w)
        scratch_[count_[(words_[w].key >> shift) & mask]++] = words_[w];
      words_.swap(scratch_);
    }
  }
  // Runs of one word (one candidate) by sponsor id, then the check on the full key.
  for (std::size_t i = 1; i < k; ++i)
    for (std::size_t j = i;
         j > 0 && words_[j].key == words_[j - 1].key &&
         pending_[words_[j].index].sponsor_gid < pending_[words_[j - 1].index].sponsor_gid;
         --j)
      std::swap(words_[j], words_[j - 1]);
  for (std::size_t i = 1; i < k; ++i)
    if (before(pending_[words_[i].index], pending_[words_[i - 1].index]))
      return false;
  return true;
}

void SuperstepQueue::sort_fully()
{
  const std::size_t k = pending_.size();
  grow(words_, k);
  for (std::size_t i = 0; i < k; ++i)
    words_[i] = { 0, std::uint32_t(i) };
  auto less = [&](const Word& a, const Word& b)
  { return before(pending_[a.index], pending_[b.index]); };
  if (k <= small)
    for (std::size_t i = 1; i < k; ++i)
      for (std::size_t j = i; j > 0 && less(words_[j], words_[j - 1]); --j)
        std::swap(words_[j], words_[j - 1]);
  else
    std::sort(words_.begin(), words_.begin() + std::ptrdiff_t(k), less);
}

void SuperstepQueue::seal(std::uint32_t generation)
{
  if (pending_.empty())
    return;
  if (generation <= sealed_generation_)
    throw std::invalid_argument("SuperstepQueue: generations must be sealed in increasing order");
  sealed_generation_ = generation;
  if (pending_.size() <= small || !sort_cheaply())
    sort_fully();
  const std::size_t k = pending_.size();
  if (pool_.size() + k > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("SuperstepQueue: more than 2^32 entries in a frame");
  std::size_t begin = pool_.size();
  for (std::size_t i = 0; i < k;)
  {
    const SuperstepEntry& first = pending_[words_[i].index];
    std::size_t j = i;
    for (; j < k; ++j)
    {
      const SuperstepEntry& e = pending_[words_[j].index];
      if (e.band != first.band || !(e.root == first.root))
        break;
      pool_.push_back({ e.vertex, e.sponsor });
    }
    file({ key(first.band, first.root, generation), std::uint32_t(begin),
      std::uint32_t(pool_.size()) });
    begin = pool_.size();
    i = j;
  }
  pending_.clear();
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
      open_of_.emplace(open_[g], std::uint32_t(g));
    const auto found = open_of_.find(k);
    if (found != open_of_.end())
      return found->second;
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
      file({ { open_[g].band_generation, open_[g].gid, generation }, std::uint32_t(b),
        std::uint32_t(e) });
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
  if (!open_of_.empty())
    open_of_.clear();
}

void SuperstepQueue::file(const Group& g)
{
  const ChainKey ck{ g.key[0], g.key[1] };
  std::uint32_t c = last_;
  if (c == nil || !(chains_[c].key == ck))
  {
    const auto found = chain_of_.find(ck);
    if (found != chain_of_.end())
      c = found->second;
    else
    {
      c = std::uint32_t(chains_.size());
      chains_.push_back({ ck, nil, nil, false });
      chain_of_.emplace(ck, c);
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
  if (g.key[0] != k[0] || g.key[1] != k[1] || g.key[2] != k[2])
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
  pending_.clear();
  groups_.clear();
  free_.clear();
  chains_.clear();
  heap_.clear();
  chain_of_.clear();
  open_.clear();
  side_.clear();
  if (!open_of_.empty())
    open_of_.clear();
  last_ = nil;
  sealed_generation_ = 0;
}

} // namespace geoshaping
