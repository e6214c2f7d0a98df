// The cost of one servo tick (ServoTick::tick: velocity filter, carry-over of the proxy
// to a new patch every 16 ticks, the proxy's sweeps, compute_force) on a realistic contact
// patch: the `patch` triangles nearest the stylus (keep_nearest, as the interactor sends
// them each frame; it sends at most 256) of a relief in 1 mm triangles, 6 x 6 cm: bumps
// of 2 mm and a fault step whose 45 degree ramp drops 5 mm. The stylus follows a fixed
// path of quantised positions (0.055 mm, 1 kHz), per `where`:
//   0 free:  5 mm above the relief, circling (one sweep, no triangle met);
//   1 face:  1.5 mm into the upper plateau, circling (one plane);
//   2 crest: 1.5 mm deep, sliding to and fro over the step's crest at 5 cm/s (the proxy
//            held and catching up, a change of plane every crossing);
//   3 fold:  1.5 mm deep at the ramp's foot, a concave fold (two planes).
// Counters: contact (fraction of ticks in contact), allocs (heap allocations per tick,
// counted by the replaced operator new below: the servo tick must make none). Not a ctest:
//   geoshaping_servo_tick_benchmark --benchmark_repetitions=3
#include "geoshaping/haptics/servo_tick.h"
#include "geoshaping/mesh/nearest_triangles.h"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

namespace
{
std::atomic<long> allocations{ 0 };
} // namespace

void* operator new(std::size_t n)
{
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1))
    return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}

using namespace geoshaping::haptics;

namespace
{
constexpr double pi = 3.14159265358979323846;
constexpr double quantum = 55e-6;

double relief(double x, double y)
{
  const double step = y < -0.0025 ? 0.0 : y > 0.0025 ? -0.005 : -(y + 0.0025);
  return step + 0.002 * std::sin(2 * pi * x / 0.04) * std::sin(2 * pi * y / 0.05);
}

std::vector<Eigen::Vector3d> relief_soup()
{
  std::vector<Eigen::Vector3d> s;
  const int n = 60;
  auto at = [](int i, int j)
  {
    const double x = -0.03 + 0.001 * i, y = -0.03 + 0.001 * j;
    return Eigen::Vector3d(x, y, relief(x, y));
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s.insert(s.end(),
        { at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1) });
  return s;
}

Eigen::Vector3d quantised(const Eigen::Vector3d& x)
{
  return (x / quantum).array().round() * quantum;
}

// One period of the stylus's path (1 ms a point) and the point the patch is centred on.
std::vector<Eigen::Vector3d> path_for(int where, Eigen::Vector3d& centre)
{
  std::vector<Eigen::Vector3d> path;
  const double depth = where == 0 ? -0.005 : 0.0015;
  auto below = [&](double x, double y) { return Eigen::Vector3d(x, y, relief(x, y) - depth); };
  switch (where)
  {
    case 0:
    case 1:
      centre = below(0.002, -0.012);
      for (int k = 0; k < 1000; ++k)
        path.push_back(below(0.002 + 0.002 * std::cos(2 * pi * k / 1000),
          -0.012 + 0.002 * std::sin(2 * pi * k / 1000)));
      break;
    case 2:
      centre = below(0.002, -0.0025);
      for (int k = 0; k < 200; ++k)
        path.push_back(below(0.002, -0.005 + 0.00005 * (k < 100 ? k : 200 - k)));
      break;
    default:
      centre = below(0.002, 0.0025);
      for (int k = 0; k < 1000; ++k)
        path.push_back(below(0.002 + 0.001 * std::sin(2 * pi * k / 1000), 0.0025));
      break;
  }
  for (auto& x : path)
    x = quantised(x);
  return path;
}

void BM_ServoTick(benchmark::State& state)
{
  const int where = int(state.range(0));
  Eigen::Vector3d centre;
  const std::vector<Eigen::Vector3d> path = path_for(where, centre);
  SceneSnapshot scene;
  scene.contact_triangles = relief_soup();
  geoshaping::keep_nearest(scene.contact_triangles, centre, std::size_t(state.range(1)));
  scene.stamp = Clock::now(); // and every tick at that instant: never stale
  scene.sequence = 1;
  const DeviceLimits limits;
  ServoTick servo;
  DeviceSample sample;
  // From 1 cm above the path's start (the side the proxy stays on), then one period, so
  // the proxy is in its steady state when the timing starts.
  sample.position = path[0] + Eigen::Vector3d(0, 0, 0.01);
  servo.tick(sample, true, scene.stamp, scene, limits);
  std::size_t k = 1;
  for (; k <= path.size(); ++k)
  {
    sample.t = 0.001 * double(k);
    sample.position = path[k % path.size()];
    servo.tick(sample, true, scene.stamp, scene, limits);
  }
  long contacts = 0;
  const long before = allocations.load();
  for (auto _ : state)
  {
    sample.t = 0.001 * double(k);
    sample.position = path[k % path.size()];
    if (k % 16 == 0)
      ++scene.sequence; // a new patch: the proxy is carried over
    const ForceResult r = servo.tick(sample, true, scene.stamp, scene, limits);
    benchmark::DoNotOptimize(r.force.data());
    contacts += r.in_contact;
    ++k;
  }
  const double ticks = double(state.iterations());
  state.counters["allocs"] = double(allocations.load() - before) / ticks;
  state.counters["contact"] = double(contacts) / ticks;
  state.counters["triangles"] = double(scene.contact_triangles.size() / 3);
}
} // namespace

BENCHMARK(BM_ServoTick)
  ->ArgNames({ "where", "patch" })
  ->ArgsProduct({ { 0, 1, 2, 3 }, { 128, 256, 512 } });

BENCHMARK_MAIN();
