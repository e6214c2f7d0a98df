#include "geoshaping/haptics/force_model.h"

#include "geoshaping/deform/transfer_function.h" // clean_malleability

#include <algorithm>
#include <cmath>

namespace geoshaping::haptics
{

const char* to_string(ForceStatus s)
{
  switch (s)
  {
    case ForceStatus::ok:
      return "ok";
    case ForceStatus::device_error:
      return "device error";
    case ForceStatus::stale_scene:
      return "stale scene";
    case ForceStatus::non_finite:
      return "non-finite input";
  }
  return "?";
}

double coupling_stiffness(
  double malleability, const ForceParams& params, const DeviceLimits& limits)
{
  const double m = clean_malleability(malleability);
  return limits.max_stiffness * (params.rigid_fraction * (1.0 - m) + params.soft_fraction * m);
}

void hold_grasp_back(SceneSnapshot& scene, const Eigen::Vector3d& stopped,
  const ForceParams& params, const DeviceLimits& limits)
{
  if (!scene.grasping || !stopped.allFinite() || !(scene.grasp_stiffness > 0.0))
    return;
  const double k_g = scene.grasp_stiffness;
  const double k_w = std::max(k_g, coupling_stiffness(0.0, params, limits));
  scene.grasp_anchor = stopped + (k_g / k_w) * (scene.grasp_anchor - stopped);
  scene.grasp_stiffness = k_w;
}

namespace
{

ForceResult zero(ForceStatus why)
{
  ForceResult r;
  r.status = why;
  return r;
}

// A spring's force f at fade g < 1: g times f clamped to max force, so a fade changes the
// force by at most f_max a tick times the fade's step, and scales the spring's stiffness
// and damping together (never above the passivity budget). g = 1: f as it is.
Eigen::Vector3d faded(const Eigen::Vector3d& f, double g, double f_max)
{
  if (g >= 1.0)
    return f;
  const double n = f.allFinite() ? f.stableNorm() : HUGE_VAL;
  return n > f_max ? Eigen::Vector3d(f * (g * f_max / n)) : Eigen::Vector3d(g * f);
}

// The energy of a spring of stiffness k stretched by d whose force is clamped to f_max:
// k d^2 / 2 up to d = f_max / k, then f_max d - f_max^2 / (2 k).
double spring_energy(double k, double d, double f_max)
{
  if (!(k > 0.0))
    return 0.0;
  return k * d <= f_max ? 0.5 * k * d * d : f_max * d - f_max * f_max / (2.0 * k);
}

} // namespace

ForceResult compute_force(const ForceInput& in, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits, ContactProxy& proxy, ForceFade* fade)
{
  // A fault renders zero at once; the force then fades back in. `forget` also drops the
  // proxy: the device's state is unknown (an error) or the proxy itself may be corrupt (a
  // non-finite result). A non-finite input sample keeps it: the proxy never saw that
  // sample, and it alone knows the side a pressed stylus came from.
  auto fault = [&](ForceStatus why, bool forget)
  {
    if (forget)
      proxy.reset();
    if (fade)
      *fade = ForceFade{ 0.0, 0.0 };
    return zero(why);
  };
  if (!in.device_ok)
    return fault(ForceStatus::device_error, true);
  if (scene.stamp == Clock::time_point())
  {
    // Never published (a loop just started): nothing to render, nothing to fade from.
    proxy.reset();
    return zero(ForceStatus::stale_scene);
  }
  if (!in.position.allFinite() || !in.velocity.allFinite() ||
      (scene.grasping &&
        (!scene.grasp_anchor.allFinite() || !std::isfinite(scene.grasp_stiffness))))
    return fault(ForceStatus::non_finite, false);

  // A stale scene stops the coupling (the graphics side no longer follows the drag) but
  // keeps the proxy and its contact with the last patch, the surface the frozen view
  // still shows, up to stale_contact_max; each fades out, and back in on resume.
  const auto stale_after =
    std::max(params.stale_after, std::min(scene.valid_for, params.stale_after_max));
  const auto age = in.now - scene.stamp;
  const bool stale = age > stale_after;
  const bool hold_contact = !stale || age <= params.stale_contact_max;
  ForceFade gain{ stale ? 0.0 : 1.0, hold_contact ? 1.0 : 0.0 };
  if (fade)
  {
    const double step = fade_step(params);
    auto toward = [step](double g, double target)
    { return std::clamp(target, g - step, g + step); };
    fade->coupling = gain.coupling = toward(std::clamp(fade->coupling, 0.0, 1.0), gain.coupling);
    fade->contact = gain.contact = toward(std::clamp(fade->contact, 0.0, 1.0), gain.contact);
  }

  const Eigen::Vector3d uncarried = proxy.position();
  const bool was_in_contact = proxy.in_contact();
  proxy.carry_over(
    scene.sequence, scene.contact_triangles, params.proxy_reach, params.proxy_clearance);
  const Eigen::Vector3d carried = proxy.position();
  proxy.update(in.position, scene.contact_triangles, params.proxy_clearance, params.proxy_reach);
  const bool contact = proxy.in_contact();
  const bool coupled = scene.grasping && gain.coupling > 0.0;
  const double b_max = std::max(0.0, limits.max_damping);
  const double b_g = coupled ? std::clamp(params.coupling_damping, 0.0, b_max) : 0.0;
  const double b_c = contact ? std::clamp(params.contact_damping, 0.0, b_max) : 0.0;
  // The stiffness the passivity rule leaves beside the damping; springs acting together
  // add up, so their sum is kept within it.
  const double budget =
    params.servo_period > 0.0
      ? std::max(0.0, limits.max_stiffness - 2.0 * (b_g + b_c) / params.servo_period)
      : 0.0;
  double k_g = coupled ? std::clamp(scene.grasp_stiffness, 0.0, budget) : 0.0;
  double k_c = contact ? std::clamp(params.contact_stiffness, 0.0, budget) : 0.0;
  if (k_g + k_c > budget)
  {
    const double s = budget / (k_g + k_c);
    k_g *= s;
    k_c *= s;
  }

  ForceResult r;
  const double f_max = std::max(0.0, limits.max_force);
  if (contact && was_in_contact && carried != uncarried)
  {
    // The spring's energy before and after the scene carried the proxy, at this stylus
    // position.
    r.scene_work =
      std::max(0.0, gain.contact * (spring_energy(k_c, (carried - in.position).norm(), f_max) -
                                     spring_energy(k_c, (uncarried - in.position).norm(), f_max)));
  }
  if (contact)
    r.stored_energy +=
      gain.contact * spring_energy(k_c, (proxy.position() - in.position).norm(), f_max);
  if (coupled)
    r.stored_energy +=
      gain.coupling * spring_energy(k_g, (scene.grasp_anchor - in.position).norm(), f_max);
  r.status = stale ? ForceStatus::stale_scene : ForceStatus::ok;
  r.in_contact = contact;
  r.proxy = proxy.position();
  if (coupled)
    r.force +=
      faded(k_g * (scene.grasp_anchor - in.position) - b_g * in.velocity, gain.coupling, f_max);
  if (contact)
  {
    const Eigen::Vector3d n = proxy.normal();
    r.force += faded(
      k_c * (proxy.position() - in.position) - b_c * in.velocity.dot(n) * n, gain.contact, f_max);
  }

  const double n = r.force.allFinite() ? r.force.stableNorm() : HUGE_VAL;
  if (!std::isfinite(n) || !proxy.position().allFinite())
    return fault(ForceStatus::non_finite, true);
  if (n > f_max)
    r.force *= f_max / n;
  return r;
}

ForceResult force_at_rest(const DeviceSnapshot& device, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits)
{
  ForceInput in;
  in.position = device.sample.position;
  in.device_ok = device.device_ok;
  in.now = scene.stamp;
  ContactProxy proxy;
  proxy.place(device.in_contact ? device.proxy : in.position);
  return compute_force(in, scene, params, limits, proxy);
}

} // namespace geoshaping::haptics
