// Per-frame cost of the ChainMail core for each candidate queue at the paper's Table 1
// displaced-vertex counts and at 1,000,000, the bare BFS floor over the same region,
// and a 1,000-vertex grasp on a 4,000,000-vertex mesh. BM_Frame's last argument is the
// valid-region shape (0 Axes, the paper's box; 1 Link, the rotation-invariant cylinder);
// each frame's pull is calibrated on its own to displace the target count.
// BM_Relaxation: the relaxation pass after a frame, timed interleaved with the frame
// itself (frame, pass, frame, pass, ...) so the ratio is not skewed by load drifting
// between two separate runs.
// BM_FrameObstacle: the FIFO Priority frame at the paper's scale (29,241 displaced)
// without obstacles (0), against a dipping fault of 100,352 triangles through the
// displaced region (1: it stops the vertices beyond it) and the same fault out of reach
// (2: the gate's queries alone); BM_ObstacleBuild: the fault's tree, built once per
// obstacle geometry.
// BM_CoreVsNaive: the core's FIFO / FIFO Priority frame against the naive reference
// (naive_chainmail.h, FIFO / FIFO-PQ) and, for FIFO Priority, the textbook
// FIFO-preserving priority queue, on one 1001 x 1001 grid painted in tiles (last argument
// 0, the friendly case) or with the Smooth brush (1, the real case), 10^3 to 10^6
// displaced, timed interleaved (core, naive, textbook, core, ...) in thread CPU time:
// `speedup` = naive / core, `vs_textbook` = textbook / core.
// BM_Envelope: the envelope refinement (ProjectionSolver::envelope, Axes) after the FIFO
// Priority frame at the paper's scale, timed the same way (frame, envelope, frame, ...), in
// a drag and on a grasp's first frame.
#include "bench_scenes.h"
#include "geoshaping/parallel/thread_clock.h"
#include "geoshaping/passes/link_projection.h"
#include "geoshaping/passes/relaxation.h"
#include "geoshaping/scenes/sample_scenes.h"
#include "naive_chainmail.h"
#include "test_sheets.h"
#include "vs_reference.h"

#include <benchmark/benchmark.h>

#include <chrono>

#include <map>
#include <memory>
#include <string>
#include <tuple>

using namespace geoshaping;

namespace
{
struct Scene
{
  std::unique_ptr<ChainMailDeformer> deformer;
  index_t grasp;
  double pull;
};

// Scenes are built once per (mesh side, target, frame) and shared by the queues.
Scene& scene(index_t side, std::size_t target, ValidRegionFrame frame = ValidRegionFrame::axes)
{
  static std::map<std::tuple<index_t, std::size_t, ValidRegionFrame>, Scene> cache;
  auto it = cache.find({ side, target, frame });
  if (it != cache.end())
    return it->second;
  std::vector<float> m;
  auto mesh = bench::painted_grid(side, m);
  auto d = std::make_unique<ChainMailDeformer>();
  d->set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
  d->set_malleability(m.data());
  d->set_valid_region_frame(frame);
  const index_t grasp = (side / 2) * side + side / 2;
  const double pull = bench::pull_for_count(*d, grasp, target);
  return cache[{ side, target, frame }] = Scene{ std::move(d), grasp, pull };
}

index_t side_for(std::size_t target)
{
  return target > 100000 ? 1600 : (target > 5000 ? 400 : 2000);
}

void BM_Frame(benchmark::State& state)
{
  const auto queue = static_cast<QueueKind>(state.range(0));
  const std::size_t target = std::size_t(state.range(1));
  const index_t side = state.range(2) ? index_t(state.range(2)) : side_for(target);
  const auto frame = static_cast<ValidRegionFrame>(state.range(3));
  Scene& s = scene(side, target, frame);
  s.deformer->set_queue(queue);
  FrameResult r;
  for (auto _ : state)
  {
    r = s.deformer->deform(s.grasp, { 0.0, 0.0, s.pull });
    benchmark::DoNotOptimize(r.moved);
  }
  state.counters["displaced"] = double(r.moved);
  state.counters["mesh_vertices"] = double(s.deformer->size());
  state.counters["bytes_per_vertex"] =
    double(s.deformer->memory_bytes()) / double(s.deformer->size());
  state.SetLabel(std::string(queue_name(queue)) + " " + frame_name(frame));
}

void BM_BfsFloor(benchmark::State& state)
{
  const std::size_t target = std::size_t(state.range(1));
  Scene& s = scene(side_for(target), target);
  s.deformer->set_queue(QueueKind::fifo_priority);
  s.deformer->deform(s.grasp, { 0.0, 0.0, s.pull });
  const std::vector<std::uint8_t> region = bench::moved_mask(*s.deformer);
  std::vector<std::uint32_t> mark(std::size_t(s.deformer->size()), 0);
  std::vector<index_t> queue;
  std::uint32_t stamp = 0;
  std::size_t visited = 0;
  for (auto _ : state)
  {
    visited = bench::bfs_floor(s.deformer->adjacency(), s.grasp, region, mark, ++stamp, queue);
    benchmark::DoNotOptimize(visited);
  }
  state.counters["displaced"] = double(visited);
  state.SetLabel("BFS floor");
}

// Figure 5D's scene: the painted fault step, grasped mid-step (FIFO Priority, lift 10);
// its triangles for the bending measure.
Scene& fault_step(const SampleMesh** triangles = nullptr)
{
  static Scene s;
  static SampleMesh mesh;
  if (triangles)
    *triangles = &mesh;
  if (s.deformer)
    return s;
  const FaultStepParams p;
  mesh = fault_step_horizon(p);
  const std::vector<float> m = fault_step_malleability(mesh, p);
  s.deformer = std::make_unique<ChainMailDeformer>();
  s.deformer->set_mesh(mesh.xyz.data(), mesh.num_points(), mesh.adjacency());
  s.deformer->set_malleability(m.data());
  const Eigen::Vector3d at(50.0, 30.0, 10.0);
  s.grasp = 0;
  for (index_t v = 0; v < mesh.num_points(); ++v)
    if ((Eigen::Vector3d(mesh.xyz.data() + 3 * v) - at).squaredNorm() <
        (Eigen::Vector3d(mesh.xyz.data() + 3 * s.grasp) - at).squaredNorm())
      s.grasp = v;
  s.pull = 10.0;
  return s;
}

// E_link (over the relaxed region) and, on a triangle mesh, the bending of the soft
// vertices displaced before or after, of the frame and of its relaxation: counters.
void quality(benchmark::State& state, const LinkMesh& links, const ChainMailDeformer& d,
  const Relaxer& r, const SampleMesh* triangles)
{
  std::vector<index_t> region = d.moved();
  region.insert(region.end(), r.changed().begin(), r.changed().end());
  const Displacements before = displacements(d);
  state.counters["elink_before"] = link_error(links, before, region);
  state.counters["elink_after"] = link_error(links, r.displacements(), region);
  if (!triangles)
    return;
  std::vector<index_t> soft;
  std::vector<std::uint8_t> seen(std::size_t(links.size()), 0);
  for (index_t v : region)
    if (!links.rigid[std::size_t(v)] && !seen[std::size_t(v)])
    {
      seen[std::size_t(v)] = 1;
      soft.push_back(v);
    }
  std::vector<Eigen::Vector3d> rest(std::size_t(links.size()));
  for (index_t v = 0; v < links.size(); ++v)
    rest[std::size_t(v)] = Eigen::Vector3d(triangles->xyz.data() + 3 * v);
  const BendingError b0 = bending_error(rest, triangles->connectivity, before, soft);
  const BendingError b1 = bending_error(rest, triangles->connectivity, r.displacements(), soft);
  state.counters["bend_max_before"] = b0.max;
  state.counters["bend_max_after"] = b1.max;
  state.counters["bend_rms_before"] = b0.rms;
  state.counters["bend_rms_after"] = b1.rms;
}

// Arguments: displaced target (0: the fault step), sweeps.
void BM_Relaxation(benchmark::State& state)
{
  const std::size_t target = std::size_t(state.range(0));
  const int sweeps = int(state.range(1));
  const SampleMesh* triangles = nullptr;
  Scene& s = target == 0 ? fault_step(&triangles) : scene(side_for(target), target);
  s.deformer->set_queue(QueueKind::fifo_priority);
  const LinkMesh links = link_mesh(*s.deformer);
  Relaxer relaxer(links);
  using clock = std::chrono::steady_clock;
  double frame_s = 0.0, relax_s = 0.0;
  RelaxationReport report;
  FrameResult r;
  for (auto _ : state)
  {
    const auto t0 = clock::now();
    r = s.deformer->deform(s.grasp, { 0.0, 0.0, s.pull });
    const auto t1 = clock::now();
    report = relax_frame(relaxer, *s.deformer, s.grasp, sweeps);
    const auto t2 = clock::now();
    frame_s += std::chrono::duration<double>(t1 - t0).count();
    relax_s += std::chrono::duration<double>(t2 - t1).count();
    benchmark::DoNotOptimize(report.updates);
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(r.moved);
  state.counters["frame_ms"] = 1e3 * frame_s / n;
  state.counters["relax_ms"] = 1e3 * relax_s / n;
  state.counters["relax_over_frame"] = relax_s / frame_s;
  state.counters["sweeps_run"] = report.iterations;
  state.counters["relaxed"] = double(relaxer.changed().size());
  quality(state, links, *s.deformer, relaxer, triangles);
  state.SetLabel(target == 0 ? "fault step" : "painted grid");
}

// Arguments: displaced target; 0 a drag (the projector kept across iterations, as the
// filter keeps it) or 1 a grasp's first frame (a fresh projector each iteration,
// allocated untimed as the filter does once per link data: the link cache is empty).
// The envelope's thread CPU time and its ratio to the frame's (the target: envelope +
// frame within 10x the frame), E_link after, vertices changed.
void BM_Envelope(benchmark::State& state)
{
  const std::size_t target = std::size_t(state.range(0));
  const bool first_frame = state.range(1) != 0;
  Scene& s = scene(side_for(target), target);
  s.deformer->set_queue(QueueKind::fifo_priority);
  const LinkMesh links = link_mesh(*s.deformer);
  auto projector = std::make_unique<LinkProjector>(links);
  ProjectionOptions options;
  options.solver = ProjectionSolver::envelope;
  options.tolerance = 1e-6;
  options.max_iterations = 1;
  double frame_s = 0.0, envelope_s = 0.0;
  ProjectionReport report;
  FrameResult r;
  for (auto _ : state)
  {
    if (first_frame)
    {
      state.PauseTiming();
      projector = std::make_unique<LinkProjector>(links);
      state.ResumeTiming();
    }
    const double t0 = thread_cpu_seconds();
    r = s.deformer->deform(s.grasp, { 0.0, 0.0, s.pull });
    const double t1 = thread_cpu_seconds();
    report = refine_links(*projector, *s.deformer, s.grasp, options);
    const double t2 = thread_cpu_seconds();
    frame_s += t1 - t0;
    envelope_s += t2 - t1;
    benchmark::DoNotOptimize(report.violation);
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(r.moved);
  state.counters["frame_ms"] = 1e3 * frame_s / n;
  state.counters["envelope_ms"] = 1e3 * envelope_s / n;
  state.counters["total_over_frame"] = (frame_s + envelope_s) / frame_s;
  state.counters["elink_after"] =
    link_error(links, projector->displacements(), projector->region());
  state.counters["changed"] = double(projector->changed().size());
  state.SetLabel(
    std::string("FIFO Priority Axes + envelope") + (first_frame ? ", first frame" : ""));
}

// The fault x = x0 + 0.5 z over y in [-10, 410], z in [-100, 100]: 2 x 224^2 triangles.
geoshaping::testing::Sheet fault(double x0)
{
  return geoshaping::testing::sheet(224, Eigen::Vector3d(x0 - 50.0, -10.0, -100.0),
    Eigen::Vector3d(0.0, 420.0, 0.0), Eigen::Vector3d(100.0, 0.0, 200.0));
}

void BM_FrameObstacle(benchmark::State& state)
{
  const long mode = state.range(0);
  // The 400 x 400 grid grasped at (200, 200): the frame reaches x in about [104, 296].
  Scene& s = scene(400, 29241);
  s.deformer->set_queue(QueueKind::fifo_priority);
  s.deformer->clear_obstacles();
  if (mode > 0)
  {
    const auto f = fault(mode == 1 ? 240.0 : 1000.0);
    const std::string error =
      s.deformer->set_obstacles(f.xyz.data(), f.points(), f.tri.data(), f.triangles());
    if (!error.empty())
      state.SkipWithError(error.c_str());
  }
  FrameResult r;
  for (auto _ : state)
  {
    r = s.deformer->deform(s.grasp, { 0.0, 0.0, s.pull });
    benchmark::DoNotOptimize(r.moved);
  }
  s.deformer->clear_obstacles();
  state.counters["displaced"] = double(r.moved);
  state.counters["blocked"] = double(r.blocked);
  state.counters["obstacle_triangles"] = mode > 0 ? 224.0 * 224.0 * 2.0 : 0.0;
  state.SetLabel(mode == 0   ? "no obstacle"
                 : mode == 1 ? "fault through the region"
                             : "fault out of reach");
}

void BM_ObstacleBuild(benchmark::State& state)
{
  const auto f = fault(240.0);
  Obstacles o;
  for (auto _ : state)
  {
    const std::string error =
      o.set(f.xyz.data(), f.points(), f.tri.data(), f.triangles(), Eigen::Vector3d::Zero());
    benchmark::DoNotOptimize(error);
  }
  state.counters["obstacle_triangles"] = double(o.size());
  state.counters["bytes"] = double(o.memory_bytes());
}

void BM_CoreVsNaive(benchmark::State& state)
{
  struct NaiveScene
  {
    geoshaping::testing::Mesh mesh;
    std::vector<float> m;
    ChainMailDeformer core;
    std::unique_ptr<bench::NaiveChainMail> naive;
    index_t grasp = 0;
    double pull = 0.0;
  };
  static std::map<std::pair<std::size_t, bool>, std::unique_ptr<NaiveScene>> cache;
  const auto queue = static_cast<QueueKind>(state.range(0));
  const std::size_t target = std::size_t(state.range(1));
  const bool brush = state.range(2) != 0;
  std::unique_ptr<NaiveScene>& s = cache[{ target, brush }];
  if (!s)
  {
    constexpr index_t side = 1001;
    s = std::make_unique<NaiveScene>();
    s->mesh = bench::painted_grid(side, s->m);
    if (brush)
      s->m = bench::brush_painted(
        s->mesh.xyz.data(), s->mesh.size(), s->mesh.adjacency, 0.0, 0.0, side - 1.0);
    s->core.set_mesh(s->mesh.xyz.data(), s->mesh.size(), s->mesh.adjacency);
    s->core.set_malleability(s->m.data());
    s->naive = std::make_unique<bench::NaiveChainMail>(
      s->mesh.xyz.data(), s->mesh.adjacency, s->m.data(), s->core.transfer_function());
    s->grasp = (side / 2) * side + side / 2;
    s->pull = bench::pull_for_count(s->core, s->grasp, target);
  }
  s->core.set_queue(queue);
  bench::time_against_references(
    state, s->core, *s->naive, s->grasp, s->pull, brush ? "brush paint" : "tiles");
}

void TableArgs(benchmark::internal::Benchmark* b)
{
  for (int q = 0; q < 4; ++q)
    for (long n : { 9152L, 14088L, 17289L, 18225L, 29241L, 1000000L })
      b->Args({ q, n, 0, 0 });
  for (int q = 0; q < 4; ++q)
    for (long n : { 9152L, 29241L })
      b->Args({ q, n, 0, 1 });
  // A 1,000-vertex grasp on a 4,000,000-vertex mesh: the frame ignores the mesh size.
  b->Args({ 2, 1000, 2000, 0 });
  b->Args({ 2, 1000, 200, 0 });
}
} // namespace

BENCHMARK(BM_Frame)->Apply(TableArgs)->Unit(benchmark::kMillisecond)->MinTime(0.2);
BENCHMARK(BM_BfsFloor)
  ->ArgsProduct({ { 0 }, { 9152, 14088, 17289, 18225, 29241, 1000000 } })
  ->Unit(benchmark::kMillisecond)
  ->MinTime(0.2);

BENCHMARK(BM_CoreVsNaive)
  ->ArgsProduct({ { 0, 2 }, { 1000, 3000, 10000, 30000, 100000, 300000, 1000000 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->MinTime(0.5);

BENCHMARK(BM_Relaxation)
  ->ArgsProduct({ { 0, 29241 }, { 1, 10, 100 } })
  ->Unit(benchmark::kMillisecond)
  ->MinTime(0.5);

BENCHMARK(BM_FrameObstacle)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->MinTime(0.2);
BENCHMARK(BM_ObstacleBuild)->Unit(benchmark::kMillisecond)->MinTime(0.2);

BENCHMARK(BM_Envelope)
  ->ArgsProduct({ { 9152, 29241 }, { 0, 1 } })
  ->Unit(benchmark::kMillisecond)
  ->MinTime(0.5);

BENCHMARK_MAIN();
