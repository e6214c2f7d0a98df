#pragma once
// @brief A simulated hand on a simulated device, rendered by the project's own servo tick
// (ServoTick: velocity filter, proxy, compute_force), with no thread and no clock: the
// physics behind geoshaping_hand_sim and the haptics tests. docs/haptics.md, "Hand
// simulator", gives the formats and the device model.
#include "geoshaping/haptics/servo_tick.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace geoshaping::haptics
{

// The hand's force on the stylus (N, device coordinates) at time t (s), linear in between.
struct HandKey
{
  double t = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

// Reads HAND.csv: a header line `t,fx,fy,fz`, then rows of 4 finite numbers with t
// strictly increasing from t >= 0; blank lines are skipped. False with `error` naming the
// line otherwise (a wrong header, a missing or extra field, text, NaN, no row).
bool read_hand_csv(std::istream& in, std::vector<HandKey>& keys, std::string& error);

// Linear interpolation of the keys at t, held constant before the first and after the last.
Eigen::Vector3d hand_force_at(const std::vector<HandKey>& keys, double t);

// The device: a point mass behind the stylus tip with viscous damping and Coulomb
// friction, positions read quantised to `resolution` per axis, the force held over each
// servo period (zero-order hold), the tip kept in the workspace box (a hard stop).
struct DeviceModel
{
  double mass = 0.045; // kg, apparent mass at the tip
  // N s/m, viscous: a model value, above the K_max T / 2 = 0.5 its stiffness rating
  // implies (the passivity rule of force_model.h), not a measured one.
  double damping = 0.6;
  double friction = 0.05;    // N, Coulomb
  double resolution = 55e-6; // m, position quantum
  double period = 0.001;     // s, servo period
  DeviceLimits limits;       // 3.3 N peak, 1000 N/m, 5 N s/m, +-8 cm

  // The Touch-like default above; false for an unknown name.
  static bool named(const std::string& name, DeviceModel& model);
};

// One servo tick of a run: the stylus position (true, not quantised), the force the
// rendering sent, the proxy, whether in contact.
struct TrajectoryRow
{
  double t = 0.0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d proxy = Eigen::Vector3d::Zero();
  bool contact = false;
};

struct HandSimOptions
{
  ForceParams force;
  double velocity_filter_s = 0.005;
  // The graphics side: every `patch_period` s the `max_triangles` triangles of the scene
  // nearest to the stylus are published as a new patch (a new sequence), as the ParaView
  // interactor does each frame.
  double patch_period = 0.016;
  std::size_t max_triangles = 256;
  // The graphics side stalls: no patch is published in [stall_from, stall_until) s (the
  // servo keeps the last one, which goes stale); the first patch after is the scene then.
  double stall_from = -1.0;
  double stall_until = -1.0;
  int substeps = 10; // integration steps of the device per servo period
  // A grasp held for the whole run: the coupling spring toward `grasp_anchor`.
  bool grasping = false;
  Eigen::Vector3d grasp_anchor = Eigen::Vector3d::Zero();
  double grasp_stiffness = 0.0;
};

// The scene at time t (device coordinates, metres): a triangle soup, filled into `soup`.
using SceneAt = std::function<void(double t, std::vector<Eigen::Vector3d>& soup)>;

// Runs until the last key's t: one row per servo tick, t = k T. Per tick: read the
// quantised position, ServoTick, then integrate the device over T with that force held
// (semi-implicit Euler, `substeps` steps):
//   m dv = (F_hand(t) + F_render - b v) dt,  then friction removes up to F_c dt of
//   momentum (sticking when that stops it),  dx = v dt.
// `injected` (if not null) gets the energy the rendering put into the stylus beyond what
// the device's own damping took back while the spring acted:
//
//   E = sum F_render . dx + U(end) - U(start) - b sum_(ticks in contact) |v|^2 dt,
//
// with U the energy stored in the contact spring at stretch d = |p - x| (saturated:
// k d^2 / 2 up to d = F_max / k, then F_max d - F_max^2 / (2 k)) plus, while grasping,
// k_g |anchor - x|^2 / 2; "in contact" counts the grasp's ticks too. An ideal continuous
// spring gives sum F . dx = -dU; the zero-order hold gives more (about K T / 2 per unit
// of v^2 dt), which a passive display (b > K T / 2) dissipates: E <= 0.
// `rendered_work` (if not null) gets the first term alone, the work of the rendered force
// on the stylus over the run (true positions), sum F_render . dx: what the passivity
// controller (passivity.h) keeps from being positive on its own, without the device's
// damping.
std::vector<TrajectoryRow> simulate_hand(const SceneAt& scene, const std::vector<HandKey>& hand,
  const Eigen::Vector3d& start, const DeviceModel& model, const HandSimOptions& options,
  double* injected = nullptr, double* rendered_work = nullptr);

// TRAJECTORY.csv: a header `t,x,y,z,fx,fy,fz,px,py,pz,contact`, one row per tick, 17
// significant digits, contact 0/1.
void write_trajectory_csv(std::ostream& out, const std::vector<TrajectoryRow>& rows);

// What a run measured, for tests and the docs table.
struct RunFigures
{
  double max_force_step = 0.0; // N, largest |F_k - F_(k-1)|
  // N, largest |F_k - F_(k-1)| - k_c |x_k - x_(k-1)|, x quantised as the servo saw it:
  // how far a force step exceeds what the stiffness times one tick of motion gives.
  double max_step_excess = 0.0;
  double max_proxy_distance = 0.0; // m, largest |proxy - stylus| while in contact
};
RunFigures run_figures(
  const std::vector<TrajectoryRow>& rows, const DeviceModel& model, const HandSimOptions& options);

} // namespace geoshaping::haptics
