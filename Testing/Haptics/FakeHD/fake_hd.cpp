// A fake OpenHaptics HD library, built as libHD.so for the tests only: the HD calls
// OpenHapticsDevice resolves, behaving as HD documents them (see fake_hd_state.h for
// where the types and values come from and what the fake enforces).
#include "fake_hd_state.h"

using namespace fakehd;

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
