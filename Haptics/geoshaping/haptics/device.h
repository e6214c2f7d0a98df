#pragma once
// The haptic device interface (docs/design.md, Haptics contract), after CHAI3D's
// cGenericHapticDevice.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace geoshaping::haptics
{

// One coherent reading of the stylus, SI units in device coordinates: metres, a unit
// quaternion, a bitmask of buttons (bit 0 = first button). `t` is seconds since open().
struct DeviceSample
{
  double t = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  std::uint32_t buttons = 0;
};

// What the hardware can render stably. A backend fills these at open() from the device
// (converted to SI); the defaults are those of a desktop PHANToM-class device.
struct DeviceLimits
{
  double max_force = 3.3;        // N, peak
  double max_stiffness = 1000.0; // N/m: above this a virtual spring at 1 kHz may buzz
  double max_damping = 5.0;      // N s/m
  Eigen::Vector3d workspace_min = Eigen::Vector3d::Constant(-0.08); // m, device coordinates
  Eigen::Vector3d workspace_max = Eigen::Vector3d::Constant(0.08);  // m, device coordinates
  double workspace_radius = 0.08; // m, radius of the sphere the stylus reaches everywhere
};

// The device a hand holds. The servo thread is the only caller of read() and set_force()
// while a ServoLoop runs; open() and close() belong to the thread that owns the device.
//
// CHAI3D names, for orientation: open/close are the same, getPosition/getRotation/
// getUserSwitches are one read() (one coherent frame on real hardware), setForce is
// set_force, getSpecifications is limits().
class HapticDevice
{
public:
  virtual ~HapticDevice() = default;

  virtual std::string name() const = 0;
  // false with error() set when the device cannot be used.
  virtual bool open() = 0;
  virtual void close() = 0;
  bool is_open() const { return open_; }

  // The current sample; false (and has_error()) when the device cannot deliver one.
  virtual bool read(DeviceSample& sample) = 0;
  // Force on the stylus in newtons, device coordinates. Backends clamp to limits().max_force
  // again as a last guard and send zero for a non-finite force.
  virtual bool set_force(const Eigen::Vector3d& force) = 0;

  const DeviceLimits& limits() const { return limits_; }

  // The error state: sticky until clear_error() or a successful open(). The flag is
  // atomic so the graphics thread can watch it; the message takes a lock only when a
  // fault is raised or read, never on a healthy servo tick.
  bool has_error() const { return error_flag_.load(std::memory_order_acquire); }
  std::string error() const;
  void clear_error();

protected:
  void set_error(const std::string& message);
  // The force a backend actually sends: zero if non-finite, scaled down to max_force.
  Eigen::Vector3d safe_force(const Eigen::Vector3d& force) const;

  DeviceLimits limits_;
  bool open_ = false;

private:
  std::atomic<bool> error_flag_{ false };
  mutable std::mutex error_mutex_;
  std::string error_;
};

// Time stamps for devices without their own clock: seconds since restart() on the
// steady clock, or, with a positive `step`, n * step for the n-th call so that a replay
// or a scripted motion is bit-for-bit repeatable whatever the machine's load.
class DeviceClock
{
public:
  explicit DeviceClock(double step = 0.0)
    : step_(step)
  {
  }
  void restart();
  double next();
  double step() const { return step_; }

private:
  double step_;
  std::uint64_t calls_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

} // namespace geoshaping::haptics
