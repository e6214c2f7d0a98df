#include "BrushControl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace geoshaping::interactor;

TEST(BrushControl, DefaultRadiusIsThreePerCentOfTheDiagonal)
{
  const double square[6] = { 0.0, 1e6, -5e5, 5e5, -2e4, 2e4 }; // 1,000 km, 40 km of relief
  EXPECT_NEAR(default_brush_radius(square), 0.03 * std::sqrt(2e12 + 1.6e9), 1e-6);
  const double horizon[6] = { 0, 100, 0, 60, 0, 20 };
  EXPECT_NEAR(default_brush_radius(horizon), 0.03 * std::sqrt(10000 + 3600 + 400), 1e-12);
  const double uninitialised[6] = { 1, -1, 1, -1, 1, -1 };
  EXPECT_EQ(default_brush_radius(uninitialised), 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double bad[6] = { 0, nan, 0, 1, 0, 1 };
  EXPECT_EQ(default_brush_radius(bad), 0.0);
  const double point[6] = { 3, 3, 4, 4, 5, 5 };
  EXPECT_EQ(default_brush_radius(point), 0.0);
}

TEST(BrushControl, SceneUnitComesFromTheReadersFieldData)
{
  EXPECT_EQ(scene_unit({ "m", "m", "m" }, false), "m");
  EXPECT_EQ(scene_unit({ "Meters", "Meters", "ft" }, false), "m");
  EXPECT_EQ(scene_unit({ "ft", "ft", "ft" }, true), "ft");
  EXPECT_EQ(scene_unit({}, true), "m"); // a DEM surface
  EXPECT_EQ(scene_unit({ "m", "ft" }, false), "");
  EXPECT_EQ(scene_unit({}, false), "");
}

TEST(BrushControl, LengthsReadWithTheirUnit)
{
  EXPECT_EQ(format_length(42426.4, "m"), "42.4 km");
  EXPECT_EQ(format_length(5.0, "m"), "5 m");
  EXPECT_EQ(format_length(999.0, "m"), "999 m");
  EXPECT_EQ(format_length(0.25, "ft"), "0.25 ft");
  EXPECT_EQ(format_length(1.5, ""), "1.5 scene units");
}

TEST(BrushControl, CursorIsAtLeastFourPixels)
{
  EXPECT_EQ(cursor_radius(42000.0, 1600.0), 42000.0);
  EXPECT_EQ(cursor_radius(5.0, 1600.0), 6400.0);
  EXPECT_EQ(cursor_radius(5.0, 0.0), 5.0);
  EXPECT_EQ(cursor_radius(std::numeric_limits<double>::quiet_NaN(), 2.0), 8.0);
}

TEST(BrushControl, NoteSaysWhyDabsWereNotStored)
{
  EXPECT_EQ(stroke_note({ 12, 0, -1 }, 42426.4, "m"), "Last stroke: 12 dabs.");
  EXPECT_EQ(stroke_note({ 0, 0, -1 }, 1, ""), "");
  EXPECT_EQ(stroke_note({ 0, 3, 12400.0 }, 5.0, "m"),
    "Last stroke painted nothing: 3 dabs reached no vertex within the brush radius (5 m), "
    "the nearest vertex was 12.4 km away, and were not stored: enlarge the brush.");
  EXPECT_EQ(stroke_note({ 10, 1, -1 }, 2.0, ""),
    "Last stroke: 10 dabs; 1 dab reached no vertex within the brush radius (2 scene units), "
    "and was not stored: paint on the surface.");
}

TEST(BrushControl, OutcomesAddUpWithTheNearestKnownDistance)
{
  StrokeOutcome total;
  total.add_unreached(-1.0);
  EXPECT_EQ(total.nearest, -1.0);
  StrokeOutcome frame;
  frame.stored = 3;
  frame.add_unreached(12.0);
  frame.add_unreached(8.0);
  total.add(frame);
  EXPECT_EQ(total.stored, 3u);
  EXPECT_EQ(total.unreached, 3u);
  EXPECT_EQ(total.nearest, 8.0);
  total.add(StrokeOutcome{ 2, 0, -1.0 });
  EXPECT_EQ(total.stored, 5u);
  EXPECT_EQ(total.unreached, 3u);
  EXPECT_EQ(total.nearest, 8.0);
}

TEST(BrushControl, RadiusAboutNamesNoSceneUnitsBeforeThereIsData)
{
  EXPECT_EQ(radius_about(5.0, "", true, false),
    "Fits the surface once there is one to paint: 3 % of its diagonal");
  EXPECT_EQ(radius_about(42426.4, "m", true, true), "42.4 km: 3 % of the data's diagonal");
  EXPECT_EQ(radius_about(5.0, "m", false, true), "5 m: set for this surface (kept in the state)");
  EXPECT_EQ(radius_about(1.5, "", true, true),
    "1.5 scene units: 3 % of the data's diagonal; the data names no unit");
}
