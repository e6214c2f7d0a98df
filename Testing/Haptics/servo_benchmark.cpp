// The servo loop with a simulated device while another thread keeps a CPU core busy the
// way the deformation does (the ChainMail deformer on a ~100k-vertex grid when the core
// test meshes are built, plain arithmetic otherwise) and publishes a scene per frame.
// Reports the servo rate and |period - 1 ms| percentiles as counters. Not a ctest:
//   geoshaping_haptics_benchmark --benchmark_counters_tabular=true
#include "geoshaping/haptics/servo_loop.h"
#include "geoshaping/haptics/simulated_device.h"

#ifdef GEOSHAPING_HAVE_CORE_MESHES
#include "geoshaping/deform/chainmail_deformer.h"
#include "test_meshes.h"
#endif

#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <thread>

using namespace geoshaping::haptics;

namespace
{

constexpr auto run_time = std::chrono::seconds(3);

// One "frame" of graphics-side work; returns something so it is not optimised away.
class Load
{
public:
  Load()
  {
#ifdef GEOSHAPING_HAVE_CORE_MESHES
    const auto mesh = geoshaping::testing::triangle_grid(317, 317, 1.0);
    deformer_.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
    // Rigid: every frame moves all ~100k vertices, the heaviest frame the deformer has.
    deformer_.set_uniform_malleability(0.0);
    grasp_ = geoshaping::testing::grid_id(317, 158, 158);
#endif
  }
  std::size_t frame(std::uint64_t n)
  {
    const double d = 40.0 * std::sin(0.05 * double(n));
#ifdef GEOSHAPING_HAVE_CORE_MESHES
    return deformer_.deform(grasp_, Eigen::Vector3d(0, 0, d)).moved;
#else
    double acc = d;
    for (int i = 0; i < 2000000; ++i)
      acc = std::sqrt(acc * acc + 1.0) - 0.5;
    return std::size_t(acc);
#endif
  }

private:
#ifdef GEOSHAPING_HAVE_CORE_MESHES
  geoshaping::ChainMailDeformer deformer_;
  geoshaping::index_t grasp_ = 0;
#endif
};

void fill_scene(SceneSnapshot& s, std::uint64_t seq)
{
  s.stamp = Clock::now();
  s.sequence = seq;
  s.grasping = true;
  s.grasp_anchor = Eigen::Vector3d::Zero();
  s.grasp_stiffness = 300.0;
  // A 16 x 16 patch of floor under the stylus: 512 triangles to test per tick.
  s.contact_triangles.clear();
  const double h = 0.01;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i)
    {
      const Eigen::Vector3d a(-0.08 + i * h, -0.08 + j * h, -0.001),
        b = a + Eigen::Vector3d(h, 0, 0), c = a + Eigen::Vector3d(h, h, 0),
        d = a + Eigen::Vector3d(0, h, 0);
      s.contact_triangles.insert(s.contact_triangles.end(), { a, b, c, a, c, d });
    }
}

void servo_under_load(benchmark::State& state)
{
  const bool loaded = state.range(0) != 0;
  ServoConfig config;
  config.realtime_priority = state.range(1) != 0 ? 80 : 0;
  bool realtime = false;
  std::uint64_t frames = 0;
  std::size_t moved = 0;
  PeriodSummary summary;
  for (auto _ : state)
  {
    SimulatedDevice device;
    ServoLoop loop(device, config);
    if (!loop.start())
    {
      state.SkipWithError(loop.error().c_str());
      return;
    }
    std::atomic<bool> stop{ false };
    std::thread graphics(
      [&]
      {
        Load load;
        while (!stop.load())
        {
          fill_scene(loop.scene_back(), frames + 1);
          loop.publish_scene();
          if (loaded)
            moved += load.frame(frames);
          else
            std::this_thread::sleep_for(std::chrono::milliseconds(16));
          ++frames;
        }
      });
    std::this_thread::sleep_for(run_time);
    stop.store(true);
    graphics.join();
    loop.stop();
    summary = loop.period_summary();
    realtime = loop.realtime();
  }
  benchmark::DoNotOptimize(moved);
  state.counters["servo_hz"] = summary.mean_rate_hz;
  state.counters["p50_us"] = summary.p50_jitter_us;
  state.counters["p99_us"] = summary.p99_jitter_us;
  state.counters["max_us"] = summary.max_jitter_us;
  state.counters["periods"] = double(summary.periods);
  state.counters["moved_per_frame"] = frames ? double(moved) / double(frames) : 0.0;
  state.counters["realtime"] = realtime ? 1.0 : 0.0;
  state.counters["load_fps"] = double(frames) / std::chrono::duration<double>(run_time).count();
}

} // namespace

BENCHMARK(servo_under_load)
  ->ArgNames({ "deforming", "fifo" })
  ->Args({ 0, 0 })
  ->Args({ 1, 0 })
  ->Args({ 1, 1 })
  ->Iterations(1)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();

BENCHMARK_MAIN();
