#include "geoshaping/mesh/triangle_grid.h"

#include "geoshaping/mesh/huge_pages.h"

namespace geoshaping
{

Adjacency grid_adjacency(const TriangleGrid& grid)
{
  const std::int64_t rows = grid.rows, cols = grid.cols, n = rows * cols;
  // Each edge twice: rows (cols - 1) horizontal, (rows - 1) cols vertical, (rows - 1)
  // (cols - 1) diagonal.
  const std::int64_t entries =
    2 * (rows * (cols - 1) + (rows - 1) * cols + (rows - 1) * (cols - 1));
  Adjacency a;
  fresh_huge(a.offsets, std::size_t(n + 1));
  a.offsets.resize(std::size_t(n + 1));
  fresh_huge(a.neighbors, std::size_t(entries));
  a.neighbors.resize(std::size_t(entries));
  std::int64_t* offset = a.offsets.data();
  index_t* out = a.neighbors.data();
  std::int64_t k = 0;
  for (std::int64_t r = 0; r < rows; ++r)
    for (std::int64_t c = 0; c < cols; ++c)
    {
      *offset++ = k;
      const std::int64_t v = r * cols + c;
      const bool up = r > 0, down = r + 1 < rows, left = c > 0, right = c + 1 < cols;
      if (up && left)
        out[k++] = index_t(v - cols - 1);
      if (up)
        out[k++] = index_t(v - cols);
      if (left)
        out[k++] = index_t(v - 1);
      if (right)
        out[k++] = index_t(v + 1);
      if (down)
        out[k++] = index_t(v + cols);
      if (down && right)
        out[k++] = index_t(v + cols + 1);
    }
  *offset = k;
  return a;
}

} // namespace geoshaping
