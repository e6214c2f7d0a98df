#include "geoshaping/haptics/passivity.h"

#include <gtest/gtest.h>

using namespace geoshaping::haptics;

namespace
{
// A spring holding `stored` J that pushes 1 N up on a stylus at rest at the origin.
ForceResult spring(double stored)
{
  ForceResult r;
  r.force = Eigen::Vector3d(0, 0, 1);
  r.in_contact = true;
  r.stored_energy = stored;
  return r;
}
} // namespace

TEST(Passivity, ASpringHoldingWhatWasAbsorbedIsRenderedBitForBit)
{
  // Nothing absorbed, 40 uJ held: within the 50 uJ margin, so the scale stays 1.
  PassivityController c;
  const ForceParams params;
  const DeviceLimits limits;
  const ForceFade fade;
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(c.control(Eigen::Vector3d::Zero(), true, spring(40e-6), fade, fade, params, limits),
      Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(c.scale(), 1.0);
}

TEST(Passivity, ASpringHoldingMoreThanWasAbsorbedIsScaledDownByTheFadesStep)
{
  // 1 mJ held, nothing absorbed: the bound is m / U = 0.05; the force moves toward it by
  // F_max T / fade_time = 0.033 N a tick, also in ticks where a fade rose (the spring
  // fading back in after a freeze), and stays there: a push, never a pull.
  PassivityController c;
  const ForceParams params;
  const DeviceLimits limits;
  const double step = limits.max_force * params.servo_period / params.fade_time;
  const ForceFade before{ 1.0, 0.5 }, after{ 1.0, 0.51 };
  double last = 1.0;
  for (int k = 1; k <= 40; ++k)
  {
    const Eigen::Vector3d f =
      c.control(Eigen::Vector3d::Zero(), true, spring(1e-3), before, after, params, limits);
    const double expected = std::max(params.passivity_margin / 1e-3, 1.0 - k * step);
    EXPECT_NEAR(f.z(), expected, 1e-12) << k;
    EXPECT_LE(last - f.z(), step + 1e-12);
    EXPECT_EQ(f.x(), 0.0);
    EXPECT_EQ(f.y(), 0.0);
    last = f.z();
  }
  EXPECT_NEAR(c.scale(), 0.05, 1e-12);
  // Where a fade fell this tick, the scale does not drop further (the fade used the step).
  PassivityController held;
  EXPECT_EQ(
    held.control(Eigen::Vector3d::Zero(), true, spring(1e-3), after, before, params, limits),
    Eigen::Vector3d(0, 0, 1));
  // Off, the force is compute_force's.
  ForceParams off = params;
  off.passivity_control = false;
  PassivityController none;
  EXPECT_EQ(none.control(
              Eigen::Vector3d::Zero(), true, spring(1e-3), ForceFade(), ForceFade(), off, limits),
    Eigen::Vector3d(0, 0, 1));
}

TEST(Passivity, ADebtIsForgivenOnceTheSpringIsAtRest)
{
  // A spring pushing 1 N lifts the stylus 1 mm while holding 1 mJ: the tank is 1 mJ in
  // debt and the scale goes to zero. At rest (the spring holding less than the margin) the
  // debt is forgiven: a scale stuck at zero would absorb nothing and never come back.
  PassivityController c;
  const ForceParams params;
  const DeviceLimits limits;
  const ForceFade fade;
  c.control(Eigen::Vector3d::Zero(), true, spring(40e-6), fade, fade, params, limits);
  for (int k = 0; k < 40; ++k)
    c.control(Eigen::Vector3d(0, 0, 1e-3), true, spring(1e-3), fade, fade, params, limits);
  EXPECT_EQ(c.scale(), 0.0);
  ForceResult rest = spring(1e-6);
  rest.force = Eigen::Vector3d(0, 0, 0.01);
  EXPECT_EQ(
    c.control(Eigen::Vector3d(0, 0, 1e-3), true, rest, fade, fade, params, limits), rest.force);
  EXPECT_EQ(c.scale(), 1.0);
}
