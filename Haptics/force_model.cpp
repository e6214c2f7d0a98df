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

} // namespace

ForceResult compute_force(const ForceInput& in, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits, ContactProxy& proxy)
{
  if (!in.device_ok)
  {
    proxy.reset();
    return zero(ForceStatus::device_error);
  }
  const auto stale_after =
    std::max(params.stale_after, std::min(scene.valid_for, params.stale_after_max));
  if (scene.stamp == Clock::time_point() || in.now - scene.stamp > stale_after)
  {
    proxy.reset();
    return zero(ForceStatus::stale_scene);
  }
  if (!in.position.allFinite() || !in.velocity.allFinite() ||
      (scene.grasping &&
        (!scene.grasp_anchor.allFinite() || !std::isfinite(scene.grasp_stiffness))))
  {
    proxy.reset();
    return zero(ForceStatus::non_finite);
  }

  proxy.carry_over(
    scene.sequence, scene.contact_triangles, params.proxy_reach, params.proxy_clearance);
  proxy.update(in.position, scene.contact_triangles, params.proxy_clearance, params.proxy_reach);
  const bool contact = proxy.in_contact();
  const double b_max = std::max(0.0, limits.max_damping);
  const double b_g = scene.grasping ? std::clamp(params.coupling_damping, 0.0, b_max) : 0.0;
  const double b_c = contact ? std::clamp(params.contact_damping, 0.0, b_max) : 0.0;
  // The stiffness the passivity rule leaves beside the damping; springs acting together
  // add up, so their sum is kept within it.
  const double budget =
    params.servo_period > 0.0
      ? std::max(0.0, limits.max_stiffness - 2.0 * (b_g + b_c) / params.servo_period)
      : 0.0;
  double k_g = scene.grasping ? std::clamp(scene.grasp_stiffness, 0.0, budget) : 0.0;
  double k_c = contact ? std::clamp(params.contact_stiffness, 0.0, budget) : 0.0;
  if (k_g + k_c > budget)
  {
    const double s = budget / (k_g + k_c);
    k_g *= s;
    k_c *= s;
  }

  ForceResult r;
  r.in_contact = contact;
  r.proxy = proxy.position();
  if (scene.grasping)
    r.force += k_g * (scene.grasp_anchor - in.position) - b_g * in.velocity;
  if (contact)
  {
    const Eigen::Vector3d n = proxy.normal();
    r.force += k_c * (proxy.position() - in.position) - b_c * in.velocity.dot(n) * n;
  }

  const double f_max = std::max(0.0, limits.max_force);
  const double n = r.force.allFinite() ? r.force.stableNorm() : HUGE_VAL;
  if (!std::isfinite(n) || !proxy.position().allFinite())
  {
    proxy.reset();
    return zero(ForceStatus::non_finite);
  }
  if (n > f_max)
    r.force *= f_max / n;
  return r;
}

} // namespace geoshaping::haptics
