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

// A made-up affine map (x = 1000 lon + 10 lat, y = 2000 lat): x depends on both, as a
// transverse Mercator's does; counts its calls and points.
struct AffineProjector
{
  int* calls;
  std::size_t* points;
  bool operator()(std::size_t n, double* x, double* y) const
  {
    ++*calls;
    *points += n;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double lon = x[i], lat = y[i];
      x[i] = 1000.0 * lon + 10.0 * lat;
      y[i] = 2000.0 * lat;
    }
    return true;
  }
};

TEST(DemSurface, GridBecomesTrianglesWithStridedRowsAndColumns)
{
  const GeographicGrid g = small_grid();
  int calls = 0;
  std::size_t points = 0;
  const SampleMesh all = dem_surface(g, 1, AffineProjector{ &calls, &points });
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(points, 20u);
  ASSERT_EQ(all.num_points(), 20);
  ASSERT_EQ(all.num_cells(), std::size_t(2 * 3 * 4));
  // Point (r, c) = id 5 r + c at the projection of (lon_c, lat_r), elevation as given.
  for (index_t r = 0; r < 4; ++r)
    for (index_t c = 0; c < 5; ++c)
    {
      const double* q = &all.xyz[3 * std::size_t(5 * r + c)];
      const double lon = -84.4 + c * 0.1, lat = 36.7 - r * 0.1;
      EXPECT_NEAR(q[0], 1000.0 * lon + 10.0 * lat, 1e-9);
      EXPECT_NEAR(q[1], 2000.0 * lat, 1e-9);
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

  // Stride 2: rows 0, 2 and columns 0, 2, 4 -> 2 x 3 points, one call of 6.
  const SampleMesh half = dem_surface(g, 2, AffineProjector{ &calls, &points });
  EXPECT_EQ(points, 26u);
  ASSERT_EQ(half.num_points(), 6);
  EXPECT_EQ(half.num_cells(), std::size_t(4));
  EXPECT_EQ(half.xyz[3 * 5 + 2], 204.0);              // (row 2, column 4)
  EXPECT_EQ(half.xyz[3 * 2 + 0], all.xyz[3 * 4 + 0]); // column 4 is the last longitude
}

TEST(DemSurface, BadGridsAndFailedProjectionsAreRefusedWithAReason)
{
  GeographicGrid g = small_grid();
  EXPECT_STREQ(validate(g, 1), "");
  EXPECT_NE(std::string(validate(g, 0)).find("stride"), std::string::npos);
  EXPECT_NE(std::string(validate(g, 4)).find("fewer than 2 x 2"), std::string::npos);
  int calls = 0;
  std::size_t points = 0;
  std::string why;
  EXPECT_TRUE(dem_surface(g, 4, AffineProjector{ &calls, &points }, &why).xyz.empty());
  EXPECT_NE(why.find("fewer than 2 x 2"), std::string::npos);
  EXPECT_EQ(calls, 0) << "nothing is projected for a bad grid";
  g.elevation.pop_back();
  EXPECT_NE(std::string(validate(g, 1)).find("rows x cols"), std::string::npos);
  g = small_grid();
  g.lat_last = g.lat_first;
  EXPECT_NE(std::string(validate(g, 1)).find("must differ"), std::string::npos);
  g = small_grid();
  g.lon_first = std::nan("");
  EXPECT_NE(std::string(validate(g, 1)).find("finite"), std::string::npos);
  g = small_grid();
  g.lat_first = 91.0;
  EXPECT_NE(std::string(validate(g, 1)).find("[-90, 90]"), std::string::npos);
  // Finite bounds, infinite span (issue 13).
  g = small_grid();
  g.lon_first = -1e308;
  g.lon_last = 1e308;
  EXPECT_NE(std::string(validate(g, 1)).find("spans must be finite"), std::string::npos);
  // A projection that fails, or gives infinite coordinates (1000 x 1.7e306 overflows).
  g = small_grid();
  EXPECT_TRUE(dem_surface(
    g, 1, [](std::size_t, double*, double*) { return false; }, &why)
                .xyz.empty());
  EXPECT_EQ(why, "the map projection failed");
  g.lon_first = 1e306;
  g.lon_last = 1.7e306;
  EXPECT_TRUE(dem_surface(g, 1, AffineProjector{ &calls, &points }, &why).xyz.empty());
  EXPECT_NE(why.find("infinite or undefined"), std::string::npos);
}
