#pragma once
// The haptics tests' device: a SimulatedDevice that records what the servo loop sent
// (test support; the product's SimulatedDevice only drops forces the way a device does).
#include "geoshaping/haptics/simulated_device.h"

#include <atomic>
#include <cmath>
#include <cstdint>

namespace geoshaping::haptics
{

class RecordingDevice : public SimulatedDevice
{
public:
  using SimulatedDevice::SimulatedDevice;

  bool set_force(const Eigen::Vector3d& force) override
  {
    const bool ok = SimulatedDevice::set_force(force);
    if (!open_)
    {
      return ok;
    }
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
    return ok;
  }
  bool open() override
  {
    for (auto& f : last_force_)
      f.store(0.0);
    max_force_sent_.store(0.0);
    forces_sent_.store(0);
    nonzero_after_error_.store(0);
    return SimulatedDevice::open();
  }

  // What the servo loop sent, read from any thread after it stopped (or racily while it
  // runs: these are atomics, the vector is not torn, the components may mix two ticks).
  Eigen::Vector3d last_force() const
  {
    return Eigen::Vector3d(last_force_[0].load(), last_force_[1].load(), last_force_[2].load());
  }
  double max_force_sent() const { return max_force_sent_.load(); }
  std::uint64_t forces_sent() const { return forces_sent_.load(); }
  std::uint64_t nonzero_forces_after_error() const { return nonzero_after_error_.load(); }

private:
  std::atomic<double> last_force_[3] = { 0.0, 0.0, 0.0 };
  std::atomic<double> max_force_sent_{ 0.0 };
  std::atomic<std::uint64_t> forces_sent_{ 0 };
  std::atomic<std::uint64_t> nonzero_after_error_{ 0 };
};

} // namespace geoshaping::haptics
