#pragma once
// The two values the graphics thread and the servo thread exchange (through
// TripleBuffer, never a lock).
#include "geoshaping/haptics/device.h"

#include <chrono>
#include <cstdint>
#include <vector>

namespace geoshaping::haptics
{

using Clock = std::chrono::steady_clock;

// Graphics -> servo: what the stylus should feel, already mapped into DEVICE coordinates
// (metres) by the graphics side, which owns the camera and the workspace -> scene
// mapping; the servo thread never converts coordinates and never calls the pipeline.
struct SceneSnapshot
{
  Clock::time_point stamp{}; // when the graphics thread made it; older than the
                             // staleness timeout => stale (compute_force): the coupling
                             // fades out, contact with this patch is held a while
  std::uint64_t sequence = 0;
  // How long the graphics side expects this snapshot to stay current (about its frame
  // period, with margin); the force model honours it up to ForceParams::stale_after_max.
  // Zero: the default staleness timeout.
  std::chrono::nanoseconds valid_for{ 0 };

  // Virtual coupling: while grasping, a spring pulls the stylus toward `grasp_anchor`,
  // the grasped vertex's position before the drag began, so the pull grows with the
  // deformation the user is making. `grasp_stiffness` (N/m) comes from the grasped
  // region's malleability (coupling_stiffness() in force_model.h).
  bool grasping = false;
  Eigen::Vector3d grasp_anchor = Eigen::Vector3d::Zero();
  double grasp_stiffness = 0.0;

  // Surfaces to touch, as a triangle soup: triangle i is vertices 3i, 3i+1, 3i+2, in any
  // winding (two-sided: the proxy stays on the side it is on). Send only the triangles
  // near the stylus: the servo thread tests every one each tick.
  std::vector<Eigen::Vector3d> contact_triangles;
};

// Why the last force was what it was.
enum class ForceStatus : std::uint8_t
{
  ok,           // force rendered from a fresh scene
  device_error, // the device reported an error: zero force
  stale_scene,  // no scene (zero force), or older than the timeout: the coupling fades
                // out, contact with the last patch held up to stale_contact_max
  non_finite    // an input (or the result) was NaN or infinite: zero force
};

const char* to_string(ForceStatus s);

// Servo -> graphics: the latest stylus state and the loop's health.
struct DeviceSnapshot
{
  Clock::time_point stamp{};
  DeviceSample sample;
  bool device_ok = false;
  Eigen::Vector3d force = Eigen::Vector3d::Zero(); // N, as sent
  ForceStatus status = ForceStatus::stale_scene;
  bool in_contact = false;
  Eigen::Vector3d proxy = Eigen::Vector3d::Zero(); // the contact proxy, device coordinates
  std::uint64_t ticks = 0;                         // servo ticks so far
  std::uint64_t zero_ticks = 0;     // ticks not rendered from a fresh scene (status not ok): a
                                    // fault's zero, or a stale scene's held contact and fades
  std::uint64_t scene_sequence = 0; // sequence of the scene snapshot used
};

} // namespace geoshaping::haptics
