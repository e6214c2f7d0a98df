// Threaded supersteps (chainmail_deformer.h, "Threads") against the one-thread frame on
// the 1600 x 1600 grid, centre grasp, pulled to displace 1,000,000, 300,000, 100,000 or
// 30,000 vertices. Paint (the last argument of BM_Interleaved and BM_SuperstepShare):
// 0 tiles (bench::painted_grid, 8 bands), 1 the project's Smooth brush (bench::brush_painted,
// tens of thousands of values: the real case).
//
// BM_ThreadedFrame/<queue>/<threads>/<displaced in thousands>/<threshold>, queue 0 FIFO or 2 FIFO
//   Priority: frames on `threads` threads (1: the one-thread frame; 0: automatic, one thread
//   for a while after a stall on a busy machine), for farm-bench to time
//   whole processes A B A B (docs/benchmarks.md, "Threaded frame"). Counters per frame:
//   wall `ms`, the calling thread's CPU `main_cpu_ms`, the process's `cpu_ms` (all
//   threads), supersteps and threaded supersteps (the last frame's), and the share of
//   frames that ran a threaded superstep, `threaded_frames`.
// BM_Interleaved/<queue>/<displaced in thousands>/<threshold>/<paint>: a one-thread and a
// two-thread deformer
//   in turn in one loop (one, two, one, ...), wall clock each: `one_ms`, `two_ms`,
//   `speedup`, and each frame's CPU; threshold 0 is the default, others choose it.
// BM_SuperstepShare/<queue>/<displaced in thousands>/<threads>/<paint>: the frame superstep
//   by superstep: `threaded_share`, the share of its time in supersteps at or above the
//   default threshold (those that run threaded on several threads), and their count;
//   `step_ms` the supersteps' examination (with a threaded one's pushes), `end_ms` the
//   pushes of the others and the filing of all, `pending_ms` finding the next superstep.
#include "bench_scenes.h"
#include "geoshaping/parallel/thread_clock.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <map>
#include <memory>

using namespace geoshaping;

namespace
{
constexpr index_t side = 1600;
constexpr index_t grasp = (side / 2) * side + side / 2;

// paint 0: tiles, 1: the Smooth brush. `instance` 1 is a second deformer of the same
// scene, built the same way (set_mesh), for BM_Interleaved: a copy is laid out otherwise
// (its big buffers are not fresh allocations) and ran 5-9 % slower than the original.
ChainMailDeformer& scene(int paint = 0, int instance = 0)
{
  static std::unique_ptr<ChainMailDeformer> d[2][2];
  std::unique_ptr<ChainMailDeformer>& s = d[paint][instance];
  if (!s)
  {
    s = std::make_unique<ChainMailDeformer>();
    std::vector<float> m;
    auto mesh = bench::painted_grid(side, m);
    if (paint == 1)
      m = bench::brush_painted(
        mesh.xyz.data(), mesh.size(), mesh.adjacency, 0.0, 0.0, double(side - 1));
    s->set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
    s->set_malleability(m.data());
  }
  return *s;
}

// The pulls that displace the given thousands of vertices (tiles: bisection on the pull,
// done once; brush: bench::pull_for_count under the queue, once per queue and size; the
// counters report the exact count).
double pull_for(QueueKind q, int thousands, int paint = 0)
{
  if (paint == 1)
  {
    static std::map<std::pair<int, int>, double> pulls;
    double& pull = pulls[{ int(q), thousands }];
    if (pull == 0.0)
      pull = bench::pull_for_count(scene(1), grasp, std::size_t(thousands) * 1000, q);
    return pull;
  }
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
  const int threads = int(state.range(1)); // 2: always two; 0: automatic
  d.set_threads(threads, threads > 1 ? ChainMailDeformer::ThreadUse::always
                                     : ChainMailDeformer::ThreadUse::when_cores_free);
  d.set_threaded_threshold(
    state.range(3) > 0 ? std::size_t(state.range(3)) : ChainMailDeformer().threaded_threshold());
  const Eigen::Vector3d pull(0.0, 0.0, pull_for(queue, int(state.range(2))));
  FrameResult r = d.deform(grasp, pull); // starts the threads
  FrameTimes times;
  double threaded_frames = 0.0;
  for (auto _ : state)
  {
    r = times.run(d, grasp, pull);
    threaded_frames += r.threaded_supersteps > 0;
    benchmark::DoNotOptimize(r.moved);
  }
  const double n = double(state.iterations());
  state.counters["threaded_frames"] = threaded_frames / n;
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
  const int paint = int(state.range(3));
  const Eigen::Vector3d pull(0.0, 0.0, pull_for(queue, int(state.range(1)), paint));
  ChainMailDeformer& one = scene(paint);
  one.set_queue(queue);
  one.set_threads(1);
  ChainMailDeformer& two = scene(paint, 1);
  two.set_queue(queue);
  two.set_threads(2, ChainMailDeformer::ThreadUse::always);
  two.set_threaded_threshold(
    state.range(2) > 0 ? std::size_t(state.range(2)) : ChainMailDeformer().threaded_threshold());
  one.deform(grasp, pull);
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
  state.SetLabel(std::string(queue_name(queue)) + (paint == 1 ? ", brush" : ", tiles"));
}

void BM_SuperstepShare(benchmark::State& state)
{
  const auto queue = static_cast<QueueKind>(state.range(0));
  const int paint = int(state.range(3));
  const Eigen::Vector3d pull(0.0, 0.0, pull_for(queue, int(state.range(1)), paint));
  ChainMailDeformer& d = scene(paint);
  d.set_queue(queue);
  d.set_threads(int(state.range(2)), ChainMailDeformer::ThreadUse::always);
  const std::size_t threshold = ChainMailDeformer().threaded_threshold();
  d.deform(grasp, pull); // starts the threads, sizes the buffers
  double total = 0.0, above = 0.0, step = 0.0, end = 0.0, pending = 0.0;
  std::size_t supersteps = 0, large = 0, moved = 0;
  for (auto _ : state)
  {
    supersteps = large = 0;
    const auto t0 = std::chrono::steady_clock::now();
    d.begin_frame();
    d.move_vertex(grasp, pull);
    d.end_superstep();
    for (;;)
    {
      const auto t1 = std::chrono::steady_clock::now();
      const SuperstepKey key = d.pending();
      const auto t2 = std::chrono::steady_clock::now();
      pending += std::chrono::duration<double>(t2 - t1).count();
      if (key == SuperstepQueue::none)
        break;
      const std::size_t entries = d.superstep(key);
      const auto t3 = std::chrono::steady_clock::now();
      d.end_superstep();
      step += std::chrono::duration<double>(t3 - t2).count();
      end += seconds_since(t3);
      ++supersteps;
      if (entries >= threshold)
      {
        above += seconds_since(t2);
        ++large;
      }
    }
    total += seconds_since(t0);
    moved = d.moved().size();
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(moved);
  state.counters["supersteps"] = double(supersteps);
  state.counters["large_supersteps"] = double(large);
  state.counters["threaded_share"] = above / total;
  state.counters["ms"] = 1e3 * total / n;
  state.counters["step_ms"] = 1e3 * step / n;
  state.counters["end_ms"] = 1e3 * end / n;
  state.counters["pending_ms"] = 1e3 * pending / n;
  state.SetLabel(std::string(queue_name(queue)) + ", " + std::to_string(d.threads()) + " threads" +
                 (paint == 1 ? ", brush" : ", tiles"));
}
} // namespace

BENCHMARK(BM_ThreadedFrame)
  ->ArgsProduct({ { 0, 2 }, { 1, 2, 0 }, { 1000, 300, 100, 30 }, { 0 } })
  ->ArgsProduct({ { 0 }, { 2 }, { 1000, 300 }, { 256, 4096 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_Interleaved)
  ->ArgsProduct({ { 0, 2 }, { 1000, 300, 100, 30 }, { 0 }, { 0, 1 } })
  ->ArgsProduct({ { 0 }, { 1000, 300, 100, 30 }, { 128, 256, 512, 1024, 4096 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(1.0);
BENCHMARK(BM_SuperstepShare)
  ->ArgsProduct({ { 0, 2 }, { 1000, 300, 100, 30 }, { 1, 2 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

BENCHMARK_MAIN();
