// ChainMail Deformation's HonourMarkers (docs/markers.md, "Honoured while shaping"): every
// inside marker keeps its vertical misfit, measured independently by Marker Misfit on the
// output, in every frame of a pull next to it and after a commit; bad markers are skipped
// with a warning; with HonourMarkers off the output is the one without markers, bit for bit.
#include "marker_samples.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkMarkerMisfitFilter.h"
#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using markers_testing::Points;
using markers_testing::Xyz;

// z = 0.1 x + 0.2 y + 5 over [0, 20]^2, 20 x 20 squares cut into triangles along the
// diagonal from (i, j) to (i + 1, j + 1).
double Plane(double x, double y)
{
  return 0.1 * x + 0.2 * y + 5.0;
}
constexpr int Side = 21;

vtkSmartPointer<vtkPolyData> TiltedPlane()
{
  auto plane =
    geoshaping::testing::TriangleGridPolyData(Side, Side, 1.0, nullptr, VTK_DOUBLE, 0.0, 0.0);
  for (vtkIdType v = 0; v < plane->GetNumberOfPoints(); ++v)
  {
    double x[3];
    plane->GetPoint(v, x);
    plane->GetPoints()->SetPoint(v, x[0], x[1], Plane(x[0], x[1]));
  }
  return plane;
}

// Markers on the plane, one of them a vertex's width from the pulled vertex (10, 10).
Xyz MarkersOnThePlane()
{
  Xyz xyz;
  for (const auto& p : std::vector<std::array<double, 2>>{
         { 9.3, 10.6 }, { 11.25, 10.7 }, { 10.5, 12.2 }, { 4.4, 15.1 }, { 12.7, 8.05 } })
    xyz.push_back({ p[0], p[1], Plane(p[0], p[1]) });
  return xyz;
}

vtkIdType Vertex(int i, int j)
{
  return j * Side + i;
}

struct Shaper
{
  vtkNew<vtkChainMailDeformationFilter> Filter;
  vtkNew<vtkTest::ErrorObserver> Observer;
  Shaper(vtkDataObject* surface, vtkDataObject* markers, bool honour)
  {
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Observer);
    this->Filter->SetInputData(surface);
    if (markers)
      this->Filter->SetMarkersData(markers);
    this->Filter->SetHonourMarkers(honour);
    this->Filter->SetDefaultMalleability(0.9);
    this->Filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
  }
  vtkPolyData* Pull(vtkIdType grasp, double dx, double dy, double dz)
  {
    this->Filter->SetGraspPointId(grasp);
    this->Filter->SetDisplacement(dx, dy, dz);
    this->Filter->Update();
    return vtkPolyData::SafeDownCast(this->Filter->GetOutput());
  }
  std::string Errors() const { return this->Observer->GetErrorMessage(); }
  std::string Warnings() const { return this->Observer->GetWarningMessage(); }
};

// Marker Misfit's output for `markers` against `surface`.
vtkSmartPointer<vtkPolyData> Measured(vtkDataObject* surface, vtkDataObject* markers)
{
  vtkNew<vtkMarkerMisfitFilter> misfit;
  misfit->SetInputData(0, surface);
  misfit->SetMarkersData(markers);
  misfit->Update();
  return misfit->GetOutput();
}

// Marker Misfit's VerticalMisfit and Inside of `markers` against `surface`.
std::vector<double> VerticalMisfit(vtkDataObject* surface, vtkDataObject* markers)
{
  const auto measured = Measured(surface, markers);
  vtkDataArray* vertical = measured->GetPointData()->GetArray("VerticalMisfit");
  vtkDataArray* inside = measured->GetPointData()->GetArray("Inside");
  std::vector<double> v;
  for (vtkIdType i = 0; vertical && i < vertical->GetNumberOfTuples(); ++i)
    v.push_back(
      inside->GetTuple1(i) ? vertical->GetTuple1(i) : std::numeric_limits<double>::quiet_NaN());
  return v;
}

std::vector<double> Coordinates(vtkPointSet* data)
{
  std::vector<double> xyz(std::size_t(3 * data->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    data->GetPoint(i, xyz.data() + 3 * i);
  return xyz;
}

bool AllFinite(vtkPointSet* data)
{
  for (const double x : Coordinates(data))
    if (!std::isfinite(x))
      return false;
  return true;
}
} // namespace

// A pull next to a marker on a plane: with HonourMarkers every marker stays on the plane
// (|VerticalMisfit| <= 1e-6 of the size) in every frame and after the commit, while the
// pulled vertex goes where it is told; without, the marker next to the pull leaves it.
TEST(HonourMarkers, PullNextToAMarkerBendsAroundIt)
{
  const auto plane = TiltedPlane();
  const auto markers = Points(MarkersOnThePlane());
  const double size = plane->GetLength();
  const vtkIdType grasp = Vertex(10, 10);

  Shaper free(plane, markers, false);
  Shaper honour(plane, markers, true);
  bool moved = false;
  for (const double dz : { 0.5, 1.0, 2.0, 3.0 })
  {
    vtkPolyData* out = honour.Pull(grasp, 0.3, -0.2, dz);
    ASSERT_EQ(honour.Errors(), "");
    double x[3];
    out->GetPoint(grasp, x);
    EXPECT_EQ(x[2], Plane(10, 10) + dz) << "the grasp goes where it is told";
    for (const double v : VerticalMisfit(out, markers))
      EXPECT_LE(std::abs(v), 1e-6 * size) << "dz " << dz;
    const auto without = VerticalMisfit(free.Pull(grasp, 0.3, -0.2, dz), markers);
    moved = moved || std::abs(without[0]) > 0.1;
  }
  EXPECT_TRUE(moved) << "without HonourMarkers the pull moves the surface off the marker";
  EXPECT_EQ(honour.Filter->GetNumberOfHonouredMarkers(), 5);
  EXPECT_EQ(honour.Filter->GetNumberOfMarkersOutside(), 0);
  EXPECT_EQ(honour.Filter->GetNumberOfMarkersOffSurface(), 0);
  EXPECT_EQ(honour.Filter->GetNumberOfMarkerPinnedPoints(), 15); // five separate triangles
  EXPECT_EQ(honour.Warnings(), "");

  // After the commit the committed shape keeps them, and so does the next pull.
  honour.Filter->CommitEdit();
  vtkPolyData* committed = honour.Pull(-1, 0, 0, 0);
  for (const double v : VerticalMisfit(committed, markers))
    EXPECT_LE(std::abs(v), 1e-6 * size) << "committed";
  double x[3];
  committed->GetPoint(grasp, x);
  EXPECT_EQ(x[2], Plane(10, 10) + 3.0) << "the commit kept the pull";
  vtkPolyData* again = honour.Pull(Vertex(12, 12), 0.0, 0.0, -2.5);
  ASSERT_EQ(honour.Errors(), "");
  for (const double v : VerticalMisfit(again, markers))
    EXPECT_LE(std::abs(v), 1e-6 * size) << "after the commit";
}

// HonourMarkers off, or no markers, or an empty marker set: the output is the one of a
// filter without the Markers input, bit for bit, frame after frame.
TEST(HonourMarkers, OffOrEmptyIsBitForBitTheFilterWithoutMarkers)
{
  const auto plane = TiltedPlane();
  const auto markers = Points(MarkersOnThePlane());
  const auto none = Points({});
  Shaper reference(plane, nullptr, false);
  Shaper off(plane, markers, false);
  Shaper empty(plane, none, true);
  Shaper unconnected(plane, nullptr, true);
  for (const double dz : { 1.0, -2.0, 3.5 })
  {
    const auto expected = Coordinates(reference.Pull(Vertex(10, 10), 0.1, 0.2, dz));
    EXPECT_EQ(Coordinates(off.Pull(Vertex(10, 10), 0.1, 0.2, dz)), expected);
    EXPECT_EQ(Coordinates(empty.Pull(Vertex(10, 10), 0.1, 0.2, dz)), expected);
    EXPECT_EQ(Coordinates(unconnected.Pull(Vertex(10, 10), 0.1, 0.2, dz)), expected);
  }
  for (Shaper* s : { &off, &empty, &unconnected })
  {
    EXPECT_EQ(s->Errors(), "");
    EXPECT_EQ(s->Warnings(), "");
    EXPECT_EQ(s->Filter->GetNumberOfMarkerPinnedPoints(), 0);
  }
  // Turned on and off again: back to the reference.
  off.Filter->HonourMarkersOn();
  const auto on = Coordinates(off.Pull(Vertex(10, 10), 0.1, 0.2, 3.0));
  EXPECT_NE(on, Coordinates(reference.Pull(Vertex(10, 10), 0.1, 0.2, 3.0)));
  off.Filter->HonourMarkersOff();
  EXPECT_EQ(Coordinates(off.Pull(Vertex(10, 10), 0.1, 0.2, 3.0)),
    Coordinates(reference.Pull(Vertex(10, 10), 0.1, 0.2, 3.0)));
}

// The markers' pins join the PinnedArray's; grasping a vertex under a marker is refused
// as grasping a pinned vertex is, the output the input.
TEST(HonourMarkers, MarkersJoinThePinsAndTheirVerticesCannotBeGrasped)
{
  const auto plane = TiltedPlane();
  vtkNew<vtkIntArray> pinned;
  pinned->SetName("Pinned");
  pinned->SetNumberOfTuples(plane->GetNumberOfPoints());
  pinned->Fill(0);
  pinned->SetValue(Vertex(8, 9), 1);
  plane->GetPointData()->AddArray(pinned);
  const auto markers = Points(MarkersOnThePlane());
  Shaper honour(plane, markers, true);
  honour.Filter->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Pinned");
  vtkPolyData* out = honour.Pull(Vertex(10, 10), 0.0, 0.0, 3.0);
  ASSERT_EQ(honour.Errors(), "");
  double x[3], rest[3];
  out->GetPoint(Vertex(8, 9), x);
  plane->GetPoint(Vertex(8, 9), rest);
  EXPECT_EQ(x[2], rest[2]) << "the user's pin holds";
  for (const double v : VerticalMisfit(out, markers))
    EXPECT_LE(std::abs(v), 1e-6 * plane->GetLength());

  // (9, 10) is a corner of the triangle under the marker at (9.3, 10.6).
  out = honour.Pull(Vertex(9, 10), 0.0, 0.0, 3.0);
  EXPECT_NE(honour.Errors().find("is pinned under an honoured marker"), std::string::npos)
    << honour.Errors();
  EXPECT_EQ(Coordinates(out), Coordinates(plane)) << "refused: the output is the input";
}

// Bad markers: a NaN one is skipped, one outside the footprint is not honoured, one off
// the surface keeps its misfit; each with one warning giving the count; no NaN out. An
// empty marker set pins nothing and says nothing.
TEST(HonourMarkers, BadMarkersAreSkippedWithAWarningAndNoNaNComesOut)
{
  const auto plane = TiltedPlane();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Xyz xyz = { { 9.3, 10.6, Plane(9.3, 10.6) }, { nan, 4.0, 5.0 }, { 40.0, 5.0, 1.0 },
    { 11.25, 10.7, Plane(11.25, 10.7) + 0.75 } };
  const auto markers = Points(xyz);
  Shaper honour(plane, markers, true);
  vtkPolyData* out = honour.Pull(Vertex(10, 10), 0.0, 0.0, 3.0);
  EXPECT_EQ(honour.Errors(), "");
  const std::string warnings = honour.Warnings();
  EXPECT_NE(warnings.find("1 of 4 markers have a NaN or infinite coordinate"), std::string::npos)
    << warnings;
  EXPECT_NE(warnings.find("1 of 4 markers lie outside the surface's footprint"), std::string::npos)
    << warnings;
  EXPECT_NE(warnings.find("1 of 2 honoured markers are off the surface"), std::string::npos)
    << warnings;
  EXPECT_EQ(honour.Filter->GetNumberOfHonouredMarkers(), 2);
  EXPECT_EQ(honour.Filter->GetNumberOfNonFiniteMarkers(), 1);
  EXPECT_EQ(honour.Filter->GetNumberOfMarkersOutside(), 1);
  EXPECT_EQ(honour.Filter->GetNumberOfMarkersOffSurface(), 1);
  EXPECT_TRUE(AllFinite(out));
  // The good ones, measured alone: on the surface, and 0.75 below it as at rest.
  const auto good = Points({ xyz[0], xyz[3] });
  const auto v = VerticalMisfit(out, good);
  EXPECT_LE(std::abs(v[0]), 1e-6 * plane->GetLength());
  EXPECT_NEAR(v[1], -0.75, 1e-6 * plane->GetLength());
  // Warned once, when the markers are mapped, not on every frame.
  honour.Observer->Clear();
  honour.Pull(Vertex(10, 10), 0.0, 0.0, 2.0);
  EXPECT_EQ(honour.Warnings(), "");
}

// A real horizon-like surface (the Cascadia subduction interface, CRESCENT, CC BY 4.0,
// read in place): 200 markers at random points of random triangles, 150 moved off it by
// dz up to 0.1 edge. Pulls next to markers keep every marker's VerticalMisfit at its rest
// value (0 or -dz) within 1e-6 of the size in every frame and after a commit; without
// HonourMarkers the markers next to the pull move.
TEST(HonourMarkers, RealHorizonKeepsItsSampledMarkers)
{
  // Inside their triangles (shrunk to 0.9 about the centroid), so each has one crossing.
  std::string path;
  const auto samples = markers_testing::SampleCascadia(11, 200, 50, 0.9, path);
  if (!samples.surface)
    GTEST_SKIP() << "CRESCENT data absent: " << path;
  vtkPolyData* surface = samples.surface;
  ASSERT_GT(surface->GetNumberOfPolys(), 1000);
  const double size = samples.size;
  const Xyz& xyz = samples.xyz;
  const auto& dz = samples.dz;
  const double edge = samples.edge;
  const auto markers = Points(xyz);
  const auto rest = VerticalMisfit(surface, markers);
  const double spacing = size / std::sqrt(double(surface->GetNumberOfPoints()));
  std::size_t offSurface = 0;
  for (std::size_t k = 0; k < xyz.size(); ++k)
  {
    ASSERT_TRUE(std::isfinite(rest[k])) << k << " is inside";
    ASSERT_NEAR(rest[k], -dz[k], 1e-9 * size) << k;
    offSurface += std::abs(rest[k]) > 1e-6 * size ? 1 : 0;
  }

  Shaper honour(surface, markers, true);
  Shaper free(surface, markers, false);
  honour.Filter->SetDefaultMalleability(0.7);
  free.Filter->SetDefaultMalleability(0.7);
  // Grasp a neighbour of marker 0's triangle that is not under any marker: the vertex
  // nearest to marker 0 among the unpinned ones, pulled up by up to 5 mean spacings.
  honour.Pull(-1, 0, 0, 0);
  ASSERT_EQ(honour.Errors(), "");
  EXPECT_EQ(honour.Filter->GetNumberOfHonouredMarkers(), 200);
  EXPECT_EQ(std::size_t(honour.Filter->GetNumberOfMarkersOffSurface()), offSurface);
  vtkIdType grasp = -1;
  double best = std::numeric_limits<double>::infinity();
  {
    // Unpinned: a vertex whose pull succeeds (a pinned one is refused).
    std::vector<std::pair<double, vtkIdType>> byDistance;
    for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
    {
      double x[3];
      surface->GetPoint(p, x);
      byDistance.emplace_back(vtkMath::Distance2BetweenPoints(x, xyz[0].data()), p);
    }
    std::sort(byDistance.begin(), byDistance.end());
    for (const auto& [d2, p] : byDistance)
    {
      honour.Observer->Clear();
      honour.Pull(p, 0, 0, spacing);
      if (honour.Errors().empty())
      {
        grasp = p, best = d2;
        break;
      }
    }
  }
  ASSERT_GE(grasp, 0);
  EXPECT_LT(std::sqrt(best), 3 * spacing) << "a vertex next to marker 0";
  double largest = 0.0;
  for (const double up : { 1.0, 3.0, 5.0 })
  {
    vtkPolyData* out = honour.Pull(grasp, 0.0, 0.0, up * spacing);
    ASSERT_EQ(honour.Errors(), "");
    EXPECT_GT(honour.Filter->GetNumberOfDisplacedPoints(), 10);
    const auto now = VerticalMisfit(out, markers);
    for (std::size_t k = 0; k < xyz.size(); ++k)
      EXPECT_NEAR(now[k], rest[k], 1e-6 * size) << k << " at " << up << " edges";
    const auto without = VerticalMisfit(free.Pull(grasp, 0.0, 0.0, up * spacing), markers);
    for (std::size_t k = 0; k < xyz.size(); ++k)
      largest = std::max(largest, std::abs(without[k] - rest[k]));
  }
  EXPECT_GT(largest, 0.5 * edge) << "without HonourMarkers a marker next to the pull moves";
  honour.Filter->CommitEdit();
  vtkPolyData* committed = honour.Pull(-1, 0, 0, 0);
  const auto after = VerticalMisfit(committed, markers);
  for (std::size_t k = 0; k < xyz.size(); ++k)
    EXPECT_NEAR(after[k], rest[k], 1e-6 * size) << k << " after the commit";
  EXPECT_TRUE(AllFinite(committed));
}

// Edits committed before the markers were honoured moved the surface under one (sideways
// too): the markers are read against the committed shape, so the marker keeps the misfit
// it has there; after undoing the edit they are read against the rest shape again.
TEST(HonourMarkers, MarkersAreReadAgainstTheCommittedShape)
{
  const auto plane = TiltedPlane();
  const auto markers = Points(MarkersOnThePlane());
  const double size = plane->GetLength();
  Shaper shaper(plane, markers, false);
  shaper.Pull(Vertex(10, 10), 0.45, 0.35, 2.0);
  shaper.Filter->CommitEdit();
  vtkPolyData* committed = shaper.Pull(-1, 0, 0, 0);
  const auto before = VerticalMisfit(committed, markers);
  ASSERT_GT(std::abs(before[0]), 0.1) << "the edit moved the surface under marker 0";

  shaper.Filter->HonourMarkersOn();
  for (const double dz : { -1.0, -2.0, 1.5 })
  {
    vtkPolyData* out = shaper.Pull(Vertex(8, 11), 0.2, 0.0, dz);
    ASSERT_EQ(shaper.Errors(), "");
    const auto now = VerticalMisfit(out, markers);
    for (std::size_t k = 0; k < now.size(); ++k)
      EXPECT_NEAR(now[k], before[k], 1e-6 * size) << k << " at " << dz;
  }
  vtkIdType off = 0;
  for (const double v : before)
    off += std::abs(v) > 1e-6 * size ? 1 : 0;
  EXPECT_GE(off, 1);
  EXPECT_EQ(shaper.Filter->GetNumberOfMarkersOffSurface(), off) << "those the edit moved";

  shaper.Filter->UndoEdit();
  shaper.Pull(-1, 0, 0, 0);
  vtkPolyData* out = shaper.Pull(Vertex(8, 11), 0.2, 0.0, -2.0);
  ASSERT_EQ(shaper.Errors(), "");
  for (const double v : VerticalMisfit(out, markers))
    EXPECT_LE(std::abs(v), 1e-6 * size) << "after the undo: the rest shape's markers";
  EXPECT_EQ(shaper.Filter->GetNumberOfMarkersOffSurface(), 0);
}

// A volume mesh is honoured on its boundary: markers on the top face of a tetrahedral
// slab stay on it while a top vertex between them is pulled up (the boundary's triangles
// name the slab's own points).
TEST(HonourMarkers, VolumeMeshIsHonouredOnItsBoundary)
{
  const int n = 11, layers = 3;
  const auto slab = geoshaping::testing::TetSlabUnstructuredGrid(n, n, layers, 1.0, nullptr);
  const double top = layers - 1;
  const auto markers = Points({ { 3.3, 5.6, top }, { 7.6, 4.3, top }, { 5.4, 7.7, top } });
  const vtkIdType grasp = vtkIdType(((layers - 1) * n + 5) * n + 5);
  vtkNew<vtkChainMailDeformationFilter> free, honour;
  for (vtkChainMailDeformationFilter* f : { free.Get(), honour.Get() })
  {
    f->SetInputData(slab);
    f->SetMarkersData(markers);
    f->SetDefaultMalleability(0.9);
    f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
    f->SetGraspPointId(grasp);
    f->SetDisplacement(0.0, 0.0, 2.0);
  }
  honour->HonourMarkersOn();
  honour->Update();
  free->Update();
  EXPECT_EQ(honour->GetNumberOfHonouredMarkers(), 3);
  EXPECT_EQ(honour->GetNumberOfMarkerPinnedPoints(), 9);
  double x[3];
  honour->GetOutput()->GetPoint(grasp, x);
  EXPECT_EQ(x[2], top + 2.0) << "the grasp goes where it is told";
  for (const double v : VerticalMisfit(honour->GetOutput(), markers))
    EXPECT_LE(std::abs(v), 1e-6 * slab->GetLength());
  double largest = 0.0;
  for (const double v : VerticalMisfit(free->GetOutput(), markers))
    largest = std::max(largest, std::abs(v));
  EXPECT_GT(largest, 0.1) << "without HonourMarkers the top face leaves them";
}

namespace
{
// Marker Misfit's MisfitRMS / MisfitMax, but of VerticalMisfit: an independent sum over
// the inside markers of the filter measured on `surface`.
std::array<double, 3> VerticalFigures(vtkDataObject* surface, vtkDataObject* markers)
{
  double sum = 0.0, max = 0.0, inside = 0.0;
  for (const double v : VerticalMisfit(surface, markers))
    if (!std::isnan(v))
    {
      sum += v * v;
      max = std::max(max, std::abs(v));
      inside += 1.0;
    }
  return { inside > 0 ? std::sqrt(sum / inside) : 0.0, max, inside };
}

double FieldValue(vtkDataObject* out, const char* name)
{
  vtkDataArray* a = vtkDataArray::SafeDownCast(out->GetFieldData()->GetAbstractArray(name));
  return a ? a->GetTuple1(0) : std::numeric_limits<double>::quiet_NaN();
}
} // namespace

// The misfit figures of every frame (issue 38 item 3, the dock's "markers: RMS ..."):
// markers above and below a tilted plane by known amounts, one outside. At rest the RMS and
// the max are those amounts' exactly; in the frames of a vertical pull among them and
// after a commit, they equal Marker Misfit's VerticalMisfit on the output, summed
// independently; the same in the output's field data; with HonourMarkers on or off.
TEST(HonourMarkers, FramesReportTheMarkersVerticalMisfit)
{
  const auto plane = TiltedPlane();
  const double size = plane->GetLength();
  const std::vector<std::array<double, 3>> offsets = { { 9.3, 10.6, 0.5 }, { 11.25, 10.7, -1.25 },
    { 10.5, 12.2, 2.0 }, { 4.4, 15.1, 0.0 }, { 12.7, 8.05, -0.75 } };
  Xyz xyz;
  double sum = 0.0, max = 0.0;
  for (const auto& o : offsets)
  {
    xyz.push_back({ o[0], o[1], Plane(o[0], o[1]) + o[2] });
    sum += o[2] * o[2];
    max = std::max(max, std::abs(o[2]));
  }
  xyz.push_back({ 40.0, 5.0, 1.0 }); // outside the footprint
  const auto markers = Points(xyz);
  for (const bool honour : { false, true })
  {
    Shaper shaper(plane, markers, honour);
    vtkPolyData* out = shaper.Pull(-1, 0, 0, 0);
    // Surface minus marker: -offset.
    EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitRMS(), std::sqrt(sum / 5.0), 1e-12 * size);
    EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitMax(), max, 1e-12 * size);
    EXPECT_EQ(shaper.Filter->GetNumberOfMarkersInside(), 5);
    EXPECT_EQ(FieldValue(out, "MarkersInside"), 5.0);
    for (const double dz : { 1.0, 2.5, -3.0 })
    {
      out = shaper.Pull(Vertex(12, 12), 0.0, 0.0, dz);
      ASSERT_EQ(shaper.Errors(), "");
      const auto expected = VerticalFigures(out, markers);
      EXPECT_GT(std::abs(expected[0] - std::sqrt(sum / 5.0)), honour ? -1.0 : 1e-3)
        << "the pull moved the surface under a marker";
      EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitRMS(), expected[0], 1e-9 * size) << dz;
      EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitMax(), expected[1], 1e-9 * size) << dz;
      EXPECT_EQ(double(shaper.Filter->GetNumberOfMarkersInside()), expected[2]);
      EXPECT_EQ(
        FieldValue(out, "MarkerVerticalMisfitRMS"), shaper.Filter->GetMarkerVerticalMisfitRMS());
      EXPECT_EQ(
        FieldValue(out, "MarkerVerticalMisfitMax"), shaper.Filter->GetMarkerVerticalMisfitMax());
    }
    shaper.Filter->CommitEdit();
    out = shaper.Pull(Vertex(8, 12), 0.0, 0.0, 1.5);
    const auto expected = VerticalFigures(out, markers);
    EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitRMS(), expected[0], 1e-9 * size);
    EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitMax(), expected[1], 1e-9 * size);
  }
  // No markers: no figures, no field data.
  Shaper none(plane, nullptr, false);
  vtkPolyData* out = none.Pull(Vertex(10, 11), 0.0, 0.0, 1.0);
  EXPECT_EQ(none.Filter->GetNumberOfMarkersInside(), 0);
  EXPECT_EQ(none.Filter->GetMarkerVerticalMisfitRMS(), 0.0);
  EXPECT_EQ(out->GetFieldData()->GetAbstractArray("MarkersInside"), nullptr);
}

// Snap to markers (issue 38 item 3): markers above and below a tilted plane by up to 2;
// one SnapToMarkers is one edit after which each marker is within 1e-6 of the size of
// the surface (Marker Misfit's VerticalMisfit and Misfit on the output); UndoEdit gives the
// shape before it bit for bit, RedoEdit the snapped one again. Refused without markers.
TEST(HonourMarkers, SnapToMarkersIsOneEditThatUndoesBitForBit)
{
  const auto plane = TiltedPlane();
  const double size = plane->GetLength();
  const Xyz xyz = { { 9.3, 10.6, Plane(9.3, 10.6) + 0.5 },
    { 11.25, 10.7, Plane(11.25, 10.7) - 1.25 }, { 10.5, 12.2, Plane(10.5, 12.2) + 2.0 },
    { 4.4, 15.1, Plane(4.4, 15.1) + 0.25 }, { 12.7, 8.05, Plane(12.7, 8.05) - 0.75 },
    { 40.0, 5.0, 1.0 } }; // the last outside
  const auto markers = Points(xyz);
  for (const bool honour : { false, true })
  {
    Shaper shaper(plane, markers, honour);
    shaper.Observer->Clear();
    shaper.Pull(Vertex(3, 3), 0.0, 0.0, 1.0); // an edit before the snap
    shaper.Filter->CommitEdit();
    const auto committed = Coordinates(shaper.Pull(-1, 0, 0, 0));
    shaper.Filter->SnapToMarkers();
    EXPECT_EQ(shaper.Errors(), "");
    EXPECT_EQ(shaper.Filter->GetLastSnappedMarkers(), 5);
    EXPECT_EQ(shaper.Filter->GetLastSkippedMarkers(), 0);
    EXPECT_EQ(shaper.Filter->GetNumberOfEdits(), 2) << "one edit for the snap";
    vtkPolyData* out = shaper.Pull(-1, 0, 0, 0);
    ASSERT_TRUE(AllFinite(out));
    const auto snapped = Coordinates(out);
    const auto vertical = VerticalMisfit(out, markers);
    for (std::size_t k = 0; k < 5; ++k)
      EXPECT_LE(std::abs(vertical[k]), 1e-6 * size) << "marker " << k << " honour " << honour;
    EXPECT_TRUE(std::isnan(vertical[5])) << "the marker outside stays outside";
    EXPECT_LE(FieldValue(Measured(out, markers), "MisfitMax"), 1e-6 * size);
    EXPECT_LE(shaper.Filter->GetMarkerVerticalMisfitMax(), 1e-6 * size) << "the dock's figure";
    EXPECT_NE(snapped, committed);

    shaper.Filter->UndoEdit();
    EXPECT_EQ(Coordinates(shaper.Pull(-1, 0, 0, 0)), committed) << "undo: bit for bit";
    EXPECT_NEAR(shaper.Filter->GetMarkerVerticalMisfitMax(), 2.0, 1e-9 * size);
    shaper.Filter->RedoEdit();
    EXPECT_EQ(Coordinates(shaper.Pull(-1, 0, 0, 0)), snapped) << "redo: the snap again";
    shaper.Filter->UndoEdit();
    shaper.Filter->UndoEdit();
    EXPECT_EQ(Coordinates(shaper.Pull(-1, 0, 0, 0)), Coordinates(plane));
  }
  // No markers: refused, nothing changed.
  Shaper none(plane, nullptr, false);
  none.Pull(-1, 0, 0, 0);
  none.Filter->SnapToMarkers();
  EXPECT_NE(none.Errors().find("SnapToMarkers: no marker inside"), std::string::npos)
    << none.Errors();
  EXPECT_EQ(none.Filter->GetNumberOfEdits(), 0);
  EXPECT_EQ(Coordinates(none.Pull(-1, 0, 0, 0)), Coordinates(plane));
  // Before any update: refused.
  Shaper early(plane, markers, false);
  early.Filter->SnapToMarkers();
  EXPECT_NE(early.Errors().find("not up to date"), std::string::npos) << early.Errors();
}

// Snap to markers on a real horizon (the Cascadia interface, CRESCENT, CC BY 4.0, read in
// place): 200 markers sampled on random triangles, 150 moved off by up to 0.1 edge. Every
// marker the snap reports as snapped is then on the surface (|VerticalMisfit| and Misfit
// within 1e-6 of the size); those it skipped (their triangle's corners all snapped
// already) are counted in its warning; UndoEdit is bit for bit.
TEST(HonourMarkers, SnapToMarkersOnARealHorizon)
{
  std::string path;
  const auto samples = markers_testing::SampleCascadia(13, 200, 50, 0.9, path);
  if (!samples.surface)
    GTEST_SKIP() << "CRESCENT data absent: " << path;
  const auto markers = Points(samples.xyz);
  const double size = samples.size;
  Shaper shaper(samples.surface, markers, false);
  shaper.Filter->SetDefaultMalleability(0.7);
  const auto before = Coordinates(shaper.Pull(-1, 0, 0, 0));
  shaper.Filter->SnapToMarkers();
  ASSERT_EQ(shaper.Errors(), "");
  const vtkIdType snapped = shaper.Filter->GetLastSnappedMarkers();
  const vtkIdType skipped = shaper.Filter->GetLastSkippedMarkers();
  EXPECT_EQ(snapped + skipped, 200);
  EXPECT_GE(snapped, 190);
  if (skipped > 0)
    EXPECT_NE(shaper.Warnings().find(std::to_string(skipped) + " of 200 markers not snapped"),
      std::string::npos)
      << shaper.Warnings();
  vtkPolyData* out = shaper.Pull(-1, 0, 0, 0);
  ASSERT_TRUE(AllFinite(out));
  const auto measured = Measured(out, markers);
  vtkDataArray* vertical = measured->GetPointData()->GetArray("VerticalMisfit");
  vtkDataArray* normal = measured->GetPointData()->GetArray("Misfit");
  vtkIdType on = 0;
  double worst = 0.0;
  for (vtkIdType k = 0; k < 200; ++k)
  {
    const double v = std::max(std::abs(vertical->GetTuple1(k)), std::abs(normal->GetTuple1(k)));
    if (v <= 1e-6 * size)
    {
      ++on;
      worst = std::max(worst, v);
    }
  }
  EXPECT_GE(on, snapped) << "every snapped marker is on the surface";
  std::cout << snapped << " snapped, " << skipped << " skipped, " << on
            << " on the surface, the farthest of those " << worst << " (size " << size << ")\n";
  shaper.Filter->UndoEdit();
  EXPECT_EQ(Coordinates(shaper.Pull(-1, 0, 0, 0)), before) << "undo: bit for bit";
}
