#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/passes/relaxation.h"
#include "geoshaping/scenes/sample_scenes.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{
using Mesh = geoshaping::testing::Mesh;

struct Frame
{
  ChainMailDeformer deformer;
  LinkMesh links;
  index_t grasp = -1;
};

void deform(Frame& f, const double* xyz, index_t n, const Adjacency& adjacency,
  const std::vector<float>& malleability, index_t grasp, const Eigen::Vector3d& pull,
  ValidRegionFrame frame = ValidRegionFrame::axes, const std::uint8_t* pins = nullptr)
{
  f.deformer.set_mesh(xyz, n, adjacency);
  f.deformer.set_malleability(malleability.data());
  f.deformer.set_valid_region_frame(frame);
  f.deformer.set_pinned(pins);
  ASSERT_TRUE(f.deformer.deform(grasp, pull).ok);
  f.links = link_mesh(f.deformer);
  f.grasp = grasp;
}

// The energy the relaxation lowers (relaxation.h), with the tether over every vertex:
// the fixed ones add a constant.
double energy(const LinkMesh& m, const Displacements& u)
{
  double e = 0.0;
  const Adjacency& adj = *m.adjacency;
  for (index_t v = 0; v < adj.size(); ++v)
  {
    e += rest_tether * u[v].squaredNorm();
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      if (*n < v)
        e += (u[v] - u[*n]).squaredNorm();
  }
  return e;
}

// The soft vertices displaced by the frame or by its relaxation (the region the
// smoothness is measured over, the same before and after).
std::vector<index_t> displaced_soft(const Frame& f, const Relaxer& r)
{
  std::vector<index_t> soft;
  for (const std::vector<index_t>* list : { &f.deformer.moved(), &r.changed() })
    for (index_t v : *list)
      if (!f.links.rigid[std::size_t(v)] && std::find(soft.begin(), soft.end(), v) == soft.end())
        soft.push_back(v);
  return soft;
}

std::vector<Eigen::Vector3d> rest_of(const SampleMesh& m)
{
  std::vector<Eigen::Vector3d> p(std::size_t(m.num_points()));
  for (index_t v = 0; v < m.num_points(); ++v)
    p[v] = Eigen::Vector3d(m.xyz.data() + 3 * v);
  return p;
}

// Figure 5D: the painted fault step, grasped mid-step and lifted 10 (FIFO Priority).
struct FaultStep
{
  SampleMesh mesh;
  Adjacency adjacency;
  Frame frame;
};

void lifted_fault_step(FaultStep& s, bool slab, ValidRegionFrame frame = ValidRegionFrame::axes)
{
  const FaultStepParams p;
  s.mesh = slab ? fault_step_slab(p) : fault_step_horizon(p);
  s.adjacency = s.mesh.adjacency();
  const std::vector<float> m = fault_step_malleability(s.mesh, p);
  index_t grasp = 0;
  const Eigen::Vector3d target(50.0, 30.0, 10.0);
  for (index_t v = 0; v < s.mesh.num_points(); ++v)
    if ((Eigen::Vector3d(s.mesh.xyz.data() + 3 * v) - target).norm() <
        (Eigen::Vector3d(s.mesh.xyz.data() + 3 * grasp) - target).norm())
      grasp = v;
  deform(s.frame, s.mesh.xyz.data(), s.mesh.num_points(), s.adjacency, m, grasp,
    Eigen::Vector3d(0.0, 0.0, 10.0), frame);
}

// The rule of relaxation.h on every directed link with an end in `region`: a satisfied
// link stays exactly satisfied, a violated one ends no further than max(before, budget),
// the budget being the start's largest link distance there.
void expect_link_rule(const LinkMesh& m, const Displacements& before, const Displacements& after,
  const std::vector<index_t>& region)
{
  const Adjacency& adj = *m.adjacency;
  double budget = 0.0;
  for (index_t v : region)
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      budget =
        std::max({ budget, link_distance(m, before, v, *n), link_distance(m, before, *n, v) });
  std::size_t satisfied = 0;
  for (index_t v : region)
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      for (const auto& [c, s] : { std::pair{ v, *n }, std::pair{ *n, v } })
      {
        const double b = link_distance(m, before, c, s);
        const double a = link_distance(m, after, c, s);
        if (b == 0.0)
        {
          ASSERT_EQ(a, 0.0) << "satisfied link " << c << " -> " << s;
          ++satisfied;
        }
        else
        {
          ASSERT_LE(a, std::max(b, budget)) << "violated link " << c << " -> " << s;
        }
      }
  EXPECT_GT(satisfied, 0u);
}
} // namespace

TEST(Relaxation, ZeroIterationsLeaveTheStartExactly)
{
  const auto scene = geoshaping::testing::rigid_island();
  Frame f;
  deform(f, scene.mesh.xyz.data(), scene.mesh.size(), scene.mesh.adjacency, scene.malleability,
    scene.grasp, Eigen::Vector3d(scene.pull));
  Relaxer r(f.links);
  const RelaxationReport report = relax_frame(r, f.deformer, f.grasp, 0);
  EXPECT_EQ(report.iterations, 0);
  EXPECT_TRUE(r.changed().empty());
  EXPECT_EQ(r.displacements(), displacements(f.deformer));
}

TEST(Relaxation, InPlanePullOfAPlaneStaysInThePlane)
{
  const Mesh m = geoshaping::testing::triangle_grid(21, 21, 1.0);
  Frame f;
  deform(f, m.xyz.data(), m.size(), m.adjacency, std::vector<float>(std::size_t(m.size()), 0.7f),
    grid_id(21, 10, 10), Eigen::Vector3d(3.0, 2.0, 0.0));
  Relaxer r(f.links);
  relax_frame(r, f.deformer, f.grasp, 20);
  ASSERT_FALSE(r.changed().empty());
  for (index_t v = 0; v < m.size(); ++v)
    EXPECT_EQ(r.displacement(v).z(), 0.0);
}

TEST(Relaxation, GraspPinsAndRigidIslandStayBitForBit)
{
  const auto scene = geoshaping::testing::rigid_island();
  const index_t n = 31;
  std::vector<std::uint8_t> pins(std::size_t(scene.mesh.size()), 0);
  for (index_t i = 10; i < 21; ++i)
    pins[grid_id(n, i, 6)] = 1;
  for (ValidRegionFrame frame : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    Frame f;
    deform(f, scene.mesh.xyz.data(), scene.mesh.size(), scene.mesh.adjacency, scene.malleability,
      scene.grasp, Eigen::Vector3d(scene.pull), frame, pins.data());
    const Displacements before = displacements(f.deformer);
    Relaxer r(f.links);
    relax_frame(r, f.deformer, f.grasp, 30);
    ASSERT_FALSE(r.changed().empty());
    std::size_t rigid_moved = 0;
    for (index_t v = 0; v < scene.mesh.size(); ++v)
      if (v == f.grasp || pins[v] || scene.malleability[v] == 0.0f)
      {
        EXPECT_EQ(r.displacement(v), before[v]) << v;
        rigid_moved += scene.malleability[v] == 0.0f && !before[v].isZero(0.0);
      }
    EXPECT_GT(rigid_moved, 0u); // the island was carried, and stays as carried
    EXPECT_EQ(rigid_error(f.links, r.displacements()), 0.0);
    for (index_t v : r.changed()) // the region grows only over resting soft vertices
      EXPECT_TRUE(f.deformer.moved_this_frame(v) ||
                  (before[v].isZero(0.0) && !pins[v] && scene.malleability[v] > 0.0f));
  }
}

TEST(Relaxation, SatisfiedLinksStaySatisfiedAndNeitherELinkNorTheEnergyGrows)
{
  FaultStep tri, slab, link;
  lifted_fault_step(tri, false);
  lifted_fault_step(slab, true);
  lifted_fault_step(link, false, ValidRegionFrame::link);
  for (const FaultStep* s : { &tri, &slab, &link })
  {
    const Frame& f = s->frame;
    const Displacements before = displacements(f.deformer);
    Relaxer r(f.links);
    const RelaxationReport report = relax_frame(r, f.deformer, f.grasp, 10);
    EXPECT_EQ(report.iterations, 10);
    ASSERT_FALSE(r.changed().empty());
    std::vector<index_t> region = f.deformer.moved();
    region.insert(region.end(), r.changed().begin(), r.changed().end());
    expect_link_rule(f.links, before, r.displacements(), region);
    EXPECT_LE(link_error(f.links, r.displacements(), region), link_error(f.links, before, region));
    EXPECT_LT(energy(f.links, r.displacements()), energy(f.links, before));
  }
}

TEST(Relaxation, EnergyNeverGrowsFromOneSweepToTheNext)
{
  FaultStep s;
  lifted_fault_step(s, true);
  const Frame& f = s.frame;
  Relaxer r(f.links);
  double previous = energy(f.links, displacements(f.deformer));
  for (int sweeps = 1; sweeps <= 6; ++sweeps)
  {
    relax_frame(r, f.deformer, f.grasp, sweeps);
    const double e = energy(f.links, r.displacements());
    EXPECT_LE(e, previous) << sweeps;
    previous = e;
  }
}

TEST(Relaxation, FaultStepBendsLess)
{
  FaultStep s;
  lifted_fault_step(s, false);
  const Frame& f = s.frame;
  const std::vector<Eigen::Vector3d> rest = rest_of(s.mesh);
  Relaxer r(f.links);
  relax_frame(r, f.deformer, f.grasp, 100);
  const std::vector<index_t> soft = displaced_soft(f, r);
  const BendingError before =
    bending_error(rest, s.mesh.connectivity, displacements(f.deformer), soft);
  const BendingError after = bending_error(rest, s.mesh.connectivity, r.displacements(), soft);
  std::printf("bending over %zu edges: max %.4f -> %.4f rad, rms %.4f -> %.4f rad\n", after.edges,
    before.max, after.max, before.rms, after.rms);
  // Measured: max 1.73 -> 1.19, rms 0.133 -> 0.096; what is left is mostly the cliff
  // along the grasp's row, links ChainMail left violated by ~6 edge lengths.
  EXPECT_LT(after.rms, 0.8 * before.rms);
  EXPECT_LT(after.max, 0.8 * before.max);
}

TEST(Relaxation, WorkFollowsTheDisplacedRegionNotTheMesh)
{
  RelaxationReport reports[2];
  const index_t sizes[2] = { 101, 201 };
  for (int k = 0; k < 2; ++k)
  {
    const index_t n = sizes[k];
    const Mesh m = geoshaping::testing::triangle_grid(n, n, 1.0);
    Frame f;
    deform(f, m.xyz.data(), m.size(), m.adjacency, std::vector<float>(std::size_t(m.size()), 0.5f),
      grid_id(n, n / 2, n / 2), Eigen::Vector3d(1.0, 2.0, 6.0));
    for (index_t v : f.deformer.moved())
    {
      const index_t i = v % n, j = v / n;
      ASSERT_TRUE(i > 0 && j > 0 && i < n - 1 && j < n - 1); // the region stays inside
    }
    Relaxer r(f.links);
    reports[k] = relax_frame(r, f.deformer, f.grasp, 8);
    for (index_t v : r.changed())
    {
      const index_t i = v % n, j = v / n;
      ASSERT_TRUE(i > 0 && j > 0 && i < n - 1 && j < n - 1); // the grown region too
    }
  }
  EXPECT_GT(reports[0].updates, 0u);
  EXPECT_EQ(reports[0].updates, reports[1].updates);
  EXPECT_EQ(reports[0].link_checks, reports[1].link_checks);
  EXPECT_EQ(reports[0].free, reports[1].free);
}

TEST(Relaxation, RepeatedCallsResetOnlyWhatTheyTouched)
{
  const auto scene = geoshaping::testing::rigid_island();
  Frame f;
  deform(f, scene.mesh.xyz.data(), scene.mesh.size(), scene.mesh.adjacency, scene.malleability,
    scene.grasp, Eigen::Vector3d(scene.pull));
  Relaxer once(f.links), twice(f.links);
  relax_frame(twice, f.deformer, f.grasp, 5);
  ASSERT_TRUE(f.deformer.deform(scene.grasp, Eigen::Vector3d(-2.0, 1.0, 4.0)).ok);
  relax_frame(once, f.deformer, f.grasp, 5);
  relax_frame(twice, f.deformer, f.grasp, 5);
  EXPECT_EQ(once.displacements(), twice.displacements());
  EXPECT_EQ(once.changed(), twice.changed());
}
