#pragma once
// A 3D Systems / SensAble device through the OpenHaptics HD API, loaded at run time.
#include "geoshaping/haptics/device.h"
#include "geoshaping/haptics/triple_buffer.h"

#include <memory>
#include <string>

namespace geoshaping::haptics
{

// @brief The HD library the OpenHaptics backend loads: the environment variable
// GEOSHAPING_LIBHD when set and not empty (a path, or a name dlopen() searches on
// LD_LIBRARY_PATH), otherwise "libHD.so". One rule for every caller: the backend opens
// this file and the GUI offers OpenHaptics only where openhaptics_loads() is true.
std::string openhaptics_library();
// @brief Whether openhaptics_library() loads (it is dlopen()ed and closed again); when
// not, `why` (if given) receives the loader's message.
bool openhaptics_loads(std::string* why = nullptr);

// @brief HapticDevice over HD. No SDK is needed to build: open() dlopen()s the library
// (openhaptics_library() unless the constructor names one) and resolves the few
// functions it uses; where it is absent open() fails with
// "OpenHaptics (libHD.so) not found: <loader message>".
//
// HD runs its own scheduler thread and only allows HD frames (hdBeginFrame ... hdEndFrame) inside
// its callbacks, so open() asks for a 1000 Hz scheduler and schedules one asynchronous callback
// that, every HD tick, reads position (mm -> m), transform (column-major; rotation -> quaternion)
// and buttons into a triple buffer and applies the latest force from another triple buffer. read()
// and set_force() only touch those buffers: neither side ever waits for the other. A sample's time
// is its tick count / 1000 s (the HD thread's own DeviceClock), so reading the same tick twice
// gives the same time.
//
// Limits come from HD_NOMINAL_MAX_FORCE (N), HD_NOMINAL_MAX_STIFFNESS (N/mm -> N/m),
// HD_NOMINAL_MAX_DAMPING (N s/mm -> N s/m) and HD_USABLE_WORKSPACE_DIMENSIONS (mm -> m);
// one the driver does not report keeps its DeviceLimits default.
//
// Faults: any HD error seen in a tick (HD_DEVICE_FAULT from a failing device, a force
// or frame error) is latched by the HD thread: from the next tick on it sends zero force
// whatever set_force() asks, and every later frame carries the error, so the servo side
// cannot miss it between two reads. read() then fails with has_error() and
//   "OpenHaptics: HD_DEVICE_FAULT (0x0300, <HD's text>) in the servo tick; force output
//    stopped. Check the device, then start haptics again"
// until close(); a new open() starts clean. open() fails if the scheduler runs no tick
// within 2 s, rather than serving no sample.
class OpenHapticsDevice : public HapticDevice
{
public:
  // `device_name`: an HD configuration name, empty for the default device. `library`:
  // the file dlopen() looks for; empty for openhaptics_library().
  explicit OpenHapticsDevice(std::string device_name = {}, std::string library = {});
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
    unsigned int error = 0;           // the latched HD error code, 0 when healthy
    const char* error_text = nullptr; // HD's static text for it
  };

private:
  static unsigned int tick(void* self); // the HD scheduler callback

  std::string device_name_;
  std::string library_;
  std::unique_ptr<Api> api_;
  // The HD thread's: its clock, its last good sample (a failed tick keeps it) and the
  // latched error.
  DeviceClock clock_;
  DeviceSample hd_sample_;
  unsigned int hd_error_ = 0;
  const char* hd_error_text_ = nullptr;
  TripleBuffer<Frame> frames_;           // HD thread -> servo thread
  TripleBuffer<Eigen::Vector3d> forces_; // servo thread -> HD thread
  Frame latest_;
};

} // namespace geoshaping::haptics
