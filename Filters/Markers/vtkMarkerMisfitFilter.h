/**
 * @class   vtkMarkerMisfitFilter
 * @brief   How far a surface is from well markers: per marker along z and along the
 *          surface normal, with the RMS and the maximum over the markers it covers.
 *
 * Input 0 is the surface (vtkPolyData, or a vtkUnstructuredGrid whose boundary is used;
 * polygons are triangulated, vertices and lines ignored); input 1 (`Markers`) the marker
 * points (any vtkPointSet: ParaView's Table To Points of a CSV, or a GOCAD VSet read by
 * vtkGocadTSurfReader). The output is the markers as vtkPolyData (one vertex cell per
 * marker, their point data kept) with three point arrays:
 *
 * - `VerticalMisfit` (double): surface minus marker along z, at the surface's crossing of
 *   the marker's vertical line nearest to the marker; 0 where there is none;
 * - `Misfit` (double): the distance to the nearest surface point, signed by the side of
 *   the surface the marker is on (negative above a horizon whose normal points up);
 * - `Inside` (unsigned char): 1 where the vertical line crosses the surface (the marker is
 *   inside its footprint), 0 otherwise (with one warning giving the count);
 *
 * and field data `MisfitRMS`, `MisfitMax` (max |Misfit|) and `MarkersInside` over the
 * inside markers. The rules and their exact statement: geoshaping/metrics/marker_misfit.h
 * and docs/markers.md.
 *
 * Refused with an error, output empty and inputs untouched: no markers input, a marker
 * or a surface point that is not finite, a surface without polygons. No markers (an
 * empty point set) is not an error: the output is empty and the summary 0.
 *
 * Cost: a vtkStaticCellLocator over the surface's triangles, O(T log T), then per marker
 * one nearest-point query and one line query, O(log T) each for a well-shaped surface.
 */
#ifndef vtkMarkerMisfitFilter_h
#define vtkMarkerMisfitFilter_h

#include "GeoShapingFiltersMarkersModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class GEOSHAPINGFILTERSMARKERS_EXPORT vtkMarkerMisfitFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkMarkerMisfitFilter* New();
  vtkTypeMacro(vtkMarkerMisfitFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The marker points (input port 1). */
  void SetMarkersConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetMarkersData(vtkDataObject* markers) { this->SetInputData(1, markers); }

protected:
  vtkMarkerMisfitFilter();
  ~vtkMarkerMisfitFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkMarkerMisfitFilter(const vtkMarkerMisfitFilter&) = delete;
  void operator=(const vtkMarkerMisfitFilter&) = delete;
};

#endif
