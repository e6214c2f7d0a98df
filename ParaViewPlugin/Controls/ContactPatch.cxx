#include "ContactPatch.h"

#include <vtkAbstractCellLocator.h>
#include <vtkBoundingBox.h>
#include <vtkCellType.h>
#include <vtkDataSet.h>
#include <vtkIdList.h>
#include <vtkNew.h>

#include <cmath>

namespace geoshaping
{
namespace contact
{

vtkIdType AppendTrianglesNear(vtkDataSet* surface, vtkAbstractCellLocator* locator,
  const double center[3], double radius, std::vector<double>& xyz)
{
  if (!surface || !locator || !(radius >= 0.0) || !std::isfinite(radius) ||
      !std::isfinite(center[0]) || !std::isfinite(center[1]) || !std::isfinite(center[2]))
  {
    return 0;
  }
  double box[6] = { center[0] - radius, center[0] + radius, center[1] - radius, center[1] + radius,
    center[2] - radius, center[2] + radius };
  vtkNew<vtkIdList> cells, ids;
  // The locator answers with the cells of the bins the box overlaps; keep those whose
  // own bounds meet the box.
  locator->FindCellsWithinBounds(box, cells);
  const vtkBoundingBox query(box);
  const std::size_t before = xyz.size();
  auto corner = [&](vtkIdType i)
  {
    double p[3];
    surface->GetPoint(ids->GetId(i), p);
    xyz.insert(xyz.end(), p, p + 3);
  };
  auto triangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    corner(a);
    corner(b);
    corner(c);
  };
  for (vtkIdType k = 0; k < cells->GetNumberOfIds(); ++k)
  {
    const vtkIdType cell = cells->GetId(k);
    double bounds[6];
    surface->GetCellBounds(cell, bounds);
    if (!query.Intersects(vtkBoundingBox(bounds)))
      continue;
    const int type = surface->GetCellType(cell);
    surface->GetCellPoints(cell, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    switch (type)
    {
      case VTK_TRIANGLE:
      case VTK_QUAD:
      case VTK_POLYGON:
        for (vtkIdType i = 1; i + 1 < n; ++i)
          triangle(0, i, i + 1);
        break;
      case VTK_PIXEL: // 0 1 3 2 around
        if (n == 4)
        {
          triangle(0, 1, 3);
          triangle(0, 3, 2);
        }
        break;
      case VTK_TRIANGLE_STRIP:
        for (vtkIdType i = 0; i + 2 < n; ++i)
          triangle(i, i + 1, i + 2);
        break;
      default:
        break;
    }
  }
  return vtkIdType((xyz.size() - before) / 9);
}

} // namespace contact
} // namespace geoshaping
