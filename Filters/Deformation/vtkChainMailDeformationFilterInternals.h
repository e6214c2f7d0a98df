// Private to the GeoShaping::FiltersDeformation module: the filter's cached core state
// and small helpers shared by its implementation files.
#ifndef vtkChainMailDeformationFilterInternals_h
#define vtkChainMailDeformationFilterInternals_h

#include "vtkChainMailDeformationFilter.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkGeoShapingGhostRing.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationStringKey.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkSparseArrayChanges.h"
#include "vtkStaticPointLocator.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/edit/edit_session.h"
#include "geoshaping/mesh/sparse_normals.h"
#include "geoshaping/metrics/marker_pins.h"
#include "geoshaping/parallel/partitioned_chainmail.h"
#include "geoshaping/parallel/partitioned_envelope.h"
#include "geoshaping/passes/frame_passes.h"

#include <chrono>
#include <initializer_list>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

struct vtkChainMailDeformationFilter::vtkInternals
{
  geoshaping::ChainMailDeformer Deformer;
  geoshaping::Curve StretchCurve, CompressionCurve, ShearCurve; // only .points used

  // What the cached core state was built from.
  vtkPoints* GeometryPoints = nullptr;
  vtkIdType GeometrySize = -1;
  vtkMTimeType GeometryTime = 0;
  int GeometryPrecision = -1;
  bool GeometryValid = false;
  vtkDataArray* MalleabilitySource = nullptr;
  vtkMTimeType MalleabilityTime = 0;
  double MalleabilityDefault = -1.0;
  vtkDataArray* PinSource = nullptr;
  vtkMTimeType PinTime = 0;
  vtkDataArray* SlidingSource = nullptr;
  vtkMTimeType SlidingTime = 0;
  // Honoured markers (port 2): the vertices pinned under them and the counts
  // (geoshaping/metrics/marker_pins.h), made from MarkerSources (data object, MTime per
  // connection; empty with HonourMarkers off); MarkersChanged until the pins take them.
  geoshaping::MarkerPins Markers;
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> MarkerSources;
  bool MarkersValid = false;
  bool MarkersHonoured = false;
  bool MarkersChanged = false;
  // The markers (any HonourMarkers) mapped to the committed shape's triangles under them,
  // for the frame's misfit figures (UpdateMarkerMisfit); made with the pins.
  geoshaping::MarkerCrossingMap MarkerMap;
  // The vertices shown before a SnapToMarkers, rewritten at the next update.
  std::vector<geoshaping::index_t> SnapStale;
  // The obstacles the deformer holds were built from (data object, MTime per connection).
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> ObstacleSources;
  // Connections taken off port 1 (obstacles) or 2 (markers) because their producer has
  // the filter upstream (a pipeline loop; Obstacles.cxx); put back once the loop is gone,
  // dropped when their port is set or cleared.
  struct HeldInput
  {
    vtkSmartPointer<vtkAlgorithm> Producer;
    int Output; // the producer's output port
    int Port;   // this filter's input port
  };
  std::vector<HeldInput> HeldInputs;
  std::string RefusedLoop; // RefuseObstacleLoop's name, until it is called with ""

  // The passes after the frame (refinement, relaxation; geoshaping/passes/frame_passes.h), and
  // the vertices they wrote beyond the frame's moved ones last update (restored to rest
  // next update, with the moved ones).
  geoshaping::FramePasses Passes;
  std::vector<geoshaping::index_t> PassesWritten;

  // Cache invalidation, in one place. Links: the link data of the refinement and the
  // relaxation (malleability, pins or the rest shape changed; rebuilt on the next pass).
  // Geometry: everything derived from the input's points and cells, the links, the
  // array sources, the locator, the passes' written vertices, the applied edits (the
  // records are replayed) and the once-only warnings.
  enum class Stale
  {
    Links,
    Geometry
  };
  void Invalidate(Stale level);

  // Editing (geoshaping/edit/edit_session.h): the EditHistory list, its commands and the
  // history that applies it; the last frame's recipe.
  geoshaping::EditSession Edits;
  geoshaping::EditRecipe FrameRecipe;

  // Displacement of v from its rest position in the last frame (after the passes).
  const Eigen::Vector3d& FinalDisplacement(geoshaping::index_t v) const
  {
    return this->Passes.displacement(this->Deformer, v);
  }

  // Whether input point v moved by u lands where the output's point type holds it:
  // positions are computed in double, and a double beyond FLT_MAX cast to float is
  // undefined behaviour (in practice inf). x receives the position.
  bool Fits(geoshaping::index_t v, const Eigen::Vector3d& u, Eigen::Vector3d& x) const
  {
    this->GeometryPoints->GetPoint(v, x.data());
    x += u;
    return x.cwiseAbs().maxCoeff() <= this->OutputPoints->GetData()->GetDataTypeMax();
  }

  // The output points persist between updates; each update rewrites only the changed
  // vertices and lists them (vtkGrowingBoundsPoints::PointsChanged), so bounds and a
  // consumer that saw the previous update (the GeoShaping Surface representation)
  // follow in O(changed).
  vtkSmartPointer<vtkGrowingBoundsPoints> OutputPoints;
  vtkNew<vtkIdTypeArray> Changed;
  // Lighting follows the shape: when the input is polygons with point normals, the
  // output carries its own copy, recomputed for the vertices each update's changes
  // affect (the changed ones and those sharing a face with them), which are listed
  // with the changed points.
  geoshaping::SparseNormals Normals;
  vtkSmartPointer<vtkDataArray> OutputNormals;
  std::vector<geoshaping::index_t> Affected, NormalsMoved; // scratch of UpdateNormals
  // A DEM's elevation follows the shape: when the input has the point array "Elevation"
  // (DEM Surface's), the output's "Elevation" is it moved by each vertex's change of z,
  // rewritten for the changed vertices each update (all of them when the input's array
  // or points change), and the input's array is passed as "RestElevation".
  vtkSmartPointer<vtkDoubleArray> OutputElevation;
  vtkDataArray* ElevationSource = nullptr;
  vtkMTimeType ElevationTime = 0;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  // The distributed path (more than one process): the input's ghost ring, made when the
  // input lacks it; the partition that drives Deformer over this piece.
  vtkGeoShapingGhostRing GhostRing;
  std::unique_ptr<geoshaping::PartitionedChainMail> Partition;
  // Its refinement (the partitioned envelope), set up on the first refinement after
  // the partition changed.
  std::shared_ptr<geoshaping::PartitionedEnvelope> Envelope;
  // Its point GlobalIds when the input has none (geoshaping::coordinate_ids), shown in
  // the output; null when the input has its own.
  vtkSmartPointer<vtkIdTypeArray> GeneratedIds;
  // Point GlobalIds of the input in one process, when it has them: global id -> point id
  // (the grasp's and the edit records' names).
  geoshaping::GlobalIdMap Ids;
  // The edits' collectives on several processes (the global controller), with Partition.
  std::unique_ptr<geoshaping::Exchange> EditExchange;
  // Where edit records' ids are: the partition's pieces, else Ids (Parallel.cxx).
  geoshaping::EditPlace Placement() const;

  // The processes of this update: their collectives when there are several, null on
  // one. Every stage of RequestData runs on both; on several each local refusal is
  // agreed (a process that stopped alone would leave the others waiting).
  std::unique_ptr<geoshaping::Exchange> Processes;
  // Every process's `mine`, by process (on one process: its own).
  std::vector<std::vector<std::int64_t>> AllGather(const std::vector<std::int64_t>& mine) const
  {
    return this->Processes ? this->Processes->all_gather(mine)
                           : std::vector<std::vector<std::int64_t>>{ mine };
  }
  // True on every process when `ok` is true on every process.
  bool AllAgree(bool ok) const
  {
    for (const auto& v : this->AllGather({ ok ? 1 : 0 }))
      if (!v[0])
        return false;
    return true;
  }
  // Where a local error happened: "Process k: " on several processes, "" on one.
  std::string Where() const
  {
    return this->Processes ? "Process " + std::to_string(this->Processes->piece()) + ": " : "";
  }
  // The name of vertex v, as GraspPointId, LastGraspPointId and the sponsors name it: its
  // global id where points have ids (point GlobalIds, or several processes), else v.
  std::int64_t PointName(geoshaping::index_t v) const
  {
    return this->Partition || !this->Ids.empty() ? this->Deformer.global_id(v) : v;
  }
  // The one process's vertex named `name` (-1: none).
  geoshaping::index_t Vertex(std::int64_t name) const
  {
    std::vector<geoshaping::index_t> holding;
    this->Holders(name, holding);
    return holding.empty() ? -1 : holding.front();
  }
  // Appends this process's vertices named `name` (none when another process holds it;
  // the copies of a point held twice).
  void Holders(std::int64_t name, std::vector<geoshaping::index_t>& out) const
  {
    if (this->Partition)
      this->Partition->holders(name, out);
    else if (!this->Ids.empty() && this->Ids.find(name) >= 0)
      out.push_back(this->Ids.find(name));
    else if (this->Ids.empty() && name >= 0 && name < this->GeometrySize)
      out.push_back(geoshaping::index_t(name));
  }
  std::set<std::string> Warned; // WarnOnce's messages, cleared when the geometry changes
};

namespace vtkChainMailDeformationFilterDetail
{
// The global controller's collectives when it has several processes, else null
// (Parallel.cxx: the filter's own message tags).
std::unique_ptr<geoshaping::Exchange> ProcessExchange();

inline void SetCurvePoints(geoshaping::Curve& curve, vtkPiecewiseFunction* f)
{
  curve.points.clear();
  if (!f)
    return;
  double node[4];
  for (int i = 0; i < f->GetSize(); ++i)
  {
    f->GetNodeValue(i, node);
    curve.points.emplace_back(node[0], node[1]);
  }
}

// GraspMode nearest to a position: the point nearest `p` by squared distance (double,
// from the points' coordinates), ties to the lowest id(v) (its global id), -1 when there
// is none. The same rule on one process and on each process of several, so the reduction
// over processes (Parallel.cxx) picks the same point for any partition.
template<class Id>
vtkIdType NearestPoint(
  vtkStaticPointLocator* locator, vtkPoints* points, const double p[3], const Id& id, double& dist2)
{
  vtkIdType best = locator->FindClosestPoint(p);
  if (best < 0)
    return -1;
  double x[3];
  points->GetPoint(best, x);
  dist2 = vtkMath::Distance2BetweenPoints(x, p);
  // Every point as near (a tie the locator may have broken either way).
  vtkNew<vtkIdList> near;
  locator->FindPointsWithinRadius(std::sqrt(dist2) * (1.0 + 1e-9) + 1e-300, p, near);
  for (vtkIdType i = 0; i < near->GetNumberOfIds(); ++i)
  {
    const vtkIdType v = near->GetId(i);
    points->GetPoint(v, x);
    const double d2 = vtkMath::Distance2BetweenPoints(x, p);
    if (d2 < dist2 || (d2 == dist2 && id(v) < id(best)))
      best = v, dist2 = d2;
  }
  return best;
}

using IdList = std::vector<geoshaping::index_t>;
using IdLists = std::initializer_list<const IdList*>;

// `grasp`: its global id (its point index without ids).
inline geoshaping::EditRecipe Recipe(vtkChainMailDeformationFilter* self, std::int64_t grasp)
{
  geoshaping::EditRecipe r;
  r.grasp = grasp;
  r.displacement = Eigen::Vector3d(self->GetDisplacement());
  r.queue = self->GetCandidateQueue();
  self->GetStretchRange(r.stretch);
  self->GetCompressionRange(r.compression);
  self->GetShearRange(r.shear);
  r.curve_shape = self->GetTransferCurveShape();
  r.step_threshold = self->GetStepThreshold();
  r.refinement_iterations = self->GetRefinementIterations();
  return r;
}

inline geoshaping::Curve MakeCurve(
  const double range[2], int shape, double threshold, const geoshaping::Curve& userPoints)
{
  geoshaping::Curve c;
  c.at_rigid = range[0];
  c.at_soft = range[1];
  c.threshold = threshold;
  c.shape = shape == vtkChainMailDeformationFilter::SMOOTH ? geoshaping::CurveShape::smooth
            : shape == vtkChainMailDeformationFilter::STEP ? geoshaping::CurveShape::step
                                                           : geoshaping::CurveShape::linear;
  if (!userPoints.points.empty())
  {
    c.shape = geoshaping::CurveShape::piecewise;
    c.points = userPoints.points;
  }
  return c;
}

// The transfer function of the filter's properties and the user's curve points.
inline geoshaping::TransferFunction Transfer(vtkChainMailDeformationFilter* self,
  const geoshaping::Curve& stretch, const geoshaping::Curve& compression,
  const geoshaping::Curve& shear)
{
  const int shape = self->GetTransferCurveShape();
  const double threshold = self->GetStepThreshold();
  geoshaping::TransferFunction tf;
  tf.stretch = MakeCurve(self->GetStretchRange(), shape, threshold, stretch);
  tf.compression = MakeCurve(self->GetCompressionRange(), shape, threshold, compression);
  tf.shear = MakeCurve(self->GetShearRange(), shape, threshold, shear);
  return tf;
}
// The boundary triangles of one obstacle (its polygons, or its surface when it is not
// polydata, triangulated) appended to xyz and triangles (indices into xyz / 3). Returns
// 0, the number of points with non-finite coordinates (nothing appended), or -1 when
// `obstacle` is not a vtkDataSet (vtkChainMailDeformationFilterObstacles.cxx).
vtkIdType AppendObstacle(
  vtkDataObject* obstacle, std::vector<double>& xyz, std::vector<std::int64_t>& triangles);
// Whether `obstacle` is a data set without points: a connection with nothing chosen (the
// panel's Pipeline Connection set to none), no obstacle rather than a bad one.
bool IsEmptyObstacle(vtkDataObject* obstacle);
// The start of an obstacle update with connections on port 1, on one process or several:
// the clearance given to the deformer (false, with the error, when it is not a finite
// distance >= 0) and each connection's data with its MTime in `sources`
// (vtkChainMailDeformationFilterObstacles.cxx).
bool ObstacleSources(vtkChainMailDeformationFilter* self, geoshaping::ChainMailDeformer& deformer,
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>>& sources);
// The end of it: every obstacle's triangles (AppendObstacle's xyz and triangles, all
// pieces' on several processes) given to the deformer; false, with the error, when the
// deformer refuses them.
bool SetObstacles(vtkChainMailDeformationFilter* self, geoshaping::ChainMailDeformer& deformer,
  const std::vector<double>& xyz, const std::vector<std::int64_t>& triangles);
} // namespace vtkChainMailDeformationFilterDetail

inline void vtkChainMailDeformationFilter::vtkInternals::Invalidate(Stale level)
{
  this->Passes.invalidate();
  if (level == Stale::Links)
    return;
  this->GeometryValid = false;
  this->MalleabilitySource = nullptr;
  this->PinSource = nullptr;
  this->MarkersValid = false;
  this->SlidingSource = nullptr;
  this->MalleabilityDefault = -1.0;
  this->Locator = nullptr;
  this->PassesWritten.clear();
  this->Edits.forget_applied();
  this->Warned.clear();
}

#endif
