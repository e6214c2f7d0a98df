// Obstacles (obstacles.h) and the deformer's gate, checked against crossings and
// distances computed here with their own code (Cramer's rule, brute-force distance).
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/obstacles.h"
#include "geoshaping/deform/valid_region.h"
#include "test_meshes.h"
#include "test_sheets.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>

using namespace geoshaping;
using geoshaping::testing::crosses_any;
using geoshaping::testing::distance_to;
using geoshaping::testing::grid_id;
using geoshaping::testing::segment_distance;
using geoshaping::testing::Sheet;
using geoshaping::testing::sheet;
using Vec = Eigen::Vector3d;

namespace
{
ChainMailDeformer make(const geoshaping::testing::Mesh& m)
{
  ChainMailDeformer d;
  d.set_mesh(m.xyz.data(), m.size(), m.adjacency);
  return d;
}

// Every vertex's path from rest to its position crosses no triangle; every moved soft
// vertex but the grasp is where its sponsor's stopped displacement sends it, or on the
// way there (a fraction of it) when the whole way crosses the obstacle (rigid ones stop
// with their component: RigidIslandStopsAsOne); with a clearance c, the whole way may
// instead come closer than c. Returns how many were held back.
int expect_obstacle_rule(
  const ChainMailDeformer& d, const Sheet& s, index_t grasp, double clearance = 0.0)
{
  int held = 0;
  for (index_t v : d.moved())
  {
    const Vec p = d.origin() + d.rest_local(v), q = d.position(v);
    EXPECT_FALSE(crosses_any(s, p, q)) << "vertex " << v;
    const index_t sp = d.sponsor(v);
    if (v == grasp || sp < 0 || region_params(d.params(v)).rigid())
      continue;
    const Vec target = required_displacement(
      d.valid_region_frame(), d.rest_local(v) - d.rest_local(sp), d.params(v), d.displacement(sp));
    const Vec u = d.displacement(v);
    if (u == target)
      continue;
    ++held;
    const double nearest = clearance > 0.0 ? segment_distance(s, p, target) : clearance;
    EXPECT_TRUE(crosses_any(s, p, p + target) || nearest < clearance + 1e-6)
      << "vertex " << v << " held back for nothing";
    const double f = u.dot(target) / target.squaredNorm();
    EXPECT_GE(f, 0.0);
    EXPECT_LT(f, 1.0);
    EXPECT_LE((u - f * target).norm(), 1e-12 * target.norm());
  }
  return held;
}

const QueueKind all_queues[] = { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority,
  QueueKind::max_violation };
} // namespace

TEST(Obstacles, CrossingFractionsThroughFacesEdgesAndVertices)
{
  // Two triangles of the square [0, 4]^2 at z = -2 sharing the diagonal (0,0)-(4,4).
  Sheet s = sheet(1, Vec(0, 0, -2), Vec(4, 0, 0), Vec(0, 4, 0));
  Obstacles o;
  ASSERT_EQ(o.set(s.xyz.data(), 4, s.tri.data(), 2, Vec::Zero()), "");
  const double g = 1e-9 * std::sqrt(32.0); // the stand-off: 1e-9 of the bounding box diagonal
  // Through a face, the shared edge and a corner: stopped g above z = -2 (t = 0.5).
  for (const Vec& p : { Vec(1, 3, 0), Vec(2, 2, 0), Vec(0, 0, 0), Vec(4, 4, 0) })
    EXPECT_NEAR(o.admissible_fraction(p, Vec(0, 0, -4)), 0.5 - g / 4, 1e-15) << p.transpose();
  // Beside the sheet, starting on it, along it, stopping short of it: free.
  EXPECT_EQ(o.admissible_fraction(Vec(5, 2, 0), Vec(0, 0, -4)), 1.0);
  EXPECT_EQ(o.admissible_fraction(Vec(2, 1, -2), Vec(0, 0, -4)), 1.0);
  EXPECT_EQ(o.admissible_fraction(Vec(2, 1, -2), Vec(1, 1, 0)), 1.0);
  EXPECT_EQ(o.admissible_fraction(Vec(2, 1, 0), Vec(0, 0, -1.5)), 1.0);
  // A slanted path: the stand-off is measured across the plane.
  EXPECT_NEAR(o.admissible_fraction(Vec(1, 1, 0), Vec(2, 0, -4)), 0.5 - g / 4, 1e-15);
}

TEST(Obstacles, SheetsTouchingAtAPointStopAPathThroughIt)
{
  // Two triangles given as separate sheets, touching only at (0, 0, -2) (each with its
  // own copy of the point): a path through the point is stopped, one beside it is not.
  Sheet s;
  s.xyz = { 0, 0, -2, 3, 1, -2, 1, 3, -2, 0, 0, -2, -3, -1, -2, -1, -3, -2 };
  s.tri = { 0, 1, 2, 3, 4, 5 };
  Obstacles o;
  ASSERT_EQ(o.set(s.xyz.data(), 6, s.tri.data(), 2, Vec::Zero()), "");
  EXPECT_LT(o.admissible_fraction(Vec(0, 0, 0), Vec(0, 0, -4)), 0.5);
  EXPECT_LT(o.admissible_fraction(Vec(-1, 1, 0), Vec(2, -2, -4)), 0.5);
  EXPECT_EQ(o.admissible_fraction(Vec(-1, 1, 0), Vec(0, 0, -4)), 1.0);
}

TEST(Obstacles, RefusesBadTrianglesAndPoints)
{
  Obstacles o;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double xyz[] = { 0, 0, 0, 1, 0, 0, 0, nan, 0 };
  const std::int64_t tri[] = { 0, 1, 2 }, bad[] = { 0, 1, 3 };
  EXPECT_NE(o.set(xyz, 3, tri, 1, Vec::Zero()).find("not finite"), std::string::npos);
  EXPECT_TRUE(o.empty());
  const double ok[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  EXPECT_NE(o.set(ok, 3, bad, 1, Vec::Zero()).find("outside"), std::string::npos);
  EXPECT_EQ(o.set(ok, 3, tri, 0, Vec::Zero()), "no triangles");
  ChainMailDeformer d;
  EXPECT_FALSE(d.set_obstacle_clearance(-1.0));
  EXPECT_FALSE(d.set_obstacle_clearance(nan));
  EXPECT_EQ(d.obstacle_clearance(), 0.0);
}

TEST(Obstacles, HorizonPulledDownStopsAboveTheLowerHorizonWithEveryQueue)
{
  // Upper horizon: a 21 x 21 triangle grid at z = 0; lower horizon wider, 3 below the
  // grasp and rising toward +x (z = -3 + 0.2 (x - 10)) more steeply than the pull's
  // cone (shear 0.05 per unit), so every vertex on that side comes down onto it.
  const auto mesh = geoshaping::testing::triangle_grid(21, 21, 1.0);
  const Sheet lower = sheet(12, Vec(-5, -5, -6), Vec(30, 0, 6), Vec(0, 30, 0));
  const index_t grasp = grid_id(21, 10, 10);
  for (QueueKind q : all_queues)
  {
    ChainMailDeformer d = make(mesh);
    d.set_transfer_function(geoshaping::testing::constant(1.5, 0.75, 0.05));
    d.set_queue(q);
    const FrameResult free = d.deform(grasp, Vec(0, 0, -10));
    ASSERT_TRUE(free.ok);
    EXPECT_LT(d.position(grasp).z(), -3.0);
    ASSERT_EQ(
      d.set_obstacles(lower.xyz.data(), lower.xyz.size() / 3, lower.tri.data(), lower.triangles()),
      "");
    const FrameResult r = d.deform(grasp, Vec(0, 0, -10));
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.grasp_fraction, 0.3, 1e-8);
    EXPECT_LT(r.grasp_fraction, 0.3);
    EXPECT_GT(r.blocked, 10u);
    for (index_t v = 0; v < d.size(); ++v)
    {
      const Vec x = d.position(v);
      EXPECT_GT(x.z(), -3.0 + 0.2 * (x.x() - 10.0)) << v;
    }
    EXPECT_NEAR(d.position(grasp).z(), -3.0, 1e-7);
    EXPECT_GT(expect_obstacle_rule(d, lower, grasp), 10);
  }
}

TEST(Obstacles, HorizonDraggedAcrossADippingFaultStopsOnIt)
{
  // Horizon x in [0, 10], y in [0, 20]; fault x = 12 + 0.5 z (dipping), y in [-5, 25].
  const auto mesh = geoshaping::testing::triangle_grid(11, 21, 1.0);
  const Sheet fault = sheet(8, Vec(7, -5, -10), Vec(0, 30, 0), Vec(10, 0, 20));
  for (ValidRegionFrame frame : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    ChainMailDeformer d = make(mesh);
    d.set_valid_region_frame(frame);
    ASSERT_EQ(
      d.set_obstacles(fault.xyz.data(), fault.xyz.size() / 3, fault.tri.data(), fault.triangles()),
      "");
    const index_t grasp = grid_id(11, 7, 10);
    const FrameResult r = d.deform(grasp, Vec(8, 0, 1));
    ASSERT_TRUE(r.ok);
    // The grasp at (7, 10, 0) meets x = 12 + 0.5 z at s: 7 + 8 s = 12 + 0.5 s.
    EXPECT_NEAR(r.grasp_fraction, 5.0 / 7.5, 1e-8);
    for (index_t v : d.moved())
    {
      const Vec x = d.position(v);
      EXPECT_LT(x.x(), 12.0 + 0.5 * x.z()) << v;
    }
    EXPECT_GT(expect_obstacle_rule(d, fault, grasp), 5);
  }
}

TEST(Obstacles, RigidIslandStopsAsOne)
{
  // The Figure 6 island lifted into a tilted ceiling: its members would reach it at
  // different fractions; it stops at the smallest, in one piece.
  const auto scene = geoshaping::testing::rigid_island();
  // z = 1.5 + 0.2 (x - 5) over y in [17.5, 30]: above the island, not the grasp.
  const Sheet ceiling = sheet(10, Vec(5, 17.5, 1.5), Vec(20, 0, 4), Vec(0, 12.5, 0));
  ChainMailDeformer d = make(scene.mesh);
  d.set_malleability(scene.malleability.data());
  ASSERT_EQ(d.set_obstacles(
              ceiling.xyz.data(), ceiling.xyz.size() / 3, ceiling.tri.data(), ceiling.triangles()),
    "");
  const FrameResult r = d.deform(scene.grasp, Vec(scene.pull[0], scene.pull[1], scene.pull[2]));
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.grasp_fraction, 1.0);
  const index_t first = grid_id(31, 12, 18);
  ASSERT_TRUE(d.moved_this_frame(first));
  double nearest = std::numeric_limits<double>::infinity();
  for (index_t j = 18; j < 25; ++j)
    for (index_t i = 12; i < 19; ++i)
    {
      const index_t v = grid_id(31, i, j);
      EXPECT_EQ(d.displacement(v), d.displacement(first)) << i << " " << j;
      nearest = std::min(nearest, distance_to(ceiling, d.position(v)));
    }
  EXPECT_GT(d.displacement(first).z(), 0.5);
  EXPECT_LT(nearest, 1e-6); // the member that met the ceiling
  expect_obstacle_rule(d, ceiling, scene.grasp);
}

TEST(Obstacles, ClearanceIsKeptByVerticesThatStartedFarEnough)
{
  const auto mesh = geoshaping::testing::triangle_grid(21, 21, 1.0);
  Sheet lower = sheet(12, Vec(-5, -5, -3), Vec(30, 0, 0), Vec(0, 30, 0));
  // A small plate 0.25 under one vertex: that vertex starts inside the clearance.
  lower.add(sheet(1, Vec(14.5, 9.5, -0.25), Vec(1, 0, 0), Vec(0, 1, 0)));
  ChainMailDeformer d = make(mesh);
  ASSERT_TRUE(d.set_obstacle_clearance(0.5));
  EXPECT_FALSE(d.set_obstacle_clearance(-0.1));
  ASSERT_EQ(
    d.set_obstacles(lower.xyz.data(), lower.xyz.size() / 3, lower.tri.data(), lower.triangles()),
    "");
  const index_t grasp = grid_id(21, 10, 10);
  const FrameResult r = d.deform(grasp, Vec(0, 0, -10));
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.grasp_fraction, 0.25, 1e-8);
  const index_t close = grid_id(21, 15, 10);
  for (index_t v : d.moved())
  {
    const Vec rest = d.origin() + d.rest_local(v);
    if (v == close)
    {
      EXPECT_LT(distance_to(lower, rest), 0.5);
      continue;
    }
    EXPECT_GE(distance_to(lower, d.position(v)), 0.5) << v;
  }
  EXPECT_TRUE(d.moved_this_frame(close));
  expect_obstacle_rule(d, lower, grasp, 0.5);
}

TEST(Obstacles, AGraspOnTheObstacleLeavesItButNothingCrosses)
{
  // A fault x = 10 through the horizon's last column: the grasp lies on it.
  const auto mesh = geoshaping::testing::triangle_grid(11, 21, 1.0);
  const Sheet fault = sheet(6, Vec(10, -5, -10), Vec(0, 30, 0), Vec(0, 0, 20));
  const index_t grasp = grid_id(11, 10, 10);
  for (const Vec& pull : { Vec(3, 0, 0), Vec(-3, 0, 0), Vec(0, 2, 2) })
  {
    ChainMailDeformer d = make(mesh);
    ASSERT_EQ(
      d.set_obstacles(fault.xyz.data(), fault.xyz.size() / 3, fault.tri.data(), fault.triangles()),
      "");
    const FrameResult r = d.deform(grasp, pull);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.grasp_fraction, 1.0); // touching is not crossing
    EXPECT_EQ(d.displacement(grasp), pull);
    expect_obstacle_rule(d, fault, grasp);
    // Touching is not crossing for them either: a vertex whose longest sponsor asks it
    // past the fault stops on it (x = 10 exactly).
    for (index_t v : d.moved())
      if (d.rest_local(v).x() + d.origin().x() < 10.0)
        EXPECT_LE(d.position(v).x(), 10.0) << v;
  }
}

TEST(Obstacles, PinsStayAndNoObstacleMeansTheSameBits)
{
  const auto mesh = geoshaping::testing::triangle_grid(21, 21, 1.0);
  const Sheet far = sheet(2, Vec(-5, -5, -50), Vec(30, 0, 0), Vec(0, 30, 0));
  std::vector<std::uint8_t> pins(std::size_t(mesh.size()), 0);
  pins[std::size_t(grid_id(21, 12, 10))] = 1;
  ChainMailDeformer a = make(mesh), b = make(mesh);
  a.set_pinned(pins.data());
  b.set_pinned(pins.data());
  ASSERT_EQ(
    b.set_obstacles(far.xyz.data(), far.xyz.size() / 3, far.tri.data(), far.triangles()), "");
  const index_t grasp = grid_id(21, 10, 10);
  a.deform(grasp, Vec(0.5, 1, -4));
  const FrameResult r = b.deform(grasp, Vec(0.5, 1, -4));
  EXPECT_EQ(r.blocked, 0u);
  ASSERT_EQ(a.moved(), b.moved());
  for (index_t v : a.moved())
    EXPECT_EQ(a.displacement(v), b.displacement(v));
  EXPECT_FALSE(b.moved_this_frame(grid_id(21, 12, 10)));
  b.clear_obstacles();
  EXPECT_EQ(b.obstacles(), nullptr);
}
