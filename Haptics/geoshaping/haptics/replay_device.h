#pragma once
// Replays a recorded stylus trace (format: trace.h) as if a hand held the device.
#include "geoshaping/haptics/device.h"

#include <vector>

namespace geoshaping::haptics
{

// Reads the trace at open(); read() returns the trace sampled at the device clock
// (sample_trace_at), and the stylus rests at the last sample once the trace is over.
// Forces are accepted and dropped: nobody holds a replayed stylus.
class ReplayDevice : public HapticDevice
{
public:
  // `step` > 0: each read() advances the clock by `step` seconds (deterministic); 0:
  // real time since open().
  explicit ReplayDevice(std::string path, double step = 0.0);
  // A trace already in memory (sorted by t); open() fails if it is empty.
  explicit ReplayDevice(std::vector<DeviceSample> samples, double step = 0.0);

  std::string name() const override { return "replay"; }
  bool open() override;
  void close() override { open_ = false; }
  bool read(DeviceSample& sample) override;
  bool set_force(const Eigen::Vector3d&) override { return open_; }

  // True once the clock has passed the last sample.
  bool finished() const { return finished_.load(std::memory_order_relaxed); }
  double duration() const { return samples_.empty() ? 0.0 : samples_.back().t; }
  const std::vector<DeviceSample>& samples() const { return samples_; }

private:
  std::string path_;
  std::vector<DeviceSample> samples_;
  DeviceClock clock_;
  std::atomic<bool> finished_{ false };
};

} // namespace geoshaping::haptics
