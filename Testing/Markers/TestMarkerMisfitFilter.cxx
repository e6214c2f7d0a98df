// vtkMarkerMisfitFilter against misfits worked by hand (a tilted plane, a box) and against
// markers sampled on a real CRESCENT surface and moved by known amounts.
#include "marker_samples.h"
#include "vtkMarkerMisfitFilter.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkHexahedron.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
struct Result
{
  vtkSmartPointer<vtkPolyData> Output;
  std::string Errors, Warnings;
  double Value(const char* array, vtkIdType i) const
  {
    return this->Output->GetPointData()->GetArray(array)->GetTuple1(i);
  }
  double Field(const char* name) const
  {
    return this->Output->GetFieldData()->GetArray(name)->GetTuple1(0);
  }
};

Result Misfit(vtkDataObject* surface, vtkDataObject* markers)
{
  vtkNew<vtkMarkerMisfitFilter> filter;
  vtkNew<vtkTest::ErrorObserver> capture;
  filter->AddObserver(vtkCommand::ErrorEvent, capture);
  filter->AddObserver(vtkCommand::WarningEvent, capture);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, capture);
  filter->SetInputData(0, surface);
  filter->SetMarkersData(markers);
  filter->Update();
  return { filter->GetOutput(), capture->GetErrorMessage(), capture->GetWarningMessage() };
}

using markers_testing::Points;

// z = 0.1 x + 0.2 y + 5 over [0, 10]^2, 10 x 10 squares cut into triangles.
double Plane(double x, double y)
{
  return 0.1 * x + 0.2 * y + 5.0;
}

vtkSmartPointer<vtkPolyData> TiltedPlane()
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i)
      points->InsertNextPoint(i, j, Plane(i, j));
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i)
    {
      const vtkIdType a = j * 11 + i, b = a + 1, c = a + 11, d = c + 1;
      const vtkIdType t1[3] = { a, b, d }, t2[3] = { a, d, c };
      triangles->InsertNextCell(3, t1);
      triangles->InsertNextCell(3, t2);
    }
  auto plane = vtkSmartPointer<vtkPolyData>::New();
  plane->SetPoints(points);
  plane->SetPolys(triangles);
  return plane;
}
}

// Every marker whose foot lies inside the plane: VerticalMisfit = plane - z exactly, and
// Misfit = (plane - z) / |(-0.1, -0.2, 1)|, the signed distance along the upward normal.
TEST(MarkerMisfitFilter, TiltedPlaneGivesTheAnalyticMisfit)
{
  const std::vector<std::array<double, 3>> xyz = { { 5, 5, 9 }, { 3.3, 6.1, 2 },
    { 7.25, 2.5, Plane(7.25, 2.5) }, { 4, 4, 6.3 }, { 20, 5, 0 } };
  const Result r = Misfit(TiltedPlane(), Points(xyz));
  ASSERT_EQ(r.Errors, "");
  EXPECT_NE(r.Warnings.find("1 of 5 markers lie outside"), std::string::npos) << r.Warnings;
  const double norm = std::sqrt(0.01 + 0.04 + 1.0);
  double sum = 0.0, max = 0.0;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    const double dz = Plane(xyz[i][0], xyz[i][1]) - xyz[i][2];
    EXPECT_NEAR(r.Value("VerticalMisfit", i), dz, 1e-12) << i;
    EXPECT_NEAR(r.Value("Misfit", i), dz / norm, 1e-12) << i;
    EXPECT_EQ(r.Value("Inside", i), 1);
    sum += (dz / norm) * (dz / norm);
    max = std::max(max, std::abs(dz / norm));
  }
  EXPECT_EQ(r.Value("Inside", 4), 0);
  EXPECT_EQ(r.Value("VerticalMisfit", 4), 0);
  EXPECT_NEAR(r.Field("MisfitRMS"), std::sqrt(sum / 4), 1e-12);
  EXPECT_NEAR(r.Field("MisfitMax"), max, 1e-12);
  EXPECT_EQ(r.Field("MarkersInside"), 4);
  EXPECT_EQ(r.Output->GetNumberOfVerts(), 5);
}

// The same plane as an unstructured grid of triangles measures the same.
TEST(MarkerMisfitFilter, UnstructuredGridOfTrianglesMeasuresAsPolyData)
{
  const auto plane = TiltedPlane();
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(plane->GetPoints());
  grid->Allocate(plane->GetNumberOfCells());
  for (vtkIdType c = 0; c < plane->GetNumberOfCells(); ++c)
    grid->InsertNextCell(VTK_TRIANGLE, plane->GetCell(c)->GetPointIds());
  const auto markers = Points({ { 5, 5, 9 }, { 1.5, 8.5, 3 } });
  const Result a = Misfit(plane, markers), b = Misfit(grid, markers);
  ASSERT_EQ(b.Errors, "");
  for (vtkIdType i = 0; i < 2; ++i)
  {
    EXPECT_EQ(a.Value("Misfit", i), b.Value("Misfit", i));
    EXPECT_EQ(a.Value("VerticalMisfit", i), b.Value("VerticalMisfit", i));
  }
}

// A volume mesh is measured by its boundary: a unit cube, a marker 1 above its top face.
TEST(MarkerMisfitFilter, VolumeMeshIsMeasuredByItsBoundary)
{
  vtkNew<vtkPoints> points;
  const double corners[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  for (const auto& c : corners)
    points->InsertNextPoint(c);
  vtkNew<vtkUnstructuredGrid> cube;
  cube->SetPoints(points);
  const vtkIdType ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  cube->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
  const Result r = Misfit(cube, Points({ { 0.5, 0.25, 2 }, { 0.5, 0.5, 0.2 } }));
  ASSERT_EQ(r.Errors, "");
  EXPECT_NEAR(r.Value("VerticalMisfit", 0), -1.0, 1e-12); // the top face, nearer than z = 0
  EXPECT_NEAR(r.Value("Misfit", 0), -1.0, 1e-12);
  EXPECT_NEAR(r.Value("VerticalMisfit", 1), -0.2, 1e-12); // inside, 0.2 above the bottom
}

TEST(MarkerMisfitFilter, BadInputIsRefusedAndLeftUntouched)
{
  const auto plane = TiltedPlane();
  const auto markers = Points({ { 5, 5, 9 }, { 1, 1, std::numeric_limits<double>::quiet_NaN() } });
  const Result nan = Misfit(plane, markers);
  EXPECT_NE(nan.Errors.find("Marker 1 of 2 has a non-finite coordinate"), std::string::npos)
    << nan.Errors;
  EXPECT_EQ(nan.Output->GetNumberOfPoints(), 0);
  EXPECT_EQ(markers->GetPointData()->GetNumberOfArrays(), 0); // the input is untouched
  EXPECT_EQ(markers->GetPoint(0)[2], 9);

  const Result flat = Misfit(Points({ { 0, 0, 0 }, { 1, 0, 0 } }), Points({ { 0, 0, 1 } }));
  EXPECT_NE(flat.Errors.find("has no polygons"), std::string::npos) << flat.Errors;
  EXPECT_EQ(flat.Output->GetNumberOfPoints(), 0);

  vtkNew<vtkMarkerMisfitFilter> noMarkers;
  vtkNew<vtkTest::ErrorObserver> capture;
  noMarkers->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, capture);
  noMarkers->AddObserver(vtkCommand::ErrorEvent, capture);
  noMarkers->SetInputData(0, plane);
  noMarkers->Update();
  EXPECT_TRUE(capture->GetError());

  // No markers is a normal case (a piece of a distributed set holds none): no error.
  const Result empty = Misfit(plane, Points({}));
  EXPECT_EQ(empty.Errors, "");
  EXPECT_EQ(empty.Output->GetNumberOfPoints(), 0);
  EXPECT_EQ(empty.Field("MisfitRMS"), 0);
}

// A real horizon-like surface (the Cascadia subduction interface, CRESCENT, CC BY 4.0):
// markers at random points of random triangles lie on it (misfit ~ 0); moved by dz along
// z they read VerticalMisfit = -dz and |Misfit| <= |dz| with the opposite sign.
TEST(MarkerMisfitFilter, MarkersSampledOnARealSurfaceReadTheirKnownOffsets)
{
  std::string path;
  const auto samples = markers_testing::SampleCascadia(7, 200, 50, 1.0, path);
  if (!samples.surface)
    GTEST_SKIP() << "CRESCENT data absent: " << path;
  const auto& dz = samples.dz;
  const double size = samples.size;
  const Result r = Misfit(samples.surface, Points(samples.xyz));
  ASSERT_EQ(r.Errors, "");
  const double tolerance = 1e-9 * size;
  for (vtkIdType i = 0; i < 200; ++i)
  {
    ASSERT_EQ(r.Value("Inside", i), 1) << i;
    EXPECT_NEAR(r.Value("VerticalMisfit", i), -dz[i], tolerance) << i;
    const double misfit = r.Value("Misfit", i);
    EXPECT_LE(std::abs(misfit), std::abs(dz[i]) + tolerance) << i;
    if (std::abs(dz[i]) > tolerance)
      EXPECT_LT(misfit * dz[i], 0.0) << i;
  }
}
