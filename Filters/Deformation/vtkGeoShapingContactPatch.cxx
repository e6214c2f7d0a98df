#include "vtkGeoShapingContactPatch.h"

#include "vtkAbstractCellLocator.h"
#include "vtkBoundingBox.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/mesh/nearest_triangles.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkGeoShapingContactPatch);

namespace
{
// The `max` triangles of `xyz` (9 doubles each) nearest to `centre`, nearest first
// (geoshaping::keep_nearest); all of them when `max` is 0.
void keepNearest(std::vector<double>& xyz, const double centre[3], int max)
{
  if (max <= 0 || xyz.size() / 9 <= std::size_t(max))
  {
    return;
  }
  std::vector<Eigen::Vector3d> corners(xyz.size() / 3);
  for (std::size_t i = 0; i < corners.size(); ++i)
  {
    corners[i] = Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  }
  geoshaping::keep_nearest(corners, Eigen::Vector3d(centre), std::size_t(max));
  xyz.resize(3 * corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i)
  {
    std::copy(corners[i].data(), corners[i].data() + 3, xyz.data() + 3 * i);
  }
}
} // namespace

vtkGeoShapingContactPatch::vtkGeoShapingContactPatch()
  : Triangles(vtkSmartPointer<vtkDoubleArray>::New())
{
  this->SetNumberOfInputPorts(1);
}

vtkGeoShapingContactPatch::~vtkGeoShapingContactPatch() = default;

vtkDoubleArray* vtkGeoShapingContactPatch::GetTriangles()
{
  return this->Triangles;
}

int vtkGeoShapingContactPatch::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

vtkIdType vtkGeoShapingContactPatch::AppendTrianglesNear(vtkDataSet* surface,
  vtkAbstractCellLocator* locator, const double center[3], double radius, std::vector<double>& xyz,
  bool ownedOnly)
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
  vtkUnsignedCharArray* ghosts = ownedOnly ? surface->GetCellGhostArray() : nullptr;
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
    if (ghosts && (ghosts->GetValue(cell) & vtkDataSetAttributes::DUPLICATECELL))
      continue;
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

int vtkGeoShapingContactPatch::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  auto* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  std::vector<double> mine;
  const bool stylusOk = std::isfinite(this->Center[0]) && std::isfinite(this->Center[1]) &&
                        std::isfinite(this->Center[2]) && std::isfinite(this->Radius) &&
                        this->Radius >= 0.0;
  if (!stylusOk)
  {
    // Still joins the gather below: the other processes wait for it.
    vtkErrorMacro("The stylus (Center " << this->Center[0] << " " << this->Center[1] << " "
                                        << this->Center[2] << ", Radius " << this->Radius
                                        << ") is not finite or the radius negative: no triangles.");
  }
  if (stylusOk && input && input->GetNumberOfPoints() > 0 && input->GetNumberOfCells() > 0)
  {
    auto* pointSet = vtkPointSet::SafeDownCast(input);
    const vtkMTimeType time =
      pointSet ? vtkGeoShapingAdapter::GeometryTime(pointSet) : input->GetMTime();
    if (!this->Locator || this->LocatorData != input || this->LocatorTime != time)
    {
      this->Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
      this->Locator->SetDataSet(input);
      this->Locator->BuildLocator();
      this->LocatorData = input;
      this->LocatorTime = time;
    }
    AppendTrianglesNear(input, this->Locator, this->Center, this->Radius, mine, true);
    keepNearest(mine, this->Center, this->MaxTriangles);
  }
  else
  {
    this->Locator = nullptr;
    this->LocatorData = nullptr;
  }
  // Every process joins, an empty piece too; the first collects the pieces rank by rank.
  vtkNew<vtkDoubleArray> piece;
  piece->SetArray(mine.data(), vtkIdType(mine.size()), 1);
  this->Triangles = vtkSmartPointer<vtkDoubleArray>::New();
  if (controller && ranks > 1)
  {
    vtkNew<vtkDoubleArray> all;
    controller->GatherV(piece, all, 0);
    std::vector<double> gathered(all->GetPointer(0), all->GetPointer(0) + all->GetNumberOfValues());
    keepNearest(gathered, this->Center, this->MaxTriangles);
    this->Triangles->SetNumberOfValues(vtkIdType(gathered.size()));
    std::copy(gathered.begin(), gathered.end(), this->Triangles->GetPointer(0));
  }
  else
  {
    this->Triangles->DeepCopy(piece);
  }
  return 1;
}

void vtkGeoShapingContactPatch::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Center: " << this->Center[0] << " " << this->Center[1] << " " << this->Center[2]
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "MaxTriangles: " << this->MaxTriangles << "\n";
  os << indent << "Triangles: " << this->Triangles->GetNumberOfValues() / 9 << "\n";
}
