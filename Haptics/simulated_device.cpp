#include "geoshaping/haptics/simulated_device.h"

#include "geoshaping/haptics/trace.h"

#include <cmath>

namespace geoshaping::haptics
{

namespace
{
DeviceSample circle(double t)
{
  constexpr double pi = 3.14159265358979323846;
  constexpr double radius = 0.02; // m
  constexpr double hz = 0.5;
  DeviceSample s;
  s.t = t;
  s.position =
    Eigen::Vector3d(radius * std::cos(2 * pi * hz * t), radius * std::sin(2 * pi * hz * t), 0.0);
  s.buttons = t >= 0.5 ? 1u : 0u;
  return s;
}
} // namespace

SimulatedDevice::SimulatedDevice()
  : motion_(circle)
{
}

SimulatedDevice::SimulatedDevice(Motion motion)
  : motion_(std::move(motion))
{
}

SimulatedDevice::SimulatedDevice(std::vector<DeviceSample> keyframes)
{
  if (keyframes.empty())
    keyframes.emplace_back();
  motion_ = [keys = std::move(keyframes)](double t) { return sample_trace_at(keys, t); };
}

bool SimulatedDevice::open()
{
  clear_error();
  clock_ = DeviceClock(step_);
  for (auto& f : last_force_)
    f.store(0.0);
  max_force_sent_.store(0.0);
  forces_sent_.store(0);
  nonzero_after_error_.store(0);
  open_ = true;
  return true;
}

void SimulatedDevice::close()
{
  open_ = false;
}

bool SimulatedDevice::read(DeviceSample& sample)
{
  if (!open_ || has_error())
    return false;
  const double t = clock_.next();
  sample = motion_(t);
  sample.t = t;
  return true;
}

bool SimulatedDevice::set_force(const Eigen::Vector3d& force)
{
  if (!open_)
    return false;
  const Eigen::Vector3d f = safe_force(force);
  for (int i = 0; i < 3; ++i)
    last_force_[i].store(f[i], std::memory_order_relaxed);
  // The raw request, not the clamped one: tests check the servo loop's own clamp.
  const double n = force.allFinite() ? force.stableNorm() : HUGE_VAL;
  if (n > max_force_sent_.load(std::memory_order_relaxed))
    max_force_sent_.store(n, std::memory_order_relaxed);
  forces_sent_.fetch_add(1, std::memory_order_relaxed);
  if (has_error() && n != 0.0)
    nonzero_after_error_.fetch_add(1, std::memory_order_relaxed);
  return !has_error();
}

Eigen::Vector3d SimulatedDevice::last_force() const
{
  return Eigen::Vector3d(last_force_[0].load(), last_force_[1].load(), last_force_[2].load());
}

} // namespace geoshaping::haptics
