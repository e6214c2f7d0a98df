#include "geoshaping/mesh/sparse_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace geoshaping;

namespace
{
// A (k+1) x (k+1) grid of unit squares split into triangles, z = 0.
struct Grid
{
  index_t k;
  std::vector<Eigen::Vector3d> x;
  SparseNormals normals;

  explicit Grid(index_t size)
    : k(size)
  {
    std::vector<std::int64_t> offsets{ 0 };
    std::vector<index_t> vertices;
    for (index_t j = 0; j <= k; ++j)
      for (index_t i = 0; i <= k; ++i)
        x.emplace_back(i, j, 0.0);
    for (index_t j = 0; j < k; ++j)
      for (index_t i = 0; i < k; ++i)
      {
        const index_t a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
        for (index_t v : { a, b, d })
          vertices.push_back(v);
        offsets.push_back(std::int64_t(vertices.size()));
        for (index_t v : { a, d, c })
          vertices.push_back(v);
        offsets.push_back(std::int64_t(vertices.size()));
      }
    normals.set_mesh(offsets, vertices, index_t(x.size()));
  }
  // Positions as the normals see them, after every vertex is reported moved.
  Eigen::Vector3d at(index_t v)
  {
    const auto position = [this](index_t w) { return x[std::size_t(w)]; };
    normals.set_positions(position);
    return normals.normal(v);
  }
};
} // namespace

TEST(SparseNormals, FlatCounterClockwiseGridFacesUp)
{
  Grid g(3);
  for (index_t v = 0; v < index_t(g.x.size()); ++v)
    EXPECT_LT((g.at(v) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-6) << v;
}

TEST(SparseNormals, VertexNormalIsTheNormalisedSumOfItsUnitFaceNormals)
{
  Grid g(2);
  g.x[4].z() = 1.0; // lift the centre: a pyramid
  // Face normals are kept as floats: 1e-6.
  // Corner 0 uses the faces (0,1,4) and (0,4,3); their unit normals, by hand.
  const auto unit = [&](index_t a, index_t b, index_t c)
  { return (g.x[b] - g.x[a]).cross(g.x[c] - g.x[a]).normalized(); };
  const Eigen::Vector3d expected = (unit(0, 1, 4) + unit(0, 4, 3)).normalized();
  EXPECT_LT((g.at(0) - expected).norm(), 1e-6);
  EXPECT_LT((g.at(4) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-6); // symmetric apex
}

TEST(SparseNormals, AffectedAreTheVerticesSharingAFaceWithAMovedOne)
{
  Grid g(3);
  std::vector<index_t> out;
  const index_t corner = 0, centre = 5; // (1, 1)
  const auto position = [&g](index_t w) { return g.x[std::size_t(w)]; };
  g.normals.set_positions(position);
  g.normals.moved(&corner, 1, position, out);
  std::sort(out.begin(), out.end());
  EXPECT_EQ(out, (std::vector<index_t>{ 0, 1, 4, 5 }));
  out.clear();
  const index_t both[2] = { corner, centre };
  g.normals.moved(both, 2, position, out);
  std::sort(out.begin(), out.end());
  // Diagonals run (i, j) to (i+1, j+1): 2 and 8 share no face with the centre.
  EXPECT_EQ(out, (std::vector<index_t>{ 0, 1, 4, 5, 6, 9, 10 })); // once each
}

TEST(SparseNormals, DegenerateFacesGiveZeroNotNaN)
{
  Grid g(1);
  for (auto& p : g.x)
    p = Eigen::Vector3d(2, 2, 2); // every face collapses
  for (index_t v = 0; v < 4; ++v)
  {
    const Eigen::Vector3d n = g.at(v);
    EXPECT_TRUE(n.allFinite());
    EXPECT_EQ(n.norm(), 0.0);
  }
}

TEST(SparseNormals, MovedRefreshesExactlyTheNormalsASetPositionsPassWouldGive)
{
  Grid g(4);
  const auto position = [&g](index_t w) { return g.x[std::size_t(w)]; };
  g.normals.set_positions(position);
  g.x[12].z() = 2.0; // (2, 2) lifted
  std::vector<index_t> affected;
  const index_t lifted = 12;
  g.normals.moved(&lifted, 1, position, affected);
  std::vector<Eigen::Vector3d> incremental;
  for (index_t v = 0; v < index_t(g.x.size()); ++v)
    incremental.push_back(g.normals.normal(v));
  g.normals.set_positions(position); // from scratch
  for (index_t v = 0; v < index_t(g.x.size()); ++v)
    EXPECT_EQ(incremental[std::size_t(v)], g.normals.normal(v)) << v;
  EXPECT_EQ(affected.size(), 7u); // the lifted vertex and its six face-neighbours
}
