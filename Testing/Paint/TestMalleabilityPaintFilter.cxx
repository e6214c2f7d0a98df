#include "vtkChainMailDeformationFilter.h"
#include "vtkFaultStepHorizonSource.h"
#include "vtkMalleabilityPaintFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellType.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "geoshaping/scenes/sample_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
vtkSmartPointer<vtkPointSet> Scene(bool slab, bool figure5c = false)
{
  vtkNew<vtkFaultStepHorizonSource> source;
  source->SetOutputMeshType(
    slab ? vtkFaultStepHorizonSource::SLAB : vtkFaultStepHorizonSource::SURFACE);
  source->SetPaintFigure5C(figure5c);
  source->Update();
  return vtkPointSet::SafeDownCast(source->GetOutputDataObject(0));
}

vtkFloatArray* Malleability(vtkDataObject* data)
{
  return vtkFloatArray::SafeDownCast(
    vtkPointSet::SafeDownCast(data)->GetPointData()->GetArray("Malleability"));
}

void AddFigure5CDabs(vtkMalleabilityPaintFilter* paint)
{
  for (const geoshaping::Dab& d : geoshaping::fault_step_painting(geoshaping::FaultStepParams{}))
    paint->AddDab(d.center.x(), d.center.y(), d.center.z(), d.radius, d.value, d.strength);
}
} // namespace

TEST(FaultStepHorizonSource, MakesTrianglesOrTetrahedraWithTheCoreGeometry)
{
  const geoshaping::SampleMesh core = geoshaping::fault_step_horizon(geoshaping::FaultStepParams{});
  vtkSmartPointer<vtkPointSet> surface = Scene(false);
  ASSERT_TRUE(vtkPolyData::SafeDownCast(surface));
  EXPECT_EQ(surface->GetNumberOfPoints(), core.num_points());
  EXPECT_EQ(surface->GetNumberOfCells(), vtkIdType(core.num_cells()));
  EXPECT_EQ(surface->GetCellType(0), VTK_TRIANGLE);
  EXPECT_EQ(surface->GetPoints()->GetDataType(), VTK_DOUBLE);
  vtkSmartPointer<vtkPointSet> slab = Scene(true);
  auto* grid = vtkUnstructuredGrid::SafeDownCast(slab);
  ASSERT_TRUE(grid);
  EXPECT_EQ(slab->GetNumberOfPoints(), 4 * core.num_points());
  vtkUnsignedCharArray* types = grid->GetDistinctCellTypesArray();
  ASSERT_EQ(types->GetNumberOfValues(), 1);
  EXPECT_EQ(types->GetValue(0), VTK_TETRA);
  EXPECT_EQ(surface->GetPointData()->GetArray("Malleability"), nullptr);
}

TEST(FaultStepHorizonSource, BadSizeGivesAnErrorAndAnEmptyOutput)
{
  vtkNew<vtkFaultStepHorizonSource> source;
  source->SetSpacing(-1.0);
  vtkNew<vtkTest::ErrorObserver> errors;
  source->AddObserver(vtkCommand::ErrorEvent, errors);
  source->Update();
  EXPECT_TRUE(errors->GetError());
  EXPECT_EQ(vtkPointSet::SafeDownCast(source->GetOutputDataObject(0))->GetNumberOfPoints(), 0);
}

TEST(MalleabilityPaint, LocatorPaintingEqualsTheCoreBruteForcePaintingBitForBit)
{
  const geoshaping::FaultStepParams p;
  for (bool slab : { false, true })
  {
    const geoshaping::SampleMesh core =
      slab ? geoshaping::fault_step_slab(p) : geoshaping::fault_step_horizon(p);
    const std::vector<float> expected = geoshaping::fault_step_malleability(core, p);
    vtkSmartPointer<vtkPointSet> scene = Scene(slab, true);
    vtkFloatArray* painted = Malleability(scene);
    ASSERT_TRUE(painted);
    ASSERT_EQ(painted->GetNumberOfTuples(), vtkIdType(expected.size()));
    EXPECT_EQ(
      std::memcmp(painted->GetPointer(0), expected.data(), expected.size() * sizeof(float)), 0);
  }
}

TEST(MalleabilityPaint, CreatesTheArrayWithTheInitialValueAndMakesItActive)
{
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(Scene(false));
  paint->SetInitialMalleability(0.25);
  paint->Update();
  vtkFloatArray* m = Malleability(paint->GetOutputDataObject(0));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->GetValueRange()[0], 0.25f);
  EXPECT_EQ(m->GetValueRange()[1], 0.25f);
  EXPECT_EQ(
    vtkPointSet::SafeDownCast(paint->GetOutputDataObject(0))->GetPointData()->GetScalars(), m);
}

TEST(MalleabilityPaint, UpdatesACopyAndNeverTheInputsArray)
{
  vtkSmartPointer<vtkPointSet> input = Scene(false);
  vtkNew<vtkFloatArray> original;
  original->SetName("Stiffness");
  original->SetNumberOfTuples(input->GetNumberOfPoints());
  original->Fill(0.75);
  original->SetValue(0, 7.0f); // out of range: clamped in the copy with a warning
  input->GetPointData()->AddArray(original);
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(input);
  paint->SetMalleabilityArrayName("Stiffness");
  paint->AddDab(50.0, 30.0, 10.0, 5.0, 0.0, 1.0);
  vtkNew<vtkTest::ErrorObserver> warnings;
  paint->AddObserver(vtkCommand::WarningEvent, warnings);
  paint->Update();
  EXPECT_TRUE(warnings->GetWarning());
  auto* out = vtkFloatArray::SafeDownCast(vtkPointSet::SafeDownCast(paint->GetOutputDataObject(0))
                                            ->GetPointData()
                                            ->GetArray("Stiffness"));
  ASSERT_TRUE(out);
  EXPECT_NE(out, original.Get());
  EXPECT_EQ(out->GetValue(0), 1.0f);
  EXPECT_EQ(original->GetValue(0), 7.0f);
  EXPECT_EQ(original->GetValueRange()[0], 0.75f);
  EXPECT_LT(out->GetValueRange()[0], 0.75f);
  EXPECT_GT(paint->GetNumberOfPaintedValues(), 0);
}

TEST(MalleabilityPaint, BadDabsAreSkippedWithAnErrorAndTheOthersApplied)
{
  vtkSmartPointer<vtkPointSet> input = Scene(false);
  vtkNew<vtkMalleabilityPaintFilter> good, mixed;
  good->SetInputData(input);
  mixed->SetInputData(input);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  mixed->AddDab(nan, 30, 20, 5, 1, 1);
  good->AddDab(20, 30, 20, 5, 1, 0.5);
  mixed->AddDab(20, 30, 20, 5, 1, 0.5);
  mixed->AddDab(20, 30, 20, -5, 1, 1);
  mixed->AddDab(20, 30, 20, 5, 2, 1);
  mixed->AddDab(20, 30, 20, 5, 1, -1);
  vtkNew<vtkTest::ErrorObserver> errors;
  mixed->AddObserver(vtkCommand::ErrorEvent, errors);
  good->Update();
  mixed->Update();
  EXPECT_TRUE(errors->GetError());
  EXPECT_NE(errors->GetErrorMessage().find("radius is negative"), std::string::npos);
  EXPECT_EQ(mixed->GetNumberOfAppliedDabs(), 1);
  EXPECT_EQ(mixed->GetNumberOfRejectedDabs(), 4);
  vtkFloatArray* a = Malleability(good->GetOutputDataObject(0));
  vtkFloatArray* b = Malleability(mixed->GetOutputDataObject(0));
  EXPECT_EQ(
    std::memcmp(a->GetPointer(0), b->GetPointer(0), sizeof(float) * a->GetNumberOfTuples()), 0);
}

TEST(MalleabilityPaint, GeodesicBrushOnTheUpperSideLeavesTheLowerSideAlone)
{
  // Brush at the top edge of the 20-high step, radius 24: the sphere reaches the lower
  // flat up to x = 60, the path down the step (about 21 long) no farther than x = 56.
  vtkSmartPointer<vtkPointSet> input = Scene(false);
  vtkIdType lowerPainted[2] = { 0, 0 };
  for (int mode : { vtkMalleabilityPaintFilter::EUCLIDEAN, vtkMalleabilityPaintFilter::GEODESIC })
  {
    vtkNew<vtkMalleabilityPaintFilter> paint;
    paint->SetInputData(input);
    paint->SetDistanceMode(mode);
    paint->SetFalloff(vtkMalleabilityPaintFilter::CONSTANT);
    paint->AddDab(47.0, 30.0, 20.0, 24.0, 0.0, 1.0);
    paint->Update();
    vtkFloatArray* m = Malleability(paint->GetOutputDataObject(0));
    for (vtkIdType v = 0; v < input->GetNumberOfPoints(); ++v)
    {
      double x[3];
      input->GetPoint(v, x);
      lowerPainted[mode] += x[2] == 0.0 && x[0] > 57.0 && m->GetValue(v) == 0.0f;
    }
  }
  EXPECT_GT(lowerPainted[vtkMalleabilityPaintFilter::EUCLIDEAN], 20);
  EXPECT_EQ(lowerPainted[vtkMalleabilityPaintFilter::GEODESIC], 0);
}

TEST(MalleabilityPaint, GeodesicDabTiesGoToTheFirstPointInCoordinateOrder)
{
  // Two separate triangles, one at p0 = (1, 0, 0), one at p1 = (0, 0, 0); the dab's centre
  // is as near to both, and its path stays on the triangle of its source. Without
  // GlobalIds the tie goes to the first in (x, y, z) order, p1, as on several processes
  // (coordinate_ids.h), not to the lower point id, p0.
  vtkNew<vtkPoints> points;
  for (const auto& p : { std::array<double, 3>{ 1, 0, 0 }, std::array<double, 3>{ 0, 0, 0 },
         std::array<double, 3>{ 2, 1, 0 }, std::array<double, 3>{ 2, -1, 0 },
         std::array<double, 3>{ -1, 1, 0 }, std::array<double, 3>{ -1, -1, 0 } })
    points->InsertNextPoint(p.data());
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->AllocateExact(2, 6);
  const vtkIdType a[3] = { 0, 2, 3 }, b[3] = { 1, 4, 5 };
  mesh->InsertNextCell(VTK_TRIANGLE, 3, a);
  mesh->InsertNextCell(VTK_TRIANGLE, 3, b);
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(mesh);
  paint->SetInitialMalleability(0.0);
  paint->SetDistanceMode(vtkMalleabilityPaintFilter::GEODESIC);
  paint->SetFalloff(vtkMalleabilityPaintFilter::CONSTANT);
  paint->AddDab(0.5, 0.0, 0.0, 0.6, 1.0, 1.0);
  paint->Update();
  vtkFloatArray* m = Malleability(paint->GetOutputDataObject(0));
  EXPECT_EQ(m->GetValue(1), 1.0f) << "the source: first in coordinate order";
  EXPECT_EQ(m->GetValue(0), 0.0f);
}

TEST(MalleabilityPaint, RepaintingReusesTheLocatorAndIsDeterministic)
{
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(Scene(false));
  AddFigure5CDabs(paint);
  paint->Update();
  vtkNew<vtkFloatArray> first;
  first->DeepCopy(Malleability(paint->GetOutputDataObject(0)));
  paint->SetDistanceMode(vtkMalleabilityPaintFilter::GEODESIC);
  paint->Update();
  paint->SetDistanceMode(vtkMalleabilityPaintFilter::EUCLIDEAN);
  paint->Update();
  EXPECT_EQ(paint->GetNumberOfRebuilds(), 1);
  vtkFloatArray* again = Malleability(paint->GetOutputDataObject(0));
  EXPECT_EQ(std::memcmp(first->GetPointer(0), again->GetPointer(0),
              sizeof(float) * first->GetNumberOfTuples()),
    0);
  double dab[6];
  ASSERT_TRUE(paint->GetDab(0, dab));
  EXPECT_FALSE(paint->GetDab(paint->GetNumberOfDabs(), dab));
}

TEST(MalleabilityPaint, PaintedBlackStepTranslatesRigidlyUnderChainMail)
{
  vtkSmartPointer<vtkPointSet> painted = Scene(false, true);
  vtkNew<vtkChainMailDeformationFilter> drag;
  drag->SetInputData(painted);
  drag->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  drag->SetGraspPosition(50.0, 30.0, 10.0);
  drag->SetDisplacement(0.0, 0.0, 10.0);
  drag->Update();
  vtkPointSet* out = vtkPointSet::SafeDownCast(drag->GetOutputDataObject(0));
  vtkFloatArray* m = Malleability(painted);
  int black = 0;
  for (vtkIdType v = 0; v < painted->GetNumberOfPoints(); ++v)
  {
    if (m->GetValue(v) != 0.0f)
      continue;
    double a[3], b[3];
    painted->GetPoint(v, a);
    out->GetPoint(v, b);
    EXPECT_NEAR(b[0] - a[0], 0.0, 1e-9);
    EXPECT_NEAR(b[2] - a[2], 10.0, 1e-9);
    ++black;
  }
  EXPECT_GT(black, 1000);
}

TEST(MalleabilityPaint, SourceArrayShorterThanThePointsIsRefused)
{
  vtkSmartPointer<vtkPointSet> input = Scene(false);
  vtkNew<vtkFloatArray> shortArray;
  shortArray->SetName("Stiffness");
  shortArray->SetNumberOfTuples(5);
  shortArray->Fill(0.5);
  input->GetPointData()->AddArray(shortArray);
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(input);
  paint->SetMalleabilityArrayName("Stiffness");
  paint->AddDab(50.0, 30.0, 10.0, 5.0, 0.0, 1.0);
  vtkNew<vtkTest::ErrorObserver> errors;
  paint->AddObserver(vtkCommand::ErrorEvent, errors);
  paint->Update();
  EXPECT_NE(errors->GetErrorMessage().find("has 5 values for"), std::string::npos)
    << errors->GetErrorMessage();
  auto* out = vtkPointSet::SafeDownCast(paint->GetOutputDataObject(0));
  EXPECT_EQ(out->GetPointData()->GetArray("Stiffness"), shortArray.Get()); // the input's
}

TEST(MalleabilityPaint, PaintingPinsIntoTheMalleabilityArrayIsRefused)
{
  vtkSmartPointer<vtkPointSet> input = Scene(false, true);
  vtkFloatArray* before = Malleability(input);
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(input);
  paint->SetPaintPins(true);
  paint->SetPinnedArrayName("Malleability");
  paint->AddDab(50.0, 30.0, 10.0, 5.0, 1.0, 1.0);
  vtkNew<vtkTest::ErrorObserver> errors;
  paint->AddObserver(vtkCommand::ErrorEvent, errors);
  paint->Update();
  EXPECT_NE(
    errors->GetErrorMessage().find("would overwrite the malleability array"), std::string::npos);
  EXPECT_EQ(Malleability(paint->GetOutputDataObject(0)), before);
}

TEST(MalleabilityPaint, SourceArrayThatIsNotNumericWarnsAndStartsFromTheInitialValue)
{
  vtkSmartPointer<vtkPointSet> input = Scene(false);
  vtkNew<vtkStringArray> text;
  text->SetName("Stiffness");
  text->SetNumberOfTuples(input->GetNumberOfPoints());
  input->GetPointData()->AddArray(text);
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(input);
  paint->SetMalleabilityArrayName("Stiffness");
  paint->SetInitialMalleability(0.25);
  vtkNew<vtkTest::ErrorObserver> warnings;
  paint->AddObserver(vtkCommand::WarningEvent, warnings);
  paint->Update();
  EXPECT_NE(warnings->GetWarningMessage().find("'Stiffness' is not numeric (vtkStringArray)"),
    std::string::npos);
  auto* out = vtkFloatArray::SafeDownCast(vtkPointSet::SafeDownCast(paint->GetOutputDataObject(0))
                                            ->GetPointData()
                                            ->GetArray("Stiffness"));
  ASSERT_TRUE(out);
  EXPECT_EQ(out->GetValueRange()[0], 0.25f);
}

TEST(MalleabilityPaint, ReportsProgressAndAnAbortLeavesThePreviousOutput)
{
  vtkNew<vtkMalleabilityPaintFilter> paint;
  paint->SetInputData(Scene(false));
  paint->SetFalloff(vtkMalleabilityPaintFilter::CONSTANT);
  // 300 dabs, each a stroke of its own (alternate values): progress comes between strokes.
  for (int i = 0; i < 300; ++i)
  {
    const double x = 5.0 + 3.0 * (i % 30);
    paint->AddDab(x, 5.0 + 5.0 * (i / 30), x < 47.0 ? 20.0 : 0.0, 2.5, i % 2 ? 0.9 : 0.1, 1.0);
  }
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
    { static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(call)); });
  paint->AddObserver(vtkCommand::ProgressEvent, onProgress);
  paint->Update();
  ASSERT_GT(progress.size(), 50u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(progress.back(), 1.0);
  vtkNew<vtkFloatArray> before;
  before->DeepCopy(Malleability(paint->GetOutputDataObject(0)));

  // Another painting, aborted from the progress bar half way: the output stays the last
  // one, with an error saying so.
  paint->SetInitialMalleability(0.9); // a full repaint
  vtkNew<vtkCallbackCommand> abortHalfWay;
  abortHalfWay->SetCallback(
    [](vtkObject* caller, unsigned long, void*, void* call)
    {
      if (*static_cast<double*>(call) > 0.5 && *static_cast<double*>(call) < 1.0)
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    });
  paint->AddObserver(vtkCommand::ProgressEvent, abortHalfWay);
  vtkNew<vtkTest::ErrorObserver> errors;
  paint->AddObserver(vtkCommand::ErrorEvent, errors);
  paint->Update();
  ASSERT_TRUE(errors->GetError());
  EXPECT_NE(errors->GetErrorMessage().find("aborted"), std::string::npos)
    << errors->GetErrorMessage();
  vtkFloatArray* after = Malleability(paint->GetOutputDataObject(0));
  ASSERT_NE(after, nullptr);
  ASSERT_EQ(after->GetNumberOfValues(), before->GetNumberOfValues());
  for (vtkIdType i = 0; i < after->GetNumberOfValues(); ++i)
    ASSERT_EQ(after->GetValue(i), before->GetValue(i)) << i;
}
