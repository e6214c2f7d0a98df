// Strokes paint each vertex once with its strongest weight (brush.h): checked against
// brute force written here from the rule, independently of DabUnion and the accumulator.
#include "geoshaping/paint/brush.h"
#include "geoshaping/paint/dab_union.h"
#include "geoshaping/scenes/sample_scenes.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace geoshaping;

namespace
{
const Falloff all_falloffs[] = { Falloff::constant, Falloff::linear, Falloff::smooth,
  Falloff::gaussian };

Dab dab(const Eigen::Vector3d& c, double radius, double value, double strength)
{
  Dab d;
  d.center = c;
  d.radius = radius;
  d.value = value;
  d.strength = strength;
  return d;
}

// The rule before strokes: every dab applied in turn to every vertex it reaches.
std::vector<float> dab_by_dab(
  const std::vector<double>& xyz, const std::vector<Dab>& dabs, Falloff f, float initial)
{
  std::vector<float> m(xyz.size() / 3, initial);
  for (const Dab& d : dabs)
    for (std::size_t v = 0; v < m.size(); ++v)
    {
      const double r = brush_distance(xyz.data(), index_t(v), d.center);
      const double w = d.strength * falloff_weight(f, r / d.radius);
      if (r <= d.radius && w > 0.0)
        m[v] = float(std::clamp(double(m[v]) + w * (d.value - double(m[v])), 0.0, 1.0));
    }
  return m;
}

// The stroke rule by brute force: split the list into strokes (same brush, each centre
// within one radius of the previous and not on it), then per vertex the largest weight of
// the stroke's dabs, applied once.
std::vector<float> strongest_per_stroke(
  const std::vector<double>& xyz, const std::vector<Dab>& dabs, Falloff f, float initial)
{
  std::vector<float> m(xyz.size() / 3, initial);
  for (std::size_t first = 0; first < dabs.size();)
  {
    std::size_t last = first + 1;
    while (last < dabs.size() && dabs[last].radius == dabs[first].radius &&
           dabs[last].value == dabs[first].value && dabs[last].strength == dabs[first].strength &&
           (dabs[last].center - dabs[last - 1].center).norm() > 0.0 &&
           (dabs[last].center - dabs[last - 1].center).norm() <= dabs[first].radius)
      ++last;
    const Dab& b = dabs[first];
    for (std::size_t v = 0; v < m.size(); ++v)
    {
      double w = -1.0;
      for (std::size_t i = first; i < last; ++i)
      {
        const double r = brush_distance(xyz.data(), index_t(v), dabs[i].center);
        if (r <= b.radius)
          w = std::max(w, b.strength * falloff_weight(f, r / b.radius));
      }
      if (w > 0.0)
        m[v] = float(std::clamp(double(m[v]) + w * (b.value - double(m[v])), 0.0, 1.0));
    }
    first = last;
  }
  return m;
}

// A triangle grid with jittered vertices, lifted into a gentle dome (a 3D surface).
std::vector<double> jittered_surface(index_t nx, index_t ny)
{
  std::vector<double> xyz = geoshaping::testing::triangle_grid(nx, ny, 1.0).xyz;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (std::size_t i = 0; i < xyz.size(); i += 3)
  {
    xyz[i] += jitter(random);
    xyz[i + 1] += jitter(random);
    xyz[i + 2] = 0.05 * (xyz[i] * (nx - xyz[i]) + xyz[i + 1] * (ny - xyz[i + 1])) / nx;
  }
  return xyz;
}

// Two overlapping curved strokes of different brushes, dabs a quarter radius apart, and a
// lone dab over both.
std::vector<Dab> curved_strokes()
{
  std::vector<Dab> dabs;
  for (int i = 0; i < 60; ++i)
  {
    const double t = 0.1 * i;
    dabs.push_back(dab(Eigen::Vector3d(5 + 4 * t, 15 + 8 * std::sin(t), 1.0), 4.0, 0.9, 0.7));
  }
  for (int i = 0; i < 40; ++i)
    dabs.push_back(dab(Eigen::Vector3d(12 + 0.5 * i, 5 + 0.4 * i, 0.5), 2.5, 0.1, 0.6));
  dabs.push_back(dab(Eigen::Vector3d(15, 15, 0), 6.0, 1.0, 0.3));
  return dabs;
}

std::vector<float> painted(const std::vector<double>& xyz, const std::vector<Dab>& dabs, Falloff f,
  DistanceMode mode, float initial, const Adjacency* adjacency = nullptr)
{
  const index_t n = index_t(xyz.size() / 3);
  std::vector<float> m(std::size_t(n), initial);
  Painter painter(xyz.data(), n, adjacency, brute_force_queries(xyz.data(), n));
  painter.paint(dabs, f, mode, m.data());
  return m;
}
} // namespace

TEST(StrokePainting, EachVertexTakesTheStrongestWeightOfItsStrokeForEveryFalloff)
{
  const std::vector<double> xyz = jittered_surface(40, 32);
  const std::vector<Dab> dabs = curved_strokes();
  for (Falloff f : all_falloffs)
  {
    const std::vector<float> expected = strongest_per_stroke(xyz, dabs, f, 0.4f);
    EXPECT_EQ(painted(xyz, dabs, f, DistanceMode::euclidean, 0.4f), expected) << falloff_name(f);
    // Where the dabs overlap, the old order compounded them: the rule did change.
    EXPECT_NE(dab_by_dab(xyz, dabs, f, 0.4f), expected) << falloff_name(f);
  }
}

TEST(StrokePainting, DabsThatShareNoVertexGiveTheValuesOfDabByDabBitForBit)
{
  // Strokes of three dabs 0.3 apart with radius 0.3 along each row of a unit grid, at
  // x = k + 0.2, 0.5, 0.8: each vertex is within the radius of one dab only (0.2 from
  // it), the middle dab reaches none; strokes of other brushes overlap earlier ones.
  const std::vector<double> xyz = geoshaping::testing::triangle_grid(12, 12, 1.0).xyz;
  std::vector<Dab> dabs;
  for (int row = 0; row < 12; ++row)
    for (int k = 0; k < 11; k += 2)
      for (double x : { 0.2, 0.5, 0.8 })
        dabs.push_back(
          dab(Eigen::Vector3d(k + x, row, 0), 0.3, row % 3 ? 0.9 : 0.1, 0.25 + 0.05 * (k % 4)));
  for (Falloff f : all_falloffs)
  {
    const std::vector<float> before = dab_by_dab(xyz, dabs, f, 0.5f);
    EXPECT_EQ(painted(xyz, dabs, f, DistanceMode::euclidean, 0.5f), before) << falloff_name(f);
    EXPECT_EQ(strongest_per_stroke(xyz, dabs, f, 0.5f), before) << falloff_name(f);
  }
}

TEST(StrokePainting, Figure5CIsTheSameAsPaintedDabByDab)
{
  FaultStepParams p;
  p.length = 30;
  p.width = 12;
  p.spacing = 0.5;
  const SampleMesh mesh = fault_step_horizon(p);
  const std::vector<Dab> dabs = fault_step_painting(p, 3.0);
  const std::vector<float> before = dab_by_dab(mesh.xyz, dabs, Falloff::constant, 0.4f);
  EXPECT_EQ(fault_step_malleability(mesh, p, 3.0), before);
  EXPECT_EQ(std::count(before.begin(), before.end(), 1.0f) > 100, true);
  EXPECT_EQ(std::count(before.begin(), before.end(), 0.0f) > 100, true);
}

TEST(StrokePainting, GeodesicStrokesTakeTheStrongestWeightOfTheirGeodesicDabs)
{
  const geoshaping::testing::Mesh grid = geoshaping::testing::triangle_grid(30, 30, 1.0);
  std::vector<Dab> dabs;
  for (int i = 0; i < 20; ++i)
    dabs.push_back(dab(Eigen::Vector3d(5 + i, 10 + 0.3 * i, 0), 3.0, 1.0, 0.5));
  const index_t n = grid.size();
  Painter painter(grid.xyz.data(), n, &grid.adjacency, brute_force_queries(grid.xyz.data(), n));
  std::vector<float> expected(std::size_t(n), 0.2f), weight(std::size_t(n), -1.0f);
  std::vector<double> best(std::size_t(n), 1e300);
  Reach reach;
  for (const Dab& d : dabs)
  {
    painter.reach(d, DistanceMode::geodesic, reach);
    for (std::size_t i = 0; i < reach.vertices.size(); ++i)
      best[reach.vertices[i]] = std::min(best[reach.vertices[i]], reach.distances[i]);
  }
  for (std::size_t v = 0; v < expected.size(); ++v)
    if (best[v] <= 3.0)
    {
      const double w = 0.5 * falloff_weight(Falloff::smooth, best[v] / 3.0);
      if (w > 0.0)
        expected[v] = float(double(0.2f) + w * (1.0 - double(0.2f)));
    }
  EXPECT_EQ(painted(grid.xyz, dabs, Falloff::smooth, DistanceMode::geodesic, 0.2f, &grid.adjacency),
    expected);
}

TEST(StrokePainting, AppendedDabsContinueTheStrokeAsIfPaintedInOneGo)
{
  const geoshaping::testing::Mesh grid = geoshaping::testing::triangle_grid(30, 30, 1.0);
  const std::vector<double>& xyz = grid.xyz;
  const std::vector<Dab> dabs = curved_strokes();
  const index_t n = grid.size();
  for (DistanceMode mode : { DistanceMode::euclidean, DistanceMode::geodesic })
    for (Falloff f : { Falloff::constant, Falloff::smooth })
    {
      const std::vector<float> whole = painted(xyz, dabs, f, mode, 0.4f, &grid.adjacency);
      Painter painter(xyz.data(), n, &grid.adjacency, brute_force_queries(xyz.data(), n));
      std::vector<float> m(std::size_t(n), 0.4f);
      // Cut inside the first stroke, then inside the second.
      painter.paint({ dabs.begin(), dabs.begin() + 17 }, f, mode, m.data());
      std::vector<index_t> touched;
      for (auto [from, to] :
        { std::pair{ 17, 33 }, std::pair{ 33, 75 }, std::pair{ 75, int(dabs.size()) } })
        painter.append({ dabs.begin() + from, dabs.begin() + to }, f, mode, m.data(), touched);
      EXPECT_EQ(m, whole) << distance_mode_name(mode) << " " << falloff_name(f);
      EXPECT_FALSE(touched.empty());
    }
}

TEST(StrokePainting, ASecondDabOnTheSameCentrePaintsAgain)
{
  const std::vector<double> xyz = geoshaping::testing::chain(5, 1.0).xyz;
  const Dab d = dab(Eigen::Vector3d(2, 0, 0), 1.5, 1.0, 0.5);
  const std::vector<float> m =
    painted(xyz, { d, d }, Falloff::constant, DistanceMode::euclidean, 0.0f);
  EXPECT_EQ(m[2], 0.75f); // 0.5, then half the way again
}

TEST(DabUnion, FindsEveryVertexWithinTheRadiusOfAnyCentreAndItsNearestDistance)
{
  const std::vector<double> xyz = jittered_surface(50, 40);
  const index_t n = index_t(xyz.size() / 3);
  const VertexGrid grid(xyz.data(), n);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> x(-10, 60), y(-10, 50), z(-3, 5);
  DabUnion u;
  for (double radius : { 0.2, 1.0, 3.7, 25.0 })
    for (std::size_t count : { 1u, 5u, 200u })
    {
      std::vector<Eigen::Vector3d> centres;
      for (std::size_t i = 0; i < count; ++i)
        centres.emplace_back(x(random), y(random), z(random));
      centres.emplace_back(1e300, 0, 0); // far away: reaches nothing
      std::vector<index_t> vertices;
      std::vector<double> distances;
      u.compute(grid, xyz.data(), centres, radius, true, vertices, distances);
      std::vector<double> got(std::size_t(n), -1.0);
      for (std::size_t i = 0; i < vertices.size(); ++i)
      {
        ASSERT_EQ(got[vertices[i]], -1.0) << "vertex " << vertices[i] << " reported twice";
        got[vertices[i]] = distances[i];
      }
      for (index_t v = 0; v < n; ++v)
      {
        double nearest = 1e308;
        for (const Eigen::Vector3d& c : centres)
          nearest = std::min(nearest, brush_distance(xyz.data(), v, c));
        EXPECT_EQ(got[v], nearest <= radius ? nearest : -1.0)
          << "vertex " << v << ", radius " << radius << ", " << count << " centres";
      }
      // Without exact distances: the same vertices, each reported within the radius.
      std::vector<index_t> inexact;
      u.compute(grid, xyz.data(), centres, radius, false, inexact, distances);
      std::sort(inexact.begin(), inexact.end());
      std::sort(vertices.begin(), vertices.end());
      EXPECT_EQ(inexact, vertices);
      for (double d : distances)
        EXPECT_LE(d, radius);
    }
}
