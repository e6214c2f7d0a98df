#include "geoshaping/haptics/proxy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace geoshaping::haptics;

namespace
{
constexpr double clearance = 1e-6;
constexpr double reach = 0.005;
constexpr double pi = 3.14159265358979323846;

using Soup = std::vector<Eigen::Vector3d>;

// An open sheet z = 0 over [-0.05, 0.05]^2 cut into a fan of `n` triangles around the
// origin: edges and a vertex of valence n under the stylus.
Soup fan(int n)
{
  Soup s;
  for (int i = 0; i < n; ++i)
  {
    const double a0 = 2 * pi * i / n, a1 = 2 * pi * (i + 1) / n;
    s.push_back(Eigen::Vector3d::Zero());
    s.push_back(0.05 * Eigen::Vector3d(std::cos(a0), std::sin(a0), 0));
    s.push_back(0.05 * Eigen::Vector3d(std::cos(a1), std::sin(a1), 0));
  }
  return s;
}

// A strip of slivers: the square [-0.05, 0.05]^2 at z = 0 cut along y into `n` strips of
// two triangles each, 100 : 1 aspect for n = 100.
Soup slivers(int n)
{
  Soup s;
  for (int i = 0; i < n; ++i)
  {
    const double y0 = -0.05 + 0.1 * i / n, y1 = -0.05 + 0.1 * (i + 1) / n;
    const Eigen::Vector3d a(-0.05, y0, 0), b(0.05, y0, 0), c(0.05, y1, 0), d(-0.05, y1, 0);
    s.insert(s.end(), { a, b, c, a, c, d });
  }
  return s;
}

// A V fold along the x axis: two half-planes rising at `angle` from the y = 0 line, the
// inside of the V up (a concave fold seen from above).
Soup valley(double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector3d a(-0.05, 0, 0), b(0.05, 0, 0);
  const Eigen::Vector3d l(0, -0.05 * c, 0.05 * s), r(0, 0.05 * c, 0.05 * s);
  return { a, b, b + l, a, b + l, a + l, a, b + r, b, a, a + r, b + r };
}

// Drives the proxy along a path of stylus positions; checks that the spring vector
// e = p - x never changes by more than the stylus moved plus `slack` in one tick and
// that the proxy stays on the side of z(p) it started, as `side` says.
double worst_excess(ContactProxy& proxy, const Soup& soup, const std::vector<Eigen::Vector3d>& path)
{
  double worst = -1.0;
  Eigen::Vector3d e_last = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < path.size(); ++i)
  {
    proxy.update(path[i], soup, clearance, reach);
    const Eigen::Vector3d e = proxy.position() - path[i];
    if (i > 0)
      worst = std::max(worst, (e - e_last).norm() - (path[i] - path[i - 1]).norm());
    e_last = e;
  }
  return worst;
}
} // namespace

TEST(Proxy, FirstHitFindsTheNearestCrossingFromEitherSide)
{
  const Soup s = { { -1, -1, 0 }, { 1, -1, 0 }, { 0, 1, 0 }, { -1, -1, 1 }, { 1, -1, 1 },
    { 0, 1, 1 } };
  SegmentHit h = first_hit({ 0, 0, -1 }, { 0, 0, 3 }, s);
  EXPECT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 1.0 / 3, 1e-15);
  EXPECT_EQ(h.normal, Eigen::Vector3d(0, 0, -1));
  h = first_hit({ 0, 0, 2 }, { 0, 0, -3 }, s);
  EXPECT_NEAR(h.t, 1.0 / 3, 1e-15);
  EXPECT_EQ(h.normal, Eigen::Vector3d(0, 0, 1));
  EXPECT_FALSE(first_hit({ 0, 0, 2 }, { 0, 0, 0.5 }, s).hit);
  EXPECT_FALSE(first_hit({ 5, 0, 2 }, { 0, 0, -3 }, s).hit);
  // Through a shared edge: one of the two triangles is hit.
  EXPECT_TRUE(first_hit({ 0, 0, 1 }, { 0, 0, -2 }, fan(6)).hit);
  EXPECT_TRUE(first_hit({ 0.01, 0, 1 }, { 0, 0, -2 }, fan(6)).hit);
}

TEST(Proxy, AnOpenSheetHoldsTheProxyOnTheSideItCameFrom)
{
  for (const double side : { 1.0, -1.0 })
  {
    ContactProxy proxy;
    proxy.update({ 0.01, 0.01, side * 0.01 }, fan(7), clearance, reach);
    EXPECT_FALSE(proxy.in_contact());
    proxy.update({ 0.02, 0.0, -side * 0.04 }, fan(7), clearance, reach);
    EXPECT_TRUE(proxy.in_contact());
    EXPECT_NEAR(proxy.position().z(), side * clearance, 1e-15);
    EXPECT_NEAR(proxy.position().x(), 0.02, 1e-12);
    EXPECT_EQ(proxy.normal(), Eigen::Vector3d(0, 0, side));
    // Coming back out: the proxy rejoins the stylus.
    proxy.update({ 0.0, 0.01, side * 0.002 }, fan(7), clearance, reach);
    EXPECT_FALSE(proxy.in_contact());
    EXPECT_EQ(proxy.position(), Eigen::Vector3d(0.0, 0.01, side * 0.002));
  }
}

TEST(Proxy, SlidingAcrossEdgesVerticesAndSliversGivesNoStepBeyondTheMotion)
{
  // 3 mm under the sheet, circles and a line through the fan's centre vertex and across
  // 100 slivers: the proxy slides on one plane, so e = p - x changes by at most |dx|.
  for (const Soup& soup : { fan(9), slivers(100) })
  {
    ContactProxy proxy;
    proxy.update({ 0.001, 0.002, 0.01 }, soup, clearance, reach);
    std::vector<Eigen::Vector3d> path;
    for (int k = 0; k <= 4000; ++k)
    {
      const double t = k * 1e-3;
      path.emplace_back(0.02 * std::sin(2 * pi * 0.5 * t), 0.03 * std::sin(2 * pi * 0.3 * t),
        -0.003 + 0.001 * std::sin(2 * pi * t));
    }
    EXPECT_LT(worst_excess(proxy, soup, path), 1e-9);
    EXPECT_GT(proxy.position().z(), 0.0);
  }
}

TEST(Proxy, PressingIntoAConcaveFoldProjectsOntoTheWedge)
{
  // The V rises at 30 degrees; the stylus presses 4 mm into it and slides across the
  // fold line and along it. The proxy sits on the wedge: on one face, or on the fold
  // line when both push.
  const Soup soup = valley(pi / 6);
  ContactProxy proxy;
  proxy.update({ 0, 0, 0.02 }, soup, clearance, reach);
  std::vector<Eigen::Vector3d> path;
  for (int k = 0; k <= 3000; ++k)
  {
    const double t = k * 1e-3;
    path.emplace_back(0.01 * std::sin(2 * pi * 0.4 * t), 0.015 * std::sin(2 * pi * t), -0.004);
  }
  // Within the clearance: where the proxy stops against the second plane it is
  // `clearance` off that one but only about that off the first.
  EXPECT_LT(worst_excess(proxy, soup, path), 2 * clearance);
  // Straight down on the fold line: held on the line (both planes active).
  proxy.update({ 0, 0, -0.004 }, soup, clearance, reach);
  EXPECT_TRUE(proxy.in_contact());
  EXPECT_NEAR(proxy.position().y(), 0.0, clearance);
  EXPECT_NEAR(proxy.position().z(), 0.0, 2 * clearance);
  EXPECT_GT(proxy.position().z(), 0.0);
}

TEST(Proxy, SlidingOverAConvexCrestGivesNoStepBeyondTheMotionAndCatchesUp)
{
  // A ridge along the x axis, its faces falling at 30 degrees (valley() upside down); the
  // stylus, 2 mm deep, slides across the crest line at 0.05 mm a tick and on down the far
  // face. A god-object would turn the spring from one face's normal to the other's in one
  // tick (a step of about 1 mm); the proxy turns it within the motion and is back on its
  // god-object position, the projection onto the far face, 5 mm past the crest.
  const double angle = pi / 6, depth = 0.002;
  const Soup soup = valley(-angle);
  auto below = [&](double y)
  { return Eigen::Vector3d(0.001, y, -std::abs(y) * std::tan(angle) - depth); };
  ContactProxy proxy;
  proxy.update({ 0.001, -0.01, 0.01 }, soup, clearance, reach);
  std::vector<Eigen::Vector3d> path;
  for (int k = 0; k <= 300; ++k)
    path.push_back(below(-0.01 + 0.00005 * k));
  EXPECT_LT(worst_excess(proxy, soup, path), 1e-12);
  const Eigen::Vector3d n(0, std::sin(angle), std::cos(angle));
  const Eigen::Vector3d on_face = path.back() + (depth * std::cos(angle) + clearance) * n;
  EXPECT_LT((proxy.position() - on_face).norm(), 1e-9);
  EXPECT_TRUE(proxy.in_contact());
  EXPECT_LT((proxy.normal() - n).norm(), 1e-12);
  // Back over the crest the other way, and a stylus stopped just past it: still within
  // the motion, the proxy held still.
  std::vector<Eigen::Vector3d> back;
  for (int k = 0; k <= 204; ++k)
    back.push_back(below(0.005 - 0.00005 * k));
  back.insert(back.end(), 50, back.back());
  EXPECT_LT(worst_excess(proxy, soup, back), 1e-12);
  EXPECT_TRUE(proxy.in_contact());
  EXPECT_GT(proxy.position().z(), -std::abs(proxy.position().y()) * std::tan(angle));
}

TEST(Proxy, AShallowCreaseKeepsContactOnEveryTick)
{
  // A valley of 0.003 rad faces, the stylus 1.4 mm under its crease line: x projected on
  // either face lands just across the crease, within the clearance band where the sweep
  // meets nothing, so the sweeps zig-zag between the faces and run out of passes. The
  // proxy is still on the surface: contact (and force) on every tick.
  const Soup soup = valley(0.003);
  ContactProxy proxy;
  proxy.update({ 0.0, 0.0, 0.01 }, soup, clearance, reach);
  std::vector<Eigen::Vector3d> path;
  for (int k = 0; k <= 1000; ++k)
    path.emplace_back(
      0.01 * std::sin(2 * pi * k / 1000), 5e-6 * std::sin(2 * pi * k / 100), -0.0014);
  for (std::size_t k = 0; k < path.size(); ++k)
  {
    proxy.update(path[k], soup, clearance, reach);
    ASSERT_TRUE(proxy.in_contact()) << k;
    ASSERT_GT(proxy.position().z(), 0.0) << k;
  }
  ContactProxy again;
  again.update({ 0.0, 0.0, 0.01 }, soup, clearance, reach);
  EXPECT_LT(worst_excess(again, soup, path), 2 * clearance);
}

TEST(Proxy, NeverCrossesACorrugatedDoubleSheetOverRandomMotions)
{
  // Two corrugated sheets 1 mm apart, z = f(x) and f(x) - 1 mm, with f a zig-zag of 4 mm
  // amplitude and 1 cm period (ridges and valleys of about 39 degrees), each zig cut in
  // slivers; the stylus jumps anywhere in the box (up to 6 cm a tick), mostly far below.
  // The proxy, which started above, must stay above the upper sheet: z > f(x) always.
  auto f = [](double x)
  {
    const double phase = (x + 0.05) / 0.01;
    const double w = phase - std::floor(phase);
    return 0.004 * (w < 0.5 ? 2 * w : 2 - 2 * w) - 0.002;
  };
  Soup soup;
  for (const double shift : { 0.0, -0.001 })
  {
    for (int i = 0; i < 20; ++i)
    {
      const double x0 = -0.05 + 0.005 * i, x1 = x0 + 0.005;
      const Eigen::Vector3d a(x0, -0.05, f(x0) + shift), b(x1, -0.05, f(x1) + shift),
        c(x1, 0.05, f(x1) + shift), d(x0, 0.05, f(x0) + shift);
      soup.insert(soup.end(), { a, b, c, a, c, d });
    }
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  ContactProxy proxy;
  proxy.update({ 0.0, 0.0, 0.02 }, soup, clearance, reach);
  int contacts = 0;
  for (int k = 0; k < 20000; ++k)
  {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng) - 0.01);
    proxy.update(x, soup, clearance, reach);
    const Eigen::Vector3d& p = proxy.position();
    ASSERT_TRUE(p.allFinite());
    ASSERT_GT(p.z() - f(p.x()), 0.0) << "tick " << k;
    contacts += proxy.in_contact();
  }
  EXPECT_GT(contacts, 5000);
}

TEST(Proxy, ANewPatchOfTheSameSurfaceDoesNotMoveTheProxy)
{
  ContactProxy proxy;
  proxy.update({ 0.003, 0.001, 0.01 }, fan(5), clearance, reach);
  proxy.update({ 0.003, 0.001, -0.002 }, fan(5), clearance, reach);
  const Eigen::Vector3d before = proxy.position();
  // Re-triangulated (slivers instead of a fan), re-sent: the proxy stays.
  proxy.carry_over(2, slivers(50), reach, clearance);
  EXPECT_LT((proxy.position() - before).norm(), 1e-14);
  proxy.update({ 0.003, 0.001, -0.002 }, slivers(50), clearance, reach);
  EXPECT_LT((proxy.position() - before).norm(), 1e-12);
}

TEST(Proxy, ASurfaceMovingThroughTheStylusCarriesTheProxyWithIt)
{
  // The stylus rests 1 mm above a sheet; the sheet rises 0.5 mm per patch, past the
  // stylus: the proxy rides on it and the spring pushes the stylus up; the same from
  // below. Without carry_over the stylus would end up on the far side, force-free.
  for (const double side : { 1.0, -1.0 })
  {
    auto sheet = [&](double z)
    {
      Soup s = slivers(10);
      for (auto& v : s)
        v.z() = z;
      return s;
    };
    ContactProxy proxy;
    const Eigen::Vector3d x(0.01, 0.01, side * 0.001);
    proxy.update(x, sheet(0), clearance, reach);
    for (int frame = 1; frame <= 8; ++frame)
    {
      const double z = side * 0.0005 * frame;
      proxy.carry_over(std::uint64_t(frame + 1), sheet(z), reach, clearance);
      proxy.update(x, sheet(z), clearance, reach);
      EXPECT_GT(side * (proxy.position().z() - z), 0.0) << frame;
      EXPECT_EQ(proxy.in_contact(), frame >= 2) << frame; // level with it from frame 2
    }
    EXPECT_NEAR(proxy.position().z(), side * (0.004 + clearance), 1e-12);
  }
}
