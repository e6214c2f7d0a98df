#pragma once
// Progress and abort for the core's long loops, without VTK: a loop over N items calls
// the caller's Progress with the fraction done, at most 100 times (every ceil(N / 100)
// items) plus once at the end, and stops early when it returns false. A VTK filter passes
// [this](double f) { this->UpdateProgress(f); return !this->CheckAbort(); }.
// Cost: one integer compare per item; the callback runs at most 101 times per loop.
#include <cstddef>
#include <functional>

namespace geoshaping
{

using Progress = std::function<bool(double fraction)>;

class ProgressTicker
{
public:
  ProgressTicker(const Progress& progress, std::size_t total)
    : progress_(progress)
    , total_(total)
    , stride_(total / 100 + 1)
    , next_(stride_)
  {
  }

  // Call after item `done` (1-based count of items finished); false: stop.
  bool tick(std::size_t done)
  {
    if (!progress_ || done < next_)
    {
      return true;
    }
    next_ = done + stride_;
    return progress_(total_ > 0 ? double(done) / double(total_) : 1.0);
  }

  // The final report (fraction 1); false: the caller asked to stop.
  bool finish() { return !progress_ || progress_(1.0); }

private:
  const Progress& progress_;
  std::size_t total_;
  std::size_t stride_;
  std::size_t next_;
};

} // namespace geoshaping
