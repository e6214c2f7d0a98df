#include "geoshaping/mesh/adjacency.h"

#include <algorithm>
#include <array>

namespace geoshaping
{
namespace
{
using Edge = std::array<int, 2>;

// Local edge tables, in VTK's point ordering for each 3D cell.
constexpr Edge tetra_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
constexpr Edge hexa_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 },
  { 6, 7 }, { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
constexpr Edge voxel_edges[] = { { 0, 1 }, { 1, 3 }, { 3, 2 }, { 2, 0 }, { 4, 5 }, { 5, 7 },
  { 7, 6 }, { 6, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
constexpr Edge wedge_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 4 }, { 4, 5 }, { 5, 3 },
  { 0, 3 }, { 1, 4 }, { 2, 5 } };
constexpr Edge pyramid_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 4 }, { 1, 4 },
  { 2, 4 }, { 3, 4 } };

template<std::size_t N>
bool add_table(AdjacencyBuilder& b, const Edge (&table)[N], const std::int64_t* ids,
  std::int64_t count, std::int64_t expected)
{
  if (count != expected)
    return false;
  for (const Edge& e : table)
    b.add_edge(index_t(ids[e[0]]), index_t(ids[e[1]]));
  return true;
}
} // namespace

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
  for (std::int64_t i = 0; i < count; ++i)
    if (ids[i] < 0 || ids[i] >= num_points_)
      return false;
  switch (kind)
  {
    case CellKind::vertex:
    case CellKind::poly_vertex:
      return true;
    case CellKind::line:
    case CellKind::poly_line:
      for (std::int64_t i = 0; i + 1 < count; ++i)
        add_edge(index_t(ids[i]), index_t(ids[i + 1]));
      return true;
    case CellKind::triangle_strip:
      for (std::int64_t i = 0; i + 1 < count; ++i)
        add_edge(index_t(ids[i]), index_t(ids[i + 1]));
      for (std::int64_t i = 0; i + 2 < count; ++i)
        add_edge(index_t(ids[i]), index_t(ids[i + 2]));
      return true;
    case CellKind::triangle:
    case CellKind::polygon:
      for (std::int64_t i = 0; i < count; ++i)
        add_edge(index_t(ids[i]), index_t(ids[(i + 1) % count]));
      return true;
    case CellKind::pixel:
    {
      if (count != 4)
        return false;
      const std::int64_t loop[4] = { ids[0], ids[1], ids[3], ids[2] };
      return add_cell(CellKind::polygon, loop, 4);
    }
    case CellKind::tetra:
      return add_table(*this, tetra_edges, ids, count, 4);
    case CellKind::voxel:
      return add_table(*this, voxel_edges, ids, count, 8);
    case CellKind::hexahedron:
      return add_table(*this, hexa_edges, ids, count, 8);
    case CellKind::wedge:
      return add_table(*this, wedge_edges, ids, count, 6);
    case CellKind::pyramid:
      return add_table(*this, pyramid_edges, ids, count, 5);
    case CellKind::unsupported:
      break;
  }
  return false;
}

Adjacency AdjacencyBuilder::build()
{
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());

  Adjacency adj;
  adj.offsets.assign(std::size_t(num_points_) + 1, 0);
  for (const auto& [a, b] : edges_)
  {
    ++adj.offsets[a + 1];
    ++adj.offsets[b + 1];
  }
  for (index_t v = 0; v < num_points_; ++v)
    adj.offsets[v + 1] += adj.offsets[v];
  adj.neighbors.resize(std::size_t(adj.offsets.back()));
  std::vector<std::int64_t> fill(adj.offsets.begin(), adj.offsets.end() - 1);
  // Edges are sorted by (a, b): every row receives its entries in ascending order.
  for (const auto& [a, b] : edges_)
    adj.neighbors[fill[a]++] = b;
  for (const auto& [a, b] : edges_)
    adj.neighbors[fill[b]++] = a;
  for (index_t v = 0; v < num_points_; ++v)
    std::sort(adj.neighbors.begin() + adj.offsets[v], adj.neighbors.begin() + adj.offsets[v + 1]);
  edges_.clear();
  edges_.shrink_to_fit();
  return adj;
}

} // namespace geoshaping
