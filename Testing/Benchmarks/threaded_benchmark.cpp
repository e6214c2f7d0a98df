// Threaded supersteps (chainmail_deformer.h, "Threads") against the one-thread frame on
// the 1600 x 1600 painted grid (bench::painted_grid, 8 bands), centre grasp, pulled to
// displace 1,000,000, 300,000, 100,000 or 30,000 vertices.
//
// BM_ThreadedFrame/<queue>/<threads>/<displaced in thousands>/<threshold>, queue 0 FIFO or 2 FIFO
//   Priority: frames on `threads` threads (1: the one-thread frame; 0: automatic, one thread
//   for a while after a stall on a busy machine), for farm-bench to time
//   whole processes A B A B (docs/benchmarks.md, "Threaded frame"). Counters per frame:
//   wall `ms`, the calling thread's CPU `main_cpu_ms`, the process's `cpu_ms` (all
//   threads), supersteps and threaded supersteps.
// BM_Interleaved/<queue>/<displaced in thousands>/<threshold>: a one-thread and a two-thread
// deformer
//   in turn in one loop (one, two, one, ...), wall clock each: `one_ms`, `two_ms`,
//   `speedup`, and each frame's CPU; threshold 0 is the default, others choose it.
// BM_SuperstepShare/<queue>/<displaced in thousands>: the one-thread frame superstep by
//   superstep: `threaded_share`, the share of its time in supersteps at or above the
//   default threshold (those that run threaded), and their count.
#include "bench_scenes.h"
#include "geoshaping/parallel/thread_clock.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <memory>

using namespace geoshaping;

namespace
{
constexpr index_t side = 1600;
constexpr index_t grasp = (side / 2) * side + side / 2;

ChainMailDeformer& scene()
{
  static std::unique_ptr<ChainMailDeformer> d;
  if (!d)
  {
    d = std::make_unique<ChainMailDeformer>();
    std::vector<float> m;
    auto mesh = bench::painted_grid(side, m);
    d->set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
    d->set_malleability(m.data());
  }
  return *d;
}

// The pulls that displace the given thousands of vertices (bisection on the pull, done
// once; the counters report the exact count).
double pull_for(QueueKind q, int thousands)
{
  const bool fifo = q == QueueKind::fifo;
  switch (thousands)
  {
    case 1000:
      return fifo ? 207.65000081081979 : 241.81000547111037;
    case 300:
      return fifo ? 114.76999919128139 : 120.75000298034865;
    case 100:
      return fifo ? 66.67000094067771 : 74.810001686331816;
    default:
      return fifo ? 36.64999960368732 : 44.749999567924533;
  }
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double process_cpu_seconds()
{
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// One deformer's frames, timed: wall clock, the calling thread's CPU, the process's CPU.
struct FrameTimes
{
  double wall = 0.0, main_cpu = 0.0, cpu = 0.0;
  FrameResult run(ChainMailDeformer& d, index_t grasp, const Eigen::Vector3d& pull)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_seconds(), p0 = process_cpu_seconds();
    FrameResult r = d.deform(grasp, pull);
    main_cpu += thread_cpu_seconds() - c0;
    cpu += process_cpu_seconds() - p0;
    wall += seconds_since(t0);
    return r;
  }
};

void BM_ThreadedFrame(benchmark::State& state)
{
  const auto queue = static_cast<QueueKind>(state.range(0));
  ChainMailDeformer& d = scene();
  d.set_queue(queue);
  d.set_threads(int(state.range(1)));
  d.set_threaded_threshold(
    state.range(3) > 0 ? std::size_t(state.range(3)) : ChainMailDeformer().threaded_threshold());
  const Eigen::Vector3d pull(0.0, 0.0, pull_for(queue, int(state.range(2))));
  FrameResult r = d.deform(grasp, pull); // starts the threads
  FrameTimes times;
  for (auto _ : state)
  {
    r = times.run(d, grasp, pull);
    benchmark::DoNotOptimize(r.moved);
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(r.moved);
  state.counters["supersteps"] = double(r.supersteps);
  state.counters["threaded_supersteps"] = double(r.threaded_supersteps);
  state.counters["ms"] = 1e3 * times.wall / n;
  state.counters["main_cpu_ms"] = 1e3 * times.main_cpu / n;
  state.counters["cpu_ms"] = 1e3 * times.cpu / n;
  state.SetLabel(std::string(queue_name(queue)) + ", " + std::to_string(d.threads()) + " threads");
}

void BM_Interleaved(benchmark::State& state)
{
  const auto queue = static_cast<QueueKind>(state.range(0));
  ChainMailDeformer& one = scene();
  one.set_queue(queue);
  one.set_threads(1);
  static std::unique_ptr<ChainMailDeformer> two_threads;
  if (!two_threads)
    two_threads = std::make_unique<ChainMailDeformer>(one);
  ChainMailDeformer& two = *two_threads;
  two.set_queue(queue);
  two.set_threads(2);
  if (state.range(2) > 0)
    two.set_threaded_threshold(std::size_t(state.range(2)));
  const Eigen::Vector3d pull(0.0, 0.0, pull_for(queue, int(state.range(1))));
  two.deform(grasp, pull); // starts the threads
  FrameTimes one_t, two_t;
  FrameResult r;
  for (auto _ : state)
  {
    one_t.run(one, grasp, pull);
    r = two_t.run(two, grasp, pull);
    benchmark::DoNotOptimize(r.moved);
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(r.moved);
  state.counters["supersteps"] = double(r.supersteps);
  state.counters["threaded_supersteps"] = double(r.threaded_supersteps);
  state.counters["one_ms"] = 1e3 * one_t.wall / n;
  state.counters["two_ms"] = 1e3 * two_t.wall / n;
  state.counters["speedup"] = one_t.wall / two_t.wall;
  state.counters["one_cpu_ms"] = 1e3 * one_t.main_cpu / n;
  state.counters["two_main_cpu_ms"] = 1e3 * two_t.main_cpu / n;
  state.counters["two_cpu_ms"] = 1e3 * two_t.cpu / n;
  state.SetLabel(queue_name(queue));
}

void BM_SuperstepShare(benchmark::State& state)
{
  const auto queue = static_cast<QueueKind>(state.range(0));
  ChainMailDeformer& d = scene();
  d.set_queue(queue);
  d.set_threads(1);
  const std::size_t threshold = ChainMailDeformer().threaded_threshold();
  const Eigen::Vector3d pull(0.0, 0.0, pull_for(queue, int(state.range(1))));
  double total = 0.0, above = 0.0;
  std::size_t supersteps = 0, large = 0, moved = 0;
  for (auto _ : state)
  {
    supersteps = large = 0;
    const auto t0 = std::chrono::steady_clock::now();
    d.begin_frame();
    d.move_vertex(grasp, pull);
    d.end_superstep();
    for (SuperstepKey key; (key = d.pending()) != SuperstepQueue::none;)
    {
      const auto t1 = std::chrono::steady_clock::now();
      const std::size_t entries = d.superstep(key);
      d.end_superstep();
      ++supersteps;
      if (entries >= threshold)
      {
        above += seconds_since(t1);
        ++large;
      }
    }
    total += seconds_since(t0);
    moved = d.moved().size();
  }
  state.counters["displaced"] = double(moved);
  state.counters["supersteps"] = double(supersteps);
  state.counters["large_supersteps"] = double(large);
  state.counters["threaded_share"] = above / total;
  state.SetLabel(queue_name(queue));
}
} // namespace

BENCHMARK(BM_ThreadedFrame)
  ->ArgsProduct({ { 0, 2 }, { 1, 2, 0 }, { 1000, 300, 100, 30 }, { 0 } })
  ->ArgsProduct({ { 0 }, { 2 }, { 1000, 300 }, { 256, 4096 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_Interleaved)
  ->ArgsProduct({ { 0, 2 }, { 1000, 300, 100, 30 }, { 0 } })
  ->ArgsProduct({ { 0 }, { 1000, 300, 100 }, { 256, 4096 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(1.0);
BENCHMARK(BM_SuperstepShare)
  ->ArgsProduct({ { 0, 2 }, { 1000, 300, 100, 30 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

BENCHMARK_MAIN();
