#include "geoshaping/paint/brush_stroke.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using geoshaping::BrushStroke;

namespace
{
using Points = std::vector<Eigen::Vector3d>;

// The largest distance from a sample of the polyline `path` to its nearest dab.
double largest_gap(const Points& path, const Points& dabs)
{
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
  {
    for (int k = 0; k <= 1000; ++k)
    {
      const Eigen::Vector3d p = path[i] + (k / 1000.0) * (path[i + 1] - path[i]);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& d : dabs)
      {
        nearest = std::min(nearest, (p - d).norm());
      }
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}
}

TEST(BrushStroke, FastMoveBetweenTwoFramesIsFilledAtTheSpacing)
{
  // Two frames 100 radii apart: 400 dabs a quarter radius apart, the first at the press.
  BrushStroke stroke;
  Points dabs;
  stroke.begin(Eigen::Vector3d(0, 0, 0), dabs);
  stroke.move_to(Eigen::Vector3d(200, 0, 0), 2.0, dabs);
  ASSERT_EQ(dabs.size(), 401u);
  for (std::size_t i = 0; i < dabs.size(); ++i)
  {
    EXPECT_NEAR(dabs[i].x(), 0.5 * i, 1e-9) << i;
    EXPECT_EQ(dabs[i].y(), 0.0);
  }
  EXPECT_LE(largest_gap({ { 0, 0, 0 }, { 200, 0, 0 } }, dabs), 0.25 + 1e-9);
}

TEST(BrushStroke, SpacingCarriesOverFramesWhateverTheFrameRate)
{
  // The same path sampled in 3 frames or in 1,000 gives the same dabs.
  const Eigen::Vector3d a(1, 2, 3), b(11, -4, 3), c(15, 0, 8);
  auto run = [&](int frames)
  {
    BrushStroke stroke(0.1);
    Points dabs;
    stroke.begin(a, dabs);
    for (int f = 1; f <= frames; ++f)
    {
      stroke.move_to(a + (f / double(frames)) * (b - a), 3.0, dabs);
    }
    for (int f = 1; f <= frames; ++f)
    {
      stroke.move_to(b + (f / double(frames)) * (c - b), 3.0, dabs);
    }
    return dabs;
  };
  const Points coarse = run(1), fine = run(1000);
  ASSERT_EQ(coarse.size(), fine.size());
  for (std::size_t i = 0; i < coarse.size(); ++i)
  {
    EXPECT_LT((coarse[i] - fine[i]).norm(), 1e-9) << i;
  }
  // Consecutive dabs 0.3 apart along the path (the corner at b cuts its chord).
  const double length = (b - a).norm() + (c - b).norm();
  EXPECT_EQ(coarse.size(), std::size_t(std::floor(length / 0.3)) + 1);
  EXPECT_LE(largest_gap({ a, b, c }, coarse), 0.15 + 1e-9);
}

TEST(BrushStroke, SmallMovesAccumulateToOneDab)
{
  BrushStroke stroke; // a quarter of radius 4: a dab every 1.0
  Points dabs;
  stroke.begin(Eigen::Vector3d::Zero(), dabs);
  for (int i = 1; i <= 9; ++i)
  {
    stroke.move_to(Eigen::Vector3d(0.1 * i, 0, 0), 4.0, dabs);
  }
  EXPECT_EQ(dabs.size(), 1u);
  stroke.move_to(Eigen::Vector3d(1.05, 0, 0), 4.0, dabs);
  ASSERT_EQ(dabs.size(), 2u);
  EXPECT_NEAR(dabs[1].x(), 1.0, 1e-12);
}

TEST(BrushStroke, ARadiusMadeSmallerMidStrokePlacesTheNextDabAtOnce)
{
  BrushStroke stroke;
  Points dabs;
  stroke.begin(Eigen::Vector3d::Zero(), dabs);
  stroke.move_to(Eigen::Vector3d(0.9, 0, 0), 4.0, dabs); // 0.9 of a spacing of 1
  stroke.move_to(Eigen::Vector3d(0.9, 0, 0), 0.4, dabs); // spacing 0.1: overdue
  ASSERT_EQ(dabs.size(), 2u);
  EXPECT_EQ(dabs[1], Eigen::Vector3d(0.9, 0, 0));
  stroke.move_to(Eigen::Vector3d(1.01, 0, 0), 0.4, dabs);
  ASSERT_EQ(dabs.size(), 3u);
  EXPECT_NEAR(dabs[2].x(), 1.0, 1e-12);
}

TEST(BrushStroke, BadInputPlacesNoDabAndKeepsThePath)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  BrushStroke stroke;
  Points dabs;
  stroke.move_to(Eigen::Vector3d(5, 0, 0), 1.0, dabs); // not begun
  stroke.begin(Eigen::Vector3d(nan, 0, 0), dabs);
  EXPECT_FALSE(stroke.active());
  EXPECT_TRUE(dabs.empty());
  stroke.begin(Eigen::Vector3d::Zero(), dabs);
  stroke.move_to(Eigen::Vector3d(inf, 0, 0), 1.0, dabs);
  stroke.move_to(Eigen::Vector3d(1, 0, 0), nan, dabs);
  stroke.move_to(Eigen::Vector3d(2, 0, 0), -1.0, dabs);
  stroke.move_to(Eigen::Vector3d(3, 0, 0), 0.0, dabs);
  EXPECT_EQ(dabs.size(), 1u);
  // The path goes on from (3, 0, 0), the last finite position.
  stroke.move_to(Eigen::Vector3d(4, 0, 0), 2.0, dabs);
  ASSERT_EQ(dabs.size(), 3u);
  EXPECT_NEAR(dabs[1].x(), 3.5, 1e-12);
  EXPECT_NEAR(dabs[2].x(), 4.0, 1e-12);
  for (const auto& d : dabs)
  {
    EXPECT_TRUE(d.allFinite());
  }
  stroke.end();
  stroke.move_to(Eigen::Vector3d(10, 0, 0), 2.0, dabs);
  EXPECT_EQ(dabs.size(), 3u);
}

TEST(BrushStroke, AHugeMoveIsCapped)
{
  BrushStroke stroke;
  Points dabs;
  stroke.begin(Eigen::Vector3d::Zero(), dabs);
  stroke.move_to(Eigen::Vector3d(1e12, 0, 0), 1.0, dabs);
  EXPECT_EQ(dabs.size(), 1u + BrushStroke::max_dabs_per_move);
  EXPECT_TRUE(BrushStroke(-1.0).spacing_fraction() == BrushStroke::default_spacing_fraction);
  EXPECT_TRUE(BrushStroke(5.0).spacing_fraction() == 1.0);
}
