#pragma once
// @brief The fake HD library's insides, shared by its two halves: fake_hd.cpp (the HD
// calls OpenHapticsDevice resolves, behaving as HD documents them) and
// fake_hd_control.cpp (the fakehd_* test controls of fake_hd.h). Not a public header.
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
// HD frames (hdBeginFrame ... hdEndFrame) only on the scheduler thread and never nested, forces set
// only inside a frame, one device initialised at a time. A breach raises an HD error and counts in
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

namespace fakehd
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
  double last_force[3]{};

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
    in_frame = false;
    std::fill(std::begin(last_force), std::end(last_force), 0.0);
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

inline Fake& fake()
{
  static Fake instance;
  return instance;
}

// Runs `change` on the fake's state under its lock (the test controls' one idiom).
template<class Change>
void locked(Change change)
{
  Fake& f = fake();
  std::lock_guard<std::mutex> lock(f.m);
  change(f);
}

inline bool on_scheduler_thread(const Fake& f)
{
  return f.state.scheduler_running && std::this_thread::get_id() == f.scheduler_id;
}
} // namespace fakehd
