// Per-update cost through vtkChainMailDeformationFilter when only Displacement changes:
// a ~1,000-vertex grasp on a 40,000-vertex and on a 4,000,000-vertex surface must cost
// the same (adjacency and rest state cached, only moved vertices rewritten).
// BM_RealDemVsTextbook/<queue>/<displaced>: the core frame on a real DEM (matplotlib's
// Jacksboro fault zone, 344 x 403, read by vtkNpzDEMReader, in UTM metres) painted with
// the Smooth brush (bench::brush_painted), against the naive ChainMail and the textbook
// FIFO-preserving priority queue (vs_reference.h), grasped at the middle vertex.
#include "bench_scenes.h"
#include "vs_reference.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkNpzDEMReader.h"
#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

namespace
{
// The same triangulation as geoshaping::testing::triangle_grid, float points.
vtkSmartPointer<vtkPolyData> Grid(vtkIdType n)
{
  return geoshaping::testing::TriangleGridPolyData(int(n), int(n), 1.0, nullptr, VTK_FLOAT);
}

double PullForThousand()
{
  static const double pull = []
  {
    auto mesh = geoshaping::testing::triangle_grid(200, 200, 1.0);
    geoshaping::ChainMailDeformer d;
    d.set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
    return geoshaping::bench::pull_for_count(d, 100 * 200 + 100, 1000);
  }();
  return pull;
}

// The timed updates: the first builds the adjacency and rest state, untimed; then two
// pulls alternate so every update really recomputes and rewrites.
// `after` runs after each timed update.
template<class After = void (*)()>
void Drag(
  vtkChainMailDeformationFilter* filter, double pull, benchmark::State& state, After after = [] {})
{
  filter->SetDisplacement(0, 0, pull);
  filter->Update();
  int k = 0;
  for (auto _ : state)
  {
    filter->SetDisplacement(0, 0, (++k & 1) ? pull : 0.999 * pull);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetPoints());
    after();
  }
}

// The filter on an n x n grid, grasped at the centre vertex.
vtkSmartPointer<vtkChainMailDeformationFilter> CentreGrasp(vtkIdType n)
{
  auto filter = vtkSmartPointer<vtkChainMailDeformationFilter>::New();
  filter->SetInputData(Grid(n));
  filter->SetGraspPointId((n / 2) * n + n / 2);
  return filter;
}

void BM_FilterUpdate(benchmark::State& state)
{
  const vtkIdType n = state.range(0);
  auto filter = CentreGrasp(n);
  const double pull = PullForThousand();
  Drag(filter, pull, state);
  state.counters["mesh_vertices"] = double(n * n);
  state.counters["displaced"] = double(filter->GetNumberOfDisplacedPoints());
  state.counters["rebuilds"] = double(filter->GetNumberOfRebuilds());
}

// The same with the passes after the frame (4 refinement sweeps, 2 relaxation sweeps) on
// the 40,000-vertex surface: what the frame, the passes' write-back and their statistics
// cost through the filter.
void BM_FilterUpdateWithPasses(benchmark::State& state)
{
  auto filter = CentreGrasp(200);
  filter->SetRefinementSolver(vtkChainMailDeformationFilter::REFINEMENT_DYKSTRA); // 4 sweeps
  filter->SetRefinementIterations(int(state.range(0)));
  filter->SetRelaxationIterations(int(state.range(1)));
  const double pull = PullForThousand();
  Drag(filter, pull, state);
  state.counters["displaced"] = double(filter->GetNumberOfDisplacedPoints());
  state.counters["refined"] = double(filter->GetNumberOfRefinedPoints());
  state.counters["relaxed"] = double(filter->GetNumberOfRelaxedPoints());
}

// A large grasp with lighting: ~88,000 of 1,000,000 vertices displaced on a surface with
// point normals (docs/rendering.md's 1M row), so the update also recomputes the normals of
// the moved vertices and their one ring.
void BM_FilterUpdateLargeGraspWithNormals(benchmark::State& state)
{
  const vtkIdType n = 1000;
  auto grid = Grid(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n * n);
  for (vtkIdType i = 0; i < n * n; ++i)
    normals->SetTuple3(i, 0.0, 0.0, 1.0);
  grid->GetPointData()->SetNormals(normals);
  const vtkIdType grasp = (n / 2) * n + n / 2;
  static const double pull = []
  {
    auto mesh = geoshaping::testing::triangle_grid(1000, 1000, 1.0);
    geoshaping::ChainMailDeformer d;
    d.set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
    return geoshaping::bench::pull_for_count(d, 500 * 1000 + 500, 88000);
  }();
  vtkNew<vtkChainMailDeformationFilter> filter;
  filter->SetInputData(grid);
  filter->SetGraspPointId(grasp);
  Drag(filter, pull, state);
  state.counters["displaced"] = double(filter->GetNumberOfDisplacedPoints());
  state.counters["core_ms"] = filter->GetLastDeformationMilliseconds();
}
// Threads through the filter, as ParaView runs it: BM_FilterThreads/<NumberOfThreads>, a
// FIFO drag of 459,841 displaced on the 1,000,000-vertex grid, NumberOfThreads 1 (one
// thread) or 0 (every core while they are free, the default), for farm-bench to time
// beside a spinning core (docs/benchmarks.md, "Threads through the filter").
// `threaded_updates`: the share of updates whose frame ran a threaded superstep.
void BM_FilterThreads(benchmark::State& state)
{
  auto filter = CentreGrasp(1000);
  filter->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO);
  filter->SetNumberOfThreads(int(state.range(0)));
  double threaded = 0.0;
  Drag(filter, 120.0, state,
    [&] { threaded += filter->GetLastFrameThreadedSupersteps() > 0 ? 1.0 : 0.0; });
  state.counters["displaced"] = double(filter->GetNumberOfDisplacedPoints());
  state.counters["threaded_updates"] = threaded / double(state.iterations());
  state.counters["core_ms"] = filter->GetLastDeformationMilliseconds();
}

// The settle pass (docs/editing.md, "Bounds once the shape settles"): a ~1,000-vertex pull
// on the 1,000,000-vertex surface, committed and released (the release frame lists its
// change as exact), then undone (exact again); with range(0) = 1 each settled output is
// asked for its bounds and coordinate ranges, as ParaView's data information asks, which
// is where the pass over every point runs. The difference of the two rows is its cost.
void BM_ReleaseAndUndoOnLargeSurface(benchmark::State& state)
{
  const vtkIdType n = 1000;
  auto grid = Grid(n);
  vtkNew<vtkChainMailDeformationFilter> filter;
  filter->SetInputData(grid);
  const vtkIdType grasp = (n / 2) * n + n / 2;
  const double pull = PullForThousand();
  filter->Update();
  const bool query = state.range(0) != 0;
  double sink = 0.0;
  auto settled = [&]
  {
    filter->Update();
    if (query)
    {
      vtkPoints* points = filter->GetOutput()->GetPoints();
      double b[6], r[2];
      filter->GetOutput()->GetBounds(b);
      for (int c = 0; c < 3; ++c)
      {
        points->GetData()->GetRange(r, c);
        sink += r[1];
      }
      points->GetData()->GetRange(r, -1);
      sink += b[5] + r[1];
    }
  };
  for (auto _ : state)
  {
    filter->SetGraspPointId(grasp);
    filter->SetDisplacement(0, 0, pull);
    filter->Update(); // the drag frame
    filter->CommitEdit();
    filter->SetGraspPointId(-1);
    filter->SetDisplacement(0, 0, 0);
    settled(); // the release
    filter->UndoEdit();
    settled(); // the undo
  }
  benchmark::DoNotOptimize(sink);
  state.counters["rebuilds"] = double(filter->GetNumberOfRebuilds());
}

// A new filter's first update on an n x n double grid, no grasp yet (a DEM surface as
// DEMSurface gives it): the adjacency, the deformer's layout, the coordinate ids and the
// output's points (docs/benchmarks.md, "The first grasp on a big DEM").
void BM_FirstUpdateOnLargeSurface(benchmark::State& state)
{
  const int n = int(state.range(0));
  auto grid = geoshaping::testing::TriangleGridPolyData(n, n, 1.0, nullptr, VTK_DOUBLE);
  for (auto _ : state)
  {
    vtkNew<vtkChainMailDeformationFilter> filter;
    filter->SetInputData(grid);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetPoints());
  }
  state.counters["mesh_vertices"] = double(n) * n;
}
} // namespace

void BM_RealDemVsTextbook(benchmark::State& state)
{
  struct DemScene
  {
    std::vector<double> xyz;
    geoshaping::Adjacency adjacency;
    std::vector<float> m;
    geoshaping::ChainMailDeformer core;
    std::unique_ptr<geoshaping::bench::NaiveChainMail> naive;
    geoshaping::index_t grasp = 0;
    double pull = 0.0;
  };
  static std::map<std::size_t, std::unique_ptr<DemScene>> cache;
  const std::size_t target = std::size_t(state.range(1));
  std::unique_ptr<DemScene>& s = cache[target];
  if (!s)
  {
    vtkNew<vtkNpzDEMReader> reader;
    reader->SetFileName("/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz");
    reader->Update();
    vtkPolyData* dem = reader->GetOutput();
    if (dem->GetNumberOfPoints() == 0)
    {
      state.SkipWithError("the Jacksboro DEM (python-matplotlib-data) is not installed");
      return;
    }
    s = std::make_unique<DemScene>();
    vtkIdType skipped = 0, bad = 0;
    vtkGeoShapingAdapter::PointsAsDouble(dem->GetPoints(), s->xyz, bad);
    s->adjacency = vtkGeoShapingAdapter::BuildAdjacency(dem, skipped);
    double b[6];
    dem->GetBounds(b);
    const double size = std::min(b[1] - b[0], b[3] - b[2]);
    const auto n = geoshaping::index_t(dem->GetNumberOfPoints());
    s->m = geoshaping::bench::brush_painted(s->xyz.data(), n, s->adjacency, b[0], b[2], size);
    s->core.set_mesh(s->xyz.data(), n, s->adjacency);
    s->core.set_malleability(s->m.data());
    s->naive = std::make_unique<geoshaping::bench::NaiveChainMail>(
      s->xyz.data(), s->adjacency, s->m.data(), s->core.transfer_function());
    s->grasp = n / 2;
    s->pull = geoshaping::bench::pull_for_count(s->core, s->grasp, target);
  }
  s->core.set_queue(static_cast<geoshaping::QueueKind>(state.range(0)));
  geoshaping::bench::time_against_references(
    state, s->core, *s->naive, s->grasp, s->pull, "Jacksboro DEM, brush paint");
}

BENCHMARK(BM_FirstUpdateOnLargeSurface)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ReleaseAndUndoOnLargeSurface)
  ->Arg(0)
  ->Arg(1)
  ->Unit(benchmark::kMillisecond)
  ->MinTime(1.0);
BENCHMARK(BM_FilterUpdate)->Arg(200)->Arg(2000)->Unit(benchmark::kMicrosecond)->MinTime(0.5);
BENCHMARK(BM_FilterThreads)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_FilterUpdateWithPasses)
  ->Args({ 4, 0 })
  ->Args({ 4, 2 })
  ->Unit(benchmark::kMicrosecond)
  ->MinTime(0.5);
BENCHMARK(BM_FilterUpdateLargeGraspWithNormals)->Unit(benchmark::kMillisecond)->MinTime(1.0);

BENCHMARK(BM_RealDemVsTextbook)
  ->ArgsProduct({ { 0, 2 }, { 3000, 10000, 30000, 100000 } })
  ->Unit(benchmark::kMillisecond)
  ->MinTime(0.5);

BENCHMARK_MAIN();
