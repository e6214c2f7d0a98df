#include "HapticsControl.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping::interactor
{

WorkspaceMapping::WorkspaceMapping(const CameraPose& camera, double workspace_radius)
{
  const Eigen::Vector3d toward_viewer = camera.position - camera.focal_point;
  const double distance = toward_viewer.norm();
  const Eigen::Vector3d z = toward_viewer / distance;
  const Eigen::Vector3d x = camera.view_up.cross(z);
  if (!(distance > 0.0) || !(x.norm() > 1e-12) || !(workspace_radius > 0.0) ||
      !std::isfinite(distance))
  {
    return;
  }
  axes_.col(0) = x.normalized();
  axes_.col(2) = z;
  axes_.col(1) = z.cross(axes_.col(0));
  const double pi = 3.14159265358979323846;
  const double half_height = camera.parallel
                               ? camera.parallel_scale
                               : distance * std::tan(0.5 * camera.view_angle_deg * pi / 180.0);
  if (!(half_height > 0.0) || !std::isfinite(half_height))
  {
    axes_.setIdentity();
    return;
  }
  origin_ = camera.focal_point;
  scale_ = half_height / workspace_radius;
  valid_ = true;
}

Eigen::Vector3d WorkspaceMapping::to_scene(const Eigen::Vector3d& device) const
{
  return origin_ + vector_to_scene(device);
}

Eigen::Vector3d WorkspaceMapping::vector_to_scene(const Eigen::Vector3d& device) const
{
  return scale_ * (axes_ * device);
}

Eigen::Vector3d WorkspaceMapping::to_device(const Eigen::Vector3d& scene) const
{
  return axes_.transpose() * (scene - origin_) / scale_;
}

Eigen::Quaterniond WorkspaceMapping::rotation_to_scene(const Eigen::Quaterniond& device) const
{
  // A rotation R in device axes is A R A^T in scene axes.
  return Eigen::Quaterniond(axes_ * device.toRotationMatrix() * axes_.transpose());
}

Eigen::Matrix4d RigidMotion::matrix() const
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  const Eigen::Matrix3d r = rotation.toRotationMatrix();
  m.topLeftCorner<3, 3>() = r;
  m.topRightCorner<3, 1>() = pivot + translation - r * pivot;
  return m;
}

HandActions HandController::finish()
{
  HandActions actions;
  if (held_)
  {
    actions.release = tool_ == Tool::deform;
    actions.end_hold = tool_ == Tool::hold_and_turn;
    actions.end_stroke = tool_ == Tool::paint;
    stroke_.end();
  }
  held_ = false;
  return actions;
}

HandActions HandController::set_tool(Tool tool)
{
  if (tool == tool_)
  {
    return {};
  }
  HandActions actions = finish();
  tool_ = tool;
  return actions;
}

HandActions HandController::update(const StylusState& stylus, const Brush& brush)
{
  const bool finite = stylus.position.allFinite() && stylus.orientation.coeffs().allFinite();
  if (!stylus.button || !finite)
  {
    return finish();
  }
  HandActions actions;
  const bool pressed = !held_;
  if (pressed)
  {
    held_ = true;
    press_position_ = stylus.position;
    press_orientation_ = stylus.orientation.normalized();
  }
  switch (tool_)
  {
    case Tool::deform:
      actions.grasp = pressed;
      actions.grasp_position = press_position_;
      actions.set_displacement = true;
      actions.displacement = stylus.position - press_position_;
      break;
    case Tool::paint:
    {
      actions.begin_stroke = pressed;
      std::vector<Eigen::Vector3d> centres;
      if (pressed)
      {
        stroke_.begin(stylus.position, centres);
      }
      else
      {
        stroke_.move_to(stylus.position, brush.radius, centres);
      }
      for (const Eigen::Vector3d& p : centres)
      {
        actions.dabs.push_back({ p.x(), p.y(), p.z(), brush.radius,
          std::clamp(brush.value, 0.0, 1.0), std::clamp(brush.strength, 0.0, 1.0) });
      }
      break;
    }
    case Tool::hold_and_turn:
      actions.begin_hold = pressed;
      actions.set_motion = true;
      actions.motion.pivot = press_position_;
      actions.motion.translation = stylus.position - press_position_;
      actions.motion.rotation =
        (stylus.orientation.normalized() * press_orientation_.conjugate()).normalized();
      break;
  }
  return actions;
}

bool stopped_grasp(const Eigen::Vector3d& press, const Eigen::Vector3d& displacement,
  double fraction, const Eigen::Vector3d* moved, Eigen::Vector3d& stopped)
{
  if (!(fraction >= 0.0))
  {
    return false; // no grasp yet
  }
  if (moved && moved->allFinite())
  {
    if (*moved == displacement)
    {
      return false; // where the stylus put it
    }
    stopped = press + *moved;
    return stopped.allFinite();
  }
  if (!(fraction < 1.0))
  {
    return false;
  }
  stopped = press + fraction * displacement;
  return stopped.allFinite();
}

double StylusPalette::update(bool button, const Eigen::Vector3d& stylus, double workspace_radius)
{
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  if (!button)
  {
    shown_ = false;
    touched_ = -1;
    return none;
  }
  if (!shown_)
  {
    if (!stylus.allFinite())
    {
      return none;
    }
    shown_ = true;
    row_centre_ = stylus + Eigen::Vector3d(0.0, lift, 0.0);
    const double room = workspace_radius - 0.5 * spacing * (count - 1);
    if (room > 0.0)
    {
      row_centre_.x() = std::clamp(row_centre_.x(), -room, room);
    }
  }
  int nearest = -1;
  double best = radius * radius;
  for (int i = 0; i < count && stylus.allFinite(); ++i)
  {
    const double d2 = (stylus - this->centre(i)).squaredNorm();
    if (d2 <= best)
    {
      best = d2;
      nearest = i;
    }
  }
  const bool fresh = nearest >= 0 && nearest != touched_;
  touched_ = nearest;
  return fresh ? value(nearest) : none;
}

Eigen::Vector3d StylusPalette::centre(int i) const
{
  return row_centre_ + Eigen::Vector3d(spacing * (i - 0.5 * (count - 1)), 0.0, 0.0);
}

} // namespace geoshaping::interactor
