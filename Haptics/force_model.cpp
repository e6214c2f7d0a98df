#include "geoshaping/haptics/force_model.h"

#include "geoshaping/transfer_function.h" // clean_malleability

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

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
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

  const double k_max = std::max(0.0, limits.max_stiffness);
  const double b_max = std::max(0.0, limits.max_damping);
  double k_g = scene.grasping ? std::clamp(scene.grasp_stiffness, 0.0, k_max) : 0.0;
  proxy.carry_over(
    scene.sequence, scene.contact_triangles, params.proxy_reach, params.proxy_clearance);
  proxy.update(in.position, scene.contact_triangles, params.proxy_clearance, params.proxy_reach);
  const bool contact = proxy.in_contact();
  double k_c = contact ? std::clamp(params.contact_stiffness, 0.0, k_max) : 0.0;
  // Springs acting together add up: keep their sum within the stable stiffness.
  if (k_g + k_c > k_max)
  {
    const double s = k_max / (k_g + k_c);
    k_g *= s;
    k_c *= s;
  }

  ForceResult r;
  r.in_contact = contact;
  r.proxy = proxy.position();
  if (scene.grasping)
    r.force += k_g * (scene.grasp_anchor - in.position) -
               std::clamp(params.coupling_damping, 0.0, b_max) * in.velocity;
  if (contact)
  {
    const Eigen::Vector3d n = proxy.normal();
    r.force += k_c * (proxy.position() - in.position) -
               std::clamp(params.contact_damping, 0.0, b_max) * in.velocity.dot(n) * n;
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
