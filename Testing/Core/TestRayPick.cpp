#include "geoshaping/mesh/ray_pick.h"

#include <gtest/gtest.h>

using geoshaping::RayHit;

namespace
{
// Two stacked unit quads (z = 0 and z = 2) over [0, 1]^2 and a triangle at z = 1.
const std::vector<double> xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, //
  0, 0, 2, 1, 0, 2, 1, 1, 2, 0, 1, 2,                                 //
  0, 0, 1, 1, 0, 1, 0, 1, 1 };
const std::vector<std::int64_t> offsets = { 0, 4, 8, 11 };
const std::vector<geoshaping::index_t> vertices = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
}

TEST(RayPick, NearestPolygonAlongTheRayWithItsNormalAndNearestVertex)
{
  // From above, straight down through (0.8, 0.7): the top quad at t = 3 (z = 2).
  const RayHit h =
    geoshaping::ray_pick(xyz.data(), offsets, vertices, { 0.8, 0.7, 5 }, { 0, 0, -1 }, 1);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t, 3.0);
  EXPECT_EQ(h.point, Eigen::Vector3d(0.8, 0.7, 2));
  EXPECT_EQ(h.normal, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(h.point_id, 6); // (1, 1, 2) is the nearest corner of the triangle met
  EXPECT_EQ(h.rank, 1);
  // Through x + y < 1 from z = 1.5: the triangle at z = 1; from below, the bottom quad,
  // at t measured on an unnormalized direction.
  const RayHit g =
    geoshaping::ray_pick(xyz.data(), offsets, vertices, { 0.2, 0.3, 1.5 }, { 0, 0, -1 }, 0);
  ASSERT_TRUE(g.hit);
  EXPECT_EQ(g.point.z(), 1.0);
  EXPECT_EQ(g.point_id, 8);
  const RayHit b =
    geoshaping::ray_pick(xyz.data(), offsets, vertices, { 0.2, 0.2, -1 }, { 0, 0, 2 }, 0);
  ASSERT_TRUE(b.hit);
  EXPECT_EQ(b.t, 0.5);
  EXPECT_EQ(b.point_id, 0);
  // Beside the quads, behind the origin, or with no direction: nothing.
  EXPECT_FALSE(
    geoshaping::ray_pick(xyz.data(), offsets, vertices, { 2, 2, 5 }, { 0, 0, -1 }, 0).hit);
  EXPECT_FALSE(
    geoshaping::ray_pick(xyz.data(), offsets, vertices, { 0.5, 0.5, 5 }, { 0, 0, 1 }, 0).hit);
  EXPECT_FALSE(
    geoshaping::ray_pick(xyz.data(), offsets, vertices, { 0.5, 0.5, 5 }, { 0, 0, 0 }, 0).hit);
}

TEST(RayPick, ReductionTakesTheNearestThenTheLowerRankAndSurvivesPacking)
{
  RayHit none, far, near0, near1;
  far.hit = near0.hit = near1.hit = true;
  far.t = 2.0;
  near0.t = near1.t = 1.0;
  near0.rank = 0;
  near1.rank = 1;
  none.rank = 0;
  far.rank = 1;
  EXPECT_EQ(&geoshaping::nearer_hit(none, far), &far);
  EXPECT_EQ(&geoshaping::nearer_hit(far, none), &far);
  EXPECT_EQ(&geoshaping::nearer_hit(far, near1), &near1);
  EXPECT_EQ(&geoshaping::nearer_hit(near1, near0), &near0);
  EXPECT_EQ(&geoshaping::nearer_hit(near0, near1), &near0);
  near1.point = Eigen::Vector3d(0.1, -2.5, 1e300);
  near1.normal = Eigen::Vector3d(0, 0.6, 0.8);
  near1.point_id = (std::int64_t(1) << 53) - 1;
  double packed[geoshaping::ray_hit_doubles];
  geoshaping::pack_ray_hit(near1, packed);
  const RayHit back = geoshaping::unpack_ray_hit(packed);
  EXPECT_TRUE(back.hit);
  EXPECT_EQ(back.t, near1.t);
  EXPECT_EQ(back.point, near1.point);
  EXPECT_EQ(back.normal, near1.normal);
  EXPECT_EQ(back.point_id, near1.point_id);
  EXPECT_EQ(back.rank, 1);
}
