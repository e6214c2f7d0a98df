// HonourMarkers: the well markers of port 2 to the vertices pinned under them
// (docs/markers.md, "Honoured while shaping"; the rule is the core's
// geoshaping/metrics/marker_pins.h, the crossings are found by vtkMarkerCrossings).
#include "vtkChainMailDeformationFilterInternals.h"
#include "vtkMarkerCrossings.h"
#include "vtkPolyData.h"

#include "geoshaping/edit/marker_snap.h"

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
  // Every connection's markers: mapped for the misfit figures whenever connected (on one
  // process), pinned only with HonourMarkers.
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> sources;
  const bool honour = this->HonourMarkers;
  if (honour || !state.Processes)
    for (int i = 0; i < this->GetNumberOfInputConnections(2); ++i)
    {
      vtkDataObject* markers = this->GetInputDataObject(2, i);
      sources.emplace_back(markers, markers ? markers->GetMTime() : 0);
    }
  if (state.MarkersValid && sources == state.MarkerSources && honour == state.MarkersHonoured &&
      (!force || sources.empty()))
  {
    return false;
  }
  state.MarkerSources = sources;
  state.MarkersHonoured = honour;
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
  geoshaping::MarkerCrossingMap map;
  vtkMarkerCrossings crossings;
  const std::size_t count = xyz.size() / 3;
  const double size = input->GetLength();
  const vtkSmartPointer<vtkPointSet> shape =
    count > 0 ? CommittedShape(input, state.Deformer) : vtkSmartPointer<vtkPointSet>(input);
  if (count > 0 && input->GetNumberOfPoints() > 0 && crossings.SetSurface(shape, zRange))
  {
    // The map: each finite marker's crossed triangles, by the input's point ids (the
    // locator's one line query per marker, made here once).
    vtkNew<vtkIdList> cells, ids;
    Eigen::Vector3d corners[3];
    for (std::size_t i = 0; i < count; ++i)
    {
      const Eigen::Vector3d m(xyz.data() + 3 * i);
      if (!m.allFinite())
        continue;
      crossings.Crossed(m.x(), m.y(), cells);
      for (vtkIdType c = 0; c < cells->GetNumberOfIds(); ++c)
      {
        crossings.Corners(cells->GetId(c), ids, corners);
        for (int k = 0; k < 3; ++k)
          map.corners.push_back(geoshaping::index_t(crossings.SurfacePointId(ids->GetId(k))));
      }
      if (map.corners.size() > map.first.back())
      {
        map.xyz.insert(map.xyz.end(), m.data(), m.data() + 3);
        map.first.push_back(map.corners.size());
      }
    }
    const auto position = [&shape](geoshaping::index_t v)
    {
      Eigen::Vector3d x;
      shape->GetPoint(v, x.data());
      return x;
    };
    if (honour)
    {
      // The map's markers come in the order pin_markers asks for them (the finite ones);
      // the others have no crossing.
      std::size_t next = 0;
      pins = geoshaping::pin_markers(
        xyz.data(), count,
        [&](const Eigen::Vector3d& m, std::vector<geoshaping::index_t>& out)
        {
          if (next < map.size() && Eigen::Vector3d(map.xyz.data() + 3 * next) == m)
          {
            out.insert(out.end(), map.corners.begin() + std::ptrdiff_t(map.first[next]),
              map.corners.begin() + std::ptrdiff_t(map.first[next + 1]));
            ++next;
          }
        },
        position, 1e-6 * size);
    }
  }
  else if (honour)
  {
    // No surface to cross (no polygons): every finite marker is outside.
    for (std::size_t i = 0; i < count; ++i)
      ++(Eigen::Vector3d(xyz.data() + 3 * i).allFinite() ? pins.outside : pins.non_finite);
  }
  state.MarkerMap = std::move(map);
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

void vtkChainMailDeformationFilter::UpdateMarkerMisfit(vtkPointSet* output)
{
  const geoshaping::MarkerCrossingMap& map = this->Internals->MarkerMap;
  vtkPoints* points = output->GetPoints();
  if (map.size() == 0 || !points)
    return;
  const geoshaping::MisfitSummary summary = geoshaping::mapped_vertical_misfit(map,
    [points](geoshaping::index_t v)
    {
      Eigen::Vector3d x;
      points->GetPoint(v, x.data());
      return x;
    });
  this->Statistics.MarkerVerticalMisfitRMS = summary.rms;
  this->Statistics.MarkerVerticalMisfitMax = summary.max;
  this->Statistics.NumberOfMarkersInside = vtkIdType(summary.inside);
}

void vtkChainMailDeformationFilter::SnapToMarkers()
{
  vtkInternals& state = *this->Internals;
  this->LastSnappedMarkers = 0;
  this->LastSkippedMarkers = 0;
  if (state.Processes)
  {
    vtkErrorMacro("SnapToMarkers: not on data split across processes yet; nothing changed.");
    return;
  }
  if (!state.GeometryValid || state.Edits.pending())
  {
    vtkErrorMacro("SnapToMarkers: the filter is not up to date (update it first); nothing "
                  "changed.");
    return;
  }
  if (state.MarkerMap.size() == 0)
  {
    vtkErrorMacro("SnapToMarkers: no marker inside the surface's footprint (connect well "
                  "markers to the Markers input); nothing changed.");
    return;
  }
  // The user's pins are kept; the honoured markers' are not (their markers are the
  // targets): they are made again from the snapped shape at the next update.
  std::vector<std::uint8_t> pins;
  if (vtkDataArray* source = state.PinSource)
  {
    pins.resize(std::size_t(source->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < source->GetNumberOfTuples(); ++i)
      pins[std::size_t(i)] = source->GetComponent(i, 0) != 0.0;
  }
  // The frame shown until now is rewritten at the next update.
  const auto& shown = state.Deformer.moved();
  state.SnapStale.insert(state.SnapStale.end(), shown.begin(), shown.end());
  const geoshaping::MarkerSnap snap =
    geoshaping::snap_to_markers(state.Deformer, state.MarkerMap, pins);
  this->LastSnappedMarkers = vtkIdType(snap.snapped);
  this->LastSkippedMarkers = vtkIdType(snap.skipped);
  if (snap.skipped > 0)
  {
    vtkWarningMacro("SnapToMarkers: " << snap.skipped << " of " << state.MarkerMap.size()
                                      << " markers not snapped (their triangle's corners are "
                                         "pinned, or an obstacle stopped the pull).");
  }
  geoshaping::EditRecipe recipe = vtkChainMailDeformationFilterDetail::Recipe(this, -1);
  recipe.displacement.setZero(); // not a grasp's: the net result is the record
  if (snap.snapped == 0 || !state.Edits.commit(state.Deformer, recipe, snap.vertices,
                             snap.displacements, state.Placement()))
  {
    vtkErrorMacro("SnapToMarkers: no marker could be snapped; nothing changed.");
    return;
  }
  state.Invalidate(vtkInternals::Stale::Links);
  this->Statistics.LastGraspPointId = -1;
  this->Statistics.LastGraspMalleability = std::numeric_limits<double>::quiet_NaN();
  this->Modified();
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
