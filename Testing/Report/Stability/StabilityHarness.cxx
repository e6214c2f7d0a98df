#include "StabilityHarness.h"

#include "vtkGeoShapingAdapter.h"
#include "vtk_test_meshes.h"

#include "geoshaping/metrics/error_metrics.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace stability
{

vtkSmartPointer<vtkPolyData> Grid(
  int nx, int ny, double h, double m, int type, double x0, double y0)
{
  return geoshaping::testing::TriangleGridPolyData(
    nx, ny, h, [m](int, int) { return m; }, type, x0, y0);
}

vtkSmartPointer<vtkUnstructuredGrid> Slab(int nx, int ny, int nz, double h, double m)
{
  return geoshaping::testing::TetSlabUnstructuredGrid(
    nx, ny, nz, h, [m](int, int, int) { return m; });
}

namespace
{
bool SameBits(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}

void ExpectSameData(vtkPointSet* a, vtkPointSet* b)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  double p[3], q[3];
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    for (int c = 0; c < 3; ++c)
      ASSERT_TRUE(SameBits(p[c], q[c])) << "input point " << i << " was modified";
  }
  vtkDataArray* ma = a->GetPointData()->GetArray("Malleability");
  vtkDataArray* mb = b->GetPointData()->GetArray("Malleability");
  ASSERT_EQ(ma == nullptr, mb == nullptr);
  if (ma)
    for (vtkIdType i = 0; i < ma->GetNumberOfValues(); ++i)
      ASSERT_TRUE(SameBits(ma->GetVariantValue(i).ToDouble(), mb->GetVariantValue(i).ToDouble()));
}

double Clamped(double m)
{
  return std::isnan(m) ? 0.0 : std::min(1.0, std::max(0.0, m));
}

void ExpectInvariants(vtkChainMailDeformationFilter* f, vtkPointSet* input, vtkPointSet* out)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* disp = out->GetPointData()->GetArray("ChainMailDisplacement");
  vtkDataArray* sponsor = out->GetPointData()->GetArray("ChainMailSponsor");
  if (!disp || !sponsor)
    return; // no deformation ran (refused input): nothing moved
  vtkIdType skipped = 0;
  const geoshaping::Adjacency adj = vtkGeoShapingAdapter::BuildAdjacency(input, skipped);
  std::vector<Eigen::Vector3d> rest(static_cast<std::size_t>(n));
  std::vector<double> m(static_cast<std::size_t>(n), f->GetDefaultMalleability());
  vtkDataArray* mal = input->GetPointData()->GetArray("Malleability");
  geoshaping::Displacements u(static_cast<std::size_t>(n));
  double umax = 0.0;
  for (vtkIdType v = 0; v < n; ++v)
  {
    input->GetPoint(v, rest[v].data());
    if (mal && mal->GetNumberOfComponents() == 1)
      m[v] = Clamped(mal->GetComponent(v, 0));
    disp->GetTuple(v, u[v].data());
    ASSERT_TRUE(u[v].allFinite()) << v;
    umax = std::max(umax, u[v].norm());
  }
  geoshaping::TransferFunction tf;
  tf.stretch = { f->GetStretchRange()[0], f->GetStretchRange()[1] };
  tf.compression = { f->GetCompressionRange()[0], f->GetCompressionRange()[1] };
  tf.shear = { f->GetShearRange()[0], f->GetShearRange()[1] };
  geoshaping::LinkMesh lm = geoshaping::link_mesh(rest, adj, m, tf);
  lm.frame = static_cast<geoshaping::ValidRegionFrame>(f->GetValidRegionFrame());
  const double tol = 1e-9 * (lm.scale() + umax);

  // The sponsors form a tree rooted at the grasp: each moved vertex moved once.
  const vtkIdType grasp = f->GetLastGraspPointId();
  vtkIdType moved = 0;
  for (vtkIdType v = 0; v < n; ++v)
  {
    const vtkIdType s = vtkIdType(sponsor->GetComponent(v, 0));
    if (v == grasp)
    {
      EXPECT_EQ(s, -1);
      ++moved;
      continue;
    }
    if (s < 0)
    {
      if (f->GetRefinementIterations() == 0)
        EXPECT_EQ(u[v].norm(), 0.0) << "vertex " << v << " moved without a sponsor";
      continue;
    }
    ++moved;
    ASSERT_LT(s, n);
    EXPECT_TRUE(std::binary_search(adj.begin(v), adj.end(v), geoshaping::index_t(s)))
      << "sponsor " << s << " of " << v << " is not a neighbour";
    EXPECT_TRUE(s == grasp || sponsor->GetComponent(s, 0) >= 0)
      << "sponsor " << s << " never moved";
    if (f->GetRefinementIterations() == 0)
      EXPECT_LE(geoshaping::link_distance(lm, u, v, s), tol) << v << " outside its valid region";
  }
  EXPECT_EQ(moved, f->GetNumberOfDisplacedPoints());
  // Pinned vertices (the "Pinned" array of these tests) may hold a rigid region back.
  if (f->GetCandidateQueue() == vtkChainMailDeformationFilter::FIFO_PRIORITY &&
      f->GetRefinementIterations() == 0 && !input->GetPointData()->GetArray("Pinned"))
    EXPECT_EQ(geoshaping::rigid_error(lm, u), 0.0) << "a rigid region did not translate exactly";
  if (out->GetPoints()->GetDataType() == VTK_DOUBLE)
    for (vtkIdType v = 0; v < n; ++v)
    {
      double q[3];
      out->GetPoint(v, q);
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(q[c], rest[v][c] + u[v][c]) << v;
    }
}
} // namespace

Outcome Check(vtkChainMailDeformationFilter* f, vtkPointSet* input, bool check_invariants)
{
  Outcome o;
  vtkSmartPointer<vtkPointSet> copy;
  copy.TakeReference(input->NewInstance());
  copy->DeepCopy(input);
  vtkNew<vtkTest::ErrorObserver> observer;
  const unsigned long e = f->AddObserver(vtkCommand::ErrorEvent, observer);
  const unsigned long w = f->AddObserver(vtkCommand::WarningEvent, observer);
  f->GenerateDiagnosticsOn();
  // The whole suite runs once per valid-region shape (CMakeLists.txt: Stability.* with
  // the default Axes, StabilityLink.* with GEOSHAPING_STABILITY_FRAME=1).
  if (const char* frame = std::getenv("GEOSHAPING_STABILITY_FRAME"))
    f->SetValidRegionFrame(std::atoi(frame));
  f->SetInputData(input);
  f->Update();
  f->RemoveObserver(e);
  f->RemoveObserver(w);
  o.error = observer->GetError();
  o.warning = observer->GetWarning();
  o.messages = observer->GetErrorMessage() + observer->GetWarningMessage();
  o.output = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
  EXPECT_NE(o.output, nullptr);
  ExpectSameData(input, copy);
  if (!o.output)
    return o;
  EXPECT_EQ(o.output->GetNumberOfPoints(), input->GetNumberOfPoints());
  double p[3], q[3];
  for (vtkIdType i = 0; i < std::min(input->GetNumberOfPoints(), o.output->GetNumberOfPoints());
       ++i)
  {
    input->GetPoint(i, p);
    o.output->GetPoint(i, q);
    for (int c = 0; c < 3; ++c)
      if (std::isfinite(p[c]))
        EXPECT_TRUE(std::isfinite(q[c])) << "non-finite output at point " << i;
  }
  if (check_invariants)
    ExpectInvariants(f, input, o.output);
  return o;
}

} // namespace stability
