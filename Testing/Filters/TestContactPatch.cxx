// vtkGeoShapingContactPatch::AppendTrianglesNear (the haptic contact patch's rule, the
// client's and the server's) against a brute-force scan of every cell's bounds; the
// filter on one process, ghost cells left out.
#include "vtkGeoShapingContactPatch.h"

#include "vtk_test_meshes.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkTestErrorObserver.h"
#include "vtkTriangle.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
// Triangles a cell of this type with n points gives, the way the contact patch cuts it.
int trianglesOf(int type, vtkIdType n)
{
  switch (type)
  {
    case VTK_TRIANGLE:
    case VTK_QUAD:
    case VTK_POLYGON:
    case VTK_TRIANGLE_STRIP:
      return int(n - 2);
    case VTK_PIXEL:
      return 2;
    default:
      return 0;
  }
}

vtkIdType bruteForce(vtkDataSet* data, const double c[3], double r)
{
  const vtkBoundingBox query(c[0] - r, c[0] + r, c[1] - r, c[1] + r, c[2] - r, c[2] + r);
  vtkIdType count = 0;
  for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell)
  {
    double b[6];
    data->GetCellBounds(cell, b);
    if (query.Intersects(vtkBoundingBox(b)))
    {
      count += trianglesOf(data->GetCellType(cell), data->GetCell(cell)->GetNumberOfPoints());
    }
  }
  return count;
}
} // namespace

TEST(ContactPatch, TrianglesNearAPointAreThoseABruteForceScanFinds)
{
  // A 40 x 30 triangle grid plus, beside it, a quad, a pentagon, a pixel, a strip of
  // 5 points and a line (skipped).
  auto grid = geoshaping::testing::TriangleGridPolyData(40, 30, 1.0, {});
  vtkPoints* points = grid->GetPoints();
  auto add = [&](std::initializer_list<std::array<double, 3>> ps)
  {
    std::vector<vtkIdType> ids;
    for (const auto& p : ps)
      ids.push_back(points->InsertNextPoint(p.data()));
    return ids;
  };
  vtkNew<vtkCellArray> polys, strips, lines;
  polys->DeepCopy(grid->GetPolys());
  auto quad = add({ { 41, 0, 0 }, { 42, 0, 0 }, { 42, 1, 0 }, { 41, 1, 0 } });
  polys->InsertNextCell(4, quad.data());
  auto pentagon = add({ { 41, 2, 0 }, { 42, 2, 0 }, { 42.5, 3, 0 }, { 41.5, 4, 0 }, { 41, 3, 0 } });
  polys->InsertNextCell(5, pentagon.data());
  auto strip = add({ { 41, 5, 0 }, { 41, 6, 0 }, { 42, 5, 0 }, { 42, 6, 0 }, { 43, 5, 0 } });
  strips->InsertNextCell(5, strip.data());
  auto line = add({ { 41, 8, 0 }, { 43, 8, 0 } });
  lines->InsertNextCell(2, line.data());
  grid->SetPolys(polys);
  grid->SetStrips(strips);
  grid->SetLines(lines);

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(grid);
  locator->BuildLocator();
  for (const auto& query : std::vector<std::array<double, 4>>{ { 10.2, 10.7, 0.0, 2.5 },
         { 41.5, 4.0, 0.3, 2.0 }, { 41.5, 7.5, 0.0, 1.0 }, { 0.0, 0.0, 0.0, 0.4 },
         { 100.0, 100.0, 0.0, 3.0 }, { 20.0, 15.0, 5.0, 4.0 } })
  {
    std::vector<double> xyz = { 1.0, 2.0 }; // appended to, not replaced
    const vtkIdType n =
      vtkGeoShapingContactPatch::AppendTrianglesNear(grid, locator, query.data(), query[3], xyz);
    EXPECT_EQ(n, bruteForce(grid, query.data(), query[3])) << query[0] << " " << query[1];
    ASSERT_EQ(xyz.size(), 2 + 9 * std::size_t(n));
    EXPECT_EQ(xyz[0], 1.0);
    for (std::size_t t = 0; t < std::size_t(n); ++t)
    {
      // every triangle is a real one: non-degenerate, its corners near the query box
      const double* a = &xyz[2 + 9 * t];
      const double e1[2] = { a[3] - a[0], a[4] - a[1] }, e2[2] = { a[6] - a[0], a[7] - a[1] };
      EXPECT_GT(std::abs(e1[0] * e2[1] - e1[1] * e2[0]), 0.1) << t;
    }
  }
  const double c[3] = { 10.2, 10.7, 0.0 };
  std::vector<double> xyz;
  // 2.5 around (10.2, 10.7) on a unit grid: 6 x 6 squares (x 8..13, y 8..13 once
  // bounds touching the box count), 2 triangles each
  EXPECT_EQ(vtkGeoShapingContactPatch::AppendTrianglesNear(grid, locator, c, 2.5, xyz), 2 * 6 * 6);
  EXPECT_EQ(vtkGeoShapingContactPatch::AppendTrianglesNear(grid, locator, c, std::nan(""), xyz), 0);
  EXPECT_EQ(vtkGeoShapingContactPatch::AppendTrianglesNear(grid, locator, c, -1.0, xyz), 0);
  EXPECT_EQ(vtkGeoShapingContactPatch::AppendTrianglesNear(nullptr, locator, c, 1.0, xyz), 0);
}

TEST(ContactPatch, VolumeCellsGiveNoContactTriangles)
{
  vtkNew<vtkPoints> p;
  p->InsertNextPoint(0, 0, 0);
  p->InsertNextPoint(1, 0, 0);
  p->InsertNextPoint(0, 1, 0);
  p->InsertNextPoint(0, 0, 1);
  vtkNew<vtkUnstructuredGrid> ug;
  ug->SetPoints(p);
  const vtkIdType tet[4] = { 0, 1, 2, 3 };
  ug->InsertNextCell(VTK_TETRA, 4, tet);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(ug);
  locator->BuildLocator();
  const double c[3] = { 0.2, 0.2, 0.2 };
  std::vector<double> xyz;
  EXPECT_EQ(vtkGeoShapingContactPatch::AppendTrianglesNear(ug, locator, c, 1.0, xyz), 0);
  EXPECT_TRUE(xyz.empty());
}

TEST(ContactPatch, TheFilterSendsTheOwnedTrianglesOnce)
{
  // A 20 x 10 unit grid whose cells with x < 5 are ghosts (another process owns them):
  // the filter (one process, no gather) sends the owned triangles of the box only,
  // those the rule gives with ownedOnly, and the rule without it gives the ghosts too.
  auto grid = geoshaping::testing::TriangleGridPolyData(20, 10, 1.0, {});
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(grid->GetNumberOfCells());
  vtkIdType ghostCells = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    double b[6];
    grid->GetCellBounds(c, b);
    const bool ghost = b[1] <= 5.0;
    ghosts->SetValue(c, ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
    ghostCells += ghost ? 1 : 0;
  }
  grid->GetCellData()->AddArray(ghosts);
  ASSERT_GT(ghostCells, 0);
  vtkNew<vtkGeoShapingContactPatch> patch;
  patch->SetInputData(grid);
  patch->SetCenter(5.5, 5.5, 0.0);
  patch->SetRadius(2.0);
  patch->Update();
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(grid);
  locator->BuildLocator();
  const double c[3] = { 5.5, 5.5, 0.0 };
  std::vector<double> owned, all;
  const vtkIdType n =
    vtkGeoShapingContactPatch::AppendTrianglesNear(grid, locator, c, 2.0, owned, true);
  // the box x, y in [3.5, 7.5] meets the squares 3..7 each way, 2 triangles a square;
  // the columns 5..7 are owned
  EXPECT_EQ(vtkGeoShapingContactPatch::AppendTrianglesNear(grid, locator, c, 2.0, all), 2 * 5 * 5);
  EXPECT_EQ(n, 2 * 3 * 5);
  ASSERT_EQ(patch->GetTriangles()->GetNumberOfValues(), vtkIdType(owned.size()));
  for (std::size_t i = 0; i < owned.size(); ++i)
  {
    EXPECT_EQ(patch->GetTriangles()->GetValue(vtkIdType(i)), owned[i]);
    if (i % 3 == 0)
    {
      EXPECT_GE(owned[i], 5.0) << "a ghost triangle was sent";
    }
  }
  // A moved stylus re-executes; an empty input gives an empty patch.
  patch->SetCenter(100.0, 100.0, 0.0);
  patch->Update();
  EXPECT_EQ(patch->GetTriangles()->GetNumberOfValues(), 0);
  vtkNew<vtkPolyData> empty;
  patch->SetInputData(empty);
  patch->SetCenter(5.0, 5.0, 0.0);
  patch->Update();
  EXPECT_EQ(patch->GetTriangles()->GetNumberOfValues(), 0);
}

TEST(ContactPatch, AStylusNotFiniteIsAnErrorAndNoTriangles)
{
  auto grid = geoshaping::testing::TriangleGridPolyData(20, 10, 1.0, {});
  const double x = grid->GetPoint(7)[0];
  vtkNew<vtkGeoShapingContactPatch> patch;
  vtkNew<vtkTest::ErrorObserver> observer;
  patch->AddObserver(vtkCommand::ErrorEvent, observer);
  patch->SetInputData(grid);
  patch->SetRadius(2.0);
  for (const std::array<double, 4>& bad :
    std::vector<std::array<double, 4>>{ { std::nan(""), 5.0, 0.0, 2.0 },
      { 5.0, 5.0, INFINITY, 2.0 }, { 5.0, 5.0, 0.0, -1.0 }, { 5.0, 5.0, 0.0, std::nan("") } })
  {
    observer->Clear();
    patch->SetCenter(bad[0], bad[1], bad[2]);
    patch->SetRadius(bad[3]);
    patch->Update();
    EXPECT_EQ(patch->GetTriangles()->GetNumberOfValues(), 0);
    EXPECT_NE(observer->GetErrorMessage().find("no triangles"), std::string::npos)
      << observer->GetErrorMessage();
  }
  EXPECT_EQ(grid->GetPoint(7)[0], x); // the input untouched
  observer->Clear();
  patch->SetCenter(5.5, 5.5, 0.0);
  patch->SetRadius(2.0);
  patch->Update();
  EXPECT_EQ(patch->GetTriangles()->GetNumberOfValues(), 9 * 2 * 5 * 5);
  EXPECT_TRUE(observer->GetErrorMessage().empty());
}

TEST(ContactPatch, MaxTrianglesKeepsTheNearest)
{
  // 10 of the box's triangles: each kept one no farther from the centre than any left
  // out (distances by vtkTriangle, not the haptics layer's rule the filter uses).
  auto grid = geoshaping::testing::TriangleGridPolyData(20, 10, 1.0, {});
  vtkNew<vtkGeoShapingContactPatch> patch;
  patch->SetInputData(grid);
  patch->SetCenter(5.3, 4.6, 0.5);
  patch->SetRadius(3.0);
  patch->Update();
  const vtkIdType all = patch->GetTriangles()->GetNumberOfValues() / 9;
  patch->SetMaxTriangles(10);
  patch->Update();
  vtkDoubleArray* kept = patch->GetTriangles();
  ASSERT_EQ(kept->GetNumberOfValues(), 9 * 10);
  ASSERT_GT(all, 10);
  auto distance = [&](const double* t)
  {
    vtkNew<vtkTriangle> triangle;
    for (int i = 0; i < 3; ++i)
      triangle->GetPoints()->SetPoint(i, t + 3 * i);
    double closest[3], pcoords[3], d2, weights[3];
    int sub;
    triangle->EvaluatePosition(patch->GetCenter(), closest, sub, pcoords, d2, weights);
    return d2;
  };
  double farthestKept = 0.0;
  std::vector<std::array<double, 9>> keptTriangles;
  for (vtkIdType t = 0; t < 10; ++t)
  {
    farthestKept = std::max(farthestKept, distance(kept->GetPointer(9 * t)));
    std::array<double, 9> a;
    std::copy(kept->GetPointer(9 * t), kept->GetPointer(9 * t) + 9, a.begin());
    keptTriangles.push_back(a);
  }
  patch->SetMaxTriangles(0);
  patch->Update();
  vtkDoubleArray* every = patch->GetTriangles();
  int found = 0;
  for (vtkIdType t = 0; t < all; ++t)
  {
    std::array<double, 9> a;
    std::copy(every->GetPointer(9 * t), every->GetPointer(9 * t) + 9, a.begin());
    if (std::find(keptTriangles.begin(), keptTriangles.end(), a) != keptTriangles.end())
      ++found;
    else
      EXPECT_GE(distance(a.data()), farthestKept - 1e-12) << "a nearer triangle was left out";
  }
  EXPECT_EQ(found, 10);
}
