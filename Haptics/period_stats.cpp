#include "geoshaping/haptics/period_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace geoshaping::haptics
{

void PeriodStats::record(std::chrono::nanoseconds period)
{
  const std::int64_t p = std::max<std::int64_t>(0, period.count());
  const std::uint64_t jitter_ns = std::uint64_t(std::llabs(p - nominal_ns_));
  const std::size_t bin = std::min<std::uint64_t>((jitter_ns + 500) / 1000, bins - 1);
  bump(histogram_[bin], 1);
  bump(total_ns_, std::uint64_t(p));
  if (jitter_ns > max_jitter_ns_.load(std::memory_order_relaxed))
    max_jitter_ns_.store(jitter_ns, std::memory_order_relaxed);
  // Last, so a concurrent summary never counts a period whose bin is not yet in.
  count_.store(count_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
}

PeriodSummary PeriodStats::summary() const
{
  PeriodSummary s;
  s.periods = count_.load(std::memory_order_acquire);
  if (s.periods == 0)
    return s;
  const double total_s = double(total_ns_.load(std::memory_order_relaxed)) * 1e-9;
  s.mean_rate_hz = total_s > 0.0 ? double(s.periods) / total_s : 0.0;
  s.max_jitter_us = double(max_jitter_ns_.load(std::memory_order_relaxed)) * 1e-3;
  // Smallest jitter with at least q of the periods at or below it (nearest rank).
  auto percentile = [&](double q)
  {
    const std::uint64_t rank =
      std::max<std::uint64_t>(1, std::uint64_t(std::ceil(q * double(s.periods))));
    std::uint64_t seen = 0;
    for (std::size_t b = 0; b < bins; ++b)
    {
      seen += histogram_[b].load(std::memory_order_relaxed);
      if (seen >= rank)
        return double(b);
    }
    return double(bins - 1);
  };
  s.p50_jitter_us = percentile(0.50);
  s.p99_jitter_us = percentile(0.99);
  return s;
}

void PeriodStats::reset()
{
  count_.store(0);
  for (auto& b : histogram_)
    b.store(0, std::memory_order_relaxed);
  total_ns_.store(0);
  max_jitter_ns_.store(0);
}

} // namespace geoshaping::haptics
