#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace geoshaping;
using geoshaping::testing::constant;
using geoshaping::testing::grid_id;

namespace
{
ChainMailDeformer make(const geoshaping::testing::Mesh& m)
{
  ChainMailDeformer d;
  d.set_mesh(m.xyz.data(), m.size(), m.adjacency);
  return d;
}

// Largest change of a rigid-rigid edge vector, in the units of the mesh.
double rigid_error(const ChainMailDeformer& d)
{
  double e = 0.0;
  for (index_t v = 0; v < d.size(); ++v)
    for (const index_t* n = d.adjacency().begin(v); n != d.adjacency().end(v); ++n)
      if (d.malleability(v) == 0.0f && d.malleability(*n) == 0.0f)
        e = std::max(e, (d.displacement(v) - d.displacement(*n)).cwiseAbs().maxCoeff());
  return e;
}
} // namespace

TEST(ChainMailDeformer, StretchedChainAbsorbsOneUnitPerLink)
{
  // Rest spacing 10, stretch 1.1: each link may lengthen by 1, so pulling the end 8
  // outward moves the vertices by 8, 7, 6, ... 1 and leaves the rest at rest.
  const auto mesh = geoshaping::testing::chain(20, 10.0);
  ChainMailDeformer d = make(mesh);
  d.set_transfer_function(constant(1.1, 1.0, 0.0));
  const FrameResult r = d.deform(19, { 8.0, 0.0, 0.0 });
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.moved, 8u);
  for (index_t i = 0; i < 20; ++i)
  {
    const double expected = std::max(0.0, 8.0 - (19 - i));
    EXPECT_NEAR(d.displacement(i).x(), expected, 1e-12) << "vertex " << i;
    EXPECT_EQ(d.displacement(i).y(), 0.0);
  }
}

TEST(ChainMailDeformer, IncompressibleChainPushedInwardMovesAsOne)
{
  const auto mesh = geoshaping::testing::chain(20, 10.0);
  ChainMailDeformer d = make(mesh);
  d.set_transfer_function(constant(1.1, 1.0, 0.0));
  ASSERT_TRUE(d.deform(19, { -8.0, 0.0, 0.0 }).ok);
  EXPECT_EQ(d.moved().size(), 20u);
  for (index_t i = 0; i < 20; ++i)
    EXPECT_NEAR(d.displacement(i).x(), -8.0, 1e-12);
}

TEST(ChainMailDeformer, QuadGridPulledAtCentreFollowsShearCone)
{
  // Grid spacing L in z = 0, centre pulled by D along z. For an edge o = (L, 0, 0) the
  // z bounds are u_z(s) -/+ h S_z with S_z = |o_x| + |o_y| = L, while x and y bounds
  // contain the rest (k L <= L <= t L). So each link absorbs h L of vertical motion and
  // with breadth-first order the sponsor is always one step closer:
  //   u_z(i, j) = max(0, D - h L (|i - ic| + |j - jc|))   (Manhattan distance),
  // and no vertex moves horizontally.
  const double L = 2.0, D = 9.0, h = 0.5;
  const index_t n = 21, c = 10;
  const auto mesh = geoshaping::testing::quad_grid(n, n, L);
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
  {
    ChainMailDeformer d = make(mesh);
    d.set_transfer_function(constant(1.5, 0.5, h));
    d.set_queue(q);
    ASSERT_TRUE(d.deform(grid_id(n, c, c), { 0.0, 0.0, D }).ok);
    for (index_t j = 0; j < n; ++j)
      for (index_t i = 0; i < n; ++i)
      {
        const double r = std::abs(i - c) + std::abs(j - c);
        const Eigen::Vector3d u = d.displacement(grid_id(n, i, j));
        EXPECT_NEAR(u.z(), std::max(0.0, D - h * L * r), 1e-12) << i << "," << j;
        EXPECT_EQ(u.x(), 0.0);
        EXPECT_EQ(u.y(), 0.0);
      }
  }
}

TEST(ChainMailDeformer, ZeroMalleabilityTranslatesEveryConnectedVertexExactly)
{
  const auto mesh = geoshaping::testing::triangle_grid(30, 20, 1.0);
  ChainMailDeformer d = make(mesh);
  d.set_uniform_malleability(0.0);
  const Eigen::Vector3d delta(0.3, -1.7, 2.25);
  ASSERT_TRUE(d.deform(123, delta).ok);
  EXPECT_EQ(d.moved().size(), std::size_t(mesh.size()));
  for (index_t v = 0; v < d.size(); ++v)
    EXPECT_EQ(d.displacement(v), delta) << v; // bit-exact
}

namespace
{
// The Figure 6 scene of test_meshes.h (a rigid island in a soft grid) under queue q.
ChainMailDeformer rigid_island_frame(QueueKind q)
{
  const auto scene = geoshaping::testing::rigid_island();
  ChainMailDeformer d = make(scene.mesh);
  d.set_malleability(scene.malleability.data());
  d.set_queue(q);
  EXPECT_TRUE(d.deform(scene.grasp, Eigen::Vector3d(scene.pull)).ok);
  return d;
}
} // namespace

TEST(ChainMailDeformer, RigidIslandKeepsItsShapeUnderFifoPriorityNotUnderFifo)
{
  const ChainMailDeformer fp = rigid_island_frame(QueueKind::fifo_priority);
  EXPECT_TRUE(fp.moved_this_frame(grid_id(31, 15, 20)));
  EXPECT_EQ(rigid_error(fp), 0.0);
  const ChainMailDeformer fifo = rigid_island_frame(QueueKind::fifo);
  EXPECT_GT(rigid_error(fifo), 0.1); // the paper's Figure 6 ripple
}

TEST(ChainMailDeformer, EachVertexMovesOnceIntoItsSponsorsValidRegion)
{
  for (QueueKind q :
    { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority, QueueKind::max_violation })
  {
    const ChainMailDeformer d = rigid_island_frame(q);
    std::set<index_t> seen(d.moved().begin(), d.moved().end());
    EXPECT_EQ(seen.size(), d.moved().size()) << queue_name(q);
    for (index_t v : d.moved())
    {
      const index_t s = d.sponsor(v);
      if (s < 0)
        continue;
      EXPECT_TRUE(d.moved_this_frame(s));
      const Box b = valid_region(
        d.rest_local(s) + d.displacement(s), d.rest_local(v) - d.rest_local(s), d.params(v));
      const Eigen::Vector3d p = d.rest_local(v) + d.displacement(v);
      EXPECT_LE((b.clamp(p) - p).norm(), 1e-9) << queue_name(q) << " vertex " << v;
    }
    for (index_t v = 0; v < d.size(); ++v)
      if (!d.moved_this_frame(v))
        EXPECT_TRUE(d.displacement(v).isZero(0.0));
  }
}

TEST(ChainMailDeformer, IdenticalInputsGiveBitIdenticalOutputs)
{
  const ChainMailDeformer a = rigid_island_frame(QueueKind::priority);
  const ChainMailDeformer b = rigid_island_frame(QueueKind::priority);
  ASSERT_EQ(a.moved(), b.moved());
  for (index_t v = 0; v < a.size(); ++v)
    EXPECT_EQ(a.displacement(v), b.displacement(v));
}

TEST(ChainMailDeformer, PriorityVeinsDifferFromFifoPrioritySpiralOnEqualMalleability)
{
  const index_t n = 41;
  const auto mesh = geoshaping::testing::triangle_grid(n, n, 1.0);
  ChainMailDeformer fp = make(mesh), pq = make(mesh);
  fp.set_queue(QueueKind::fifo_priority);
  pq.set_queue(QueueKind::priority);
  const Eigen::Vector3d delta(0.0, 0.0, 10.0);
  fp.deform(grid_id(n, 20, 20), delta);
  pq.deform(grid_id(n, 20, 20), delta);
  double diff = 0.0;
  for (index_t v = 0; v < fp.size(); ++v)
    diff = std::max(diff, (fp.displacement(v) - pq.displacement(v)).norm());
  EXPECT_GT(diff, 1.0);
  // On one bucket FIFO Priority is exactly FIFO.
  ChainMailDeformer fifo = make(mesh);
  fifo.set_queue(QueueKind::fifo);
  fifo.deform(grid_id(n, 20, 20), delta);
  for (index_t v = 0; v < fp.size(); ++v)
    EXPECT_EQ(fp.displacement(v), fifo.displacement(v));
}

// A smooth brush leaves many values a hair apart; within one band (priority_band) they are
// equal for the order, so FIFO Priority is exactly FIFO there, while each vertex keeps its
// own valid region.
TEST(ChainMailDeformer, FifoPriorityTakesValuesOfOneBandFirstInFirstOut)
{
  const index_t n = 41;
  const auto mesh = geoshaping::testing::triangle_grid(n, n, 1.0);
  std::vector<float> m(std::size_t(mesh.size()));
  for (std::size_t v = 0; v < m.size(); ++v) // in [0.5, 0.5 + 1/64): band 33
    m[v] = 0.5f + 0.015f * float((v * 7919) % 101) / 100.0f;
  ChainMailDeformer fp = make(mesh), fifo = make(mesh), flat = make(mesh);
  fp.set_malleability(m.data());
  fifo.set_malleability(m.data());
  fp.set_queue(QueueKind::fifo_priority);
  fifo.set_queue(QueueKind::fifo);
  flat.set_queue(QueueKind::fifo_priority);
  const Eigen::Vector3d delta(0.0, 0.0, 10.0);
  fp.deform(grid_id(n, 20, 20), delta);
  fifo.deform(grid_id(n, 20, 20), delta);
  flat.deform(grid_id(n, 20, 20), delta); // malleability 0.5 everywhere
  ASSERT_EQ(fp.moved(), fifo.moved());
  double from_flat = 0.0;
  for (index_t v = 0; v < fp.size(); ++v)
  {
    EXPECT_EQ(fp.displacement(v), fifo.displacement(v)) << v;
    from_flat = std::max(from_flat, (fp.displacement(v) - flat.displacement(v)).norm());
  }
  EXPECT_GT(from_flat, 0.0); // the exact values still shape the regions
}

TEST(ChainMailDeformer, PinnedVerticesStayPutAndBlockPropagation)
{
  const auto mesh = geoshaping::testing::chain(10, 1.0);
  ChainMailDeformer d = make(mesh);
  std::vector<std::uint8_t> pins(10, 0);
  pins[4] = 1;
  d.set_pinned(pins.data());
  d.set_uniform_malleability(0.0);
  ASSERT_TRUE(d.deform(0, { 0.0, 5.0, 0.0 }).ok);
  for (index_t i = 0; i < 10; ++i)
    EXPECT_EQ(d.displacement(i).y(), i < 4 ? 5.0 : 0.0) << i;
  EXPECT_FALSE(d.deform(4, { 0.0, 1.0, 0.0 }).ok);
  for (index_t i = 0; i < 10; ++i)
    EXPECT_TRUE(d.displacement(i).isZero(0.0));
}

TEST(ChainMailDeformer, FrameResetsOnlyWhatMovedAndReturnsToRest)
{
  const auto mesh = geoshaping::testing::chain(100, 1.0);
  ChainMailDeformer d = make(mesh);
  d.set_transfer_function(constant(1.5, 0.5, 0.0));
  d.deform(0, { -3.0, 0.0, 0.0 });
  const auto first = d.moved();
  d.deform(99, { 2.0, 0.0, 0.0 });
  EXPECT_EQ(d.previously_moved(), first);
  for (index_t v : first)
    EXPECT_TRUE(d.displacement(v).isZero(0.0));
  d.reset();
  for (index_t v = 0; v < d.size(); ++v)
    EXPECT_TRUE(d.displacement(v).isZero(0.0));
}

TEST(ChainMailDeformer, BadGraspAndDisplacementAreRefused)
{
  const auto mesh = geoshaping::testing::chain(5, 1.0);
  ChainMailDeformer d = make(mesh);
  EXPECT_FALSE(d.deform(-1, { 1, 0, 0 }).ok);
  EXPECT_FALSE(d.deform(5, { 1, 0, 0 }).ok);
  EXPECT_FALSE(d.deform(0, { NAN, 0, 0 }).ok);
  EXPECT_FALSE(d.deform(0, { INFINITY, 0, 0 }).ok);
  const FrameResult r = d.deform(0, { 0, 0, 0 });
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.moved, 1u);
}

TEST(ChainMailDeformer, MalleabilityIsClampedAndNanIsRigid)
{
  const auto mesh = geoshaping::testing::chain(4, 1.0);
  ChainMailDeformer d = make(mesh);
  const float m[4] = { -1.0f, 2.0f, NAN, 0.5f };
  EXPECT_EQ(d.set_malleability(m), 3u);
  EXPECT_EQ(d.malleability(0), 0.0f);
  EXPECT_EQ(d.malleability(1), 1.0f);
  EXPECT_EQ(d.malleability(2), 0.0f);
  EXPECT_EQ(d.malleability(3), 0.5f);
}

TEST(ChainMailDeformer, UtmSizedCoordinatesGiveTheSameDisplacementsAsNearTheOrigin)
{
  auto near = geoshaping::testing::triangle_grid(25, 25, 10.0);
  auto far = near;
  for (std::size_t i = 0; i < far.xyz.size(); i += 3)
  {
    far.xyz[i] = double(float(far.xyz[i] + 512345.0));
    far.xyz[i + 1] = double(float(far.xyz[i + 1] + 4123456.0));
  }
  ChainMailDeformer a = make(near), b = make(far);
  a.deform(300, { 5.0, -3.0, 20.0 });
  b.deform(300, { 5.0, -3.0, 20.0 });
  for (index_t v = 0; v < a.size(); ++v)
    EXPECT_LE((a.displacement(v) - b.displacement(v)).norm(), 1e-9 * 240.0) << v;
}
