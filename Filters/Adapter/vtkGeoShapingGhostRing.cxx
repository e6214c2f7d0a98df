#include "vtkGeoShapingGhostRing.h"

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

#include "geoshaping/coordinate_ids.h"

#include <algorithm>
#include <chrono>
#include <vector>

struct vtkGeoShapingGhostRing::vtkInternals
{
  vtkPointSet* Source = nullptr; // the input the copy was made from
  vtkMTimeType SourceTime = 0;
  bool Generated = false; // Ensure's last decision, kept with the copy
  vtkSmartPointer<vtkPointSet> Copy;
  int Generations = 0;
  double Milliseconds = 0.0;
};

vtkGeoShapingGhostRing::vtkGeoShapingGhostRing()
  : Internals(new vtkInternals)
{
}

vtkGeoShapingGhostRing::~vtkGeoShapingGhostRing() = default;

int vtkGeoShapingGhostRing::GetNumberOfGenerations() const
{
  return this->Internals->Generations;
}

double vtkGeoShapingGhostRing::GetLastMilliseconds() const
{
  return this->Internals->Milliseconds;
}

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
  const bool kept =
    in.Copy && in.Source == input && in.SourceTime == input->GetMTime() && in.Generated;
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
    in.Source = nullptr;
    return input;
  }
  if (allKept)
    return in.Copy;
  in.Copy = nullptr;
  in.Source = nullptr;
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

  const auto start = std::chrono::steady_clock::now();
  auto shallow = vtk::TakeSmartPointer(input->NewInstance());
  shallow->ShallowCopy(input);
  if (!anyIds)
  {
    // Numbered by coordinates, the same numbers for any partition (coordinate_ids.h).
    vtkGeoShapingControllerExchange ex(controller, 914500);
    const std::vector<std::uint8_t> claimed(static_cast<std::size_t>(n), 1);
    std::vector<std::uint8_t> owned;
    geoshaping::index_t coincident = 0;
    const std::vector<std::int64_t> ids = geoshaping::coordinate_ids(
      xyz.data(), geoshaping::index_t(n), claimed.data(), owned, ex, &coincident);
    error = geoshaping::coincident_points_refusal(coincident, ex);
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
  in.Source = input;
  in.SourceTime = input->GetMTime();
  in.Generated = true;
  ++in.Generations;
  in.Milliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return in.Copy;
}
