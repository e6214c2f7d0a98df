#include "geoshaping/dem_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace geoshaping;

namespace
{
// 4 rows (north to south, as image-ordered DEMs) x 5 columns; elevation 100 r + c.
GeographicGrid small_grid()
{
  GeographicGrid g;
  g.rows = 4;
  g.cols = 5;
  g.lon_first = -84.4;
  g.lon_last = -84.0;
  g.lat_first = 36.7;
  g.lat_last = 36.4;
  for (index_t r = 0; r < g.rows; ++r)
    for (index_t c = 0; c < g.cols; ++c)
      g.elevation.push_back(100.0 * r + c);
  return g;
}
} // namespace

TEST(DemSurface, ProjectionPutsTheCentreAtTheGivenEastingNorthingAndScalesByTheEarthRadius)
{
  const GeographicGrid g = small_grid();
  const LocalProjection p;
  double x, y;
  project(g, p, -84.2, 36.55, x, y);
  EXPECT_NEAR(x, 745000.0, 1e-9);
  EXPECT_NEAR(y, 4055000.0, 1e-9);
  // One degree of latitude is R pi / 180 = 111,195.08 m; a degree of longitude at 36.55
  // degrees north is that times cos(36.55 degrees).
  project(g, p, -84.2, 37.55, x, y);
  EXPECT_NEAR(y - 4055000.0, 6371008.8 * M_PI / 180.0, 1e-6);
  project(g, p, -83.2, 36.55, x, y);
  EXPECT_NEAR(x - 745000.0, 6371008.8 * M_PI / 180.0 * std::cos(36.55 * M_PI / 180.0), 1e-6);
}

TEST(DemSurface, GridBecomesTrianglesWithStridedRowsAndColumns)
{
  const GeographicGrid g = small_grid();
  const LocalProjection p;
  const SampleMesh all = dem_surface(g, 1, p);
  ASSERT_EQ(all.num_points(), 20);
  ASSERT_EQ(all.num_cells(), std::size_t(2 * 3 * 4));
  // Point (r, c) = id 5 r + c, elevation as given, x by column and y by row.
  for (index_t r = 0; r < 4; ++r)
    for (index_t c = 0; c < 5; ++c)
    {
      const double* q = &all.xyz[3 * std::size_t(5 * r + c)];
      double x, y;
      project(g, p, -84.4 + c * 0.1, 36.7 - r * 0.1, x, y);
      EXPECT_NEAR(q[0], x, 1e-6);
      EXPECT_NEAR(q[1], y, 1e-6);
      EXPECT_EQ(q[2], 100.0 * r + c);
    }
  // The first quad's two triangles: (0, 1, 6) first among the first halves, (0, 6, 5)
  // first among the second halves.
  EXPECT_EQ(all.connectivity[0], 0);
  EXPECT_EQ(all.connectivity[1], 1);
  EXPECT_EQ(all.connectivity[2], 6);
  EXPECT_EQ(all.connectivity[3 * 12 + 0], 0);
  EXPECT_EQ(all.connectivity[3 * 12 + 1], 6);
  EXPECT_EQ(all.connectivity[3 * 12 + 2], 5);
  EXPECT_EQ(all.adjacency().size(), 20);

  // Stride 2: rows 0, 2 and columns 0, 2, 4 -> 2 x 3 points.
  const SampleMesh half = dem_surface(g, 2, p);
  ASSERT_EQ(half.num_points(), 6);
  EXPECT_EQ(half.num_cells(), std::size_t(4));
  EXPECT_EQ(half.xyz[3 * 5 + 2], 204.0);              // (row 2, column 4)
  EXPECT_EQ(half.xyz[3 * 2 + 0], all.xyz[3 * 4 + 0]); // column 4 is the last longitude
}

TEST(DemSurface, BadGridsAreRefusedWithAReason)
{
  const LocalProjection p;
  GeographicGrid g = small_grid();
  EXPECT_STREQ(validate(g, 1, p), "");
  EXPECT_NE(std::string(validate(g, 0, p)).find("stride"), std::string::npos);
  EXPECT_NE(std::string(validate(g, 4, p)).find("fewer than 2 x 2"), std::string::npos);
  EXPECT_TRUE(dem_surface(g, 4, p).xyz.empty());
  g.elevation.pop_back();
  EXPECT_NE(std::string(validate(g, 1, p)).find("rows x cols"), std::string::npos);
  g = small_grid();
  g.lat_last = g.lat_first;
  EXPECT_NE(std::string(validate(g, 1, p)).find("must differ"), std::string::npos);
  g = small_grid();
  g.lon_first = std::nan("");
  EXPECT_NE(std::string(validate(g, 1, p)).find("finite"), std::string::npos);
  g = small_grid();
  g.lat_first = 91.0;
  EXPECT_NE(std::string(validate(g, 1, p)).find("[-90, 90]"), std::string::npos);
  LocalProjection bad;
  bad.earth_radius = 0.0;
  EXPECT_NE(std::string(validate(small_grid(), 1, bad)).find("radius"), std::string::npos);
  // Finite bounds, infinite span (issue 13) or infinite projected x.
  g = small_grid();
  g.lon_first = -1e308;
  g.lon_last = 1e308;
  EXPECT_NE(std::string(validate(g, 1, p)).find("coordinates must be finite"), std::string::npos);
  g.lon_first = 1e305;
  g.lon_last = 1.5e305;
  EXPECT_NE(std::string(validate(g, 1, p)).find("coordinates must be finite"), std::string::npos);
}
