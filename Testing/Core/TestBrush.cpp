#include "geoshaping/paint/brush.h"
#include "geoshaping/scenes/sample_scenes.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace geoshaping;

namespace
{
const Falloff all_falloffs[] = { Falloff::constant, Falloff::linear, Falloff::smooth,
  Falloff::gaussian };

struct Scene
{
  std::vector<double> xyz;
  Adjacency adjacency;
  index_t size() const { return index_t(xyz.size() / 3); }
};

Scene scene(const SampleMesh& m)
{
  return { m.xyz, m.adjacency() };
}
Scene scene(const geoshaping::testing::Mesh& m)
{
  return { m.xyz, m.adjacency };
}

std::vector<float> paint(const Scene& s, const std::vector<Dab>& dabs, Falloff f, DistanceMode mode,
  float initial = 0.5f, PaintReport* report = nullptr)
{
  std::vector<float> m(std::size_t(s.size()), initial);
  Painter painter(
    s.xyz.data(), s.size(), &s.adjacency, brute_force_queries(s.xyz.data(), s.size()));
  const PaintReport r = painter.paint(dabs, f, mode, m.data());
  if (report)
    *report = r;
  return m;
}

Dab dab(double x, double y, double z, double radius, double value, double strength = 1.0)
{
  Dab d;
  d.center = Eigen::Vector3d(x, y, z);
  d.radius = radius;
  d.value = value;
  d.strength = strength;
  return d;
}

bool bit_identical(const std::vector<float>& a, const std::vector<float>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}
} // namespace

TEST(Brush, FalloffsAreOneAtTheCentreAndZeroAtTheRim)
{
  for (Falloff f : all_falloffs)
  {
    EXPECT_EQ(falloff_weight(f, 0.0), 1.0) << falloff_name(f);
    EXPECT_EQ(falloff_weight(f, 1.0 + 1e-12), 0.0) << falloff_name(f);
    EXPECT_EQ(falloff_weight(f, 7.0), 0.0) << falloff_name(f);
    double previous = 1.0;
    for (int i = 1; i <= 100; ++i)
    {
      const double w = falloff_weight(f, i / 100.0);
      EXPECT_LE(w, previous) << falloff_name(f) << " must not increase outward";
      EXPECT_GE(w, 0.0);
      previous = w;
    }
  }
  EXPECT_EQ(falloff_weight(Falloff::constant, 1.0), 1.0);
  // From the core (half the radius) to the rim, t = 2 r - 1.
  EXPECT_NEAR(falloff_weight(Falloff::linear, 0.625), 0.75, 1e-15);
  EXPECT_NEAR(falloff_weight(Falloff::smooth, 0.75), 0.5, 1e-15);
  EXPECT_NEAR(falloff_weight(Falloff::linear, 1.0), 0.0, 1e-15);
  EXPECT_NEAR(falloff_weight(Falloff::smooth, 1.0), 0.0, 1e-15);
  EXPECT_NEAR(falloff_weight(Falloff::gaussian, 1.0), 0.0, 1e-15);
  // Smooth is flat at both ends; the Gaussian has sigma = (rim - core) / 3 before rescaling.
  EXPECT_NEAR(falloff_weight(Falloff::smooth, 0.5 + 0.5e-4), 1.0, 1e-7);
  EXPECT_NEAR(falloff_weight(Falloff::smooth, 1.0 - 0.5e-4), 0.0, 1e-7);
  const double rim = std::exp(-4.5);
  EXPECT_NEAR(
    falloff_weight(Falloff::gaussian, 0.5 + 1.0 / 6.0), (std::exp(-0.5) - rim) / (1 - rim), 1e-15);
}

TEST(Brush, EveryFalloffIsOneWithinTheCoreSoABlackStrokePaintsRigid)
{
  // The case: a default (Smooth) black stroke over a coarse surface left 0.022
  // where a vertex was an eighth of a radius from the path.
  for (Falloff f : all_falloffs)
  {
    for (double r : { 0.0, 0.125, 0.25, 0.4, brush_core })
    {
      EXPECT_EQ(falloff_weight(f, r), 1.0) << falloff_name(f) << " at " << r;
    }
    if (f != Falloff::constant)
    {
      EXPECT_LT(falloff_weight(f, brush_core + 0.05), 1.0) << falloff_name(f);
    }
  }
  std::vector<float> m(4, 0.5f);
  Reach reach;
  reach.vertices = { 0, 1, 2, 3 };
  reach.distances = { 0.0, 0.9, 1.5, 1.6 };
  Dab black;
  black.radius = 3.0;
  black.value = 0.0;
  apply_dab(black, Falloff::smooth, reach, m.data());
  EXPECT_EQ(m[0], 0.0f);
  EXPECT_EQ(m[1], 0.0f);
  EXPECT_EQ(m[2], 0.0f); // on the core's edge
  EXPECT_GT(m[3], 0.0f); // beyond it, the falloff
}

TEST(Brush, DabMovesEachValueTowardItsValueByStrengthTimesFalloff)
{
  const Scene s = scene(geoshaping::testing::chain(11, 1.0));
  // Centre on vertex 5, radius 8, linear: weights 1 in the core (distances 0..4), then
  // .75, .5, .25 at distances 5..7.
  const auto m =
    paint(s, { dab(5, 0, 0, 8, 1.0, 0.5) }, Falloff::linear, DistanceMode::euclidean, 0.2f);
  const float core = float(0.2 + 0.5 * 0.8);
  const float expected[11] = { float(0.2 + 0.5 * 0.75 * 0.8), core, core, core, core, core, core,
    core, core, core, float(0.2 + 0.5 * 0.75 * 0.8) };
  for (int i = 0; i < 11; ++i)
    EXPECT_FLOAT_EQ(m[i], expected[i]) << "vertex " << i;
  // Geodesic along a straight chain is the same distance.
  EXPECT_TRUE(bit_identical(
    m, paint(s, { dab(5, 0, 0, 8, 1.0, 0.5) }, Falloff::linear, DistanceMode::geodesic, 0.2f)));
}

TEST(Brush, DabsApplyInOrderAndFullStrengthConstantSetsTheValue)
{
  const Scene s = scene(geoshaping::testing::triangle_grid(21, 21, 1.0));
  const auto white_then_black = paint(s, { dab(10, 10, 0, 6, 1.0), dab(10, 10, 0, 3, 0.0) },
    Falloff::constant, DistanceMode::euclidean);
  const auto black_then_white = paint(s, { dab(10, 10, 0, 3, 0.0), dab(10, 10, 0, 6, 1.0) },
    Falloff::constant, DistanceMode::euclidean);
  const index_t centre = geoshaping::testing::grid_id(21, 10, 10);
  const index_t ring = geoshaping::testing::grid_id(21, 15, 10);
  EXPECT_EQ(white_then_black[centre], 0.0f);
  EXPECT_EQ(white_then_black[ring], 1.0f);
  EXPECT_EQ(black_then_white[centre], 1.0f);
  EXPECT_EQ(white_then_black[0], 0.5f);
}

TEST(Brush, GeodesicDistanceOnAFlatGridIsAtLeastEuclideanAndCloseToIt)
{
  const Scene s = scene(geoshaping::testing::triangle_grid(41, 41, 1.0));
  Painter painter(
    s.xyz.data(), s.size(), &s.adjacency, brute_force_queries(s.xyz.data(), s.size()));
  Reach euclid, geo;
  const Dab d = dab(20.3, 19.8, 0, 12, 1.0);
  painter.reach(d, DistanceMode::euclidean, euclid);
  painter.reach(d, DistanceMode::geodesic, geo);
  ASSERT_FALSE(geo.vertices.empty());
  std::vector<double> straight(std::size_t(s.size()), -1.0);
  for (std::size_t i = 0; i < euclid.vertices.size(); ++i)
    straight[euclid.vertices[i]] = euclid.distances[i];
  for (std::size_t i = 0; i < geo.vertices.size(); ++i)
  {
    const double e = straight[geo.vertices[i]];
    ASSERT_GE(e, 0.0) << "geodesic reach must lie inside the Euclidean sphere";
    EXPECT_GE(geo.distances[i], e - 1e-12);
    // Paths along edges: up to sqrt(2) longer across the grid's diagonals, plus the
    // step from the centre to the nearest vertex.
    EXPECT_LE(geo.distances[i], std::sqrt(2.0) * e + 1.0);
    EXPECT_LE(geo.distances[i], d.radius);
  }
  EXPECT_GT(geo.vertices.size(), euclid.vertices.size() * 7 / 10);
}

TEST(Brush, GeodesicReachIsSparseAndIndependentOfThePreviousCall)
{
  const Scene s = scene(geoshaping::testing::triangle_grid(101, 101, 1.0));
  GeodesicReach reusable;
  Reach first, again, fresh;
  reusable.compute(s.adjacency, s.xyz.data(), 0, 0.0, 30.0, first);
  reusable.compute(s.adjacency, s.xyz.data(), 5050, 0.25, 3.0, again);
  GeodesicReach().compute(s.adjacency, s.xyz.data(), 5050, 0.25, 3.0, fresh);
  EXPECT_EQ(again.vertices, fresh.vertices);
  EXPECT_EQ(again.distances, fresh.distances);
  EXPECT_LT(again.vertices.size(), 40u); // a radius-3 disc, not the mesh
  EXPECT_EQ(again.distances.front(), 0.25);
  // Nothing is reached when the centre is farther from the mesh than the radius.
  reusable.compute(s.adjacency, s.xyz.data(), 5050, 3.5, 3.0, again);
  EXPECT_TRUE(again.vertices.empty());
}

TEST(Brush, GeodesicBrushStaysOnItsSheetOfATightFoldWhereEuclideanCrossesTheGap)
{
  // Sheets at z = 0 and z = 2; the brush sits on the upper sheet far from the hinge.
  const Scene s = scene(tight_fold(40.0, 10.0, 2.0, 0.5));
  const std::vector<Dab> dabs = { dab(10, 5, 2, 4.0, 0.0) };
  const auto euclid = paint(s, dabs, Falloff::constant, DistanceMode::euclidean);
  const auto geo = paint(s, dabs, Falloff::constant, DistanceMode::geodesic);
  int euclid_lower = 0, geo_lower = 0, geo_upper = 0;
  for (index_t v = 0; v < s.size(); ++v)
  {
    const bool lower = s.xyz[3 * v + 2] < 1e-9 && s.xyz[3 * v] < 39.0;
    euclid_lower += lower && euclid[v] == 0.0f;
    geo_lower += lower && geo[v] == 0.0f;
    geo_upper += !lower && geo[v] == 0.0f;
  }
  EXPECT_GT(euclid_lower, 20);
  EXPECT_EQ(geo_lower, 0);
  EXPECT_GT(geo_upper, 20);
}

TEST(Brush, GeodesicBrushAtTheTopOfTheFaultStepReachesLessOfTheFootwall)
{
  // A brush on the upper side at the step's edge, radius 1.4 x the throw: the sphere
  // reaches far over the lower flat, the path down the step only just arrives there.
  FaultStepParams p;
  p.length = 60;
  p.width = 10;
  p.throw_height = 10;
  p.step_run = 2;
  p.spacing = 0.5;
  const Scene s = scene(fault_step_horizon(p));
  const double x0 = 0.5 * p.length - 0.5 * p.step_run, foot = x0 + p.step_run;
  const std::vector<Dab> dabs = { dab(x0, 5, p.throw_height, 14.0, 0.0) };
  const auto euclid = paint(s, dabs, Falloff::constant, DistanceMode::euclidean);
  const auto geo = paint(s, dabs, Falloff::constant, DistanceMode::geodesic);
  double euclid_far = 0.0, geo_far = 0.0; // farthest painted lower-flat vertex past the foot
  for (index_t v = 0; v < s.size(); ++v)
  {
    const double x = s.xyz[3 * v], z = s.xyz[3 * v + 2];
    if (z > 1e-9 || x < foot)
      continue;
    if (euclid[v] == 0.0f)
      euclid_far = std::max(euclid_far, x - foot);
    if (geo[v] == 0.0f)
      geo_far = std::max(geo_far, x - foot);
  }
  EXPECT_GT(euclid_far, 7.0);
  EXPECT_LT(geo_far, 4.5);
}

TEST(Brush, SameDabsGiveBitIdenticalArrays)
{
  const Scene s = scene(fault_step_horizon(FaultStepParams{}));
  std::vector<Dab> dabs;
  for (int i = 0; i < 50; ++i)
    dabs.push_back(
      dab(2.0 * i, 0.9 * i, 10.0 + 0.1 * i, 3.0 + (i % 5), (i % 7) / 6.0, 0.3 + (i % 3) * 0.3));
  for (Falloff f : all_falloffs)
    for (DistanceMode mode : { DistanceMode::euclidean, DistanceMode::geodesic })
      EXPECT_TRUE(bit_identical(paint(s, dabs, f, mode), paint(s, dabs, f, mode)))
        << falloff_name(f) << " " << distance_mode_name(mode);
}

TEST(Brush, BadDabsAreRejectedAndChangeNothingElse)
{
  const Scene s = scene(geoshaping::testing::triangle_grid(21, 21, 1.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Dab> good = { dab(5, 5, 0, 4, 1.0, 0.7), dab(12, 12, 0, 5, 0.1, 0.5) };
  const std::vector<Dab> mixed = { dab(nan, 5, 0, 4, 1.0), good[0], dab(5, 5, 0, -1, 1.0),
    dab(5, 5, 0, nan, 1.0), dab(5, 5, 0, 4, 1.5), dab(5, 5, 0, 4, -0.5), good[1],
    dab(5, 5, 0, 4, 1.0, 1.01), dab(5, 5, 0, 4, 1.0, nan),
    dab(5, 5, 0, std::numeric_limits<double>::infinity(), 1.0) };
  PaintReport report;
  const auto m = paint(s, mixed, Falloff::smooth, DistanceMode::geodesic, 0.5f, &report);
  EXPECT_TRUE(bit_identical(m, paint(s, good, Falloff::smooth, DistanceMode::geodesic)));
  EXPECT_EQ(report.applied, 2u);
  ASSERT_EQ(report.rejected.size(), 8u);
  EXPECT_EQ(report.rejected[0].first, 0u);
  EXPECT_EQ(report.rejected[1].second, "its radius is negative");
  EXPECT_EQ(report.rejected[3].second, "its value is outside [0, 1]");
  EXPECT_EQ(report.rejected[5].second, "its strength is outside [0, 1]");
  EXPECT_EQ(report.rejected[7].second, "its radius is not finite");
  // A zero radius is valid and paints nothing.
  PaintReport zero;
  const auto untouched =
    paint(s, { dab(5, 5, 0, 0.0, 1.0) }, Falloff::constant, DistanceMode::euclidean, 0.5f, &zero);
  EXPECT_EQ(zero.applied, 1u);
  EXPECT_TRUE(bit_identical(untouched, std::vector<float>(std::size_t(s.size()), 0.5f)));
}

TEST(Brush, ValuesStayInTheUnitInterval)
{
  const Scene s = scene(geoshaping::testing::triangle_grid(11, 11, 1.0));
  std::vector<Dab> dabs;
  for (int i = 0; i < 200; ++i)
    dabs.push_back(dab(i % 11, (i * 7) % 11, 0, 2.5, (i % 2) ? 1.0 : 0.0, 1.0));
  for (Falloff f : all_falloffs)
    for (float v : paint(s, dabs, f, DistanceMode::euclidean))
    {
      EXPECT_GE(v, 0.0f);
      EXPECT_LE(v, 1.0f);
    }
}

TEST(MalleabilityColor, FollowsTheBlackBodyPreset)
{
  // ParaViewPlugin/Presets/Malleability_black-body.json: black 0, red 0.4, orange 0.6,
  // yellow 0.8, white 1, linear in RGB between them.
  auto expect = [](double m, const Eigen::Vector3d& rgb)
  { EXPECT_LE((malleability_color(m) - rgb).norm(), 1e-12) << m; };
  expect(0.0, { 0.0, 0.0, 0.0 });
  expect(0.4, { 0.9, 0.0, 0.0 });
  expect(0.5, { 0.95, 0.25, 0.0 });
  expect(0.6, { 1.0, 0.5, 0.0 });
  expect(0.8, { 1.0, 0.9, 0.1 });
  expect(1.0, { 1.0, 1.0, 1.0 });
  expect(0.2, { 0.45, 0.0, 0.0 });
  expect(7.0, { 1.0, 1.0, 1.0 });                                      // clamped
  expect(-1.0, { 0.0, 0.0, 0.0 });                                     // clamped
  expect(std::numeric_limits<double>::quiet_NaN(), { 0.0, 0.0, 0.0 }); // NaN is rigid
}

TEST(Painter, ReportsProgressAndStopsWhenAsked)
{
  const geoshaping::testing::Mesh s = geoshaping::testing::triangle_grid(30, 30, 1.0);
  std::vector<Dab> dabs;
  // Alternate values: each dab is a stroke of its own (brush.h), a point where it can stop.
  for (int i = 0; i < 250; ++i)
    dabs.push_back({ Eigen::Vector3d(i % 30, (i / 30) % 30, 0.0), 2.0, double(i % 2), 1.0 });
  std::vector<float> m(std::size_t(s.size()), 0.5f);
  Painter painter(s.xyz.data(), s.size(), nullptr, brute_force_queries(s.xyz.data(), s.size()));

  std::vector<double> seen;
  PaintReport all = painter.paint(dabs, Falloff::constant, DistanceMode::euclidean, m.data(),
    [&](double f)
    {
      seen.push_back(f);
      return true;
    });
  EXPECT_FALSE(all.aborted);
  EXPECT_EQ(all.applied, dabs.size());
  // Every third dab (250 / 100 + 1), then the end: monotone, at most 101 calls, ends at 1.
  ASSERT_EQ(seen.size(), 250u / 3u + 1u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.front(), 3.0 / 250.0);
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);

  // Stop at the second report: six dabs applied, exactly as painting those six alone.
  std::vector<float> stopped(m.size(), 0.5f);
  int calls = 0;
  const PaintReport part = painter.paint(dabs, Falloff::constant, DistanceMode::euclidean,
    stopped.data(), [&](double) { return ++calls < 2; });
  EXPECT_TRUE(part.aborted);
  EXPECT_EQ(part.applied, 6u);
  std::vector<float> six(m.size(), 0.5f);
  painter.paint(std::vector<Dab>(dabs.begin(), dabs.begin() + 6), Falloff::constant,
    DistanceMode::euclidean, six.data());
  EXPECT_EQ(stopped, six);
}
