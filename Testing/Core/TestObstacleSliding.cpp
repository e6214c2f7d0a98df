// Sliding contact (Obstacles::slide, ChainMailDeformer::set_sliding): vertices on an
// obstacle stay on it while they move along it, checked against projections onto the
// obstacle's planes and distances computed here (test_sheets.h).
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/obstacles.h"
#include "geoshaping/deform/valid_region.h"
#include "test_meshes.h"
#include "test_sheets.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace geoshaping;
using geoshaping::testing::crosses_any;
using geoshaping::testing::distance_to;
using geoshaping::testing::grid_id;
using geoshaping::testing::Sheet;
using geoshaping::testing::sheet;
using Vec = Eigen::Vector3d;

namespace
{
// Mean length of the mesh's edges (each counted from both ends).
double mean_edge_length(const geoshaping::testing::Mesh& m)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (index_t v = 0; v < m.size(); ++v)
    for (const index_t* it = m.adjacency.begin(v); it != m.adjacency.end(v); ++it, ++count)
      sum += (Vec(&m.xyz[3 * std::size_t(v)]) - Vec(&m.xyz[3 * std::size_t(*it)])).norm();
  return sum / double(count);
}

// The point of the plane through a with unit normal e nearest to x.
Vec onto_plane(const Vec& x, const Vec& a, const Vec& e)
{
  return x - e.dot(x - a) * e;
}

const QueueKind all_queues[] = { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority,
  QueueKind::max_violation };
} // namespace

TEST(Obstacles, SlidingVerticesStayOnTheFaultWhileMovingAlongIt)
{
  // Horizon x in [0, 10], y in [0, 20] at z = 0, cut off by the fault x = 10 - 0.5 z
  // (y in [-5, 25], z in [-10, 10]), which leans away below it: its last column lies on
  // the fault. Pulled down, the column slides down the fault; unflagged it would leave
  // it (touching is not crossing) and hang in the air beside it.
  const auto mesh = geoshaping::testing::triangle_grid(11, 21, 1.0);
  const Sheet fault = sheet(8, Vec(15, -5, -10), Vec(0, 30, 0), Vec(-10, 0, 20));
  const Vec a(10, 0, 0), e = Vec(1, 0, 0.5).normalized(); // the fault's plane
  std::vector<std::uint8_t> on_fault(std::size_t(mesh.size()), 0);
  for (index_t j = 0; j < 21; ++j)
    on_fault[std::size_t(grid_id(11, 10, j))] = 1;
  const double tolerance = 1e-9 * mean_edge_length(mesh);
  const index_t grasp = grid_id(11, 5, 10);
  for (ValidRegionFrame frame : { ValidRegionFrame::axes, ValidRegionFrame::link })
    for (QueueKind q : all_queues)
    {
      ChainMailDeformer d;
      d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
      d.set_transfer_function(geoshaping::testing::constant(1.5, 0.75, 0.05));
      d.set_valid_region_frame(frame);
      d.set_queue(q);
      ASSERT_EQ(
        d.set_obstacles(fault.xyz.data(), fault.points(), fault.tri.data(), fault.triangles()), "");
      d.set_sliding(on_fault.data());
      const FrameResult r = d.deform(grasp, Vec(0, 0, -4));
      ASSERT_TRUE(r.ok);
      EXPECT_EQ(r.grasp_fraction, 1.0);
      int slid = 0;
      for (index_t v : d.moved())
      {
        const Vec p = d.origin() + d.rest_local(v), x = d.position(v);
        if (!d.sliding(v))
        {
          EXPECT_FALSE(crosses_any(fault, p, x)) << v;
          continue;
        }
        // Where its sponsor sends it, projected onto the fault's plane here.
        const index_t s = d.sponsor(v);
        ASSERT_GE(s, 0);
        const Vec target = required_displacement(
          frame, d.rest_local(v) - d.rest_local(s), d.params(v), d.displacement(s));
        EXPECT_LE((x - onto_plane(p + target, a, e)).norm(), 1e-12) << v;
        EXPECT_LE(distance_to(fault, x), tolerance) << v;
        EXPECT_LT(x.z(), v == grid_id(11, 10, 10) ? -2.0 : -0.25) << v; // down along the fault
        ++slid;
      }
      EXPECT_EQ(slid, 21) << queue_name(q);
    }
}

TEST(Obstacles, ASlidingGraspLandsOnTheFaultNearestItsTarget)
{
  const auto mesh = geoshaping::testing::triangle_grid(11, 21, 1.0);
  const Sheet fault = sheet(8, Vec(15, -5, -10), Vec(0, 30, 0), Vec(-10, 0, 20));
  const Vec a(10, 0, 0), e = Vec(1, 0, 0.5).normalized();
  std::vector<std::uint8_t> on_fault(std::size_t(mesh.size()), 0);
  const index_t grasp = grid_id(11, 10, 10);
  on_fault[std::size_t(grasp)] = 1;
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  ASSERT_EQ(
    d.set_obstacles(fault.xyz.data(), fault.points(), fault.tri.data(), fault.triangles()), "");
  d.set_sliding(on_fault.data());
  EXPECT_TRUE(d.sliding(grasp));
  EXPECT_FALSE(d.sliding(grasp - 1));
  const Vec pull(0, 3, -2), p = d.origin() + d.rest_local(grasp);
  const FrameResult r = d.deform(grasp, pull);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.grasp_fraction, 1.0);
  EXPECT_EQ(r.blocked, 0u);
  EXPECT_LE((d.position(grasp) - onto_plane(p + pull, a, e)).norm(), 1e-12);
  EXPECT_NE(d.displacement(grasp), pull);
  // Without the mask the grasp goes where it is pulled, off the fault.
  d.set_sliding(nullptr);
  d.deform(grasp, pull);
  EXPECT_EQ(d.displacement(grasp), pull);
  EXPECT_GT(distance_to(fault, d.position(grasp)), 0.5);
}

TEST(Obstacles, SlidingStopsWhereItsStraightPathWouldCrossARidge)
{
  // A surface z = 0 with a ridge: up to (1, y, 2) over x in [0, 1] (face A, z = 2x) and
  // down over [1, 2] (face B, z = 4 - 2x). A vertex at (-1, 0, 0) pulled along +x by 5:
  // its targets (-1 + 5s, 0, 0) land on the flat, then on A, and from s = 0.4 (below the
  // crest, as near to B as to A) on B or beyond, where the straight path from its rest
  // position would pass through A. It stops at s = 0.4, on A.
  Sheet s;
  for (double x : { -5.0, 0.0, 1.0, 2.0, 7.0 })
    for (double y : { -5.0, 5.0 })
      s.xyz.insert(s.xyz.end(), { x, y, x == 1.0 ? 2.0 : 0.0 });
  for (std::int64_t k = 0; k < 4; ++k)
    s.tri.insert(s.tri.end(), { 2 * k, 2 * k + 2, 2 * k + 3, 2 * k, 2 * k + 3, 2 * k + 1 });
  Obstacles o;
  ASSERT_EQ(o.set(s.xyz.data(), s.points(), s.tri.data(), s.triangles(), Vec::Zero()), "");
  const Vec p(-1, 0, 0), w(5, 0, 0);
  double fraction = 0.0;
  const Vec u = o.slide(p, w, fraction);
  EXPECT_NEAR(fraction, 0.4, 1e-9);
  const Vec x = p + u;
  EXPECT_NEAR(x.z(), 2.0 * x.x(), 1e-12); // on A
  EXPECT_GT(x.x(), 0.1);
  EXPECT_LT(x.x(), 1.0);
  EXPECT_LE(distance_to(s, x), 1e-12);
  // A short pull along the flat slides freely and exactly.
  const Vec v = o.slide(p, Vec(-2, 1, 0.5), fraction);
  EXPECT_EQ(fraction, 1.0);
  EXPECT_EQ(v, Vec(-2, 1, 0));
}
