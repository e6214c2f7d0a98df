// vtkChainMailDeformationFilter on bad input: a clear error and the
// input geometry, or a warning once per cause when a documented fall-back is used; never
// an out-of-bounds read or a non-finite coordinate.
#include "vtkChainMailDeformationFilter.h"

#include "geoshaping/edit/edit_history.h"
#include "vtk_test_meshes.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
// 6 x 6 points (36), 50 triangles, float "Malleability" 0.5.
vtkSmartPointer<vtkPolyData> Grid(int type = VTK_DOUBLE, double m = 0.5)
{
  return geoshaping::testing::TriangleGridPolyData(
    6, 6, 1.0, [m](int, int) { return m; }, type);
}

// A filter pulling vertex 14 up by 2, its errors and warnings recorded.
struct Watched
{
  vtkNew<vtkChainMailDeformationFilter> Filter;
  vtkNew<vtkTest::ErrorObserver> Observer;
  explicit Watched(vtkDataObject* input)
  {
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Observer);
    this->Filter->SetInputData(input);
    this->Filter->SetGraspPointId(14);
    this->Filter->SetDisplacement(0, 0, 2);
  }
  void PinBy(const char* name)
  {
    this->Filter->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
  }
  vtkPointSet* Run()
  {
    this->Filter->Update();
    return this->Filter->GetOutput();
  }
};

// Largest coordinate difference; NaN or inf anywhere gives inf.
double Difference(vtkPointSet* a, vtkPointSet* b)
{
  double e = 0.0, p[3], q[3];
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(p[c] - q[c]);
      e = std::isfinite(d) ? std::max(e, d) : std::numeric_limits<double>::infinity();
    }
  }
  return e;
}

std::size_t Count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

template<class Array>
vtkSmartPointer<Array> PointArray(const char* name, vtkIdType tuples, int components = 1)
{
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}
} // namespace

TEST(ChainMailDeformationBadInput, MalleabilityArrayShorterThanThePointsIsRefused)
{
  auto grid = Grid();
  auto shortArray = PointArray<vtkFloatArray>("Malleability", 5);
  shortArray->Fill(0.5);
  grid->GetPointData()->AddArray(shortArray); // replaces the full one
  Watched w(grid);
  EXPECT_EQ(Difference(w.Run(), grid), 0.0);
  EXPECT_NE(w.Observer->GetErrorMessage().find("has 5 values for 36 points"), std::string::npos)
    << w.Observer->GetErrorMessage();
  EXPECT_EQ(w.Filter->GetNumberOfDisplacedPoints(), 0);
}

TEST(ChainMailDeformationBadInput, PinArrayThatIsShortOrNotNumericIsRefused)
{
  auto shortPins = PointArray<vtkIntArray>("Pinned", 5);
  shortPins->Fill(1);
  auto textPins = PointArray<vtkStringArray>("Pinned", 36);
  for (vtkAbstractArray* pins : { static_cast<vtkAbstractArray*>(shortPins.Get()),
         static_cast<vtkAbstractArray*>(textPins.Get()) })
  {
    auto grid = Grid();
    grid->GetPointData()->AddArray(pins);
    Watched w(grid);
    w.PinBy("Pinned");
    EXPECT_EQ(Difference(w.Run(), grid), 0.0);
    EXPECT_NE(w.Observer->GetErrorMessage().find(std::string("Pinned array 'Pinned' must be "
                                                             "numeric point data with one value "
                                                             "per point (it is ") +
                                                 pins->GetClassName()),
      std::string::npos)
      << w.Observer->GetErrorMessage();
  }
}

TEST(ChainMailDeformationBadInput, DisplacementBeyondFloatPointsIsRefusedAndNothingIsInfinite)
{
  auto grid = Grid(VTK_FLOAT);
  Watched w(grid);
  ASSERT_GT(Difference(w.Run(), grid), 1.0); // a good frame first: it must be undone
  for (double d : { 1e39, 1e308, -3.5e38 })
  {
    w.Observer->Clear();
    w.Filter->SetDisplacement(0, d, 0);
    EXPECT_EQ(Difference(w.Run(), grid), 0.0) << d;
    EXPECT_NE(w.Observer->GetErrorMessage().find("beyond what the output's float points hold"),
      std::string::npos)
      << w.Observer->GetErrorMessage();
    EXPECT_EQ(w.Filter->GetLastGraspPointId(), -1);
  }
  // Double output holds 1e39: the same displacement is then a deformation.
  w.Observer->Clear();
  w.Filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  w.Filter->SetDisplacement(0, 1e39, 0);
  const double moved = Difference(w.Run(), grid);
  EXPECT_FALSE(w.Observer->GetError());
  EXPECT_TRUE(std::isfinite(moved) && moved >= 1e39);
}

// A hand-made EditHistory record is checked like a drag: its positions must fit too.
TEST(ChainMailDeformationBadInput, EditRecordBeyondFloatPointsIsRefused)
{
  auto grid = Grid(VTK_FLOAT);
  geoshaping::Edit good, huge;
  good.ids = huge.ids = { 14, 15 };
  good.displacements = { { 0, 0, 1 }, { 0, 0, 1 } };
  huge.displacements = { { 0, 0, 1 }, { 0, 0, 1e39 } };
  Watched w(grid);
  w.Filter->SetGraspPointId(-1);
  w.Filter->AddEdit(geoshaping::encode_edit(good).c_str());
  w.Filter->AddEdit(geoshaping::encode_edit(huge).c_str());
  vtkPointSet* out = w.Run();
  EXPECT_NE(w.Observer->GetErrorMessage().find(
              "edit 1 moves vertex 15 beyond what the output's points hold"),
    std::string::npos)
    << w.Observer->GetErrorMessage();
  double p[3];
  out->GetPoint(15, p);
  EXPECT_EQ(p[2], 1.0f); // the edit before it is applied, this one is not
  out->GetPoint(14, p);
  EXPECT_EQ(p[2], 1.0f);
  EXPECT_TRUE(std::isfinite(Difference(out, grid)));
}

TEST(ChainMailDeformationBadInput, RefinementIterationsAreCappedAtThePluginsRange)
{
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetRefinementIterations(VTK_INT_MAX);
  EXPECT_EQ(f->GetRefinementIterations(), 64);
  EXPECT_EQ(f->GetRefinementIterations(), vtkChainMailDeformationFilter::MAX_REFINEMENT_ITERATIONS);
  f->SetRefinementIterations(-5);
  EXPECT_EQ(f->GetRefinementIterations(), 0);
}

TEST(ChainMailDeformationBadInput, RefinementToleranceIsClampedToItsRange)
{
  vtkNew<vtkChainMailDeformationFilter> f;
  EXPECT_EQ(f->GetRefinementTolerance(), 1e-6);
  f->SetRefinementTolerance(0.0);
  EXPECT_EQ(f->GetRefinementTolerance(), 1e-12);
  f->SetRefinementTolerance(-1.0);
  EXPECT_EQ(f->GetRefinementTolerance(), 1e-12);
  f->SetRefinementTolerance(5.0);
  EXPECT_EQ(f->GetRefinementTolerance(), 1.0);
}

namespace
{
// Rigid everywhere, one pinned vertex two edges from the grasp: the links between them
// cannot all hold, so the refinement never converges and runs to its cap.
vtkSmartPointer<vtkPolyData> ImpossibleLinks()
{
  auto grid = Grid(VTK_DOUBLE, 0.0);
  auto pins = PointArray<vtkIntArray>("Pinned", 36);
  pins->Fill(0);
  pins->SetValue(16, 1);
  grid->GetPointData()->AddArray(pins);
  return grid;
}
} // namespace

TEST(ChainMailDeformationBadInput, RefinementOfLinksThatCannotHoldStopsAtTheCap)
{
  auto grid = ImpossibleLinks();
  Watched w(grid);
  w.PinBy("Pinned");
  w.Filter->SetRefinementSolver(vtkChainMailDeformationFilter::REFINEMENT_DYKSTRA); // iterative
  w.Filter->SetRefinementIterations(VTK_INT_MAX);
  w.Run();
  EXPECT_EQ(w.Filter->GetNumberOfRefinementSweeps(), 64);
}

TEST(ChainMailDeformationBadInput, RefinementStopsAfterTheSweepWhenThePipelineAborts)
{
  auto grid = ImpossibleLinks();
  Watched w(grid);
  w.PinBy("Pinned");
  w.Filter->SetRefinementSolver(vtkChainMailDeformationFilter::REFINEMENT_DYKSTRA); // iterative
  w.Filter->SetRefinementIterations(64);
  // The executive reports progress 0 before RequestData: abort from there, as a GUI
  // "abort" button does from its progress handler.
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
    { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
  w.Filter->AddObserver(vtkCommand::ProgressEvent, abort);
  vtkPointSet* out = w.Run();
  EXPECT_EQ(w.Filter->GetNumberOfRefinementSweeps(), 1);
  // The deformation refined that far is kept (not emptied by the executive) and the
  // stop is reported.
  ASSERT_EQ(out->GetNumberOfPoints(), grid->GetNumberOfPoints());
  double moved[3];
  out->GetPoint(14, moved);
  EXPECT_EQ(moved[2], 2.0);
  EXPECT_NE(w.Observer->GetWarningMessage().find("Refinement stopped after 1 of 64 sweeps"),
    std::string::npos)
    << w.Observer->GetWarningMessage();
}

TEST(ChainMailDeformationBadInput, MalleabilityThatIsNotNumericPointDataWarnsOnceAndUsesTheDefault)
{
  auto grid = Grid();
  auto text = PointArray<vtkStringArray>("Malleability", 36);
  grid->GetPointData()->AddArray(text);
  vtkNew<vtkFloatArray> cells;
  cells->SetName("CellMalleability");
  cells->SetNumberOfTuples(grid->GetNumberOfCells());
  cells->Fill(0.0);
  grid->GetCellData()->AddArray(cells);
  vtkNew<vtkChainMailDeformationFilter> reference;
  reference->SetInputData(Grid(VTK_DOUBLE, 0.5));
  reference->SetGraspPointId(14);
  reference->SetDisplacement(0, 0, 2);
  reference->Update();

  Watched w(grid);
  EXPECT_EQ(Difference(w.Run(), reference->GetOutput()), 0.0);
  w.Filter->SetDisplacement(0, 0, 2.5); // a drag: the same cause is not repeated
  w.Run();
  w.Filter->SetDisplacement(0, 0, 2);
  w.Run();
  EXPECT_EQ(Count(w.Observer->GetWarningMessage(), "is not numeric (vtkStringArray)"), 1u)
    << w.Observer->GetWarningMessage();
  EXPECT_FALSE(w.Observer->GetError());

  w.Filter->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "CellMalleability");
  EXPECT_EQ(Difference(w.Run(), reference->GetOutput()), 0.0);
  EXPECT_EQ(Count(w.Observer->GetWarningMessage(), "'CellMalleability' is not point data"), 1u)
    << w.Observer->GetWarningMessage();
}

TEST(ChainMailDeformationBadInput, ThreeComponentPinArrayWarnsThatComponentZeroIsUsed)
{
  auto grid = Grid();
  auto pins = PointArray<vtkIntArray>("Pinned", 36, 3);
  pins->Fill(0);
  grid->GetPointData()->AddArray(pins);
  Watched w(grid);
  w.PinBy("Pinned");
  w.Run();
  EXPECT_NE(w.Observer->GetWarningMessage().find("3 components; component 0 is the mask"),
    std::string::npos)
    << w.Observer->GetWarningMessage();
}

TEST(ChainMailDeformationBadInput, InputWithoutCellEdgesWarnsThatOnlyTheGraspMoves)
{
  auto grid = Grid();
  for (bool verts : { false, true })
  {
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(grid->GetPoints());
    if (verts)
    {
      vtkNew<vtkCellArray> cells;
      for (vtkIdType i = 0; i < 36; ++i)
        cells->InsertNextCell(1, &i);
      cloud->SetVerts(cells);
    }
    Watched w(cloud);
    w.Run();
    EXPECT_EQ(w.Filter->GetNumberOfDisplacedPoints(), 1);
    EXPECT_NE(
      w.Observer->GetWarningMessage().find("only the grasped vertex moves"), std::string::npos)
      << verts;
  }
}

TEST(ChainMailDeformationBadInput, NonFiniteGraspPositionIsAClearError)
{
  auto grid = Grid();
  Watched w(grid);
  w.Filter->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  w.Filter->SetGraspPosition(std::nan(""), 0, 0);
  w.Filter->SetDisplacement(0, 0, 2);
  EXPECT_EQ(Difference(w.Run(), grid), 0.0);
  EXPECT_NE(w.Observer->GetErrorMessage().find("GraspPosition (nan, 0, 0) is not finite"),
    std::string::npos)
    << w.Observer->GetErrorMessage();
}
