#pragma once
// The device used when there is none: it sits at the origin and renders nothing.
#include "geoshaping/haptics/device.h"

namespace geoshaping::haptics
{

class NullDevice : public HapticDevice
{
public:
  // A non-empty `failure` makes open() fail with that message (make_device uses it for
  // an unknown kind, so the caller learns why at the usual place).
  explicit NullDevice(std::string failure = {})
    : failure_(std::move(failure))
  {
  }

  std::string name() const override { return "null"; }
  bool open() override;
  void close() override { open_ = false; }
  bool read(DeviceSample& sample) override;
  bool set_force(const Eigen::Vector3d&) override { return open_; }

private:
  std::string failure_;
  DeviceClock clock_;
};

} // namespace geoshaping::haptics
