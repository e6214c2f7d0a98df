#pragma once
// @brief The force rendered each servo tick: virtual coupling to the grasped vertex plus
// contact with the scene's triangles through a proxy (proxy.h), clamped to what the
// device renders stably.
#include "geoshaping/haptics/proxy.h"
#include "geoshaping/haptics/snapshots.h"

#include <chrono>

namespace geoshaping::haptics
{

struct ForceParams
{
  // Coupling stiffness as a fraction of the device's max stiffness, for a rigid (m = 0)
  // and a soft (m = 1) grasped region: rigid rock pulls back harder.
  double rigid_fraction = 0.8;
  double soft_fraction = 0.15;
  // N s/m, while grasping. Small: by the passivity rule (below) each N s/m of virtual
  // damping costs 2 / T = 2000 N/m of stiffness; 0.05 leaves a rigid grasp (0.8 of the
  // max) its full stiffness.
  double coupling_damping = 0.05;

  double contact_stiffness = 800.0; // N/m, the spring from the stylus to the proxy
  // N s/m, along the contact normal. Zero, so that contact may use the device's whole
  // stiffness rating (the passivity rule below).
  double contact_damping = 0.0;
  // s, the zero-order hold period T of the passivity rule: the servo period (ServoLoop
  // sets it from ServoConfig::period).
  double servo_period = 0.001;
  double proxy_clearance = 1e-7; // m the proxy keeps off a triangle, on its side
  double proxy_reach = 0.005;    // m: how far a new patch's surface may have moved and
                                 // still carry the proxy with it (ContactProxy::carry_over)

  // A scene snapshot older than this is stale (compute_force), unless the snapshot says it
  // stays valid longer (SceneSnapshot::valid_for, a slow renderer), up to
  // stale_after_max: a frozen graphics thread still stops the coupling within that.
  std::chrono::nanoseconds stale_after = std::chrono::milliseconds(100);
  std::chrono::nanoseconds stale_after_max = std::chrono::milliseconds(500);
  // A stale scene's coupling fades out, but its contact patch (the surface the frozen view
  // still shows) keeps holding the proxy, with its force, until the scene is this old;
  // then that fades out too. The proxy is kept all along.
  std::chrono::nanoseconds stale_contact_max = std::chrono::seconds(2);
  // s for a force to fade from full to zero or back (ForceFade): 1 / 100 of it a tick at
  // 1 kHz, at most 0.033 N a tick at 3.3 N max force.
  double fade_time = 0.1;

  // ServoTick's passivity controller (passivity.h): the rendered force's work on the
  // stylus kept from being positive by a variable damper and an energy bound on the
  // springs' force, so that a display is passive without the device's own damping. Off:
  // the force compute_force gives, as is.
  bool passivity_control = true;
  // J the controller keeps the observed work below zero by, and the springs' seed: the
  // observer reads quantised positions, and the true work differs from the observed by the
  // force times the quantisation error; 50 uJ covers it in every run of the hand simulator
  // (docs/haptics.md, "Passivity").
  double passivity_margin = 50e-6;
  // Credit the work a moving scene does on the springs (ForceResult::scene_work) to the
  // controller, so that a surface rising under the stylus lifts the hand as it did before
  // the energy bound: the rendering is then not passive. Off: such a surface passes
  // through a resting stylus (the proxy keeps the side).
  bool credit_scene_work = false;
};

// What compute_force keeps from tick to tick beside the proxy: the fraction (0 to 1) of
// the coupling and of the contact force it renders. Each moves toward 1 while its force
// may be rendered and toward 0 when not, by servo_period / fade_time a tick, so that a
// stale scene or its return never cuts a force in or out in one tick.
struct ForceFade
{
  double coupling = 1.0;
  double contact = 1.0;
};

// How far a fade moves `amount` in one tick: amount servo_period / fade_time (all of it
// where fade_time <= 0). compute_force moves the fractions by fade_step(params); the
// passivity controller's force step is fade_step(params, max_force).
inline double fade_step(const ForceParams& params, double amount = 1.0)
{
  return params.fade_time > 0.0 ? amount * params.servo_period / params.fade_time : amount;
}

// Coupling stiffness for the malleability m in [0, 1] of the grasped region:
//   k(m) = k_max (rigid_fraction (1 - m) + soft_fraction m),
// m clamped to [0, 1]; NaN m is treated as rigid (as the deformer does).
double coupling_stiffness(
  double malleability, const ForceParams& params, const DeviceLimits& limits);

// A grasp an obstacle held back (docs/obstacles.md): the grasped vertex stopped at
// `stopped` (device coordinates) short of where the stylus put it. The coupling becomes
//
//   F = k_g (anchor - stopped) + k_w (stopped - x),   k_w = max(k_g, k(0)),
//
// k(0) the rigid coupling stiffness above: the pull of the deformation the grasp made
// plus a spring as stiff as rigid rock toward the stopped grasp, so pushing on into the
// obstacle is felt as a wall and a grasp stopped on a dipping fault pulls the stylus back
// onto it (toward where the grasp is, not along the drag). It is one spring, of
// stiffness k_w toward stopped + (k_g / k_w) (anchor - stopped), written into the
// snapshot so that compute_force and its passivity budget are unchanged. A non-finite
// `stopped` or a snapshot without a grasp is left as it is.
void hold_grasp_back(SceneSnapshot& scene, const Eigen::Vector3d& stopped,
  const ForceParams& params, const DeviceLimits& limits);

struct ForceInput
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); // m, device coordinates
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); // m/s
  bool device_ok = true;
  Clock::time_point now{};
};

struct ForceResult
{
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  ForceStatus status = ForceStatus::ok;
  bool in_contact = false;
  Eigen::Vector3d proxy = Eigen::Vector3d::Zero(); // the proxy after this tick
  // J: the energy the scene's own motion put into the contact spring this tick (carry_over
  // moving the proxy with a surface that moved, at this tick's stylus position; 0 when it
  // took energy out): work the passivity controller passes on to the hand only with
  // ForceParams::credit_scene_work.
  double scene_work = 0.0;
  // J: the energy the springs acting hold (each clamped at max force, times its fade): what
  // they give back to a stylus that lets go (what the passivity controller's energy bound
  // weighs against the energy the rendering absorbed).
  double stored_energy = 0.0;
};

// With x the stylus position, v its velocity, p the proxy after proxy.update(x) on the
// scene's patch (first proxy.carry_over() if the patch is a new one), n its first
// contact normal:
//
//   coupling (while grasping):  F_g = k_g (anchor - x) - b_g v
//   contact:                    F_c = k_c (p - x) - b_c (v.n) n      (p = x out of contact)
//
// Passivity (Colgate & Schenkel 1997: a spring K and a virtual damper B behind a
// zero-order hold of period T, on a device of physical damping b) needs
//
//   b > K T / 2 + |B|.
//
// b is not a figure a device reports; its nominal max stiffness K_max is (OpenHaptics'
// HD_NOMINAL_MAX_STIFFNESS, rated at its 1 kHz servo rate), and rating K_max stable with
// no virtual damping says b >= K_max T / 2. So the rendering keeps
//
//   K + 2 |B| / T <= K_max,        K = k_g + k_c,  B = b_g + b_c (those acting this tick),
//
// which gives K T / 2 + |B| <= K_max T / 2 <= b whatever b is: b_g, b_c are clamped to the
// device's max damping, then k_g and k_c each to the budget K_max - 2 |B| / T (at least
// 0) and scaled down together if their sum exceeds it. The total force is scaled down to
// max force (direction kept, norm computed without overflow): a projection onto a ball,
// so saturation never makes a step larger than the unsaturated force's.
//
// Faults give exactly zero (never NaN), with the reason in `status`, and reset the fades
// (the force fades back in): device error, any non-finite input, or a non-finite result
// (e.g. overflow from an absurd position). A device error and a non-finite result also
// reset the proxy (nothing is known of the side the stylus is on when rendering
// resumes); a non-finite input sample keeps it, so one glitched sample of a stylus
// pressed into a surface does not let it fall through. A scene never published gives
// zero and resets the proxy.
//
// A stale scene (older than max(stale_after, min(scene.valid_for, stale_after_max))) is
// not a fault for contact: status stale_scene, the coupling fades out, and the proxy is
// kept and goes on against the scene's last patch, its force held until the scene is
// stale_contact_max old, then faded out. When a fresh scene comes back the forces fade
// back in, and carry_over() takes the proxy onto the new patch (a surface that moved
// during the stall). A fading spring renders g times its force clamped to max force
// (g the fade), so a fade adds at most max_force servo_period / fade_time to a tick's
// force step. Without `fade` (a one-off evaluation) the fades are 1 or 0 at once.
ForceResult compute_force(const ForceInput& in, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits, ContactProxy& proxy,
  ForceFade* fade = nullptr);

// The force `scene` asks for at the stylus of `device` (a servo snapshot), the stylus at
// rest and the scene taken as fresh: compute_force at the scene's own stamp, without
// fades, with the servo's proxy as the snapshot left it (at the stylus when out of
// contact) moved once against the scene. What the servo renders while the graphics side
// keeps its scene fresh, whatever the frame rate and however long ago the servo last
// ticked (the servo itself fades the coupling out of a stale scene: its sent force at
// 1-2 frames/s is a matter of timing, this one is not). A device hand's figure in the
// Haptics dock.
ForceResult force_at_rest(const DeviceSnapshot& device, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits);

} // namespace geoshaping::haptics
