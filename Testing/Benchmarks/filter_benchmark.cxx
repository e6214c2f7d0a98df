// Per-update cost through vtkChainMailDeformationFilter when only Displacement changes:
// a ~1,000-vertex grasp on a 40,000-vertex and on a 4,000,000-vertex surface must cost
// the same (adjacency and rest state cached, only moved vertices rewritten).
#include "bench_scenes.h"
#include "vtkChainMailDeformationFilter.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <benchmark/benchmark.h>

namespace
{
// The same triangulation as geoshaping::testing::triangle_grid, as vtkPolyData.
vtkSmartPointer<vtkPolyData> Grid(vtkIdType n)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataType(VTK_FLOAT);
  pts->SetNumberOfPoints(n * n);
  for (vtkIdType j = 0; j < n; ++j)
    for (vtkIdType i = 0; i < n; ++i)
      pts->SetPoint(j * n + i, double(i), double(j), 0.0);
  vtkNew<vtkCellArray> tris;
  tris->AllocateExact(2 * (n - 1) * (n - 1), 6 * (n - 1) * (n - 1));
  for (vtkIdType j = 0; j + 1 < n; ++j)
    for (vtkIdType i = 0; i + 1 < n; ++i)
    {
      const vtkIdType a = j * n + i, c = a + 1, d = a + n + 1, e = a + n;
      const vtkIdType t0[3] = { a, c, d }, t1[3] = { a, d, e };
      tris->InsertNextCell(3, t0);
      tris->InsertNextCell(3, t1);
    }
  pd->SetPoints(pts);
  pd->SetPolys(tris);
  return pd;
}

double PullForThousand()
{
  static const double pull = [] {
    auto mesh = geoshaping::testing::triangle_grid(200, 200, 1.0);
    geoshaping::ChainMailDeformer d;
    d.set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
    return geoshaping::bench::pull_for_count(d, 100 * 200 + 100, 1000);
  }();
  return pull;
}

void BM_FilterUpdate(benchmark::State& state)
{
  const vtkIdType n = state.range(0);
  auto grid = Grid(n);
  vtkNew<vtkChainMailDeformationFilter> filter;
  filter->SetInputData(grid);
  filter->SetGraspPointId((n / 2) * n + n / 2);
  const double pull = PullForThousand();
  filter->SetDisplacement(0, 0, pull);
  filter->Update(); // builds adjacency once
  int k = 0;
  for (auto _ : state)
  {
    // Alternate two pulls so every update really recomputes and rewrites.
    filter->SetDisplacement(0, 0, (++k & 1) ? pull : 0.999 * pull);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetPoints());
  }
  state.counters["mesh_vertices"] = double(n * n);
  state.counters["displaced"] = double(filter->GetNumberOfDisplacedPoints());
  state.counters["rebuilds"] = double(filter->GetNumberOfRebuilds());
}
} // namespace

BENCHMARK(BM_FilterUpdate)->Arg(200)->Arg(2000)->Unit(benchmark::kMicrosecond)->MinTime(0.5);

BENCHMARK_MAIN();
