#pragma once
// Vertex adjacency (vertices that share a cell edge) in compressed sparse row form.
#include "geoshaping/mesh/huge_pages.h"

#include <array>
#include <cstdint>
#include <vector>

namespace geoshaping
{

using index_t = std::int32_t;

// Cell kinds whose edges define the neighbourhood. The VTK adapter maps VTK cell
// types onto these; the core stays free of VTK.
enum class CellKind
{
  vertex,
  poly_vertex,
  line,
  poly_line,
  triangle,
  triangle_strip,
  polygon, // any closed loop: quads, pixels (see below), general polygons
  pixel,   // VTK_PIXEL ordering (0,1,3,2)
  tetra,
  voxel, // VTK_VOXEL ordering
  hexahedron,
  wedge,
  pyramid,
  unsupported
};

struct Adjacency
{
  std::vector<std::int64_t> offsets; // size n + 1
  std::vector<index_t> neighbors;    // sorted, unique per row, no self loops

  index_t size() const { return offsets.empty() ? 0 : index_t(offsets.size() - 1); }
  const index_t* begin(index_t v) const { return neighbors.data() + offsets[v]; }
  const index_t* end(index_t v) const { return neighbors.data() + offsets[v + 1]; }
  std::int64_t degree(index_t v) const { return offsets[v + 1] - offsets[v]; }
};

// Calls edge(a, b) for each edge of one cell (a == b for a degenerate one). Returns false,
// calling nothing, for an unsupported kind, a count the kind cannot have or an id outside
// [0, num_points). Id: any integer type (VTK's cell arrays hold 32- or 64-bit ids).
template<class Id, class Edge>
bool cell_edges(
  CellKind kind, const Id* ids, std::int64_t count, index_t num_points, const Edge& edge);

// Accumulates undirected edges cell by cell, then compresses them into CSR.
class AdjacencyBuilder
{
public:
  explicit AdjacencyBuilder(index_t num_points);

  // Appends the edges of one cell. Returns false for an unsupported kind or an id
  // outside [0, num_points) (the cell is then skipped entirely).
  bool add_cell(CellKind kind, const std::int64_t* ids, std::int64_t count);
  void add_edge(index_t a, index_t b);

  // Duplicate edges and self loops (zero-length or degenerate cells) are merged.
  Adjacency build();

private:
  index_t num_points_;
  std::vector<std::pair<index_t, index_t>> edges_;
};

// The adjacency AdjacencyBuilder gives for the same cells, without keeping their edges:
// for_each_cell(visit) must call visit(kind, ids, count) for every cell, the same cells
// each time, and is called twice (the degrees, then the rows). `skipped` counts the cells
// refused (as add_cell refuses them). O(cells + entries); its one temporary is the rows
// before repeated edges are merged (twice the entries of a closed triangle mesh).
template<class ForEachCell>
Adjacency adjacency_of_cells(
  index_t num_points, const ForEachCell& for_each_cell, std::int64_t* skipped = nullptr);

// Sorts each row of `rows` (CSR whose rows may repeat entries) and drops the repeats, in
// place: the last step of adjacency_of_cells.
void merge_rows(Adjacency& rows);

namespace adjacency_detail
{
using Edge = std::array<int, 2>;

// Local edge tables, in VTK's point ordering for each cell.
constexpr Edge pixel_edges[] = { { 0, 1 }, { 1, 3 }, { 3, 2 }, { 2, 0 } };
constexpr Edge tetra_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
constexpr Edge hexa_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 },
  { 6, 7 }, { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
constexpr Edge voxel_edges[] = { { 0, 1 }, { 1, 3 }, { 3, 2 }, { 2, 0 }, { 4, 5 }, { 5, 7 },
  { 7, 6 }, { 6, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
constexpr Edge wedge_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 4 }, { 4, 5 }, { 5, 3 },
  { 0, 3 }, { 1, 4 }, { 2, 5 } };
constexpr Edge pyramid_edges[] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 4 }, { 1, 4 },
  { 2, 4 }, { 3, 4 } };

template<class Id, class EdgeFn, std::size_t N>
bool table_edges(const Edge (&table)[N], const Id* ids, std::int64_t count, std::int64_t expected,
  const EdgeFn& edge)
{
  if (count != expected)
    return false;
  for (const Edge& e : table)
    edge(index_t(ids[e[0]]), index_t(ids[e[1]]));
  return true;
}
} // namespace adjacency_detail

template<class Id, class Edge>
bool cell_edges(
  CellKind kind, const Id* ids, std::int64_t count, index_t num_points, const Edge& edge)
{
  using namespace adjacency_detail;
  for (std::int64_t i = 0; i < count; ++i)
    if (ids[i] < 0 || ids[i] >= num_points)
      return false;
  switch (kind)
  {
    case CellKind::vertex:
    case CellKind::poly_vertex:
      return true;
    case CellKind::line:
    case CellKind::poly_line:
      for (std::int64_t i = 0; i + 1 < count; ++i)
        edge(index_t(ids[i]), index_t(ids[i + 1]));
      return true;
    case CellKind::triangle_strip:
      for (std::int64_t i = 0; i + 1 < count; ++i)
        edge(index_t(ids[i]), index_t(ids[i + 1]));
      for (std::int64_t i = 0; i + 2 < count; ++i)
        edge(index_t(ids[i]), index_t(ids[i + 2]));
      return true;
    case CellKind::triangle:
    case CellKind::polygon:
      for (std::int64_t i = 0; i < count; ++i)
        edge(index_t(ids[i]), index_t(ids[i + 1 < count ? i + 1 : 0]));
      return true;
    case CellKind::pixel:
      return table_edges(pixel_edges, ids, count, 4, edge);
    case CellKind::tetra:
      return table_edges(tetra_edges, ids, count, 4, edge);
    case CellKind::voxel:
      return table_edges(voxel_edges, ids, count, 8, edge);
    case CellKind::hexahedron:
      return table_edges(hexa_edges, ids, count, 8, edge);
    case CellKind::wedge:
      return table_edges(wedge_edges, ids, count, 6, edge);
    case CellKind::pyramid:
      return table_edges(pyramid_edges, ids, count, 5, edge);
    case CellKind::unsupported:
      break;
  }
  return false;
}

template<class ForEachCell>
Adjacency adjacency_of_cells(
  index_t num_points, const ForEachCell& for_each_cell, std::int64_t* skipped)
{
  Adjacency rows;
  fresh_huge(rows.offsets, std::size_t(num_points > 0 ? num_points : 0) + 1);
  rows.offsets.assign(std::size_t(num_points > 0 ? num_points : 0) + 1, 0);
  std::int64_t* const offsets = rows.offsets.data();
  std::int64_t refused = 0;
  // Degrees at offsets[v + 1], then row starts there; filling moves each to its row's end.
  for_each_cell(
    [&](CellKind kind, const auto* ids, std::int64_t count)
    {
      const auto degree = [offsets](index_t a, index_t b)
      {
        offsets[a + 1] += a != b;
        offsets[b + 1] += a != b;
      };
      refused += !cell_edges(kind, ids, count, num_points, degree);
    });
  std::int64_t start = 0;
  for (std::size_t v = 1; v < rows.offsets.size(); ++v)
  {
    const std::int64_t degree = offsets[v];
    offsets[v] = start;
    start += degree;
  }
  fresh_huge(rows.neighbors, std::size_t(start));
  rows.neighbors.resize(std::size_t(start));
  index_t* const neighbors = rows.neighbors.data();
  for_each_cell(
    [&](CellKind kind, const auto* ids, std::int64_t count)
    {
      const auto fill = [offsets, neighbors](index_t a, index_t b)
      {
        if (a == b)
          return;
        neighbors[offsets[a + 1]++] = b;
        neighbors[offsets[b + 1]++] = a;
      };
      cell_edges(kind, ids, count, num_points, fill);
    });
  if (skipped)
    *skipped = refused;
  merge_rows(rows);
  return rows;
}

} // namespace geoshaping
