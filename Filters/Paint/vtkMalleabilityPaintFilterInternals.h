// Private to the GeoShaping::FiltersPaint module: the paint filter's cached state and
// what its implementation files share (vtkMalleabilityPaintFilter.cxx: one process and
// the stages; vtkMalleabilityPaintFilterParallel.cxx: geodesic dabs on several).
#ifndef vtkMalleabilityPaintFilterInternals_h
#define vtkMalleabilityPaintFilterInternals_h

#include "vtkMalleabilityPaintFilter.h"

#include "vtkFloatArray.h"
#include "vtkGeoShapingGhostRing.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include "geoshaping/paint/brush.h"
#include "geoshaping/parallel/partitioned_geodesic.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace vtkMalleabilityPaintFilterDetail
{
// The message tags of this filter's exchange (not the deformation filter's, 914300).
constexpr int PaintTag = 914400;
// What cells BuildAdjacency skipped cost a geodesic dab.
constexpr const char* GeodesicSkips = "geodesic paths do not follow their edges.";

inline double MillisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}
} // namespace vtkMalleabilityPaintFilterDetail

struct vtkMalleabilityPaintFilter::vtkInternals
{
  // Geodesic dabs on several processes: the input's ghost ring, made when it lacks one.
  vtkGeoShapingGhostRing GhostRing;
  // The last painted output (shallow): what an aborted painting leaves in place, since
  // the executive empties the output before each execution.
  vtkSmartPointer<vtkPointSet> LastOutput;
  void KeepOutput(vtkPointSet* output)
  {
    this->LastOutput = vtk::TakeSmartPointer(output->NewInstance());
    this->LastOutput->ShallowCopy(output);
  }
  std::vector<geoshaping::Dab> Dabs;
  std::vector<double> PointDabs; // id value weight

  // Geometry the locator, points and adjacency were built from.
  vtkPoints* GeometryPoints = nullptr;
  vtkIdType GeometrySize = -1;
  vtkMTimeType GeometryTime = 0;
  bool GeometryValid = false;
  std::vector<double> Xyz;
  // Built on first use (geodesic dabs, single-dab reach): Euclidean strokes go through the
  // painter's own vertex grid instead.
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  vtkStaticPointLocator* GetLocator();
  bool AdjacencyValid = false;
  geoshaping::Adjacency Adjacency;
  // Kept between updates: its vertex grid (built once per geometry) and the open stroke
  // of the array in Painted, which appended dabs continue.
  std::unique_ptr<geoshaping::Painter> Painter;

  // The last painted array, what it was painted from (input geometry, source array,
  // settings) and the dabs applied to it: an update that only appends dabs continues it.
  vtkSmartPointer<vtkFloatArray> Painted;
  std::vector<std::uintptr_t> PaintedFrom;
  std::vector<geoshaping::Dab> AppliedDabList;
  std::vector<double> AppliedPointDabs;

  // What the painted array was painted from, apart from the dabs.
  static std::vector<std::uintptr_t> Signature(
    vtkPointSet* input, vtkMalleabilityPaintFilter* self, const char* name);

  // Rebuilds what depends on the geometry when it changed; false on bad points.
  bool Update(vtkPointSet* input, vtkMalleabilityPaintFilter* self);
  geoshaping::PointQueries Queries();

  // The id a tie for the nearest vertex goes by: the point GlobalIds when the input has
  // them (one per point), else the points' coordinate ids (coordinate_ids.h, the
  // numbering several processes use); copied when that array changes, numbered when the
  // geometry changes.
  vtkDataArray* IdSource = nullptr;
  vtkMTimeType IdTime = 0;
  bool IdsFromCoordinates = false;
  std::vector<std::int64_t> Ids; // empty: the point ids
  void UpdateIds(vtkPointSet* input);
  // The vertex nearest p, ties to the lowest id (-1 when there is none).
  geoshaping::index_t Nearest(const Eigen::Vector3d& p);
  vtkNew<vtkIdList> Found;

  // Geodesic painting on data split across processes: the pieces' label exchange, set
  // up when the geometry or the ids change on any process.
  std::unique_ptr<geoshaping::PartitionedGeodesic> Geodesic;
};

#endif
