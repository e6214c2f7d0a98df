#include "vtkGeoShapingRayPick.h"

#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/mesh/ray_pick.h"

#include <vector>

vtkStandardNewMacro(vtkGeoShapingRayPick);

vtkGeoShapingRayPick::vtkGeoShapingRayPick()
{
  this->SetNumberOfInputPorts(1);
}

int vtkGeoShapingRayPick::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkGeoShapingRayPick::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  auto* input = vtkPointSet::GetData(inputVector[0], 0);
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  geoshaping::RayHit mine;
  mine.rank = rank;
  if (input && input->GetNumberOfPoints() > 0 && input->GetNumberOfCells() > 0)
  {
    // The owned polygons (triangles, quads, polygons; a ghost copy is met by its owner,
    // so the hit names the owning rank) as CSR faces.
    std::vector<std::int64_t> offsets{ 0 };
    std::vector<geoshaping::index_t> vertices;
    vtkUnsignedCharArray* ghosts = input->GetCellGhostArray();
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
    {
      const int type = input->GetCellType(c);
      if ((type != VTK_TRIANGLE && type != VTK_QUAD && type != VTK_POLYGON) ||
          (ghosts && (ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL)))
      {
        continue;
      }
      input->GetCellPoints(c, ids);
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      {
        vertices.push_back(geoshaping::index_t(ids->GetId(i)));
      }
      offsets.push_back(std::int64_t(vertices.size()));
    }
    std::vector<double> storage;
    vtkIdType bad = 0, firstBad = -1;
    const double* xyz =
      vtkGeoShapingAdapter::PointsView(input->GetPoints(), storage, bad, firstBad);
    mine = geoshaping::ray_pick(xyz, offsets, vertices, Eigen::Vector3d(this->RayOrigin),
      Eigen::Vector3d(this->RayDirection), rank);
    vtkDataArray* gids = vtkGeoShapingAdapter::PointGlobalIds(input);
    if (mine.hit && gids)
    {
      mine.point_id = static_cast<std::int64_t>(gids->GetTuple1(mine.point_id));
    }
  }
  // Every process joins, an empty piece too.
  double packed[geoshaping::ray_hit_doubles];
  geoshaping::pack_ray_hit(mine, packed);
  std::vector<double> all(std::size_t(ranks) * geoshaping::ray_hit_doubles);
  if (controller && ranks > 1)
  {
    controller->AllGather(packed, all.data(), geoshaping::ray_hit_doubles);
  }
  else
  {
    std::copy(packed, packed + geoshaping::ray_hit_doubles, all.begin());
  }
  geoshaping::RayHit best = geoshaping::unpack_ray_hit(all.data());
  for (int r = 1; r < ranks; ++r)
  {
    best = geoshaping::nearer_hit(
      best, geoshaping::unpack_ray_hit(all.data() + std::size_t(r) * geoshaping::ray_hit_doubles));
  }
  this->Hit = best.hit ? 1 : 0;
  for (int i = 0; i < 3; ++i)
  {
    this->HitPoint[i] = best.point[i];
    this->HitNormal[i] = best.normal[i];
  }
  this->HitRank = best.hit ? best.rank : -1;
  this->HitPointId = best.hit ? vtkIdType(best.point_id) : -1;
  return 1;
}

void vtkGeoShapingRayPick::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RayOrigin: " << this->RayOrigin[0] << " " << this->RayOrigin[1] << " "
     << this->RayOrigin[2] << "\n";
  os << indent << "RayDirection: " << this->RayDirection[0] << " " << this->RayDirection[1] << " "
     << this->RayDirection[2] << "\n";
  os << indent << "Hit: " << this->Hit << " rank " << this->HitRank << " point id "
     << this->HitPointId << "\n";
}
