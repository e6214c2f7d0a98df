#include "geoshaping/parallel/partitioned_labels.h"

#include <algorithm>

namespace geoshaping
{

void SparseLabels::begin(std::size_t n)
{
  if (stamp.size() != n)
  {
    value.assign(n, 0.0);
    stamp.assign(n, 0);
    pass = 0;
  }
  ++pass;
  touched.clear();
}

void SparseLabels::set(index_t v, double y)
{
  if (stamp[std::size_t(v)] != pass)
  {
    stamp[std::size_t(v)] = pass;
    touched.push_back(v);
  }
  value[std::size_t(v)] = y;
}

void PartitionedLabels::set_piece(
  index_t n, const std::int64_t* gid, const std::uint8_t* owned, Exchange& exchange)
{
  const int pieces = exchange.pieces(), me = exchange.piece();
  n_ = n;
  const std::size_t size = std::size_t(n);
  gid_.assign(gid, gid + size);
  owned_.resize(size);
  local_of_.clear();
  local_of_.reserve(size);
  for (index_t v = 0; v < n; ++v)
  {
    owned_[std::size_t(v)] = owned[v] != 0;
    // As PartitionedChainMail: the owned copy, else the first, stands for the vertex.
    const auto [it, fresh] = local_of_.emplace(gid_[std::size_t(v)], v);
    if (!fresh && owned_[std::size_t(v)] && !owned_[std::size_t(it->second)])
      it->second = v;
  }
  aliases_.clear();
  std::vector<std::int64_t> ghosts;
  for (index_t v = 0; v < n; ++v)
  {
    const index_t rep = local(gid_[std::size_t(v)]);
    if (rep != v)
    {
      aliases_.emplace_back(v, rep);
      owned_[std::size_t(v)] = 0;
    }
    else if (!owned_[std::size_t(v)])
      ghosts.push_back(gid_[std::size_t(v)]);
  }

  // Who holds my owned vertices as ghosts (every piece's ghost ids), and who owns my
  // ghosts (each owner tells the holders).
  const auto all_ghosts = exchange.all_gather(ghosts);
  std::vector<std::vector<int>> holders(size);
  std::vector<std::vector<std::int64_t>> tell(static_cast<std::size_t>(pieces));
  for (int q = 0; q < pieces; ++q)
    if (q != me)
      for (std::int64_t g : all_ghosts[std::size_t(q)])
      {
        const index_t v = local(g);
        if (v >= 0 && owned_[std::size_t(v)])
        {
          holders[std::size_t(v)].push_back(q);
          tell[std::size_t(q)].push_back(g);
        }
      }
  const auto told = exchange.all_to_all(tell);
  for (int q = 0; q < pieces; ++q)
    if (q != me)
      for (std::int64_t g : told[std::size_t(q)])
      {
        const index_t v = local(g);
        if (v >= 0 && !owned_[std::size_t(v)])
          holders[std::size_t(v)].push_back(q);
      }
  neighbours_.clear();
  for (const auto& h : holders)
    neighbours_.insert(neighbours_.end(), h.begin(), h.end());
  std::sort(neighbours_.begin(), neighbours_.end());
  neighbours_.erase(std::unique(neighbours_.begin(), neighbours_.end()), neighbours_.end());
  holder_offsets_.assign(size + 1, 0);
  holders_.clear();
  for (std::size_t v = 0; v < size; ++v)
  {
    for (int q : holders[v])
      holders_.push_back(std::uint32_t(
        std::lower_bound(neighbours_.begin(), neighbours_.end(), q) - neighbours_.begin()));
    holder_offsets_[v + 1] = std::uint32_t(holders_.size());
  }
  dirty_stamp_.assign(size, 0);
  dirty_pass_ = 0;
  out_.assign(neighbours_.size(), {});
}

} // namespace geoshaping
