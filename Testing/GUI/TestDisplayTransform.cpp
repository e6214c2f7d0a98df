// A representation's display transform (ParaViewPlugin/Controls/DisplayTransform.h): its matrix
// is vtkProp3D's, and under a vertical exaggeration the pick rule finds the data point
// drawn under the cursor, so the pull that follows keeps it there and moves the data by
// the cursor's motion in data units.
#include "DisplayTransform.h"
#include "PullControl.h"
#include "camera_projection.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <cmath>

using namespace geoshaping::interactor;
using Eigen::Vector2d;
using Eigen::Vector3d;
using geoshaping::interactor::test_camera::CameraProjection;
using geoshaping::interactor::test_camera::oblique;

namespace
{
// A DEM-like data plane: z = 800 + 0.05 x - 0.02 y, metres, around (5e5, 4.1e6).
const Vector3d planePoint(5.0e5, 4.1e6, 800.0);
const Vector3d planeNormal = Vector3d(-0.05, 0.02, 1.0).normalized();

// Where the segment a-b meets the data plane (the cell the view's selection found).
Vector3d meetPlane(const Vector3d& a, const Vector3d& b)
{
  const double t = planeNormal.dot(planePoint - a) / planeNormal.dot(b - a);
  return a + t * (b - a);
}

DisplayTransform exaggerated(double s)
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const Vector3d scale = exaggeration_scale(s);
  return DisplayTransform::of_prop(zero, zero, zero, scale.data());
}
}

TEST(DisplayTransform, MatrixIsTheOneVtkProp3DDrawsWith)
{
  const double position[3] = { 10.0, -4.0, 2.5 };
  const double orientation[3] = { 20.0, -35.0, 70.0 };
  const double origin[3] = { 3.0, 1.0, -2.0 };
  const double scale[3] = { 1.5, 0.5, 5.0 };
  vtkNew<vtkActor> actor;
  actor->SetPosition(position[0], position[1], position[2]);
  actor->SetOrientation(orientation[0], orientation[1], orientation[2]);
  actor->SetOrigin(origin[0], origin[1], origin[2]);
  actor->SetScale(scale[0], scale[1], scale[2]);
  vtkMatrix4x4* expected = actor->GetMatrix();
  const Eigen::Matrix4d m =
    DisplayTransform::of_prop(position, orientation, origin, scale).matrix();
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      EXPECT_NEAR(m(i, j), expected->GetElement(i, j), 1e-12) << i << ", " << j;
    }
  }
}

TEST(DisplayTransform, ExaggeratedPickFindsTheDataPointDrawnUnderTheCursor)
{
  for (double s : { 1.0, 5.0, 20.0 })
  {
    const DisplayTransform shown = exaggerated(s);
    const Vector3d data = planePoint + Vector3d(1200.0, -700.0, 0.0);
    const Vector3d drawn =
      data + Vector3d(0, 0, planeNormal.dot(planePoint - data) / planeNormal.z());
    const CameraProjection view = oblique(2.0e4, shown.to_world(drawn), false);
    const Vector3d pixel = view.to_display(shown.to_world(drawn));
    const Vector3d nearEnd = view.to_world(Vector3d(pixel.x(), pixel.y(), 0.0));
    const Vector3d farEnd = view.to_world(Vector3d(pixel.x(), pixel.y(), 1.0));
    // The rule: the view ray in the data's coordinates meets the cell there.
    const Vector3d found = meetPlane(shown.to_data(nearEnd), shown.to_data(farEnd));
    EXPECT_LE((found - drawn).norm(), 1e-6) << "s = " << s;
    EXPECT_LE((view.to_display(shown.to_world(found)) - pixel).head<2>().norm(), 1e-6);
    if (s > 1.0)
    {
      // The world ray against the data's own cell (what ParaView's point-on-surface pick
      // does) lands elsewhere: kilometres off.
      EXPECT_GT((meetPlane(nearEnd, farEnd) - drawn).norm(), 1000.0) << "s = " << s;
    }
    // The normal comes back perpendicular to the drawn surface, toward the viewer.
    const Vector3d toward = (view.to_world(Vector3d(pixel.x(), pixel.y(), 0.0)) -
                             view.to_world(Vector3d(pixel.x(), pixel.y(), 0.5)))
                              .normalized();
    const Vector3d n = shown.normal_to_world(-planeNormal, toward);
    const Vector3d alongX = shown.to_world(Vector3d(1, 0, 0.05)) - shown.to_world(Vector3d::Zero());
    const Vector3d alongY =
      shown.to_world(Vector3d(0, 1, -0.02)) - shown.to_world(Vector3d::Zero());
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(n.dot(alongX), 0.0, 1e-12);
    EXPECT_NEAR(n.dot(alongY), 0.0, 1e-12);
    EXPECT_GT(n.dot(toward), 0.0);
  }
}

TEST(DisplayTransform, PullMovesTheDataByTheCursorsMotionInDataUnits)
{
  // A pull on the exaggerated surface: the grasp stays under the cursor, and in the data
  // it moves as drawn across and by the drawn rise over s up.
  const double s = 5.0;
  const DisplayTransform shown = exaggerated(s);
  const Vector3d grasp = planePoint;
  const Vector3d world = shown.to_world(grasp);
  const CameraProjection view = oblique(2.0e4, world, false);
  PullControl pull;
  pull.press(view.pixel(world), world, Vector3d::UnitZ());
  pull.move(pull.target() + Vector2d(10.0, 80.0), false);
  const Vector3d drawnDisplacement = pull.displacement(view, Vector3d::UnitZ());
  const Vector3d dataDisplacement = shown.to_data(world + drawnDisplacement) - grasp;
  EXPECT_LE((view.pixel(shown.to_world(grasp + dataDisplacement)) - pull.target()).norm(), 1e-6);
  EXPECT_GT(drawnDisplacement.z(), 0.0);
  EXPECT_NEAR(dataDisplacement.z(), drawnDisplacement.z() / s, 1e-9 * drawnDisplacement.z());
  EXPECT_LE(
    (dataDisplacement - drawnDisplacement).head<2>().norm(), 1e-9 * drawnDisplacement.norm());
}

TEST(DisplayTransform, ExaggerationIsTheVerticalScaleWithinItsRange)
{
  EXPECT_EQ(exaggeration_scale(5.0), Vector3d(1.0, 1.0, 5.0));
  EXPECT_EQ(exaggeration_scale(1e6), Vector3d(1.0, 1.0, max_exaggeration));
  EXPECT_EQ(exaggeration_scale(0.0), Vector3d(1.0, 1.0, min_exaggeration));
  EXPECT_EQ(exaggeration_scale(std::nan("")), Vector3d(1.0, 1.0, 1.0));
  const double five[3] = { 1.0, 1.0, 5.0 };
  const double doubled[3] = { 2.0, 2.0, 10.0 };
  const double uneven[3] = { 1.0, 2.0, 5.0 };
  EXPECT_EQ(exaggeration_of(five), 5.0);
  EXPECT_EQ(exaggeration_of(doubled), 5.0);
  EXPECT_TRUE(std::isnan(exaggeration_of(uneven)));
  EXPECT_FALSE(DisplayTransform(Eigen::Matrix4d::Zero()).invertible());
}

TEST(DisplayTransform, GraspTakesTheVertexDrawnNearest)
{
  // Under Scale (1, 1, 5) a vertex 60 m to the side is drawn nearer than one 20 m below.
  const DisplayTransform shown = exaggerated(5.0);
  EXPECT_DOUBLE_EQ(shown.stretch(), 5.0);
  const Vector3d picked(0.0, 0.0, 0.0);
  const std::vector<Vector3d> candidates = { Vector3d(0, 0, -20), Vector3d(60, 0, 0),
    Vector3d(0, 90, 0) };
  EXPECT_EQ(shown.nearest_drawn(picked, candidates), 1u);
  EXPECT_EQ(DisplayTransform().nearest_drawn(picked, candidates), 0u);
  EXPECT_EQ(DisplayTransform().stretch(), 1.0);
}

TEST(DisplayTransform, CageAboutThePointIsTheBrushAsDrawn)
{
  const DisplayTransform shown = exaggerated(5.0);
  const Vector3d at(7.0e5, 4.0e6, 4000.0); // world
  const Eigen::Matrix4d about = shown.about(at);
  const auto apply = [&about](const Vector3d& p)
  { return (about * p.homogeneous()).hnormalized(); };
  EXPECT_LE((apply(at) - at).norm(), 1e-9);
  // A brush of radius 100 (data) reaches 100 across and 500 up as drawn.
  EXPECT_LE((apply(at + Vector3d(100, 0, 0)) - (at + Vector3d(100, 0, 0))).norm(), 1e-9);
  EXPECT_LE((apply(at + Vector3d(0, 0, 100)) - (at + Vector3d(0, 0, 500))).norm(), 1e-9);
}
