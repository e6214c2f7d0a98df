#include "vtkSparseSurface.h"

#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkSparseSurface);

void vtkSparseSurface::Adopt(vtkPolyData* from, vtkGrowingBoundsPoints* shared)
{
  this->vtkPolyData::ShallowCopy(from);
  vtkSmartPointer<vtkGrowingBoundsPoints> points = shared;
  if (!points)
  {
    points = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
    if (from->GetPoints())
    {
      points->SetData(from->GetPoints()->GetData());
    }
  }
  this->SetPoints(points);
  double bounds[6];
  points->GetBounds(bounds); // exact once, if not known yet: later changes grow it
}

void vtkSparseSurface::PointsChanged(vtkIdTypeArray* ids, bool exact)
{
  auto* points = vtkGrowingBoundsPoints::SafeDownCast(this->Points);
  if (!points)
  {
    this->Modified();
    return;
  }
  if (ids)
  {
    points->PointsChanged(ids->GetPointer(0), ids->GetNumberOfTuples(), exact);
  }
  if (points->HasGrownBounds())
  {
    points->GetBounds(this->CellsBounds);
    this->CellsBoundsTime.Modified();
  }
}

void vtkSparseSurface::ShallowCopy(vtkDataObject* src)
{
  this->Superclass::ShallowCopy(src);
  auto* from = vtkSparseSurface::SafeDownCast(src);
  if (from && from->CellsBoundsTime > from->GetMeshMTime())
  {
    std::copy(from->CellsBounds, from->CellsBounds + 6, this->CellsBounds);
    this->CellsBoundsTime.Modified();
  }
}
