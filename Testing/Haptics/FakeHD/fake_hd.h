#pragma once
// @brief The test-control side of the fake OpenHaptics HD library (libHD.so built with
// the tests): what a test scripts (pose, buttons, nominal limits, faults) and what it
// reads back (forces the application set, scheduler and device state).
//
// The fake exports the HD calls OpenHapticsDevice resolves, with the real signatures and
// constant values, and these fakehd_* functions. A test dlopen()s the same file the
// backend loads and resolves them with dlsym (the handle is shared, so is the state);
// it declares the pointers with decltype(&fakehd_...) from this header.
//
// Determinism: the scheduler thread runs the scheduled callbacks at the rate the
// application asked for (hdSetSchedulerRate, 1000 Hz if never asked), but a test never
// measures that: fakehd_hold() parks the thread and fakehd_step(n) lets exactly n ticks
// run and waits for them, so what a test asserts is a function of the tick count only.
#include <cstdint>

extern "C"
{
  struct FakeHDState
  {
    int initialized;       // hdInitDevice succeeded and hdDisableDevice was not called
    int disabled;          // hdDisableDevice calls since the last reset
    int force_output;      // hdEnable(HD_FORCE_OUTPUT) on the device
    int scheduler_running; // between hdStartScheduler and hdStopScheduler
    int scheduler_stops;   // hdStopScheduler calls since the last reset
    int callbacks;         // scheduled and not unscheduled
    unsigned long rate;    // Hz, as asked by hdSetSchedulerRate (0: never asked)
    std::uint64_t ticks;   // scheduler ticks run since the last reset
    int faulted;           // fakehd_inject_fault() and not fakehd_clear_fault()
    unsigned int misuse;   // calls outside the HD rules (a frame off the scheduler
                           // thread, a force set outside a frame...); each also raised
                           // an HD error
  };

  // Back to a fresh device: scheduler stopped (thread joined), nothing scheduled, the
  // default pose and limits, no fault, counters zero. Call at the start of each test.
  void fakehd_reset();
  void fakehd_state(FakeHDState* out);
  // The device and scheduler life-cycle calls since the last reset, in order, as
  // "init enable rate=1000 schedule start stop unschedule disable" (frame calls are
  // counted in FakeHDState, not logged). Valid until the next call into the fake.
  const char* fakehd_calls();

  // The stylus: position in mm; rotation as a row-major 3x3 matrix (the fake serves
  // HD_CURRENT_TRANSFORM column-major, as HD does); buttons as HD's bitmask.
  void fakehd_set_position(double x, double y, double z);
  void fakehd_set_rotation(const double* row_major_3x3);
  void fakehd_set_buttons(int buttons);
  // What HD_NOMINAL_MAX_FORCE (N), _STIFFNESS (N/mm), _DAMPING (N s/mm) and
  // HD_USABLE_WORKSPACE_DIMENSIONS (min xyz, max xyz, mm) return.
  void fakehd_set_nominal(double force, double stiffness, double damping);
  void fakehd_set_workspace(const double* min_max_mm);
  // hdGetDoublev of this parameter raises HD_INVALID_ENUM (a driver without it).
  void fakehd_reject_parameter(unsigned int parameter);

  // From now on every HD call fails: it raises HD_DEVICE_FAULT and does nothing
  // (no value written, no force rendered), as an amplifier fault or a pulled cable.
  void fakehd_inject_fault();
  // The device works again (the application must not trust it without reopening).
  void fakehd_clear_fault();

  // The force (N) the application last set with hdSetDoublev(HD_CURRENT_FORCE), whether
  // or not the device could render it.
  void fakehd_last_force(double* out3);

  // Park the scheduler thread between ticks (1) or let it run at its rate (0); returns
  // when the thread is parked (or at once if the scheduler is not running).
  void fakehd_hold(int hold);
  // Run exactly n more ticks (held) or wait for n more (running); returns after them.
  // Returns 0 without waiting if the scheduler is not running.
  int fakehd_step(unsigned int n);
  unsigned long fakehd_scheduler_rate();
}
