// Stability of vtkChainMailDeformationFilter on stiff, extreme and malformed input
// (docs/stability.md). Every case goes through stability::Run, which asserts
// the input unmodified, nothing non-finite introduced and the ChainMail invariants.
#include "StabilityHarness.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using stability::Check;
using stability::Grid;
using stability::Slab;
using Filter = vtkChainMailDeformationFilter;

namespace
{
const double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

vtkSmartPointer<Filter> Make(
  vtkIdType grasp, double dx, double dy, double dz, int queue = Filter::FIFO_PRIORITY)
{
  auto f = vtkSmartPointer<Filter>::New();
  f->SetGraspPointId(grasp);
  f->SetDisplacement(dx, dy, dz);
  f->SetCandidateQueue(queue);
  return f;
}

double Z(vtkPointSet* out, vtkIdType v)
{
  double p[3];
  out->GetPoint(v, p);
  return p[2];
}

// A grid with the left half rigid (0) and the right half soft (1).
vtkSmartPointer<vtkPolyData> StepContrast()
{
  auto g = Grid(30, 30, 1.0, 1.0);
  auto* m = g->GetPointData()->GetArray("Malleability");
  for (vtkIdType v = 0; v < 900; ++v)
    m->SetComponent(v, 0, v % 30 < 15 ? 0.0 : 1.0);
  return g;
}

void SetMalleability(vtkPointSet* g, vtkIdType v, double value)
{
  g->GetPointData()->GetArray("Malleability")->SetComponent(v, 0, value);
}
} // namespace

// --- stiffness ------------------------------------------------------------------------

TEST(Filter, MalleabilityZeroEverywhereTranslatesTheWholeMesh)
{
  auto g = Grid(20, 20, 1.0, 0.0);
  auto f = Make(210, 1, 2, 3);
  auto o = Check(f, g);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 400);
  EXPECT_EQ(Z(o.output, 0), 3.0);
}

TEST(Filter, Stretch200AbsorbsAnAxialPullInTheGraspRow)
{
  // Behind the grasp the first link along x may stretch to 200 edge lengths, so the row
  // there stays put; ahead of it compression pushes vertices on.
  auto g = Grid(20, 20, 1.0, 1.0);
  auto f = Make(210, 50, 0, 0);
  f->SetStretchRange(1, 200);
  auto o = Check(f, g);
  double p[3];
  if (f->GetValidRegionFrame() == Filter::LINK)
  {
    // The cylinder lets a link stretch only along itself: the diagonal neighbour (9, 9)
    // (link o = (-1, -1, 0), l = sqrt(2)) takes the pull's part along the link,
    // a = 50 / sqrt(2), and slides h l = 0.5 sqrt(2) of the rest across it:
    // u = (-25, -25, 0) + (-0.5, 0.5, 0) + (50, 0, 0) = (24.5, -24.5, 0).
    o.output->GetPoint(189, p);
    EXPECT_NEAR(p[0], 9.0 + 24.5, 1e-12);
    EXPECT_NEAR(p[1], 9.0 - 24.5, 1e-12);
    o.output->GetPoint(209, p); // the link along x stretches 50x: 209 is not pushed by 210
    EXPECT_LT(p[0], 9.0 + 50.0);
    return;
  }
  o.output->GetPoint(208, p); // behind the grasp: the link stretches 50x, 208 stays
  EXPECT_EQ(p[0], 8.0);
}

TEST(Filter, CompressionZeroLetsNeighboursCollapse)
{
  auto g = Grid(20, 20, 1.0, 1.0);
  auto f = Make(210, -5, 0, 0);
  f->SetCompressionRange(1, 0);
  Check(f, g);
  EXPECT_GT(f->GetNumberOfDisplacedPoints(), 1);
}

TEST(Filter, ShearZeroPropagatesAVerticalPullRigidly)
{
  auto g = Grid(20, 20, 1.0, 1.0);
  auto f = Make(210, 0, 0, 4);
  f->SetShearRange(0, 0);
  auto o = Check(f, g);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 400); // no slack across: everything lifts
  EXPECT_EQ(Z(o.output, 0), 4.0);
}

TEST(Filter, ShearTenAbsorbsAVerticalPullAtTheGrasp)
{
  auto g = Grid(20, 20, 1.0, 1.0);
  auto f = Make(210, 0, 0, 4);
  f->SetShearRange(0, 10);
  Check(f, g);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 1);
}

class Queues : public ::testing::TestWithParam<int>
{
};

TEST_P(Queues, ZeroOneStepContrastStaysFiniteAndInvariant)
{
  auto g = StepContrast();
  auto f = Make(15 * 30 + 20, 3, -2, 9, GetParam());
  Check(f, g);
  EXPECT_GT(f->GetNumberOfDisplacedPoints(), 1);
}

TEST_P(Queues, HugeDisplacementOnTheStepStaysFinite)
{
  auto g = StepContrast();
  auto f = Make(15 * 30 + 20, 0, 0, 30e6, GetParam()); // 1e6 x the extent
  Check(f, g);
}

TEST_P(Queues, RefinementOnAStiffContrastStaysFinite)
{
  auto g = StepContrast();
  auto f = Make(15 * 30 + 20, 0, 4, 12, GetParam());
  f->SetStretchRange(1, 200);
  f->SetRefinementIterations(16);
  Check(f, g);
}

INSTANTIATE_TEST_SUITE_P(Stiff, Queues,
  ::testing::Values(Filter::FIFO, Filter::PRIORITY, Filter::FIFO_PRIORITY, Filter::MAX_VIOLATION));

// --- displacement magnitudes -----------------------------------------------------------

TEST(Filter, ZeroDisplacementLeavesTheMeshAtRest)
{
  auto g = Grid(10, 10, 1.0, 0.5);
  auto f = Make(55, 0, 0, 0);
  auto o = Check(f, g);
  for (vtkIdType v = 0; v < 100; ++v)
    EXPECT_EQ(Z(o.output, v), 0.0);
}

TEST(Filter, TinyDisplacementMovesOnlyTheGrasp)
{
  auto g = Grid(10, 10, 1.0, 0.5);
  auto f = Make(55, 0, 0, 1e-12);
  auto o = Check(f, g);
  EXPECT_EQ(Z(o.output, 55), 1e-12);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 1);
}

TEST(Filter, DisplacementMillionTimesTheExtentStaysFinite)
{
  auto g = Grid(10, 10, 1.0, 0.5);
  auto f = Make(55, 9e6, -9e6, 9e6);
  auto o = Check(f, g);
  EXPECT_EQ(Z(o.output, 55), 9e6);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 100);
}

TEST(Filter, DisplacementMillionTimesTheExtentOnATetSlab)
{
  auto s = Slab(6, 6, 3, 1.0, 0.7);
  auto f = Make(40, 0, 5e6, 0);
  Check(f, s);
}

// --- precision ---------------------------------------------------------------------------

TEST(Filter, UtmFloat32MatchesTheSameMeshNearTheOrigin)
{
  // float32 points at x ~ 5e5, y ~ 4e6 (spacing 8 m, exactly representable) against the
  // same mesh at the origin in double: the double outputs' displacements agree to 1e-9
  // of the extent.
  auto utm = Grid(25, 25, 8.0, 0.6, VTK_FLOAT, 500000.0, 4000000.0);
  auto local = Grid(25, 25, 8.0, 0.6, VTK_DOUBLE);
  for (vtkIdType v = 0; v < 625; v += 7)
  {
    SetMalleability(utm, v, 0.0);
    SetMalleability(local, v, 0.0);
  }
  vtkSmartPointer<Filter> f[2] = { Make(312, 3.5, -2.25, 20), Make(312, 3.5, -2.25, 20) };
  for (auto& fi : f)
    fi->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  auto a = Check(f[0], utm);
  auto b = Check(f[1], local);
  const double extent = 24 * 8.0;
  double p[3], q[3], r[3], s[3];
  for (vtkIdType v = 0; v < 625; ++v)
  {
    utm->GetPoint(v, p);
    a.output->GetPoint(v, q);
    local->GetPoint(v, r);
    b.output->GetPoint(v, s);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(q[c] - p[c], s[c] - r[c], 1e-9 * extent) << v;
  }
  EXPECT_EQ(f[0]->GetNumberOfDisplacedPoints(), f[1]->GetNumberOfDisplacedPoints());
}

TEST(Filter, UtmDoubleKeepsRigidTranslationExact)
{
  auto utm = Grid(15, 15, 10.0, 0.0, VTK_DOUBLE, 512345.678, 4123456.789);
  auto f = Make(100, 0.125, 0.25, 1.5);
  auto o = Check(f, utm);
  double p[3], q[3];
  utm->GetPoint(0, p);
  o.output->GetPoint(0, q);
  EXPECT_EQ(q[0], p[0] + 0.125);
  EXPECT_EQ(q[1], p[1] + 0.25);
}

// --- non-finite input ----------------------------------------------------------------------

TEST(Filter, NaNPointIsRefusedWithAMessage)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  g->GetPoints()->SetPoint(10, kNaN, 0, 0);
  auto f = Make(20, 0, 0, 1);
  auto o = Check(f, g, false);
  EXPECT_TRUE(o.error);
  EXPECT_NE(o.messages.find("non-finite"), std::string::npos);
  EXPECT_EQ(Z(o.output, 20), 0.0);
}

TEST(Filter, InfPointIsRefusedWithAMessage)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  g->GetPoints()->SetPoint(10, 0, -kInf, 0);
  auto f = Make(20, 0, 0, 1);
  auto o = Check(f, g, false);
  EXPECT_TRUE(o.error);
  EXPECT_EQ(Z(o.output, 20), 0.0);
}

TEST(Filter, NaNMalleabilityWarnsAndCountsAsRigid)
{
  auto g = Grid(10, 10, 1.0, 0.8);
  SetMalleability(g, 56, kNaN);
  auto f = Make(55, 0, 0, 3);
  Check(f, g);
  // (the harness treats NaN as 0 too, so the valid-region check covers vertex 56)
}

TEST(Filter, InfAndOutOfRangeMalleabilityAreClampedWithAWarning)
{
  auto g = Grid(10, 10, 1.0, 0.8);
  SetMalleability(g, 56, kInf);
  SetMalleability(g, 57, -kInf);
  SetMalleability(g, 58, 7.0);
  auto f = Make(55, 0, 0, 3);
  auto o = Check(f, g);
  EXPECT_TRUE(o.warning);
  EXPECT_NE(o.messages.find("clamped"), std::string::npos);
}

TEST(Filter, NaNDisplacementIsRefusedWithAMessage)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  auto f = Make(20, kNaN, 0, 1);
  auto o = Check(f, g);
  EXPECT_TRUE(o.error);
  EXPECT_EQ(f->GetNumberOfDisplacedPoints(), 0);
}

TEST(Filter, InfDisplacementIsRefusedWithAMessage)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  auto f = Make(20, 0, kInf, 1);
  auto o = Check(f, g);
  EXPECT_TRUE(o.error);
  EXPECT_EQ(Z(o.output, 20), 0.0);
}

TEST(Filter, RefusedFrameAfterAGoodOneRestoresTheRestShape)
{
  auto g = Grid(12, 12, 1.0, 0.5);
  auto f = Make(70, 0, 0, 4);
  Check(f, g);
  f->SetDisplacement(kNaN, 0, 0);
  auto o = Check(f, g);
  EXPECT_TRUE(o.error);
  for (vtkIdType v = 0; v < 144; ++v)
    EXPECT_EQ(Z(o.output, v), 0.0);
}

// --- grasp -------------------------------------------------------------------------------------

TEST(Filter, GraspMinusOneIsTheUndeformedInputWithoutError)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  auto f = Make(-1, 0, 0, 5);
  auto o = Check(f, g);
  EXPECT_FALSE(o.error);
  EXPECT_EQ(Z(o.output, 0), 0.0);
}

TEST(Filter, GraspEqualToThePointCountIsRefused)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  auto f = Make(64, 0, 0, 5);
  auto o = Check(f, g);
  EXPECT_TRUE(o.error);
  EXPECT_NE(o.messages.find("outside"), std::string::npos);
}

TEST(Filter, GraspFarBeyondThePointCountIsRefused)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  auto f = Make(vtkIdType(1) << 40, 0, 0, 5);
  auto o = Check(f, g);
  EXPECT_TRUE(o.error);
}

TEST(Filter, GraspOfAPinnedVertexIsRefused)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  vtkNew<vtkIntArray> pins;
  pins->SetName("Pinned");
  pins->SetNumberOfTuples(64);
  pins->Fill(0);
  pins->SetValue(20, 1);
  g->GetPointData()->AddArray(pins);
  auto f = Make(20, 0, 0, 5);
  f->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Pinned");
  auto o = Check(f, g);
  EXPECT_TRUE(o.error);
}

TEST(Filter, NearestGraspWithANaNPositionDoesNotCrash)
{
  auto g = Grid(8, 8, 1.0, 0.5);
  auto f = Make(0, 0, 0, 1);
  f->SetGraspMode(Filter::GRASP_NEAREST_TO_POSITION);
  f->SetGraspPosition(kNaN, 0, 0);
  Check(f, g);
}
