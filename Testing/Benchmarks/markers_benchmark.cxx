// The cost of HonourMarkers per drag frame (docs/markers.md, "Cost"): a drag on a real
// horizon (argv[1], a GOCAD TSurf: the CRESCENT Cascadia interface in docs/benchmarks.md)
// without markers and with 10, 100 and 1,000 honoured markers on random triangles,
// frames interleaved (one without, one with, the order swapped each round) so a loaded
// machine slows both alike; the median per frame of each. Also the one-off cost of
// mapping the markers to pins (the first update after the markers change), and a filter
// with the markers connected but HonourMarkers off (the pipeline's share). Run by hand.
#include "vtkChainMailDeformationFilter.h"
#include "vtkGocadTSurfReader.h"

#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{
double Milliseconds(vtkChainMailDeformationFilter* filter, double dz)
{
  filter->SetDisplacement(0.0, 0.0, dz);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s surface.ts [rounds] [pull in mean spacings]\n", argv[0]);
    return 2;
  }
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 2000;
  vtkNew<vtkGocadTSurfReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();
  vtkPolyData* surface = reader->GetOutput();
  const vtkIdType grasp = surface->GetNumberOfPoints() / 2;
  const double spacings = argc > 3 ? std::atof(argv[3]) : 3.0;
  const double pull =
    spacings * surface->GetLength() / std::sqrt(double(surface->GetNumberOfPoints()));
  std::printf("%lld points, %lld triangles, grasp %lld pulled up by %.1f\n",
    static_cast<long long>(surface->GetNumberOfPoints()),
    static_cast<long long>(surface->GetNumberOfPolys()), static_cast<long long>(grasp), pull);
  std::mt19937 random(3);
  std::uniform_int_distribution<vtkIdType> cell(0, surface->GetNumberOfCells() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const int count : { 10, 100, 1000 })
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    while (points->GetNumberOfPoints() < count)
    {
      vtkIdList* ids = surface->GetCell(cell(random))->GetPointIds();
      if (ids->IsId(grasp) >= 0)
        continue; // the grasp stays graspable
      double a = unit(random), b = unit(random);
      if (a + b > 1.0)
        a = 1.0 - a, b = 1.0 - b;
      double p[3][3], m[3];
      for (int k = 0; k < 3; ++k)
        surface->GetPoint(ids->GetId(k), p[k]);
      for (int c = 0; c < 3; ++c)
        m[c] = (1 - a - b) * p[0][c] + a * p[1][c] + b * p[2][c];
      points->InsertNextPoint(m);
    }
    vtkNew<vtkPolyData> markers;
    markers->SetPoints(points);
    vtkNew<vtkChainMailDeformationFilter> without, with, off;
    for (vtkChainMailDeformationFilter* f : { without.Get(), with.Get(), off.Get() })
    {
      f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
      f->SetInputData(surface);
      f->SetDefaultMalleability(0.7);
      f->SetGraspPointId(grasp);
    }
    with->SetMarkersData(markers);
    with->HonourMarkersOn();
    off->SetMarkersData(markers); // connected, HonourMarkers off: the pipeline's share
    Milliseconds(without, pull);
    Milliseconds(off, pull);
    std::vector<double> map;
    for (int i = 0; i < 20; ++i) // the map, made again when the markers change
    {
      markers->Modified();
      map.push_back(Milliseconds(with, i % 2 ? pull : 0.999 * pull));
    }
    std::vector<double> a, b, c, core[2];
    for (int i = 0; i < rounds; ++i)
    {
      const double dz = i % 2 ? pull : 0.999 * pull;
      if (i % 4 < 2)
      {
        a.push_back(Milliseconds(without, dz));
        b.push_back(Milliseconds(with, dz));
        c.push_back(Milliseconds(off, dz));
      }
      else
      {
        c.push_back(Milliseconds(off, dz));
        b.push_back(Milliseconds(with, dz));
        a.push_back(Milliseconds(without, dz));
      }
      core[0].push_back(without->GetLastDeformationMilliseconds());
      core[1].push_back(with->GetLastDeformationMilliseconds());
    }
    std::printf("%4d markers (%lld honoured, %lld pinned): update %.4f ms without, %.4f ms "
                "with (%+.1f%%), %.4f ms connected but off; core frame %.4f / %.4f ms; moved "
                "%lld vs %lld; update that maps the markers %.3f ms\n",
      count, static_cast<long long>(with->GetNumberOfHonouredMarkers()),
      static_cast<long long>(with->GetNumberOfMarkerPinnedPoints()), Median(a), Median(b),
      100.0 * (Median(b) / Median(a) - 1.0), Median(c), Median(core[0]), Median(core[1]),
      static_cast<long long>(without->GetNumberOfDisplacedPoints()),
      static_cast<long long>(with->GetNumberOfDisplacedPoints()), Median(map));
  }
  return 0;
}
