// Tests of vtkChainMailDeformationFilter against the core and against hand values.
#include "vtkChainMailDeformationFilter.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/metrics/error_metrics.h"
#include "test_meshes.h"
#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
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
#include <string>
#include <vector>

namespace
{
template<class F>
vtkSmartPointer<vtkPolyData> TriangleGrid(
  int nx, int ny, double h, F m, int type = VTK_DOUBLE, double x0 = 0.0, double y0 = 0.0)
{
  return geoshaping::testing::TriangleGridPolyData(nx, ny, h, m, type, x0, y0);
}

vtkSmartPointer<vtkPolyData> UniformGrid(int nx, int ny, double h, double m)
{
  return TriangleGrid(nx, ny, h, [m](int, int) { return m; });
}

// A slab of nx * ny * nz points, each hexahedral block split into 6 tetrahedra.
vtkSmartPointer<vtkUnstructuredGrid> TetSlab(int nx, int ny, int nz, double h)
{
  return geoshaping::testing::TetSlabUnstructuredGrid(nx, ny, nz, h, {});
}

vtkPointSet* Deform(vtkChainMailDeformationFilter* f, vtkDataObject* input)
{
  f->SetInputData(input);
  f->Update();
  return vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
}

double MaxPointDifference(vtkPointSet* a, vtkPointSet* b)
{
  double e = 0.0, p[3], q[3];
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    e = std::max({ e, std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2]) });
  }
  return e;
}
} // namespace

TEST(ChainMailDeformationFilter, MatchesTheCoreDeformerOnPolyData)
{
  auto grid =
    TriangleGrid(30, 20, 1.0, [](int i, int j) { return (i > 10 && i < 16 && j > 5) ? 0.0 : 0.8; });
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(5 * 30 + 20);
  f->SetDisplacement(1.0, -2.0, 6.0);
  vtkPointSet* out = Deform(f, grid);
  ASSERT_NE(out, nullptr);
  EXPECT_TRUE(out->IsA("vtkPolyData"));
  EXPECT_EQ(out->GetNumberOfCells(), grid->GetNumberOfCells());
  EXPECT_NE(out->GetPointData()->GetArray("Malleability"), nullptr);

  const auto mesh = geoshaping::testing::triangle_grid(30, 20, 1.0);
  geoshaping::ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  std::vector<float> m(600);
  for (int v = 0; v < 600; ++v)
    m[v] = vtkFloatArray::SafeDownCast(grid->GetPointData()->GetArray("Malleability"))->GetValue(v);
  d.set_malleability(m.data());
  d.deform(5 * 30 + 20, { 1.0, -2.0, 6.0 });
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), vtkIdType(d.moved().size()));
  for (vtkIdType v = 0; v < 600; ++v)
  {
    double p[3];
    out->GetPoint(v, p);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(p[c], mesh.xyz[3 * v + c] + d.displacement(v)[c]) << v;
  }
}

// The malleability the deformation used at the grasp, for a haptic client's coupling
// stiffness (also read over a remote connection: Python.pvserver_loopback).
TEST(ChainMailDeformationFilter, ReportsTheMalleabilityAtTheGraspedVertex)
{
  auto grid = TriangleGrid(
    30, 20, 1.0, [](int i, int j) { return (i > 10 && i < 16 && j > 5) ? 0.0 : 0.25 + 0.01 * i; });
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(grid);
  f->Update();
  EXPECT_TRUE(std::isnan(f->GetLastGraspMalleability())); // no grasp
  f->SetGraspPointId(5 * 30 + 20);
  f->SetDisplacement(0.0, 0.0, 3.0);
  f->Update();
  EXPECT_EQ(f->GetLastGraspPointId(), 5 * 30 + 20);
  EXPECT_EQ(f->GetLastGraspMalleability(), double(0.25f + 0.01f * 20)); // the float array's value
  f->SetGraspPointId(12 * 30 + 13);                                     // in the rigid block
  f->Update();
  EXPECT_EQ(f->GetLastGraspMalleability(), 0.0);
  f->SetGraspPointId(-1);
  f->Update();
  EXPECT_TRUE(std::isnan(f->GetLastGraspMalleability()));
}

TEST(ChainMailDeformationFilter, SparseUpdatesEqualAFreshFilterAndNeverRebuild)
{
  auto grid = UniformGrid(40, 40, 1.0, 0.6);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(grid);
  const double moves[4][3] = { { 0, 0, 8 }, { 3, 0, -2 }, { 0, 0, 0.5 }, { -1, 4, 9 } };
  const vtkIdType grasps[4] = { 820, 100, 1500, 820 };
  for (int k = 0; k < 4; ++k)
  {
    f->SetGraspPointId(grasps[k]);
    f->SetDisplacement(moves[k][0], moves[k][1], moves[k][2]);
    f->SetCandidateQueue(
      k % 2 ? vtkChainMailDeformationFilter::FIFO : vtkChainMailDeformationFilter::FIFO_PRIORITY);
    f->Update();
    vtkNew<vtkChainMailDeformationFilter> fresh;
    fresh->SetGraspPointId(grasps[k]);
    fresh->SetDisplacement(moves[k][0], moves[k][1], moves[k][2]);
    fresh->SetCandidateQueue(f->GetCandidateQueue());
    EXPECT_EQ(MaxPointDifference(f->GetOutput(), Deform(fresh, grid)), 0.0) << "step " << k;
  }
  EXPECT_EQ(f->GetNumberOfRebuilds(), 1);
  f->SetGraspPointId(-1);
  f->Update();
  EXPECT_EQ(MaxPointDifference(f->GetOutput(), grid), 0.0);
}

TEST(ChainMailDeformationFilter, RepaintingUpdatesMalleabilityWithoutRebuildingAdjacency)
{
  auto grid = UniformGrid(21, 21, 1.0, 1.0);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(220);
  f->SetDisplacement(0, 0, 5);
  Deform(f, grid);
  const vtkIdType softMoved = f->GetNumberOfDisplacedPoints();
  auto* mal = vtkFloatArray::SafeDownCast(grid->GetPointData()->GetArray("Malleability"));
  mal->Fill(0.0f);
  mal->Modified();
  f->Update();
  EXPECT_EQ(f->GetNumberOfRebuilds(), 1);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 441); // rigid: everything translates
  EXPECT_LT(softMoved, 441);
  double p[3];
  f->GetOutput()->GetPoint(0, p);
  EXPECT_EQ(p[2], 5.0);
}

TEST(ChainMailDeformationFilter, DefaultMalleabilityIsUsedWithoutAnArray)
{
  auto grid = UniformGrid(11, 11, 1.0, 0.0);
  grid->GetPointData()->RemoveArray("Malleability");
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetDefaultMalleability(0.0);
  f->SetGraspPointId(60);
  f->SetDisplacement(0, 0, 1);
  Deform(f, grid);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 121);
  f->SetDefaultMalleability(1.0);
  f->Update();
  EXPECT_LT(f->GetNumberOfDisplacedPoints(), 121);
}

TEST(ChainMailDeformationFilter, TetrahedralSlabTranslatesRigidlyAndKeepsItsType)
{
  auto slab = TetSlab(6, 5, 3, 2.0);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetDefaultMalleability(0.0);
  f->SetGraspPointId(7);
  f->SetDisplacement(0.25, 0.5, -1.0);
  vtkPointSet* out = Deform(f, slab);
  ASSERT_TRUE(out->IsA("vtkUnstructuredGrid"));
  EXPECT_EQ(out->GetNumberOfCells(), slab->GetNumberOfCells());
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), slab->GetNumberOfPoints());
  double p[3], q[3];
  for (vtkIdType i = 0; i < slab->GetNumberOfPoints(); ++i)
  {
    slab->GetPoint(i, p);
    out->GetPoint(i, q);
    EXPECT_EQ(q[0], p[0] + 0.25);
    EXPECT_EQ(q[1], p[1] + 0.5);
    EXPECT_EQ(q[2], p[2] - 1.0);
  }
}

TEST(ChainMailDeformationFilter, SoftTetrahedralSlabAttenuatesAwayFromTheGrasp)
{
  auto slab = TetSlab(15, 15, 3, 1.0);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetDefaultMalleability(1.0);
  f->SetGraspPointId(2 * 225 + 7 * 15 + 7);
  f->SetDisplacement(0, 0, 3.0);
  vtkPointSet* out = Deform(f, slab);
  double corner[3];
  out->GetPoint(0, corner);
  EXPECT_EQ(corner[2], 0.0);
  EXPECT_GT(f->GetNumberOfDisplacedPoints(), 20);
  EXPECT_LT(f->GetNumberOfDisplacedPoints(), slab->GetNumberOfPoints());
}

TEST(ChainMailDeformationFilter, GraspNearestToPositionUsesTheClosestVertex)
{
  auto grid = UniformGrid(10, 10, 1.0, 0.0);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  f->SetGraspPosition(3.2, 4.9, 0.3);
  f->SetDisplacement(0, 0, 1);
  Deform(f, grid);
  EXPECT_EQ(f->GetLastGraspPointId(), 5 * 10 + 3);
}

TEST(ChainMailDeformationFilter, PinnedArrayKeepsVerticesInPlace)
{
  auto grid = UniformGrid(10, 10, 1.0, 0.0);
  vtkNew<vtkIntArray> pins;
  pins->SetName("Pinned");
  pins->SetNumberOfTuples(100);
  pins->Fill(0);
  for (int i = 0; i < 10; ++i)
    pins->SetValue(50 + i, 1); // a pinned row cuts the grid in two
  grid->GetPointData()->AddArray(pins);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Pinned");
  f->SetGraspPointId(5);
  f->SetDisplacement(0, 0, 2);
  vtkPointSet* out = Deform(f, grid);
  double p[3];
  for (vtkIdType i = 0; i < 100; ++i)
  {
    out->GetPoint(i, p);
    EXPECT_EQ(p[2], i < 50 ? 2.0 : 0.0) << i;
  }
}

TEST(ChainMailDeformationFilter, PiecewiseStretchCurveDrivesTheChainAnalytically)
{
  // A 1-point-wide strip: pulling the end of an x-chain (spacing 10) by 8 with stretch 1.1
  // moves the vertices 8, 7, 6, ... (each link absorbs 1).
  auto strip = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  for (int i = 0; i < 12; ++i)
    pts->InsertNextPoint(10.0 * i, 0, 0);
  for (vtkIdType i = 0; i + 1 < 12; ++i)
  {
    const vtkIdType l[2] = { i, i + 1 };
    lines->InsertNextCell(2, l);
  }
  strip->SetPoints(pts);
  strip->SetLines(lines);
  vtkNew<vtkPiecewiseFunction> stretch;
  stretch->AddPoint(0.0, 1.1);
  stretch->AddPoint(1.0, 1.1);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetStretchFunction(stretch);
  f->SetCompressionRange(1.0, 1.0);
  f->SetShearRange(0.0, 0.0);
  f->SetGraspPointId(11);
  f->SetDisplacement(8, 0, 0);
  vtkPointSet* out = Deform(f, strip);
  for (int i = 0; i < 12; ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    EXPECT_NEAR(p[0] - 10.0 * i, std::max(0, 8 - (11 - i)), 1e-12) << i;
  }
}

TEST(ChainMailDeformationFilter, OutputPrecisionFollowsVtkConvention)
{
  auto grid = TriangleGrid(
    5, 5, 1.0, [](int, int) { return 0.5; }, VTK_FLOAT);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(12);
  f->SetDisplacement(0, 0, 1);
  EXPECT_EQ(Deform(f, grid)->GetPoints()->GetDataType(), VTK_FLOAT);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetPoints()->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(f->GetNumberOfRebuilds(), 2);
}

TEST(ChainMailDeformationFilter, BadInputGivesAnErrorAndTheInputGeometry)
{
  auto grid = UniformGrid(6, 6, 1.0, 0.5);
  vtkNew<vtkChainMailDeformationFilter> f;
  vtkNew<vtkTest::ErrorObserver> errors;
  f->AddObserver(vtkCommand::ErrorEvent, errors);
  f->SetGraspPointId(36);
  f->SetDisplacement(0, 0, 1);
  EXPECT_EQ(MaxPointDifference(Deform(f, grid), grid), 0.0);
  EXPECT_TRUE(errors->GetError());
  EXPECT_NE(errors->GetErrorMessage().find("outside"), std::string::npos);
  errors->Clear();

  f->SetGraspPointId(3);
  f->SetDisplacement(0, std::nan(""), 1);
  f->Update();
  EXPECT_TRUE(errors->GetError());
  EXPECT_EQ(MaxPointDifference(f->GetOutput(), grid), 0.0);
  errors->Clear();

  grid->GetPoints()->SetPoint(4, 0, INFINITY, 0);
  grid->GetPoints()->Modified();
  f->SetDisplacement(0, 0, 1);
  f->Update();
  EXPECT_TRUE(errors->GetError());
  EXPECT_NE(errors->GetErrorMessage().find("non-finite"), std::string::npos);
  double p[3];
  f->GetOutput()->GetPoint(4, p);
  EXPECT_TRUE(std::isinf(p[1])); // the input, untouched
  f->GetOutput()->GetPoint(3, p);
  EXPECT_EQ(p[2], 0.0);
}

TEST(ChainMailDeformationFilter, EmptyInputGivesEmptyOutput)
{
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(0);
  vtkPointSet* out = Deform(f, empty);
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(ChainMailDeformationFilter, DiagnosticsArraysOnlyWhenAsked)
{
  auto grid = UniformGrid(8, 8, 1.0, 0.5);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(27);
  f->SetDisplacement(0, 0, 1);
  vtkPointSet* out = Deform(f, grid);
  EXPECT_EQ(out->GetPointData()->GetArray("ChainMailDisplacement"), nullptr);
  f->GenerateDiagnosticsOn();
  f->Update();
  auto* disp = f->GetOutput()->GetPointData()->GetArray("ChainMailDisplacement");
  ASSERT_NE(disp, nullptr);
  EXPECT_EQ(disp->GetComponent(27, 2), 1.0);
  EXPECT_EQ(f->GetOutput()->GetPointData()->GetArray("ChainMailSponsor")->GetComponent(27, 0), -1);
}

TEST(ChainMailDeformationFilter, InputIsNeverModified)
{
  auto grid = UniformGrid(12, 12, 1.0, 0.7);
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(grid);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(70);
  f->SetDisplacement(2, 2, 2);
  Deform(f, grid);
  f->SetDisplacement(-2, 0, 1);
  f->Update();
  EXPECT_EQ(MaxPointDifference(grid, copy), 0.0);
  EXPECT_GT(MaxPointDifference(f->GetOutput(), copy), 1.0);
}

namespace
{
// A 30 x 30 grid, soft (0.9) with a rigid 8 x 8 island, pulled under FIFO: ChainMail
// leaves links violated there (E_link > 0), which the refinement pass reduces.
vtkSmartPointer<vtkPolyData> IslandGrid()
{
  return TriangleGrid(
    30, 30, 1.0, [](int i, int j) { return (i >= 12 && i < 20 && j >= 12 && j < 20) ? 0.0 : 0.9; });
}

// E_link of the filter's output against the grid's own malleability.
double OutputLinkError(vtkPointSet* input, vtkPointSet* output)
{
  const auto mesh = geoshaping::testing::triangle_grid(30, 30, 1.0);
  auto* mal = input->GetPointData()->GetArray("Malleability");
  std::vector<Eigen::Vector3d> rest(900);
  std::vector<double> m(900);
  geoshaping::Displacements u(900);
  for (vtkIdType v = 0; v < 900; ++v)
  {
    double p[3], q[3];
    input->GetPoint(v, p);
    output->GetPoint(v, q);
    rest[v] = Eigen::Vector3d(p[0], p[1], p[2]);
    u[v] = Eigen::Vector3d(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
    m[v] = mal->GetComponent(v, 0);
  }
  return geoshaping::link_error(geoshaping::link_mesh(rest, mesh.adjacency, m), u);
}
} // namespace

TEST(ChainMailDeformationFilter, RefinementZeroIsThePlainChainMailResult)
{
  auto grid = IslandGrid();
  vtkNew<vtkChainMailDeformationFilter> plain, refined;
  for (auto* f : { plain.Get(), refined.Get() })
  {
    f->SetGraspPointId(5 * 30 + 5);
    f->SetDisplacement(2, 1, 9);
    f->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO);
  }
  EXPECT_EQ(refined->GetRefinementIterations(), 0);
  refined->SetRefinementIterations(0);
  EXPECT_EQ(MaxPointDifference(Deform(plain, grid), Deform(refined, grid)), 0.0);
  EXPECT_EQ(refined->GetNumberOfRefinementSweeps(), 0);
  EXPECT_EQ(refined->GetNumberOfRefinedPoints(), 0);
}

TEST(ChainMailDeformationFilter, EnvelopeRefinementSatisfiesEveryLinkInAxesAndIsDykstraInLink)
{
  auto grid = IslandGrid();
  vtkNew<vtkChainMailDeformationFilter> f, dykstra;
  const vtkIdType grasp = 8 * 30 + 8;
  for (auto* g : { f.Get(), dykstra.Get() })
  {
    g->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO);
    g->SetGraspPointId(grasp);
    g->SetDisplacement(3, -2, 12);
  }
  EXPECT_EQ(f->GetRefinementSolver(), vtkChainMailDeformationFilter::REFINEMENT_ENVELOPE)
    << "the default is the solver that satisfies every link";
  dykstra->SetRefinementSolver(vtkChainMailDeformationFilter::REFINEMENT_DYKSTRA);
  const double chainmail = OutputLinkError(grid, Deform(f, grid));
  ASSERT_GT(chainmail, 0.1);
  f->SetRefinementIterations(1);
  f->Update();
  EXPECT_GT(f->GetNumberOfRefinedPoints(), 0);
  EXPECT_LE(OutputLinkError(grid, f->GetOutput()), 1e-9) << "one pass satisfies every link";
  double p[3], q[3];
  grid->GetPoint(grasp, p);
  f->GetOutput()->GetPoint(grasp, q);
  EXPECT_EQ(q[2], p[2] + 12.0);
  // The Link region has no envelope: the pass is Dykstra's.
  for (auto* g : { f.Get(), dykstra.Get() })
  {
    g->SetValidRegionFrame(vtkChainMailDeformationFilter::LINK);
    g->SetRefinementIterations(4);
  }
  EXPECT_EQ(MaxPointDifference(Deform(f, grid), Deform(dykstra, grid)), 0.0);
  f->SetRefinementSolver(99);
  EXPECT_EQ(f->GetRefinementSolver(), vtkChainMailDeformationFilter::REFINEMENT_ENVELOPE);
}

TEST(ChainMailDeformationFilter, RefinementLowersLinkErrorAndKeepsGraspAndPins)
{
  auto grid = IslandGrid();
  vtkNew<vtkIntArray> pins;
  pins->SetName("Pinned");
  pins->SetNumberOfTuples(900);
  pins->Fill(0);
  for (int i = 0; i < 30; ++i)
    pins->SetValue(29 * 30 + i, 1); // the far row
  grid->GetPointData()->AddArray(pins);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Pinned");
  f->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO);
  f->SetRefinementSolver(vtkChainMailDeformationFilter::REFINEMENT_DYKSTRA); // sweep by sweep
  const vtkIdType grasp = 8 * 30 + 8;
  f->SetGraspPointId(grasp);
  f->SetDisplacement(3, -2, 12);
  const double chainmail = OutputLinkError(grid, Deform(f, grid));
  ASSERT_GT(chainmail, 0.1);
  double previous = chainmail;
  for (int sweeps : { 1, 4, 16 })
  {
    f->SetRefinementIterations(sweeps);
    f->Update();
    EXPECT_GT(f->GetNumberOfRefinedPoints(), 0);
    EXPECT_LE(f->GetNumberOfRefinementSweeps(), sweeps);
    const double e = OutputLinkError(grid, f->GetOutput());
    EXPECT_LE(e, previous) << sweeps << " sweeps"; // best iterate: never worse
    previous = e;
    double p[3], q[3];
    grid->GetPoint(grasp, p);
    f->GetOutput()->GetPoint(grasp, q);
    EXPECT_EQ(q[0], p[0] + 3.0);
    EXPECT_EQ(q[1], p[1] - 2.0);
    EXPECT_EQ(q[2], p[2] + 12.0);
    for (vtkIdType v = 29 * 30; v < 900; ++v)
    {
      grid->GetPoint(v, p);
      f->GetOutput()->GetPoint(v, q);
      EXPECT_EQ(q[2], p[2]) << v;
    }
  }
  EXPECT_LT(previous, 0.9 * chainmail);
  EXPECT_EQ(f->GetNumberOfRebuilds(), 1);
  // RefinementTolerance reaches the pass: a loose one never runs more sweeps than a tight
  // one, and when it stops before the cap every link holds to it.
  f->SetRefinementIterations(64);
  f->SetRefinementTolerance(1e-12);
  f->Update();
  const int tight = f->GetNumberOfRefinementSweeps();
  f->SetRefinementTolerance(10.0); // clamped to 1 mean edge
  f->Update();
  const int loose = f->GetNumberOfRefinementSweeps();
  EXPECT_LE(loose, tight);
  if (loose < 64)
    EXPECT_LE(OutputLinkError(grid, f->GetOutput()), 1.0 + 1e-12);
}

TEST(ChainMailDeformationFilter, RefinedSparseUpdatesEqualAFreshFilter)
{
  auto grid = IslandGrid();
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(grid);
  f->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO);
  const vtkIdType grasps[5] = { 5 * 30 + 5, 25 * 30 + 25, 5 * 30 + 5, 15 * 30 + 2, 25 * 30 + 4 };
  const double moves[5][3] = { { 0, 0, 10 }, { 2, 0, -6 }, { 0, 0, 10 }, { 0, 3, 4 }, { 1, 1, 1 } };
  const int sweeps[5] = { 8, 2, 0, 16, 0 };
  for (int k = 0; k < 5; ++k)
  {
    f->SetGraspPointId(grasps[k]);
    f->SetDisplacement(moves[k][0], moves[k][1], moves[k][2]);
    f->SetRefinementIterations(sweeps[k]);
    f->Update();
    vtkNew<vtkChainMailDeformationFilter> fresh;
    fresh->SetGraspPointId(grasps[k]);
    fresh->SetDisplacement(moves[k][0], moves[k][1], moves[k][2]);
    fresh->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO);
    fresh->SetRefinementIterations(sweeps[k]);
    EXPECT_EQ(MaxPointDifference(f->GetOutput(), Deform(fresh, grid)), 0.0) << "step " << k;
  }
  f->SetGraspPointId(-1);
  f->Update();
  EXPECT_EQ(MaxPointDifference(f->GetOutput(), grid), 0.0);
}

TEST(ChainMailDeformationFilter, RelaxationKeepsGraspAndLinksAndSparseUpdatesEqualAFreshFilter)
{
  auto grid = IslandGrid();
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(grid);
  EXPECT_EQ(f->GetRelaxationIterations(), 0);
  const vtkIdType grasps[5] = { 5 * 30 + 5, 25 * 30 + 25, 5 * 30 + 5, 15 * 30 + 2, 25 * 30 + 4 };
  const double moves[5][3] = { { 0, 0, 10 }, { 2, 0, -6 }, { 0, 0, 10 }, { 0, 3, 4 }, { 1, 1, 1 } };
  const int refine[5] = { 0, 4, 0, 8, 0 };
  const int relax[5] = { 10, 5, 0, 20, 0 };
  for (int k = 0; k < 5; ++k)
  {
    f->SetGraspPointId(grasps[k]);
    f->SetDisplacement(moves[k][0], moves[k][1], moves[k][2]);
    f->SetRefinementIterations(refine[k]);
    f->SetRelaxationIterations(relax[k]);
    f->Update();
    EXPECT_EQ(f->GetNumberOfRelaxedPoints() > 0, relax[k] > 0) << "step " << k;
    EXPECT_LE(f->GetNumberOfRelaxationSweeps(), relax[k]);
    double p[3], q[3];
    grid->GetPoint(grasps[k], p);
    f->GetOutput()->GetPoint(grasps[k], q);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(q[i], p[i] + moves[k][i]) << "step " << k;
    vtkNew<vtkChainMailDeformationFilter> fresh, unrelaxed;
    for (auto* g : { fresh.Get(), unrelaxed.Get() })
    {
      g->SetGraspPointId(grasps[k]);
      g->SetDisplacement(moves[k][0], moves[k][1], moves[k][2]);
      g->SetRefinementIterations(refine[k]);
    }
    fresh->SetRelaxationIterations(relax[k]);
    EXPECT_EQ(MaxPointDifference(f->GetOutput(), Deform(fresh, grid)), 0.0) << "step " << k;
    EXPECT_LE(OutputLinkError(grid, f->GetOutput()), OutputLinkError(grid, Deform(unrelaxed, grid)))
      << "step " << k;
  }
  f->SetGraspPointId(-1);
  f->Update();
  EXPECT_EQ(MaxPointDifference(f->GetOutput(), grid), 0.0);
  f->SetRelaxationIterations(VTK_INT_MAX);
  EXPECT_EQ(f->GetRelaxationIterations(), vtkChainMailDeformationFilter::MAX_RELAXATION_ITERATIONS);
  f->SetRelaxationIterations(-3);
  EXPECT_EQ(f->GetRelaxationIterations(), 0);
}

TEST(ChainMailDeformationFilter, RelaxationRunsOnTetrahedra)
{
  auto slab = TetSlab(12, 12, 4, 1.0);
  vtkNew<vtkChainMailDeformationFilter> f, plain;
  for (auto* g : { f.Get(), plain.Get() })
  {
    g->SetDefaultMalleability(0.6);
    g->SetGraspPointId(6 * 12 + 6);
    g->SetDisplacement(0.0, 0.0, 4.0);
  }
  f->SetRelaxationIterations(10);
  vtkPointSet* relaxed = Deform(f, slab);
  EXPECT_GT(f->GetNumberOfRelaxedPoints(), 0);
  EXPECT_GT(MaxPointDifference(relaxed, Deform(plain, slab)), 0.0);
  for (vtkIdType v = 0; v < relaxed->GetNumberOfPoints(); ++v)
  {
    double p[3];
    relaxed->GetPoint(v, p);
    EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
  }
}

namespace
{
// Every output coordinate, for bit-exact comparison (float points widen exactly).
std::vector<double> Coordinates(vtkPointSet* ps)
{
  std::vector<double> x(std::size_t(3 * ps->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < ps->GetNumberOfPoints(); ++i)
    ps->GetPoint(i, x.data() + 3 * i);
  return x;
}

std::vector<double> Drag(
  vtkChainMailDeformationFilter* f, vtkIdType grasp, double dx, double dy, double dz)
{
  f->SetGraspPointId(grasp);
  f->SetDisplacement(dx, dy, dz);
  f->Update();
  return Coordinates(f->GetOutput());
}

// What a client does after CommitEdit (ParaView's proxy does it, docs/editing.md).
void Release(vtkChainMailDeformationFilter* f)
{
  f->SetGraspPointId(-1);
  f->SetDisplacement(0.0, 0.0, 0.0);
}
} // namespace

TEST(ChainMailDeformationFilter, CommitLeavesGraspAndDisplacementToTheClient)
{
  // The output is a function of the properties: after a commit an unchanged grasp is
  // applied again, to the new rest shape, exactly as a fresh filter given the record.
  auto grid = TriangleGrid(21, 21, 1.0, [](int i, int) { return i < 6 ? 0.0 : 0.8; });
  vtkNew<vtkChainMailDeformationFilter> f;
  Deform(f, grid);
  const auto once = Drag(f, 10 * 21 + 10, 0.0, 0.0, 2.0);
  f->CommitEdit();
  EXPECT_EQ(f->GetGraspPointId(), 10 * 21 + 10) << "the server leaves the client's properties";
  EXPECT_EQ(f->GetDisplacement()[2], 2.0);
  ASSERT_EQ(f->GetNumberOfEdits(), 1);
  f->Update();
  vtkNew<vtkChainMailDeformationFilter> fresh;
  fresh->AddEdit(f->GetEdit(0));
  fresh->SetGraspPointId(10 * 21 + 10);
  fresh->SetDisplacement(0.0, 0.0, 2.0);
  const auto twice = Coordinates(f->GetOutput());
  EXPECT_EQ(twice, Coordinates(Deform(fresh, grid)));
  EXPECT_NE(twice, once) << "the grasp moved the committed shape again";
  Release(f);
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), once) << "released: the committed shape";
}

TEST(ChainMailDeformationFilter, CommitUndoRedoAndResetAreBitExact)
{
  auto grid = TriangleGrid(
    25, 25, 1.0, [](int i, int) { return i < 8 ? 0.0 : 0.7; }, VTK_FLOAT, 512345.0, 4123456.0);
  vtkNew<vtkChainMailDeformationFilter> f;
  const auto original = Coordinates(Deform(f, grid));
  const auto one = Drag(f, 12 * 25 + 12, 0.0, 0.0, 3.0);
  f->CommitEdit();
  Release(f);
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), one) << "the committed shape is shown";
  EXPECT_EQ(f->GetNumberOfEdits(), 1);
  const std::string record = f->GetLastEdit();
  EXPECT_EQ(record, f->GetEdit(0));
  const auto two = Drag(f, 12 * 25 + 14, 1.0, 0.0, -2.0);
  f->CommitEdit();
  Release(f);
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), two);

  f->UndoEdit();
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), one) << "undo";
  EXPECT_EQ(f->GetNumberOfRedoableEdits(), 1);
  f->RedoEdit();
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), two) << "redo";
  f->ResetEdits();
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), original) << "reset";
  EXPECT_EQ(f->GetNumberOfRebuilds(), 1) << "edits never rebuild the adjacency";

  // The records alone reproduce the shape in a fresh filter, once per change of the list.
  vtkNew<vtkChainMailDeformationFilter> fresh;
  f->RedoEdit();
  f->RedoEdit();
  EXPECT_EQ(record, f->GetEdit(0));
  fresh->AddEdit(f->GetEdit(0));
  fresh->AddEdit(f->GetEdit(1));
  EXPECT_EQ(Coordinates(Deform(fresh, grid)), two);
}

namespace
{
// The output's bounds as its points report them (cached), and by a pass over its points.
std::array<std::array<double, 6>, 2> ReportedAndExactBounds(vtkPointSet* output)
{
  std::array<std::array<double, 6>, 2> b;
  output->GetPoints()->GetBounds(b[0].data());
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double x[3];
    output->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      b[1][2 * k] = i == 0 ? x[k] : std::min(b[1][2 * k], x[k]);
      b[1][2 * k + 1] = i == 0 ? x[k] : std::max(b[1][2 * k + 1], x[k]);
    }
  }
  return b;
}
} // namespace

TEST(ChainMailDeformationFilter, BoundsShrinkBackOnReleaseUndoRedoAndReset)
{
  // During a drag the bounds only grow (O(moved) a frame); once the shape settles they are
  // exact again, so a large pull backed off, released or undone leaves no grown box.
  auto grid = TriangleGrid(21, 21, 1.0, [](int, int) { return 0.8; });
  vtkNew<vtkChainMailDeformationFilter> f;
  vtkPointSet* out = Deform(f, grid);
  const auto rest = ReportedAndExactBounds(out)[1];
  Drag(f, 10 * 21 + 10, 0.0, 0.0, 60.0);
  Drag(f, 10 * 21 + 10, 0.0, 0.0, 5.0);
  auto b = ReportedAndExactBounds(f->GetOutput());
  EXPECT_EQ(b[0][5], 60.0) << "a drag frame grows the box";
  EXPECT_EQ(b[1][5], 5.0);
  f->CommitEdit();
  Release(f);
  f->Update();
  b = ReportedAndExactBounds(f->GetOutput());
  EXPECT_EQ(b[0], b[1]) << "released";
  EXPECT_EQ(b[0][5], 5.0);
  f->UndoEdit();
  f->Update();
  b = ReportedAndExactBounds(f->GetOutput());
  EXPECT_EQ(b[0], rest) << "undone";
  f->RedoEdit();
  f->Update();
  b = ReportedAndExactBounds(f->GetOutput());
  EXPECT_EQ(b[0], b[1]) << "redone";
  EXPECT_EQ(b[0][5], 5.0);
  f->ResetEdits();
  f->Update();
  EXPECT_EQ(ReportedAndExactBounds(f->GetOutput())[0], rest) << "reset";
}

TEST(ChainMailDeformationFilter, CommitKeepsTheRefinedShape)
{
  auto grid = TriangleGrid(21, 21, 1.0, [](int i, int) { return i < 6 ? 0.0 : 0.9; });
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetRefinementIterations(20);
  Deform(f, grid);
  const auto refined = Drag(f, 10 * 21 + 10, 0.0, 2.0, 4.0);
  ASSERT_GT(f->GetNumberOfRefinedPoints(), 0);
  f->CommitEdit();
  Release(f);
  f->Update();
  EXPECT_EQ(Coordinates(f->GetOutput()), refined);
  f->UndoEdit();
  f->Update();
  EXPECT_EQ(MaxPointDifference(f->GetOutput(), grid), 0.0);
}

TEST(ChainMailDeformationFilter, CommitWithoutADeformationOrWithABadRecordWarns)
{
  auto grid = UniformGrid(11, 11, 1.0, 0.5);
  vtkNew<vtkChainMailDeformationFilter> f;
  vtkNew<vtkTest::ErrorObserver> observer;
  f->AddObserver(vtkCommand::WarningEvent, observer);
  f->AddObserver(vtkCommand::ErrorEvent, observer);
  Deform(f, grid);
  f->CommitEdit();
  EXPECT_TRUE(observer->GetWarning());
  EXPECT_EQ(f->GetNumberOfEdits(), 0);
  f->AddEdit("GSE1 junk");
  f->Update();
  EXPECT_TRUE(observer->GetError());
  EXPECT_EQ(MaxPointDifference(f->GetOutput(), grid), 0.0);
}

TEST(ChainMailDeformationFilter, ValidRegionFrameLinkRotatesWithTheMeshAndAxesIsTheDefault)
{
  // A rotation about z by 30 degrees (exactly representable enough for 1e-9 relative).
  const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
  auto turn = [&](const double p[3], double q[3])
  {
    q[0] = c * p[0] - s * p[1];
    q[1] = s * p[0] + c * p[1];
    q[2] = p[2];
  };
  auto grid = TriangleGrid(25, 25, 1.0, [](int i, int j) { return (i + j) % 5 == 0 ? 0.2 : 0.8; });
  vtkNew<vtkPolyData> turned;
  turned->DeepCopy(grid);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    grid->GetPoint(i, p);
    turn(p, q);
    turned->GetPoints()->SetPoint(i, q);
  }
  const double d[3] = { 3.0, -1.0, 6.0 };
  double dt[3];
  turn(d, dt);
  // The same point GlobalIds on both (the point ids): without them the order follows the
  // coordinates (TestChainMailOrder.cxx), which the rotation changes.
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("GlobalIds");
  ids->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    ids->SetValue(i, i);
  grid->GetPointData()->SetGlobalIds(ids);
  turned->GetPointData()->SetGlobalIds(ids);
  auto run = [&](vtkPolyData* mesh, const double* disp, int frame)
  {
    vtkNew<vtkChainMailDeformationFilter> f;
    EXPECT_EQ(f->GetValidRegionFrame(), vtkChainMailDeformationFilter::AXES);
    f->SetValidRegionFrame(frame);
    f->SetGraspPointId(12 * 25 + 12);
    f->SetDisplacement(disp[0], disp[1], disp[2]);
    Deform(f, mesh);
    EXPECT_GT(f->GetNumberOfDisplacedPoints(), 50);
    vtkSmartPointer<vtkPointSet> out;
    out.TakeReference(f->GetOutput()->NewInstance());
    out->DeepCopy(f->GetOutput());
    return out;
  };
  auto defect = [&](int frame)
  {
    auto a = run(grid, d, frame);
    auto b = run(turned, dt, frame);
    double worst = 0.0;
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3], r[3];
      a->GetPoint(i, p);
      turn(p, q);
      b->GetPoint(i, r);
      worst = std::max(worst, std::hypot(q[0] - r[0], q[1] - r[1], q[2] - r[2]));
    }
    return worst / (24.0 * std::sqrt(2.0));
  };
  EXPECT_LE(defect(vtkChainMailDeformationFilter::LINK), 1e-9);
  EXPECT_GT(defect(vtkChainMailDeformationFilter::AXES), 1e-3);

  // Switching the frame reuses the adjacency and equals a fresh filter with that frame.
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetGraspPointId(12 * 25 + 12);
  f->SetDisplacement(d[0], d[1], d[2]);
  Deform(f, grid);
  f->SetValidRegionFrame(vtkChainMailDeformationFilter::LINK);
  f->Update();
  EXPECT_EQ(f->GetNumberOfRebuilds(), 1);
  EXPECT_EQ(
    MaxPointDifference(f->GetOutput(), run(grid, d, vtkChainMailDeformationFilter::LINK)), 0.0);
  f->SetValidRegionFrame(7); // clamped
  EXPECT_EQ(f->GetValidRegionFrame(), vtkChainMailDeformationFilter::LINK);
  f->SetValidRegionFrame(-1);
  EXPECT_EQ(f->GetValidRegionFrame(), vtkChainMailDeformationFilter::AXES);
}

TEST(ChainMailDeformationFilter, ADemsElevationFollowsTheShapeAndTheRestElevationIsKept)
{
  // A DEM Surface-like grid: z = 300 + 10 x + y, the point array Elevation = z, active.
  auto dem = geoshaping::testing::TriangleGridPolyData(21, 21, 1.0, {});
  vtkNew<vtkDoubleArray> elevation;
  elevation->SetName("Elevation");
  elevation->SetNumberOfTuples(dem->GetNumberOfPoints());
  for (vtkIdType p = 0; p < dem->GetNumberOfPoints(); ++p)
  {
    double x[3];
    dem->GetPoint(p, x);
    x[2] = 300.0 + 10.0 * x[0] + x[1];
    dem->GetPoints()->SetPoint(p, x);
    elevation->SetValue(p, x[2]);
  }
  dem->GetPointData()->SetScalars(elevation);
  vtkNew<vtkChainMailDeformationFilter> f;
  f->SetInputData(dem);
  f->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  f->SetGraspPointId(10 * 21 + 10);
  const auto check = [&](const char* when)
  {
    f->Update();
    auto* out = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
    vtkDataArray* now = out->GetPointData()->GetArray("Elevation");
    vtkDataArray* rest = out->GetPointData()->GetArray("RestElevation");
    if (!now || !rest)
    {
      ADD_FAILURE() << when << ": no Elevation or RestElevation";
      return vtkIdType(-1);
    }
    EXPECT_EQ(out->GetPointData()->GetScalars(), now) << when;
    vtkIdType raised = 0, notZ = 0, notRest = 0;
    for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    {
      double x[3];
      out->GetPoint(p, x);
      notZ += now->GetComponent(p, 0) != x[2];
      notRest += rest->GetComponent(p, 0) != elevation->GetValue(p);
      raised += x[2] > elevation->GetValue(p);
    }
    EXPECT_EQ(notZ, 0) << when << ": vertices whose Elevation is not their z";
    EXPECT_EQ(notRest, 0) << when << ": vertices whose RestElevation is not the input's";
    EXPECT_EQ(elevation->GetValue(0), dem->GetPoint(0)[2]) << "the input's array is untouched";
    return raised;
  };
  f->SetDisplacement(0, 0, 500);
  EXPECT_GT(check("pulled up"), 1);
  f->SetDisplacement(3, -2, 200); // a smaller pull: vertices the first moved come back
  EXPECT_GT(check("pulled less"), 1);
  f->CommitEdit();
  f->SetGraspPointId(5 * 21 + 5);
  f->SetDisplacement(0, 0, -100);
  EXPECT_GT(check("a second drag after the commit"), 1);
  f->UndoEdit();
  check("undone");
}
