#include "geoshaping/haptics/force_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace geoshaping::haptics;

namespace
{
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

const Clock::time_point now = Clock::time_point(std::chrono::hours(1));

SceneSnapshot fresh_scene()
{
  SceneSnapshot s;
  s.stamp = now - std::chrono::milliseconds(10);
  s.sequence = 1;
  return s;
}

SceneSnapshot grasp(const Eigen::Vector3d& anchor, double stiffness)
{
  SceneSnapshot s = fresh_scene();
  s.grasping = true;
  s.grasp_anchor = anchor;
  s.grasp_stiffness = stiffness;
  return s;
}

// A 20 cm square in the z = 0 plane, counter-clockwise seen from +z (free side up).
SceneSnapshot floor_scene()
{
  SceneSnapshot s = fresh_scene();
  const Eigen::Vector3d a(-0.1, -0.1, 0), b(0.1, -0.1, 0), c(0.1, 0.1, 0), d(-0.1, 0.1, 0);
  s.contact_triangles = { a, b, c, a, c, d };
  return s;
}

// The force of one tick with a proxy that starts at the stylus (no history).
ForceResult compute_force(const ForceInput& in, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits)
{
  ContactProxy proxy;
  return geoshaping::haptics::compute_force(in, scene, params, limits, proxy);
}

ForceInput at(const Eigen::Vector3d& x)
{
  ForceInput in;
  in.position = x;
  in.now = now;
  return in;
}
} // namespace

TEST(ForceModel, CouplingPullsTowardTheAnchorInProportionToTheDeformation)
{
  const DeviceLimits limits;
  const ForceParams params;
  const SceneSnapshot scene = grasp(Eigen::Vector3d::Zero(), 200.0);
  const ForceResult one = compute_force(at({ 0.001, 0, 0 }), scene, params, limits);
  const ForceResult two = compute_force(at({ 0.002, 0, 0 }), scene, params, limits);
  EXPECT_EQ(one.status, ForceStatus::ok);
  EXPECT_NEAR(one.force.x(), -0.2, 1e-12);
  EXPECT_NEAR(two.force.x(), -0.4, 1e-12);
  EXPECT_EQ(one.force.y(), 0.0);
}

TEST(ForceModel, AGraspHeldBackByAnObstaclePullsTowardWhereItStopped)
{
  const DeviceLimits limits; // k_max 1000 N/m: rigid coupling 800, soft 150
  const ForceParams params;
  // Soft grasp at the origin; the stylus 3 mm along x; an obstacle dipping across the
  // drag stopped the grasp (it slid) at (1, 0.5, 0) mm.
  const Eigen::Vector3d x(0.003, 0, 0), stopped(0.001, 0.0005, 0);
  const SceneSnapshot free = grasp(Eigen::Vector3d::Zero(), 150.0);
  SceneSnapshot held = free;
  hold_grasp_back(held, stopped, params, limits);
  const ForceResult before = compute_force(at(x), free, params, limits);
  const ForceResult after = compute_force(at(x), held, params, limits);
  // Without the rule: straight back along the drag, as if nothing were in the way.
  EXPECT_NEAR(before.force.x(), -0.45, 1e-12);
  EXPECT_EQ(before.force.y(), 0.0);
  // With it: 150 (0 - stopped) + 800 (stopped - x), computed here term by term.
  const Eigen::Vector3d expected = 150.0 * (-stopped) + 800.0 * (stopped - x);
  EXPECT_NEAR(after.force.x(), expected.x(), 1e-12); // -1.75 N
  EXPECT_NEAR(after.force.y(), expected.y(), 1e-12); // +0.325 N: toward the stopped grasp
  EXPECT_GT(after.force.y(), 0.0);
  // At the stopped grasp only the deformation made pulls.
  const ForceResult there = compute_force(at(stopped), held, params, limits);
  EXPECT_NEAR((there.force - 150.0 * (-stopped)).norm(), 0.0, 1e-12);
  // A rigid grasp keeps its own stiffness; no grasp or a NaN stop changes nothing.
  SceneSnapshot rigid = grasp(Eigen::Vector3d::Zero(), 900.0);
  hold_grasp_back(rigid, stopped, params, limits);
  EXPECT_EQ(rigid.grasp_stiffness, 900.0);
  SceneSnapshot none = fresh_scene();
  hold_grasp_back(none, stopped, params, limits);
  EXPECT_FALSE(none.grasping);
  SceneSnapshot nan = free;
  hold_grasp_back(nan, Eigen::Vector3d(not_a_number, 0, 0), params, limits);
  EXPECT_EQ(nan.grasp_anchor, free.grasp_anchor);
  EXPECT_EQ(nan.grasp_stiffness, free.grasp_stiffness);
}

TEST(ForceModel, RigidGraspFeelsStifferThanSoftGrasp)
{
  const DeviceLimits limits;
  const ForceParams params;
  const double rigid = coupling_stiffness(0.0, params, limits);
  const double soft = coupling_stiffness(1.0, params, limits);
  EXPECT_DOUBLE_EQ(rigid, params.rigid_fraction * limits.max_stiffness);
  EXPECT_DOUBLE_EQ(soft, params.soft_fraction * limits.max_stiffness);
  EXPECT_GT(rigid, coupling_stiffness(0.5, params, limits));
  EXPECT_GT(coupling_stiffness(0.5, params, limits), soft);
  EXPECT_DOUBLE_EQ(coupling_stiffness(not_a_number, params, limits), rigid);
  const Eigen::Vector3d x(0.003, 0, 0);
  const double f_rigid =
    compute_force(at(x), grasp({ 0, 0, 0 }, rigid), params, limits).force.norm();
  const double f_soft = compute_force(at(x), grasp({ 0, 0, 0 }, soft), params, limits).force.norm();
  EXPECT_GT(f_rigid, 4.0 * f_soft);
}

TEST(ForceModel, StiffnessIsClampedToTheDeviceMaximum)
{
  DeviceLimits limits;
  limits.max_stiffness = 500.0;
  ForceParams params;
  params.coupling_damping = 0.0;
  const ForceResult r = compute_force(at({ 0.001, 0, 0 }), grasp({ 0, 0, 0 }, 1e6), params, limits);
  EXPECT_NEAR(r.force.x(), -0.5, 1e-12);
}

TEST(ForceModel, VirtualDampingCostsStiffnessByThePassivityRule)
{
  // K + 2 |B| / T <= K_max: at 1 kHz the default coupling damping (0.05 N s/m) leaves
  // 1000 - 100 = 900 N/m of the 1000 N/m rating; with 0.2 N s/m of contact damping as
  // well, in contact, 1000 - 500 = 500 N/m for both springs together (600 + 600 asked).
  const DeviceLimits limits;
  ForceParams params;
  EXPECT_NEAR(compute_force(at({ 0.001, 0, 0 }), grasp({ 0, 0, 0 }, 1e6), params, limits).force.x(),
    -0.9, 1e-12);
  // The rule read at a 0.5 ms period: the same damping costs 2 |B| / T = 200 N/m.
  params.servo_period = 0.0005;
  EXPECT_NEAR(compute_force(at({ 0.001, 0, 0 }), grasp({ 0, 0, 0 }, 1e6), params, limits).force.x(),
    -0.8, 1e-12);
  params.servo_period = 0.001;
  params.contact_damping = 0.2;
  params.contact_stiffness = 600.0;
  SceneSnapshot scene = floor_scene();
  scene.grasping = true;
  scene.grasp_anchor = Eigen::Vector3d(0.001, 0, -0.002);
  scene.grasp_stiffness = 600.0;
  ContactProxy proxy;
  geoshaping::haptics::compute_force(at({ 0, 0, 0.003 }), scene, params, limits, proxy);
  const ForceResult r =
    geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy);
  ASSERT_TRUE(r.in_contact);
  // Still (velocity zero): k_g = k_c = 250 N/m; the grasp pulls 1 mm along x, the proxy
  // (clearance above the floor) 2 mm up.
  EXPECT_NEAR(r.force.x(), 250.0 * 0.001, 1e-12);
  EXPECT_NEAR(r.force.z(), 250.0 * (0.002 + params.proxy_clearance), 1e-9);
  // A period that is no number renders no stiffness rather than an unbounded one.
  params.servo_period = std::nan("");
  EXPECT_EQ(compute_force(at({ 0.001, 0, 0 }), grasp({ 0, 0, 0 }, 1e6), params, limits).force,
    Eigen::Vector3d::Zero());
}

TEST(ForceModel, ForceIsScaledDownToTheDeviceMaximumKeepingItsDirection)
{
  const DeviceLimits limits;
  const ForceResult r =
    compute_force(at({ 0.3, 0.4, 0 }), grasp({ 0, 0, 0 }, 800.0), ForceParams(), limits);
  EXPECT_NEAR(r.force.norm(), limits.max_force, 1e-12);
  EXPECT_NEAR(r.force.x() / r.force.y(), 0.75, 1e-12);
}

TEST(ForceModel, ContactIsASpringFromTheStylusToTheProxy)
{
  const DeviceLimits limits;
  ForceParams params;
  params.contact_stiffness = 600.0;
  const SceneSnapshot scene = floor_scene();
  ContactProxy proxy;
  ForceResult r =
    geoshaping::haptics::compute_force(at({ 0.01, 0.02, 0.003 }), scene, params, limits, proxy);
  EXPECT_FALSE(r.in_contact);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(r.proxy, Eigen::Vector3d(0.01, 0.02, 0.003));
  r = geoshaping::haptics::compute_force(at({ 0.01, 0.02, -0.002 }), scene, params, limits, proxy);
  EXPECT_EQ(r.status, ForceStatus::ok);
  EXPECT_TRUE(r.in_contact);
  // The proxy stopped on the sheet (clearance 1 um above it), straight above the stylus.
  EXPECT_NEAR(r.proxy.z(), params.proxy_clearance, 1e-12);
  EXPECT_NEAR(r.force.z(), 600.0 * (0.002 + params.proxy_clearance), 1e-9);
  EXPECT_NEAR(r.force.head<2>().norm(), 0.0, 1e-12);
}

TEST(ForceModel, ADeepStylusIsHeldOnTheSideItCameFromWithASaturatedForce)
{
  const DeviceLimits limits;
  const ForceParams params;
  const SceneSnapshot scene = floor_scene();
  for (const double side : { 1.0, -1.0 })
  {
    ContactProxy proxy;
    geoshaping::haptics::compute_force(at({ 0, 0, side * 0.01 }), scene, params, limits, proxy);
    // 3 cm through the sheet (the old penalty shell was 5 mm): still pushed back, at
    // max force, along the normal of the side the stylus came from.
    const ForceResult r =
      geoshaping::haptics::compute_force(at({ 0, 0, -side * 0.03 }), scene, params, limits, proxy);
    EXPECT_TRUE(r.in_contact);
    EXPECT_NEAR(r.force.z(), side * limits.max_force, 1e-12);
    EXPECT_NEAR(r.proxy.z(), side * params.proxy_clearance, 1e-12);
  }
}

TEST(ForceModel, AFaultResetsTheProxy)
{
  const DeviceLimits limits;
  const ForceParams params;
  SceneSnapshot scene = floor_scene();
  ContactProxy proxy;
  geoshaping::haptics::compute_force(at({ 0, 0, 0.01 }), scene, params, limits, proxy);
  geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy);
  EXPECT_TRUE(proxy.in_contact());
  scene.stamp = Clock::time_point();
  const ForceResult r =
    geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy);
  EXPECT_EQ(r.status, ForceStatus::stale_scene);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
  EXPECT_FALSE(proxy.placed());
}

TEST(ForceModel, AStaleSceneKeepsTheProxyAndItsContactWithTheLastPatch)
{
  // A stylus resting 2 mm under the floor; the graphics side stalls. The proxy is not
  // forgotten: the last patch holds it, with its force, while the scene is stale (up to
  // stale_contact_max), and the side it is on survives a longer stall too.
  const DeviceLimits limits;
  const ForceParams params;
  SceneSnapshot scene = floor_scene();
  ContactProxy proxy;
  geoshaping::haptics::compute_force(at({ 0, 0, 0.01 }), scene, params, limits, proxy);
  const ForceResult fresh =
    geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy);
  ASSERT_TRUE(fresh.in_contact);
  const double held = params.contact_stiffness * (0.002 + params.proxy_clearance);
  for (const auto age : { std::chrono::milliseconds(150), std::chrono::milliseconds(1999) })
  {
    scene.stamp = now - age;
    const ForceResult r =
      geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy);
    EXPECT_EQ(r.status, ForceStatus::stale_scene);
    EXPECT_TRUE(r.in_contact);
    EXPECT_NEAR(r.force.z(), held, 1e-9);
    EXPECT_LT((r.proxy - fresh.proxy).norm(), 1e-15);
  }
  // Stale beyond the hold: no force, the proxy still on top.
  scene.stamp = now - std::chrono::seconds(3);
  ForceResult r =
    geoshaping::haptics::compute_force(at({ 0, 0, -0.004 }), scene, params, limits, proxy);
  EXPECT_EQ(r.status, ForceStatus::stale_scene);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
  EXPECT_TRUE(proxy.placed());
  EXPECT_GT(proxy.position().z(), 0.0);
  // A fresh scene again (another frame of the same floor): pushed back up from the side
  // the stylus came from.
  scene.stamp = now - std::chrono::milliseconds(10);
  ++scene.sequence;
  r = geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy);
  EXPECT_EQ(r.status, ForceStatus::ok);
  EXPECT_TRUE(r.in_contact);
  EXPECT_NEAR(r.force.z(), held, 1e-9);
}

TEST(ForceModel, ForceIsZeroWhenTheDeviceReportsAnError)
{
  ForceInput in = at({ 0.05, 0, 0 });
  in.device_ok = false;
  const ForceResult r = compute_force(in, grasp({ 0, 0, 0 }, 800.0), ForceParams(), DeviceLimits());
  EXPECT_EQ(r.status, ForceStatus::device_error);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
}

TEST(ForceModel, ForceIsZeroWhenTheSceneIsStaleOrWasNeverPublished)
{
  ForceParams params;
  params.stale_after = std::chrono::milliseconds(100);
  SceneSnapshot scene = grasp({ 0, 0, 0 }, 800.0);
  scene.stamp = now - std::chrono::milliseconds(101);
  ForceResult r = compute_force(at({ 0.05, 0, 0 }), scene, params, DeviceLimits());
  EXPECT_EQ(r.status, ForceStatus::stale_scene);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
  scene.stamp = Clock::time_point();
  r = compute_force(at({ 0.05, 0, 0 }), scene, params, DeviceLimits());
  EXPECT_EQ(r.status, ForceStatus::stale_scene);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
}

TEST(ForceModel, ASlowRenderersSnapshotStaysValidAsLongAsItSaysUpToTheCap)
{
  const ForceParams params; // 100 ms, at most 500 ms
  SceneSnapshot scene = grasp({ 0, 0, 0 }, 800.0);
  scene.valid_for = std::chrono::milliseconds(300); // a renderer at ~10 frames/s
  scene.stamp = now - std::chrono::milliseconds(250);
  EXPECT_EQ(
    compute_force(at({ 0.001, 0, 0 }), scene, params, DeviceLimits()).status, ForceStatus::ok);
  scene.stamp = now - std::chrono::milliseconds(301);
  EXPECT_EQ(compute_force(at({ 0.001, 0, 0 }), scene, params, DeviceLimits()).status,
    ForceStatus::stale_scene);
  // A frozen GUI cannot keep the force on beyond the cap, whatever it claimed.
  scene.valid_for = std::chrono::hours(1);
  scene.stamp = now - std::chrono::milliseconds(499);
  EXPECT_EQ(
    compute_force(at({ 0.001, 0, 0 }), scene, params, DeviceLimits()).status, ForceStatus::ok);
  scene.stamp = now - std::chrono::milliseconds(501);
  const ForceResult r = compute_force(at({ 0.001, 0, 0 }), scene, params, DeviceLimits());
  EXPECT_EQ(r.status, ForceStatus::stale_scene);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
  // Shorter than the default: the default holds.
  scene.valid_for = std::chrono::milliseconds(10);
  scene.stamp = now - std::chrono::milliseconds(90);
  EXPECT_EQ(
    compute_force(at({ 0.001, 0, 0 }), scene, params, DeviceLimits()).status, ForceStatus::ok);
}

TEST(ForceModel, ForceIsZeroWhenAnyInputIsNonFinite)
{
  const DeviceLimits limits;
  const ForceParams params;
  EXPECT_EQ(
    compute_force(at({ not_a_number, 0, 0 }), grasp({ 0, 0, 0 }, 800), params, limits).status,
    ForceStatus::non_finite);
  ForceInput moving = at({ 0.01, 0, 0 });
  moving.velocity.y() = infinity;
  EXPECT_EQ(
    compute_force(moving, grasp({ 0, 0, 0 }, 800), params, limits).status, ForceStatus::non_finite);
  EXPECT_EQ(
    compute_force(at({ 0, 0, 0 }), grasp({ 0, not_a_number, 0 }, 800), params, limits).status,
    ForceStatus::non_finite);
  EXPECT_EQ(
    compute_force(at({ 0.01, 0, 0 }), grasp({ 0, 0, 0 }, not_a_number), params, limits).status,
    ForceStatus::non_finite);
  // Overflow from an absurd position is a fault too, not an infinite pull.
  const ForceResult r =
    compute_force(at({ 1e308, -1e308, 0 }), grasp({ 0, 0, 0 }, 800), params, limits);
  EXPECT_TRUE(r.force.allFinite());
  EXPECT_LE(r.force.norm(), limits.max_force);
}

TEST(ForceModel, ANonFiniteSampleDoesNotLetAPressedStylusFallThrough)
{
  // A stylus pressed 2 mm under the floor; one sample reads NaN (a glitch of the
  // device's driver). That tick renders zero, but the proxy keeps the side the stylus
  // came from: the next finite sample, still under the floor, is pushed back up, the
  // force fading back in (a proxy reset there would start afresh under the floor and
  // let the hand fall through).
  const DeviceLimits limits;
  const ForceParams params;
  const SceneSnapshot scene = floor_scene();
  ContactProxy proxy;
  ForceFade fade;
  geoshaping::haptics::compute_force(at({ 0, 0, 0.01 }), scene, params, limits, proxy, &fade);
  ASSERT_TRUE(
    geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy, &fade)
      .in_contact);
  const ForceResult glitch = geoshaping::haptics::compute_force(
    at({ not_a_number, 0, 0 }), scene, params, limits, proxy, &fade);
  EXPECT_EQ(glitch.status, ForceStatus::non_finite);
  EXPECT_EQ(glitch.force, Eigen::Vector3d::Zero());
  const ForceResult back =
    geoshaping::haptics::compute_force(at({ 0, 0, -0.002 }), scene, params, limits, proxy, &fade);
  EXPECT_EQ(back.status, ForceStatus::ok);
  EXPECT_TRUE(back.in_contact);
  EXPECT_NEAR(back.proxy.z(), params.proxy_clearance, 1e-12);
  EXPECT_GT(back.force.z(), 0.0);
  // Faded in: no more than max force times one fade step on the first tick back.
  EXPECT_LE(back.force.norm(), limits.max_force * params.servo_period / params.fade_time + 1e-12);
}

TEST(ForceModel, ForceNeverExceedsTheMaximumAndIsNeverNaNOverRandomInputs)
{
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 9);
  // Mostly sensible values, sometimes NaN, infinities, huge or tiny ones.
  auto value = [&](double scale)
  {
    switch (pick(rng))
    {
      case 0:
        return not_a_number;
      case 1:
        return unit(rng) > 0 ? infinity : -infinity;
      case 2:
        return unit(rng) * 1e300;
      case 3:
        return unit(rng) * 1e-300;
      default:
        return unit(rng) * scale;
    }
  };
  auto vec = [&](double scale)
  { return Eigen::Vector3d(value(scale), value(scale), value(scale)); };
  DeviceLimits limits;
  limits.max_force = 2.5;
  int rendered = 0;
  for (int i = 0; i < 20000; ++i)
  {
    SceneSnapshot scene;
    scene.stamp = now - std::chrono::milliseconds(int(std::abs(unit(rng)) * 150)); // some stale
    scene.grasping = pick(rng) < 7;
    scene.grasp_anchor = vec(0.1);
    scene.grasp_stiffness = value(5000.0);
    for (int t = 0; t < 3 * (pick(rng) % 4); ++t)
      scene.contact_triangles.push_back(vec(0.1));
    ForceInput in = at(vec(0.1));
    in.velocity = vec(1.0);
    in.device_ok = pick(rng) != 0;
    const ForceResult r = compute_force(in, scene, ForceParams(), limits);
    ASSERT_TRUE(r.force.allFinite()) << "sample " << i;
    ASSERT_LE(r.force.norm(), limits.max_force * (1 + 1e-12)) << "sample " << i;
    // Faults render zero; a stale scene may still hold contact (its coupling is off).
    if (r.status == ForceStatus::device_error || r.status == ForceStatus::non_finite)
    {
      ASSERT_EQ(r.force, Eigen::Vector3d::Zero()) << "sample " << i;
    }
    rendered += r.force != Eigen::Vector3d::Zero();
  }
  // The sweep must exercise real forces, not only faults.
  EXPECT_GT(rendered, 500);
}

TEST(ForceModel, AtRestTheSceneAsksForItsForceHoweverOldItIs)
{
  const DeviceLimits limits;
  const ForceParams params;
  // A grasp published an hour ago (stale to the servo, which would have faded it out):
  // at rest it asks for the whole coupling k_g (anchor - x), as when it was fresh.
  SceneSnapshot scene = grasp({ 0.0, 0.01, 0.0 }, 200.0);
  scene.stamp = Clock::time_point(std::chrono::seconds(1));
  DeviceSnapshot device;
  device.device_ok = true;
  device.sample.position = Eigen::Vector3d(0.0, 0.0, 0.002);
  ForceResult r = force_at_rest(device, scene, params, limits);
  EXPECT_EQ(r.status, ForceStatus::ok);
  EXPECT_FALSE(r.in_contact);
  EXPECT_EQ(r.force, Eigen::Vector3d(0.0, 200.0 * 0.01, 200.0 * -0.002));
  // Pressed 2 mm into the floor, its proxy on top (where the servo's ticks left it): the
  // contact spring k_c (proxy - x) up; a stylus whose proxy the servo never saw in
  // contact starts below and feels nothing.
  scene = floor_scene();
  device.sample.position = Eigen::Vector3d(0.01, 0.02, -0.002);
  device.in_contact = true;
  device.proxy = Eigen::Vector3d(0.01, 0.02, params.proxy_clearance);
  r = force_at_rest(device, scene, params, limits);
  EXPECT_TRUE(r.in_contact);
  EXPECT_NEAR(r.force.z(), params.contact_stiffness * (0.002 + params.proxy_clearance), 1e-12);
  EXPECT_NEAR(r.force.head<2>().norm(), 0.0, 1e-12);
  device.in_contact = false;
  EXPECT_EQ(force_at_rest(device, scene, params, limits).force, Eigen::Vector3d::Zero());
  // A failed device asks for nothing.
  device.in_contact = true;
  device.device_ok = false;
  r = force_at_rest(device, scene, params, limits);
  EXPECT_EQ(r.status, ForceStatus::device_error);
  EXPECT_EQ(r.force, Eigen::Vector3d::Zero());
}
