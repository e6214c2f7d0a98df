#include "geoshaping/haptics/openhaptics_device.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <thread>

// HD's error record, at global scope under HD's own name (hdDefines.h declares it so): a
// pointer to libHD's hdGetError then has the very function type libHD defines. Under any
// other name (geoshaping::haptics::hd::HDErrorInfo) the call through the dlsym'd pointer
// is a call through an incompatible function type, which UBSan's -fsanitize=function
// reports against the tests' fake libHD.
struct HDErrorInfo
{
  unsigned int errorCode; // HDerror
  int internalErrorCode;
  unsigned int hHD; // HHD
};

namespace geoshaping::haptics
{

// The subset of the HD API (OpenHaptics 3.x: HD/hdDefines.h, HD/hdScheduler.h,
// HD/hdDevice.h) this backend uses, declared here so no SDK header is needed. HD's
// types are 32-bit unsigned on Linux; HDSchedulerHandle is an unsigned long.
namespace hd
{
using HHD = unsigned int;
using HDenum = unsigned int;
using HDerror = unsigned int;
using HDSchedulerHandle = unsigned long;
using HDCallbackCode = unsigned int;
using HDSchedulerCallback = HDCallbackCode (*)(void*);
using HDErrorInfo = ::HDErrorInfo;

constexpr HHD invalid_handle = 0xFFFFFFFF;
constexpr HDerror success = 0x0000;
constexpr HDCallbackCode callback_continue = 1;
constexpr unsigned short default_priority = 0xFFFF / 2;
constexpr unsigned long scheduler_rate = 1000; // Hz: the servo rate the backend asks for
constexpr HDenum current_buttons = 0x2000;
constexpr HDenum current_position = 0x2050;      // 3 doubles, mm
constexpr HDenum current_transform = 0x2052;     // 16 doubles, column-major, mm
constexpr HDenum usable_workspace = 0x2551;      // 6 doubles: min xyz, max xyz, mm
constexpr HDenum nominal_max_stiffness = 0x2602; // N/mm
constexpr HDenum nominal_max_force = 0x2603;     // N
constexpr HDenum nominal_max_damping = 0x2609;   // N s/mm
constexpr HDenum current_force = 0x2700;         // 3 doubles, N
constexpr HDenum force_output = 0x4000;

// The error codes of hdDefines.h by name, for messages a user can look up.
const char* error_name(HDerror code)
{
  struct Name
  {
    HDerror code;
    const char* name;
  };
  static constexpr Name names[] = { { 0x0100, "HD_INVALID_ENUM" }, { 0x0101, "HD_INVALID_VALUE" },
    { 0x0102, "HD_INVALID_OPERATION" }, { 0x0103, "HD_INVALID_INPUT_TYPE" },
    { 0x0104, "HD_BAD_HANDLE" }, { 0x0200, "HD_WARM_MOTORS" }, { 0x0201, "HD_EXCEEDED_MAX_FORCE" },
    { 0x0202, "HD_EXCEEDED_MAX_FORCE_IMPULSE" }, { 0x0203, "HD_EXCEEDED_MAX_VELOCITY" },
    { 0x0204, "HD_FORCE_ERROR" }, { 0x0300, "HD_DEVICE_FAULT" },
    { 0x0301, "HD_DEVICE_ALREADY_INITIATED" }, { 0x0302, "HD_COMM_ERROR" },
    { 0x0303, "HD_COMM_CONFIG_ERROR" }, { 0x0304, "HD_TIMER_ERROR" },
    { 0x0400, "HD_ILLEGAL_BEGIN" }, { 0x0401, "HD_ILLEGAL_END" }, { 0x0402, "HD_FRAME_ERROR" },
    { 0x0500, "HD_INVALID_PRIORITY" }, { 0x0501, "HD_SCHEDULER_FULL" },
    { 0x0600, "HD_INVALID_LICENSE" } };
  for (const Name& n : names)
    if (n.code == code)
      return n.name;
  return "HD error";
}

// "HD_NAME (0xCODE, HD's text)", or empty for no error.
std::string describe(HDerror code, const char* text)
{
  if (code == success)
    return {};
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", code);
  return std::string(error_name(code)) + " (" + hex + ", " + (text ? text : "no text") + ")";
}
} // namespace hd

struct OpenHapticsDevice::Api
{
  void* library = nullptr;
  hd::HHD handle = hd::invalid_handle;
  hd::HDSchedulerHandle callback = 0;
  bool scheduled = false;
  bool started = false;

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
  void (*hdSetSchedulerRate)(unsigned long) = nullptr;
  void (*hdStartScheduler)() = nullptr;
  void (*hdStopScheduler)() = nullptr;
  hd::HDSchedulerHandle (*hdScheduleAsynchronous)(
    hd::HDSchedulerCallback, void*, unsigned short) = nullptr;
  void (*hdUnschedule)(hd::HDSchedulerHandle) = nullptr;

  // HD keeps errors on a stack that hdGetError() pops. Empties it (one failing call can
  // leave several entries; a bounded loop in case a driver never reports success) and
  // returns the oldest error popped, the cause, or 0.
  hd::HDerror take_error() const
  {
    hd::HDerror oldest = hd::success;
    for (int i = 0; i < 64; ++i)
    {
      const hd::HDErrorInfo e = hdGetError();
      if (e.errorCode == hd::success)
        break;
      oldest = e.errorCode;
    }
    return oldest;
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

// Reads one nominal limit: `value` times `scale` into `out` when HD reports a positive
// value; a parameter the driver rejects leaves `out` (its default) and its error is
// taken off HD's stack so that it is not blamed on a later call.
void nominal(const OpenHapticsDevice::Api& a, hd::HDenum parameter, double scale, double& out)
{
  double value = 0.0;
  a.hdGetDoublev(parameter, &value);
  if (a.take_error() == hd::success && value > 0.0)
    out = value * scale;
}
} // namespace

std::string openhaptics_library()
{
  const char* configured = std::getenv("GEOSHAPING_LIBHD");
  return configured && *configured ? configured : "libHD.so";
}

bool openhaptics_loads(std::string* why)
{
  void* library = dlopen(openhaptics_library().c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!library && why)
  {
    const char* message = dlerror();
    *why = message ? message : openhaptics_library();
  }
  if (library)
    dlclose(library);
  return library != nullptr;
}

OpenHapticsDevice::OpenHapticsDevice(std::string device_name, std::string library)
  : device_name_(std::move(device_name))
  , library_(library.empty() ? openhaptics_library() : std::move(library))
  , clock_(1.0 / double(hd::scheduler_rate))
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
              " (install the OpenHaptics runtime, set GEOSHAPING_LIBHD to its libHD.so, or "
              "choose another device)");
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
  resolve(a.library, "hdSetSchedulerRate", a.hdSetSchedulerRate, missing);
  resolve(a.library, "hdStartScheduler", a.hdStartScheduler, missing);
  resolve(a.library, "hdStopScheduler", a.hdStopScheduler, missing);
  resolve(a.library, "hdScheduleAsynchronous", a.hdScheduleAsynchronous, missing);
  resolve(a.library, "hdUnschedule", a.hdUnschedule, missing);
  if (!missing.empty())
  {
    dlclose(a.library);
    set_error("OpenHaptics (" + library_ + ") is incomplete: missing " + missing);
    return false;
  }
  api_ = std::move(api);
  a.take_error(); // nothing of an earlier session is this session's fault
  // Ends a failed open(): releases what was acquired, says what failed and HD's reason.
  auto fail = [this, &a](const std::string& what, hd::HDerror error)
  {
    const std::string why = hd::describe(error, a.hdGetErrorString(error));
    close();
    set_error("OpenHaptics: " + what + (why.empty() ? "" : ": " + why));
    return false;
  };

  a.handle = a.hdInitDevice(device_name_.empty() ? nullptr : device_name_.c_str());
  hd::HDerror error = a.take_error();
  if (a.handle == hd::invalid_handle || error != hd::success)
    return fail("cannot initialise device '" +
                  (device_name_.empty() ? std::string("default") : device_name_) + "'",
      error);
  a.hdMakeCurrentDevice(a.handle);
  if ((error = a.take_error()) != hd::success)
    return fail("cannot make the device current", error);
  limits_ = DeviceLimits();
  nominal(a, hd::nominal_max_force, 1.0, limits_.max_force);
  nominal(a, hd::nominal_max_stiffness, 1000.0, limits_.max_stiffness);
  nominal(a, hd::nominal_max_damping, 1000.0, limits_.max_damping);
  double workspace[6] = {};
  a.hdGetDoublev(hd::usable_workspace, workspace);
  const Eigen::Vector3d lo(workspace[0], workspace[1], workspace[2]);
  const Eigen::Vector3d hi(workspace[3], workspace[4], workspace[5]);
  if (a.take_error() == hd::success && (hi - lo).minCoeff() > 0.0)
  {
    limits_.workspace_min = lo / 1000.0;
    limits_.workspace_max = hi / 1000.0;
    limits_.workspace_radius = 0.5 * (hi - lo).minCoeff() / 1000.0;
  }
  a.hdEnable(hd::force_output);
  a.hdSetSchedulerRate(hd::scheduler_rate);
  if ((error = a.take_error()) != hd::success)
    return fail(
      "cannot enable force output at " + std::to_string(hd::scheduler_rate) + " Hz", error);

  // No HD thread runs yet: drop what a previous session left in the buffers.
  frames_.update();
  forces_.write(Eigen::Vector3d::Zero());
  latest_ = Frame();
  hd_sample_ = DeviceSample();
  hd_error_ = hd::success;
  hd_error_text_ = nullptr;
  clock_.restart();
  a.callback = a.hdScheduleAsynchronous(&OpenHapticsDevice::tick, this, hd::default_priority);
  a.scheduled = true;
  a.hdStartScheduler();
  a.started = true;
  if ((error = a.take_error()) != hd::success)
    return fail("cannot start the servo scheduler", error);
  // The first sample, so that a successful open() always has one to read. A scheduler
  // that never calls back (the device held by another program, a broken driver) fails
  // here with a message rather than leaving the stylus at the origin.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (!frames_.update())
  {
    if (std::chrono::steady_clock::now() > give_up)
      return fail("the HD scheduler ran no servo tick within 2 s of starting", hd::success);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  latest_ = frames_.front();
  if (latest_.error != hd::success)
    return fail("the first servo tick failed", latest_.error);
  open_ = true;
  return true;
}

void OpenHapticsDevice::close()
{
  open_ = false;
  if (!api_)
    return;
  Api& a = *api_;
  // HD's order: stop the scheduler (no callback runs after it), unschedule, disable.
  if (a.started)
    a.hdStopScheduler();
  if (a.scheduled)
    a.hdUnschedule(a.callback);
  if (a.handle != hd::invalid_handle)
    a.hdDisableDevice(a.handle);
  a.take_error();
  dlclose(a.library);
  api_.reset();
}

unsigned int OpenHapticsDevice::tick(void* self)
{
  auto& d = *static_cast<OpenHapticsDevice*>(self);
  const Api& a = *d.api_;
  d.forces_.update();
  // After a fault nothing the servo side asks is sent: zero, from this tick on.
  const Eigen::Vector3d f =
    d.hd_error_ == hd::success ? d.safe_force(d.forces_.front()) : Eigen::Vector3d::Zero();
  // Start from the last good values: a failing call writes nothing.
  DeviceSample& s = d.hd_sample_;
  double position[3] = { s.position.x() * 1000.0, s.position.y() * 1000.0,
    s.position.z() * 1000.0 };
  double transform[16];
  Eigen::Map<Eigen::Matrix4d> m(transform); // column-major, like OpenGL and HD
  m.setIdentity();
  m.topLeftCorner<3, 3>() = s.orientation.toRotationMatrix();
  int buttons = int(s.buttons);
  a.hdBeginFrame(a.handle);
  a.hdGetDoublev(hd::current_position, position);
  a.hdGetDoublev(hd::current_transform, transform);
  a.hdGetIntegerv(hd::current_buttons, &buttons);
  a.hdSetDoublev(hd::current_force, f.data());
  a.hdEndFrame(a.handle);

  const hd::HDerror error = a.take_error();
  if (error != hd::success && d.hd_error_ == hd::success)
  {
    d.hd_error_ = error;
    d.hd_error_text_ = a.hdGetErrorString(error);
  }
  s.t = d.clock_.next();
  if (d.hd_error_ == hd::success)
  {
    s.position = Eigen::Vector3d(position[0], position[1], position[2]) / 1000.0;
    s.orientation = Eigen::Quaterniond(m.topLeftCorner<3, 3>()).normalized();
    s.buttons = std::uint32_t(buttons);
  }
  Frame& out = d.frames_.back();
  out.sample = s;
  out.error = d.hd_error_;
  out.error_text = d.hd_error_text_;
  d.frames_.publish();
  return hd::callback_continue;
}

bool OpenHapticsDevice::read(DeviceSample& sample)
{
  if (!open_)
    return false;
  if (frames_.update())
    latest_ = frames_.front();
  if (latest_.error != hd::success)
  {
    if (!has_error()) // the message once, not an allocation every tick
      set_error("OpenHaptics: " + hd::describe(latest_.error, latest_.error_text) +
                " in the servo tick; force output stopped. Check the device, then start "
                "haptics again");
    return false;
  }
  sample = latest_.sample;
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
