// The fake HD library's test controls (fake_hd.h): script the device, read back what the
// application did, hold and step the scheduler.
#include "fake_hd_state.h"

using namespace fakehd;

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
  locked([&](Fake& f) { *out = f.state; });
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
  const double position[3] = { x, y, z };
  locked([&](Fake& f) { std::copy(position, position + 3, f.position); });
}

FAKEHD_API void fakehd_set_rotation(const double* row_major_3x3)
{
  locked([&](Fake& f) { std::copy(row_major_3x3, row_major_3x3 + 9, f.rotation); });
}

FAKEHD_API void fakehd_set_buttons(int buttons)
{
  locked([&](Fake& f) { f.buttons = buttons; });
}

FAKEHD_API void fakehd_set_nominal(double force, double stiffness, double damping)
{
  const double nominal[3] = { force, stiffness, damping };
  locked([&](Fake& f) { std::copy(nominal, nominal + 3, f.nominal); });
}

FAKEHD_API void fakehd_set_workspace(const double* min_max_mm)
{
  locked([&](Fake& f) { std::copy(min_max_mm, min_max_mm + 6, f.workspace); });
}

FAKEHD_API void fakehd_reject_parameter(unsigned int parameter)
{
  locked([&](Fake& f) { f.rejected.push_back(parameter); });
}

FAKEHD_API void fakehd_inject_fault()
{
  locked([&](Fake& f) { f.state.faulted = 1; });
}

FAKEHD_API void fakehd_clear_fault()
{
  locked([&](Fake& f) { f.state.faulted = 0; });
}

FAKEHD_API void fakehd_last_force(double* out3)
{
  locked([&](Fake& f) { std::copy(f.last_force, f.last_force + 3, out3); });
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
