#include "geoshaping/haptics/contact_patch.h"
#include "geoshaping/haptics/force_model.h"

#include <gtest/gtest.h>

#include <random>

using namespace geoshaping::haptics;

namespace
{
const Clock::time_point now = Clock::time_point(std::chrono::hours(1));

// A 20 cm square sheet in z = 0, two triangles, counter-clockwise seen from -z (so its
// stored free side is DOWN).
std::vector<Eigen::Vector3d> sheet_facing_down()
{
  const Eigen::Vector3d a(-0.1, -0.1, 0), b(0.1, -0.1, 0), c(0.1, 0.1, 0), d(-0.1, 0.1, 0);
  return { a, c, b, a, d, c };
}

Eigen::Vector3d normal(const std::vector<Eigen::Vector3d>& t, std::size_t i)
{
  return (t[3 * i + 1] - t[3 * i]).cross(t[3 * i + 2] - t[3 * i]).normalized();
}

ForceResult touch(const std::vector<Eigen::Vector3d>& triangles, const Eigen::Vector3d& x)
{
  SceneSnapshot scene;
  scene.stamp = now;
  scene.contact_triangles = triangles;
  ForceInput in;
  in.position = x;
  in.now = now;
  return compute_force(in, scene, ForceParams(), DeviceLimits());
}
} // namespace

TEST(ContactPatch, OrientTowardTurnsEveryTriangleToFaceTheFreePoint)
{
  auto t = sheet_facing_down();
  orient_toward(t, { 0.02, 0.01, 0.05 });
  EXPECT_EQ(normal(t, 0), Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(normal(t, 1), Eigen::Vector3d(0, 0, 1));
  orient_toward(t, { 0.0, 0.0, -0.01 });
  EXPECT_EQ(normal(t, 0), Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(normal(t, 1), Eigen::Vector3d(0, 0, -1));
  // The vertices are the same ones, only their order changed.
  auto u = sheet_facing_down();
  for (std::size_t i = 0; i < 2; ++i)
  {
    EXPECT_EQ(t[3 * i], u[3 * i]);
  }
}

TEST(ContactPatch, AStylusJustBelowTheSheetIsPushedBackTheWayItCame)
{
  // Stored facing down, the sheet would push a stylus 2 mm under it (seen from above)
  // further down; oriented toward where the stylus came from (above), it pushes it up.
  auto t = sheet_facing_down();
  const Eigen::Vector3d inside(0.01, 0.01, -0.002);
  EXPECT_FALSE(touch(t, inside).in_contact); // seen from below the stylus is outside
  orient_toward(t, { 0.01, 0.01, 0.03 });
  const ForceResult f = touch(t, inside);
  EXPECT_TRUE(f.in_contact);
  EXPECT_NEAR(f.force.z(), ForceParams().contact_stiffness * 0.002, 1e-9);
  EXPECT_NEAR(f.force.head<2>().norm(), 0.0, 1e-12);
}

TEST(ContactPatch, FreeSideIsTheLastPositionOutOfContactWithThePreviousPatch)
{
  // The stylus comes down onto the sheet, 2 and 4 mm into it, then through it (10 mm).
  const double shell = ForceParams().contact_shell;
  FreeSide side;
  EXPECT_FALSE(side.known());
  std::vector<Eigen::Vector3d> patch;
  for (const double z : { 0.03, 0.01, -0.002, -0.004 })
  {
    side.update({ 0.01, 0, z }, patch, shell);
    patch = sheet_facing_down();
    orient_toward(patch, side.point());
  }
  side.update({ std::nan(""), 0, 0 }, patch, shell); // ignored
  EXPECT_TRUE(side.known());
  EXPECT_EQ(side.point(), Eigen::Vector3d(0.01, 0, 0.01)); // where it entered
  EXPECT_EQ(normal(patch, 0), Eigen::Vector3d(0, 0, 1));   // still pushes it back up
  EXPECT_TRUE(touch(patch, { 0.01, 0, -0.004 }).in_contact);
  side.update({ 0.01, 0, -0.01 }, patch, shell); // deeper than the shell: went through
  EXPECT_EQ(side.point(), Eigen::Vector3d(0.01, 0, -0.01));
}

TEST(ContactPatch, KeepNearestMatchesABruteForceSortAndDropsIncompleteTriangles)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> soup;
  for (int i = 0; i < 3 * 300; ++i)
  {
    soup.emplace_back(u(rng), u(rng), u(rng));
  }
  const Eigen::Vector3d p(0.1, -0.2, 0.3);
  std::vector<std::pair<double, std::size_t>> brute;
  for (std::size_t t = 0; t < 300; ++t)
  {
    const Eigen::Vector3d q =
      closest_point_on_triangle(p, soup[3 * t], soup[3 * t + 1], soup[3 * t + 2]);
    brute.emplace_back((q - p).squaredNorm(), t);
  }
  std::sort(brute.begin(), brute.end());
  auto kept = soup;
  keep_nearest(kept, p, 40);
  ASSERT_EQ(kept.size(), 120u);
  for (std::size_t k = 0; k < 40; ++k)
  {
    const std::size_t t = brute[k].second;
    EXPECT_EQ(kept[3 * k], soup[3 * t]) << k;
    EXPECT_EQ(kept[3 * k + 2], soup[3 * t + 2]) << k;
  }
  auto all = soup;
  keep_nearest(all, p, 1000); // fewer than asked: all kept (reordered)
  EXPECT_EQ(all.size(), soup.size());

  std::vector<Eigen::Vector3d> ragged = sheet_facing_down();
  ragged.push_back(Eigen::Vector3d::Zero());
  orient_toward(ragged, { 0, 0, 1 });
  EXPECT_EQ(ragged.size(), 6u);
}
