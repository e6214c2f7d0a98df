#include "geoshaping/haptics/passivity.h"

#include <algorithm>
#include <cmath>

namespace geoshaping::haptics
{

void PassivityController::reset()
{
  *this = PassivityController();
}

Eigen::Vector3d PassivityController::control(const Eigen::Vector3d& position, bool readable,
  const ForceResult& rendered, bool hold, const ForceParams& params, const DeviceLimits& limits)
{
  const Eigen::Vector3d& desired = rendered.force;
  const double scene_work = rendered.scene_work;
  if (!readable || !position.allFinite() || !desired.allFinite())
  {
    // A fault: compute_force renders zero at once; the chain of positions restarts.
    this->have_last_ = false;
    this->damper_.setZero();
    this->last_force_.setZero();
    return desired.allFinite() ? desired : Eigen::Vector3d::Zero();
  }
  const Eigen::Vector3d dx =
    this->have_last_ ? Eigen::Vector3d(position - this->last_position_) : Eigen::Vector3d::Zero();
  this->work_ += this->last_force_.dot(dx);
  if (std::isfinite(scene_work) && scene_work > 0.0)
    this->scene_work_ += scene_work;

  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  const double dx2 = dx.squaredNorm();
  const bool rendering = (desired.array() != 0.0).any();
  if (!rendering)
  {
    // No spring acts: nothing to control, and no force where nothing is touched.
    this->damper_.setZero();
    this->last_position_ = position;
    this->last_force_ = desired;
    this->have_last_ = true;
    return desired;
  }
  if (params.passivity_control && dx2 > 0.0 && params.servo_period > 0.0)
  {
    const double ahead = desired.dot(dx);
    const double excess = this->work_ + ahead + rendered.stored_energy - this->scene_work_ +
                          std::max(0.0, params.passivity_margin);
    // The damper of Hannaford & Ryu, alpha = excess T / |dx|^2, at most the device's rated
    // max damping: stronger, it would stop a slow stylus dead, and only motion dissipates.
    const double b_max = std::max(0.0, limits.max_damping);
    if (excess > 0.0)
      target = -std::min(excess / dx2, b_max / params.servo_period) * dx;
  }
  const double f_max = std::max(0.0, limits.max_force);
  if (!hold)
  {
    const double step =
      params.fade_time > 0.0 ? f_max * params.servo_period / params.fade_time : f_max;
    const Eigen::Vector3d change = target - this->damper_;
    const double n = change.stableNorm();
    this->damper_ += n > step ? Eigen::Vector3d(change * (step / n)) : change;
    const double d = this->damper_.stableNorm();
    if (d > f_max)
      this->damper_ *= f_max / d;
  }
  Eigen::Vector3d force = desired; // as it is while the damper rests (bit for bit)
  if ((this->damper_.array() != 0.0).any())
  {
    force += this->damper_;
    // The damper brakes; it never turns contact's push into a pull (a sticky surface).
    const double along = force.dot(desired);
    if (rendered.in_contact && along < 0.0)
      force -= (along / desired.squaredNorm()) * desired;
    const double n = force.stableNorm();
    if (n > f_max)
      force *= f_max / n;
  }
  this->last_position_ = position;
  this->last_force_ = force;
  this->have_last_ = true;
  return force;
}

} // namespace geoshaping::haptics
