// The haptic interactor's Qt-free logic: workspace -> scene mapping and the per-hand
// tool state machine (ParaViewPlugin/Controls/HapticsControl.h).
#include "HapticsControl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace geoshaping::interactor;
using Eigen::Vector3d;

namespace
{
// Looking down -z at the origin from 10 units, y up: screen axes are the scene axes.
CameraPose topCamera()
{
  CameraPose c;
  c.position = Vector3d(0, 0, 10);
  c.focal_point = Vector3d::Zero();
  c.view_up = Vector3d::UnitY();
  c.view_angle_deg = 90.0; // half height at the focal point = 10 * tan(45 deg) = 10
  return c;
}

StylusState at(const Vector3d& p, bool button)
{
  StylusState s;
  s.position = p;
  s.button = button;
  return s;
}

void expectNear(const Vector3d& a, const Vector3d& b, double tol = 1e-12)
{
  EXPECT_LE((a - b).norm(), tol) << a.transpose() << " vs " << b.transpose();
}
}

TEST(WorkspaceMapping, PutsTheWorkspaceCentreAtTheFocalPoint)
{
  CameraPose c = topCamera();
  c.focal_point = Vector3d(5e5, 4e6, 100);
  c.position = c.focal_point + Vector3d(0, 0, 10);
  const WorkspaceMapping m(c, 0.08);
  ASSERT_TRUE(m.valid());
  expectNear(m.to_scene(Vector3d::Zero()), c.focal_point);
}

TEST(WorkspaceMapping, WorkspaceRadiusSpansHalfTheViewHeight)
{
  const WorkspaceMapping m(topCamera(), 0.08);
  EXPECT_NEAR(m.scale(), 10.0 / 0.08, 1e-9);
  CameraPose parallel = topCamera();
  parallel.parallel = true;
  parallel.parallel_scale = 4.0;
  EXPECT_NEAR(WorkspaceMapping(parallel, 0.1).scale(), 40.0, 1e-12);
}

TEST(WorkspaceMapping, StylusMovesWhereTheUserLooks)
{
  // Camera on +x looking at the origin, z up: screen right is +y, toward the viewer +x.
  CameraPose c;
  c.position = Vector3d(10, 0, 0);
  c.view_up = Vector3d::UnitZ();
  c.view_angle_deg = 90.0;
  const WorkspaceMapping m(c, 0.1);
  const double s = m.scale();
  expectNear(m.vector_to_scene(Vector3d(0.01, 0, 0)), Vector3d(0, 0.01 * s, 0), 1e-9);
  expectNear(m.vector_to_scene(Vector3d(0, 0.01, 0)), Vector3d(0, 0, 0.01 * s), 1e-9);
  expectNear(m.vector_to_scene(Vector3d(0, 0, 0.01)), Vector3d(0.01 * s, 0, 0), 1e-9);
}

TEST(WorkspaceMapping, DeviceToSceneAndBackIsTheIdentity)
{
  CameraPose c;
  c.position = Vector3d(3, -7, 12);
  c.focal_point = Vector3d(1, 2, 3);
  c.view_up = Vector3d(0.3, 0.2, 1).normalized();
  const WorkspaceMapping m(c, 0.08);
  const Vector3d p(0.011, -0.02, 0.035);
  expectNear(m.to_device(m.to_scene(p)), p, 1e-12);
}

TEST(WorkspaceMapping, RotationsFollowTheCamera)
{
  CameraPose c;
  c.position = Vector3d(10, 0, 0);
  c.view_up = Vector3d::UnitZ();
  const WorkspaceMapping m(c, 0.1);
  // A quarter turn about the device's y (screen up) is a quarter turn about scene z.
  const Eigen::Quaterniond q(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY()));
  expectNear(m.rotation_to_scene(q) * Vector3d::UnitX(), Vector3d(0, 1, 0), 1e-12);
}

TEST(WorkspaceMapping, DegenerateCameraIsInvalid)
{
  CameraPose c = topCamera();
  c.view_up = Vector3d::UnitZ(); // along the view direction
  EXPECT_FALSE(WorkspaceMapping(c, 0.08).valid());
  c = topCamera();
  c.position = c.focal_point;
  EXPECT_FALSE(WorkspaceMapping(c, 0.08).valid());
  EXPECT_FALSE(WorkspaceMapping(topCamera(), 0.0).valid());
}

TEST(HandController, DeformPressGraspsAndHoldingDragsByTheStylusMotion)
{
  HandController hand;
  const Brush brush;
  EXPECT_FALSE(hand.update(at(Vector3d(1, 2, 3), false), brush).grasp);
  HandActions press = hand.update(at(Vector3d(1, 2, 3), true), brush);
  EXPECT_TRUE(press.grasp);
  expectNear(press.grasp_position, Vector3d(1, 2, 3));
  EXPECT_TRUE(press.set_displacement);
  expectNear(press.displacement, Vector3d::Zero());
  HandActions drag = hand.update(at(Vector3d(1.5, 2, 5), true), brush);
  EXPECT_FALSE(drag.grasp);
  expectNear(drag.displacement, Vector3d(0.5, 0, 2));
  HandActions release = hand.update(at(Vector3d(9, 9, 9), false), brush);
  EXPECT_TRUE(release.release);
  EXPECT_FALSE(release.set_displacement);
  EXPECT_FALSE(hand.held());
}

TEST(HandController, PaintDabsAtThePressAndEveryQuarterRadius)
{
  HandController hand;
  hand.set_tool(Tool::paint);
  Brush brush;
  brush.radius = 4.0;
  brush.value = 0.2;
  brush.strength = 0.7;
  HandActions press = hand.update(at(Vector3d(0, 0, 0), true), brush);
  ASSERT_EQ(press.dabs.size(), 1u);
  EXPECT_EQ(press.dabs[0], (std::array<double, 6>{ 0, 0, 0, 4.0, 0.2, 0.7 }));
  EXPECT_TRUE(hand.update(at(Vector3d(0.9, 0, 0), true), brush).dabs.empty());
  EXPECT_EQ(hand.update(at(Vector3d(1.0, 0, 0), true), brush).dabs.size(), 1u);
  EXPECT_TRUE(hand.update(at(Vector3d(5, 0, 0), false), brush).dabs.empty());
}

TEST(HandController, AStrokeIsOneStepAndAFastMoveIsFilled)
{
  HandController hand;
  hand.set_tool(Tool::paint);
  Brush brush;
  brush.radius = 2.0;
  brush.value = 0.0;
  EXPECT_EQ(brush.strength, 1.0); // full strength by default: a swatch paints its value
  HandActions press = hand.update(at(Vector3d(0, 0, 0), true), brush);
  EXPECT_TRUE(press.begin_stroke);
  EXPECT_FALSE(press.end_stroke);
  // The next frame is 10 radii away: 40 dabs fill the way, half a unit apart.
  HandActions fast = hand.update(at(Vector3d(0, 20, 0), true), brush);
  EXPECT_FALSE(fast.begin_stroke);
  ASSERT_EQ(fast.dabs.size(), 40u);
  for (std::size_t i = 0; i < fast.dabs.size(); ++i)
  {
    EXPECT_EQ(fast.dabs[i], (std::array<double, 6>{ 0, 0.5 * (i + 1), 0, 2.0, 0.0, 1.0 })) << i;
  }
  HandActions release = hand.update(at(Vector3d(0, 20, 0), false), brush);
  EXPECT_TRUE(release.end_stroke);
  EXPECT_FALSE(release.release);
  EXPECT_TRUE(release.dabs.empty());
  // A tool change ends a stroke as a release does.
  EXPECT_TRUE(hand.update(at(Vector3d(0, 0, 0), true), brush).begin_stroke);
  EXPECT_TRUE(hand.set_tool(Tool::deform).end_stroke);
}

TEST(HandController, HoldAndTurnFollowsTheStylusInSixDegreesOfFreedom)
{
  HandController hand;
  hand.set_tool(Tool::hold_and_turn);
  const Brush brush;
  StylusState s = at(Vector3d(1, 0, 0), true);
  EXPECT_TRUE(hand.update(s, brush).begin_hold);
  s.position = Vector3d(1, 0, 2);
  s.orientation = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitZ());
  const HandActions turn = hand.update(s, brush);
  ASSERT_TRUE(turn.set_motion);
  const Eigen::Matrix4d m = turn.motion.matrix();
  // About the press point (1, 0, 0): the origin goes to (1, -1, 0), then up by 2.
  expectNear((m * Eigen::Vector4d(0, 0, 0, 1)).head<3>(), Vector3d(1, -1, 2), 1e-12);
  expectNear((m * Eigen::Vector4d(1, 0, 0, 1)).head<3>(), Vector3d(1, 0, 2), 1e-12);
  EXPECT_TRUE(hand.update(at(s.position, false), brush).end_hold);
}

TEST(HandController, ChangingTheToolEndsWhatTheOldToolWasDoing)
{
  HandController hand;
  const Brush brush;
  hand.update(at(Vector3d::Zero(), true), brush);
  EXPECT_TRUE(hand.set_tool(Tool::paint).release);
  EXPECT_FALSE(hand.held());
  EXPECT_FALSE(hand.set_tool(Tool::paint).release);
  // The button still held under the new tool starts a fresh paint stroke.
  EXPECT_EQ(hand.update(at(Vector3d::Zero(), true), brush).dabs.size(), 1u);
}

TEST(HandController, NonFiniteStylusReleasesInsteadOfDragging)
{
  HandController hand;
  const Brush brush;
  hand.update(at(Vector3d::Zero(), true), brush);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const HandActions a = hand.update(at(Vector3d(nan, 0, 0), true), brush);
  EXPECT_TRUE(a.release);
  EXPECT_FALSE(a.set_displacement);
}

TEST(StylusPalette, AppearsAboveThePressAndPicksTheSwatchTouched)
{
  StylusPalette palette;
  const double r = 0.08; // workspace radius
  EXPECT_TRUE(std::isnan(palette.update(false, Vector3d(0.01, 0, 0), r)));
  EXPECT_FALSE(palette.shown());
  // Second button pressed at (0.01, -0.01, 0.02): the row is 2 cm above, 1 cm apart,
  // centred on the press, swatch 5 (0.5) above the press.
  EXPECT_TRUE(std::isnan(palette.update(true, Vector3d(0.01, -0.01, 0.02), r)));
  EXPECT_TRUE(palette.shown());
  EXPECT_EQ(palette.touched(), -1); // the press itself is 2 cm below the row
  expectNear(palette.centre(5), Vector3d(0.01, 0.01, 0.02), 1e-15);
  expectNear(palette.centre(0), Vector3d(-0.04, 0.01, 0.02), 1e-15);
  expectNear(palette.centre(10), Vector3d(0.06, 0.01, 0.02), 1e-15);
  // Touch swatch 2 (0.2) 3 mm off its centre: picked once, not again while still on it.
  EXPECT_DOUBLE_EQ(palette.update(true, Vector3d(-0.02, 0.013, 0.02), r), 0.2);
  EXPECT_EQ(palette.touched(), 2);
  EXPECT_TRUE(std::isnan(palette.update(true, Vector3d(-0.02, 0.012, 0.02), r)));
  // Between swatches 2 and 3 (5 mm from each): nothing.
  EXPECT_TRUE(std::isnan(palette.update(true, Vector3d(-0.015, 0.01, 0.02), r)));
  EXPECT_EQ(palette.touched(), -1);
  EXPECT_DOUBLE_EQ(palette.update(true, Vector3d(0.05, 0.01, 0.02), r), 0.9);
  EXPECT_TRUE(std::isnan(palette.update(true, Vector3d(std::nan(""), 0, 0), r)));
  // Released: hidden; the next press lays the row out again.
  EXPECT_TRUE(std::isnan(palette.update(false, Vector3d(0.05, 0.01, 0.02), r)));
  EXPECT_FALSE(palette.shown());
  EXPECT_EQ(palette.touched(), -1);
}

TEST(StylusPalette, StaysInsideTheWorkspace)
{
  StylusPalette palette;
  palette.update(true, Vector3d(0.075, 0, 0), 0.08); // near the right edge
  EXPECT_NEAR(palette.centre(10).x(), 0.08, 1e-15);
  EXPECT_NEAR(palette.centre(5).x(), 0.03, 1e-15);
  for (int i = 0; i < StylusPalette::count; ++i)
  {
    EXPECT_DOUBLE_EQ(StylusPalette::value(i), i / 10.0);
  }
}

TEST(StoppedGrasp, AGraspHeldBackIsWhereItStoppedNotWhereTheStylusPutIt)
{
  const Vector3d press(1, 2, 3), displacement(10, 0, -4);
  Vector3d stopped;
  ASSERT_TRUE(stopped_grasp(press, displacement, 0.25, nullptr, stopped));
  EXPECT_EQ(stopped, Vector3d(3.5, 2, 2));
  // A sliding grasp lands off its straight path: the output says where.
  const Vector3d landed(2, 0.5, -1);
  ASSERT_TRUE(stopped_grasp(press, displacement, 0.5, &landed, stopped));
  EXPECT_EQ(stopped, Vector3d(3, 2.5, 2));
  // Stopped on the obstacle at the press.
  ASSERT_TRUE(stopped_grasp(press, displacement, 0.0, nullptr, stopped));
  EXPECT_EQ(stopped, press);
}

TEST(StoppedGrasp, ASlidingGraspThatSlidFreelyPullsTowardWhereItLanded)
{
  // Fraction 1, but the grasp landed on the obstacle, off the stylus's straight path.
  const Vector3d press(1, 2, 3), displacement(0, 0, -4), landed(1.6, 0, -3.2);
  Vector3d stopped;
  ASSERT_TRUE(stopped_grasp(press, displacement, 1.0, &landed, stopped));
  EXPECT_TRUE(stopped.isApprox(Vector3d(2.6, 2, -0.2), 1e-15));
  // Landed exactly where the stylus put it: the coupling stays as it is.
  EXPECT_FALSE(stopped_grasp(press, displacement, 1.0, &displacement, stopped));
  // Not known (NaN): the fraction decides.
  const Vector3d unknown(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_FALSE(stopped_grasp(press, displacement, 1.0, &unknown, stopped));
  ASSERT_TRUE(stopped_grasp(press, displacement, 0.5, &unknown, stopped));
  EXPECT_EQ(stopped, Vector3d(1, 2, 1));
}

TEST(StoppedGrasp, AFreeGraspOrNoGraspLeavesTheCouplingAsItIs)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Vector3d stopped(7, 7, 7);
  EXPECT_FALSE(stopped_grasp(Vector3d::Zero(), Vector3d(1, 0, 0), 1.0, nullptr, stopped));
  EXPECT_FALSE(stopped_grasp(Vector3d::Zero(), Vector3d(1, 0, 0), nan, nullptr, stopped));
  EXPECT_FALSE(stopped_grasp(Vector3d(nan, 0, 0), Vector3d(1, 0, 0), 0.5, nullptr, stopped));
}
