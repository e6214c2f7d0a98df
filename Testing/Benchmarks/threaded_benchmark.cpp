// The threaded frame (threaded_chainmail.h) against the one-thread frame at 1,000,000
// displaced on a 1600 x 1600 painted grid (bench::painted_grid, 8 bands), centre grasp.
//
// BM_ThreadedFrame/<queue>/<threads>/<mode>, queue 0 FIFO or 2 FIFO Priority:
//   mode 0: one-thread and threaded frames interleaved in one loop (one, threaded, one,
//     ...), wall clock each: `one_ms`, `threaded_ms`, `speedup` = one / threaded;
//   mode 1: only frames on `threads` threads (1: the one-thread frame), for farm-bench
//     to time whole processes A B A B (docs/benchmarks.md, "Threaded frame").
// Counters: displaced, supersteps and rounds (synchronisations) per frame, and whether
// the frames ran threaded. The threshold is forced to 0 so every frame after the first
// runs threaded; the pieces are built before the timed loop.
#include "bench_scenes.h"
#include "geoshaping/parallel/thread_clock.h"
#include "geoshaping/parallel/threaded_chainmail.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>

using namespace geoshaping;

namespace
{
constexpr index_t side = 1600;

struct Scene
{
  ChainMailDeformer deformer;
  index_t grasp = (side / 2) * side + side / 2;
};

Scene& scene()
{
  static std::unique_ptr<Scene> s;
  if (!s)
  {
    s = std::make_unique<Scene>();
    std::vector<float> m;
    auto mesh = bench::painted_grid(side, m);
    s->deformer.set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
    s->deformer.set_malleability(m.data());
  }
  return *s;
}

// The pulls that displace 1,000,000 vertices (bisection on the pull, as
// bench::pull_for_count, done once: 999,999 and 1,000,000 at the bracket's two ends).
double pull_for(QueueKind q)
{
  return q == QueueKind::fifo ? 207.65000081081979 : 241.81000547111037;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void BM_ThreadedFrame(benchmark::State& state)
{
  const auto queue = static_cast<QueueKind>(state.range(0));
  const int threads = int(state.range(1));
  const bool interleaved = state.range(2) == 0;
  Scene& s = scene();
  s.deformer.set_queue(queue);
  const Eigen::Vector3d d(0.0, 0.0, pull_for(queue));
  ThreadedChainMail one, many;
  one.set_threads(1);
  many.set_threads(threads);
  many.set_threshold(0);
  many.set_per_superstep(0.0);
  many.deform(s.deformer, s.grasp, d); // the prediction
  many.deform(s.deformer, s.grasp, d); // builds the pieces
  double one_s = 0.0, many_s = 0.0, one_cpu = 0.0, many_cpu = 0.0;
  FrameResult r;
  for (auto _ : state)
  {
    if (interleaved)
    {
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = thread_cpu_seconds();
      r = one.deform(s.deformer, s.grasp, d);
      one_cpu += thread_cpu_seconds() - c0;
      one_s += seconds_since(t0);
    }
    const auto t1 = std::chrono::steady_clock::now();
    r = many.deform(s.deformer, s.grasp, d);
    many_s += seconds_since(t1);
    if (many.last_threaded())
      many_cpu += *std::max_element(many.thread_seconds().begin(), many.thread_seconds().end());
    benchmark::DoNotOptimize(r.moved);
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(r.moved);
  state.counters["supersteps"] = double(many.supersteps());
  state.counters["rounds"] = double(many.rounds());
  state.counters["threaded"] = many.last_threaded();
  state.counters["threaded_ms"] = 1e3 * many_s / n;
  if (interleaved)
  {
    state.counters["one_ms"] = 1e3 * one_s / n;
    state.counters["speedup"] = one_s / many_s;
    state.counters["one_cpu_ms"] = 1e3 * one_cpu / n;
    state.counters["max_thread_cpu_ms"] = 1e3 * many_cpu / n;
    state.counters["cpu_model_speedup"] = one_cpu / many_cpu;
  }
  state.SetLabel(std::string(queue_name(queue)) + ", " + std::to_string(threads) + " threads");
}
} // namespace

BENCHMARK(BM_ThreadedFrame)
  ->ArgsProduct({ { 0, 2 }, { 2 }, { 0 } })
  ->ArgsProduct({ { 0, 2 }, { 1, 2 }, { 1 } })
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->MinTime(0.5);

BENCHMARK_MAIN();
