#include "marker_samples.h"

#include "vtkCell.h"
#include "vtkGocadTSurfReader.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <cmath>
#include <filesystem>
#include <random>

namespace markers_testing
{

vtkSmartPointer<vtkPolyData> Points(const Xyz& xyz)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : xyz)
    points->InsertNextPoint(p.data());
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

Samples SampleCascadia(unsigned seed, int count, int onSurface, double shrink, std::string& path)
{
  path = std::string(GEOSHAPING_CFM_DIR) + "/mccrory_2012_cascadia_interface.ts";
  if (!std::filesystem::exists(path))
    return {};
  vtkNew<vtkGocadTSurfReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return SampleMarkers(reader->GetOutput(), seed, count, onSurface, shrink);
}

Samples SampleMarkers(vtkPolyData* surface, unsigned seed, int count, int onSurface, double shrink)
{
  Samples s;
  s.surface = surface;
  s.size = surface->GetLength();
  {
    double a[3], b[3];
    surface->GetPoint(surface->GetCell(0)->GetPointId(0), a);
    surface->GetPoint(surface->GetCell(0)->GetPointId(1), b);
    s.edge = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  }
  std::mt19937 random(seed);
  std::uniform_int_distribution<vtkIdType> cell(0, surface->GetNumberOfCells() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < count; ++k)
  {
    vtkIdList* ids = surface->GetCell(cell(random))->GetPointIds();
    double a = unit(random), b = unit(random);
    if (a + b > 1.0)
      a = 1.0 - a, b = 1.0 - b;
    const double u = shrink == 1.0 ? a : 1.0 / 3.0 + shrink * (a - 1.0 / 3.0);
    const double v = shrink == 1.0 ? b : 1.0 / 3.0 + shrink * (b - 1.0 / 3.0);
    double p0[3], p1[3], p2[3];
    surface->GetPoint(ids->GetId(0), p0);
    surface->GetPoint(ids->GetId(1), p1);
    surface->GetPoint(ids->GetId(2), p2);
    const double offset = k < onSurface ? 0.0 : (unit(random) - 0.5) * 0.2 * s.edge;
    std::array<double, 3> m;
    for (int c = 0; c < 3; ++c)
      m[c] = (1 - u - v) * p0[c] + u * p1[c] + v * p2[c];
    m[2] += offset;
    s.xyz.push_back(m);
    s.dz.push_back(offset);
  }
  return s;
}
}
