// The misfit rules (geoshaping/metrics/marker_misfit.h) on cases worked by hand.
#include "geoshaping/metrics/marker_misfit.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geoshaping;

TEST(MarkerMisfit, VerticalTakesTheCrossingNearestTheMarker)
{
  bool inside = false;
  // A fold crosses the line at 10, 40 and 95: a marker at 50 reads against 40.
  EXPECT_EQ(vertical_misfit(50.0, { 10.0, 95.0, 40.0 }, inside), -10.0);
  EXPECT_TRUE(inside);
  EXPECT_EQ(vertical_misfit(-3.0, { 2.0 }, inside), 5.0); // surface above: positive
  EXPECT_EQ(vertical_misfit(7.0, {}, inside), 0.0);
  EXPECT_FALSE(inside);
}

TEST(MarkerMisfit, NormalIsSignedBySideOfAnUpwardNormal)
{
  // The triangle z = 1 over the unit corner, in both vertex orders.
  const Eigen::Vector3d a(0, 0, 1), b(1, 0, 1), c(0, 1, 1);
  // A marker 2 above the surface: -2, whichever way the vertex order turns the normal.
  EXPECT_EQ(normal_misfit({ 0.25, 0.25, 3 }, a, b, c), -2.0);
  EXPECT_EQ(normal_misfit({ 0.25, 0.25, 3 }, a, c, b), -2.0);
  EXPECT_EQ(normal_misfit({ 0.25, 0.25, -1 }, a, b, c), 2.0);   // below: positive
  EXPECT_EQ(normal_misfit({ 0.25, 0.25, 1 }, a, b, c), 0.0);    // on it: exactly 0
  EXPECT_EQ(normal_misfit({ -3, 0, 1 }, a, b, c), 3.0);         // beside it: the distance
  EXPECT_DOUBLE_EQ(normal_misfit({ -3, 0, 5 }, a, b, c), -5.0); // above and beside: 3-4-5
  // A vertical triangle keeps its own orientation: the side its normal points to.
  const Eigen::Vector3d p(0, 0, 0), q(0, 1, 0), r(0, 0, 1); // normal (1, 0, 0)
  EXPECT_EQ(normal_misfit({ 2, 0.2, 0.2 }, p, q, r), -2.0);
  EXPECT_EQ(normal_misfit({ 2, 0.2, 0.2 }, p, r, q), 2.0);
}

// A UTM-sized triangle keeps its digits: the elevation is taken from its first corner.
TEST(MarkerMisfit, PlaneElevationIsExactAtUtmSizes)
{
  const Eigen::Vector3d a(412345.5, 5123456.25, -12000), b(412845.5, 5123456.25, -11000),
    c(412345.5, 5123956.25, -13000);
  double z = 0.0;
  ASSERT_TRUE(plane_elevation(a, b, c, 412345.5 + 125, 5123456.25 + 250, z));
  EXPECT_EQ(z, -12000 + 0.25 * 1000.0 - 0.5 * 1000.0); // u = 1/4, v = 1/2
  const Eigen::Vector3d up(412345.5, 5123456.25, 0);
  z = 7.0;
  EXPECT_FALSE(plane_elevation(a, up, b, a.x(), a.y(), z)); // vertical: no crossing
  EXPECT_EQ(z, 7.0);
}

TEST(MarkerMisfit, SummaryCountsOnlyTheInsideMarkers)
{
  const MisfitSummary s = summarize_misfit({ 3.0, -4.0, 100.0 }, { 1, 1, 0 });
  EXPECT_EQ(s.inside, 2u);
  EXPECT_DOUBLE_EQ(s.rms, std::sqrt((9.0 + 16.0) / 2.0));
  EXPECT_EQ(s.max, 4.0);
  const MisfitSummary none = summarize_misfit({ 1.0 }, { 0 });
  EXPECT_EQ(none.inside, 0u);
  EXPECT_EQ(none.rms, 0.0);
  EXPECT_EQ(none.max, 0.0);
}
