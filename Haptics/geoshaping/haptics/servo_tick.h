#pragma once
// @brief What one servo tick computes and the state it keeps between ticks: the stylus
// velocity (filtered) and the contact proxy. ServoLoop runs it at 1 kHz on its thread;
// the hand simulator (hand_sim.h) runs the very same code against a simulated device.
// No allocation, no lock.
#include "geoshaping/haptics/force_model.h"
#include "geoshaping/haptics/passivity.h"

namespace geoshaping::haptics
{

class ServoTick
{
public:
  // Velocity for damping: finite difference of positions on the device's own time
  // stamps, low-passed with time constant `velocity_filter_s` (encoder quantisation
  // makes the raw difference noisy):
  //   v <- v + dt / (dt + tau) ((x - x_last) / dt - v).
  explicit ServoTick(const ForceParams& params = {}, double velocity_filter_s = 0.005);

  // Forgets the velocity, the proxy and the fades (a restarted loop).
  void reset();

  // One tick: updates the velocity from `sample` (a failed read or a non-finite position
  // zeroes it), then compute_force with the proxy and the fades kept here, then the
  // passivity controller (passivity.h) on its force.
  ForceResult tick(const DeviceSample& sample, bool device_ok, Clock::time_point now,
    const SceneSnapshot& scene, const DeviceLimits& limits);

  const Eigen::Vector3d& velocity() const { return this->velocity_; }
  const ContactProxy& proxy() const { return this->proxy_; }
  const ForceFade& fade() const { return this->fade_; }
  const PassivityController& passivity() const { return this->passivity_; }
  const ForceParams& params() const { return this->params_; }

private:
  ForceParams params_;
  double velocity_filter_s_;
  ContactProxy proxy_;
  ForceFade fade_;
  PassivityController passivity_;
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
  double last_t_ = 0.0;
  bool have_last_ = false;
};

} // namespace geoshaping::haptics
