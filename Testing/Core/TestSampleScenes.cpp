#include "geoshaping/scenes/sample_scenes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

using namespace geoshaping;

namespace
{
Eigen::Vector3d point(const SampleMesh& m, index_t v)
{
  return Eigen::Vector3d(m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]);
}

double tetra_volume(const SampleMesh& m, std::size_t c)
{
  const index_t* t = &m.connectivity[4 * c];
  const Eigen::Vector3d o = point(m, t[0]);
  return (point(m, t[1]) - o).cross(point(m, t[2]) - o).dot(point(m, t[3]) - o) / 6.0;
}

FaultStepParams small()
{
  FaultStepParams p;
  p.length = 40;
  p.width = 12;
  p.throw_height = 8;
  p.step_run = 2;
  p.spacing = 0.5;
  p.thickness = 3;
  p.layers = 2;
  return p;
}
} // namespace

TEST(SampleScenes, FaultStepHorizonSpansItsSizeWithANearVerticalStep)
{
  const FaultStepParams p = small();
  const SampleMesh m = fault_step_horizon(p);
  const index_t nu = fault_step_columns(p), nv = index_t(std::lround(p.width / p.spacing)) + 1;
  ASSERT_EQ(m.num_points(), nu * nv);
  EXPECT_EQ(m.num_cells(), std::size_t(2 * (nu - 1) * (nv - 1)));
  EXPECT_EQ(m.cell_size, 3);
  Eigen::Vector3d lo = point(m, 0), hi = lo;
  int on_step = 0;
  for (index_t v = 0; v < m.num_points(); ++v)
  {
    lo = lo.cwiseMin(point(m, v));
    hi = hi.cwiseMax(point(m, v));
    on_step += m.xyz[3 * v + 2] > 0.1 * p.throw_height && m.xyz[3 * v + 2] < 0.9 * p.throw_height;
  }
  EXPECT_NEAR(lo.x(), 0.0, 1e-12);
  EXPECT_NEAR(hi.x(), p.length, 1e-9);
  EXPECT_NEAR(hi.y(), p.width, 1e-12);
  EXPECT_NEAR(lo.z(), 0.0, 1e-12);
  EXPECT_NEAR(hi.z(), p.throw_height, 1e-12);
  // Arc-length sampling gives the step rows in proportion to its height.
  EXPECT_GE(on_step / nv, int(0.8 * p.throw_height / p.spacing) - 1);
  // Edges along the profile and along y are close to the spacing everywhere.
  const Adjacency adj = m.adjacency();
  double longest = 0.0;
  for (index_t v = 0; v < m.num_points(); ++v)
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      if (std::abs(m.xyz[3 * v + 1] - m.xyz[3 * *n + 1]) < 1e-12)
        longest = std::max(longest, (point(m, v) - point(m, *n)).norm());
  EXPECT_LT(longest, 1.05 * p.spacing);
  // The steepest part of the step: slope 1.5 throw / run = 6, about 80 degrees.
  double steepest = 0.0;
  for (index_t i = 0; i + 1 < nu; ++i)
  {
    const Eigen::Vector3d d = point(m, i + 1) - point(m, i);
    steepest = std::max(steepest, std::abs(d.z()) / std::max(d.x(), 1e-12));
  }
  EXPECT_GT(steepest, 5.0);
}

TEST(SampleScenes, TrianglesFaceUpAndAreNotDegenerate)
{
  const SampleMesh m = fault_step_horizon(small());
  for (std::size_t c = 0; c < m.num_cells(); ++c)
  {
    const index_t* t = &m.connectivity[3 * c];
    const Eigen::Vector3d n =
      (point(m, t[1]) - point(m, t[0])).cross(point(m, t[2]) - point(m, t[0]));
    ASSERT_GT(n.norm(), 1e-6) << "triangle " << c;
    // The profile descends in x, so the normal points up or toward +x, never down.
    EXPECT_GE(n.z() + n.x(), 0.0) << "triangle " << c;
  }
}

TEST(SampleScenes, SlabTetrahedraArePositiveAndFillTheSlabExactly)
{
  const FaultStepParams p = small();
  const SampleMesh slab = fault_step_slab(p);
  const SampleMesh top = fault_step_horizon(p);
  ASSERT_EQ(slab.cell_size, 4);
  ASSERT_EQ(slab.num_points(), top.num_points() * (p.layers + 1));
  EXPECT_TRUE(std::equal(top.xyz.begin(), top.xyz.end(), slab.xyz.begin()));
  double volume = 0.0;
  for (std::size_t c = 0; c < slab.num_cells(); ++c)
  {
    const double v = tetra_volume(slab, c);
    ASSERT_GT(v, 0.0) << "tetra " << c;
    volume += v;
  }
  // Vertical offsets: the cross-section is length x thickness whatever the step.
  EXPECT_NEAR(volume, p.length * p.width * p.thickness, 1e-6 * volume);
  // Kuhn's split is conforming: interior vertices have 14 neighbours, none more.
  const Adjacency adj = slab.adjacency();
  std::int64_t most = 0;
  for (index_t v = 0; v < adj.size(); ++v)
    most = std::max(most, adj.degree(v));
  EXPECT_EQ(most, 14);
}

TEST(SampleScenes, OriginShiftsEveryVertex)
{
  FaultStepParams p = small();
  const SampleMesh here = fault_step_horizon(p);
  p.origin = Eigen::Vector3d(500000.0, 4200000.0, -1500.0);
  const SampleMesh utm = fault_step_horizon(p);
  ASSERT_EQ(here.xyz.size(), utm.xyz.size());
  for (std::size_t i = 0; i < here.xyz.size(); ++i)
    EXPECT_NEAR(utm.xyz[i] - p.origin[int(i % 3)], here.xyz[i], 1e-9);
}

TEST(SampleScenes, BadParametersGiveAnEmptyMeshAndAReason)
{
  FaultStepParams p = small();
  p.spacing = 0.0;
  EXPECT_STRNE(validate(p), "");
  EXPECT_EQ(fault_step_horizon(p).num_points(), 0);
  p = small();
  p.step_position = 1.5;
  EXPECT_EQ(fault_step_slab(p).num_points(), 0);
  p = small();
  p.spacing = 1e-6;
  EXPECT_STRNE(validate(p), "");
  EXPECT_STREQ(validate(small()), "");
  EXPECT_EQ(tight_fold(10, 10, -1, 1).num_points(), 0);
}

TEST(SampleScenes, Figure5CPaintsTheStepBlackItsBorderWhiteTheRestRed)
{
  const FaultStepParams p = small();
  const double border = 4.0;
  const std::vector<Dab> dabs = fault_step_painting(p, border);
  ASSERT_FALSE(dabs.empty());
  for (const Dab& d : dabs)
    EXPECT_STREQ(validate_dab(d), "");
  EXPECT_EQ(dabs.back().value, 0.0); // black last, over the white band
  const index_t top = fault_step_horizon(p).num_points();
  for (const SampleMesh& m : { fault_step_horizon(p), fault_step_slab(p) })
  {
    const std::vector<float> mall = fault_step_malleability(m, p, border);
    ASSERT_EQ(mall.size(), std::size_t(m.num_points()));
    const double x0 = 0.5 * p.length - 0.5 * p.step_run, x1 = x0 + p.step_run;
    int black = 0, white = 0, red = 0;
    for (index_t v = 0; v < top; ++v) // the horizon (the slab's top layer)
    {
      const double x = m.xyz[3 * v];
      if (x > x0 && x < x1)
      {
        EXPECT_EQ(mall[v], 0.0f) << "on the step, vertex " << v;
        ++black;
      }
      else if (std::min(std::abs(x - x0), std::abs(x - x1)) > 2 * p.spacing + 0.1 &&
               std::min(std::abs(x - x0), std::abs(x - x1)) < 2 * p.spacing + border - 0.5)
      {
        EXPECT_EQ(mall[v], 1.0f) << "in the border, vertex " << v;
        ++white;
      }
      else if (std::min(std::abs(x - x0), std::abs(x - x1)) > 2 * p.spacing + border + 0.1)
      {
        EXPECT_EQ(mall[v], float(fault_step_red)) << "far from the step, vertex " << v;
        ++red;
      }
    }
    EXPECT_GT(black, 0);
    EXPECT_GT(white, 0);
    EXPECT_GT(red, black);
  }
}

TEST(SampleScenes, TightFoldHasTwoSheetsGapApart)
{
  const SampleMesh m = tight_fold(20.0, 5.0, 1.0, 0.25);
  int upper = 0, lower = 0;
  for (index_t v = 0; v < m.num_points(); ++v)
  {
    const double x = m.xyz[3 * v], z = m.xyz[3 * v + 2];
    EXPECT_LE(x, 20.5 + 1e-9);
    upper += x < 19.0 && std::abs(z - 1.0) < 1e-9;
    lower += x < 19.0 && std::abs(z) < 1e-9;
  }
  EXPECT_EQ(upper, lower);
  EXPECT_GT(upper, 0);
}
