// ValidRegionFrame::link: the cylinder of valid_region.h, its exact
// projection, rigid exactness, analytic chains and cones in any orientation, and
// rotation invariance of whole frames on a triangle horizon and a tetrahedral slab.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"
#include "geoshaping/metrics/error_metrics.h"
#include "geoshaping/scenes/sample_scenes.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <set>

using namespace geoshaping;
using geoshaping::testing::constant;
using geoshaping::testing::grid_id;

namespace
{

Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

std::vector<double> rotated(const std::vector<double>& xyz, const Eigen::Matrix3d& R)
{
  std::vector<double> out(xyz.size());
  for (std::size_t i = 0; i < xyz.size(); i += 3)
  {
    const Eigen::Vector3d p = R * Eigen::Vector3d(xyz[i], xyz[i + 1], xyz[i + 2]);
    out[i] = p.x();
    out[i + 1] = p.y();
    out[i + 2] = p.z();
  }
  return out;
}

ChainMailDeformer make(const std::vector<double>& xyz, const Adjacency& adj, ValidRegionFrame f)
{
  ChainMailDeformer d;
  d.set_mesh(xyz.data(), index_t(xyz.size() / 3), adj);
  d.set_valid_region_frame(f);
  return d;
}

// Whether w lies in the link region of (o, p) up to `tol` (the definition, not the code).
bool in_cylinder(
  const Eigen::Vector3d& o, const ChainMailParams& p, const Eigen::Vector3d& w, double tol)
{
  const double l = o.norm();
  const Eigen::Vector3d e = o / l;
  const Eigen::Vector3d d = o + w;
  const double a = d.dot(e);
  return a >= p.compression * l - tol && a <= p.stretch * l + tol &&
         (d - a * e).norm() <= p.shear * l + tol;
}
} // namespace

TEST(ValidRegionFrame, DefaultIsTheAxisAlignedBox)
{
  ChainMailDeformer d;
  EXPECT_EQ(d.valid_region_frame(), ValidRegionFrame::axes);
  EXPECT_STREQ(frame_name(ValidRegionFrame::axes), "Axes");
  EXPECT_STREQ(frame_name(ValidRegionFrame::link), "Link");
}

TEST(ValidRegionFrame, LinkProjectionIsTheExactEuclideanProjectionOntoTheCylinder)
{
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const Eigen::Vector3d o(3 * u(rng), 3 * u(rng), 3 * u(rng));
    ChainMailParams p{ 1.0 + unit(rng), unit(rng), unit(rng) };
    const Eigen::Vector3d w(4 * u(rng), 4 * u(rng), 4 * u(rng));
    const Eigen::Vector3d pw = link_displacement_projection(o, p, w);
    const double scale = o.norm() + w.norm();
    // In the region,
    ASSERT_TRUE(in_cylinder(o, p, pw, 1e-12 * scale)) << trial;
    if (in_cylinder(o, p, w, -1e-9 * scale)) // strictly inside: unchanged, bit for bit
    {
      ++inside;
      EXPECT_EQ(pw, w) << trial;
      continue;
    }
    ++outside;
    // and nearest: no point of the region is closer (random points of the cylinder,
    // and the variational inequality (w - pw).(q - pw) <= 0 of a convex projection).
    const double l = o.norm();
    const Eigen::Vector3d e = o / l;
    const Eigen::Vector3d b1 = e.unitOrthogonal(), b2 = e.cross(b1);
    for (int k = 0; k < 50; ++k)
    {
      const double a = (p.compression + (p.stretch - p.compression) * unit(rng)) * l;
      const double r = p.shear * l * std::sqrt(unit(rng)), phi = 6.283185307179586 * unit(rng);
      const Eigen::Vector3d q = a * e + r * (std::cos(phi) * b1 + std::sin(phi) * b2) - o;
      EXPECT_LE((w - pw).norm(), (w - q).norm() + 1e-12 * scale) << trial;
      EXPECT_LE((w - pw).dot(q - pw), 1e-9 * scale * scale) << trial;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(ValidRegionFrame, LinkRegionOfAnAxisLinkHasTheBoxIntervalAlongItAndItsHalfWidthAcross)
{
  const ChainMailParams p{ 1.7, 0.4, 0.3 };
  const Eigen::Vector3d o(0.0, -2.5, 0.0);
  const Box b = displacement_bounds(o, p);
  // Along y: the same interval [lo_y, hi_y].
  for (double wy : { -5.0, -1.0, 0.3, 1.5, 4.0 })
  {
    const Eigen::Vector3d w(0.0, wy, 0.0);
    EXPECT_DOUBLE_EQ(link_displacement_projection(o, p, w).y(), b.clamp(w).y()) << wy;
  }
  // Across, along one axis: the same half-width h |o|.
  for (double wx : { -3.0, -0.5, 0.5, 3.0 })
  {
    const Eigen::Vector3d w(wx, 0.0, 0.0);
    EXPECT_DOUBLE_EQ(link_displacement_projection(o, p, w).x(), b.clamp(w).x()) << wx;
  }
  // Diagonally across the box keeps its corner, the cylinder its disc.
  const Eigen::Vector3d w(3.0, 0.0, 3.0);
  EXPECT_NEAR(b.clamp(w).norm(), std::sqrt(2.0) * 0.75, 1e-15);
  EXPECT_NEAR(link_displacement_projection(o, p, w).norm(), 0.75, 1e-15);
}

TEST(ValidRegionFrame, RigidLinkProjectsToExactlyZero)
{
  const ChainMailParams rigid{ 1.0, 1.0, 0.0 };
  const Eigen::Vector3d o(0.1, 0.7, -0.3), w(1e-3, -2.0, 0.25);
  EXPECT_TRUE(link_displacement_projection(o, rigid, w).isZero(0.0));
  // A zero-length link likewise, whatever the parameters.
  EXPECT_TRUE(
    link_displacement_projection(Eigen::Vector3d::Zero(), { 2.0, 0.5, 0.5 }, w).isZero(0.0));
  // required_displacement returns the sponsor's displacement itself.
  const Eigen::Vector3d su(0.1, 0.2, 0.30000000000000004);
  EXPECT_EQ(required_displacement(ValidRegionFrame::link, o, rigid, su), su);
}

TEST(ValidRegionFrame, LinkRigidRegionsTranslateBitExactlyOnARotatedGrid)
{
  std::mt19937 rng(7);
  const auto mesh = geoshaping::testing::triangle_grid(30, 20, 0.37);
  const std::vector<double> xyz = rotated(mesh.xyz, random_rotation(rng));
  ChainMailDeformer d = make(xyz, mesh.adjacency, ValidRegionFrame::link);
  d.set_uniform_malleability(0.0);
  const Eigen::Vector3d delta(0.3, -1.7, 2.25);
  ASSERT_TRUE(d.deform(123, delta).ok);
  EXPECT_EQ(d.moved().size(), std::size_t(mesh.size()));
  for (index_t v = 0; v < d.size(); ++v)
    EXPECT_EQ(d.displacement(v), delta) << v; // bit-exact

  // A rigid island in a soft grid (Figure 6) keeps every rigid-rigid edge bit-exact.
  const auto scene = geoshaping::testing::rigid_island();
  const std::vector<double> xyz2 = rotated(scene.mesh.xyz, random_rotation(rng));
  ChainMailDeformer island = make(xyz2, scene.mesh.adjacency, ValidRegionFrame::link);
  island.set_malleability(scene.malleability.data());
  ASSERT_TRUE(island.deform(scene.grasp, Eigen::Vector3d(scene.pull)).ok);
  std::size_t rigid_moved = 0;
  for (index_t v = 0; v < island.size(); ++v)
    if (island.malleability(v) == 0.0f && island.moved_this_frame(v))
    {
      ++rigid_moved;
      const index_t s = island.sponsor(v);
      if (island.malleability(s) == 0.0f)
        EXPECT_EQ(island.displacement(v), island.displacement(s)) << v;
    }
  EXPECT_EQ(rigid_moved, 49u); // the whole 7 x 7 island moved
}

TEST(ValidRegionFrame, LinkStretchedChainAbsorbsOneUnitPerLinkInAnyDirection)
{
  // The axes test StretchedChainAbsorbsOneUnitPerLink, with the chain along x and then
  // along a random direction n: the end pulled by 8 n moves vertex i by
  // max(0, 8 - (19 - i)) n, the box's answer for the chain along x.
  std::mt19937 rng(3);
  const auto mesh = geoshaping::testing::chain(20, 10.0);
  for (int turn = 0; turn < 4; ++turn)
  {
    const Eigen::Matrix3d R = turn == 0 ? Eigen::Matrix3d::Identity() : random_rotation(rng);
    const Eigen::Vector3d n = R.col(0);
    ChainMailDeformer d = make(rotated(mesh.xyz, R), mesh.adjacency, ValidRegionFrame::link);
    d.set_transfer_function(constant(1.1, 1.0, 0.0));
    ASSERT_TRUE(d.deform(19, 8.0 * n).ok);
    EXPECT_EQ(d.moved().size(), 8u);
    for (index_t i = 0; i < 20; ++i)
    {
      const double expected = std::max(0.0, 8.0 - (19 - i));
      EXPECT_LE((d.displacement(i) - expected * n).norm(), 1e-12) << turn << " vertex " << i;
    }
    // Pushed inward, the incompressible chain moves as one.
    ASSERT_TRUE(d.deform(19, -8.0 * n).ok);
    EXPECT_EQ(d.moved().size(), 20u);
    for (index_t i = 0; i < 20; ++i)
      EXPECT_LE((d.displacement(i) + 8.0 * n).norm(), 1e-12) << turn << " vertex " << i;
  }
}

TEST(ValidRegionFrame, LinkChainPulledSidewaysAbsorbsShearTimesLengthPerLinkInAnyDirection)
{
  // Chain along x, spacing L, shear h; the end pulled by D m with m across the chain:
  // each link slides h L, so u_i = max(0, D - h L (19 - i)) m whatever the direction m
  // in the y-z plane. The box agrees only for m along an axis (it allows h L per axis,
  // sqrt(2) h L diagonally).
  const double L = 2.0, D = 7.0, h = 0.25;
  const auto mesh = geoshaping::testing::chain(20, L);
  for (double angle : { 0.0, 0.3, 0.7853981633974483, 2.0 })
  {
    const Eigen::Vector3d m(0.0, std::cos(angle), std::sin(angle));
    for (ValidRegionFrame f : { ValidRegionFrame::link, ValidRegionFrame::axes })
    {
      ChainMailDeformer d = make(mesh.xyz, mesh.adjacency, f);
      d.set_transfer_function(constant(1.5, 0.5, h));
      ASSERT_TRUE(d.deform(19, D * m).ok);
      double worst = 0.0;
      for (index_t i = 0; i < 20; ++i)
        worst =
          std::max(worst, (d.displacement(i) - std::max(0.0, D - h * L * (19 - i)) * m).norm());
      if (f == ValidRegionFrame::link || angle == 0.0)
        EXPECT_LE(worst, 1e-12) << frame_name(f) << " angle " << angle;
      else if (angle == 0.7853981633974483)
        EXPECT_GT(worst, 0.1) << "the box slides sqrt(2) h L diagonally";
    }
  }
}

TEST(ValidRegionFrame, LinkQuadGridPulledAcrossFollowsTheShearConeInAnyOrientation)
{
  // The axes test QuadGridPulledAtCentreFollowsShearCone on the grid turned by a random
  // rotation R and pulled by D along the turned normal R z: each link (length L) absorbs
  // h L of the pull across it, so u(i, j) = max(0, D - h L (|i - ic| + |j - jc|)) R z,
  // exactly the box's answer on the unturned grid.
  const double L = 2.0, D = 9.0, h = 0.5;
  const index_t n = 21, c = 10;
  const auto mesh = geoshaping::testing::quad_grid(n, n, L);
  std::mt19937 rng(11);
  for (int turn = 0; turn < 3; ++turn)
  {
    const Eigen::Matrix3d R = turn == 0 ? Eigen::Matrix3d::Identity() : random_rotation(rng);
    const Eigen::Vector3d z = R.col(2);
    for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    {
      ChainMailDeformer d = make(rotated(mesh.xyz, R), mesh.adjacency, ValidRegionFrame::link);
      d.set_transfer_function(constant(1.5, 0.5, h));
      d.set_queue(q);
      ASSERT_TRUE(d.deform(grid_id(n, c, c), D * z).ok);
      for (index_t j = 0; j < n; ++j)
        for (index_t i = 0; i < n; ++i)
        {
          const double r = std::abs(i - c) + std::abs(j - c);
          const Eigen::Vector3d u = d.displacement(grid_id(n, i, j));
          EXPECT_LE((u - std::max(0.0, D - h * L * r) * z).norm(), 1e-12)
            << turn << " " << i << "," << j;
        }
    }
  }
}

namespace
{
struct RotationCase
{
  std::vector<double> xyz;
  Adjacency adjacency;
  std::vector<float> malleability;
  index_t grasp;
  Eigen::Vector3d pull;
};

// Largest |R x(mesh) - x(R mesh)| over the vertices, relative to the mesh's bounding
// box diagonal, after one frame of `f` under queue `q`; `same_moved` tells whether both
// frames moved the same vertices.
double rotation_defect(const RotationCase& s, const Eigen::Matrix3d& R, ValidRegionFrame f,
  QueueKind q, bool& same_moved)
{
  ChainMailDeformer a = make(s.xyz, s.adjacency, f), b = make(rotated(s.xyz, R), s.adjacency, f);
  for (ChainMailDeformer* d : { &a, &b })
  {
    d->set_malleability(s.malleability.data());
    d->set_queue(q);
  }
  EXPECT_TRUE(a.deform(s.grasp, s.pull).ok);
  EXPECT_TRUE(b.deform(s.grasp, R * s.pull).ok);
  EXPECT_GT(a.moved().size(), 100u);
  same_moved = std::set<index_t>(a.moved().begin(), a.moved().end()) ==
               std::set<index_t>(b.moved().begin(), b.moved().end());
  Eigen::Vector3d lo = a.position(0), hi = lo;
  double worst = 0.0;
  for (index_t v = 0; v < a.size(); ++v)
  {
    lo = lo.cwiseMin(a.position(v));
    hi = hi.cwiseMax(a.position(v));
    worst = std::max(worst, (R * a.position(v) - b.position(v)).norm());
  }
  return worst / (hi - lo).norm();
}

FaultStepParams small_step()
{
  FaultStepParams p;
  p.length = 40;
  p.width = 20;
  p.throw_height = 8;
  p.step_run = 3;
  p.spacing = 1.0;
  p.thickness = 3;
  p.layers = 3;
  return p;
}

RotationCase scene_case(const SampleMesh& mesh, const FaultStepParams& p)
{
  RotationCase s;
  s.xyz = mesh.xyz;
  s.adjacency = mesh.adjacency();
  s.malleability = fault_step_malleability(mesh, p, 4.0);
  // Soften the uniform parts unevenly so several malleability ranks are in play.
  for (std::size_t v = 0; v < s.malleability.size(); ++v)
    if (s.malleability[v] == 1.0f)
      s.malleability[v] = 0.6f + 0.4f * float((v * 7919) % 11) / 10.0f;
  // Grasp a vertex on the upper flat, a third along, and pull it up, sideways and out.
  const index_t nu = fault_step_columns(p);
  const index_t nv = fault_step_horizon(p).num_points() / nu;
  s.grasp = (nv / 2) * nu + nu / 3;
  s.pull = Eigen::Vector3d(2.5, -3.0, 7.0);
  return s;
}
} // namespace

TEST(ValidRegionFrame, LinkFrameRotatesWithTheMeshOnATriangleHorizonAndATetrahedralSlab)
{
  const FaultStepParams p = small_step();
  const RotationCase triangles = scene_case(fault_step_horizon(p), p);
  const RotationCase tetrahedra = scene_case(fault_step_slab(p), p);
  std::mt19937 rng(2026);
  for (int turn = 0; turn < 3; ++turn)
  {
    const Eigen::Matrix3d R = random_rotation(rng);
    for (const RotationCase* s : { &triangles, &tetrahedra })
    {
      const char* name = s == &triangles ? "triangles" : "tetrahedra";
      for (QueueKind q : { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority,
             QueueKind::max_violation })
      {
        bool same = false;
        EXPECT_LE(rotation_defect(*s, R, ValidRegionFrame::link, q, same), 1e-9)
          << name << " " << queue_name(q) << " turn " << turn;
        EXPECT_TRUE(same) << name << " " << queue_name(q) << " turn " << turn;
      }
      // The box is not rotation invariant: the same check fails by far.
      bool same = false;
      EXPECT_GT(
        rotation_defect(*s, R, ValidRegionFrame::axes, QueueKind::fifo_priority, same), 1e-3)
        << name << " turn " << turn;
    }
  }
}

TEST(ValidRegionFrame, LinkFrameMovesEachVertexOnceIntoItsSponsorsCylinder)
{
  const FaultStepParams p = small_step();
  const RotationCase s = scene_case(fault_step_slab(p), p);
  for (QueueKind q :
    { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority, QueueKind::max_violation })
  {
    ChainMailDeformer d = make(s.xyz, s.adjacency, ValidRegionFrame::link);
    d.set_malleability(s.malleability.data());
    d.set_queue(q);
    ASSERT_TRUE(d.deform(s.grasp, s.pull).ok);
    std::set<index_t> seen(d.moved().begin(), d.moved().end());
    EXPECT_EQ(seen.size(), d.moved().size()) << queue_name(q);
    for (index_t v : d.moved())
    {
      const index_t sp = d.sponsor(v);
      if (sp < 0)
        continue;
      const Eigen::Vector3d o = d.rest_local(v) - d.rest_local(sp);
      const Eigen::Vector3d w = d.displacement(v) - d.displacement(sp);
      EXPECT_LE(region_distance(ValidRegionFrame::link, o, d.params(v), w), 1e-12)
        << queue_name(q) << " vertex " << v;
      // On the cylinder's surface (it moved: its rest position was outside).
      EXPECT_GT(region_distance(ValidRegionFrame::link, o, d.params(v), -d.displacement(sp)), 0.0);
    }
    // The error metrics measure against the deformer's frame. Its sponsor links hold in
    // the Link region and in the box too: the cylinder lies inside the box
    // (valid_region.h). An Axes region's result leaves the cylinders.
    LinkMesh lm = link_mesh(d);
    ASSERT_EQ(lm.frame, ValidRegionFrame::link);
    auto sponsor_links = [](const ChainMailDeformer& def, const LinkMesh& mesh)
    {
      const Displacements u = displacements(def);
      double e = 0.0;
      for (index_t v : def.moved())
        if (def.sponsor(v) >= 0)
          e = std::max(e, link_distance(mesh, u, v, def.sponsor(v)));
      return e;
    };
    EXPECT_LE(sponsor_links(d, lm), 1e-12) << queue_name(q);
    lm.frame = ValidRegionFrame::axes;
    EXPECT_LE(sponsor_links(d, lm), 1e-12) << queue_name(q);
    ChainMailDeformer axes = make(s.xyz, s.adjacency, ValidRegionFrame::axes);
    axes.set_malleability(s.malleability.data());
    axes.set_queue(q);
    ASSERT_TRUE(axes.deform(s.grasp, s.pull).ok);
    EXPECT_LE(sponsor_links(axes, lm), 1e-12) << queue_name(q);
    lm.frame = ValidRegionFrame::link;
    EXPECT_GT(sponsor_links(axes, lm), 0.1) << queue_name(q);
  }
}

TEST(ValidRegionFrame, LinkFrameDiffersFromAxesOnlyWhereLinksLeaveTheAxes)
{
  // On a straight chain along x the two frames agree bit for bit for a pull along x.
  const auto chain = geoshaping::testing::chain(30, 1.5);
  ChainMailDeformer a = make(chain.xyz, chain.adjacency, ValidRegionFrame::axes);
  ChainMailDeformer l = make(chain.xyz, chain.adjacency, ValidRegionFrame::link);
  for (ChainMailDeformer* d : { &a, &l })
    ASSERT_TRUE(d->deform(29, { 9.0, 0.0, 0.0 }).ok);
  ASSERT_EQ(a.moved(), l.moved());
  for (index_t v = 0; v < a.size(); ++v)
    EXPECT_EQ(a.displacement(v), l.displacement(v)) << v;
  // On a triangle grid (diagonal links) they differ.
  const auto grid = geoshaping::testing::triangle_grid(21, 21, 1.0);
  ChainMailDeformer ga = make(grid.xyz, grid.adjacency, ValidRegionFrame::axes);
  ChainMailDeformer gl = make(grid.xyz, grid.adjacency, ValidRegionFrame::link);
  for (ChainMailDeformer* d : { &ga, &gl })
    ASSERT_TRUE(d->deform(grid_id(21, 10, 10), { 0.0, 0.0, 3.0 }).ok);
  double most = 0.0;
  for (index_t v = 0; v < ga.size(); ++v)
    most = std::max(most, (ga.displacement(v) - gl.displacement(v)).norm());
  EXPECT_GT(most, 0.1);
  // Default malleability 0.5: h = 0.25. A diagonal link o = (1, 1, 0) slides 0.5 vertically
  // in the box (h (|o_x| + |o_y|)), h |o| = 0.354 in the cylinder: the cylinder's pull
  // spreads farther along the diagonals.
  EXPECT_GT(gl.moved().size(), ga.moved().size());
}
