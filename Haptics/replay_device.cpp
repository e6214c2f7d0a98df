#include "geoshaping/haptics/replay_device.h"

#include "geoshaping/haptics/trace.h"

namespace geoshaping::haptics
{

ReplayDevice::ReplayDevice(std::string path, double step)
  : path_(std::move(path))
  , clock_(step)
{
}

ReplayDevice::ReplayDevice(std::vector<DeviceSample> samples, double step)
  : samples_(std::move(samples))
  , clock_(step)
{
}

bool ReplayDevice::open()
{
  clear_error();
  if (!path_.empty())
  {
    TraceParseResult trace = read_trace_file(path_);
    if (!trace.ok)
    {
      set_error(trace.message);
      return false;
    }
    samples_ = std::move(trace.samples);
  }
  if (samples_.empty())
  {
    set_error(path_.empty() ? std::string("replay: empty trace") : path_ + ": no samples");
    return false;
  }
  clock_.restart();
  finished_.store(false);
  open_ = true;
  return true;
}

bool ReplayDevice::read(DeviceSample& sample)
{
  if (!open_)
    return false;
  // The trace plays from its first time stamp, whatever that is.
  const double t = clock_.next();
  sample = sample_trace_at(samples_, samples_.front().t + t);
  sample.t = t;
  if (samples_.front().t + t >= samples_.back().t)
    finished_.store(true, std::memory_order_relaxed);
  return true;
}

} // namespace geoshaping::haptics
