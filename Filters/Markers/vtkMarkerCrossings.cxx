#include "vtkMarkerCrossings.h"

#include "vtkDataArray.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"

#include <algorithm>

vtkMarkerCrossings::vtkMarkerCrossings() = default;
vtkMarkerCrossings::~vtkMarkerCrossings() = default;

bool vtkMarkerCrossings::SetSurface(vtkDataSet* surface, const double markerZ[2])
{
  // The surface's polygons as triangles (a volume mesh's boundary first), each point
  // naming the surface's point it is (vtkPolyData's points pass as they are).
  vtkNew<vtkDataSetSurfaceFilter> boundary;
  boundary->SetInputData(surface);
  boundary->PassThroughPointIdsOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(boundary->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  this->Triangles = triangles->GetOutput();
  this->Original = this->Triangles->GetPointData()->GetArray(boundary->GetOriginalPointIdsName());
  if (this->Triangles->GetNumberOfPolys() == 0)
  {
    return false;
  }
  this->Locator->SetDataSet(this->Triangles);
  this->Locator->BuildLocator();
  double bounds[6];
  this->Triangles->GetBounds(bounds);
  const double diagonal = std::max(this->Triangles->GetLength(), 1.0);
  this->ZLow = std::min(bounds[4], markerZ[0]) - diagonal;
  this->ZHigh = std::max(bounds[5], markerZ[1]) + diagonal;
  this->Tolerance = 1e-9 * diagonal;
  return true;
}

vtkIdType vtkMarkerCrossings::SurfacePointId(vtkIdType id) const
{
  return this->Original ? vtkIdType(this->Original->GetTuple1(id)) : id;
}

void vtkMarkerCrossings::Crossed(double x, double y, vtkIdList* cells)
{
  const double low[3] = { x, y, this->ZLow }, high[3] = { x, y, this->ZHigh };
  this->Locator->IntersectWithLine(low, high, this->Tolerance, this->Hits, cells);
}

void vtkMarkerCrossings::Corners(vtkIdType cell, vtkIdList* ids, Eigen::Vector3d corners[3])
{
  this->Triangles->GetCellPoints(cell, ids);
  for (int k = 0; k < 3; ++k)
    this->Triangles->GetPoint(ids->GetId(k), corners[k].data());
}
