#pragma once
// Vertex adjacency (vertices that share a cell edge) in compressed sparse row form.
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

} // namespace geoshaping
