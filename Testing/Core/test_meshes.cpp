#include "test_meshes.h"

namespace geoshaping::testing
{

Mesh chain(index_t n, double spacing)
{
  Mesh m;
  AdjacencyBuilder b(n);
  for (index_t i = 0; i < n; ++i)
  {
    m.xyz.insert(m.xyz.end(), { i * spacing, 0.0, 0.0 });
    if (i + 1 < n)
    {
      const std::int64_t line[2] = { i, i + 1 };
      b.add_cell(CellKind::line, line, 2);
    }
  }
  m.adjacency = b.build();
  return m;
}

namespace
{
Mesh grid(index_t nx, index_t ny, double h, bool triangles)
{
  Mesh m;
  AdjacencyBuilder b(nx * ny);
  for (index_t j = 0; j < ny; ++j)
    for (index_t i = 0; i < nx; ++i)
      m.xyz.insert(m.xyz.end(), { i * h, j * h, 0.0 });
  for (index_t j = 0; j + 1 < ny; ++j)
    for (index_t i = 0; i + 1 < nx; ++i)
    {
      const std::int64_t a = grid_id(nx, i, j), c = grid_id(nx, i + 1, j),
                         d = grid_id(nx, i + 1, j + 1), e = grid_id(nx, i, j + 1);
      if (triangles)
      {
        const std::int64_t t0[3] = { a, c, d }, t1[3] = { a, d, e };
        b.add_cell(CellKind::triangle, t0, 3);
        b.add_cell(CellKind::triangle, t1, 3);
      }
      else
      {
        const std::int64_t q[4] = { a, c, d, e };
        b.add_cell(CellKind::polygon, q, 4);
      }
    }
  m.adjacency = b.build();
  return m;
}
} // namespace

IslandScene rigid_island()
{
  const index_t n = 31;
  IslandScene s{ triangle_grid(n, n, 1.0), {}, grid_id(n, 15, 12), { 4.0, 3.0, 12.0 } };
  s.malleability.assign(std::size_t(s.mesh.size()), 1.0f);
  for (index_t j = 18; j < 25; ++j)
    for (index_t i = 12; i < 19; ++i)
      s.malleability[grid_id(n, i, j)] = 0.0f;
  return s;
}

Mesh quad_grid(index_t nx, index_t ny, double h)
{
  return grid(nx, ny, h, false);
}
Mesh triangle_grid(index_t nx, index_t ny, double h)
{
  return grid(nx, ny, h, true);
}

} // namespace geoshaping::testing
