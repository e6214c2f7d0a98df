#pragma once
// @brief The servo tick's passivity controller: the passivity observer and variable damper
// of Hannaford & Ryu (2002), and an energy bound on the springs' force (an energy tank, in
// the spirit of Kim & Ryu's Energy Bounding, 2004): the springs give the stylus back no
// more than the rendering absorbed from it, without relying on the device's own damping,
// also where the scene moves or a contact comes back after a freeze. docs/haptics.md,
// "Passivity". No allocation, no lock.
#include "geoshaping/haptics/force_model.h"

namespace geoshaping::haptics
{

class PassivityController
{
public:
  // Forgets the observed work, the tank, the last position and force, the damper and the
  // scale (a restarted loop).
  void reset();

  // One servo tick. `position` is the one read this tick (as the servo sees it, quantised)
  // and `readable` whether there is one (false after a fault: the observer's chain of
  // positions restarts; the force over the gap is unknown and not counted). `rendered` is
  // compute_force's result: F_d its force, U its stored_energy, C_k its scene_work.
  // `before` and `after` are the fades before and after compute_force this tick (a fade
  // that moved used the tick's step). Returns the force F to send; with s the scale
  // carried from the last tick (1 at first) and dx = x_k - x_(k-1):
  //
  //   the observer (Hannaford & Ryu):
  //     W += F_(k-1) . dx
  //   the tank, the energy the rendering absorbed, by the trapezoidal rule:
  //     L -= (F_(k-1) + s F_d) . dx / 2,   L += C_k with credit_scene_work,
  //     L  = max(L, 0) where U <= m
  //   the energy bound, a scale on the springs' force:
  //     s* = U <= L + m ? 1 : max(L + m, 0) / U
  //     s moves toward s* within [s - step / |F_d|, s + step / |F_d|], step the fades'
  //       F_max T / fade_time: not down in a tick where a fade fell, nor up where one
  //       rose; down to s (U - C_k) / U at once in a tick where the scene carried the
  //       proxy (C_k > 0)
  //   the damper (Hannaford & Ryu), C the credited scene work:
  //     E  = W + s F_d . dx + s U - C + m
  //     f moves toward E > 0 ? -min(E / |dx|^2, b_max / T) dx : 0 by what the scale left
  //       of the step, step - |s_k - s_(k-1)| |F_d|; not at all in a tick where a fade moved
  //   F  = s F_d + f, less any part of f against F_d in contact, scaled down to max force;
  //   F  = F_d, f = 0, s = 1 where F_d = 0 (no spring acts).
  //
  // Why the bound. The damper dissipates only what the stylus's motion lets it (at most
  // the device's rated max damping b_max), so it cannot stop a spring that lifts the hand
  // with energy the rendering never absorbed: a surface carrying the proxy up, a contact
  // fading back in on a stylus pushed centimetres deep during a freeze. Scaled by s, a
  // spring holding U gives back at most s U, and s <= s* keeps L + m >= s U: whatever the
  // stylus does next, the springs return no more than the rendering absorbed plus m. L
  // counts the work of the force as if it followed the stylus within the tick (the
  // trapezoidal rule): a zero-order hold does about k |dx|^2 / 2 more a tick, which the
  // damper takes back (charged to L, it would scale down a stylus that merely arrives
  // fast). A carry stretches the spring by k_c times the carried distance in one tick;
  // the scale may drop as fast, so that the stylus is not lifted before the bound acts.
  // Debt is forgiven where the springs hold at most m (a spring at rest): a scale of zero
  // absorbs nothing and would stay zero for good.
  //
  // The scale changes the force by at most step a tick, shared with the damper, and a
  // carry's drop by at most what the carry added, so a tick's force step stays within
  // k_c |dx| (+ k_c carried) + step; it never turns a push into a pull. Where U <= L + m
  // (a static scene, whose springs hold what the stylus put in) s = 1 and F is F_d plus
  // the damper, bit for bit. m is params.passivity_margin: the observer reads quantised
  // positions, and a first contact stores energy before the force has absorbed any. C_k
  // is credited only with params.credit_scene_work (a surface rising under the stylus
  // then lifts the hand: not passive). With params.passivity_control off it returns F_d
  // unchanged.
  Eigen::Vector3d control(const Eigen::Vector3d& position, bool readable,
    const ForceResult& rendered, const ForceFade& before, const ForceFade& after,
    const ForceParams& params, const DeviceLimits& limits);

  // The scale s the energy bound applies to the springs' force this tick (1: none).
  double scale() const { return this->scale_; }

private:
  // The energy bound's step: the new scale, given this tick's stored energy U, scene work
  // C_k, |F_d|, the fades' step and margin, and whether a fade fell or rose this tick.
  double bounded_scale(double stored, double scene_work, double desired_norm, double step,
    double margin, bool fell, bool rose) const;

  // What control() carries from tick to tick: W is work_, L tank_, C scene_work_, f
  // damper_, s scale_.
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_force_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d damper_ = Eigen::Vector3d::Zero();
  double work_ = 0.0;
  double tank_ = 0.0;
  double scene_work_ = 0.0;
  double scale_ = 1.0;
  bool have_last_ = false;
};

} // namespace geoshaping::haptics
