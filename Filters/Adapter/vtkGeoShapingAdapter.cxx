#include "vtkGeoShapingAdapter.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellIterator.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "geoshaping/mesh/triangle_grid.h"
#include "geoshaping/parallel/coordinate_ids.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

using geoshaping::CellKind;

CellKind vtkGeoShapingAdapter::CellKindOf(int type)
{
  switch (type)
  {
    case VTK_VERTEX:
      return CellKind::vertex;
    case VTK_POLY_VERTEX:
      return CellKind::poly_vertex;
    case VTK_LINE:
      return CellKind::line;
    case VTK_POLY_LINE:
      return CellKind::poly_line;
    case VTK_TRIANGLE:
      return CellKind::triangle;
    case VTK_TRIANGLE_STRIP:
      return CellKind::triangle_strip;
    case VTK_QUAD:
    case VTK_POLYGON:
      return CellKind::polygon;
    case VTK_PIXEL:
      return CellKind::pixel;
    case VTK_TETRA:
      return CellKind::tetra;
    case VTK_VOXEL:
      return CellKind::voxel;
    case VTK_HEXAHEDRON:
      return CellKind::hexahedron;
    case VTK_WEDGE:
      return CellKind::wedge;
    case VTK_PYRAMID:
      return CellKind::pyramid;
    default:
      return CellKind::unsupported;
  }
}

namespace
{
// Visits the cells of one cell array through its own offsets and connectivity (32- or
// 64-bit): visit(kind, ids, count) with no copy and no virtual call per cell.
template<class Visit>
struct CellArrayVisitor
{
  template<class State>
  void operator()(State& state, CellKind kind, const Visit& visit) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* ids = state.GetConnectivity()->GetPointer(0);
    const vtkIdType cells = state.GetNumberOfCells();
    for (vtkIdType c = 0; c < cells; ++c)
      visit(kind, ids + offsets[c], std::int64_t(offsets[c + 1] - offsets[c]));
  }
};

// Whether a cell array is a triangulated grid (geoshaping/mesh/triangle_grid.h).
struct TriangleGridWorker
{
  template<class State>
  void operator()(
    State& state, geoshaping::index_t n, geoshaping::TriangleGrid* grid, bool* found) const
  {
    *found = geoshaping::triangle_grid_of(state.GetOffsets()->GetPointer(0),
      state.GetConnectivity()->GetPointer(0), state.GetNumberOfCells(), n, grid);
  }
};

// out = points as doubles, through the array's own value type.
struct PointsWorker
{
  template<class Array>
  void operator()(Array* array, double* out) const
  {
    const auto values = vtk::DataArrayValueRange<3>(array);
    std::copy(values.begin(), values.end(), out);
  }
};
} // namespace

geoshaping::Adjacency vtkGeoShapingAdapter::BuildAdjacency(vtkDataSet* input, vtkIdType& skipped)
{
  const auto n = geoshaping::index_t(input->GetNumberOfPoints());
  std::int64_t refused = 0;
  geoshaping::Adjacency adjacency;
  auto* pd = vtkPolyData::SafeDownCast(input);
  geoshaping::TriangleGrid grid;
  bool found = false;
  if (pd && pd->GetNumberOfVerts() == 0 && pd->GetNumberOfLines() == 0 &&
      pd->GetNumberOfStrips() == 0 && pd->GetNumberOfPolys() > 0)
    pd->GetPolys()->Visit(TriangleGridWorker(), n, &grid, &found);
  if (found)
  {
    // A DEM's grid: the rows from the rows and columns, no cell walked twice.
    adjacency = geoshaping::grid_adjacency(grid);
  }
  else if (pd)
  {
    // The four cell arrays walked directly: no per-cell dispatch on large surfaces.
    const auto cells = [pd](const auto& visit)
    {
      const CellKind kinds[4] = { CellKind::poly_vertex, CellKind::poly_line, CellKind::polygon,
        CellKind::triangle_strip };
      vtkCellArray* arrays[4] = { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() };
      for (int a = 0; a < 4; ++a)
        if (arrays[a])
          arrays[a]->Visit(CellArrayVisitor<std::decay_t<decltype(visit)>>(), kinds[a], visit);
    };
    adjacency = geoshaping::adjacency_of_cells(n, cells, &refused);
  }
  else
  {
    const auto cells = [input](const auto& visit)
    {
      vtkSmartPointer<vtkCellIterator> it = vtk::TakeSmartPointer(input->NewCellIterator());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextCell())
      {
        vtkIdList* ids = it->GetPointIds();
        visit(CellKindOf(it->GetCellType()), ids->GetPointer(0), ids->GetNumberOfIds());
      }
    };
    adjacency = geoshaping::adjacency_of_cells(n, cells, &refused);
  }
  skipped = vtkIdType(refused);
  return adjacency;
}

namespace
{
// The number of non-finite coordinates of n points, firstBad the first point with one.
vtkIdType CountNonFinite(const double* xyz, vtkIdType n, vtkIdType& firstBad)
{
  vtkIdType bad = 0;
  firstBad = -1;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int finite =
      std::isfinite(xyz[3 * i]) + std::isfinite(xyz[3 * i + 1]) + std::isfinite(xyz[3 * i + 2]);
    if (finite < 3)
    {
      bad += 3 - finite;
      firstBad = firstBad < 0 ? i : firstBad;
    }
  }
  return bad;
}
} // namespace

vtkIdType vtkGeoShapingAdapter::PointsAsDouble(
  vtkPoints* points, std::vector<double>& xyz, vtkIdType& firstBad)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  xyz.resize(std::size_t(3 * n));
  if (n > 0 && (points->GetData()->GetNumberOfComponents() != 3 ||
                 !vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
                   points->GetData(), PointsWorker(), xyz.data())))
  {
    for (vtkIdType i = 0; i < n; ++i)
      points->GetPoint(i, xyz.data() + 3 * i);
  }
  return CountNonFinite(xyz.data(), n, firstBad);
}

const double* vtkGeoShapingAdapter::PointsView(
  vtkPoints* points, std::vector<double>& storage, vtkIdType& bad, vtkIdType& firstBad)
{
  auto* doubles = points ? vtkDoubleArray::FastDownCast(points->GetData()) : nullptr;
  if (!doubles || doubles->GetNumberOfComponents() != 3)
  {
    bad = PointsAsDouble(points, storage, firstBad);
    return storage.data();
  }
  storage.clear();
  const double* xyz = doubles->GetPointer(0);
  bad = CountNonFinite(xyz, doubles->GetNumberOfTuples(), firstBad);
  return xyz;
}

vtkSmartPointer<vtkPoints> vtkGeoShapingAdapter::MakePoints(const std::vector<double>& xyz)
{
  vtkNew<vtkDoubleArray> data;
  data->SetNumberOfComponents(3);
  data->SetNumberOfTuples(vtkIdType(xyz.size() / 3));
  std::copy(xyz.begin(), xyz.end(), data->GetPointer(0));
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(data);
  return points;
}

vtkSmartPointer<vtkCellArray> vtkGeoShapingAdapter::MakeCells(
  const std::vector<geoshaping::index_t>& connectivity, int cellSize)
{
  const vtkIdType numCells = cellSize > 0 ? vtkIdType(connectivity.size()) / cellSize : 0;
  vtkNew<vtkIdTypeArray> offsets, ids;
  offsets->SetNumberOfTuples(numCells + 1);
  for (vtkIdType c = 0; c <= numCells; ++c)
    offsets->SetValue(c, c * cellSize);
  ids->SetNumberOfTuples(vtkIdType(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), ids->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, ids);
  return cells;
}

vtkMTimeType vtkGeoShapingAdapter::GeometryTime(vtkPointSet* input)
{
  vtkMTimeType t = input->GetPoints() ? input->GetPoints()->GetMTime() : 0;
  if (auto* pd = vtkPolyData::SafeDownCast(input))
  {
    for (vtkCellArray* a : { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() })
      t = std::max(t, a ? a->GetMTime() : 0);
    return t;
  }
  if (auto* ug = vtkUnstructuredGrid::SafeDownCast(input))
  {
    t = std::max(t, ug->GetCells() ? ug->GetCells()->GetMTime() : 0);
    return t;
  }
  return std::max(t, input->GetMTime());
}

bool vtkGeoShapingAdapter::BuildFaces(vtkPointSet* input, std::vector<std::int64_t>& offsets,
  std::vector<geoshaping::index_t>& vertices)
{
  offsets.clear();
  vertices.clear();
  auto* poly = vtkPolyData::SafeDownCast(input);
  if (!poly || poly->GetNumberOfPolys() == 0 || poly->GetNumberOfStrips() > 0)
  {
    return false;
  }
  const vtkIdType n = poly->GetNumberOfPoints();
  vtkCellArray* polys = poly->GetPolys();
  offsets.reserve(std::size_t(polys->GetNumberOfCells()) + 1);
  vertices.reserve(std::size_t(polys->GetNumberOfConnectivityIds()));
  offsets.push_back(0);
  auto cells = vtk::TakeSmartPointer(polys->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    for (vtkIdType i = 0; i < size; ++i)
    {
      if (ids[i] < 0 || ids[i] >= n)
      {
        offsets.clear();
        vertices.clear();
        return false;
      }
      vertices.push_back(geoshaping::index_t(ids[i]));
    }
    offsets.push_back(std::int64_t(vertices.size()));
  }
  return true;
}

void vtkGeoShapingAdapter::RequestGhostRing(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int levels =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
      ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
      : 0;
  inInfo->Set(
    vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), std::max(levels, 1));
}

vtkDataArray* vtkGeoShapingAdapter::PointGlobalIds(vtkDataSet* input)
{
  vtkDataArray* ids = input->GetPointData()->GetGlobalIds();
  const char* name = ids ? ids->GetName() : nullptr;
  return name && std::strcmp(name, "___D3___GlobalNodeIds") == 0 ? nullptr : ids;
}

std::string vtkGeoShapingAdapter::PieceArraysProblem(vtkDataSet* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* gids = PointGlobalIds(input);
  vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
  if (n > 0 && gids && (gids->GetNumberOfTuples() != n || gids->GetNumberOfComponents() != 1))
    return "a point GlobalIds array that is not one value per point";
  if (n > 0 && ghosts && ghosts->GetNumberOfTuples() != n)
    return "a vtkGhostType point array that is not one value per point";
  return "";
}

vtkGeoShapingAdapter::PieceAgreement vtkGeoShapingAdapter::AgreeOnPieces(
  geoshaping::Exchange* ex, bool ok, bool changed, vtkIdType n, bool hasIds)
{
  const std::vector<std::int64_t> mine{ ok, changed, n == 0 ? 0 : hasIds ? 1 : 2 };
  PieceAgreement all;
  bool withoutIds = false;
  for (const auto& v : ex ? ex->all_gather(mine) : std::vector<std::vector<std::int64_t>>{ mine })
  {
    all.Ok = all.Ok && v[0];
    all.AnyChanged = all.AnyChanged || v[1];
    all.WithIds = all.WithIds || v[2] == 1;
    withoutIds = withoutIds || v[2] == 2;
  }
  if (all.Ok && all.WithIds && withoutIds)
  {
    all.Ok = false;
    all.Refusal = "Point GlobalIds on some processes and not on others";
  }
  else if (!all.Ok && ok)
    all.Refusal = "Another process refused its piece";
  return all;
}

std::vector<std::uint8_t> vtkGeoShapingAdapter::OwnedPoints(vtkDataSet* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
  std::vector<std::uint8_t> owned(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
    owned[std::size_t(i)] =
      !ghosts || (ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT) == 0;
  return owned;
}

std::vector<std::int64_t> vtkGeoShapingAdapter::CoordinateIds(const double* xyz, vtkIdType n,
  std::vector<std::uint8_t>& owned, geoshaping::Exchange& ex, std::string& refusal)
{
  const std::vector<std::uint8_t> claimed = std::move(owned);
  geoshaping::index_t coincident = 0;
  std::vector<std::int64_t> ids =
    geoshaping::coordinate_ids(xyz, geoshaping::index_t(n), claimed.data(), owned, ex, &coincident);
  refusal = geoshaping::coincident_points_refusal(coincident, ex);
  if (!refusal.empty())
    ids.clear();
  return ids;
}

bool vtkGeoShapingAdapter::IdentifyPiece(vtkDataSet* input, const double* xyz, bool globalIds,
  geoshaping::Exchange& ex, std::vector<std::int64_t>& ids, std::vector<std::uint8_t>& owned,
  std::string& refusal)
{
  const vtkIdType n = input->GetNumberOfPoints();
  owned = OwnedPoints(input);
  refusal.clear();
  if (!globalIds)
  {
    ids = CoordinateIds(xyz, n, owned, ex, refusal);
    return refusal.empty();
  }
  vtkDataArray* gids = PointGlobalIds(input);
  ids.assign(static_cast<std::size_t>(n), 0);
  for (vtkIdType i = 0; gids && i < n; ++i)
    ids[std::size_t(i)] = std::int64_t(gids->GetTuple1(i));
  return true;
}

geoshaping::Adjacency vtkGeoShapingAdapter::BuildAdjacency(
  vtkObject* self, vtkDataSet* input, const std::string& where, const char* consequence)
{
  vtkIdType skipped = 0;
  geoshaping::Adjacency adjacency = BuildAdjacency(input, skipped);
  if (skipped > 0)
  {
    vtkWarningWithObjectMacro(self, << where << skipped
                                    << " cells are of an unsupported type (higher-order or "
                                       "polyhedral) or have invalid point ids; "
                                    << consequence);
  }
  return adjacency;
}
