#pragma once
// Rate and period jitter of a periodic loop, kept as a histogram.
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>

namespace geoshaping::haptics
{

struct PeriodSummary
{
  std::uint64_t periods = 0;
  double mean_rate_hz = 0.0;  // periods / their total duration
  double p50_jitter_us = 0.0; // percentiles of |period - nominal|
  double p99_jitter_us = 0.0;
  double max_jitter_us = 0.0;
};

// Jitter |period - nominal| is binned at 1 us up to 20 ms (anything longer lands in the
// last bin, reported as >= 20 ms). A histogram rather than a ring buffer: constant
// memory, exact percentiles over the whole run at 1 us resolution, and O(1) per tick.
//
// One thread records; any thread may summarise while it does. Bins are atomics written
// with relaxed load+store (single writer, no read-modify-write), so recording never
// waits; a concurrent summary may see a tick's count without its bin, which is harmless.
class PeriodStats
{
public:
  explicit PeriodStats(std::chrono::nanoseconds nominal = std::chrono::milliseconds(1))
    : nominal_ns_(nominal.count())
  {
  }
  void record(std::chrono::nanoseconds period);
  PeriodSummary summary() const;
  void reset();
  std::chrono::nanoseconds nominal() const { return std::chrono::nanoseconds(nominal_ns_); }

  static constexpr std::size_t bins = 20001; // 0 .. 20000 us

private:
  static void bump(std::atomic<std::uint64_t>& a, std::uint64_t by)
  {
    a.store(a.load(std::memory_order_relaxed) + by, std::memory_order_relaxed);
  }

  std::int64_t nominal_ns_;
  std::array<std::atomic<std::uint64_t>, bins> histogram_{};
  std::atomic<std::uint64_t> count_{ 0 };
  std::atomic<std::uint64_t> total_ns_{ 0 };
  std::atomic<std::uint64_t> max_jitter_ns_{ 0 };
};

} // namespace geoshaping::haptics
