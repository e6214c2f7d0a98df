#include "geoshaping/haptics/hand_sim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace geoshaping::haptics;

namespace
{
using Soup = std::vector<Eigen::Vector3d>;

// The 10 cm open sheet z = 0, centred on the origin, in 2 x 10 x 10 triangles.
Soup sheet(double z = 0.0)
{
  Soup s;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
    {
      const double x0 = -0.05 + 0.01 * i, y0 = -0.05 + 0.01 * j;
      const Eigen::Vector3d a(x0, y0, z), b(x0 + 0.01, y0, z), c(x0 + 0.01, y0 + 0.01, z),
        d(x0, y0 + 0.01, z);
      s.insert(s.end(), { a, b, c, a, c, d });
    }
  return s;
}

SceneAt still(const Soup& soup)
{
  return [soup](double, Soup& out) { out = soup; };
}

// The sheet rising at `rising_speed` (3 cm/s: 0.48 mm per 16 ms patch).
constexpr double rising_speed = 0.03;
SceneAt rising_sheet()
{
  return [](double t, Soup& out) { out = sheet(rising_speed * t); };
}

std::vector<HandKey> push(const Eigen::Vector3d& f, double seconds)
{
  return { { 0.0, Eigen::Vector3d::Zero() }, { 0.2, f }, { seconds, f } };
}

struct SimRun
{
  std::vector<TrajectoryRow> rows;
  RunFigures figures;
  double energy = 0.0; // injected (hand_sim.h)
  double work = 0.0;   // the rendered force's on the stylus (hand_sim.h)
};

SimRun run(const SceneAt& scene, const std::vector<HandKey>& hand, const Eigen::Vector3d& start,
  const HandSimOptions& options = {})
{
  SimRun r;
  const DeviceModel model;
  r.rows = simulate_hand(scene, hand, start, model, options, &r.energy, &r.work);
  r.figures = run_figures(r.rows, model, options);
  return r;
}

// How far a tick's force step may exceed k_c |dx|: the passivity controller's damper
// changes by at most the fade's step a tick (passivity.h), and never where a fade moved.
double damper_step()
{
  const ForceParams params;
  return DeviceLimits().max_force * params.servo_period / params.fade_time + 1e-9;
}

// How deep under a surface a hand pushing `f` N rests on the contact spring (k_c).
double shell_of(double f)
{
  return f / ForceParams().contact_stiffness;
}

// Largest force step a stylus moving by one position quantum per tick may cause.
double quantum_step()
{
  return ForceParams().contact_stiffness * DeviceModel().resolution;
}
} // namespace

TEST(HandSim, HandCsvIsReadStrictly)
{
  std::vector<HandKey> keys;
  std::string error;
  std::istringstream good("t,fx,fy,fz\n0,0,0,0\n\n0.5, 1, 2, -3\n1,0,0,0\n");
  ASSERT_TRUE(read_hand_csv(good, keys, error)) << error;
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_EQ(hand_force_at(keys, 0.25), Eigen::Vector3d(0.5, 1, -1.5));
  EXPECT_EQ(hand_force_at(keys, 7.0), Eigen::Vector3d::Zero());
  for (const char* bad : { "", "t,x,y,z\n0,0,0,0\n", "t,fx,fy,fz\n", "t,fx,fy,fz\n0,0,0\n",
         "t,fx,fy,fz\n0,0,0,0,0\n", "t,fx,fy,fz\n0,0,0,nan\n", "t,fx,fy,fz\n0,0,0,1N\n",
         "t,fx,fy,fz\n0,0,0,0\n0,1,1,1\n", "t,fx,fy,fz\n-1,0,0,0\n", "t,fx,fy,fz\n0,0,0,0,\n" })
  {
    std::istringstream in(bad);
    EXPECT_FALSE(read_hand_csv(in, keys, error)) << bad;
    EXPECT_FALSE(error.empty());
  }
}

TEST(HandSim, AFreeStylusAcceleratesAsTheDeviceModelSays)
{
  // No scene, 0.15 N along x for 0.2 s after a 0.2 s ramp: v = impulse / m less damping and
  // friction; checked against the closed form of m v' = F(t) - b v - F_c within 2 %.
  DeviceModel model;
  const std::vector<HandKey> hand = { { 0.0, { 0, 0, 0 } }, { 0.2, { 0.15, 0, 0 } },
    { 0.4, { 0.15, 0, 0 } } };
  const auto rows =
    simulate_hand([](double, Soup& s) { s.clear(); }, hand, Eigen::Vector3d::Zero(), model, {});
  ASSERT_EQ(rows.size(), 401u);
  // Closed form by fine integration of the same ODE (independent of the substeps).
  double v = 0.0, x = 0.0;
  const double h = 1e-6;
  for (double t = 0.0; t < 0.4; t += h)
  {
    const double f = hand_force_at(hand, t).x() - model.damping * v;
    v =
      std::max(0.0, v + h * (f - (v > 0 || f > model.friction ? model.friction : f)) / model.mass);
    x += h * v;
  }
  EXPECT_NEAR(rows.back().x.x(), x, 0.02 * x);
  EXPECT_EQ(rows.back().force, Eigen::Vector3d::Zero());
}

TEST(HandSim, PressingWithTwoNewtonsRestsOnTheSheet)
{
  const SimRun r = run(still(sheet()), push({ 0, 0, -2 }, 2.0), { 0.0, 0.0, 0.01 });
  const TrajectoryRow& last = r.rows.back();
  EXPECT_TRUE(last.contact);
  // At rest the spring balances the hand: 2 N / 800 N/m = 2.5 mm, within a quantum.
  EXPECT_NEAR(last.x.z(), -2.0 / ForceParams().contact_stiffness, DeviceModel().resolution);
  EXPECT_NEAR(last.force.z(), 2.0, quantum_step() + 0.06);
  EXPECT_GT(last.proxy.z(), 0.0);
  EXPECT_LE(r.figures.max_step_excess, damper_step());
}

TEST(HandSim, PressingHarderThanTheDeviceIsASteadySaturatedForceNotAFallThrough)
{
  // 5 N against a 3.3 N device: the stylus sinks, the force stays at 3.3 N upward, the
  // proxy stays on the sheet; no step beyond what the motion gives.
  const SimRun r = run(still(sheet()), push({ 0, 0, -5 }, 1.0), { 0.0, 0.0, 0.01 });
  const double f_max = DeviceModel().limits.max_force;
  int saturated = 0;
  for (const TrajectoryRow& row : r.rows)
  {
    ASSERT_GT(row.proxy.z(), 0.0);
    ASSERT_GE(row.force.z(), 0.0);
    saturated += std::abs(row.force.z() - f_max) < 1e-9;
  }
  EXPECT_GT(saturated, 500);
  EXPECT_NEAR(r.rows.back().force.z(), f_max, 1e-9);
  EXPECT_LE(r.figures.max_step_excess, damper_step());
  EXPECT_LE(r.energy, 0.0);
}

TEST(HandSim, ComingFromTheBackSideIsFeltOnTheBackSide)
{
  const SimRun r = run(still(sheet()), push({ 0, 0, 0.5 }, 1.5), { 0.0, 0.0, -0.01 });
  for (const TrajectoryRow& row : r.rows)
  {
    // The stylus arrives at speed and may overshoot the sheet; the proxy holds.
    ASSERT_LT(row.proxy.z(), 0.0);
    ASSERT_LE(row.force.z(), 1e-12);
  }
  EXPECT_NEAR(r.rows.back().x.z(), 0.5 / ForceParams().contact_stiffness, DeviceModel().resolution);
  EXPECT_NEAR(r.rows.back().force.z(), -0.5, quantum_step() + 0.06);
  EXPECT_LE(r.figures.max_step_excess, damper_step());
}

TEST(HandSim, SlidingAcrossAPatchReplacedEvery16msGivesNoStep)
{
  // 1 N down and 0.1 N sideways (about 8 cm/s) over the 200 triangles, a patch of the
  // 12 nearest re-sent every 16 ms (so triangles enter and leave the patch under the
  // stylus).
  HandSimOptions options;
  options.max_triangles = 12;
  const std::vector<HandKey> hand = { { 0.0, { 0, 0, -1 } }, { 0.3, { 0, 0, -1 } },
    { 0.5, { 0.08, 0.06, -1 } }, { 1.2, { 0.08, 0.06, -1 } } };
  const SimRun r = run(still(sheet()), hand, { -0.03, -0.03, 0.002 }, options);
  EXPECT_GT(r.rows.back().x.x(), 0.0); // it did slide across triangles
  for (const TrajectoryRow& row : r.rows)
    ASSERT_GT(row.proxy.z(), 0.0);
  EXPECT_LE(r.figures.max_step_excess, damper_step());
  EXPECT_LE(r.energy, 0.0);
}

TEST(HandSim, WithTheScenesWorkCreditedARisingSurfacePushesTheStylusWithoutAStep)
{
  // The sheet rises 3 cm/s (0.48 mm per 16 ms patch) under a stylus pressing 1 N, the
  // scene's work credited (ForceParams::credit_scene_work): it is carried up, on top, and
  // each patch changes the force by at most k times the surface's motion in that patch
  // plus the stylus's own motion.
  const double speed = rising_speed;
  HandSimOptions options;
  options.force.credit_scene_work = true;
  const SimRun r = run(rising_sheet(), push({ 0, 0, -1 }, 1.0), { 0.0, 0.0, 0.003 }, options);
  const double k = ForceParams().contact_stiffness;
  for (std::size_t i = 1; i < r.rows.size(); ++i)
  {
    const TrajectoryRow& row = r.rows[i];
    ASSERT_GT(row.proxy.z(), speed * row.t - 0.016 * speed);
    const double step = (row.force - r.rows[i - 1].force).norm();
    const double motion = (row.x - r.rows[i - 1].x).norm() + 2 * DeviceModel().resolution;
    ASSERT_LE(step, k * (motion + 0.016 * speed) + 1e-9) << row.t;
  }
  std::cout << "rising sheet, the scene's work credited: work " << r.work * 1e3 << " mJ\n";
  EXPECT_NEAR(r.rows.back().x.z(), speed * 1.0 - 1.0 / k, 0.001);
  EXPECT_GT(r.work, 0.0); // the scene's work, passed on to the hand
}

TEST(HandSim, ASurfaceRisingUnderARestingStylusPassesThroughItInsteadOfLiftingTheHand)
{
  // The same sheet and hand by default: the energy bound (passivity.h) scales the contact
  // force down as the carried proxy stretches the spring beyond what the rendering
  // absorbed, so the hand sinks through the rising sheet instead of being lifted: the
  // proxy stays on top (the side is kept), the rendered work is not positive, and no
  // force step exceeds k times the motion and the carry by more than the fades' step.
  const double speed = rising_speed;
  const SimRun r = run(rising_sheet(), push({ 0, 0, -1 }, 1.0), { 0.0, 0.0, 0.003 });
  const double k = ForceParams().contact_stiffness;
  double through = -1.0; // when the stylus got under the sheet
  for (std::size_t i = 1; i < r.rows.size(); ++i)
  {
    const TrajectoryRow& row = r.rows[i];
    if (row.contact)
      ASSERT_GT(row.proxy.z(), speed * row.t - 0.016 * speed) << row.t;
    const double step = (row.force - r.rows[i - 1].force).norm();
    const double motion = (row.x - r.rows[i - 1].x).norm() + 2 * DeviceModel().resolution;
    ASSERT_LE(step, k * (motion + 0.016 * speed) + damper_step()) << row.t;
    if (through < 0.0 && speed * row.t - row.x.z() > shell_of(DeviceLimits().max_force))
      through = row.t;
  }
  std::cout << "rising sheet: deeper than the shell from " << through << " s, end z "
            << r.rows.back().x.z() * 1e3 << " mm, force " << r.rows.back().force.z() << " N, work "
            << r.work * 1e3 << " mJ, injected " << r.energy * 1e3 << " mJ\n";
  EXPECT_LT(r.rows.back().x.z(), speed * 1.0 - shell_of(1.0)); // not lifted: through it
  EXPECT_TRUE(r.rows.back().contact);
  EXPECT_GT(r.rows.back().proxy.z(), speed * 1.0 - 0.016 * speed); // the side is kept
  EXPECT_LE(r.work, 0.0);
}

namespace
{
// A grid surface z = h(x, y) over [-0.05, 0.05]^2 in nx x ny quads, two triangles each.
template<class Height>
Soup grid(int nx, int ny, Height h)
{
  Soup s;
  auto at = [&](int i, int j)
  {
    const double x = -0.05 + 0.1 * i / nx, y = -0.05 + 0.1 * j / ny;
    return Eigen::Vector3d(x, y, h(x, y));
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s.insert(s.end(),
        { at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1) });
  return s;
}

// The fault step: a plateau z = 0 for y < -5 mm, a 45 degree ramp down to z = -1 cm at
// y = +5 mm, a lower plateau: a convex crest, then a concave fold.
double fault_step(double, double y)
{
  return y < -0.005 ? 0.0 : y > 0.005 ? -0.01 : -(y + 0.005);
}
} // namespace

TEST(HandSim, SlidingOverACrestAFoldEdgesAndSliversStaysWithinTheStepBound)
{
  // The hand presses 1 N and drags along +y over: the fault step (its crest, where a
  // point god-object stepped 0.72 N in a tick, then its foot, a concave fold); a ridge of
  // 30 degree faces (a crest turning the normal by 60 degrees), climbed; a valley of 30
  // degree faces (a fold) slid into and across; a fan of 9 triangles whose centre vertex
  // the path passes 0.3 mm off (edges and a vertex); 500 slivers of 250 : 1 crossed at a
  // slant. The largest force step of any tick is at most k_c times the quantised motion
  // of that tick, and the stylus got past the feature (y beyond `past`).
  const double pi = 3.14159265358979323846, tan30 = std::tan(pi / 6);
  struct Case
  {
    const char* name;
    Soup soup;
    Eigen::Vector3d start;
    double pull; // N along +y
    double past; // m
  };
  Soup fan;
  for (int i = 0; i < 9; ++i)
    fan.insert(fan.end(),
      { Eigen::Vector3d::Zero(),
        0.05 * Eigen::Vector3d(std::cos(2 * pi * i / 9), std::sin(2 * pi * i / 9), 0),
        0.05 *
          Eigen::Vector3d(std::cos(2 * pi * (i + 1) / 9), std::sin(2 * pi * (i + 1) / 9), 0) });
  const std::vector<Case> cases = {
    { "fault step", grid(10, 8, fault_step), { 0.001, -0.02, 0.002 }, 0.1, 0.005 },
    { "ridge", grid(4, 20, [&](double, double y) { return -std::abs(y) * tan30; }),
      { 0.001, -0.012, -0.012 * tan30 + 0.002 }, 0.8, 0.005 },
    { "valley", grid(4, 20, [&](double, double y) { return std::abs(y) * tan30; }),
      { 0.001, -0.02, 0.02 * tan30 + 0.002 }, 0.1, 0.0 },
    { "fan", fan, { 0.0003, -0.02, 0.002 }, 0.1, 0.005 },
    { "slivers", grid(1, 250, [](double, double) { return 0.0; }), { -0.01, -0.02, 0.002 }, 0.1,
      0.005 },
  };
  for (const Case& c : cases)
  {
    const std::vector<HandKey> hand = { { 0.0, { 0, 0, -1 } }, { 0.3, { 0, 0, -1 } },
      { 0.5, { 0.01, c.pull, -1 } }, { 0.9, { 0.01, c.pull, -1 } } };
    const SimRun r = run(still(c.soup), hand, c.start);
    double furthest = -1.0;
    for (const TrajectoryRow& row : r.rows)
      furthest = std::max(furthest, row.x.y());
    std::cout << c.name << ": largest step " << r.figures.max_force_step << " N, beyond k |dx| "
              << r.figures.max_step_excess << " N, injected " << r.energy << " J\n";
    EXPECT_GT(furthest, c.past) << c.name;
    EXPECT_LE(r.figures.max_step_excess, damper_step()) << c.name;
    EXPECT_LE(r.energy, 0.0) << c.name;
  }
}

TEST(HandSim, TheSimulatedDeviceMeetsTheRatingThePassivityRuleAssumes)
{
  // The rendering keeps K + 2 |B| / T <= K_max (force_model.h), which is passive on any
  // device whose damping b honours its own stiffness rating, b >= K_max T / 2. The
  // simulated Touch is such a device (0.6 > 0.5 N s/m), so the runs below are a fair test.
  const DeviceModel device;
  EXPECT_GE(device.damping, device.limits.max_stiffness * device.period / 2);
  EXPECT_EQ(ForceParams().servo_period, device.period);
}

namespace
{
// Hold, tap, release: 1.5 N onto the sheet, held; five 20 ms taps of 3 N; held again;
// then the hand lifts (0.5 N up for 0.1 s) and lets go.
std::vector<HandKey> hold_tap_release()
{
  std::vector<HandKey> h = { { 0.0, { 0, 0, -1.5 } }, { 0.8, { 0, 0, -1.5 } } };
  for (int i = 0; i < 5; ++i)
  {
    const double t = 0.8 + 0.1 * i;
    h.push_back({ t + 0.001, { 0, 0, -3 } });
    h.push_back({ t + 0.02, { 0, 0, -3 } });
    h.push_back({ t + 0.021, { 0, 0, -1.5 } });
    h.push_back({ t + 0.1, { 0, 0, -1.5 } });
  }
  h.push_back({ 1.8, { 0, 0, -1.5 } });
  h.push_back({ 1.81, { 0, 0, 0.5 } });
  h.push_back({ 1.91, { 0, 0, 0.5 } });
  h.push_back({ 1.92, { 0, 0, 0 } });
  h.push_back({ 3.0, { 0, 0, 0 } });
  return h;
}
} // namespace

TEST(HandSim, HoldTapReleaseAtMaxStiffnessInjectsNoEnergyAndSettles)
{
  HandSimOptions options;
  options.force.contact_stiffness = DeviceModel().limits.max_stiffness;
  const SimRun r = run(still(sheet()), hold_tap_release(), { 0.0, 0.0, 0.002 }, options);
  std::cout << "hold-tap-release: injected " << r.energy << " J\n";
  EXPECT_LE(r.energy, 0.0);
  // No limit cycle while held: over the last 0.2 s of the hold the force stays within
  // two position quanta of stiffness.
  double lo = 1e9, hi = -1e9;
  for (const TrajectoryRow& row : r.rows)
    if (row.t > 0.6 && row.t < 0.8)
    {
      lo = std::min(lo, row.force.z());
      hi = std::max(hi, row.force.z());
    }
  EXPECT_LE(hi - lo, 2 * options.force.contact_stiffness * DeviceModel().resolution + 1e-9);
  // Released: off the sheet and at rest by the end.
  for (const TrajectoryRow& row : r.rows)
    if (row.t > 2.5)
      ASSERT_FALSE(row.contact) << row.t;
  EXPECT_LT((r.rows.back().x - r.rows[r.rows.size() - 2].x).norm(), 1e-9);
}

TEST(HandSim, AGraspHeldTappedAndReleasedInjectsNoEnergy)
{
  // The coupling at its stiffest (rigid rock: 0.8 of the device's max) with the default
  // coupling damping; the hand pulls 1.5 N, taps, lets go; no scene.
  HandSimOptions options;
  options.grasping = true;
  options.grasp_stiffness = coupling_stiffness(0.0, options.force, DeviceModel().limits);
  const SimRun r =
    run([](double, Soup& s) { s.clear(); }, hold_tap_release(), Eigen::Vector3d::Zero(), options);
  std::cout << "grasp hold-tap-release: injected " << r.energy << " J\n";
  EXPECT_LE(r.energy, 0.0);
  EXPECT_LT(r.rows.back().x.norm(), 2 * DeviceModel().resolution);
}

namespace
{
// A hand pressing 1.5 N on the fault step's upper plateau (z = 0 at y = -2 cm) while the
// graphics side stalls for `frames` frame periods from 0.6 s; `scene` may move it meanwhile.
struct Stall
{
  SimRun run;
  HandSimOptions options;
  std::size_t resume = 0; // the row of the first tick with a patch after the stall
};
Stall press_through_a_stall(double frame, int frames, const SceneAt& scene, double extra = 0.5,
  bool credit_scene_work = false)
{
  Stall s;
  s.options.force.credit_scene_work = credit_scene_work;
  s.options.patch_period = frame;
  s.options.stall_from = 0.6;
  s.options.stall_until = 0.6 + frames * frame;
  const double end = s.options.stall_until + extra;
  s.run = run(scene, push({ 0, 0, -1.5 }, end), { 0.001, -0.02, 0.002 }, s.options);
  s.resume = std::size_t(std::ceil(s.options.stall_until / DeviceModel().period - 1e-9));
  return s;
}

// The fault step, `moved` higher from `when` s on.
SceneAt plateau_moved_at(double when, double moved)
{
  return [when, moved](double t, Soup& out)
  {
    out =
      grid(10, 8, [&](double x, double y) { return fault_step(x, y) + (t > when ? moved : 0.0); });
  };
}

// How deep under the plateau a hand the device can hold keeps the stylus: the contact
// spring at max force, F_max / k_c (4.1 mm; docs/haptics.md, "A stale scene").
double shell()
{
  return shell_of(DeviceLimits().max_force);
}
} // namespace

TEST(HandSim, AHandPressingOnThePlateauThroughAGuiStallKeepsContactAndNeverFallsThrough)
{
  // 60 frames/s stalled for 5 and 50 frames (80 ms, under the 100 ms timeout; 0.8 s), and
  // a slow renderer at 10 frames/s (each snapshot valid for 3 frames) stalled for 5 (0.5 s).
  const SceneAt plateau = still(grid(10, 8, fault_step));
  for (const auto& [frame, frames] : { std::pair{ 0.016, 5 }, { 0.016, 50 }, { 0.1, 5 } })
  {
    const Stall s = press_through_a_stall(frame, frames, plateau);
    const auto& rows = s.run.rows;
    double deepest = 0.0, resume_step = 0.0;
    for (std::size_t i = 400; i < rows.size(); ++i) // resting in contact from 0.4 s on
    {
      ASSERT_TRUE(rows[i].contact) << frame << " x " << frames << " at " << rows[i].t;
      ASSERT_GT(rows[i].proxy.z(), 0.0) << rows[i].t;
      deepest = std::max(deepest, -rows[i].x.z());
      if (i >= s.resume && i < s.resume + 5)
        resume_step = std::max(resume_step, (rows[i].force - rows[i - 1].force).norm());
    }
    std::cout << frames << " frames of " << frame * 1000 << " ms: deepest " << deepest * 1000
              << " mm, step on resume " << resume_step << " N, largest beyond k |dx| "
              << s.run.figures.max_step_excess << " N, injected " << s.run.energy << " J\n";
    EXPECT_LE(deepest, shell());
    EXPECT_NEAR(rows.back().x.z(), -1.5 / ForceParams().contact_stiffness, 0.0002);
    EXPECT_NEAR(rows.back().force.z(), 1.5, 0.1);
    EXPECT_LE(s.run.figures.max_step_excess, damper_step());
    EXPECT_LE(s.run.energy, 0.0);
  }
}

TEST(HandSim, APlateauThatMovedDuringAStallCarriesTheProxyOntoItsNewPlace)
{
  // The plateau is 1 mm lower, or higher, when the 0.8 s stall ends: the first patch after
  // carries the proxy by s = 1 mm (carry_over), a step of at most k_c (|dx| + s); the
  // stylus stays on top of the surface where it is, within the shell. Raised, only with
  // the scene's work credited: by default the plateau comes up through the stylus, whose
  // spring the energy bound softens instead of lifting the hand (the next test).
  const double k = ForceParams().contact_stiffness;
  for (const double moved : { -0.001, 0.001 })
  {
    const Stall s = press_through_a_stall(0.016, 50, plateau_moved_at(1.0, moved), 0.5, moved > 0);
    const auto& rows = s.run.rows;
    double worst = 0.0;
    for (std::size_t i = 400; i < rows.size(); ++i)
    {
      const double surface = rows[i].t >= s.options.stall_until ? moved : 0.0;
      ASSERT_TRUE(rows[i].contact) << moved << " at " << rows[i].t;
      ASSERT_GT(rows[i].proxy.z(), surface) << rows[i].t;
      ASSERT_LE(surface - rows[i].x.z(), shell()) << rows[i].t;
      const double step = (rows[i].force - rows[i - 1].force).norm();
      const double motion = (rows[i].x - rows[i - 1].x).norm() + 2 * DeviceModel().resolution;
      worst = std::max(worst, step - k * motion);
    }
    std::cout << "plateau moved " << moved * 1000 << " mm: step beyond k |dx| " << worst
              << " N (k s = " << k * std::abs(moved) << "), injected " << s.run.energy
              << " J, work " << s.run.work * 1e3 << " mJ\n";
    EXPECT_LE(worst, k * std::abs(moved) + 1e-9);
    EXPECT_NEAR(rows.back().x.z(), moved - 1.5 / k, 0.0002);
    if (moved < 0.0)
      EXPECT_LE(s.run.energy, 0.0); // a surface moving up does work on the hand; down, not
  }
}

TEST(HandSim, APlateauRaisedDuringAStallDoesNotLiftTheHand)
{
  // The plateau 1 mm higher after the 0.8 s stall, by default: the carried proxy stretches
  // the spring by 1 mm with energy the rendering never absorbed, so the energy bound
  // scales its force down (at most the fades' step a tick beyond k_c (|dx| + s)) rather
  // than lifting the hand: the stylus stays in contact, the proxy on the new plateau,
  // the stylus no higher than it rested before, and the rendered work is not positive.
  const double k = ForceParams().contact_stiffness, moved = 0.001;
  const Stall s = press_through_a_stall(0.016, 50, plateau_moved_at(1.0, moved));
  const auto& rows = s.run.rows;
  const double rest = rows[s.resume - 1].x.z();
  double worst = 0.0, highest = -1.0;
  for (std::size_t i = s.resume; i < rows.size(); ++i)
  {
    ASSERT_TRUE(rows[i].contact) << rows[i].t;
    ASSERT_GT(rows[i].proxy.z(), moved) << rows[i].t;
    const double step = (rows[i].force - rows[i - 1].force).norm();
    const double motion = (rows[i].x - rows[i - 1].x).norm() + 2 * DeviceModel().resolution;
    worst = std::max(worst, step - k * motion);
    highest = std::max(highest, rows[i].x.z());
  }
  std::cout << "plateau raised 1 mm: rested at " << rest * 1e3 << " mm, highest after "
            << highest * 1e3 << " mm, end " << rows.back().x.z() * 1e3 << " mm, force "
            << rows.back().force.z() << " N, step beyond k |dx| " << worst << " N, work "
            << s.run.work * 1e3 << " mJ, injected " << s.run.energy * 1e3 << " mJ\n";
  EXPECT_LE(highest, rest + DeviceModel().resolution);
  EXPECT_LE(worst, k * moved + damper_step());
  EXPECT_LE(s.run.work, 0.0);
}

TEST(HandSim, AFreezeLongerThanTheContactHoldKeepsTheSideWithoutYankingTheStylusBack)
{
  // 10 frames/s frozen for 5 s: the contact is held 2 s (ForceParams::stale_contact_max),
  // then fades out and the hand pushes the stylus down to the workspace's floor; the proxy
  // stays on the plateau. When the scene comes back the contact fades in, but its spring,
  // stretched 8 cm, holds far more than the rendering absorbed: the energy bound keeps it
  // weak (the stylus is not yanked back up) until the hand brings the stylus back above
  // the plateau (lifting 0.5 N from 7.1 s); pressed again, it rests on the plateau with
  // the full force. No step beyond the fades' step; the rendered work is not positive.
  HandSimOptions options;
  options.patch_period = 0.1;
  options.stall_from = 0.6;
  options.stall_until = 5.6;
  const std::vector<HandKey> hand = { { 0.0, { 0, 0, 0 } }, { 0.2, { 0, 0, -1.5 } },
    { 7.1, { 0, 0, -1.5 } }, { 7.11, { 0, 0, 0.5 } }, { 7.6, { 0, 0, 0.5 } },
    { 7.61, { 0, 0, -1.5 } }, { 9.0, { 0, 0, -1.5 } } };
  const SimRun r = run(still(grid(10, 8, fault_step)), hand, { 0.001, -0.02, 0.002 }, options);
  const ForceParams params;
  double deepest = 0.0, resumed = 1.0, strongest = 0.0;
  for (const TrajectoryRow& row : r.rows)
  {
    if (row.t < 0.4)
      continue;
    ASSERT_GT(row.proxy.z(), 0.0) << row.t;
    deepest = std::max(deepest, -row.x.z());
    if (row.t >= options.stall_until && row.t < 7.1)
    {
      resumed = std::min(resumed, -row.x.z());
      strongest = std::max(strongest, row.force.norm());
    }
  }
  std::cout << "5 s freeze: deepest " << deepest * 1000 << " mm, after the resume at least "
            << resumed * 1000 << " mm deep, force at most " << strongest
            << " N, largest step beyond k |dx| " << r.figures.max_step_excess << " N, work "
            << r.work * 1e3 << " mJ, injected " << r.energy * 1e3 << " mJ\n";
  EXPECT_GT(deepest, shell());        // the hand got through while the force was off ...
  EXPECT_GT(resumed, shell());        // ... and the contact that came back did not lift it
  EXPECT_LT(strongest, 1.0);          // (weaker than the hand)
  EXPECT_TRUE(r.rows.back().contact); // back on top once the hand brought it back
  EXPECT_NEAR(r.rows.back().x.z(), -1.5 / params.contact_stiffness, 0.0002);
  EXPECT_NEAR(r.rows.back().force.z(), 1.5, 0.1);
  EXPECT_LE(r.figures.max_step_excess, damper_step());
  EXPECT_LE(r.work, 0.0);
}

namespace
{
// A hand that presses `f` (ramped over 0.2 s, held to 1 s), then lets go at once: the
// stylus, pushed back by the contact spring, leaves the surface; the run ends at 2 s.
std::vector<HandKey> press_and_release(const Eigen::Vector3d& f)
{
  return { { 0.0, Eigen::Vector3d::Zero() }, { 0.2, f }, { 1.0, f },
    { 1.001, Eigen::Vector3d::Zero() }, { 2.0, Eigen::Vector3d::Zero() } };
}

// The runs of the passivity table (docs/haptics.md, "Passivity"): name, work of the
// rendered force on the stylus (J), largest force step beyond k_c |dx| (N).
struct PassivityRow
{
  std::string name;
  SimRun run;
};

std::vector<PassivityRow> passivity_runs(bool control)
{
  std::vector<PassivityRow> out;
  HandSimOptions options;
  options.force.passivity_control = control;
  auto add = [&](const std::string& name, const SceneAt& scene, const std::vector<HandKey>& hand,
               const Eigen::Vector3d& start, HandSimOptions o)
  {
    o.force.passivity_control = control;
    out.push_back({ name, run(scene, hand, start, o) });
  };
  const Soup plate = sheet();
  add(
    "press 2 N, let go", still(plate), press_and_release({ 0, 0, -2 }), { 0, 0, 0.0005 }, options);
  add("press 5 N (> max force), let go", still(plate), press_and_release({ 0, 0, -5 }),
    { 0, 0, 0.0005 }, options);
  add("press 0.5 N from the back side, let go", still(plate), press_and_release({ 0, 0, 0.5 }),
    { 0, 0, -0.0005 }, options);
  HandSimOptions stiff = options;
  stiff.force.contact_stiffness = DeviceModel().limits.max_stiffness;
  add("hold 1.5 N, tap 3 N, lift (1000 N/m)", still(plate), hold_tap_release(), { 0, 0, 0.002 },
    stiff);
  HandSimOptions grasp = options;
  grasp.grasping = true;
  grasp.grasp_stiffness = coupling_stiffness(0.0, grasp.force, DeviceModel().limits);
  add(
    "grasp: pull 1.5 N, tap, let go", [](double, Soup& s) { s.clear(); }, hold_tap_release(),
    Eigen::Vector3d::Zero(), grasp);
  const std::vector<HandKey> slide = { { 0.0, { 0, 0, -1 } }, { 0.3, { 0, 0, -1 } },
    { 0.5, { 0.01, 0.1, -1 } }, { 0.9, { 0.01, 0.1, -1 } }, { 0.901, { 0, 0, 0 } },
    { 1.5, { 0, 0, 0 } } };
  add("slide 1 N over the fault step's crest, let go", still(grid(10, 8, fault_step)), slide,
    { 0.001, -0.02, 0.002 }, options);
  add("slide 1 N over 500 slivers, let go", still(grid(1, 250, [](double, double) { return 0.0; })),
    slide, { -0.01, -0.02, 0.002 }, options);
  add("the sheet rising 3 cm/s under a 1 N hand", rising_sheet(), push({ 0, 0, -1 }, 1.0),
    { 0.0, 0.0, 0.003 }, options);
  HandSimOptions frozen = options;
  frozen.patch_period = 0.1;
  frozen.stall_from = 0.6;
  frozen.stall_until = 5.6;
  add("5 s freeze, contact faded out and back in", still(grid(10, 8, fault_step)),
    push({ 0, 0, -1.5 }, 7.1), { 0.001, -0.02, 0.002 }, frozen);
  return out;
}
} // namespace

TEST(HandSim, WithoutThePassivityControllerAPressAndReleaseMakesTheForceDoPositiveWork)
{
  // The zero-order hold: each tick the spring's force is held while the stylus moves, so
  // it does k |dx|^2 / 2 more work than a continuous spring (Colgate & Schenkel 1997), on
  // the way in and on the way out; a press and release gives the stylus that back, which
  // only the device's own damping absorbs.
  const auto runs = passivity_runs(false);
  std::cout << "without the controller, " << runs[0].name << ": work " << runs[0].run.work * 1e3
            << " mJ\n";
  EXPECT_GT(runs[0].run.work, 1e-4);
}

TEST(HandSim, ThePassivityControllerKeepsTheRenderedWorkNonPositiveWithinTheStepBound)
{
  // Hannaford & Ryu (2002) (passivity.h): over every run the rendered force's work on the
  // stylus is at most zero, on the simulator's true (not quantised) positions, and the
  // controller's force changes by at most the fade's step a tick beyond k_c |dx|.
  const auto with = passivity_runs(true);
  const auto without = passivity_runs(false);
  const ForceParams params;
  const double fade_step = DeviceLimits().max_force * params.servo_period / params.fade_time;
  for (std::size_t i = 0; i < with.size(); ++i)
  {
    const SimRun& r = with[i].run;
    std::cout << with[i].name << ": work " << without[i].run.work * 1e3 << " mJ without, "
              << r.work * 1e3 << " mJ with the controller; beyond k |dx| "
              << without[i].run.figures.max_step_excess << " / " << r.figures.max_step_excess
              << " N\n";
    EXPECT_LE(r.work, 0.0) << with[i].name;
    EXPECT_LE(r.figures.max_step_excess, without[i].run.figures.max_step_excess + fade_step + 1e-9)
      << with[i].name;
    for (const TrajectoryRow& row : r.rows)
      ASSERT_LE(row.force.norm(), DeviceLimits().max_force + 1e-12) << with[i].name;
  }
}
