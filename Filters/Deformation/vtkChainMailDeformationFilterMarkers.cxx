// HonourMarkers: the well markers of port 2 to the vertices pinned under them
// (docs/markers.md, "Honoured while shaping"; the rule is the core's
// geoshaping/metrics/marker_pins.h, the crossings are found by vtkMarkerCrossings).
#include "vtkChainMailDeformationFilterInternals.h"
#include "vtkMarkerCrossings.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// The input, or a copy of it with the committed edits' points (input + committed offset).
vtkSmartPointer<vtkPointSet> CommittedShape(
  vtkPointSet* input, const geoshaping::ChainMailDeformer& deformer)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkIdType first = 0;
  while (first < n && deformer.committed_offset(geoshaping::index_t(first)).isZero(0.0))
    ++first;
  if (first == n)
  {
    return input;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    Eigen::Vector3d x;
    input->GetPoint(v, x.data());
    x += deformer.committed_offset(geoshaping::index_t(v));
    points->SetPoint(v, x.data());
  }
  auto shape = vtk::TakeSmartPointer(input->NewInstance());
  shape->ShallowCopy(input);
  shape->SetPoints(points);
  return shape;
}
}

bool vtkChainMailDeformationFilter::UpdateMarkers(vtkPointSet* input, bool force)
{
  vtkInternals& state = *this->Internals;
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> sources;
  if (this->HonourMarkers)
    for (int i = 0; i < this->GetNumberOfInputConnections(2); ++i)
    {
      vtkDataObject* markers = this->GetInputDataObject(2, i);
      sources.emplace_back(markers, markers ? markers->GetMTime() : 0);
    }
  if (state.MarkersValid && sources == state.MarkerSources && (!force || sources.empty()))
  {
    return false;
  }
  state.MarkerSources = sources;
  state.MarkersValid = true;

  // Every connection's finite and non-finite markers, in order; the z range of the finite.
  std::vector<double> xyz;
  double zRange[2] = { std::numeric_limits<double>::infinity(),
    -std::numeric_limits<double>::infinity() };
  for (const auto& source : sources)
  {
    vtkDataSet* markers = vtkDataSet::SafeDownCast(source.first);
    for (vtkIdType i = 0; markers && i < markers->GetNumberOfPoints(); ++i)
    {
      double m[3];
      markers->GetPoint(i, m);
      xyz.insert(xyz.end(), m, m + 3);
      if (std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]))
      {
        zRange[0] = std::min(zRange[0], m[2]);
        zRange[1] = std::max(zRange[1], m[2]);
      }
    }
  }
  geoshaping::MarkerPins pins;
  vtkMarkerCrossings crossings;
  const std::size_t count = xyz.size() / 3;
  const double size = input->GetLength();
  if (count > 0 && input->GetNumberOfPoints() > 0 &&
      crossings.SetSurface(CommittedShape(input, state.Deformer), zRange))
  {
    vtkPolyData* triangles = crossings.GetTriangles();
    vtkNew<vtkIdList> cells, ids;
    Eigen::Vector3d corners[3];
    pins = geoshaping::pin_markers(
      xyz.data(), count,
      [&](const Eigen::Vector3d& m, std::vector<geoshaping::index_t>& out)
      {
        crossings.Crossed(m.x(), m.y(), cells);
        for (vtkIdType c = 0; c < cells->GetNumberOfIds(); ++c)
        {
          crossings.Corners(cells->GetId(c), ids, corners);
          for (int k = 0; k < 3; ++k)
            out.push_back(geoshaping::index_t(ids->GetId(k)));
        }
      },
      [triangles](geoshaping::index_t v)
      {
        Eigen::Vector3d x;
        triangles->GetPoint(v, x.data());
        return x;
      },
      1e-6 * size);
    // The triangles' points to the input's.
    for (geoshaping::index_t& v : pins.vertices)
      v = geoshaping::index_t(crossings.SurfacePointId(v));
    std::sort(pins.vertices.begin(), pins.vertices.end());
  }
  else
  {
    // No surface to cross (no polygons): every finite marker is outside.
    for (std::size_t i = 0; i < count; ++i)
      ++(Eigen::Vector3d(xyz.data() + 3 * i).allFinite() ? pins.outside : pins.non_finite);
  }
  if (pins.non_finite > 0)
  {
    vtkWarningMacro(<< pins.non_finite << " of " << count
                    << " markers have a NaN or infinite coordinate: skipped, not honoured.");
  }
  if (pins.outside > 0)
  {
    vtkWarningMacro(<< pins.outside << " of " << count
                    << " markers lie outside the surface's footprint (no surface above or "
                       "below them): not honoured.");
  }
  if (pins.off_surface > 0)
  {
    vtkWarningMacro(<< pins.off_surface << " of " << pins.honoured
                    << " honoured markers are off the surface by more than 1e-6 of its size: "
                       "their vertical misfit is kept as it is, not brought to 0.");
  }
  const bool changed = pins.vertices != state.Markers.vertices;
  state.MarkersChanged = state.MarkersChanged || changed;
  state.Markers = std::move(pins);
  return changed;
}

vtkIdType vtkChainMailDeformationFilter::GetNumberOfHonouredMarkers()
{
  return vtkIdType(this->Internals->Markers.honoured);
}

vtkIdType vtkChainMailDeformationFilter::GetNumberOfMarkersOutside()
{
  return vtkIdType(this->Internals->Markers.outside);
}

vtkIdType vtkChainMailDeformationFilter::GetNumberOfNonFiniteMarkers()
{
  return vtkIdType(this->Internals->Markers.non_finite);
}

vtkIdType vtkChainMailDeformationFilter::GetNumberOfMarkersOffSurface()
{
  return vtkIdType(this->Internals->Markers.off_surface);
}

vtkIdType vtkChainMailDeformationFilter::GetNumberOfMarkerPinnedPoints()
{
  return vtkIdType(this->Internals->Markers.vertices.size());
}
