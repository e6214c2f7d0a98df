// The markers' pins (geoshaping/metrics/marker_pins.h) on cases worked by hand.
#include "geoshaping/metrics/marker_misfit.h"
#include "geoshaping/metrics/marker_pins.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace geoshaping;

TEST(MarkerPins, NearestCrossingIsTheOneVerticalMisfitReads)
{
  EXPECT_EQ(nearest_crossing(50.0, { 10.0, 95.0, 40.0 }), 2);
  EXPECT_EQ(nearest_crossing(50.0, { 45.0, 55.0 }), 0); // the first of equally near ones
  EXPECT_EQ(nearest_crossing(50.0, {}), -1);
}

// A fold: the triangle z = 0 (vertices 0-2) under the triangle z = 10 (vertices 3-5),
// both over the unit corner; the line through (0.25, 0.25) crosses both.
TEST(MarkerPins, TheTriangleOfTheNearestCrossingIsPinned)
{
  const std::vector<Eigen::Vector3d> vertex = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 10 },
    { 1, 0, 10 }, { 0, 1, 10 } };
  const auto position = [&](index_t v) { return vertex[std::size_t(v)]; };
  const auto crossed = [](const Eigen::Vector3d& m, std::vector<index_t>& corners)
  {
    if (m.x() >= 0 && m.y() >= 0 && m.x() + m.y() <= 1)
      corners.insert(corners.end(), { 0, 1, 2, 3, 4, 5 });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // On the upper sheet; 1 below the lower one; outside; NaN.
  const std::vector<double> markers = { 0.25, 0.25, 10, 0.5, 0.25, -1, 2, 2, 0, nan, 0, 0 };
  const MarkerPins pins = pin_markers(markers.data(), 4, crossed, position, 1e-9);
  EXPECT_EQ(pins.vertices, (std::vector<index_t>{ 0, 1, 2, 3, 4, 5 }));
  EXPECT_EQ(pins.honoured, 2u);
  EXPECT_EQ(pins.off_surface, 1u);
  EXPECT_EQ(pins.outside, 1u);
  EXPECT_EQ(pins.non_finite, 1u);
  // The marker on the upper sheet alone pins the upper triangle only.
  const MarkerPins upper = pin_markers(markers.data(), 1, crossed, position, 1e-9);
  EXPECT_EQ(upper.vertices, (std::vector<index_t>{ 3, 4, 5 }));
  EXPECT_EQ(upper.off_surface, 0u);
  // No markers: nothing pinned.
  EXPECT_TRUE(pin_markers(nullptr, 0, crossed, position, 1e-9).vertices.empty());
}
