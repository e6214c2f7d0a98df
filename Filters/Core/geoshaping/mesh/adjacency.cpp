#include "geoshaping/mesh/adjacency.h"

#include <algorithm>

namespace geoshaping
{

AdjacencyBuilder::AdjacencyBuilder(index_t num_points)
  : num_points_(num_points)
{
}

void AdjacencyBuilder::add_edge(index_t a, index_t b)
{
  if (a == b)
    return;
  edges_.emplace_back(std::min(a, b), std::max(a, b));
}

bool AdjacencyBuilder::add_cell(CellKind kind, const std::int64_t* ids, std::int64_t count)
{
  return cell_edges(
    kind, ids, count, num_points_, [this](index_t a, index_t b) { add_edge(a, b); });
}

Adjacency AdjacencyBuilder::build()
{
  const auto for_each_edge = [this](const auto& visit)
  {
    for (const auto& edge : edges_)
    {
      const index_t ids[2] = { edge.first, edge.second };
      visit(CellKind::line, ids, 2);
    }
  };
  Adjacency adj = adjacency_of_cells(num_points_, for_each_edge);
  edges_.clear();
  edges_.shrink_to_fit();
  return adj;
}

void merge_rows(Adjacency& rows)
{
  std::int64_t* const offsets = rows.offsets.data();
  index_t* const neighbors = rows.neighbors.data();
  std::int64_t kept = 0;
  for (std::size_t v = 0; v + 1 < rows.offsets.size(); ++v)
  {
    index_t* const first = neighbors + offsets[v];
    index_t* const last = neighbors + offsets[v + 1];
    std::sort(first, last);
    offsets[v] = kept;
    for (index_t* it = first; it != last; ++it)
      if (it == first || *it != it[-1])
        neighbors[kept++] = *it;
  }
  rows.offsets.back() = kept;
  std::vector<index_t> merged; // shrink_to_fit's copy, in fresh pages
  fresh_huge(merged, std::size_t(kept));
  merged.assign(neighbors, neighbors + kept);
  rows.neighbors.swap(merged);
}

} // namespace geoshaping
