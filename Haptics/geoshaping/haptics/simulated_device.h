#pragma once
// A scripted stylus (the dock's Simulated device, tests and benchmarks): deterministic
// motion; forces are accepted and dropped.
#include "geoshaping/haptics/device.h"

#include <functional>
#include <vector>

namespace geoshaping::haptics
{

class SimulatedDevice : public HapticDevice
{
public:
  using Motion = std::function<DeviceSample(double t)>;

  // The default motion: a 2 cm circle in the xy plane at 0.5 Hz, button 1 held from
  // t = 0.5 s on.
  SimulatedDevice();
  // Motion as a function of time (the sample's t is overwritten with the clock's).
  explicit SimulatedDevice(Motion motion);
  // Motion through keyframes, interpolated like a trace (sample_trace_at).
  explicit SimulatedDevice(std::vector<DeviceSample> keyframes);

  std::string name() const override { return "simulated"; }
  bool open() override;
  void close() override;
  bool read(DeviceSample& sample) override;
  bool set_force(const Eigen::Vector3d& force) override;

  // Time source: 0 = real time since open(); > 0 = `step` seconds per read() (replays
  // identically whatever the load). Takes effect at the next open().
  void set_time_step(double step) { step_ = step; }
  // Puts the device into its error state as a failing driver would; reads fail until
  // clear_error().
  void inject_error(const std::string& message) { set_error(message); }

private:
  Motion motion_;
  double step_ = 0.0;
  DeviceClock clock_;
};

} // namespace geoshaping::haptics
