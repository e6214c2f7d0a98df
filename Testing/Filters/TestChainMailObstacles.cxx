// vtkChainMailDeformationFilter with obstacles on port 1 (docs/obstacles.md): paths
// checked against planes computed here, polydata and unstructured grids on both ports,
// and bad obstacles (an error, the input untouched).
#include "vtkChainMailDeformationFilter.h"

#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPassThrough.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace
{
using geoshaping::testing::TetSlabUnstructuredGrid;
using geoshaping::testing::TriangleGridPolyData;

// A triangle grid of n x n points mapped by (i, j) -> o + i du + j dv.
vtkSmartPointer<vtkPolyData> Sheet(int n, const double o[3], const double du[3], const double dv[3])
{
  auto sheet = TriangleGridPolyData(n, n, 1.0, {});
  vtkPoints* points = sheet->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    const double i = x[0], j = x[1];
    points->SetPoint(
      p, o[0] + i * du[0] + j * dv[0], o[1] + i * du[1] + j * dv[1], o[2] + i * du[2] + j * dv[2]);
  }
  return sheet;
}

vtkPointSet* Update(vtkChainMailDeformationFilter* f)
{
  f->Update();
  return vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
}

// Whether a and b hold the same points, coordinate for coordinate.
bool SamePoints(vtkPointSet* a, vtkPointSet* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
    return false;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    if (!(x[0] == y[0] && x[1] == y[1] && x[2] == y[2]))
      return false;
  }
  return true;
}

// Updates f, which must refuse: an error holding `says`, and the input as the output.
vtkPointSet* ExpectRefused(vtkChainMailDeformationFilter* f, vtkTest::ErrorObserver* errors,
  const std::string& says, vtkPointSet* input)
{
  vtkPointSet* out = Update(f);
  EXPECT_NE(errors->GetErrorMessage().find(says), std::string::npos) << errors->GetErrorMessage();
  EXPECT_TRUE(SamePoints(out, input));
  return out;
}
// Horizon x in [0, 10], y in [0, 20] (spacing 1), its last column x = 10 flagged in the
// point array "OnFault"; and the fault x = 10 - 0.5 z under it (a 9 x 9 sheet).
vtkSmartPointer<vtkPolyData> CutOffHorizon()
{
  auto horizon = TriangleGridPolyData(11, 21, 1.0, {});
  vtkNew<vtkUnsignedCharArray> onFault;
  onFault->SetName("OnFault");
  onFault->SetNumberOfTuples(horizon->GetNumberOfPoints());
  onFault->Fill(0);
  for (int j = 0; j < 21; ++j)
    onFault->SetValue(j * 11 + 10, 1);
  horizon->GetPointData()->AddArray(onFault);
  return horizon;
}

vtkSmartPointer<vtkPolyData> DippingFault()
{
  const double o[3] = { 15, -5, -10 }, du[3] = { 0, 30.0 / 8, 0 },
               dv[3] = { -10.0 / 8, 0, 20.0 / 8 };
  return Sheet(9, o, du, dv);
}

// The loop tests' scene: a 6 x 6 horizon, vertex 14 pulled up by 3, errors caught, and a
// pass-through of the filter's own output (`loop`) for the test to connect back into it.
struct LoopScene
{
  vtkSmartPointer<vtkPolyData> horizon = TriangleGridPolyData(6, 6, 1.0, {});
  vtkNew<vtkChainMailDeformationFilter> f;
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkPassThrough> loop;
  LoopScene()
  {
    f->AddObserver(vtkCommand::ErrorEvent, errors);
    f->SetInputData(horizon);
    f->SetGraspPointId(14);
    f->SetDisplacement(0, 0, 3);
    loop->SetInputConnection(f->GetOutputPort());
  }
  // Updates the filter with the loop connected: refused with an error holding `message`,
  // the output the undeformed horizon, and the pass-through downstream of the loop
  // updates to it too.
  void Refused(const std::string& message)
  {
    ExpectRefused(f, errors, message, horizon);
    loop->Update();
    double x[3];
    vtkPointSet::SafeDownCast(loop->GetOutputDataObject(0))->GetPoint(14, x);
    EXPECT_EQ(x[2], 0.0);
  }
  // Updates the filter with no loop: no error, and vertex 14 pulled up by 3.
  void Pulled()
  {
    errors->Clear();
    vtkPointSet* out = Update(f);
    EXPECT_EQ(errors->GetErrorMessage(), "");
    double x[3];
    out->GetPoint(14, x);
    EXPECT_EQ(x[2], 3.0);
  }
};
} // namespace

TEST(ChainMailObstacles, HorizonPulledDownStopsAboveTheLowerHorizon)
{
  // Horizon 21 x 21 at z = 0; lower horizon z = -3 over [-5, 25]^2 (one plane: a path
  // crosses it exactly when it ends below z = -3, the horizon starting above).
  auto horizon = TriangleGridPolyData(21, 21, 1.0, {});
  const double o[3] = { -5, -5, -3 }, du[3] = { 1, 0, 0 }, dv[3] = { 0, 1, 0 };
  auto lower = Sheet(31, o, du, dv);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(horizon);
  f->SetGraspPointId(10 * 21 + 10);
  f->SetDisplacement(0, 0, -10);
  auto unobstructed = vtk::TakeSmartPointer(Update(f)->NewInstance());
  unobstructed->DeepCopy(f->GetOutputDataObject(0));
  EXPECT_FALSE(f->GetLastGraspBlocked());
  EXPECT_EQ(f->GetLastGraspObstacleFraction(), 1.0);

  f->AddObstacleData(lower);
  EXPECT_EQ(f->GetNumberOfObstacleConnections(), 1);
  vtkPointSet* out = Update(f);
  EXPECT_TRUE(f->GetLastGraspBlocked());
  EXPECT_NEAR(f->GetLastGraspObstacleFraction(), 0.3, 1e-8);
  double lowest = 0.0, x[3];
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    out->GetPoint(p, x);
    EXPECT_GT(x[2], -3.0) << p;
    lowest = std::min(lowest, x[2]);
  }
  EXPECT_LT(lowest, -3.0 + 1e-6);
  unobstructed->GetPoint(10 * 21 + 10, x);
  EXPECT_EQ(x[2], -10.0);

  // Disconnected: today's output bit for bit, and the obstacle's tree rebuilt only when
  // the obstacle changes.
  f->RemoveAllObstacleConnections();
  out = Update(f);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    out->GetPoint(p, a);
    unobstructed->GetPoint(p, b);
    ASSERT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << p;
  }
}

TEST(ChainMailObstacles, RefinementAndRelaxationKeepTheHorizonAboveTheLowerOne)
{
  // The horizon pulled down onto the lower horizon z = -3 + 0.2 (x - 10), refined and
  // relaxed: every vertex stays above it (the plane, computed here).
  auto horizon = TriangleGridPolyData(21, 21, 1.0, {});
  const double o[3] = { -5, -5, -6 }, du[3] = { 2.5, 0, 0.5 }, dv[3] = { 0, 2.5, 0 };
  auto lower = Sheet(13, o, du, dv);
  vtkNew<vtkChainMailDeformationFilter> f;
  vtkNew<vtkTest::ErrorObserver> errors;
  f->AddObserver(vtkCommand::ErrorEvent, errors);
  f->SetInputData(horizon);
  f->AddObstacleData(lower);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->SetGraspPointId(10 * 21 + 10);
  f->SetDisplacement(0, 0, -10);
  // Stretch 1.5, compression 0.75, shear 0.05 at every malleability, as in
  // Core.ObstaclePasses.
  const double tkh[3] = { 1.5, 0.75, 0.05 };
  vtkNew<vtkPiecewiseFunction> functions[3];
  for (int i = 0; i < 3; ++i)
  {
    functions[i]->AddPoint(0.0, tkh[i]);
    functions[i]->AddPoint(1.0, tkh[i]);
  }
  f->SetStretchFunction(functions[0]);
  f->SetCompressionFunction(functions[1]);
  f->SetShearFunction(functions[2]);
  Update(f);
  const vtkIdType frameHeld = f->GetNumberOfObstacleBlockedPoints();
  EXPECT_GT(frameHeld, 0);
  EXPECT_EQ(f->GetNumberOfPassObstacleBlockedPoints(), 0);
  f->SetRefinementIterations(64);
  f->SetRelaxationIterations(50);
  vtkPointSet* out = Update(f);
  EXPECT_TRUE(errors->GetErrorMessage().empty()) << errors->GetErrorMessage();
  EXPECT_GT(f->GetNumberOfRefinedPoints(), 0);
  EXPECT_GT(f->GetNumberOfRelaxedPoints(), 0);
  // Everything held back is said: the frame's (the same frame as without the passes)
  // and the passes' gate's.
  EXPECT_GT(f->GetNumberOfPassObstacleBlockedPoints(), 0);
  EXPECT_EQ(
    f->GetNumberOfObstacleBlockedPoints(), frameHeld + f->GetNumberOfPassObstacleBlockedPoints());
  double x[3], lowest = 0.0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    out->GetPoint(p, x);
    EXPECT_GT(x[2], -3.0 + 0.2 * (x[0] - 10.0)) << p;
    lowest = std::min(lowest, x[2]);
  }
  EXPECT_LT(lowest, -2.0);
}

TEST(ChainMailObstacles, ACommitStoresTheStoppedShapeAndTheNextDragStartsFromIt)
{
  auto horizon = TriangleGridPolyData(21, 21, 1.0, {});
  const double o[3] = { -5, -5, -3 }, du[3] = { 1, 0, 0 }, dv[3] = { 0, 1, 0 };
  auto lower = Sheet(31, o, du, dv);
  auto points = [](vtkPointSet* data)
  {
    std::vector<double> xyz(std::size_t(3 * data->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
      data->GetPoint(p, xyz.data() + 3 * p);
    return xyz;
  };
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(horizon);
  f->AddObstacleData(lower);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->SetGraspPointId(10 * 21 + 10);
  f->SetDisplacement(0, 0, -10);
  const std::vector<double> stopped = points(Update(f));
  ASSERT_TRUE(f->GetLastGraspBlocked());
  f->CommitEdit();
  f->SetGraspPointId(-1);
  f->SetDisplacement(0, 0, 0);
  EXPECT_EQ(points(Update(f)), stopped) << "the committed shape is the stopped one";

  // The record holds the stopped shape itself: a fresh filter without obstacles
  // reproduces it bit for bit.
  vtkNew<vtkChainMailDeformationFilter> fresh;
  fresh->SetInputData(horizon);
  fresh->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  fresh->AddEdit(f->GetLastEdit());
  EXPECT_EQ(points(Update(fresh)), stopped);

  // Dragging on from the committed shape: the stopped vertices rest just above the
  // lower horizon and cannot be pushed through it.
  f->SetGraspPointId(10 * 21 + 10);
  f->SetDisplacement(0.5, 0, -5);
  const std::vector<double> again = points(Update(f));
  EXPECT_TRUE(f->GetLastGraspBlocked());
  EXPECT_LT(f->GetLastGraspObstacleFraction(), 1e-6);
  for (std::size_t p = 0; p < again.size() / 3; ++p)
    EXPECT_GT(again[3 * p + 2], -3.0) << p;
}

TEST(ChainMailObstacles, TetrahedralSlabPushedIntoADippingFaultAndABlock)
{
  // Slab x, y in [0, 5], z in [0, 2]; fault x = 7 + 0.25 z (polydata); a block of
  // tetrahedra (an unstructured grid obstacle: its boundary) at y in [8, 10].
  auto slab = TetSlabUnstructuredGrid(6, 6, 3, 1.0, {});
  const double o[3] = { 7 - 2.5, -5, -10 }, du[3] = { 0, 1, 0 }, dv[3] = { 0.25, 0, 1 };
  auto fault = Sheet(21, o, du, dv);
  auto block = TetSlabUnstructuredGrid(4, 4, 4, 1.0, {});
  for (vtkIdType p = 0; p < block->GetNumberOfPoints(); ++p)
  {
    double x[3];
    block->GetPoint(p, x);
    block->GetPoints()->SetPoint(p, x[0] + 1, x[1] + 8, x[2] - 0.5);
  }
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(slab);
  f->AddObstacleData(fault);
  f->AddObstacleData(block);
  struct Push
  {
    vtkIdType grasp;
    std::array<double, 3> d;
    double fraction;
  };
  // (5, 2, 1) toward the fault at x = 7.25; (2, 5, 1) toward the block's face y = 8.
  for (const Push& push : { Push{ 1 * 36 + 2 * 6 + 5, { 6, 0, 0 }, 2.25 / 6 },
         Push{ 1 * 36 + 5 * 6 + 2, { 0, 8, 0 }, 3.0 / 8 } })
  {
    f->SetGraspPointId(push.grasp);
    f->SetDisplacement(push.d.data());
    vtkPointSet* out = Update(f);
    ASSERT_EQ(out->GetNumberOfPoints(), slab->GetNumberOfPoints());
    EXPECT_TRUE(f->GetLastGraspBlocked());
    EXPECT_NEAR(f->GetLastGraspObstacleFraction(), push.fraction, 1e-8);
    EXPECT_LT(f->GetLastGraspObstacleFraction(), push.fraction);
    for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    {
      double x[3], r[3];
      out->GetPoint(p, x);
      slab->GetPoint(p, r);
      EXPECT_LT(x[0], 7.0 + 0.25 * x[2]) << p; // the fault, every point starting before it
      // The block's near face y = 8 spans x in [1, 4], z in [-0.5, 2.5]; a path may end
      // on it (touching is not crossing).
      if (r[0] >= 1 && r[0] <= 4)
        EXPECT_LE(x[1], 8.0) << p;
    }
  }
}

TEST(ChainMailObstacles, BadObstaclesAreRefusedAndTheInputIsUntouched)
{
  auto horizon = TriangleGridPolyData(6, 6, 1.0, {});
  const double o[3] = { -1, -1, -1 }, du[3] = { 1, 0, 0 }, dv[3] = { 0, 1, 0 };
  auto nan = Sheet(8, o, du, dv);
  nan->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0, -1);
  vtkNew<vtkPolyData> lines;
  lines->SetPoints(Sheet(8, o, du, dv)->GetPoints());
  vtkNew<vtkCellArray> cells;
  const vtkIdType line[2] = { 0, 1 };
  cells->InsertNextCell(2, line);
  lines->SetLines(cells);
  auto good = Sheet(8, o, du, dv);
  struct Case
  {
    vtkPolyData* obstacle;
    const char* says;
  };
  for (const Case& c : { Case{ nan, "non-finite" }, Case{ lines, "no triangles" } })
  {
    vtkNew<vtkChainMailDeformationFilter> f;
    vtkNew<vtkTest::ErrorObserver> errors;
    f->AddObserver(vtkCommand::ErrorEvent, errors);
    f->SetInputData(horizon);
    f->AddObstacleData(good);
    f->AddObstacleData(c.obstacle);
    f->SetGraspPointId(14);
    f->SetDisplacement(0, 0, -3);
    ExpectRefused(f, errors, c.says, horizon);
  }
  // A NaN clearance is refused.
  for (const char* says : { "ObstacleClearance" })
  {
    vtkNew<vtkChainMailDeformationFilter> f;
    vtkNew<vtkTest::ErrorObserver> errors;
    f->AddObserver(vtkCommand::ErrorEvent, errors);
    f->SetInputData(horizon);
    f->AddObstacleData(good);
    f->SetObstacleClearance(std::numeric_limits<double>::quiet_NaN());
    f->SetGraspPointId(14);
    f->SetDisplacement(0, 0, -3);
    vtkPointSet* out = Update(f);
    EXPECT_NE(errors->GetErrorMessage().find(says), std::string::npos);
    double x[3];
    out->GetPoint(14, x);
    EXPECT_EQ(x[2], 0.0);
  }
}

TEST(ChainMailObstacles, SlidingArrayKeepsTheCutOffLineOnTheFault)
{
  // Horizon x in [0, 10], y in [0, 20] cut off at x = 10 by the fault x = 10 - 0.5 z,
  // leaning away below it; the last column ("OnFault") lies on the fault. Pulled down,
  // that column slides down the fault, at distance 0 from it (computed here from the
  // plane) within 1e-9 of the mean edge length (>= 1, the grid's spacing).
  auto horizon = CutOffHorizon();
  auto fault = DippingFault();
  auto* onFault = vtkUnsignedCharArray::SafeDownCast(horizon->GetPointData()->GetArray("OnFault"));
  auto fromFault = [](const double x[3]) { return (x[0] + 0.5 * x[2] - 10.0) / std::sqrt(1.25); };

  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(horizon);
  f->AddObstacleData(fault);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->SetStretchRange(1.5, 1.5);
  f->SetCompressionRange(0.75, 0.75);
  f->SetShearRange(0.05, 0.05);
  f->SetGraspPointId(10 * 11 + 5);
  f->SetDisplacement(0, 0, -4);
  // Unflagged, the column leaves the fault (touching is not crossing).
  vtkPointSet* out = Update(f);
  double x[3];
  out->GetPoint(10 * 11 + 10, x);
  EXPECT_GT(std::abs(fromFault(x)), 0.5);

  f->SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "OnFault");
  out = Update(f);
  EXPECT_EQ(f->GetLastGraspObstacleFraction(), 1.0);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    out->GetPoint(p, x);
    if (onFault->GetValue(p))
    {
      EXPECT_LE(std::abs(fromFault(x)), 1e-9) << p;
      EXPECT_LT(x[2], p == 10 * 11 + 10 ? -2.0 : -0.25) << p; // down along the fault
    }
    else
      EXPECT_LT(fromFault(x), 0.0) << p; // on the horizon's side
  }

  // A sliding mask with a value per cell is refused: an error, the input untouched.
  vtkNew<vtkUnsignedCharArray> perCell;
  perCell->SetName("PerCell");
  perCell->SetNumberOfTuples(5);
  perCell->Fill(1);
  horizon->GetPointData()->AddArray(perCell);
  vtkNew<vtkTest::ErrorObserver> errors;
  f->AddObserver(vtkCommand::ErrorEvent, errors);
  f->SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "PerCell");
  out = Update(f);
  EXPECT_NE(errors->GetErrorMessage().find("Sliding array 'PerCell' must be"), std::string::npos)
    << errors->GetErrorMessage();
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double r[3];
    out->GetPoint(p, x);
    horizon->GetPoint(p, r);
    ASSERT_TRUE(x[0] == r[0] && x[1] == r[1] && x[2] == r[2]) << p;
  }
}

TEST(ChainMailObstacles, LastGraspDisplacementSaysWhereTheGraspLanded)
{
  // The horizon of SlidingArrayKeepsTheCutOffLineOnTheFault, grasped on its cut-off line
  // (sliding) and pulled straight down: the grasp slides down the fault x = 10 - 0.5 z,
  // fraction 1, but lands off rest + Displacement, on the fault's plane (computed here).
  auto horizon = CutOffHorizon();
  auto fault = DippingFault();
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(horizon);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  const vtkIdType grasp = 10 * 11 + 10;
  f->SetGraspPointId(grasp);
  f->SetDisplacement(0, 0, -4);
  // No grasp yet: NaN. Free: Displacement, bit for bit.
  EXPECT_TRUE(std::isnan(f->GetLastGraspDisplacement()[0]));
  Update(f);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(f->GetLastGraspDisplacement()[k], f->GetDisplacement()[k]) << k;

  f->AddObstacleData(fault);
  f->SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "OnFault");
  vtkPointSet* out = Update(f);
  EXPECT_EQ(f->GetLastGraspObstacleFraction(), 1.0);
  double x[3], rest[3];
  out->GetPoint(grasp, x);
  horizon->GetPoint(grasp, rest);
  const double* landed = f->GetLastGraspDisplacement();
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(landed[k], x[k] - rest[k]) << k;
  // On the fault, and not where the stylus put it: the projection of (10, 10, -4) onto
  // the plane x + 0.5 z = 10 is (10, 10, -4) + 1.6 (1, 0, 0.5).
  EXPECT_NEAR(x[0] + 0.5 * x[2], 10.0, 1e-9);
  EXPECT_NEAR(landed[0], 1.6, 1e-9);
  EXPECT_NEAR(landed[1], 0.0, 1e-9);
  EXPECT_NEAR(landed[2], -3.2, 1e-9);
}

TEST(ChainMailObstacles, AnEmptyConnectionIsNoObstacleAndTheHeldBackCountIsInTheFieldData)
{
  // An empty data set on port 1 (the panel's Pipeline Connection with nothing chosen) is
  // no obstacle: beside the lower horizon the pull stops where it stops without it, and
  // alone the pull goes through as with no connection. The count held back is in the
  // output's field data, equal to NumberOfObstacleBlockedPoints.
  auto horizon = TriangleGridPolyData(21, 21, 1.0, {});
  const double o[3] = { -5, -5, -3 }, du[3] = { 1, 0, 0 }, dv[3] = { 0, 1, 0 };
  auto lower = Sheet(31, o, du, dv);
  vtkNew<vtkPolyData> empty;
  auto run = [&](std::initializer_list<vtkPolyData*> obstacles, vtkIdType& held)
  {
    vtkNew<vtkChainMailDeformationFilter> f;
    vtkNew<vtkTest::ErrorObserver> errors;
    f->AddObserver(vtkCommand::ErrorEvent, errors);
    f->SetInputData(horizon);
    for (vtkPolyData* obstacle : obstacles)
      f->AddObstacleData(obstacle);
    f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    f->SetGraspPointId(10 * 21 + 10);
    f->SetDisplacement(0, 0, -10);
    vtkPointSet* out = Update(f);
    EXPECT_TRUE(errors->GetErrorMessage().empty()) << errors->GetErrorMessage();
    auto* field =
      vtkIdTypeArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("ObstacleBlockedPoints"));
    EXPECT_EQ(field != nullptr, obstacles.size() > 0);
    if (field)
    {
      EXPECT_EQ(field->GetNumberOfTuples(), 1);
      EXPECT_EQ(field->GetValue(0), f->GetNumberOfObstacleBlockedPoints());
    }
    EXPECT_EQ(horizon->GetFieldData()->GetAbstractArray("ObstacleBlockedPoints"), nullptr);
    held = f->GetNumberOfObstacleBlockedPoints();
    auto copy = vtk::TakeSmartPointer(out->NewInstance());
    copy->DeepCopy(out);
    return copy;
  };
  vtkIdType heldAlone = 0, heldBeside = 0, heldEmpty = 0, heldNone = 0;
  auto alone = run({ lower }, heldAlone);
  auto beside = run({ empty, lower }, heldBeside);
  auto onlyEmpty = run({ empty }, heldEmpty);
  auto none = run({}, heldNone);
  EXPECT_GT(heldAlone, 0);
  EXPECT_EQ(heldBeside, heldAlone);
  EXPECT_TRUE(SamePoints(alone, beside));
  EXPECT_EQ(heldEmpty, 0);
  EXPECT_TRUE(SamePoints(onlyEmpty, none));
  double x[3];
  onlyEmpty->GetPoint(10 * 21 + 10, x);
  EXPECT_EQ(x[2], -10.0);
}

TEST(ChainMailObstacles, AnObstacleMadeFromTheOutputIsALoopRefusedWithoutRecursion)
{
  // A pass-through of the filter's own output as its obstacle: VTK's requests would go
  // round the loop until the stack overflows. The filter holds it off port 1, refuses
  // (error, output = input), lets what is downstream update, and puts it back once the
  // loop is gone (the pass-through's input a fixed sheet below: nothing held back).
  LoopScene scene;
  auto& [horizon, f, errors, lifted] = scene;
  f->AddObstacleConnection(lifted->GetOutputPort());
  scene.Refused("vtkPassThrough is made from this filter's own output: a pipeline loop");
  EXPECT_EQ(f->GetNumberOfObstacleConnections(), 0); // held off

  const double o[3] = { -1, -1, -5 }, du[3] = { 1, 0, 0 }, dv[3] = { 0, 1, 0 };
  lifted->SetInputData(Sheet(8, o, du, dv));
  scene.Pulled();
  EXPECT_EQ(f->GetNumberOfObstacleConnections(), 1); // back: the loop is gone
  EXPECT_FALSE(f->GetLastGraspBlocked());

  // Set again as a loop, then port 1 cleared: the held obstacle goes with it.
  lifted->SetInputConnection(f->GetOutputPort());
  Update(f);
  EXPECT_EQ(f->GetNumberOfObstacleConnections(), 0);
  f->RemoveAllObstacleConnections();
  scene.Pulled();
}

TEST(ChainMailObstacles, MarkersMadeFromTheOutputAreALoopRefusedWithoutRecursion)
{
  // The same loop through port 2 (the Markers): held off, refused (error naming the
  // Markers input, output = input), the downstream pass-through updates; clearing the
  // Markers ends the refusal and the pull is back.
  LoopScene scene;
  auto& [horizon, f, errors, wells] = scene;
  f->AddMarkersConnection(wells->GetOutputPort());
  scene.Refused(
    "Markers input vtkPassThrough is made from this filter's own output: a pipeline loop");
  EXPECT_EQ(f->GetNumberOfInputConnections(2), 0); // held off
  f->RemoveAllMarkersConnections();
  scene.Pulled();
}
