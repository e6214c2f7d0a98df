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

bool SimulatedDevice::set_force(const Eigen::Vector3d&)
{
  if (!open_)
    return false;
  return !has_error();
}

} // namespace geoshaping::haptics
