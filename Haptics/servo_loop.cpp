#include "geoshaping/haptics/servo_loop.h"

#ifdef __linux__
#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#endif

namespace geoshaping::haptics
{

ServoLoop::ServoLoop(HapticDevice& device, ServoConfig config)
  : device_(device)
  , config_(config)
  , periods_(config.period)
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
  Eigen::Vector3d last_position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  bool have_last = false;
  double last_t = 0.0;
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
    if (device_ok && sample.position.allFinite())
    {
      // Velocity from the device's own time stamps, so a late tick does not read as a
      // fast stylus; an exponential filter with time constant velocity_filter_s.
      const double dt = sample.t - last_t;
      if (have_last && dt > 0.0)
      {
        const Eigen::Vector3d raw = (sample.position - last_position) / dt;
        const double alpha = dt / (dt + config_.velocity_filter_s);
        velocity += alpha * (raw - velocity);
      }
      if (!velocity.allFinite())
        velocity.setZero();
      last_position = sample.position;
      last_t = sample.t;
      have_last = true;
    }
    else
    {
      have_last = false;
      velocity.setZero();
    }

    scene_.update();
    const SceneSnapshot& scene = scene_.front();
    ForceInput in;
    in.position = sample.position;
    in.velocity = velocity;
    in.device_ok = device_ok;
    in.now = start;
    const ForceResult f = compute_force(in, scene, config_.force, device_.limits());
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
