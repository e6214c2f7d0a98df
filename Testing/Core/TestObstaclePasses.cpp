// The refinement and relaxation passes with obstacles (frame_passes.h): no pass moves a
// vertex through an obstacle, checked against crossings and distances computed here
// (test_sheets.h: Cramer's rule, brute-force distance), not by obstacles.h.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/passes/frame_passes.h"
#include "test_meshes.h"
#include "test_sheets.h"

#include <gtest/gtest.h>

#include <limits>

using namespace geoshaping;
using geoshaping::testing::crosses_any;
using geoshaping::testing::distance_to;
using geoshaping::testing::grid_id;
using geoshaping::testing::Sheet;
using geoshaping::testing::sheet;
using Vec = Eigen::Vector3d;

namespace
{
ChainMailDeformer make(const geoshaping::testing::Mesh& m, const Sheet& obstacle)
{
  ChainMailDeformer d;
  d.set_mesh(m.xyz.data(), m.size(), m.adjacency);
  EXPECT_EQ(d.set_obstacles(
              obstacle.xyz.data(), obstacle.points(), obstacle.tri.data(), obstacle.triangles()),
    "");
  return d;
}

struct Passes
{
  bool refine = false;
  bool relax = false;
};

// Runs the passes after d's frame and returns the final shape's vertices whose path from
// rest crosses the sheet (computed here), and in `moved` how many the passes changed.
std::size_t crossings_after(
  const ChainMailDeformer& d, index_t grasp, const Sheet& s, Passes which, std::size_t& moved)
{
  FramePasses passes;
  ProjectionOptions refine;
  refine.max_iterations = 200;
  RelaxationOptions relax;
  relax.iterations = 50;
  if (which.refine)
    passes.refine(d, grasp, refine);
  if (which.relax)
    passes.relax(d, grasp, relax);
  moved = passes.refined_count() + passes.relaxed_count();
  std::vector<index_t> vertices;
  Displacements values;
  passes.final_shape(d, vertices, values);
  std::size_t crossing = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const Vec p = d.origin() + d.rest_local(vertices[i]);
    crossing += crosses_any(s, p, p + values[i]);
  }
  return crossing;
}

// The same passes without the obstacle (a copy of the frame's shape, the obstacle
// cleared): how many vertices they would have moved through it.
std::size_t crossings_without_gate(
  const ChainMailDeformer& d, index_t grasp, const Sheet& s, Passes which)
{
  ChainMailDeformer ungated = d;
  ungated.clear_obstacles();
  std::size_t moved = 0;
  return crossings_after(ungated, grasp, s, which, moved);
}
} // namespace

TEST(ObstaclePasses, RefinementAndRelaxationNeverPushTheHorizonThroughTheLowerOne)
{
  // The horizon of Core.Obstacles.HorizonPulledDownStopsAboveTheLowerHorizon: 21 x 21
  // at z = 0, pulled down by 10 onto a lower horizon z = -3 + 0.2 (x - 10).
  const auto mesh = geoshaping::testing::triangle_grid(21, 21, 1.0);
  const Sheet lower = sheet(12, Vec(-5, -5, -6), Vec(30, 0, 6), Vec(0, 30, 0));
  const index_t grasp = grid_id(21, 10, 10);
  for (Passes which : { Passes{ true, false }, Passes{ false, true }, Passes{ true, true } })
  {
    ChainMailDeformer d = make(mesh, lower);
    d.set_transfer_function(geoshaping::testing::constant(1.5, 0.75, 0.05));
    ASSERT_TRUE(d.deform(grasp, Vec(0, 0, -10)).ok);
    const std::size_t would_cross = crossings_without_gate(d, grasp, lower, which);
    std::size_t moved = 0;
    EXPECT_EQ(crossings_after(d, grasp, lower, which, moved), 0u) << which.refine << which.relax;
    EXPECT_GT(moved, 0u);
    // The passes do push through it when nothing gates them.
    EXPECT_GT(would_cross, 0u) << which.refine << which.relax;
    RecordProperty(
      std::string("would_cross_") + (which.refine ? "refine" : "") + (which.relax ? "relax" : ""),
      int(would_cross));
  }
}

TEST(ObstaclePasses, ARigidSetTheRefinementMovesStopsAsOne)
{
  // The Figure 6 island lifted into a tilted ceiling (Core.Obstacles.RigidIslandStopsAsOne),
  // then refined: the refinement moves the island as one set, the gate stops it as one.
  const auto scene = geoshaping::testing::rigid_island();
  const Sheet ceiling = sheet(10, Vec(5, 17.5, 1.5), Vec(20, 0, 4), Vec(0, 12.5, 0));
  ChainMailDeformer d = make(scene.mesh, ceiling);
  d.set_malleability(scene.malleability.data());
  ASSERT_TRUE(d.deform(scene.grasp, Vec(scene.pull[0], scene.pull[1], scene.pull[2])).ok);
  FramePasses passes;
  ProjectionOptions options;
  options.max_iterations = 200;
  passes.refine(d, scene.grasp, options);
  const index_t first = grid_id(31, 12, 18);
  const Vec u = passes.displacement(d, first);
  double nearest = std::numeric_limits<double>::infinity();
  for (index_t j = 18; j < 25; ++j)
    for (index_t i = 12; i < 19; ++i)
    {
      const index_t v = grid_id(31, i, j);
      EXPECT_EQ(passes.displacement(d, v), u) << i << " " << j;
      const Vec p = d.origin() + d.rest_local(v);
      EXPECT_FALSE(crosses_any(ceiling, p, p + passes.displacement(d, v))) << i << " " << j;
      nearest = std::min(nearest, distance_to(ceiling, p + passes.displacement(d, v)));
    }
  EXPECT_GT(nearest, 0.0);
  EXPECT_GT(passes.held_back(), 0u); // the island, held back as one
  RecordProperty("held_back", int(passes.held_back()));
  RecordProperty(
    "would_cross", int(crossings_without_gate(d, scene.grasp, ceiling, { true, false })));
}

TEST(ObstaclePasses, ClearanceHoldsAfterThePasses)
{
  const auto mesh = geoshaping::testing::triangle_grid(21, 21, 1.0);
  const Sheet lower = sheet(12, Vec(-5, -5, -6), Vec(30, 0, 6), Vec(0, 30, 0));
  const index_t grasp = grid_id(21, 10, 10);
  const double clearance = 0.5;
  ChainMailDeformer d = make(mesh, lower);
  d.set_transfer_function(geoshaping::testing::constant(1.5, 0.75, 0.05));
  ASSERT_TRUE(d.set_obstacle_clearance(clearance));
  ASSERT_TRUE(d.deform(grasp, Vec(0, 0, -10)).ok);
  FramePasses passes;
  ProjectionOptions refine;
  refine.max_iterations = 200;
  RelaxationOptions relax;
  relax.iterations = 50;
  passes.refine(d, grasp, refine);
  passes.relax(d, grasp, relax);
  EXPECT_GT(passes.held_back(), 0u);
  std::vector<index_t> vertices;
  Displacements values;
  passes.final_shape(d, vertices, values);
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const Vec p = d.origin() + d.rest_local(vertices[i]);
    if (distance_to(lower, p) >= clearance)
      nearest = std::min(nearest, distance_to(lower, p + values[i]));
  }
  EXPECT_GE(nearest, clearance);
  EXPECT_LT(nearest, clearance + 1e-6); // the horizon does reach the clearance
}

TEST(ObstaclePasses, WithoutObstaclesThePassesAreUntouched)
{
  const auto mesh = geoshaping::testing::triangle_grid(21, 21, 1.0);
  const Sheet far = sheet(2, Vec(-5, -5, -60), Vec(30, 0, 0), Vec(0, 30, 0));
  const index_t grasp = grid_id(21, 10, 10);
  ChainMailDeformer with = make(mesh, far);
  ChainMailDeformer without = with;
  without.clear_obstacles();
  for (ChainMailDeformer* d : { &with, &without })
  {
    d->set_transfer_function(geoshaping::testing::constant(1.5, 0.75, 0.05));
    ASSERT_TRUE(d->deform(grasp, Vec(0, 0, -10)).ok);
  }
  FramePasses a, b;
  ProjectionOptions refine;
  refine.max_iterations = 50;
  RelaxationOptions relax;
  relax.iterations = 20;
  for (auto [passes, d] : { std::pair{ &a, &with }, std::pair{ &b, &without } })
  {
    passes->refine(*d, grasp, refine);
    passes->relax(*d, grasp, relax);
  }
  EXPECT_EQ(a.held_back(), 0u);
  for (index_t v = 0; v < with.size(); ++v)
    ASSERT_EQ(a.displacement(with, v), b.displacement(without, v)) << v;
}
