// vtkGrowingBoundsPoints and vtkSparseArrayChanges: what a sparse rewrite leaves in the
// caches that bounds and range queries read, and what a consumer may follow.
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkSparseArrayChanges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
vtkSmartPointer<vtkGrowingBoundsPoints> Line(int n)
{
  auto points = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
  for (int i = 0; i < n; ++i)
    points->InsertNextPoint(i, 0, 0);
  return points;
}
} // namespace

TEST(GrowingBoundsPoints, FirstQueryIsExactThenChangesGrowTheBox)
{
  auto points = Line(10);
  double b[6];
  points->GetBounds(b);
  EXPECT_EQ(b[1], 9.0);
  EXPECT_TRUE(points->HasGrownBounds());
  points->SetPoint(3, 4.0, 5.0, -2.0);
  const vtkIdType id = 3;
  points->PointsChanged(&id, 1);
  points->GetBounds(b);
  EXPECT_EQ(b[2], 0.0);
  EXPECT_EQ(b[3], 5.0);
  EXPECT_EQ(b[4], -2.0);
  // The coordinate array's ranges agree with the box, without a pass over the points.
  double range[2];
  points->GetData()->GetRange(range, 1);
  EXPECT_EQ(range[1], 5.0);
  // Moving it back does not shrink the box (conservative until an exact pass).
  points->SetPoint(3, 3.0, 0.0, 0.0);
  points->PointsChanged(&id, 1);
  points->GetBounds(b);
  EXPECT_EQ(b[3], 5.0);
}

TEST(GrowingBoundsPoints, AnExactChangeShrinksTheBoxAndIsStillListed)
{
  auto points = Line(10);
  double b[6];
  points->GetBounds(b);
  const vtkIdType id = 9;
  points->SetPoint(9, 20.0, 0.0, 0.0);
  points->PointsChanged(&id, 1);
  points->GetBounds(b);
  EXPECT_EQ(b[1], 20.0);
  EXPECT_FALSE(points->GetLastChangeExact());
  const int g = points->GetGeneration();
  points->SetPoint(9, 9.0, 0.0, 0.0); // back: a released drag
  points->PointsChanged(&id, 1, true);
  EXPECT_TRUE(points->GetLastChangeExact());
  ASSERT_NE(points->ChangesAfter(g), nullptr) << "a consumer still follows it sparsely";
  points->GetBounds(b);
  EXPECT_EQ(b[1], 9.0);
  double range[2];
  points->GetData()->GetRange(range, 0);
  EXPECT_EQ(range[1], 9.0);
}

TEST(GrowingBoundsPoints, AnyOtherModificationTakesAnExactPass)
{
  auto points = Line(10);
  double b[6];
  points->GetBounds(b);
  points->SetPoint(9, 20.0, 0.0, 0.0);
  points->Modified();
  points->GetBounds(b);
  EXPECT_EQ(b[1], 20.0);
  points->SetPoint(9, 1.0, 0.0, 0.0);
  points->Modified();
  points->GetBounds(b);
  EXPECT_EQ(b[1], 8.0); // exact again: shrinks
}

namespace
{
// A 20 x 20 grid in the plane z = 0 with a bump, as float points (as the filter's output).
vtkSmartPointer<vtkGrowingBoundsPoints> Grid()
{
  auto points = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
  points->SetDataTypeToFloat();
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i)
      points->InsertNextPoint(i, j, (i == 3 && j == 4) ? 2.0 : 0.1 * ((i * 7 + j * 3) % 5));
  return points;
}

// What a pass over every point gives: the box and the norm range.
void Brute(vtkPoints* points, double box[6], double norm[2])
{
  vtkNew<vtkPoints> copy;
  copy->DeepCopy(points);
  copy->GetBounds(box);
  norm[0] = VTK_DOUBLE_MAX;
  norm[1] = 0.0;
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    double x[3];
    copy->GetPoint(i, x);
    const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    norm[0] = std::min(norm[0], r);
    norm[1] = std::max(norm[1], r);
  }
}

void Move(vtkGrowingBoundsPoints* points, vtkIdType id, double x, double y, double z, bool exact)
{
  points->SetPoint(id, x, y, z);
  points->PointsChanged(&id, 1, exact);
}
} // namespace

TEST(GrowingBoundsPoints, ASettleAwayFromTheExtremesIsExactWithoutAPassOverEveryPoint)
{
  // A drag of interior points out beyond the box and partly back, then the release: the
  // exact box and norm range come from the rest box and the moved points alone.
  auto points = Grid();
  double b[6], range[2];
  points->GetBounds(b);
  EXPECT_EQ(points->GetNumberOfFullPasses(), 1);
  Move(points, 210, 10, 10, 9.0, false); // up, beyond the bump
  Move(points, 211, 11, 10, -3.0, false);
  points->GetBounds(b);
  EXPECT_EQ(b[5], 9.0);
  Move(points, 210, 10, 10, 1.5, false); // back down, still moved
  Move(points, 211, 11, 10, 0.0, true);  // the release
  double box[6], norm[2];
  Brute(points, box, norm);
  points->GetBounds(b);
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(b[k], box[k]) << k;
  EXPECT_EQ(b[5], 2.0); // shrank back to the bump
  points->GetData()->GetRange(range, -1);
  EXPECT_EQ(range[0], norm[0]);
  EXPECT_EQ(range[1], norm[1]);
  points->GetData()->GetRange(range, 2);
  EXPECT_EQ(range[1], 2.0);
  EXPECT_EQ(points->GetNumberOfFullPasses(), 1);
  // The settled state is the next exact one: a second drag and release, beyond the box.
  Move(points, 100, 0, 5, 7.0, false);
  Move(points, 100, 0, 5, 4.0, true);
  points->GetBounds(b);
  Brute(points, box, norm);
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(b[k], box[k]) << k;
  EXPECT_EQ(b[5], 4.0);
  // The same point pulled further (it is the witness of z max now, moved outward).
  Move(points, 100, 0, 5, 6.0, true);
  points->GetBounds(b);
  EXPECT_EQ(b[5], 6.0);
  EXPECT_EQ(points->GetNumberOfFullPasses(), 1);
}

TEST(GrowingBoundsPoints, ASettleThatMovedAnExtremePointPassesOverEveryPoint)
{
  // The bump (the highest point) pulled down: z max shrinks to the next highest point,
  // which only a pass over every point finds.
  auto points = Grid();
  double b[6];
  points->GetBounds(b);
  EXPECT_EQ(b[5], 2.0);
  Move(points, 4 * 20 + 3, 3, 4, 0.0, true);
  double box[6], norm[2];
  Brute(points, box, norm);
  points->GetBounds(b);
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(b[k], box[k]) << k;
  EXPECT_LT(b[5], 2.0);
  EXPECT_EQ(points->GetNumberOfFullPasses(), 2);
}

TEST(GrowingBoundsPoints, ChangesAreFollowedOnlyFromTheDirectlyPreviousUpdate)
{
  auto points = Line(10);
  const vtkIdType a[2] = { 1, 2 }, c = 7;
  points->PointsChanged(a, 2);
  const int g = points->GetGeneration();
  points->PointsChanged(&c, 1);
  ASSERT_NE(points->ChangesAfter(g), nullptr);
  EXPECT_EQ(points->ChangesAfter(g)->GetValue(0), 7);
  EXPECT_EQ(points->ChangesAfter(g - 1), nullptr); // skipped an update
  points->Modified();
  EXPECT_EQ(points->ChangesAfter(g), nullptr); // modified some other way
}

TEST(SparseArrayChanges, CachedRangesGrowOverTheChangedTuples)
{
  vtkNew<vtkFloatArray> values;
  for (int i = 0; i < 100; ++i)
    values->InsertNextValue(0.5f);
  double range[2];
  values->GetRange(range, 0);
  EXPECT_EQ(range[0], 0.5);
  values->SetValue(42, 0.125f);
  const vtkIdType id = 42;
  vtkSparseArrayChanges::ValuesChanged(values, &id, 1);
  values->GetRange(range, 0);
  EXPECT_EQ(range[0], 0.125);
  EXPECT_EQ(range[1], 0.5);
  ASSERT_NE(vtkSparseArrayChanges::ChangesAfter(values, 0), nullptr);
  EXPECT_EQ(vtkSparseArrayChanges::ChangesAfter(values, 0)->GetValue(0), 42);
  values->Modified();
  EXPECT_EQ(vtkSparseArrayChanges::ChangesAfter(values, 0), nullptr);
}

TEST(SparseArrayChanges, AnArrayWithoutCachedRangesGetsAnExactOneLater)
{
  vtkNew<vtkDoubleArray> values;
  for (int i = 0; i < 10; ++i)
    values->InsertNextValue(i);
  values->SetValue(0, -3.0);
  const vtkIdType id = 0;
  vtkSparseArrayChanges::ValuesChanged(values, &id, 1);
  double range[2];
  values->GetRange(range, 0);
  EXPECT_EQ(range[0], -3.0);
  EXPECT_EQ(range[1], 9.0);
}
