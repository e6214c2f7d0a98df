#include "vtkGeoShapingGhostRing.h"

#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkGeoShapingControllerExchange.h"
#include "vtkGhostCellsGenerator.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace
{
// What the copy is made from: the input object, its points and cells, and its arrays,
// each by its own modification time (the executive touches the data object and its
// attribute containers at every update, so their times would make the ring again at
// every drag frame).
std::vector<std::uintptr_t> Signature(vtkPointSet* input)
{
  std::vector<std::uintptr_t> s{ std::uintptr_t(input), std::uintptr_t(input->GetPoints()),
    std::uintptr_t(vtkGeoShapingAdapter::GeometryTime(input)) };
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(input->GetPointData()),
         static_cast<vtkFieldData*>(input->GetCellData()) })
    for (int i = 0; i < data->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* a = data->GetAbstractArray(i);
      s.push_back(std::uintptr_t(a));
      s.push_back(a ? std::uintptr_t(a->GetMTime()) : 0);
    }
  return s;
}
} // namespace

struct vtkGeoShapingGhostRing::vtkInternals
{
  std::vector<std::uintptr_t> Source; // what the copy was made from (Signature)
  bool Generated = false;             // Ensure's last decision, kept with the copy
  vtkSmartPointer<vtkPointSet> Copy;
};

vtkGeoShapingGhostRing::vtkGeoShapingGhostRing()
  : Internals(new vtkInternals)
{
}

vtkGeoShapingGhostRing::~vtkGeoShapingGhostRing() = default;

vtkPointSet* vtkGeoShapingGhostRing::Ensure(
  vtkPointSet* input, vtkMultiProcessController* controller, std::string& error)
{
  error.clear();
  vtkInternals& in = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType cells = input->GetNumberOfCells();
  vtkUnsignedCharArray* pointGhosts = input->GetPointGhostArray();
  vtkUnsignedCharArray* cellGhosts = input->GetCellGhostArray();
  const bool marked = pointGhosts && pointGhosts->GetNumberOfTuples() == n &&
                      (cells == 0 || (cellGhosts && cellGhosts->GetNumberOfTuples() == cells));
  // Kept: the same input object, unchanged (points, cells and arrays).
  const bool kept = in.Copy && in.Generated && in.Source == Signature(input);
  // Per process: holds points, is marked, still has its copy, has point GlobalIds.
  const int mine[4] = { n > 0, marked, kept,
    vtkGeoShapingAdapter::PointGlobalIds(input) != nullptr };
  const int pieces = controller->GetNumberOfProcesses();
  std::vector<int> all(4 * std::size_t(pieces));
  controller->AllGather(mine, all.data(), 4);
  int holding = 0;
  bool allMarked = true, allKept = true, anyIds = false;
  for (int p = 0; p < pieces; ++p)
  {
    const int* v = all.data() + 4 * std::size_t(p);
    holding += v[0];
    allMarked = allMarked && (!v[0] || v[1]);
    allKept = allKept && v[2];
    anyIds = anyIds || (v[0] && v[3]);
  }
  if (holding <= 1 || allMarked)
  {
    in.Generated = false;
    in.Copy = nullptr;
    in.Source.clear();
    return input;
  }
  if (allKept)
    return in.Copy;
  in.Copy = nullptr;
  in.Source.clear();
  std::vector<double> xyz;
  vtkIdType firstBad = -1;
  const int finite =
    n == 0 || vtkGeoShapingAdapter::PointsAsDouble(input->GetPoints(), xyz, firstBad) == 0;
  int allFinite = 0;
  controller->AllReduce(&finite, &allFinite, 1, vtkCommunicator::MIN_OP);
  if (!allFinite)
  {
    error = "non-finite point coordinates, so no ghost cells could be made";
    return nullptr;
  }

  auto shallow = vtk::TakeSmartPointer(input->NewInstance());
  shallow->ShallowCopy(input);
  if (!anyIds)
  {
    // Numbered by coordinates, the same numbers for any partition, every point claimed
    // (no ghosts yet).
    vtkGeoShapingControllerExchange ex(controller, 914500);
    std::vector<std::uint8_t> claimed(static_cast<std::size_t>(n), 1);
    const std::vector<std::int64_t> ids =
      vtkGeoShapingAdapter::CoordinateIds(xyz.data(), n, claimed, ex, error);
    if (!error.empty())
      return nullptr;
    vtkNew<vtkIdTypeArray> gids;
    gids->SetName("GlobalIds");
    gids->SetNumberOfTuples(n);
    std::copy(ids.begin(), ids.end(), gids->GetPointer(0));
    shallow->GetPointData()->SetGlobalIds(gids);
  }
  vtkNew<vtkGhostCellsGenerator> generator;
  generator->SetController(controller);
  generator->BuildIfRequiredOff();
  generator->SetNumberOfGhostLayers(1);
  generator->SetInputData(shallow);
  generator->Update();
  vtkPointSet* made = vtkPointSet::SafeDownCast(generator->GetOutputDataObject(0));
  const int ok = made != nullptr;
  int allOk = 0;
  controller->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (!allOk)
  {
    error = "vtkGhostCellsGenerator made no point set on some process";
    return nullptr;
  }
  in.Copy = vtk::TakeSmartPointer(made->NewInstance());
  in.Copy->ShallowCopy(made);
  in.Source = Signature(input);
  in.Generated = true;
  return in.Copy;
}
