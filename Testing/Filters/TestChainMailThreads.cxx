// vtkChainMailDeformationFilter with NumberOfThreads > 1 and the threshold forced low: every
// frame runs supersteps on threads, and the output (points, displacement and sponsor
// diagnostics, figures) equals the one-thread filter's bit for bit.
#include "vtkChainMailDeformationFilter.h"

#include "vtk_test_meshes.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

namespace
{
// Every point's position and the named point array's tuples, as bits.
bool SameArray(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
      a->GetNumberOfComponents() != b->GetNumberOfComponents())
    return false;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      const double x = a->GetComponent(i, c), y = b->GetComponent(i, c);
      if (std::memcmp(&x, &y, sizeof x) != 0)
        return false;
    }
  return true;
}
} // namespace

TEST(ChainMailThreads, ThreadedFramesEqualTheOneThreadFilterBitForBit)
{
  // Bands of malleability across the grid, so FIFO Priority enters several regions.
  auto grid = geoshaping::testing::TriangleGridPolyData(70, 60, 1.0,
    [](int i, int j)
    { return 0.3 + 0.1 * std::floor(3.5 + 3.4 * std::sin(0.2 * i) * std::cos(0.15 * j)); });
  for (int queue :
    { vtkChainMailDeformationFilter::FIFO, vtkChainMailDeformationFilter::FIFO_PRIORITY })
  {
    vtkNew<vtkChainMailDeformationFilter> threaded, plain;
    for (vtkChainMailDeformationFilter* f : { threaded.Get(), plain.Get() })
    {
      f->SetInputData(grid);
      f->SetCandidateQueue(queue);
      f->SetGenerateDiagnostics(true);
      f->SetGraspPointId(30 * 70 + 35);
    }
    threaded->SetNumberOfThreads(3);
    threaded->ThreadsEvenWhenBusyOn(); // what is checked does not depend on the load
    plain->SetNumberOfThreads(1);
    threaded->SetThreadedSuperstepThreshold(2);
    const double pulls[4][3] = { { 0.0, 0.0, 4.0 }, { 1.0, 0.5, 7.0 }, { -2.0, 1.0, 9.0 },
      { 0.5, -3.0, 6.0 } };
    for (int frame = 0; frame < 4; ++frame)
    {
      const std::string what =
        "queue " + std::to_string(queue) + ", frame " + std::to_string(frame);
      for (vtkChainMailDeformationFilter* f : { threaded.Get(), plain.Get() })
      {
        f->SetDisplacement(pulls[frame][0], pulls[frame][1], pulls[frame][2]);
        f->Update();
      }
      EXPECT_EQ(threaded->GetLastFrameThreads(), 3) << what;
      EXPECT_GT(threaded->GetLastFrameThreadedSupersteps(), 0) << what;
      EXPECT_EQ(plain->GetLastFrameThreadedSupersteps(), 0) << what;
      EXPECT_GT(plain->GetLastFrameSupersteps(), 10) << what;
      EXPECT_EQ(threaded->GetLastFrameSupersteps(), plain->GetLastFrameSupersteps()) << what;
      EXPECT_EQ(plain->GetLastFrameThreads(), 1) << what;
      EXPECT_GT(plain->GetNumberOfDisplacedPoints(), 300) << what;
      EXPECT_EQ(threaded->GetNumberOfDisplacedPoints(), plain->GetNumberOfDisplacedPoints())
        << what;
      EXPECT_EQ(threaded->GetNumberOfExaminedCandidates(), plain->GetNumberOfExaminedCandidates())
        << what;
      vtkPointSet* a = threaded->GetOutput();
      vtkPointSet* b = plain->GetOutput();
      EXPECT_TRUE(SameArray(a->GetPoints()->GetData(), b->GetPoints()->GetData())) << what;
      for (const char* name : { "ChainMailDisplacement", "ChainMailSponsor" })
        EXPECT_TRUE(SameArray(a->GetPointData()->GetArray(name), b->GetPointData()->GetArray(name)))
          << what << " " << name;
    }
  }
}
