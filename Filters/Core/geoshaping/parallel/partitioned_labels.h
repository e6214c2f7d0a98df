#pragma once
// Label correction (min-plus shortest paths) on a mesh split into pieces, with the same
// labels as on the whole mesh, bit for bit, whatever the partition: the machinery of the
// partitioned envelope (partitioned_envelope.h) and the partitioned geodesic brush
// (partitioned_geodesic.h).
//
// Pieces as in partitioned_chainmail.h: owned vertices plus one ghost ring, global ids,
// exactly one owner per vertex; copies of one global id on a piece: the owned one, else
// the first, stands for the vertex (the others follow it).
//
// A run computes the greatest fixed point below the start of the monotone map
//   y_a -> min(y_a, min_b fl(y_b + w_ba))   (w >= 0, kept only where allowed(a, y))
// where `allowed` is monotone (a lower label is allowed when a higher one is, e.g.
// y < limit). Any fair order of updates from the same start reaches the same fixed
// point: every label ever set is >= it (induction, fl is monotone) and at quiescence
// every constraint holds (each lowered label is relaxed); w >= 0 makes fl(y + w) >= y,
// so no cycle lowers a label for ever. Hence the pieces get the whole mesh's labels as
// long as every constraint b -> a of the whole mesh is relaxed somewhere (a's owner
// holds a's ring) and every lowered label reaches the other copies.
//
// One superstep: each piece relaxes its labels to local quiescence (Dijkstra's order),
// sends each label it lowered to the other holders (a ghost's to its owner, an owned
// vertex's to its ghost holders; a MovedVertex record, 48 bytes, the label in
// displacement[0]), keeps the lower of what it receives (an owner forwards a label it
// received next superstep) and stops when no piece has anything pending (all_gather of
// one flag). At quiescence every copy holds its owner's label: an owner forwards every
// label it sets, and a ghost forwards every label it sets itself.
// Cost: O(t log t) per piece for the t labels it sets, plus per superstep one message
// to and from each neighbour piece (the lowered border labels) and one all_gather.
#include "geoshaping/parallel/exchange.h"

#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace geoshaping
{

// Labels of one run, set sparsely: a stamp per run, the vertices set.
struct SparseLabels
{
  std::vector<double> value;
  std::vector<std::uint32_t> stamp;
  std::uint32_t pass = 0;
  std::vector<index_t> touched;
  void begin(std::size_t n);
  bool has(index_t v) const { return stamp[std::size_t(v)] == pass; }
  void set(index_t v, double y);
};

class PartitionedLabels
{
public:
  // Collective, once per partition: global ids and ownership of the piece's n vertices.
  // Finds the other holders of each vertex (gathers every piece's ghost ids).
  void set_piece(index_t n, const std::int64_t* gid, const std::uint8_t* owned, Exchange& exchange);

  index_t size() const { return n_; }
  std::int64_t gid(index_t v) const { return gid_[std::size_t(v)]; }
  bool owned(index_t v) const { return owned_[std::size_t(v)] != 0; }
  // The copy that stands for global id g on this piece, or -1.
  index_t local(std::int64_t g) const
  {
    const auto it = local_of_.find(g);
    return it == local_of_.end() ? -1 : it->second;
  }
  bool stands_for_itself(index_t v) const { return local(gid(v)) == v; }
  // (other copy, the copy that stands for it) for every doubled global id.
  const std::vector<std::pair<index_t, index_t>>& aliases() const { return aliases_; }

  // Collective: a run to quiescence over all pieces. `label(v)` reads the current label
  // (the start until `labels` sets one); `relax(b, y, lower)` calls lower(a, cap) for
  // each neighbour a of b whose label may fall to cap = fl(y + w_ba); a cap is taken when
  // cap < label(a) and allowed(a, cap). `seeds` are relaxed first; `dirty` are owned
  // vertices set before the run (sent to their ghosts in the first superstep). Returns
  // the supersteps.
  template<class Label, class Relax, class Allowed>
  std::size_t correct(SparseLabels& labels, const Label& label, const Relax& relax,
    const Allowed& allowed, const std::vector<index_t>& seeds, std::vector<index_t> dirty,
    Exchange& exchange);

private:
  index_t n_ = 0;
  std::vector<std::int64_t> gid_;
  std::vector<std::uint8_t> owned_;
  std::unordered_map<std::int64_t, index_t> local_of_;
  std::vector<std::pair<index_t, index_t>> aliases_;
  std::vector<int> neighbours_; // pieces to exchange with
  // By local vertex: indices into neighbours_ of the other holders (CSR).
  std::vector<std::uint32_t> holder_offsets_, holders_;
  std::vector<std::uint32_t> dirty_stamp_;
  std::uint32_t dirty_pass_ = 0;
  std::vector<std::vector<MovedVertex>> out_;
};

template<class Label, class Relax, class Allowed>
std::size_t PartitionedLabels::correct(SparseLabels& labels, const Label& label, const Relax& relax,
  const Allowed& allowed, const std::vector<index_t>& seeds, std::vector<index_t> dirty,
  Exchange& exchange)
{
  using Item = std::pair<double, index_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (index_t s : seeds)
    heap.emplace(label(s), s);
  ++dirty_pass_;
  for (index_t v : dirty)
    dirty_stamp_[std::size_t(v)] = dirty_pass_;
  const auto mark = [&](index_t v)
  {
    if (dirty_stamp_[std::size_t(v)] != dirty_pass_)
    {
      dirty_stamp_[std::size_t(v)] = dirty_pass_;
      dirty.push_back(v);
    }
  };
  const auto lower = [&](index_t a, double cap)
  {
    if (cap < label(a) && allowed(a, cap))
    {
      labels.set(a, cap);
      heap.emplace(cap, a);
      mark(a);
    }
  };
  std::size_t supersteps = 0;
  while (true)
  {
    while (!heap.empty())
    {
      const auto [y, b] = heap.top();
      heap.pop();
      if (y != label(b))
        continue; // lowered again since it was pushed
      relax(b, y, lower);
    }
    for (auto& o : out_)
      o.clear();
    for (index_t v : dirty)
      for (std::uint32_t i = holder_offsets_[std::size_t(v)];
           i < holder_offsets_[std::size_t(v) + 1]; ++i)
        out_[holders_[i]].push_back({ gid_[std::size_t(v)], { label(v), 0.0, 0.0 }, {} });
    dirty.clear();
    ++dirty_pass_;
    const auto in = exchange.exchange(neighbours_, out_, neighbours_);
    ++supersteps;
    for (const auto& box : in)
      for (const MovedVertex& m : box)
      {
        const index_t v = local(m.gid);
        const double y = m.displacement[0];
        if (v >= 0 && y < label(v))
        {
          labels.set(v, y);
          heap.emplace(y, v);
          if (owned(v))
            mark(v);
        }
      }
    bool pending = false;
    for (const auto& p : exchange.all_gather({ heap.empty() && dirty.empty() ? 0 : 1 }))
      pending = pending || p[0] != 0;
    if (!pending)
      return supersteps;
  }
}

} // namespace geoshaping
