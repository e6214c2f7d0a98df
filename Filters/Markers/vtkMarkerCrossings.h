/**
 * @class   vtkMarkerCrossings
 * @brief   Finds, for well markers, the surface triangles their vertical lines cross.
 *
 * The VTK half of the markers' crossing rule (the core's
 * geoshaping/metrics/marker_misfit.h evaluates what is found): the surface's polygons as
 * triangles (a volume mesh's boundary first; vertices and lines ignored), VTK's
 * vtkStaticCellLocator over them, and per marker the triangles the vertical line through
 * it crosses, within 1e-9 of the surface's size. Shared by vtkMarkerMisfitFilter and
 * vtkChainMailDeformationFilter's HonourMarkers (docs/markers.md). Not wrapped.
 */
#ifndef vtkMarkerCrossings_h
#define vtkMarkerCrossings_h

#include "GeoShapingFiltersMarkersModule.h" // For export macro
#include "vtkNew.h"                         // For vtkNew
#include "vtkSmartPointer.h"                // For vtkSmartPointer

#include <Eigen/Core> // For Eigen::Vector3d

class vtkDataArray;
class vtkDataSet;
class vtkIdList;
class vtkPoints;
class vtkPolyData;
class vtkStaticCellLocator;

class GEOSHAPINGFILTERSMARKERS_EXPORT vtkMarkerCrossings
{
public:
  vtkMarkerCrossings();
  ~vtkMarkerCrossings();
  vtkMarkerCrossings(const vtkMarkerCrossings&) = delete;
  void operator=(const vtkMarkerCrossings&) = delete;

  /// Triangulates `surface` and builds the locator; the vertical lines reach past the
  /// surface's and the markers' z range (`markerZ`: lowest, highest; an empty range,
  /// lowest > highest, for none). False when the surface has no polygons.
  bool SetSurface(vtkDataSet* surface, const double markerZ[2]);
  /// The triangles; point ids are the surface's own when it is vtkPolyData, else
  /// SurfacePointId maps them.
  vtkPolyData* GetTriangles() { return this->Triangles; }
  vtkStaticCellLocator* GetLocator() { return this->Locator; }
  /// The surface's point id of triangle point `id`.
  vtkIdType SurfacePointId(vtkIdType id) const;
  /// The triangles (cell ids of GetTriangles) the vertical line through (x, y) crosses.
  void Crossed(double x, double y, vtkIdList* cells);
  /// The corners of triangle `cell`: their ids in GetTriangles (into `ids`) and positions.
  void Corners(vtkIdType cell, vtkIdList* ids, Eigen::Vector3d corners[3]);

private:
  vtkSmartPointer<vtkPolyData> Triangles;
  vtkNew<vtkStaticCellLocator> Locator;
  vtkNew<vtkPoints> Hits;
  vtkDataArray* Original = nullptr;
  double ZLow = 0.0, ZHigh = 0.0, Tolerance = 0.0;
};

#endif
