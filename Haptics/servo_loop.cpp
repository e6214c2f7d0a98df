#include "geoshaping/haptics/servo_loop.h"

#ifdef __linux__
#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#endif

namespace geoshaping::haptics
{

namespace
{
// The force model's zero-order hold period is the loop's.
ServoConfig with_servo_period(ServoConfig config)
{
  config.force.servo_period = std::chrono::duration<double>(config.period).count();
  return config;
}
} // namespace

ServoLoop::ServoLoop(HapticDevice& device, ServoConfig config)
  : device_(device)
  , config_(with_servo_period(config))
  , periods_(config.period)
  , tick_(config_.force, config.velocity_filter_s)
{
}

ServoLoop::~ServoLoop()
{
  stop();
}

bool ServoLoop::start()
{
  error_.clear();
  if (running())
  {
    error_ = "servo loop already running";
    return false;
  }
  if (!device_.is_open() && !device_.open())
  {
    error_ = device_.error();
    return false;
  }
  stop_.store(false);
  realtime_.store(false);
  ticks_.store(0);
  periods_.reset();
  running_.store(true, std::memory_order_release);
  thread_ = std::thread([this] { run(); });
  return true;
}

void ServoLoop::stop()
{
  stop_.store(true, std::memory_order_release);
  if (thread_.joinable())
    thread_.join();
  if (running_.exchange(false) && device_.is_open())
    device_.set_force(Eigen::Vector3d::Zero());
}

bool ServoLoop::poll_device(DeviceSnapshot& out)
{
  if (!device_state_.update())
    return false;
  out = device_state_.front();
  return true;
}

void ServoLoop::run()
{
#ifdef __linux__
  if (config_.tight_timer_slack)
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
  if (config_.realtime_priority > 0)
  {
    sched_param param{};
    param.sched_priority = config_.realtime_priority;
    realtime_.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0);
  }
#endif
  const Clock::duration period = config_.period;
  DeviceSample sample;
  tick_.reset();
  std::uint64_t ticks = 0, zero_ticks = 0;
  Clock::time_point last_start{};
  Clock::time_point deadline = Clock::now();

  while (!stop_.load(std::memory_order_acquire))
  {
    const Clock::time_point start = Clock::now();
    if (ticks > 0)
      periods_.record(start - last_start);
    last_start = start;

    const bool read_ok = device_.read(sample);
    const bool device_ok = read_ok && !device_.has_error();
    scene_.update();
    const SceneSnapshot& scene = scene_.front();
    const ForceResult f = tick_.tick(sample, device_ok, start, scene, device_.limits());
    device_.set_force(f.force);
    ++ticks;
    zero_ticks += f.status != ForceStatus::ok;
    ticks_.store(ticks, std::memory_order_relaxed);

    DeviceSnapshot& out = device_state_.back();
    out.stamp = start;
    out.sample = sample;
    out.device_ok = device_ok;
    out.force = f.force;
    out.status = f.status;
    out.in_contact = f.in_contact;
    out.proxy = f.proxy;
    out.ticks = ticks;
    out.zero_ticks = zero_ticks;
    out.scene_sequence = scene.sequence;
    device_state_.publish();

    deadline += period;
    const Clock::time_point now = Clock::now();
    if (now - deadline > period)
      deadline = now; // more than a tick late: skip, do not burst to catch up
    std::this_thread::sleep_until(deadline);
  }
}

} // namespace geoshaping::haptics
