#include "geoshaping/haptics/openhaptics_device.h"

#include <dlfcn.h>

namespace geoshaping::haptics
{

// The subset of the HD API (hdDefines.h / hd.h, OpenHaptics 3.x) this backend uses,
// declared here so no SDK header is needed. HD's types are 32-bit unsigned on Linux.
namespace hd
{
using HHD = unsigned int;
using HDenum = unsigned int;
using HDerror = unsigned int;
using HDSchedulerHandle = unsigned long;
using HDCallbackCode = unsigned int;
using HDSchedulerCallback = HDCallbackCode (*)(void*);
struct HDErrorInfo
{
  HDerror errorCode;
  int internalErrorCode;
  HHD hHD;
};

constexpr HHD invalid_handle = 0xFFFFFFFF;
constexpr HDerror success = 0x0000;
constexpr HDCallbackCode callback_continue = 1;
constexpr unsigned short default_priority = 0xFFFF / 2;
constexpr HDenum current_buttons = 0x2000;
constexpr HDenum current_position = 0x2050;      // 3 doubles, mm
constexpr HDenum current_transform = 0x2052;     // 16 doubles, column-major, mm
constexpr HDenum usable_workspace = 0x2551;      // 6 doubles: min xyz, max xyz, mm
constexpr HDenum nominal_max_stiffness = 0x2602; // N/mm
constexpr HDenum nominal_max_force = 0x2603;     // N
constexpr HDenum nominal_max_damping = 0x2609;   // N s/mm
constexpr HDenum current_force = 0x2700;         // 3 doubles, N
constexpr HDenum force_output = 0x4000;
} // namespace hd

struct OpenHapticsDevice::Api
{
  void* library = nullptr;
  hd::HHD handle = hd::invalid_handle;
  hd::HDSchedulerHandle callback = 0;
  bool scheduled = false;

  hd::HHD (*hdInitDevice)(const char*) = nullptr;
  void (*hdDisableDevice)(hd::HHD) = nullptr;
  void (*hdMakeCurrentDevice)(hd::HHD) = nullptr;
  hd::HDErrorInfo (*hdGetError)() = nullptr;
  const char* (*hdGetErrorString)(hd::HDerror) = nullptr;
  void (*hdBeginFrame)(hd::HHD) = nullptr;
  void (*hdEndFrame)(hd::HHD) = nullptr;
  void (*hdGetDoublev)(hd::HDenum, double*) = nullptr;
  void (*hdGetIntegerv)(hd::HDenum, int*) = nullptr;
  void (*hdSetDoublev)(hd::HDenum, const double*) = nullptr;
  void (*hdEnable)(hd::HDenum) = nullptr;
  void (*hdStartScheduler)() = nullptr;
  void (*hdStopScheduler)() = nullptr;
  hd::HDSchedulerHandle (*hdScheduleAsynchronous)(
    hd::HDSchedulerCallback, void*, unsigned short) = nullptr;
  void (*hdUnschedule)(hd::HDSchedulerHandle) = nullptr;

  // The last HD error as text, or empty if none.
  std::string last_error() const
  {
    const hd::HDErrorInfo e = hdGetError();
    if (e.errorCode == hd::success)
      return {};
    return hdGetErrorString ? hdGetErrorString(e.errorCode)
                            : "HD error " + std::to_string(e.errorCode);
  }
};

namespace
{
template<class F>
bool resolve(void* library, const char* name, F& f, std::string& missing)
{
  f = reinterpret_cast<F>(dlsym(library, name));
  if (!f)
    missing += std::string(missing.empty() ? "" : ", ") + name;
  return f != nullptr;
}
} // namespace

OpenHapticsDevice::OpenHapticsDevice(std::string device_name, std::string library)
  : device_name_(std::move(device_name))
  , library_(std::move(library))
{
}

OpenHapticsDevice::~OpenHapticsDevice()
{
  close();
}

bool OpenHapticsDevice::open()
{
  close();
  clear_error();
  auto api = std::make_unique<Api>();
  api->library = dlopen(library_.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!api->library)
  {
    const char* why = dlerror();
    set_error("OpenHaptics (libHD.so) not found: " + std::string(why ? why : library_) +
              " (install the OpenHaptics runtime or choose another device)");
    return false;
  }
  std::string missing;
  Api& a = *api;
  resolve(a.library, "hdInitDevice", a.hdInitDevice, missing);
  resolve(a.library, "hdDisableDevice", a.hdDisableDevice, missing);
  resolve(a.library, "hdMakeCurrentDevice", a.hdMakeCurrentDevice, missing);
  resolve(a.library, "hdGetError", a.hdGetError, missing);
  resolve(a.library, "hdGetErrorString", a.hdGetErrorString, missing);
  resolve(a.library, "hdBeginFrame", a.hdBeginFrame, missing);
  resolve(a.library, "hdEndFrame", a.hdEndFrame, missing);
  resolve(a.library, "hdGetDoublev", a.hdGetDoublev, missing);
  resolve(a.library, "hdGetIntegerv", a.hdGetIntegerv, missing);
  resolve(a.library, "hdSetDoublev", a.hdSetDoublev, missing);
  resolve(a.library, "hdEnable", a.hdEnable, missing);
  resolve(a.library, "hdStartScheduler", a.hdStartScheduler, missing);
  resolve(a.library, "hdStopScheduler", a.hdStopScheduler, missing);
  resolve(a.library, "hdScheduleAsynchronous", a.hdScheduleAsynchronous, missing);
  resolve(a.library, "hdUnschedule", a.hdUnschedule, missing);
  if (!missing.empty())
  {
    dlclose(a.library);
    set_error("OpenHaptics (libHD.so) is incomplete: missing " + missing);
    return false;
  }
  api_ = std::move(api);

  a.handle = a.hdInitDevice(device_name_.empty() ? nullptr : device_name_.c_str());
  if (a.handle == hd::invalid_handle)
  {
    const std::string why = a.last_error();
    close();
    set_error("OpenHaptics: cannot initialise device '" +
              (device_name_.empty() ? std::string("default") : device_name_) + "': " + why);
    return false;
  }
  a.hdMakeCurrentDevice(a.handle);
  double force = 0.0, stiffness = 0.0, damping = 0.0, workspace[6] = {};
  a.hdGetDoublev(hd::nominal_max_force, &force);
  a.hdGetDoublev(hd::nominal_max_stiffness, &stiffness);
  a.hdGetDoublev(hd::nominal_max_damping, &damping);
  a.hdGetDoublev(hd::usable_workspace, workspace);
  if (force > 0.0)
    limits_.max_force = force;
  if (stiffness > 0.0)
    limits_.max_stiffness = stiffness * 1000.0;
  if (damping > 0.0)
    limits_.max_damping = damping * 1000.0;
  const Eigen::Vector3d lo(workspace[0], workspace[1], workspace[2]);
  const Eigen::Vector3d hi(workspace[3], workspace[4], workspace[5]);
  if ((hi - lo).minCoeff() > 0.0)
  {
    limits_.workspace_min = lo / 1000.0;
    limits_.workspace_max = hi / 1000.0;
    limits_.workspace_radius = 0.5 * (hi - lo).minCoeff() / 1000.0;
  }
  a.hdEnable(hd::force_output);
  // No HD thread runs yet: drop what a previous session left in the buffers.
  frames_.update();
  forces_.write(Eigen::Vector3d::Zero());
  latest_ = Frame();
  clock_.restart();
  a.callback = a.hdScheduleAsynchronous(&OpenHapticsDevice::tick, this, hd::default_priority);
  a.scheduled = true;
  a.hdStartScheduler();
  const std::string why = a.last_error();
  if (!why.empty())
  {
    close();
    set_error("OpenHaptics: cannot start the servo scheduler: " + why);
    return false;
  }
  open_ = true;
  return true;
}

void OpenHapticsDevice::close()
{
  open_ = false;
  if (!api_)
    return;
  Api& a = *api_;
  if (a.handle != hd::invalid_handle)
  {
    a.hdStopScheduler();
    if (a.scheduled)
      a.hdUnschedule(a.callback);
    a.hdDisableDevice(a.handle);
  }
  dlclose(a.library);
  api_.reset();
}

unsigned int OpenHapticsDevice::tick(void* self)
{
  auto& d = *static_cast<OpenHapticsDevice*>(self);
  Api& a = *d.api_;
  d.forces_.update();
  const Eigen::Vector3d f = d.safe_force(d.forces_.front());
  double position[3], transform[16];
  int buttons = 0;
  a.hdBeginFrame(a.handle);
  a.hdGetDoublev(hd::current_position, position);
  a.hdGetDoublev(hd::current_transform, transform);
  a.hdGetIntegerv(hd::current_buttons, &buttons);
  a.hdSetDoublev(hd::current_force, f.data());
  a.hdEndFrame(a.handle);

  Frame& out = d.frames_.back();
  const hd::HDErrorInfo e = a.hdGetError();
  out.ok = e.errorCode == hd::success;
  out.error = out.ok ? std::string_view() : std::string_view(a.hdGetErrorString(e.errorCode));
  out.sample.position = Eigen::Vector3d(position[0], position[1], position[2]) / 1000.0;
  const Eigen::Map<const Eigen::Matrix4d> m(transform); // column-major, like OpenGL
  out.sample.orientation = Eigen::Quaterniond(m.topLeftCorner<3, 3>()).normalized();
  out.sample.buttons = std::uint32_t(buttons);
  d.frames_.publish();
  return hd::callback_continue;
}

bool OpenHapticsDevice::read(DeviceSample& sample)
{
  if (!open_)
    return false;
  if (frames_.update())
    latest_ = frames_.front();
  if (!latest_.ok && !latest_.error.empty())
  {
    set_error("OpenHaptics: " + std::string(latest_.error));
    return false;
  }
  sample = latest_.sample;
  sample.t = clock_.next();
  return !has_error();
}

bool OpenHapticsDevice::set_force(const Eigen::Vector3d& force)
{
  if (!open_)
    return false;
  forces_.write(has_error() ? Eigen::Vector3d::Zero() : safe_force(force));
  return !has_error();
}

} // namespace geoshaping::haptics
