#pragma once
// A 3D Systems / SensAble device through the OpenHaptics HD API, loaded at run time.
#include "geoshaping/haptics/device.h"
#include "geoshaping/haptics/triple_buffer.h"

#include <memory>
#include <string_view>

namespace geoshaping::haptics
{

// No SDK is needed to build: open() dlopen()s the HD library and resolves the few
// functions it uses. Where the library is absent open() fails with
// "OpenHaptics (libHD.so) not found: <loader message>".
//
// HD runs its own 1 kHz scheduler thread and only allows device frames inside its
// callbacks, so the backend schedules one asynchronous callback that, every HD tick,
// reads position (mm -> m), transform (rotation -> quaternion) and buttons into a
// triple buffer and applies the latest force from another triple buffer. read() and
// set_force() only touch those buffers: neither side ever waits for the other.
// Limits come from HD_NOMINAL_MAX_FORCE, HD_NOMINAL_MAX_STIFFNESS (N/mm -> N/m),
// HD_NOMINAL_MAX_DAMPING (N s/mm -> N s/m) and HD_USABLE_WORKSPACE_DIMENSIONS (mm -> m).
class OpenHapticsDevice : public HapticDevice
{
public:
  // `device_name`: an HD configuration name, empty for the default device. `library`:
  // the file dlopen() looks for (a path or a name searched on LD_LIBRARY_PATH).
  explicit OpenHapticsDevice(std::string device_name = {}, std::string library = "libHD.so");
  ~OpenHapticsDevice() override;

  std::string name() const override { return "openhaptics"; }
  bool open() override;
  void close() override;
  bool read(DeviceSample& sample) override;
  bool set_force(const Eigen::Vector3d& force) override;

  struct Api;  // the resolved HD functions
  struct Frame // what one HD tick saw
  {
    DeviceSample sample;
    bool ok = false;
    std::string_view error; // static text from HD when !ok
  };

private:
  static unsigned int tick(void* self); // the HD scheduler callback

  std::string device_name_;
  std::string library_;
  std::unique_ptr<Api> api_;
  DeviceClock clock_;
  TripleBuffer<Frame> frames_;           // HD thread -> servo thread
  TripleBuffer<Eigen::Vector3d> forces_; // servo thread -> HD thread
  Frame latest_;
};

} // namespace geoshaping::haptics
