#include "vtkMarkerMisfitFilter.h"
#include "vtkMarkerCrossings.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "geoshaping/metrics/marker_misfit.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMarkerMisfitFilter);

namespace
{
// The first point of `points` with a non-finite coordinate, or -1.
vtkIdType FirstNonFinite(vtkPoints* points)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      return i;
  }
  return -1;
}

// `f` of the corners of triangle `cell` of the crossings' triangles.
template<typename F>
double Triangle(vtkMarkerCrossings& crossings, vtkIdType cell, vtkIdList* ids, F&& f)
{
  Eigen::Vector3d corner[3];
  crossings.Corners(cell, ids, corner);
  return f(corner[0], corner[1], corner[2]);
}

vtkNew<vtkDoubleArray> Scalar(const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  return a;
}

void AddSummary(vtkPolyData* output, const geoshaping::MisfitSummary& s)
{
  output->GetFieldData()->AddArray(Scalar("MisfitRMS", s.rms));
  output->GetFieldData()->AddArray(Scalar("MisfitMax", s.max));
  output->GetFieldData()->AddArray(Scalar("MarkersInside", double(s.inside)));
}
}

vtkMarkerMisfitFilter::vtkMarkerMisfitFilter()
{
  this->SetNumberOfInputPorts(2);
}

int vtkMarkerMisfitFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkMarkerMisfitFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* surface = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* markers = vtkPointSet::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();

  // Stage 1: the inputs, refused before anything is computed.
  if (!surface || !markers)
  {
    vtkErrorMacro("Marker Misfit needs a surface (input 0) and markers (input 1, Markers).");
    return 0;
  }
  const vtkIdType numMarkers = markers->GetNumberOfPoints();
  if (numMarkers == 0)
  {
    AddSummary(output, {});
    return 1;
  }
  const vtkIdType badMarker = FirstNonFinite(markers->GetPoints());
  if (badMarker >= 0)
  {
    vtkErrorMacro("Marker " << badMarker << " of " << numMarkers
                            << " has a non-finite coordinate (NaN or infinite): remove it "
                               "or give it a position; no misfit computed.");
    return 0;
  }
  const vtkIdType badPoint = FirstNonFinite(surface->GetPoints());
  if (badPoint >= 0)
  {
    vtkErrorMacro(
      "Surface point " << badPoint << " has a non-finite coordinate; no misfit computed.");
    return 0;
  }
  vtkMarkerCrossings crossed;
  double markerBounds[6];
  markers->GetBounds(markerBounds);
  if (!crossed.SetSurface(surface, markerBounds + 4))
  {
    vtkErrorMacro("The surface (input 0) has no polygons to measure the markers against.");
    return 0;
  }

  // Stage 2: per marker, the nearest surface point and the vertical line's crossings.
  vtkStaticCellLocator* locator = crossed.GetLocator();

  vtkNew<vtkDoubleArray> vertical, misfit;
  vertical->SetName("VerticalMisfit");
  misfit->SetName("Misfit");
  vtkNew<vtkUnsignedCharArray> inside;
  inside->SetName("Inside");
  vertical->SetNumberOfValues(numMarkers);
  misfit->SetNumberOfValues(numMarkers);
  inside->SetNumberOfValues(numMarkers);
  vtkNew<vtkIdList> hitCells, triangle;
  std::vector<double> crossings;
  std::vector<double> misfits(numMarkers);
  std::vector<unsigned char> isInside(numMarkers);
  vtkIdType outside = 0;
  for (vtkIdType i = 0; i < numMarkers; ++i)
  {
    double m[3], c[3], dist2 = 0.0;
    markers->GetPoint(i, m);
    vtkIdType cell = -1;
    int subId = 0;
    locator->FindClosestPoint(m, c, cell, subId, dist2);
    const Eigen::Vector3d marker(m[0], m[1], m[2]);
    misfits[i] = Triangle(crossed, cell, triangle,
      [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& d)
      { return geoshaping::normal_misfit(marker, a, b, d); });

    // The locator finds the triangles the line crosses; the core evaluates their
    // elevation at the marker exactly (VTK's own intersection loses ~1e-3 m at UTM sizes).
    crossed.Crossed(m[0], m[1], hitCells);
    crossings.clear();
    for (vtkIdType h = 0; h < hitCells->GetNumberOfIds(); ++h)
      Triangle(crossed, hitCells->GetId(h), triangle,
        [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& d)
        {
          double z = 0.0;
          if (geoshaping::plane_elevation(a, b, d, m[0], m[1], z))
            crossings.push_back(z);
          return 0.0;
        });
    bool in = false;
    vertical->SetValue(i, geoshaping::vertical_misfit(m[2], crossings, in));
    isInside[i] = in ? 1 : 0;
    outside += in ? 0 : 1;
    misfit->SetValue(i, misfits[i]);
    inside->SetValue(i, isInside[i]);
  }
  if (outside > 0)
  {
    vtkWarningMacro(<< outside << " of " << numMarkers
                    << " markers lie outside the surface's footprint (no surface above or "
                       "below them): Inside = 0, VerticalMisfit = 0, left out of MisfitRMS "
                       "and MisfitMax.");
  }

  // Stage 3: the markers with their misfit.
  output->SetPoints(markers->GetPoints());
  output->GetPointData()->PassData(markers->GetPointData());
  output->GetPointData()->AddArray(vertical);
  output->GetPointData()->AddArray(misfit);
  output->GetPointData()->AddArray(inside);
  output->GetPointData()->SetActiveScalars("Misfit");
  vtkNew<vtkCellArray> verts;
  verts->AllocateExact(numMarkers, numMarkers);
  for (vtkIdType i = 0; i < numMarkers; ++i)
    verts->InsertNextCell(1, &i);
  output->SetVerts(verts);
  AddSummary(output, geoshaping::summarize_misfit(misfits, isInside));
  return 1;
}

void vtkMarkerMisfitFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
