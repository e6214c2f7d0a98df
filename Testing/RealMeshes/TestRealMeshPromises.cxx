// The other promises of the docs and the panel, checked on the real meshes (issue 36
// item 3; the meshes and their painted scene: real_meshes.h) as their synthetic tests
// check them on generated scenes:
// - rigid regions are exact: a region of malleability 0 translates as one, E_rigid == 0
//   bit for bit, under FIFO Priority, Priority and Max Violation (docs/error-metrics.md;
//   FIFO ripples through them, Figure 6), over a drag, a commit and a second pull;
// - the envelope refinement (Axes) leaves every link satisfied (E_link <= its 1e-9
//   tolerance), the grasp where the frame put it, and rigid regions translated
//   (docs/error-metrics.md, "the envelope");
// - an obstacle is never crossed: a copy of the mesh a few edges above it, pulled into,
//   stops every vertex's straight path from rest at it, in the frame and after the
//   refinement (docs/obstacles.md), crossings computed here with the tests' own code;
// - Figure 8's order: equal malleability dragged in small steps gives E_temporal 1 (no
//   vertex moves further than the grasp) under FIFO and FIFO Priority in the Axes region
//   on surfaces (docs/report.md); where it is above 1 (the Link region, a slab), only
//   because a vertex took another sponsor (docs/deformer.md, "Figure 8 on real meshes").
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/metrics/error_metrics.h"
#include "geoshaping/passes/frame_passes.h"
#include "real_meshes.h"
#include "test_sheets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace geoshaping;
using geoshaping::testing::real_meshes;
using geoshaping::testing::real_scene;
using geoshaping::testing::RealMesh;

namespace
{

void start(ChainMailDeformer& d, const RealMesh& m, const std::vector<float>& malleability,
  QueueKind q, ValidRegionFrame f)
{
  d.set_mesh(m.xyz.data(), m.size(), m.adjacency);
  d.set_malleability(malleability.data());
  d.set_queue(q);
  d.set_valid_region_frame(f);
}

// The report's Figure 8 drag: the last quarter of the pull in 25 steps.
std::vector<Eigen::Vector3d> figure8_drag(const Eigen::Vector3d& pull)
{
  std::vector<Eigen::Vector3d> drags;
  for (int k = 0; k <= 25; ++k)
    drags.push_back((0.75 + 0.01 * k) * pull);
  return drags;
}

} // namespace

TEST(Promises, RigidRegionsTranslateExactlyOnRealMeshes)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    const auto s = real_scene(m, false);
    for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
      for (QueueKind q :
        { QueueKind::fifo_priority, QueueKind::priority, QueueKind::max_violation })
      {
        ChainMailDeformer d;
        start(d, m, s.malleability, q, f);
        double worst = 0.0;
        for (double k : { 0.4, 0.8, 1.2 })
        {
          ASSERT_TRUE(d.deform(s.grasp, k * s.pull).ok);
          worst = std::max(worst, rigid_error(link_mesh(d), displacements(d)));
        }
        d.commit();
        for (double k : { -0.3, -0.6 })
        {
          ASSERT_TRUE(d.deform(s.second, k * s.pull).ok);
          worst = std::max(worst, rigid_error(link_mesh(d), displacements(d)));
        }
        EXPECT_EQ(worst, 0.0) << m.name << " " << frame_name(f) << " " << queue_name(q);
      }
  }
}

TEST(Promises, TheEnvelopeLeavesEveryLinkSatisfiedOnRealMeshes)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    const auto s = real_scene(m, false);
    for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    {
      ChainMailDeformer d;
      start(d, m, s.malleability, q, ValidRegionFrame::axes);
      ASSERT_TRUE(d.deform(s.grasp, s.pull).ok);
      const LinkMesh links = link_mesh(d);
      const double before = link_error(links, displacements(d));
      FramePasses passes;
      ProjectionOptions options;
      options.solver = ProjectionSolver::envelope;
      const ProjectionReport report = passes.refine(d, s.grasp, options);
      Displacements u(std::size_t(m.size()), Eigen::Vector3d::Zero());
      for (index_t v = 0; v < m.size(); ++v)
        u[std::size_t(v)] = passes.displacement(d, v);
      EXPECT_GT(before, 1e-3) << m.name << ": the frame leaves links to refine";
      EXPECT_LE(link_error(links, u), 1e-9) << m.name << " " << queue_name(q);
      EXPECT_LE(report.violation, 1e-9) << m.name << " " << queue_name(q);
      EXPECT_EQ(u[std::size_t(s.grasp)], s.pull) << m.name;
      EXPECT_EQ(rigid_error(links, u), 0.0) << m.name << " " << queue_name(q);
    }
  }
}

TEST(Promises, AnObstacleAboveARealMeshIsNeverCrossed)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    if (m.triangles.empty())
      continue; // the slab: its surface is a copy of a fault's, tested there
    const auto s = real_scene(m, false);
    // The obstacle: the mesh itself, lifted 3 mean edge lengths along the pull's
    // direction, so the pull (12 edges) drives the grasp's neighbourhood through it.
    geoshaping::testing::Sheet lid;
    const Eigen::Vector3d lift = 3.0 * m.edge * s.pull.normalized();
    for (index_t v = 0; v < m.size(); ++v)
    {
      const Eigen::Vector3d p = m.point(v) + lift;
      lid.xyz.insert(lid.xyz.end(), { p.x(), p.y(), p.z() });
    }
    lid.tri = m.triangles;
    for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
      for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority, QueueKind::priority,
             QueueKind::max_violation })
      {
        ChainMailDeformer d;
        start(d, m, s.malleability, q, f);
        ASSERT_EQ(
          d.set_obstacles(lid.xyz.data(), lid.points(), lid.tri.data(), lid.triangles()), "");
        const FrameResult r = d.deform(s.grasp, s.pull);
        ASSERT_TRUE(r.ok);
        EXPECT_GT(r.blocked, 0u) << m.name << ": the pull reaches the obstacle";
        EXPECT_LT(r.grasp_fraction, 1.0) << m.name;
        int crossed = 0;
        for (index_t v : d.moved())
          crossed += geoshaping::testing::crosses_any(lid, m.point(v), d.position(v));
        EXPECT_EQ(crossed, 0) << m.name << " " << frame_name(f) << " " << queue_name(q);
      }
  }
}

// Figure 8's promise, in the Axes region where it is made (docs/report.md): equal
// malleability dragged in small steps moves no vertex further than the grasp under FIFO
// and FIFO Priority (E_temporal 1), while Priority's veins jump.
TEST(Promises, EqualMalleabilityDragsAsOneInTheAxesRegionOnRealSurfaces)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    if (m.triangles.empty())
      continue; // the slab: 1.012 (a sponsor switch, below; docs/deformer.md)
    const auto s = real_scene(m, true);
    for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority, QueueKind::priority })
    {
      ChainMailDeformer d;
      start(d, m, s.malleability, q, ValidRegionFrame::axes);
      const double e = temporal_error(d, s.grasp, figure8_drag(s.pull));
      if (q == QueueKind::priority)
        EXPECT_GT(e, 10.0) << m.name << ": Priority's veins jump";
      else
        EXPECT_LE(e, 1.0 + 1e-9) << m.name << " " << queue_name(q);
    }
  }
}

// Why E_temporal exceeds 1 where it does (the Link region on every real mesh, a slab):
// the valid region is convex and placed at the sponsor, so the move it asks of a vertex
// is u_s + (P - I)(-u_s) (P the projection onto the region around the sponsor's rest
// offset), and I - P is non-expansive: a vertex that keeps its sponsor from one step of
// the drag to the next moves no further than its sponsor did. The jumps come only from a
// vertex taking another sponsor (whose move has nearly the same length but another
// direction: the longest move wins, docs/deformer.md) and from what it sponsors.
TEST(Promises, AVertexThatKeepsItsSponsorMovesNoFurtherThanItsSponsor)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    const auto s = real_scene(m, true);
    for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
      for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority, QueueKind::priority,
             QueueKind::max_violation })
      {
        ChainMailDeformer d;
        start(d, m, s.malleability, q, f);
        std::vector<Eigen::Vector3d> before;
        std::vector<index_t> sponsor_before;
        double worst = 0.0; // max over kept sponsors of |du_v| - |du_s|, / mean edge
        int kept = 0, switched = 0;
        for (const Eigen::Vector3d& drag : figure8_drag(s.pull))
        {
          ASSERT_TRUE(d.deform(s.grasp, drag).ok);
          std::vector<Eigen::Vector3d> now(std::size_t(m.size()), Eigen::Vector3d::Zero());
          std::vector<index_t> sponsor(std::size_t(m.size()), -1);
          for (index_t v : d.moved())
          {
            now[std::size_t(v)] = d.displacement(v);
            sponsor[std::size_t(v)] = d.sponsor(v);
          }
          if (!before.empty())
            for (index_t v : d.moved())
            {
              const index_t sp = sponsor[std::size_t(v)];
              if (sp < 0 || sponsor_before[std::size_t(v)] < 0)
                continue;
              if (sp != sponsor_before[std::size_t(v)])
              {
                ++switched;
                continue;
              }
              ++kept;
              const double dv = (now[std::size_t(v)] - before[std::size_t(v)]).norm();
              const double ds = (now[std::size_t(sp)] - before[std::size_t(sp)]).norm();
              worst = std::max(worst, (dv - ds) / m.edge);
            }
          before = std::move(now);
          sponsor_before = std::move(sponsor);
        }
        EXPECT_GT(kept, 0) << m.name;
        EXPECT_LE(worst, 1e-9) << m.name << " " << frame_name(f) << " " << queue_name(q) << ": "
                               << switched << " sponsor switches";
      }
  }
}
