// geoshaping::FramePasses: the refinement and relaxation after a frame, against the
// core passes called by hand (link_projection.h, relaxation.h).
#include "geoshaping/passes/frame_passes.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{
struct Scene
{
  geoshaping::testing::IslandScene island = geoshaping::testing::rigid_island();
  ChainMailDeformer deformer;
  std::vector<std::uint8_t> pins;
  Scene(ValidRegionFrame frame = ValidRegionFrame::axes)
  {
    deformer.set_mesh(island.mesh.xyz.data(), island.mesh.size(), island.mesh.adjacency);
    deformer.set_malleability(island.malleability.data());
    pins.assign(std::size_t(island.mesh.size()), 0);
    pins[std::size_t(grid_id(31, 15, 25))] = 1;
    deformer.set_pinned(pins.data());
    deformer.set_valid_region_frame(frame);
    EXPECT_TRUE(deform());
  }
  bool deform() { return deformer.deform(island.grasp, Eigen::Vector3d(island.pull)).ok; }
};

ProjectionOptions sweeps(int n)
{
  ProjectionOptions o;
  o.max_iterations = n;
  o.solver = ProjectionSolver::dykstra;
  return o;
}

RelaxationOptions relaxation(int n)
{
  RelaxationOptions o;
  o.iterations = n;
  return o;
}

bool bit_equal(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}
} // namespace

TEST(FramePasses, WithoutAPassTheShapeIsTheFrame)
{
  Scene s;
  FramePasses passes;
  passes.begin_frame();
  std::vector<index_t> vertices;
  Displacements values;
  passes.final_shape(s.deformer, vertices, values);
  EXPECT_EQ(vertices, s.deformer.moved());
  ASSERT_EQ(values.size(), vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    EXPECT_TRUE(bit_equal(values[i], s.deformer.displacement(vertices[i])));
  EXPECT_TRUE(passes.beyond().empty());
  EXPECT_FALSE(passes.refined() || passes.relaxed());
}

TEST(FramePasses, RefineThenRelaxEqualsThePassesCalledByHand)
{
  for (ValidRegionFrame frame : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    Scene s(frame);
    FramePasses passes;
    passes.begin_frame();
    passes.refine(s.deformer, s.island.grasp, sweeps(8));
    passes.relax(s.deformer, s.island.grasp, relaxation(6));

    // By hand: refine_links, then relax from the frame plus what the refinement moved.
    LinkMesh links = link_mesh(s.deformer);
    LinkProjector projector(links);
    refine_links(projector, s.deformer, s.island.grasp, sweeps(8));
    std::vector<index_t> start = s.deformer.moved();
    for (index_t v : projector.changed())
      if (!s.deformer.moved_this_frame(v))
        start.push_back(v);
    Displacements values;
    for (index_t v : start)
      values.push_back(projector.displacement(v));
    Relaxer relaxer(links);
    relaxer.relax(s.island.grasp, start, values, relaxation(6));

    std::set<index_t> expected_beyond;
    for (const std::vector<index_t>* list : { &projector.changed(), &relaxer.changed() })
      for (index_t v : *list)
        if (!s.deformer.moved_this_frame(v))
          expected_beyond.insert(v);
    ASSERT_FALSE(expected_beyond.empty()) << "the scene's passes reach beyond the frame";
    const std::vector<index_t>& beyond = passes.beyond();
    EXPECT_EQ(std::set<index_t>(beyond.begin(), beyond.end()), expected_beyond);
    EXPECT_EQ(beyond.size(), expected_beyond.size()) << "each vertex once";
    for (index_t v = 0; v < s.deformer.size(); ++v)
      ASSERT_TRUE(bit_equal(passes.displacement(s.deformer, v), relaxer.displacement(v)))
        << "vertex " << v;
    EXPECT_EQ(passes.refined_count(), projector.changed().size());
    EXPECT_EQ(passes.relaxed_count(), relaxer.changed().size());
  }
}

TEST(FramePasses, ANewFrameForgetsThePassesAndTheLinksFollowTheDeformer)
{
  Scene s;
  FramePasses passes;
  passes.begin_frame();
  passes.refine(s.deformer, s.island.grasp, sweeps(8));
  ASSERT_FALSE(passes.beyond().empty());
  passes.begin_frame();
  EXPECT_TRUE(passes.beyond().empty());
  const index_t v = s.deformer.moved().back();
  EXPECT_TRUE(bit_equal(passes.displacement(s.deformer, v), s.deformer.displacement(v)));

  // A changed transfer function rebuilds the link data; changed malleability does after
  // invalidate(): either way the result equals fresh passes.
  TransferFunction stiffer;
  stiffer.stretch = { 1.0, 1.5 };
  s.deformer.set_transfer_function(stiffer);
  std::vector<float> m = s.island.malleability;
  std::fill(m.begin(), m.begin() + 200, 0.3f);
  s.deformer.set_malleability(m.data());
  passes.invalidate();
  ASSERT_TRUE(s.deform());
  passes.begin_frame();
  passes.refine(s.deformer, s.island.grasp, sweeps(8));
  FramePasses fresh;
  fresh.refine(s.deformer, s.island.grasp, sweeps(8));
  EXPECT_EQ(passes.beyond(), fresh.beyond());
  for (index_t u = 0; u < s.deformer.size(); ++u)
    ASSERT_TRUE(bit_equal(passes.displacement(s.deformer, u), fresh.displacement(s.deformer, u)));
}
