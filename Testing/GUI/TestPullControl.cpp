// The mouse pull's math (ParaViewPlugin/Controls/PullControl.h) through a camera's projection
// matrix: the grasp stays under the cursor at any data scale and camera, Shift makes the
// motion a tenth, and the constraints keep the pull on their line.
#include "HapticsControl.h"
#include "PullControl.h"
#include "camera_projection.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <limits>

using namespace geoshaping::interactor;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace
{
using geoshaping::interactor::test_camera::CameraProjection;
using geoshaping::interactor::test_camera::oblique;

PullControl pressAt(const CameraProjection& view, const Vector3d& grasp, const Vector3d& normal,
  PullConstraint constraint = PullConstraint::view_plane)
{
  PullControl pull;
  pull.press(view.pixel(grasp), grasp, normal);
  pull.constrain(constraint, view, Vector3d::UnitZ());
  return pull;
}

struct Scene
{
  double scale;
  Vector3d centre;
  bool parallel;
};
const Scene scenes[] = { { 1.0, Vector3d::Zero(), false }, { 1.0, Vector3d::Zero(), true },
  { 1e6, Vector3d(5e5, 4.1e6, -2e3), false }, { 1e6, Vector3d(5e5, 4.1e6, -2e3), true } };
}

TEST(PullControl, GraspStaysUnderTheCursorAtAnyScaleAndCamera)
{
  for (const Scene& s : scenes)
  {
    const CameraProjection view = oblique(s.scale, s.centre, s.parallel);
    const Vector3d grasp = s.centre + s.scale * Vector3d(0.1, 0.2, 0.05);
    PullControl pull = pressAt(view, grasp, Vector3d::UnitZ());
    const Vector2d press = view.pixel(grasp);
    for (const Vector2d& step : { Vector2d(30, 10), Vector2d(50, -70), Vector2d(-3, 120) })
    {
      pull.move(pull.target() + step, false);
      const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
      EXPECT_LE((view.pixel(grasp + d) - pull.target()).norm(), 1e-6)
        << "scale " << s.scale << " parallel " << s.parallel;
      // In the view plane: the grasp keeps its depth.
      EXPECT_NEAR(view.to_display(grasp + d).z(), view.to_display(grasp).z(), 1e-9);
    }
    EXPECT_GT((pull.target() - press).norm(), 90.0);
  }
}

TEST(PullControl, TheMotionIsTheCursorsWorldMotionWhateverTheDataScale)
{
  // The same pixels pull a million times farther on a million times larger scene seen
  // by the same camera scaled up: the displacement follows the view, not the data.
  Vector3d unit;
  for (const double scale : { 1.0, 1e6 })
  {
    const CameraProjection view = oblique(scale, Vector3d::Zero(), false);
    PullControl pull = pressAt(view, Vector3d::Zero(), Vector3d::UnitZ());
    pull.move(pull.target() + Vector2d(80, 0), false);
    const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
    if (scale == 1.0)
    {
      unit = d;
    }
    else
    {
      EXPECT_LE((d - 1e6 * unit).norm(), 1e-6 * d.norm());
    }
  }
}

TEST(PullControl, ShiftScalesTheMotionByATenth)
{
  const CameraProjection view = oblique(1e6, scenes[2].centre, false);
  const Vector3d grasp = scenes[2].centre;
  for (const PullConstraint c :
    { PullConstraint::view_plane, PullConstraint::vertical, PullConstraint::normal })
  {
    PullControl free = pressAt(view, grasp, Vector3d::UnitZ(), c);
    PullControl precise = free;
    const Vector2d end = free.target() + Vector2d(60, 45);
    free.move(end, false);
    precise.move(end, true);
    const Vector3d a = free.displacement(view, Vector3d::UnitZ());
    const Vector3d b = precise.displacement(view, Vector3d::UnitZ());
    if (c == PullConstraint::view_plane)
    {
      EXPECT_LE((b - 0.1 * a).norm(), 1e-9 * a.norm());
    }
    EXPECT_GT(b.norm(), 0.0);
    EXPECT_LT(b.norm(), 0.2 * a.norm());
  }
}

TEST(PullControl, ShiftMidPullDoesNotJump)
{
  const CameraProjection view = oblique(1.0, Vector3d::Zero(), false);
  PullControl pull = pressAt(view, Vector3d::Zero(), Vector3d::UnitZ());
  const Vector2d press = pull.target();
  pull.move(press + Vector2d(50, 0), false);
  pull.move(press + Vector2d(50, 0), true); // Shift pressed, the cursor still
  EXPECT_LE((pull.target() - (press + Vector2d(50, 0))).norm(), 1e-12);
  pull.move(press + Vector2d(70, 10), true);
  EXPECT_LE((pull.target() - (press + Vector2d(52, 1))).norm(), 1e-12);
  pull.move(press + Vector2d(80, 10), false);
  EXPECT_LE((pull.target() - (press + Vector2d(62, 1))).norm(), 1e-12);
}

TEST(PullControl, VerticalKeepsXAndYAndFollowsTheCursorAlongTheVertical)
{
  for (const Scene& s : scenes)
  {
    const CameraProjection view = oblique(s.scale, s.centre, s.parallel);
    const Vector3d grasp = s.centre + s.scale * Vector3d(-0.1, 0.1, 0.0);
    PullControl pull = pressAt(view, grasp, Vector3d(0.3, 0.0, 1.0), PullConstraint::vertical);
    // Up the screen and a little to the side: the grasp rises, and its image is the
    // cursor's foot on the vertical's image.
    pull.move(pull.target() + Vector2d(25, 70), false);
    const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
    EXPECT_EQ(d.x(), 0.0);
    EXPECT_EQ(d.y(), 0.0);
    EXPECT_GT(d.z(), 0.0);
    const Vector2d g = view.pixel(grasp);
    const Vector2d e = (view.pixel(grasp + s.scale * Vector3d::UnitZ() * 1e-3) - g).normalized();
    const Vector2d foot = g + (pull.target() - g).dot(e) * e;
    EXPECT_LE((view.pixel(grasp + d) - foot).norm(), 1e-6) << "scale " << s.scale;
  }
}

TEST(PullControl, NormalConstraintMovesAlongTheSurfaceNormal)
{
  const CameraProjection view = oblique(1.0, Vector3d::Zero(), false);
  const Vector3d normal = Vector3d(1.0, 0.0, 1.0).normalized();
  PullControl pull = pressAt(view, Vector3d::Zero(), normal, PullConstraint::normal);
  pull.move(pull.target() + Vector2d(40, 40), false);
  const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
  EXPECT_GT(d.norm(), 0.0);
  EXPECT_LE(d.cross(normal).norm(), 1e-12 * d.norm());
}

TEST(PullControl, TheDragPlaneGoesThroughTheGraspedVertex)
{
  // The press lands on the surface a little in front of the vertex that is grasped: the
  // vertex, not the pressed point, moves with the cursor.
  const CameraProjection view = oblique(1.0, Vector3d::Zero(), false);
  const Vector3d vertex(0.05, 0.3, -0.2);
  PullControl pull = pressAt(view, Vector3d::Zero(), Vector3d::UnitZ());
  pull.press(view.pixel(vertex), vertex + Vector3d(0.0, -0.2, 0.15), Vector3d::UnitZ());
  pull.set_grasp(vertex);
  pull.move(pull.target() + Vector2d(-90, 35), false);
  const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
  EXPECT_LE((view.pixel(vertex + d) - pull.target()).norm(), 1e-6);
}

TEST(PullControl, AVerticalSeenEndOnMovesWithTheCursorsUpwardMotion)
{
  // Looking straight down: the vertical's image is a point. Moving the cursor up raises
  // the grasp toward the viewer by the cursor's motion on the view plane; down lowers it.
  CameraPose c;
  c.position = Vector3d(0, 0, 10);
  c.view_up = Vector3d::UnitY();
  const CameraProjection view(c, 800, 600, 1.0, 100.0);
  PullControl pull = pressAt(view, Vector3d::Zero(), Vector3d::UnitZ(), PullConstraint::vertical);
  const Vector2d press = pull.target();
  pull.move(press + Vector2d(5, 30), false);
  const Vector3d up = pull.displacement(view, Vector3d::UnitZ());
  PullControl plane = pressAt(view, Vector3d::Zero(), Vector3d::UnitZ());
  plane.move(press + Vector2d(0, 30), false);
  const double thirty = plane.displacement(view, Vector3d::UnitZ()).norm();
  EXPECT_NEAR(up.z(), thirty, 1e-9);
  EXPECT_EQ(up.head<2>().norm(), 0.0);
  pull.move(press + Vector2d(5, -30), false);
  EXPECT_NEAR(pull.displacement(view, Vector3d::UnitZ()).z(), -thirty, 1e-9);
}

TEST(PullControl, BadInputGivesNoDisplacement)
{
  const CameraProjection view = oblique(1.0, Vector3d::Zero(), false);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PullControl pull = pressAt(view, Vector3d(nan, 0, 0), Vector3d::UnitZ());
  pull.move(Vector2d(10, 10), false);
  EXPECT_EQ(pull.displacement(view, Vector3d::UnitZ()), Vector3d::Zero());
  for (const PullConstraint c : { PullConstraint::normal, PullConstraint::vertical })
  {
    // A zero normal; a non-finite vertical.
    PullControl axis = pressAt(view, Vector3d::Zero(), Vector3d::Zero(), c);
    axis.move(axis.target() + Vector2d(10, 10), false);
    EXPECT_EQ(axis.displacement(view, Vector3d(nan, 0, 1)), Vector3d::Zero());
    axis.constrain(PullConstraint::view_plane, view, Vector3d(nan, 0, 1));
    axis.move(Vector2d(nan, 0), false);
    EXPECT_EQ(axis.displacement(view, Vector3d::UnitZ()), Vector3d::Zero());
  }
}

TEST(PullControl, KeysSwitchTheConstraintAndTheSameKeyFreesIt)
{
  using C = PullConstraint;
  EXPECT_EQ(constraint_for_key('z', C::view_plane), C::vertical);
  EXPECT_EQ(constraint_for_key('Z', C::normal), C::vertical);
  EXPECT_EQ(constraint_for_key('n', C::vertical), C::normal);
  EXPECT_EQ(constraint_for_key('N', C::view_plane), C::normal);
  EXPECT_EQ(constraint_for_key('z', C::vertical), C::view_plane);
  EXPECT_EQ(constraint_for_key('n', C::normal), C::view_plane);
  EXPECT_EQ(constraint_for_key('c', C::vertical), C::view_plane);
  EXPECT_EQ(constraint_for_key('C', C::view_plane), C::view_plane);
  // ParaView's own render-view keys (selection, find data) and others are left alone.
  for (const char key : { 's', 'd', 'f', 'g', 'b', 'v', 'x', ' ', '\0' })
  {
    EXPECT_FALSE(constraint_for_key(key, C::view_plane).has_value()) << key;
  }
}

TEST(PullControl, ASwitchMidPullDoesNotJump)
{
  // Every constraint to every other, mid-pull, at both scales and under both cameras: the
  // displacement at the switch is the one before it (to 1e-9 of it), and one more pixel
  // of cursor motion moves the grasp by about a pixel's worth, not more.
  const PullConstraint all[] = { PullConstraint::view_plane, PullConstraint::vertical,
    PullConstraint::normal };
  for (const Scene& s : scenes)
  {
    const CameraProjection view = oblique(s.scale, s.centre, s.parallel);
    const Vector3d grasp = s.centre + s.scale * Vector3d(0.1, -0.1, 0.02);
    const Vector3d normal = Vector3d(0.3, -0.2, 1.0).normalized();
    const double pixel = (view.to_world(view.to_display(grasp) + Vector3d(1, 0, 0)) - grasp).norm();
    for (const PullConstraint from : all)
    {
      for (const PullConstraint to : all)
      {
        if (to == from)
        {
          continue;
        }
        PullControl pull = pressAt(view, grasp, normal, from);
        pull.move(pull.target() + Vector2d(35, 50), false);
        pull.move(pull.target() + Vector2d(-12, 30), false);
        const Vector3d before = pull.displacement(view, Vector3d::UnitZ());
        ASSERT_GT(before.norm(), 10.0 * pixel);
        pull.constrain(to, view, Vector3d::UnitZ());
        EXPECT_EQ(pull.constraint(), to);
        const Vector3d at = pull.displacement(view, Vector3d::UnitZ());
        EXPECT_LE((at - before).norm(), 1e-9 * before.norm())
          << "scale " << s.scale << " parallel " << s.parallel << " " << int(from) << " -> "
          << int(to);
        pull.move(pull.target() + Vector2d(1, 1), false);
        EXPECT_LE((pull.displacement(view, Vector3d::UnitZ()) - at).norm(), 20.0 * pixel);
      }
    }
  }
}

TEST(PullControl, AfterASwitchToTheVerticalOnlyTheElevationChanges)
{
  // A free pull, then Z: from the switch on x and y stay as they were (exactly), z follows
  // the cursor, and the grasp, which the free pull kept under the cursor, shows at the
  // cursor's foot on the image of the vertical through where it was at the switch.
  for (const Scene& s : scenes)
  {
    const CameraProjection view = oblique(s.scale, s.centre, s.parallel);
    const Vector3d grasp = s.centre + s.scale * Vector3d(-0.05, 0.1, 0.0);
    PullControl pull = pressAt(view, grasp, Vector3d::UnitZ());
    pull.move(pull.target() + Vector2d(40, 25), false);
    const Vector3d at = pull.displacement(view, Vector3d::UnitZ());
    EXPECT_LE((view.pixel(grasp + at) - pull.target()).norm(), 1e-6);
    pull.constrain(PullConstraint::vertical, view, Vector3d::UnitZ());
    const Vector2d g = view.pixel(grasp + at);
    const Vector2d e =
      (view.pixel(grasp + at + 1e-3 * s.scale * Vector3d::UnitZ()) - g).normalized();
    for (const Vector2d& step : { Vector2d(10, 60), Vector2d(-30, 20), Vector2d(5, -150) })
    {
      pull.move(pull.target() + step, false);
      const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
      EXPECT_EQ(d.x(), at.x());
      EXPECT_EQ(d.y(), at.y());
      const Vector2d foot = g + (pull.target() - g).dot(e) * e;
      EXPECT_LE((view.pixel(grasp + d) - foot).norm(), 1e-6) << "scale " << s.scale;
    }
    EXPECT_LT(pull.displacement(view, Vector3d::UnitZ()).z(), at.z()); // 70 px down in all
  }
}

TEST(PullControl, BackToFreeTheGraspMovesAsTheCursorDoes)
{
  // Free, vertical, free again: after the last switch the grasp's image moves exactly as
  // the cursor does, keeping the offset the vertical left (no jump under the cursor).
  for (const Scene& s : scenes)
  {
    const CameraProjection view = oblique(s.scale, s.centre, s.parallel);
    const Vector3d grasp = s.centre + s.scale * Vector3d(0.05, 0.05, 0.01);
    PullControl pull = pressAt(view, grasp, Vector3d::UnitZ());
    pull.move(pull.target() + Vector2d(20, 10), false);
    pull.constrain(PullConstraint::vertical, view, Vector3d::UnitZ());
    pull.move(pull.target() + Vector2d(45, 40), false);
    const Vector3d at = pull.displacement(view, Vector3d::UnitZ());
    const Vector2d offset = view.pixel(grasp + at) - pull.target();
    EXPECT_GT(offset.norm(), 10.0); // the vertical kept it off the cursor
    pull.constrain(PullConstraint::view_plane, view, Vector3d::UnitZ());
    pull.move(pull.target() + Vector2d(-70, 15), false);
    pull.move(pull.target() + Vector2d(25, -90), true); // with Shift: a tenth
    const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
    EXPECT_LE((view.pixel(grasp + d) - (pull.target() + offset)).norm(), 1e-6)
      << "scale " << s.scale;
    EXPECT_NEAR(view.to_display(grasp + d).z(), view.to_display(grasp + at).z(), 1e-9);
  }
}

TEST(PullControl, APressStartsAFreshPullUnderTheConstraintInForce)
{
  const CameraProjection view = oblique(1.0, Vector3d::Zero(), false);
  PullControl pull = pressAt(view, Vector3d::Zero(), Vector3d::UnitZ());
  pull.move(pull.target() + Vector2d(30, 30), false);
  pull.choose(PullConstraint::vertical); // the dock's choice mid-pull, as pqHapticsMouse
  pull.constrain(PullConstraint::vertical, view, Vector3d::UnitZ());
  pull.move(pull.target() + Vector2d(0, 30), false);
  const Vector3d grasp(0.1, 0.1, 0.0);
  pull.press(view.pixel(grasp), grasp, Vector3d::UnitZ());
  EXPECT_EQ(pull.constraint(), PullConstraint::vertical);
  EXPECT_EQ(pull.displacement(view, Vector3d::UnitZ()), Vector3d::Zero());
  pull.move(pull.target() + Vector2d(20, 40), false);
  const Vector3d d = pull.displacement(view, Vector3d::UnitZ());
  EXPECT_EQ(d.x(), 0.0);
  EXPECT_EQ(d.y(), 0.0);
  EXPECT_GT(d.z(), 0.0);
}

TEST(PullControl, KeyedConstraintLastsOneDragAndTheChosenOneStays)
{
  const CameraProjection view = oblique(1.0, Vector3d::Zero(), false);
  const Vector3d grasp(0.1, 0.2, 0.05);
  PullControl pull;
  pull.choose(PullConstraint::normal); // the dock's choice, between pulls: at once
  EXPECT_EQ(pull.constraint(), PullConstraint::normal);
  pull.press(view.pixel(grasp), grasp, Vector3d::UnitZ());
  EXPECT_EQ(pull.constraint(), PullConstraint::normal);
  pull.constrain(PullConstraint::vertical, view, Vector3d::UnitZ()); // a key, mid-pull
  EXPECT_EQ(pull.constraint(), PullConstraint::vertical);
  EXPECT_EQ(pull.chosen(), PullConstraint::normal);
  EXPECT_EQ(pull_mode_note(pull.constraint(), pull.chosen()),
    "This drag: vertical only (z) (by key); the release goes back to along the surface normal.");
  EXPECT_TRUE(pull.release()); // back to the chosen one
  EXPECT_EQ(pull.constraint(), PullConstraint::normal);
  EXPECT_EQ(pull_mode_note(pull.constraint(), pull.chosen()),
    "Every pull: along the surface normal, until changed here.");
  pull.press(view.pixel(grasp), grasp, Vector3d::UnitZ());
  EXPECT_EQ(pull.constraint(), PullConstraint::normal);
  EXPECT_FALSE(pull.release()); // no key: nothing to go back from
  // Chosen mid-pull: it holds for this pull too, and after it.
  pull.press(view.pixel(grasp), grasp, Vector3d::UnitZ());
  pull.choose(PullConstraint::vertical);
  pull.constrain(PullConstraint::vertical, view, Vector3d::UnitZ());
  EXPECT_FALSE(pull.release());
  EXPECT_EQ(pull.constraint(), PullConstraint::vertical);
}
