#pragma once
// A camera as the GUI tests' Qt-free units see it: VTK's view transform and perspective
// or parallel projection on a viewport, as a geoshaping::interactor::ViewProjection.
#include "HapticsControl.h"
#include "PullControl.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>

namespace geoshaping::interactor::test_camera
{
using Eigen::Vector2d;
using Eigen::Vector3d;

// A camera as VTK builds it (vtkCamera view transform, perspective or parallel
// projection) on a width x height viewport; display depth in [0, 1].
class CameraProjection : public ViewProjection
{
public:
  CameraProjection(const CameraPose& c, double width, double height, double near, double far)
  {
    const Vector3d z = (c.position - c.focal_point).normalized();
    const Vector3d x = c.view_up.cross(z).normalized();
    const Vector3d y = z.cross(x);
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
    view.block<1, 3>(0, 0) = x.transpose();
    view.block<1, 3>(1, 0) = y.transpose();
    view.block<1, 3>(2, 0) = z.transpose();
    view.block<3, 1>(0, 3) = -view.block<3, 3>(0, 0) * c.position;
    const double aspect = width / height;
    Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
    if (c.parallel)
    {
      const double s = c.parallel_scale;
      projection(0, 0) = 1.0 / (aspect * s);
      projection(1, 1) = 1.0 / s;
      projection(2, 2) = -2.0 / (far - near);
      projection(2, 3) = -(far + near) / (far - near);
      projection(3, 3) = 1.0;
    }
    else
    {
      const double f = 1.0 / std::tan(0.5 * c.view_angle_deg * 3.14159265358979323846 / 180.0);
      projection(0, 0) = f / aspect;
      projection(1, 1) = f;
      projection(2, 2) = -(far + near) / (far - near);
      projection(2, 3) = -2.0 * far * near / (far - near);
      projection(3, 2) = -1.0;
    }
    Eigen::Matrix4d viewport = Eigen::Matrix4d::Identity();
    viewport(0, 0) = 0.5 * width;
    viewport(0, 3) = 0.5 * width;
    viewport(1, 1) = 0.5 * height;
    viewport(1, 3) = 0.5 * height;
    viewport(2, 2) = 0.5;
    viewport(2, 3) = 0.5;
    toDisplay = viewport * projection * view;
    toWorld = toDisplay.inverse();
  }
  Vector3d to_display(const Vector3d& world) const override
  {
    return (toDisplay * world.homogeneous()).hnormalized();
  }
  Vector3d to_world(const Vector3d& display) const override
  {
    return (toWorld * display.homogeneous()).hnormalized();
  }
  Vector2d pixel(const Vector3d& world) const { return to_display(world).head<2>(); }

private:
  Eigen::Matrix4d toDisplay, toWorld;
};

// An oblique camera on a scene of size `scale` centred at `centre`.
inline CameraProjection oblique(double scale, const Vector3d& centre, bool parallel)
{
  CameraPose c;
  c.focal_point = centre;
  c.position = centre + scale * Vector3d(0.4, -1.6, 1.3);
  c.view_up = Vector3d(0.0, 0.6, 0.8);
  c.view_angle_deg = 30.0;
  c.parallel = parallel;
  c.parallel_scale = 0.6 * scale;
  return CameraProjection(c, 800, 600, 0.1 * scale, 10.0 * scale);
}

} // namespace geoshaping::interactor::test_camera
