#pragma once
// The 1 kHz servo loop: read the device, compute the force, send it, on its own thread.
#include "geoshaping/haptics/period_stats.h"
#include "geoshaping/haptics/servo_tick.h"
#include "geoshaping/haptics/triple_buffer.h"

#include <atomic>
#include <string>
#include <thread>

namespace geoshaping::haptics
{

struct ServoConfig
{
  std::chrono::nanoseconds period = std::chrono::milliseconds(1);
  ForceParams force;
  // Time constant (s) of the velocity filter (ServoTick).
  double velocity_filter_s = 0.005;
  // Linux: ask for 1 ns timer slack on the servo thread so sleep_until wakes on time
  // (the default 50 us slack is half the jitter budget). No privileges needed.
  bool tight_timer_slack = true;
  // > 0: try to run the servo thread SCHED_FIFO at this priority (1..99). Needs
  // CAP_SYS_NICE or an rtprio limit; without them the loop runs at normal priority and
  // realtime() says so. Off by default: a runaway real-time thread can starve a desktop.
  int realtime_priority = 0;
};

// One tick, every `period`, on steady_clock deadlines (sleep_until, not sleep_for, so
// the work time does not accumulate as drift):
//   read the device -> take the newest scene snapshot (if any) -> ServoTick (velocity,
//   proxy, compute_force) -> set_force -> publish a device snapshot -> record the period since the
//   last tick.
// A tick that finds itself more than a whole period late does not try to catch up with
// a burst of ticks; it rebases the deadline on now (the long period shows in the jitter).
//
// Threads: the graphics thread is the single writer of scenes and the single reader of
// device snapshots; the servo thread is the other end of both triple buffers, so it
// never takes a lock, never allocates on a tick, and never waits for the graphics side.
class ServoLoop
{
public:
  explicit ServoLoop(HapticDevice& device, ServoConfig config = {});
  ~ServoLoop();
  ServoLoop(const ServoLoop&) = delete;
  ServoLoop& operator=(const ServoLoop&) = delete;

  // Opens the device if needed and starts the thread; false with error() if the device
  // does not open or the loop already runs.
  bool start();
  // Stops the thread and sends a last zero force. Safe to call twice.
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }
  const std::string& error() const { return error_; }

  // Graphics thread: fill scene_back() completely (reuse its vectors), then
  // publish_scene(); or publish_scene(snapshot) to copy one in. The stamp is the
  // caller's, so a frozen pipeline is noticed as stale.
  SceneSnapshot& scene_back() { return scene_.back(); }
  void publish_scene() { scene_.publish(); }
  void publish_scene(const SceneSnapshot& s) { scene_.write(s); }

  // Graphics thread: the newest device snapshot into `out`; false if nothing new since
  // the last call (then `out` is left as it was).
  bool poll_device(DeviceSnapshot& out);

  // Any thread, while running or after.
  PeriodSummary period_summary() const { return periods_.summary(); }
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_relaxed); }
  // Whether the servo thread got the real-time priority it asked for.
  bool realtime() const { return realtime_.load(std::memory_order_relaxed); }

private:
  void run();

  HapticDevice& device_;
  ServoConfig config_;
  std::string error_;
  std::thread thread_;
  std::atomic<bool> running_{ false };
  std::atomic<bool> stop_{ false };
  std::atomic<bool> realtime_{ false };
  std::atomic<std::uint64_t> ticks_{ 0 };
  PeriodStats periods_;
  ServoTick tick_; // the servo thread's own state, allocated here, not per tick
  TripleBuffer<SceneSnapshot> scene_;
  TripleBuffer<DeviceSnapshot> device_state_;
};

} // namespace geoshaping::haptics
