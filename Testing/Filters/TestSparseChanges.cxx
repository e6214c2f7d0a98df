// vtkGrowingBoundsPoints and vtkSparseArrayChanges: what a sparse rewrite leaves in the
// caches that bounds and range queries read, and what a consumer may follow.
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkSparseArrayChanges.h"

#include <gtest/gtest.h>

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
