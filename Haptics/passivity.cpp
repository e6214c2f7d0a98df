#include "geoshaping/haptics/passivity.h"

#include <algorithm>
#include <cmath>

namespace geoshaping::haptics
{

void PassivityController::reset()
{
  *this = PassivityController();
}

double PassivityController::bounded_scale(double stored, double scene_work, double desired_norm,
  double step, double margin, bool fell, bool rose) const
{
  // The springs may hold what the rendering absorbed, plus the margin.
  const double budget = std::max(0.0, this->tank_ + margin);
  const double bound = stored <= budget ? 1.0 : budget / stored;
  const double reach = step / desired_norm;
  // A moving scene stretched the spring this tick (a step of k_c times the carry): the
  // scale may drop at once to keep the spring's energy where it was, within that step.
  const double carried = std::isfinite(scene_work) && scene_work > 0.0 && stored > 0.0
                           ? this->scale_ * std::max(0.0, stored - scene_work) / stored
                           : this->scale_;
  const double lo = std::min(fell ? this->scale_ : this->scale_ - reach, carried);
  const double hi = rose ? this->scale_ : this->scale_ + reach;
  return std::clamp(bound, std::max(0.0, lo), std::min(1.0, hi));
}

Eigen::Vector3d PassivityController::control(const Eigen::Vector3d& position, bool readable,
  const ForceResult& rendered, const ForceFade& before, const ForceFade& after,
  const ForceParams& params, const DeviceLimits& limits)
{
  const Eigen::Vector3d& desired = rendered.force;
  const double scene_work = rendered.scene_work;
  if (!readable || !position.allFinite() || !desired.allFinite())
  {
    // A fault: compute_force renders zero at once; the chain of positions restarts.
    this->have_last_ = false;
    this->damper_.setZero();
    this->scale_ = 1.0;
    this->last_force_.setZero();
    return desired.allFinite() ? desired : Eigen::Vector3d::Zero();
  }
  const Eigen::Vector3d dx =
    this->have_last_ ? Eigen::Vector3d(position - this->last_position_) : Eigen::Vector3d::Zero();
  this->work_ += this->last_force_.dot(dx);
  // The tank takes the work of the force had it followed the stylus over the tick (the
  // trapezoidal rule, the springs at this tick's position scaled as last tick): the
  // energy the rendering absorbed, without the hold's excess, which the damper takes back.
  this->tank_ -= 0.5 * (this->last_force_ + this->scale_ * desired).dot(dx);
  if (params.credit_scene_work && std::isfinite(scene_work) && scene_work > 0.0)
  {
    this->scene_work_ += scene_work;
    this->tank_ += scene_work;
  }
  const double margin = std::max(0.0, params.passivity_margin);
  const double stored = std::max(0.0, rendered.stored_energy);
  // No debt while the springs hold no more than the margin (at rest): a debt would scale
  // a spring to zero for good, and a spring scaled to zero absorbs nothing.
  if (stored <= margin)
    this->tank_ = std::max(this->tank_, 0.0);

  const bool rendering = (desired.array() != 0.0).any();
  if (!rendering)
  {
    // No spring acts: nothing to control, and no force where nothing is touched.
    this->damper_.setZero();
    this->scale_ = 1.0;
    this->last_position_ = position;
    this->last_force_ = desired;
    this->have_last_ = true;
    return desired;
  }
  const double f_max = std::max(0.0, limits.max_force);
  const double step = fade_step(params, f_max);
  const double desired_norm = desired.stableNorm();
  // Whether a fade fell or rose this tick (each used the tick's step).
  const bool fell = after.coupling < before.coupling || after.contact < before.contact;
  const bool rose = after.coupling > before.coupling || after.contact > before.contact;
  double left = step; // of the step, what the scale leaves the damper
  if (params.passivity_control)
  {
    const double scale =
      this->bounded_scale(stored, scene_work, desired_norm, step, margin, fell, rose);
    left = std::max(0.0, step - std::abs(scale - this->scale_) * desired_norm);
    this->scale_ = scale;
  }
  const Eigen::Vector3d spring = this->scale_ * desired;

  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  const double dx2 = dx.squaredNorm();
  if (params.passivity_control && dx2 > 0.0 && params.servo_period > 0.0)
  {
    const double ahead = spring.dot(dx);
    const double excess = this->work_ + ahead + this->scale_ * stored - this->scene_work_ + margin;
    // The damper of Hannaford & Ryu, alpha = excess T / |dx|^2, at most the device's rated
    // max damping: stronger, it would stop a slow stylus dead, and only motion dissipates.
    const double b_max = std::max(0.0, limits.max_damping);
    if (excess > 0.0)
      target = -std::min(excess / dx2, b_max / params.servo_period) * dx;
  }
  if (!fell && !rose) // the fades are in [0, 1]: either differs, or neither
  {
    const Eigen::Vector3d change = target - this->damper_;
    const double n = change.stableNorm();
    this->damper_ += n > left ? Eigen::Vector3d(change * (left / n)) : change;
    const double d = this->damper_.stableNorm();
    if (d > f_max)
      this->damper_ *= f_max / d;
  }
  Eigen::Vector3d force = spring; // as it is while the damper rests (bit for bit at s = 1)
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
