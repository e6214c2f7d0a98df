// The propagation order of vtkChainMailDeformationFilter on one process: point GlobalIds
// when the input has them, else the points' coordinate order, the numbering several
// processes use (coordinate_ids.h), so one process gives their result bit for bit.
#include "vtkChainMailDeformationFilter.h"

#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

namespace
{
// Rigid stripes in a soft grid turned by 30 degrees about z, pulled with the Link region: a
// mesh whose result depends on which sponsor wins inside a superstep, so on the ids.
vtkSmartPointer<vtkPolyData> StripedGrid()
{
  auto grid = geoshaping::testing::TriangleGridPolyData(
    25, 25, 1.0, [](int i, int j) { return (i + j) % 5 == 0 ? 0.2 : 0.8; });
  const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    grid->GetPoints()->SetPoint(i, c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]);
  }
  return grid;
}

// The grid's points deformed with `ids` as point GlobalIds (none when empty); the grasp
// is point 12 * 25 + 12, named by its id.
std::vector<double> Deformed(vtkPolyData* grid, const std::vector<vtkIdType>& ids)
{
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(grid);
  vtkIdType grasp = 12 * 25 + 12;
  if (!ids.empty())
  {
    vtkNew<vtkIdTypeArray> gids;
    gids->SetName("GlobalIds");
    gids->SetNumberOfTuples(vtkIdType(ids.size()));
    std::copy(ids.begin(), ids.end(), gids->GetPointer(0));
    mesh->GetPointData()->SetGlobalIds(gids);
    grasp = ids[std::size_t(grasp)];
  }
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetValidRegionFrame(vtkChainMailDeformationFilter::LINK);
  f->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO_PRIORITY);
  f->SetGraspPointId(grasp);
  f->SetDisplacement(3.0, -1.0, 6.0);
  f->SetInputData(mesh);
  f->Update();
  EXPECT_GT(f->GetNumberOfDisplacedPoints(), 50);
  vtkPointSet* out = f->GetOutput();
  std::vector<double> xyz(3 * std::size_t(out->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    out->GetPoint(i, xyz.data() + 3 * i);
  return xyz;
}
} // namespace

TEST(ChainMailOrder, WithoutGlobalIdsOneProcessOrdersByCoordinatesAsSeveralDo)
{
  auto grid = StripedGrid();
  const vtkIdType n = grid->GetNumberOfPoints();
  // The coordinate ranks, computed here directly: (x, y, z) sorted as numbers.
  std::vector<vtkIdType> byIndex(static_cast<std::size_t>(n)), order(byIndex.size()),
    byCoordinates(byIndex.size());
  std::iota(byIndex.begin(), byIndex.end(), 0);
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::array<double, 3>> x(byIndex.size());
  for (vtkIdType i = 0; i < n; ++i)
    grid->GetPoint(i, x[std::size_t(i)].data());
  std::sort(order.begin(), order.end(),
    [&x](vtkIdType a, vtkIdType b) { return x[std::size_t(a)] < x[std::size_t(b)]; });
  for (std::size_t r = 0; r < order.size(); ++r)
    byCoordinates[std::size_t(order[r])] = vtkIdType(r);
  ASSERT_NE(byCoordinates, byIndex); // the grid's points are not in coordinate order

  const std::vector<double> plain = Deformed(grid, {});
  EXPECT_EQ(plain, Deformed(grid, byCoordinates)) << "the coordinate ranks, bit for bit";
  // The order uses the ids only at exact ties of length (docs/deformer.md, "Order"),
  // which this scene has none of: the point indices as GlobalIds give the same bits too
  // (before the longest move won, they gave another frame).
  EXPECT_EQ(plain, Deformed(grid, byIndex)) << "the point indices as GlobalIds";
}

TEST(ChainMailOrder, CoincidentPointsStayApartOnOneProcess)
{
  // Two copies of a grid strip meeting along x = 12 without sharing a point (a split
  // node line, as across a fault): the copies' points at x = 12 coincide.
  auto left = geoshaping::testing::TriangleGridPolyData(13, 9, 1.0, [](int, int) { return 0.8; });
  auto right = geoshaping::testing::TriangleGridPolyData(
    13, 9, 1.0, [](int, int) { return 0.8; }, VTK_DOUBLE, 12.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (auto* part : { left.Get(), right.Get() })
    for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
      points->InsertNextPoint(part->GetPoint(i));
  vtkNew<vtkCellArray> cells;
  const vtkIdType offset = left->GetNumberOfPoints();
  for (auto* part : { left.Get(), right.Get() })
  {
    vtkNew<vtkIdList> cell;
    for (vtkIdType c = 0; c < part->GetNumberOfCells(); ++c)
    {
      part->GetCellPoints(c, cell);
      for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
        cell->SetId(k, cell->GetId(k) + (part == right.Get() ? offset : 0));
      cells->InsertNextCell(cell);
    }
  }
  vtkNew<vtkPolyData> split;
  split->SetPoints(points);
  split->SetPolys(cells);

  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetDefaultMalleability(0.8);
  f->SetGraspPointId(4 * 13 + 11); // left copy, next to the split line
  f->SetDisplacement(0.0, 0.0, 5.0);
  f->SetInputData(split);
  f->Update();
  EXPECT_GT(f->GetNumberOfDisplacedPoints(), 20);
  vtkPointSet* out = f->GetOutput();
  double a[3], b[3];
  out->GetPoint(4 * 13 + 12, a);         // left copy of the split line's point
  out->GetPoint(offset + 4 * 13 + 0, b); // right copy, at the same rest position
  EXPECT_NE(a[2], 0.0) << "the grasped side moves";
  EXPECT_EQ(b[2], 0.0) << "the other side does not: the coincident points stay apart";
  for (vtkIdType i = offset; i < out->GetNumberOfPoints(); ++i)
  {
    out->GetPoint(i, b);
    ASSERT_EQ(b[2], 0.0) << "point " << i << " of the other side moved";
  }
}
