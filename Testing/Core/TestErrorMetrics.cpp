#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"
#include "geoshaping/metrics/error_metrics.h"
#include "test_meshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{
std::vector<Eigen::Vector3d> points(const geoshaping::testing::Mesh& m)
{
  std::vector<Eigen::Vector3d> p(std::size_t(m.size()));
  for (index_t v = 0; v < m.size(); ++v)
    p[v] = Eigen::Vector3d(m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]);
  return p;
}

Adjacency edges(index_t n, std::initializer_list<std::pair<index_t, index_t>> list)
{
  AdjacencyBuilder b(n);
  for (const auto& [i, j] : list)
    b.add_edge(i, j);
  return b.build();
}

ChainMailParams params(double t, double k, double h)
{
  return { t, k, h };
}
} // namespace

TEST(ErrorMetrics, MeanEdgeLengthOfUnitGridIsOne)
{
  const auto grid = geoshaping::testing::quad_grid(7, 5, 1.0);
  EXPECT_DOUBLE_EQ(mean_edge_length(points(grid), grid.adjacency), 1.0);
}

TEST(ErrorMetrics, MeanEdgeLengthCountsEachEdgeOnce)
{
  const Adjacency adj = edges(3, { { 0, 1 }, { 1, 2 } });
  const std::vector<Eigen::Vector3d> rest{ { 0, 0, 0 }, { 1, 0, 0 }, { 4, 0, 0 } };
  EXPECT_DOUBLE_EQ(mean_edge_length(rest, adj), 2.0);
}

TEST(ErrorMetrics, RigidPairTranslatedHasZeroRigidError)
{
  const Adjacency adj = edges(2, { { 0, 1 } });
  const LinkMesh m = link_mesh({ { 0.3, 0.1, 0 }, { 1.3, 0.1, 0 } }, adj, { 0.0, 0.0 });
  const Eigen::Vector3d t(0.3, -2.0, 5.0);
  EXPECT_EQ(rigid_error(m, { t, t }), 0.0);
}

TEST(ErrorMetrics, RigidPairRotatedQuarterTurnHasRigidErrorRootTwo)
{
  // Rotating (0,0,0)-(1,0,0) by 90 degrees about z around vertex 0 moves vertex 1 to
  // (0,1,0): u_1 - u_0 = (-1, 1, 0), |.| = sqrt 2, mean edge 1.
  const Adjacency adj = edges(2, { { 0, 1 } });
  const LinkMesh m = link_mesh({ { 0, 0, 0 }, { 1, 0, 0 } }, adj, { 0.0, 0.0 });
  EXPECT_DOUBLE_EQ(rigid_error(m, { { 0, 0, 0 }, { -1, 1, 0 } }), std::sqrt(2.0));
}

TEST(ErrorMetrics, RigidErrorIgnoresEdgesWithASoftEnd)
{
  const Adjacency adj = edges(2, { { 0, 1 } });
  const LinkMesh m = link_mesh({ { 0, 0, 0 }, { 1, 0, 0 } }, adj, { 0.0, 0.2 });
  EXPECT_EQ(rigid_error(m, { { 0, 0, 0 }, { -1, 1, 0 } }), 0.0);
}

TEST(ErrorMetrics, StretchOvershootOnTwoEdgeChainGivesExactLinkError)
{
  // Chain 0-1-2 along x, spacing 10; vertex 2 displaced by (3, 4, 0), the rest at rest.
  // 2 w.r.t. 1 (t 1.1, k 1, h 0.1): o = (10,0,0), S = (0,10,10): x in 10 + [10, 11],
  // y in [-1, 1]; x_2 = (23, 4) lies (2, 3) outside: sqrt 13.
  // 1 w.r.t. 2 (t 1.5): o = (-10,0,0): x in 23 + [-15, -10] contains 10, y in 4 + [-1, 1]
  // misses 0 by 3. Edge 0-1 is at rest. E_link = sqrt 13 / 10.
  const Adjacency adj = edges(3, { { 0, 1 }, { 1, 2 } });
  LinkMesh m;
  m.adjacency = &adj;
  m.rest = { { 0, 0, 0 }, { 10, 0, 0 }, { 20, 0, 0 } };
  m.params = { params(2, 0.5, 0.5), params(1.5, 1, 0.1), params(1.1, 1, 0.1) };
  m.rigid = { 0, 0, 0 };
  m.mean_edge = mean_edge_length(m.rest, adj);
  const Displacements u{ { 0, 0, 0 }, { 0, 0, 0 }, { 3, 4, 0 } };
  EXPECT_DOUBLE_EQ(link_distance(m, u, 2, 1), std::sqrt(13.0));
  EXPECT_DOUBLE_EQ(link_distance(m, u, 1, 2), 3.0);
  EXPECT_EQ(link_distance(m, u, 0, 1), 0.0);
  EXPECT_EQ(link_distance(m, u, 1, 0), 0.0);
  EXPECT_DOUBLE_EQ(link_error(m, u), std::sqrt(13.0) / 10.0);

  // The same distance from the box of valid_region.h in positions.
  const Box box = valid_region(m.rest[1] + u[1], m.rest[2] - m.rest[1], m.params[2]);
  const Eigen::Vector3d x2 = m.rest[2] + u[2];
  EXPECT_DOUBLE_EQ((box.clamp(x2) - x2).norm(), std::sqrt(13.0));
}

TEST(ErrorMetrics, ChainMailChainSatisfiesEveryLink)
{
  const auto mesh = geoshaping::testing::chain(20, 10.0);
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  TransferFunction tf;
  tf.stretch = { 1.1, 1.1 };
  tf.compression = { 1.0, 1.0 };
  tf.shear = { 0.0, 0.0 };
  d.set_transfer_function(tf);
  ASSERT_TRUE(d.deform(19, { 8.0, 0.0, 0.0 }).ok);
  const LinkMesh m = link_mesh(d);
  EXPECT_LE(link_error(m, displacements(d)), 1e-15);
}

namespace
{
// The Figure 6 scene of test_meshes.h under queue q (`mesh` must be its mesh).
ChainMailDeformer island_frame(const geoshaping::testing::Mesh& mesh, QueueKind q)
{
  const auto scene = geoshaping::testing::rigid_island();
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  d.set_malleability(scene.malleability.data());
  d.set_queue(q);
  EXPECT_TRUE(d.deform(scene.grasp, Eigen::Vector3d(scene.pull)).ok);
  return d;
}
} // namespace

TEST(ErrorMetrics, FifoRipplesThroughRigidIslandWhileFifoPriorityDoesNot)
{
  const auto mesh = geoshaping::testing::triangle_grid(31, 31, 1.0);
  const ChainMailDeformer fifo = island_frame(mesh, QueueKind::fifo);
  const ChainMailDeformer fp = island_frame(mesh, QueueKind::fifo_priority);
  EXPECT_GT(rigid_error(link_mesh(fifo), displacements(fifo)), 0.1);
  EXPECT_EQ(rigid_error(link_mesh(fp), displacements(fp)), 0.0);
}

TEST(ErrorMetrics, SparseMetricsOverDisplacedRegionEqualDenseMetrics)
{
  const auto mesh = geoshaping::testing::triangle_grid(31, 31, 1.0);
  for (QueueKind q : { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority })
  {
    const ChainMailDeformer d = island_frame(mesh, q);
    const LinkMesh m = link_mesh(d);
    const Displacements u = displacements(d);
    EXPECT_GT(link_error(m, u), 0.0) << queue_name(q);
    EXPECT_EQ(link_error(m, u, d.moved()), link_error(m, u)) << queue_name(q);
    EXPECT_EQ(rigid_error(m, u, d.moved()), rigid_error(m, u)) << queue_name(q);
    const Displacements zero(u.size(), Eigen::Vector3d::Zero());
    const ReferenceError dense = reference_error(m, u, zero);
    const ReferenceError sparse = reference_error(m, u, zero, d.moved());
    EXPECT_EQ(sparse.max, dense.max);
    EXPECT_DOUBLE_EQ(sparse.rms, dense.rms);
  }
}

TEST(ErrorMetrics, ReferenceErrorIsMaxAndRmsOverDisplacedVertices)
{
  // Mean edge 2; distances 5 (vertex 1) and 2 (vertex 2); vertices 0 and 3 at rest in
  // both configurations do not count: max = 5 / 2, rms = sqrt((25 + 4) / 2) / 2.
  const auto mesh = geoshaping::testing::chain(4, 2.0);
  const LinkMesh m = link_mesh(points(mesh), mesh.adjacency, std::vector<double>(4, 0.5));
  const Displacements u{ { 0, 0, 0 }, { 3, 4, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  const Displacements r{ { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 2 }, { 0, 0, 0 } };
  const ReferenceError e = reference_error(m, u, r);
  EXPECT_DOUBLE_EQ(e.max, 2.5);
  EXPECT_DOUBLE_EQ(e.rms, std::sqrt(14.5) / 2.0);
  const ReferenceError none = reference_error(m, r, r);
  EXPECT_EQ(none.max, 0.0);
  EXPECT_EQ(none.rms, 0.0);
}

TEST(ErrorMetrics, TemporalErrorOfLinearMapIsItsGainAlongTheDrag)
{
  // X_v(d) = A_v d. Dragging along y: vertex 1 with A = [1 2 0; 0 1 0; 0 0 1] moves by
  // (2, 1, 0) per unit of drag, the largest gain: sqrt 5.
  std::vector<Eigen::Matrix3d> a(3, Eigen::Matrix3d::Identity());
  a[1](0, 1) = 2.0;
  a[2] *= 0.5;
  std::vector<Eigen::Vector3d> drags;
  std::vector<Displacements> frames;
  TemporalError streamed(3);
  for (int k = 0; k <= 20; ++k)
  {
    drags.emplace_back(0.0, 0.1 * k, 0.0);
    Displacements x;
    for (const auto& ai : a)
      x.push_back(ai * drags.back());
    frames.push_back(x);
    streamed.add_frame(drags.back(), { 0, 1, 2 }, x);
  }
  EXPECT_NEAR(temporal_error(drags, frames), std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(streamed.value(), std::sqrt(5.0), 1e-12);
}

TEST(ErrorMetrics, SparseTemporalErrorCountsVerticesThatReturnToRest)
{
  // Frame 0 displaces vertex 0 by 3, frame 1 only vertex 1 by 4: the step compares
  // |0 - 3| and |4 - 0|, over a drag step of 2.
  TemporalError e(2);
  e.add_frame({ 0, 0, 0 }, { 0 }, { { 3, 0, 0 } });
  e.add_frame({ 2, 0, 0 }, { 1 }, { { 0, 4, 0 } });
  EXPECT_DOUBLE_EQ(e.value(), 2.0);
}

TEST(ErrorMetrics, RepeatedDragStepsAreSkippedNotDividedByZero)
{
  const std::vector<Eigen::Vector3d> drags(3, Eigen::Vector3d(1, 1, 1));
  const std::vector<Displacements> frames{ { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 2, 0, 0 } } };
  EXPECT_EQ(temporal_error(drags, frames), 0.0);
}

TEST(ErrorMetrics, RigidMeshDraggedHasTemporalErrorOne)
{
  const auto mesh = geoshaping::testing::triangle_grid(12, 9, 1.0);
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  d.set_uniform_malleability(0.0);
  std::vector<Eigen::Vector3d> drags;
  for (int k = 0; k < 30; ++k)
    drags.emplace_back(0.05 * k, 0.02 * k, 0.1 * k);
  EXPECT_NEAR(temporal_error(d, 40, drags), 1.0, 1e-12);
}

TEST(ErrorMetrics, DegenerateMeshGivesFiniteMetrics)
{
  // Two coincident vertices joined by a zero-length edge, one isolated vertex: mean edge
  // 0, so lengths are reported raw. A zero-length link is an equality: distance 1.
  const Adjacency adj = edges(3, { { 0, 1 } });
  const LinkMesh m = link_mesh({ { 1, 1, 1 }, { 1, 1, 1 }, { 5, 5, 5 } }, adj, { 0.0, 0.0, 1.0 });
  EXPECT_EQ(m.mean_edge, 0.0);
  const Displacements u{ { 0, 0, 0 }, { 1, 0, 0 }, { 7, 0, 0 } };
  EXPECT_DOUBLE_EQ(link_error(m, u), 1.0);
  EXPECT_DOUBLE_EQ(rigid_error(m, u), 1.0);
  const ReferenceError e = reference_error(m, u, Displacements(3, Eigen::Vector3d::Zero()));
  EXPECT_DOUBLE_EQ(e.max, 7.0);
  EXPECT_TRUE(std::isfinite(e.rms));

  const Adjacency none = edges(0, {});
  const LinkMesh empty = link_mesh({}, none, {});
  EXPECT_EQ(mean_edge_length({}, none), 0.0);
  EXPECT_EQ(link_error(empty, {}), 0.0);
  EXPECT_EQ(rigid_error(empty, {}), 0.0);
}

TEST(ErrorMetrics, NonFiniteDisplacementReportsInfinityNotNaN)
{
  const Adjacency adj = edges(2, { { 0, 1 } });
  const LinkMesh m = link_mesh({ { 0, 0, 0 }, { 1, 0, 0 } }, adj, { 0.0, 0.0 });
  const Displacements u{ { 0, 0, 0 }, { std::nan(""), 0, 0 } };
  EXPECT_TRUE(std::isinf(link_error(m, u)));
  EXPECT_TRUE(std::isinf(rigid_error(m, u)));
}

namespace
{
// An nx-by-ny grid in z = 0, each quad split along its (i, j)-(i+1, j+1) diagonal,
// counter-clockwise seen from +z.
std::vector<index_t> grid_triangles(index_t nx, index_t ny)
{
  std::vector<index_t> t;
  for (index_t j = 0; j + 1 < ny; ++j)
    for (index_t i = 0; i + 1 < nx; ++i)
    {
      const index_t a = grid_id(nx, i, j), b = grid_id(nx, i + 1, j), c = grid_id(nx, i + 1, j + 1),
                    d = grid_id(nx, i, j + 1);
      t.insert(t.end(), { a, b, c, a, c, d });
    }
  return t;
}

std::vector<index_t> all_vertices(index_t n)
{
  std::vector<index_t> v(static_cast<std::size_t>(n));
  for (index_t i = 0; i < n; ++i)
    v[i] = i;
  return v;
}
} // namespace

TEST(ErrorMetrics, FoldingAFlatSheetAlongAGridLineBendsByTheFoldAngle)
{
  const index_t nx = 9, ny = 5, fold = 4;
  const auto rest = points(geoshaping::testing::triangle_grid(nx, ny, 1.0));
  const double phi = 0.7;
  Displacements u(rest.size(), Eigen::Vector3d::Zero());
  for (index_t v = 0; v < index_t(rest.size()); ++v)
  {
    const double s = rest[v].x() - fold;
    if (s > 0.0)
      u[v] = Eigen::Vector3d(fold + s * std::cos(phi), rest[v].y(), s * std::sin(phi)) - rest[v];
  }
  const BendingError e = bending_error(rest, grid_triangles(nx, ny), u, all_vertices(nx * ny));
  // Interior edges: 8*5 + 9*4 + 8*4 = 108 edges, 2*8 + 2*4 = 24 on the border; the fold
  // bends the 4 on x = 4 by phi, the rest not at all.
  EXPECT_EQ(e.edges, 84u);
  EXPECT_NEAR(e.max, phi, 1e-12);
  EXPECT_NEAR(e.rms, phi * std::sqrt(4.0 / 84.0), 1e-12);
  // Over the band of columns 3..5 only: the edges whose two triangles lie in it are the
  // 4 on the fold, 2 * 4 diagonals and 2 * 3 interior horizontals.
  std::vector<index_t> band;
  for (index_t j = 0; j < ny; ++j)
    for (index_t i = fold - 1; i <= fold + 1; ++i)
      band.push_back(grid_id(nx, i, j));
  const BendingError in_band = bending_error(rest, grid_triangles(nx, ny), u, band);
  EXPECT_EQ(in_band.edges, 18u);
  EXPECT_NEAR(in_band.max, phi, 1e-12);
  EXPECT_NEAR(in_band.rms, phi * std::sqrt(4.0 / 18.0), 1e-12);
}

TEST(ErrorMetrics, RigidMotionOfARelief)
{
  const index_t nx = 7, ny = 6;
  auto rest = points(geoshaping::testing::triangle_grid(nx, ny, 1.0));
  for (auto& p : rest)
    p.z() = std::sin(p.x()) * std::cos(0.7 * p.y()); // the rest shape's own relief
  const std::vector<index_t> triangles = grid_triangles(nx, ny);
  const Displacements none(rest.size(), Eigen::Vector3d::Zero());
  const BendingError at_rest = bending_error(rest, triangles, none, all_vertices(nx * ny));
  EXPECT_EQ(at_rest.max, 0.0);
  EXPECT_GT(at_rest.edges, 0u);
  const Eigen::Matrix3d R =
    Eigen::AngleAxisd(0.9, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  Displacements u(rest.size());
  for (std::size_t v = 0; v < rest.size(); ++v)
    u[v] = R * rest[v] + Eigen::Vector3d(3.0, -1.0, 2.0) - rest[v];
  EXPECT_LT(bending_error(rest, triangles, u, all_vertices(nx * ny)).max, 1e-12);
  EXPECT_EQ(bending_error(rest, triangles, u, {}).edges, 0u);
}
