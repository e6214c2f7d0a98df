#pragma once
// The force rendered each servo tick: virtual coupling to the grasped vertex plus
// penalty contact with the scene's triangles, clamped to what the device renders stably.
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
  double coupling_damping = 1.0; // N s/m, while grasping

  double contact_stiffness = 800.0; // N/m
  double contact_damping = 1.0;     // N s/m, along the normal, while in contact
  double contact_shell = 0.005;     // m: penetration depth below which contact acts

  // A scene snapshot older than this renders zero force, unless the snapshot says it
  // stays valid longer (SceneSnapshot::valid_for, a slow renderer), up to
  // stale_after_max: a frozen graphics thread still zeroes the force within that.
  std::chrono::nanoseconds stale_after = std::chrono::milliseconds(100);
  std::chrono::nanoseconds stale_after_max = std::chrono::milliseconds(500);
};

// Coupling stiffness for the malleability m in [0, 1] of the grasped region:
//   k(m) = k_max (rigid_fraction (1 - m) + soft_fraction m),
// m clamped to [0, 1]; NaN m is treated as rigid (as the deformer does).
double coupling_stiffness(
  double malleability, const ForceParams& params, const DeviceLimits& limits);

// Nearest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5:
// Voronoi regions of the vertices, then the edges, else the face).
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Penalty contact with a triangle soup (counter-clockwise seen from the free side): the
// triangle nearest to x decides (summing over all would push twice at a shared edge);
// with its unit normal n and nearest point q the depth is d = -(x - q).n, and contact
// holds when 0 < d <= shell. Degenerate and non-finite triangles are skipped.
struct Contact
{
  bool found = false;
  double depth = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};
Contact nearest_contact(
  const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& soup, double shell);

struct ForceInput
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); // m, device frame
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); // m/s
  bool device_ok = true;
  Clock::time_point now{};
};

struct ForceResult
{
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  ForceStatus status = ForceStatus::ok;
  bool in_contact = false;
};

// With x the stylus position, v its velocity:
//
//   coupling (while grasping):  F_g = k_g (anchor - x) - b_g v
//   contact (nearest triangle, normal n, nearest point q, depth d = -(x - q).n):
//                               F_c = (k_c d - b_c (v.n)) n   if 0 < d <= shell
//
// The shell keeps contact to a thin layer under the surface: a stylus that is deeper
// has come round the edge of a sheet or through it and is not pushed back through it.
//
// Stability: k_g and k_c are each clamped to the device's max stiffness, and scaled
// down together if their sum exceeds it; b_g, b_c to its max damping. The total force
// is scaled down to max force (direction kept, norm computed without overflow).
//
// Faults give exactly zero (never NaN), with the reason in `status`: device error,
// a scene older than max(stale_after, min(scene.valid_for, stale_after_max)) (or never
// published), any non-finite input, or a
// non-finite result (e.g. overflow from an absurd position).
ForceResult compute_force(const ForceInput& in, const SceneSnapshot& scene,
  const ForceParams& params, const DeviceLimits& limits);

} // namespace geoshaping::haptics
