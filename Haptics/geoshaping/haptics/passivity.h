#pragma once
// @brief The passivity observer and controller of Hannaford & Ryu (2002) on the servo tick:
// the work the rendered force does on the stylus is observed each tick, and a variable
// damper, changing its force at most by the fade's step a tick, keeps it from becoming
// positive, so that the display is passive without relying on the device's own damping.
// docs/haptics.md, "Passivity". No allocation, no lock.
#include "geoshaping/haptics/force_model.h"

namespace geoshaping::haptics
{

class PassivityController
{
public:
  // Forgets the observed work, the last position and force, and the damper (a restarted
  // loop).
  void reset();

  // One servo tick. `position` is the one read this tick (as the servo sees it, quantised)
  // and `readable` whether there is one (false after a fault: the observer's chain of
  // positions restarts; the force over the gap is unknown and not counted). `rendered` is
  // compute_force's result: F_d its force, U its stored_energy, and its scene_work adds to
  // C. `hold` keeps the damper's force as it was (a fade moved this tick and used the
  // step). Returns the force to send:
  //
  //   W += F_(k-1) . (x_k - x_(k-1))                       the observer
  //   E  = W + F_d . dx + U - C + margin,  dx = x_k - x_(k-1)
  //   target = E > 0 ? -min(E / |dx|^2, b_max / T) dx : 0   the damper (Hannaford & Ryu)
  //   f moves toward target by at most F_max T / fade_time (the fades' step),
  //   F = F_d + f, less any part against F_d in contact, scaled down to max force;
  //   F = F_d, f = 0 where F_d = 0 (no spring acts).
  //
  // C is the work a moving scene did (a surface carrying the stylus up does work on the
  // hand); a static scene gives C = 0 and W <= -U - margin wherever the damper keeps up.
  // With `params`' passivity_control off it observes and returns F_d unchanged.
  Eigen::Vector3d control(const Eigen::Vector3d& position, bool readable,
    const ForceResult& rendered, bool hold, const ForceParams& params, const DeviceLimits& limits);

private:
  // What control() carries from tick to tick: W is work_, C scene_work_, f damper_.
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_force_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d damper_ = Eigen::Vector3d::Zero();
  double work_ = 0.0;
  double scene_work_ = 0.0;
  bool have_last_ = false;
};

} // namespace geoshaping::haptics
