#pragma once
// A triangulated grid recognised from its cells, so that its adjacency is written row by
// row from the rows and columns (O(points), nothing to sort or merge) instead of being
// gathered from the cells (adjacency_of_cells). The layout is dem_surface's without
// holes (a DEMSurface output, the surface of every elevation raster): point (r, c) has
// id r cols + c; each quad (r, c), in row-major order, gives the triangle
// (a, a + 1, a + cols + 1) with a = r cols + c, and after all of those each gives
// (a, a + cols + 1, a + cols). Any other cells take the general path.
#include "geoshaping/mesh/adjacency.h"

#include <cstdint>

namespace geoshaping
{

struct TriangleGrid
{
  index_t rows = 0, cols = 0;
};

// True, with `grid` set, when the `cells` cells of a cell array (`offsets`, cells + 1 of
// them, and `ids`, any integer types) over num_points points are exactly the triangles
// of a rows x cols grid laid out as above; false (grid untouched) for anything else. One
// sequential pass over the offsets and the ids.
template<class Offset, class Id>
bool triangle_grid_of(
  const Offset* offsets, const Id* ids, std::int64_t cells, index_t num_points, TriangleGrid* grid)
{
  if (cells < 2 || num_points < 4 || offsets[0] != 0 || offsets[1] != 3)
    return false;
  const std::int64_t cols = std::int64_t(ids[2]) - 1;
  if (cols < 2 || num_points % cols != 0)
    return false;
  const std::int64_t rows = num_points / cols;
  if (rows < 2 || cells != 2 * (rows - 1) * (cols - 1))
    return false;
  for (std::int64_t c = 0; c <= cells; ++c)
    if (std::int64_t(offsets[c]) != 3 * c)
      return false;
  const Id* t = ids;
  for (int second = 0; second < 2; ++second)
    for (std::int64_t r = 0; r + 1 < rows; ++r)
      for (std::int64_t a = r * cols, end = a + cols - 1; a < end; ++a, t += 3)
      {
        const std::int64_t corner[2][3] = { { a, a + 1, a + cols + 1 },
          { a, a + cols + 1, a + cols } };
        const std::int64_t* want = corner[second];
        if (std::int64_t(t[0]) != want[0] || std::int64_t(t[1]) != want[1] ||
            std::int64_t(t[2]) != want[2])
          return false;
      }
  grid->rows = index_t(rows);
  grid->cols = index_t(cols);
  return true;
}

// The adjacency adjacency_of_cells gives for the grid's triangles: each point's
// neighbours are (r-1, c-1), (r-1, c), (r, c-1), (r, c+1), (r+1, c), (r+1, c+1), those
// inside the grid, in that (ascending id) order.
Adjacency grid_adjacency(const TriangleGrid& grid);

} // namespace geoshaping
