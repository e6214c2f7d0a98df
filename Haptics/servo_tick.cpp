#include "geoshaping/haptics/servo_tick.h"

namespace geoshaping::haptics
{

ServoTick::ServoTick(const ForceParams& params, double velocity_filter_s)
  : params_(params)
  , velocity_filter_s_(velocity_filter_s)
{
}

void ServoTick::reset()
{
  this->proxy_.reset();
  this->fade_ = ForceFade();
  this->passivity_.reset();
  this->velocity_.setZero();
  this->have_last_ = false;
}

ForceResult ServoTick::tick(const DeviceSample& sample, bool device_ok, Clock::time_point now,
  const SceneSnapshot& scene, const DeviceLimits& limits)
{
  if (device_ok && sample.position.allFinite())
  {
    // The device's own time stamps, so a late tick does not read as a fast stylus.
    const double dt = sample.t - this->last_t_;
    if (this->have_last_ && dt > 0.0)
    {
      const Eigen::Vector3d raw = (sample.position - this->last_position_) / dt;
      const double alpha = dt / (dt + this->velocity_filter_s_);
      this->velocity_ += alpha * (raw - this->velocity_);
    }
    if (!this->velocity_.allFinite())
      this->velocity_.setZero();
    this->last_position_ = sample.position;
    this->last_t_ = sample.t;
    this->have_last_ = true;
  }
  else
  {
    this->have_last_ = false;
    this->velocity_.setZero();
  }
  ForceInput in;
  in.position = sample.position;
  in.velocity = this->velocity_;
  in.device_ok = device_ok;
  in.now = now;
  const ForceFade before = this->fade_;
  ForceResult r = compute_force(in, scene, this->params_, limits, this->proxy_, &this->fade_);
  const bool fault = r.status == ForceStatus::device_error || r.status == ForceStatus::non_finite;
  r.force = this->passivity_.control(
    sample.position, !fault, r, before, this->fade_, this->params_, limits);
  return r;
}

} // namespace geoshaping::haptics
