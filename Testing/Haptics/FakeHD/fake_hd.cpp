// A fake OpenHaptics HD library (built as libHD.so for the tests only): the HD calls
// OpenHapticsDevice resolves, behaving as HD documents them, plus the fakehd_* test
// controls of fake_hd.h.
//
// Types, signatures and constant values are those of OpenHaptics 3.x, written out here
// from its headers (HD/hdDefines.h: types, HDErrorInfo, error codes, parameter codes,
// HD_FORCE_OUTPUT, HD_INVALID_HANDLE; HD/hdScheduler.h: HDCallbackCode, HD_CALLBACK_*,
// HDSchedulerHandle, the scheduler calls; HD/hdDevice.h: device and frame calls). They
// are checked against public copies of those headers (e.g. github.com/hhmai/PhantomAPI,
// include/HD/hdDefines.h) and deliberately NOT shared with the backend's own
// declarations in Haptics/openhaptics_device.cpp, so a wrong value there fails a test.
//
// What the fake enforces (stricter than a lenient driver, never looser than HD):
// device frames only on the scheduler thread and never nested, forces set only inside
// a frame, one device initialised at a time. A breach raises an HD error and counts in
// FakeHDState::misuse.
#include "fake_hd.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#define FAKEHD_API extern "C" __attribute__((visibility("default")))

using HHD = unsigned int;
using HDenum = unsigned int;
using HDerror = unsigned int;
using HDint = int;
using HDdouble = double;
using HDushort = unsigned short;
using HDulong = unsigned long;
using HDstring = const char*;
using HDSchedulerHandle = unsigned long;
using HDCallbackCode = unsigned int;
using HDSchedulerCallback = HDCallbackCode (*)(void*);
struct HDErrorInfo
{
  HDerror errorCode;
  int internalErrorCode;
  HHD hHD;
};

namespace
{
constexpr HHD HD_INVALID_HANDLE = 0xFFFFFFFF;
constexpr HDerror HD_SUCCESS = 0x0000;
constexpr HDerror HD_INVALID_ENUM = 0x0100;
constexpr HDerror HD_INVALID_VALUE = 0x0101;
constexpr HDerror HD_INVALID_OPERATION = 0x0102;
constexpr HDerror HD_BAD_HANDLE = 0x0104;
constexpr HDerror HD_DEVICE_FAULT = 0x0300;
constexpr HDerror HD_DEVICE_ALREADY_INITIATED = 0x0301;
constexpr HDerror HD_COMM_CONFIG_ERROR = 0x0303;
constexpr HDerror HD_ILLEGAL_BEGIN = 0x0400;
constexpr HDerror HD_ILLEGAL_END = 0x0401;
constexpr HDenum HD_CURRENT_BUTTONS = 0x2000;
constexpr HDenum HD_CURRENT_POSITION = 0x2050;
constexpr HDenum HD_CURRENT_TRANSFORM = 0x2052;
constexpr HDenum HD_USABLE_WORKSPACE_DIMENSIONS = 0x2551;
constexpr HDenum HD_NOMINAL_MAX_STIFFNESS = 0x2602;
constexpr HDenum HD_NOMINAL_MAX_FORCE = 0x2603;
constexpr HDenum HD_NOMINAL_MAX_DAMPING = 0x2609;
constexpr HDenum HD_CURRENT_FORCE = 0x2700;
constexpr HDenum HD_FORCE_OUTPUT = 0x4000;
constexpr HDCallbackCode HD_CALLBACK_DONE = 0;
constexpr HHD device_handle = 0; // HD numbers devices from 0
constexpr std::size_t error_stack_size = 32;

struct Callback
{
  HDSchedulerCallback function;
  void* data;
  HDushort priority;
  HDSchedulerHandle handle;
};

// All the fake's state. `m` guards everything but `callbacks`, which `run_m` guards and
// which the scheduler thread walks with `m` released (the callbacks call back into HD).
struct Fake
{
  std::mutex m;
  std::condition_variable cv;
  FakeHDState state{};
  std::string calls, calls_copy;
  double position[3]{};
  double rotation[9]{};
  int buttons = 0;
  double nominal[3]{};   // force N, stiffness N/mm, damping N s/mm
  double workspace[6]{}; // mm
  std::vector<HDenum> rejected;
  std::vector<HDErrorInfo> errors;
  bool in_frame = false;
  bool force_set = false;
  double last_force[3]{};
  std::uint64_t force_frames = 0;

  std::thread scheduler;
  std::thread::id scheduler_id;
  bool stop = false, held = false, parked = false;
  unsigned int credit = 0;

  std::mutex run_m;
  std::vector<Callback> callbacks;
  HDSchedulerHandle next_handle = 1;

  Fake() { reset_locked(); }
  ~Fake() { stop_scheduler(); }

  // A Touch-like default: 3.3 N, 1 N/mm, 0.0025 N s/mm, 160 x 120 x 70 mm workspace.
  void reset_locked()
  {
    state = FakeHDState{};
    calls.clear();
    std::fill(std::begin(position), std::end(position), 0.0);
    const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    std::copy(std::begin(identity), std::end(identity), rotation);
    buttons = 0;
    nominal[0] = 3.3;
    nominal[1] = 1.0;
    nominal[2] = 0.0025;
    const double box[6] = { -80, -60, -35, 80, 60, 35 };
    std::copy(std::begin(box), std::end(box), workspace);
    rejected.clear();
    errors.clear();
    in_frame = force_set = false;
    std::fill(std::begin(last_force), std::end(last_force), 0.0);
    force_frames = 0;
    held = false;
    credit = 0;
  }

  void log(const std::string& call) { calls += (calls.empty() ? "" : " ") + call; }

  void raise(HDerror code, bool misuse = false)
  {
    if (errors.size() == error_stack_size)
      errors.erase(errors.begin());
    errors.push_back(HDErrorInfo{ code, 0, device_handle });
    state.misuse += misuse ? 1u : 0u;
  }

  // The common prologue of a device call: false (with HD_DEVICE_FAULT raised) if faulted.
  bool usable()
  {
    if (state.faulted)
      raise(HD_DEVICE_FAULT);
    return !state.faulted;
  }

  void run_callbacks()
  {
    std::lock_guard<std::mutex> run(run_m);
    std::stable_sort(callbacks.begin(), callbacks.end(),
      [](const Callback& a, const Callback& b) { return a.priority > b.priority; });
    for (std::size_t i = 0; i < callbacks.size();)
    {
      if (callbacks[i].function(callbacks[i].data) == HD_CALLBACK_DONE)
        callbacks.erase(callbacks.begin() + std::ptrdiff_t(i));
      else
        ++i;
    }
  }

  // The scheduler thread: one tick per period of the asked rate while running, or one
  // per credit while held.
  void scheduler_main()
  {
    std::unique_lock<std::mutex> lock(m);
    scheduler_id = std::this_thread::get_id();
    auto next = std::chrono::steady_clock::now();
    while (!stop)
    {
      if (held && credit == 0)
      {
        parked = true;
        cv.notify_all();
        cv.wait(lock, [this] { return stop || !held || credit > 0; });
        parked = false;
        next = std::chrono::steady_clock::now();
        continue;
      }
      if (held)
        --credit;
      lock.unlock();
      run_callbacks();
      lock.lock();
      ++state.ticks;
      cv.notify_all();
      if (!held)
      {
        const unsigned long rate = state.rate > 0 ? state.rate : 1000;
        // Late (a loaded machine): rebase instead of bursting to catch up.
        next = std::max(
          next + std::chrono::nanoseconds(1000000000 / rate), std::chrono::steady_clock::now());
        cv.wait_until(lock, next, [this] { return stop || held; });
      }
    }
    parked = false;
  }

  void stop_scheduler()
  {
    std::unique_lock<std::mutex> lock(m);
    if (!scheduler.joinable())
      return;
    stop = true;
    cv.notify_all();
    lock.unlock();
    scheduler.join();
    lock.lock();
    state.scheduler_running = 0;
    cv.notify_all();
  }
};

Fake& fake()
{
  static Fake instance;
  return instance;
}

bool on_scheduler_thread(const Fake& f)
{
  return f.state.scheduler_running && std::this_thread::get_id() == f.scheduler_id;
}
} // namespace

// ---- HD: device (HD/hdDevice.h) ----

FAKEHD_API HHD hdInitDevice(HDstring config_name)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.log("init");
  if (!f.usable())
    return HD_INVALID_HANDLE;
  if (config_name && *config_name && std::strcmp(config_name, "Default Device") != 0)
  {
    f.raise(HD_COMM_CONFIG_ERROR);
    return HD_INVALID_HANDLE;
  }
  if (f.state.initialized)
  {
    f.raise(HD_DEVICE_ALREADY_INITIATED, true);
    return HD_INVALID_HANDLE;
  }
  f.state.initialized = 1;
  return device_handle;
}

FAKEHD_API void hdDisableDevice(HHD handle)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.log("disable");
  if (handle != device_handle || !f.state.initialized)
  {
    f.raise(HD_BAD_HANDLE, true);
    return;
  }
  f.state.initialized = 0;
  f.state.force_output = 0;
  ++f.state.disabled;
}

FAKEHD_API void hdMakeCurrentDevice(HHD handle)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.log("make_current");
  if (handle != device_handle || !f.state.initialized)
    f.raise(HD_BAD_HANDLE, true);
}

FAKEHD_API HDErrorInfo hdGetError()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  if (f.errors.empty())
    return HDErrorInfo{ HD_SUCCESS, 0, device_handle };
  const HDErrorInfo e = f.errors.back();
  f.errors.pop_back();
  return e;
}

FAKEHD_API HDstring hdGetErrorString(HDerror code)
{
  switch (code)
  {
    case HD_SUCCESS:
      return "No error";
    case HD_INVALID_ENUM:
      return "Invalid enumeration";
    case HD_INVALID_VALUE:
      return "Invalid value";
    case HD_INVALID_OPERATION:
      return "Invalid operation";
    case HD_BAD_HANDLE:
      return "Bad handle";
    case HD_DEVICE_FAULT:
      return "Device fault";
    case HD_DEVICE_ALREADY_INITIATED:
      return "Device already initiated";
    case HD_COMM_CONFIG_ERROR:
      return "Communication configuration error";
    case HD_ILLEGAL_BEGIN:
      return "Illegal begin frame";
    case HD_ILLEGAL_END:
      return "Illegal end frame";
    default:
      return "Unknown error";
  }
}

FAKEHD_API void hdEnable(HDenum capability)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.log("enable");
  if (!f.usable())
    return;
  if (capability != HD_FORCE_OUTPUT)
    f.raise(HD_INVALID_ENUM);
  else
    f.state.force_output = f.state.initialized;
}

FAKEHD_API void hdBeginFrame(HHD handle)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  if (!on_scheduler_thread(f) || f.in_frame || handle != device_handle)
  {
    f.raise(HD_ILLEGAL_BEGIN, true);
    return;
  }
  f.in_frame = true;
  f.force_set = false;
  f.usable();
}

FAKEHD_API void hdEndFrame(HHD handle)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  if (!f.in_frame || handle != device_handle)
  {
    f.raise(HD_ILLEGAL_END, true);
    return;
  }
  f.in_frame = false;
  f.force_frames += f.force_set ? 1u : 0u;
  f.usable();
}

FAKEHD_API void hdGetDoublev(HDenum parameter, HDdouble* out)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  if (!f.usable())
    return;
  if (std::find(f.rejected.begin(), f.rejected.end(), parameter) != f.rejected.end())
  {
    f.raise(HD_INVALID_ENUM);
    return;
  }
  switch (parameter)
  {
    case HD_CURRENT_POSITION:
      std::copy(f.position, f.position + 3, out);
      break;
    case HD_CURRENT_TRANSFORM: // column-major, translation in elements 12..14
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
          out[4 * c + r] = f.rotation[3 * r + c];
      out[3] = out[7] = out[11] = 0.0;
      std::copy(f.position, f.position + 3, out + 12);
      out[15] = 1.0;
      break;
    case HD_NOMINAL_MAX_FORCE:
      *out = f.nominal[0];
      break;
    case HD_NOMINAL_MAX_STIFFNESS:
      *out = f.nominal[1];
      break;
    case HD_NOMINAL_MAX_DAMPING:
      *out = f.nominal[2];
      break;
    case HD_USABLE_WORKSPACE_DIMENSIONS:
      std::copy(f.workspace, f.workspace + 6, out);
      break;
    default:
      f.raise(HD_INVALID_ENUM);
  }
}

FAKEHD_API void hdGetIntegerv(HDenum parameter, HDint* out)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  if (!f.usable())
    return;
  if (parameter == HD_CURRENT_BUTTONS)
    *out = f.buttons;
  else
    f.raise(HD_INVALID_ENUM);
}

FAKEHD_API void hdSetDoublev(HDenum parameter, const HDdouble* in)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  if (parameter != HD_CURRENT_FORCE)
  {
    f.raise(HD_INVALID_ENUM);
    return;
  }
  if (!f.in_frame)
  {
    f.raise(HD_INVALID_OPERATION, true);
    return;
  }
  std::copy(in, in + 3, f.last_force);
  f.force_set = true;
  f.usable();
}

// ---- HD: scheduler (HD/hdScheduler.h) ----

FAKEHD_API void hdSetSchedulerRate(HDulong rate)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.log("rate=" + std::to_string(rate));
  if (rate == 0 || f.state.scheduler_running)
    f.raise(HD_INVALID_VALUE, f.state.scheduler_running != 0);
  else
    f.state.rate = rate;
}

FAKEHD_API void hdStartScheduler()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.log("start");
  if (f.state.scheduler_running)
    return;
  f.stop = false;
  f.state.scheduler_running = 1;
  f.scheduler = std::thread([&f] { f.scheduler_main(); });
}

FAKEHD_API void hdStopScheduler()
{
  Fake& f = fake();
  {
    std::lock_guard<std::mutex> lock(f.m);
    f.log("stop");
    ++f.state.scheduler_stops;
  }
  f.stop_scheduler();
}

FAKEHD_API HDSchedulerHandle hdScheduleAsynchronous(
  HDSchedulerCallback callback, void* data, HDushort priority)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> run(f.run_m);
  std::lock_guard<std::mutex> lock(f.m);
  f.log("schedule");
  f.callbacks.push_back(Callback{ callback, data, priority, f.next_handle });
  f.state.callbacks = int(f.callbacks.size());
  return f.next_handle++;
}

FAKEHD_API void hdUnschedule(HDSchedulerHandle handle)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> run(f.run_m);
  std::lock_guard<std::mutex> lock(f.m);
  f.log("unschedule");
  const auto it = std::find_if(f.callbacks.begin(), f.callbacks.end(),
    [handle](const Callback& c) { return c.handle == handle; });
  if (it == f.callbacks.end())
  {
    f.raise(HD_INVALID_VALUE, true);
    return;
  }
  f.callbacks.erase(it);
  f.state.callbacks = int(f.callbacks.size());
}

// ---- test controls (fake_hd.h) ----

FAKEHD_API void fakehd_reset()
{
  Fake& f = fake();
  f.stop_scheduler();
  std::lock_guard<std::mutex> run(f.run_m);
  std::lock_guard<std::mutex> lock(f.m);
  f.callbacks.clear();
  f.reset_locked();
}

FAKEHD_API void fakehd_state(FakeHDState* out)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  *out = f.state;
}

FAKEHD_API const char* fakehd_calls()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.calls_copy = f.calls;
  return f.calls_copy.c_str();
}

FAKEHD_API void fakehd_set_position(double x, double y, double z)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.position[0] = x;
  f.position[1] = y;
  f.position[2] = z;
}

FAKEHD_API void fakehd_set_rotation(const double* row_major_3x3)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  std::copy(row_major_3x3, row_major_3x3 + 9, f.rotation);
}

FAKEHD_API void fakehd_set_buttons(int buttons)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.buttons = buttons;
}

FAKEHD_API void fakehd_set_nominal(double force, double stiffness, double damping)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.nominal[0] = force;
  f.nominal[1] = stiffness;
  f.nominal[2] = damping;
}

FAKEHD_API void fakehd_set_workspace(const double* min_max_mm)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  std::copy(min_max_mm, min_max_mm + 6, f.workspace);
}

FAKEHD_API void fakehd_reject_parameter(unsigned int parameter)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.rejected.push_back(parameter);
}

FAKEHD_API void fakehd_inject_fault()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.state.faulted = 1;
}

FAKEHD_API void fakehd_clear_fault()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  f.state.faulted = 0;
}

FAKEHD_API void fakehd_last_force(double* out3)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  std::copy(f.last_force, f.last_force + 3, out3);
}

FAKEHD_API std::uint64_t fakehd_force_frames()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  return f.force_frames;
}

FAKEHD_API void fakehd_hold(int hold)
{
  Fake& f = fake();
  std::unique_lock<std::mutex> lock(f.m);
  f.held = hold != 0;
  f.credit = 0;
  f.cv.notify_all();
  if (f.held)
    f.cv.wait(lock, [&f] { return f.parked || !f.state.scheduler_running; });
}

FAKEHD_API int fakehd_step(unsigned int n)
{
  Fake& f = fake();
  std::unique_lock<std::mutex> lock(f.m);
  if (!f.state.scheduler_running)
    return 0;
  const std::uint64_t target = f.state.ticks + n;
  if (f.held)
    f.credit += n;
  f.cv.notify_all();
  f.cv.wait(lock, [&f, target] { return f.state.ticks >= target || !f.state.scheduler_running; });
  return f.state.ticks >= target ? 1 : 0;
}

FAKEHD_API unsigned long fakehd_scheduler_rate()
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  return f.state.rate;
}
