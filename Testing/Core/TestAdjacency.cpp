#include "geoshaping/mesh/adjacency.h"

#include <gtest/gtest.h>

#include <random>

using namespace geoshaping;

namespace
{
std::vector<index_t> row(const Adjacency& a, index_t v)
{
  return { a.begin(v), a.end(v) };
}
} // namespace

TEST(Adjacency, TriangleEdgesAreMergedAcrossCells)
{
  AdjacencyBuilder b(4);
  const std::int64_t t0[3] = { 0, 1, 2 }, t1[3] = { 2, 1, 3 };
  EXPECT_TRUE(b.add_cell(CellKind::triangle, t0, 3));
  EXPECT_TRUE(b.add_cell(CellKind::triangle, t1, 3));
  const Adjacency a = b.build();
  EXPECT_EQ(a.neighbors.size(), 10u); // 5 undirected edges
  EXPECT_EQ(row(a, 1), (std::vector<index_t>{ 0, 2, 3 }));
  EXPECT_EQ(row(a, 3), (std::vector<index_t>{ 1, 2 }));
}

TEST(Adjacency, TetrahedronConnectsAllFourVertices)
{
  AdjacencyBuilder b(4);
  const std::int64_t t[4] = { 0, 1, 2, 3 };
  EXPECT_TRUE(b.add_cell(CellKind::tetra, t, 4));
  const Adjacency a = b.build();
  for (index_t v = 0; v < 4; ++v)
    EXPECT_EQ(a.degree(v), 3);
}

TEST(Adjacency, HexahedronHasTwelveEdgesAndNoDiagonals)
{
  AdjacencyBuilder b(8);
  const std::int64_t h[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  EXPECT_TRUE(b.add_cell(CellKind::hexahedron, h, 8));
  const Adjacency a = b.build();
  EXPECT_EQ(a.neighbors.size(), 24u);
  EXPECT_EQ(row(a, 0), (std::vector<index_t>{ 1, 3, 4 }));
}

TEST(Adjacency, WedgePyramidPixelAndVoxelUseVtkOrdering)
{
  AdjacencyBuilder b(8);
  const std::int64_t w[6] = { 0, 1, 2, 3, 4, 5 };
  EXPECT_TRUE(b.add_cell(CellKind::wedge, w, 6));
  EXPECT_EQ(b.build().neighbors.size(), 18u);

  AdjacencyBuilder p(5);
  const std::int64_t y[5] = { 0, 1, 2, 3, 4 };
  EXPECT_TRUE(p.add_cell(CellKind::pyramid, y, 5));
  EXPECT_EQ(p.build().neighbors.size(), 16u);

  AdjacencyBuilder px(4);
  const std::int64_t q[4] = { 0, 1, 2, 3 };
  EXPECT_TRUE(px.add_cell(CellKind::pixel, q, 4));
  const Adjacency a = px.build();
  EXPECT_EQ(row(a, 0), (std::vector<index_t>{ 1, 2 })); // pixel: 0-1, 1-3, 3-2, 2-0

  AdjacencyBuilder vx(8);
  const std::int64_t v8[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  EXPECT_TRUE(vx.add_cell(CellKind::voxel, v8, 8));
  EXPECT_FALSE(vx.add_cell(CellKind::voxel, v8, 6));
  const Adjacency va = vx.build();
  EXPECT_EQ(va.neighbors.size(), 24u);
  EXPECT_EQ(row(va, 0), (std::vector<index_t>{ 1, 2, 4 }));
}

TEST(Adjacency, StripAndPolylineAndVertexCells)
{
  AdjacencyBuilder b(5);
  const std::int64_t strip[4] = { 0, 1, 2, 3 };
  const std::int64_t vert[1] = { 4 };
  EXPECT_TRUE(b.add_cell(CellKind::triangle_strip, strip, 4));
  EXPECT_TRUE(b.add_cell(CellKind::vertex, vert, 1));
  const Adjacency a = b.build();
  EXPECT_EQ(a.neighbors.size(), 10u); // 01 12 23 02 13
  EXPECT_EQ(a.degree(4), 0);
}

TEST(Adjacency, BadIdsAndDegenerateEdgesAreRejectedOrMerged)
{
  AdjacencyBuilder b(3);
  const std::int64_t bad[3] = { 0, 1, 7 };
  EXPECT_FALSE(b.add_cell(CellKind::triangle, bad, 3));
  const std::int64_t degenerate[3] = { 0, 0, 1 };
  EXPECT_TRUE(b.add_cell(CellKind::triangle, degenerate, 3));
  EXPECT_FALSE(b.add_cell(CellKind::unsupported, degenerate, 3));
  const Adjacency a = b.build();
  EXPECT_EQ(a.neighbors.size(), 2u); // only 0-1 survives
}

TEST(Adjacency, CellsListedTwiceGiveTheBuildersAdjacencyWithoutAnEdgeList)
{
  // Mixed kinds, 32-bit ids, repeated edges, degenerate and refused cells.
  struct Cell
  {
    CellKind kind;
    std::vector<std::int32_t> ids;
  };
  std::mt19937 rng(7);
  const index_t n = 300;
  std::uniform_int_distribution<int> id(0, n - 1);
  const std::pair<CellKind, int> kinds[] = { { CellKind::triangle, 3 }, { CellKind::polygon, 5 },
    { CellKind::tetra, 4 }, { CellKind::hexahedron, 8 }, { CellKind::triangle_strip, 6 },
    { CellKind::poly_line, 4 }, { CellKind::vertex, 1 }, { CellKind::pixel, 4 },
    { CellKind::wedge, 5 }, { CellKind::unsupported, 3 } };
  std::vector<Cell> cells;
  for (int c = 0; c < 2000; ++c)
  {
    const auto& [kind, count] = kinds[std::size_t(c) % std::size(kinds)];
    Cell cell{ kind, {} };
    for (int i = 0; i < count; ++i)
      cell.ids.push_back(c % 97 == 0 ? n + i : id(rng) % (c % 5 == 0 ? 3 : n));
    cells.push_back(cell);
  }
  AdjacencyBuilder builder(n);
  std::int64_t refused = 0;
  for (const Cell& cell : cells)
  {
    const std::vector<std::int64_t> ids(cell.ids.begin(), cell.ids.end());
    refused += !builder.add_cell(cell.kind, ids.data(), std::int64_t(ids.size()));
  }
  const Adjacency expected = builder.build();
  int visits = 0;
  std::int64_t skipped = -1;
  const Adjacency a = adjacency_of_cells(
    n,
    [&](const auto& visit)
    {
      ++visits;
      for (const Cell& cell : cells)
        visit(cell.kind, cell.ids.data(), std::int64_t(cell.ids.size()));
    },
    &skipped);
  EXPECT_EQ(visits, 2);
  EXPECT_EQ(skipped, refused);
  EXPECT_GT(refused, 0);
  EXPECT_EQ(a.offsets, expected.offsets);
  EXPECT_EQ(a.neighbors, expected.neighbors);
  EXPECT_EQ(a.neighbors.capacity(), a.neighbors.size());
}
