// 1,000 dabs on a 1,000,000-vertex fault-step horizon through vtkMalleabilityPaintFilter.
// Reports the painting time per dab (the filter's own timer, excluding the array copy
// and the one-off locator build), Euclidean and Geodesic.
#include "vtkFaultStepHorizonSource.h"
#include "vtkMalleabilityPaintFilter.h"

#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"

#include <benchmark/benchmark.h>

#include <random>

namespace
{
vtkPointSet* Horizon()
{
  // About 1000 x 1000 vertices: the profile (length + the step's extra arc) is ~1000 long.
  static vtkSmartPointer<vtkPointSet> horizon = []
  {
    vtkNew<vtkFaultStepHorizonSource> source;
    source->SetLength(984.0);
    source->SetWidth(999.0);
    source->SetSpacing(1.0);
    source->Update();
    return vtkSmartPointer<vtkPointSet>(vtkPointSet::SafeDownCast(source->GetOutputDataObject(0)));
  }();
  return horizon;
}

void PaintThousandDabs(benchmark::State& state)
{
  vtkPointSet* input = Horizon();
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(input);
  paint->SetDistanceMode(int(state.range(0)));
  std::mt19937 random(42);
  std::uniform_real_distribution<double> x(0.0, 984.0), y(0.0, 999.0);
  for (int i = 0; i < 1000; ++i)
  {
    const double cx = x(random); // on the upper (z = 20) or lower (z = 0) side of the step
    paint->AddDab(cx, y(random), cx < 492.0 ? 20.0 : 0.0, 5.0, (i % 2) ? 1.0 : 0.0, 0.5);
  }
  paint->Update(); // builds the locator (and adjacency) once
  double total = 0.0;
  for (auto _ : state)
  {
    paint->Modified();
    paint->Update();
    total += paint->GetLastPaintMilliseconds();
  }
  state.counters["ms_per_dab"] = total / double(state.iterations()) / 1000.0;
  state.counters["vertices"] = double(input->GetNumberOfPoints());
  state.counters["values_per_dab"] = double(paint->GetNumberOfPaintedValues()) / 1000.0;
}
} // namespace

BENCHMARK(PaintThousandDabs)
  ->Arg(vtkMalleabilityPaintFilter::EUCLIDEAN)
  ->Arg(vtkMalleabilityPaintFilter::GEODESIC)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(5);
BENCHMARK_MAIN();
