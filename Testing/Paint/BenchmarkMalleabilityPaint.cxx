// 1,000 dabs on a 1,000,000-vertex fault-step horizon through vtkMalleabilityPaintFilter.
// Reports the painting time per dab (the filter's own timer, excluding the array copy
// and the one-off locator build), Euclidean and Geodesic. And the Figure 5C horizon at
// Spacing 0.1 (693,000 vertices) made with and without its painting (two strokes of
// 14,600 and 132,000 dabs): the painting's share of the source.
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
    // Another initial value each time: a full repaint, not an incremental update.
    paint->SetInitialMalleability(paint->GetInitialMalleability() == 0.5 ? 0.25 : 0.5);
    paint->Update();
    total += paint->GetLastPaintMilliseconds();
  }
  state.counters["ms_per_dab"] = total / double(state.iterations()) / 1000.0;
  state.counters["vertices"] = double(input->GetNumberOfPoints());
  state.counters["values_per_dab"] = double(paint->GetNumberOfPaintedValues()) / 1000.0;
}

void FaultStepHorizonSpacing01(benchmark::State& state)
{
  for (auto _ : state)
  {
    vtkNew<vtkFaultStepHorizonSource> source;
    source->SetSpacing(0.1);
    source->SetPaintFigure5C(state.range(0) != 0);
    source->Update();
    benchmark::DoNotOptimize(source->GetOutputDataObject(0));
  }
  state.SetLabel(state.range(0) ? "Figure 5C painted" : "unpainted");
}
} // namespace

BENCHMARK(FaultStepHorizonSpacing01)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK(PaintThousandDabs)
  ->Arg(vtkMalleabilityPaintFilter::EUCLIDEAN)
  ->Arg(vtkMalleabilityPaintFilter::GEODESIC)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(5);
BENCHMARK_MAIN();
