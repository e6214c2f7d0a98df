#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/scenes/layered_scene.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geoshaping;

TEST(LayeredScene, HorizonsEndOnTheFaultWithTheThrow)
{
  LayeredSceneParams p;
  const LayeredScene s = layered_fault_scene(p);
  ASSERT_GT(s.mesh.num_points(), 0);
  ASSERT_EQ(s.part.size(), std::size_t(s.mesh.num_points()));
  const double cot = 1.0 / std::tan(70.0 * M_PI / 180.0);
  double footwall_end = -1e9, hanging_start = 1e9;
  for (index_t v = 0; v < s.mesh.num_points(); ++v)
  {
    const double x = s.mesh.xyz[3 * v], z = s.mesh.xyz[3 * v + 2];
    if (s.part[v] == int(ScenePart::upper_horizon))
    {
      EXPECT_TRUE(z == -30.0 || z == -45.0) << z;
      if (z == -30.0)
        footwall_end = std::max(footwall_end, x);
      else
        hanging_start = std::min(hanging_start, x);
    }
    if (s.part[v] == int(ScenePart::fault)) // on the fault plane
      EXPECT_NEAR(x, 90.0 + (0.0 - z) * cot, 1e-9);
  }
  EXPECT_NEAR(footwall_end, 90.0 + 30.0 * cot, 1e-9);
  EXPECT_NEAR(hanging_start, 90.0 + 45.0 * cot, 1e-9);
}

TEST(LayeredScene, PartsAreSeparateComponentsSoAGraspMovesOnlyItsPart)
{
  LayeredSceneParams p;
  p.spacing = 5.0;
  const LayeredScene s = layered_fault_scene(p);
  ChainMailDeformer d;
  d.set_mesh(s.mesh.xyz.data(), s.mesh.num_points(), s.mesh.adjacency());
  d.set_uniform_malleability(0.0);
  index_t grasp = 0;
  while (s.part[grasp] != int(ScenePart::fault))
    ++grasp;
  ASSERT_TRUE(d.deform(grasp, { 5.0, 0.0, 0.0 }).ok);
  for (index_t v = 0; v < s.mesh.num_points(); ++v)
  {
    // The fault translates rigidly; the horizons, other components here, stay.
    const bool on_fault = s.part[v] == int(ScenePart::fault);
    EXPECT_EQ(d.displacement(v).x(), on_fault ? 5.0 : 0.0) << v;
  }
}

TEST(LayeredScene, BadParametersGiveAnEmptySceneAndAReason)
{
  LayeredSceneParams p;
  p.dip_degrees = 0.0;
  EXPECT_STRNE(validate(p), "");
  EXPECT_EQ(layered_fault_scene(p).mesh.num_points(), 0);
  p = {};
  p.horizon_upper = -100.0;
  EXPECT_STRNE(validate(p), "");
  p = {};
  p.spacing = std::nan("");
  EXPECT_STRNE(validate(p), "");
}
