#include "geoshaping/haptics/device.h"
#include "geoshaping/haptics/null_device.h"

namespace geoshaping::haptics
{

std::string HapticDevice::error() const
{
  std::lock_guard<std::mutex> lock(error_mutex_);
  return error_;
}

void HapticDevice::clear_error()
{
  std::lock_guard<std::mutex> lock(error_mutex_);
  error_.clear();
  error_flag_.store(false, std::memory_order_release);
}

void HapticDevice::set_error(const std::string& message)
{
  std::lock_guard<std::mutex> lock(error_mutex_);
  error_ = message;
  error_flag_.store(true, std::memory_order_release);
}

Eigen::Vector3d HapticDevice::safe_force(const Eigen::Vector3d& force) const
{
  if (!force.allFinite())
    return Eigen::Vector3d::Zero();
  const double n = force.stableNorm();
  return n > limits_.max_force ? Eigen::Vector3d(force * (limits_.max_force / n)) : force;
}

void DeviceClock::restart()
{
  calls_ = 0;
  start_ = std::chrono::steady_clock::now();
}

double DeviceClock::next()
{
  if (step_ > 0.0)
    return double(calls_++) * step_;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool NullDevice::open()
{
  if (!failure_.empty())
  {
    set_error(failure_);
    return false;
  }
  clear_error();
  clock_.restart();
  open_ = true;
  return true;
}

bool NullDevice::read(DeviceSample& sample)
{
  sample = DeviceSample();
  sample.t = clock_.next();
  return open_;
}

} // namespace geoshaping::haptics
