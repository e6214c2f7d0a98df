#include "geoshaping/scenes/dem_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace geoshaping;

namespace
{
// 4 rows (north to south, as image-ordered DEMs) x 5 columns; elevation 100 r + c.
ElevationGrid small_grid()
{
  ElevationGrid g;
  g.rows = 4;
  g.cols = 5;
  g.x_first = -84.4;
  g.x_last = -84.0;
  g.y_first = 36.7;
  g.y_last = 36.4;
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
  const ElevationGrid g = small_grid();
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
  ElevationGrid g = small_grid();
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
  g.y_last = g.y_first;
  EXPECT_NE(std::string(validate(g, 1)).find("must differ"), std::string::npos);
  g = small_grid();
  g.x_first = std::nan("");
  EXPECT_NE(std::string(validate(g, 1)).find("finite"), std::string::npos);
  g = small_grid();
  g.y_first = 91.0;
  EXPECT_NE(std::string(validate(g, 1)).find("[-90, 90]"), std::string::npos);
  // Finite bounds, infinite span.
  g = small_grid();
  g.x_first = -1e308;
  g.x_last = 1e308;
  EXPECT_NE(std::string(validate(g, 1)).find("spans must be finite"), std::string::npos);
  // A projection that fails, or gives infinite coordinates (1000 x 1.7e306 overflows).
  g = small_grid();
  EXPECT_TRUE(dem_surface(
    g, 1, [](std::size_t, double*, double*) { return false; }, &why)
                .xyz.empty());
  EXPECT_EQ(why, "the map projection failed");
  g.x_first = 1e306;
  g.x_last = 1.7e306;
  EXPECT_TRUE(dem_surface(g, 1, AffineProjector{ &calls, &points }, &why).xyz.empty());
  EXPECT_NE(why.find("infinite or undefined"), std::string::npos);
}

TEST(DemSurface, NoDataSamplesAreHolesWithTheTrianglesThatUseThem)
{
  ElevationGrid g = small_grid();
  g.elevation[5 * 1 + 2] = std::nan(""); // sample (1, 2): id 7 of the full grid
  int calls = 0;
  std::size_t points = 0;
  const SampleMesh mesh = dem_surface(g, 1, AffineProjector{ &calls, &points });
  EXPECT_EQ(points, 19u) << "the no-data sample is not projected";
  ASSERT_EQ(mesh.num_points(), 19);
  // An inner vertex of this triangulation is in 6 triangles: 2 of quad (0, 1), 1 of
  // (0, 2) (its second), 1 of (1, 1) (its first), 2 of (1, 2): 24 - 6 left.
  ASSERT_EQ(mesh.num_cells(), std::size_t(18));
  for (const index_t id : mesh.connectivity)
    EXPECT_TRUE(id >= 0 && id < 19);
  for (double v : mesh.xyz)
    EXPECT_TRUE(std::isfinite(v));
  // Ids after the hole move down by one: (1, 3) is id 7, at its own place.
  EXPECT_EQ(mesh.xyz[3 * 7 + 2], 103.0);
  EXPECT_NEAR(mesh.xyz[3 * 7 + 1], 2000.0 * 36.6, 1e-9);
  // The first quad keeps its first triangle (0, 1, 6): ids before the hole stay.
  EXPECT_EQ(mesh.connectivity[0], 0);
  EXPECT_EQ(mesh.connectivity[1], 1);
  EXPECT_EQ(mesh.connectivity[2], 6);
  // Every sample no data: refused with a reason, nothing projected.
  g.elevation.assign(g.elevation.size(), std::nan(""));
  std::string why;
  EXPECT_TRUE(dem_surface(g, 1, AffineProjector{ &calls, &points }, &why).xyz.empty());
  EXPECT_EQ(why, "every sample is no data");
  EXPECT_EQ(calls, 1);
}

TEST(DemSurface, ImagesBecomeGridsNorthFirstWithNoDataAsNaN)
{
  // 3 x 2 pixels as GDALRasterReader gives them: y grows with j, values row j = 0 first.
  ImageSamples image;
  image.dims[0] = 3;
  image.dims[1] = 2;
  image.origin[0] = 10.0;
  image.origin[1] = 49.0;
  image.spacing[0] = 0.5;
  image.spacing[1] = 0.25;
  image.values = { 0, 1, 2, 3, 4, 5 };
  image.hidden = { 0, 0, 1, 0, 0, 0 };
  image.has_nodata = true;
  image.nodata = 4.0;
  ElevationGrid g = grid_of_image(image, true);
  EXPECT_TRUE(g.geographic);
  ASSERT_EQ(g.rows, 2);
  ASSERT_EQ(g.cols, 3);
  // Pixel centres: x 10.25 ... 11.25; the northern row (j = 1, y 49.375) first.
  EXPECT_EQ(g.x_first, 10.25);
  EXPECT_EQ(g.x_last, 11.25);
  EXPECT_EQ(g.y_first, 49.375);
  EXPECT_EQ(g.y_last, 49.125);
  EXPECT_EQ(g.elevation[0], 3.0);
  EXPECT_TRUE(std::isnan(g.elevation[1])) << "equal to the no-data value";
  EXPECT_EQ(g.elevation[2], 5.0);
  EXPECT_EQ(g.elevation[3], 0.0);
  EXPECT_EQ(g.elevation[4], 1.0);
  EXPECT_TRUE(std::isnan(g.elevation[5])) << "hidden by the reader";
  // Point data (offset 0), rows already north first (y falls with j): no flip.
  image.cell_centred = false;
  image.spacing[1] = -0.25;
  image.hidden.clear();
  image.has_nodata = false;
  g = grid_of_image(image, false);
  EXPECT_FALSE(g.geographic);
  EXPECT_EQ(g.x_first, 10.0);
  EXPECT_EQ(g.y_first, 49.0);
  EXPECT_EQ(g.y_last, 48.75);
  EXPECT_EQ(g.elevation[1], 1.0);
  EXPECT_EQ(g.elevation[4], 4.0);
  // A size that does not match is named by validate(), not read out of bounds.
  image.values.pop_back();
  EXPECT_NE(
    std::string(validate(grid_of_image(image, false), 1)).find("rows x cols"), std::string::npos);
  // Projected grids have no latitude limit.
  g.y_first = 4.1e6;
  EXPECT_STREQ(validate(g, 1), "");
}

TEST(DemSurface, NoDataValuesAreOneNumber)
{
  double v = 0.0;
  EXPECT_TRUE(parse_nodata("-9999", &v));
  EXPECT_EQ(v, -9999.0);
  EXPECT_TRUE(parse_nodata(" -3.4028234663852886e+38\n", &v));
  EXPECT_EQ(v, -3.4028234663852886e+38);
  EXPECT_TRUE(parse_nodata("nan", &v));
  EXPECT_TRUE(std::isnan(v));
  v = 7.0;
  for (const char* bad : { "", "  ", "abc", "5x", "1e999", "5 6", "0x10" })
  {
    EXPECT_FALSE(parse_nodata(bad, &v)) << bad;
    EXPECT_EQ(v, 7.0) << bad;
  }
}
