#include "PullControl.h"

#include <algorithm>
#include <cmath>

namespace geoshaping::interactor
{

namespace
{
constexpr double degrees = 3.14159265358979323846 / 180.0;
// Lines closer than this to the view direction show as a point.
const double cos_along_view = std::cos(5.0 * degrees);
constexpr double max_pixels = 1e4;

Eigen::Vector3d on_view_plane(
  const ViewProjection& view, const Eigen::Vector2d& pixel, double depth)
{
  return view.to_world(Eigen::Vector3d(pixel.x(), pixel.y(), depth));
}
}

std::optional<PullConstraint> constraint_for_key(char key, PullConstraint current)
{
  PullConstraint asked;
  switch (key)
  {
    case 'z':
    case 'Z':
      asked = PullConstraint::vertical;
      break;
    case 'n':
    case 'N':
      asked = PullConstraint::normal;
      break;
    case 'c':
    case 'C':
      return PullConstraint::view_plane;
    default:
      return std::nullopt;
  }
  return asked == current ? PullConstraint::view_plane : asked;
}

std::string pull_mode_note(PullConstraint in_force, PullConstraint chosen)
{
  const auto name = [](PullConstraint c)
  {
    return std::string(c == PullConstraint::vertical ? "vertical only (z)"
                       : c == PullConstraint::normal ? "along the surface normal"
                                                     : "follow the cursor");
  };
  if (in_force == chosen)
  {
    return "Every pull: " + name(chosen) + ", until changed here.";
  }
  return "This drag: " + name(in_force) + " (by key); the release goes back to " + name(chosen) +
         ".";
}

void PullControl::press(
  const Eigen::Vector2d& cursor, const Eigen::Vector3d& grasp, const Eigen::Vector3d& normal)
{
  press_ = last_ = target_ = cursor;
  grasp_ = grasp;
  normal_ = normal;
  base_.setZero();
  constraint_ = chosen_;
  pulling_ = true;
}

void PullControl::choose(PullConstraint constraint)
{
  chosen_ = constraint;
  if (!pulling_)
  {
    constraint_ = constraint;
  }
}

bool PullControl::release()
{
  pulling_ = false;
  const bool back = constraint_ != chosen_;
  constraint_ = chosen_;
  return back;
}

void PullControl::constrain(
  PullConstraint constraint, const ViewProjection& view, const Eigen::Vector3d& up)
{
  if (constraint == constraint_)
  {
    return;
  }
  base_ = displacement(view, up);
  press_ = target_;
  constraint_ = constraint;
}

void PullControl::move(const Eigen::Vector2d& cursor, bool precise)
{
  target_ += (precise ? precision_factor : 1.0) * (cursor - last_);
  last_ = cursor;
}

Eigen::Vector3d PullControl::displacement(
  const ViewProjection& view, const Eigen::Vector3d& up) const
{
  const Eigen::Vector3d d = base_ + segment(view, up);
  return d.allFinite() ? d : Eigen::Vector3d::Zero();
}

Eigen::Vector3d PullControl::segment(const ViewProjection& view, const Eigen::Vector3d& up) const
{
  const Eigen::Vector3d from = grasp_ + base_;
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  if (!from.allFinite() || !target_.allFinite())
  {
    return d;
  }
  switch (constraint_)
  {
    case PullConstraint::view_plane:
    {
      const double depth = view.to_display(from).z();
      d = on_view_plane(view, target_, depth) - on_view_plane(view, press_, depth);
      break;
    }
    case PullConstraint::vertical:
      d = along_line(view, from, up);
      break;
    case PullConstraint::normal:
      d = along_line(view, from, normal_);
      break;
  }
  return d.allFinite() ? d : Eigen::Vector3d::Zero();
}

Eigen::Vector3d PullControl::along_line(
  const ViewProjection& view, const Eigen::Vector3d& from, const Eigen::Vector3d& axis) const
{
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return Eigen::Vector3d::Zero();
  }
  const Eigen::Vector3d a = axis / length;
  const Eigen::Vector3d g_display = view.to_display(from);
  const Eigen::Vector2d g_pixel = g_display.head<2>();
  const double depth = g_display.z();
  // World length of one pixel on the view plane through the grasp.
  const double pixel =
    (on_view_plane(view, g_pixel + Eigen::Vector2d(1.0, 0.0), depth) - from).norm();
  const Eigen::Vector3d near = on_view_plane(view, g_pixel, 0.0);
  const Eigen::Vector3d into_view = (on_view_plane(view, g_pixel, 1.0) - near).normalized();
  if (!(pixel > 0.0) || !into_view.allFinite())
  {
    return Eigen::Vector3d::Zero();
  }
  const Eigen::Vector2d motion = target_ - press_;
  if (motion.isZero(0.0))
  {
    // Where the segment began (the ray through g's own pixel meets the line at g, up to
    // rounding): a switch to this line is then exactly continuous.
    return Eigen::Vector3d::Zero();
  }
  double t = 0.0;
  if (std::abs(a.dot(into_view)) > cos_along_view)
  {
    t = motion.y() * pixel * (a.dot(into_view) < 0.0 ? 1.0 : -1.0);
  }
  else
  {
    const Eigen::Vector2d image = view.to_display(from + pixel * a).head<2>() - g_pixel;
    if (!(image.norm() > 0.0))
    {
      return Eigen::Vector3d::Zero();
    }
    const Eigen::Vector2d e = image.normalized();
    const Eigen::Vector2d pixel_on_line = g_pixel + motion.dot(e) * e;
    const Eigen::Vector3d o = on_view_plane(view, pixel_on_line, 0.0);
    const Eigen::Vector3d r = (on_view_plane(view, pixel_on_line, 1.0) - o).normalized();
    const Eigen::Vector3d w = from - o;
    const double b = a.dot(r);
    t = (b * r.dot(w) - a.dot(w)) / (1.0 - b * b);
  }
  const double limit = max_pixels * pixel;
  return std::clamp(std::isfinite(t) ? t : 0.0, -limit, limit) * a;
}

} // namespace geoshaping::interactor
