#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/mesh/triangle_grid.h"
#include "geoshaping/scenes/dem_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace geoshaping;

namespace
{
// dem_surface's surface of a rows x cols grid in metres (a projected CRS), with the
// samples listed in `holes` left out (no data).
SampleMesh dem(index_t rows, index_t cols, std::vector<index_t> holes = {})
{
  ElevationGrid g;
  g.rows = rows;
  g.cols = cols;
  g.geographic = false;
  g.x_first = 500000.0;
  g.x_last = 500000.0 + 10.0 * (cols - 1);
  g.y_first = 4000000.0 + 10.0 * (rows - 1);
  g.y_last = 4000000.0;
  for (index_t k = 0; k < rows * cols; ++k)
    g.elevation.push_back(300.0 + 20.0 * std::sin(0.3 * k));
  for (index_t k : holes)
    g.elevation[std::size_t(k)] = std::nan("");
  return dem_surface(g, 1, [](std::size_t, double*, double*) { return true; });
}

std::vector<std::int64_t> triangle_offsets(const SampleMesh& mesh)
{
  std::vector<std::int64_t> offsets;
  for (std::size_t c = 0; c <= mesh.num_cells(); ++c)
    offsets.push_back(3 * std::int64_t(c));
  return offsets;
}

bool grid_of(const SampleMesh& mesh, TriangleGrid* grid)
{
  const std::vector<std::int64_t> offsets = triangle_offsets(mesh);
  return triangle_grid_of(offsets.data(), mesh.connectivity.data(), std::int64_t(mesh.num_cells()),
    mesh.num_points(), grid);
}
} // namespace

TEST(TriangleGrid, DemSurfaceIsRecognisedWithItsRowsAndColumns)
{
  for (const auto& [rows, cols] : { std::pair{ 2, 2 }, { 2, 7 }, { 9, 2 }, { 13, 17 } })
  {
    TriangleGrid grid;
    ASSERT_TRUE(grid_of(dem(rows, cols), &grid)) << rows << " x " << cols;
    EXPECT_EQ(grid.rows, rows);
    EXPECT_EQ(grid.cols, cols);
  }
}

TEST(TriangleGrid, AdjacencyIsTheOneGatheredFromTheCells)
{
  // adjacency_of_cells (SampleMesh::adjacency) is the reference: the same offsets and the
  // same rows, entry for entry, so the deformer's layout and order are unchanged.
  for (const auto& [rows, cols] : { std::pair{ 2, 2 }, { 2, 7 }, { 9, 2 }, { 13, 17 } })
  {
    const SampleMesh mesh = dem(rows, cols);
    TriangleGrid grid;
    ASSERT_TRUE(grid_of(mesh, &grid));
    const Adjacency fast = grid_adjacency(grid), reference = mesh.adjacency();
    EXPECT_EQ(fast.offsets, reference.offsets) << rows << " x " << cols;
    EXPECT_EQ(fast.neighbors, reference.neighbors) << rows << " x " << cols;
    EXPECT_EQ(fast.neighbors.capacity(), fast.neighbors.size());
  }
}

TEST(TriangleGrid, AnythingElseTakesTheGeneralPath)
{
  TriangleGrid grid;
  EXPECT_FALSE(grid_of(dem(6, 5, { 12 }), &grid)); // a hole: some triangles left out
  SampleMesh flipped = dem(6, 5);
  std::swap(flipped.connectivity[30], flipped.connectivity[31]); // one triangle reordered
  EXPECT_FALSE(grid_of(flipped, &grid));
  SampleMesh other = dem(6, 5);
  other.connectivity.back() = 0; // the last corner elsewhere
  EXPECT_FALSE(grid_of(other, &grid));
  const SampleMesh mesh = dem(6, 5);
  std::vector<std::int64_t> offsets = triangle_offsets(mesh);
  offsets[3] = 8, offsets[4] = 13; // a quad and a pentagon in the middle
  EXPECT_FALSE(triangle_grid_of(offsets.data(), mesh.connectivity.data(),
    std::int64_t(mesh.num_cells()), mesh.num_points(), &grid));
  EXPECT_FALSE(triangle_grid_of(triangle_offsets(mesh).data(), mesh.connectivity.data(),
    std::int64_t(mesh.num_cells()), mesh.num_points() + 5, &grid)); // points beside the grid
  EXPECT_EQ(grid.rows, 0);                                          // untouched
}

TEST(TriangleGrid, DeformerHoldsAFixedNumberOfBytesPerVertex)
{
  // The set-up's memory, from the capacities of what the deformer keeps (not from timing
  // or the process's RSS): per vertex the 32-byte node, the slot, both renumberings, the
  // row offset, the global id and the rows (6 neighbours inside a grid, fewer on its
  // border), nothing more, so a big DEM's peak per vertex cannot grow unnoticed.
  const index_t rows = 60, cols = 70, n = rows * cols;
  const SampleMesh mesh = dem(rows, cols);
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), n, grid_adjacency({ rows, cols }));
  std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
    gid[std::size_t(v)] = n - 1 - v;
  d.set_global_ids(gid.data());
  const std::size_t entries = mesh.adjacency().neighbors.size();
  const std::size_t per_vertex = 32 + 4 + 4 + 4 + 4 + 8,
                    held = per_vertex * std::size_t(n) + 4 * entries;
  EXPECT_GE(d.memory_bytes(), held);
  EXPECT_LE(d.memory_bytes(), held + 256); // the last row offset, one malleability value
  EXPECT_LE(double(d.memory_bytes()) / n, 80.0);
}
