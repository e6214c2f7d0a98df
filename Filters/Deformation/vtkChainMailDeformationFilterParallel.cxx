// The distributed path of vtkChainMailDeformationFilter (docs/mpi.md): each process
// holds a piece with one ghost level; the core's PartitionedChainMail propagates across
// processes through a geoshaping::Exchange over the global vtkMultiProcessController.
#include "vtkChainMailDeformationFilterInternals.h"
#include "vtkChainMailDeformationFilterParallelRefine.h"

#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkGeoShapingControllerExchange.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/parallel/coordinate_ids.h"
#include "geoshaping/parallel/partitioned_chainmail.h"

#include <algorithm>
#include <cmath>

namespace
{
// Its own message tags: the paint filter's exchange (914400) never mixes with it.
class ControllerExchange : public vtkGeoShapingControllerExchange
{
public:
  explicit ControllerExchange(vtkMultiProcessController* c)
    : vtkGeoShapingControllerExchange(c, 914300)
  {
  }
};

// True on every process when `ok` is true on every process.
bool AllAgree(ControllerExchange& ex, bool ok)
{
  for (const auto& v : ex.all_gather({ ok ? 1 : 0 }))
    if (!v[0])
      return false;
  return true;
}
} // namespace

using namespace vtkChainMailDeformationFilterDetail;

geoshaping::EditPlace vtkChainMailDeformationFilter::vtkInternals::Placement() const
{
  if (!this->Partition || !this->EditExchange)
    return this->Ids.place();
  geoshaping::EditPlace place;
  const geoshaping::PartitionedChainMail* partition = this->Partition.get();
  place.holders = [partition](std::int64_t id, std::vector<geoshaping::index_t>& out)
  { partition->holders(id, out); };
  place.exchange = this->EditExchange.get();
  return place;
}

int vtkChainMailDeformationFilter::ComputeInputUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::ComputeInputUpdateExtent(request, inputVector, outputVector))
    return 0;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // One ring of ghosts: every neighbour of an owned point is on this process.
    vtkGeoShapingAdapter::RequestGhostRing(inputVector, outputVector);
  }
  return 1;
}

bool vtkChainMailDeformationFilter::RequestDataParallel(vtkPointSet* input, vtkPointSet* output)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
    return false;
  vtkInternals& state = *this->Internals;
  ControllerExchange ex(controller);

  // Not distributed yet: decided from properties, so the same on every process.
  std::string refused;
  if (this->RefinementIterations > 0 &&
      (this->RefinementSolver != REFINEMENT_ENVELOPE || this->ValidRegionFrame != AXES))
    refused =
      std::string("refinement with RefinementSolver ") +
      geoshaping::solver_name(static_cast<geoshaping::ProjectionSolver>(this->RefinementSolver)) +
      (this->ValidRegionFrame == AXES ? " in the Axes frame" : " in the Link frame") +
      " (use RefinementSolver Envelope with ValidRegionFrame Axes)";
  else if (this->RelaxationIterations > 0)
    refused = "RelaxationIterations > 0 (relaxation)";
  else if (this->GetNumberOfInputConnections(1) > 0)
    refused = "Obstacles (obstacle surfaces are not distributed yet)";
  else if (this->CandidateQueue != FIFO && this->CandidateQueue != FIFO_PRIORITY)
    refused = std::string("the ") +
              geoshaping::queue_name(static_cast<geoshaping::QueueKind>(this->CandidateQueue)) +
              " queue (sequential; use FIFO or FIFO Priority)";
  if (!refused.empty())
  {
    vtkErrorMacro("Not supported on data split across " << ex.pieces()
                                                        << " processes yet: " << refused
                                                        << "; output is the undeformed input.");
    return true;
  }

  // The ghost ring, made here when the input lacks it; the output is then the input with
  // the ring, deformed.
  std::string ringError;
  vtkPointSet* ringed = state.GhostRing.Ensure(input, controller, ringError);
  if (!ringed) // the same on every process
  {
    vtkErrorMacro(<< ringError << "; output is the undeformed input.");
    state.GeometryValid = false;
    state.Partition.reset();
    return true;
  }
  if (ringed != input)
  {
    output->ShallowCopy(ringed);
    input = ringed;
  }

  // Local checks, agreed on by every process (a process that stopped alone would leave
  // the others waiting in a collective), in one gather with whether the geometry changed
  // and whether the piece has point GlobalIds.
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* gids = vtkGeoShapingAdapter::PointGlobalIds(input);
  vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
  std::string problem;
  if (n > vtkIdType(std::numeric_limits<geoshaping::index_t>::max()))
    problem = "more than 2^31 - 1 points";
  else if (n > 0 && gids && (gids->GetNumberOfTuples() != n || gids->GetNumberOfComponents() != 1))
    problem = "a point GlobalIds array that is not one value per point";
  else if (n > 0 && ghosts && ghosts->GetNumberOfTuples() != n)
    problem = "a vtkGhostType point array that is not one value per point";
  if (!problem.empty())
    vtkErrorMacro(
      "Process " << ex.piece() << ": " << problem << "; output is the undeformed input.");
  const bool stale = !state.Partition || !state.GeometryValid ||
                     state.GeometryPoints != input->GetPoints() || state.GeometrySize != n ||
                     state.GeometryTime != vtkGeoShapingAdapter::GeometryTime(input) ||
                     state.GeometryPrecision != this->OutputPointsPrecision;
  bool ok = true, anyStale = false, withIds = false, withoutIds = false;
  for (const auto& v : ex.all_gather({ problem.empty(), stale, n == 0 ? 0 : gids ? 1 : 2 }))
  {
    ok = ok && v[0];
    anyStale = anyStale || v[1];
    withIds = withIds || v[2] == 1;
    withoutIds = withoutIds || v[2] == 2;
  }
  if (ok && withIds && withoutIds)
  {
    vtkErrorMacro("Point GlobalIds on some processes and not on others; output is the "
                  "undeformed input.");
    ok = false;
  }
  else if (!ok && problem.empty())
    vtkErrorMacro("Another process refused its piece; output is the undeformed input.");
  if (!ok)
  {
    state.GeometryValid = false;
    state.Partition.reset();
    return true;
  }

  // Geometry: rebuilt on every process when it changed on any (points read only then).
  if (anyStale)
  {
    // On every process, whether its own piece changed or not: set_piece below resets the
    // deformer, so every process replays its edits (collectively) at UpdateEdits.
    state.Invalidate(vtkInternals::Stale::Geometry);
    std::vector<double> xyz;
    vtkIdType firstBad = -1;
    const bool finite =
      n == 0 || vtkGeoShapingAdapter::PointsAsDouble(input->GetPoints(), xyz, firstBad) == 0;
    if (!finite)
      vtkErrorMacro("Process " << ex.piece() << ": non-finite point coordinates (first at point "
                               << firstBad << "); output is the undeformed input.");
    if (!AllAgree(ex, finite))
    {
      state.Partition.reset();
      return true;
    }
    // The setup once: the points read once, the adjacency built once, the deformer set
    // up by set_piece alone (not also as a whole mesh), then the output's caches.
    state.GeometryPoints = input->GetPoints();
    state.GeometrySize = n;
    state.GeometryTime = vtkGeoShapingAdapter::GeometryTime(input);
    state.GeometryPrecision = this->OutputPointsPrecision;
    state.Ids.clear(); // one process's map: the partition names the points here
    if (n > 0)
    {
      this->BuildOutputCaches(input, xyz);
      ++this->NumberOfRebuilds;
    }
    vtkIdType skipped = 0;
    geoshaping::Adjacency adjacency = vtkGeoShapingAdapter::BuildAdjacency(input, skipped);
    if (skipped > 0)
    {
      vtkWarningMacro("Process " << ex.piece() << ": " << skipped
                                 << " cells are of an unsupported type (higher-order or "
                                    "polyhedral) or have invalid point ids; their edges do not "
                                    "propagate deformation.");
    }
    std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
    std::vector<std::uint8_t> owned(static_cast<std::size_t>(n));
    // Without vtkGhostType this is the one process holding points (GhostRing): all owned.
    for (vtkIdType i = 0; i < n; ++i)
      owned[std::size_t(i)] =
        !ghosts || (ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT) == 0;
    state.GeneratedIds = nullptr;
    if (withIds)
    {
      for (vtkIdType i = 0; i < n; ++i)
        gid[std::size_t(i)] = std::int64_t(gids->GetTuple1(i));
    }
    else
    {
      // None anywhere: numbered by coordinates, whatever the partition, and a seam point
      // that several processes claim owned by the lowest (coordinate_ids.h).
      const std::vector<std::uint8_t> claimed = std::move(owned);
      geoshaping::index_t coincident = 0;
      gid = geoshaping::coordinate_ids(
        xyz.data(), geoshaping::index_t(n), claimed.data(), owned, ex, &coincident);
      const std::string split = geoshaping::coincident_points_refusal(coincident, ex);
      if (!split.empty())
      {
        vtkErrorMacro(<< split << "; output is the undeformed input.");
        state.Partition.reset();
        return true;
      }
      state.GeneratedIds = vtkSmartPointer<vtkIdTypeArray>::New();
      state.GeneratedIds->SetName("GlobalIds");
      state.GeneratedIds->SetNumberOfTuples(n);
      std::copy(gid.begin(), gid.end(), state.GeneratedIds->GetPointer(0));
    }
    state.Partition = std::make_unique<geoshaping::PartitionedChainMail>(state.Deformer);
    state.Envelope.reset(); // set up again on the next refinement
    state.Passes.invalidate();
    state.EditExchange = std::make_unique<ControllerExchange>(controller);
    const std::string error = state.Partition->set_piece(
      xyz.data(), geoshaping::index_t(n), std::move(adjacency), gid.data(), owned.data(), ex);
    state.MalleabilitySource = nullptr; // set_piece reset the deformer's arrays
    state.PinSource = nullptr;
    state.MalleabilityDefault = -1.0;
    if (!error.empty())
    {
      vtkErrorMacro("Refused partition: " << error << "; output is the undeformed input.");
      state.GeometryValid = false;
      state.Partition.reset();
      return true;
    }
    state.GeometryValid = true;
  }
  if (!AllAgree(ex, n == 0 || this->UpdateMalleabilityAndPins(input)))
  {
    state.Deformer.reset();
    return true;
  }
  // Committed edits (collective: the same list on every process).
  std::vector<int> shown; // the last frame, shown until rewritten
  const std::vector<int> touched = this->UpdateEdits(shown);

  // The grasp, as a global id: GraspPointId, or the point nearest GraspPosition over all
  // processes (each process's nearest, reduced by (squared distance, global id): a ghost
  // has its owner's coordinates and id, so the result is the same for any partition).
  std::int64_t grasp = this->GraspPointId;
  if (this->GraspMode == GRASP_NEAREST_TO_POSITION)
  {
    grasp = -1;
    const double* p = this->GraspPosition;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      vtkErrorMacro("No deformation: GraspPosition (" << p[0] << ", " << p[1] << ", " << p[2]
                                                      << ") is not finite; output is the "
                                                         "undeformed input.");
    }
    else
    {
      std::int64_t mine[3] = { 0, 0, 0 }; // found, squared distance's bits, global id
      if (n > 0)
      {
        if (!state.Locator)
        {
          state.Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
          state.Locator->SetDataSet(input);
          state.Locator->BuildLocator();
        }
        double dist2 = 0.0;
        const vtkIdType v = NearestPoint(
          state.Locator, input->GetPoints(), p,
          [&state](vtkIdType w) { return state.Deformer.global_id(geoshaping::index_t(w)); },
          dist2);
        if (v >= 0)
        {
          mine[0] = 1;
          mine[1] = geoshaping::bit_cast<std::int64_t>(dist2);
          mine[2] = state.Deformer.global_id(geoshaping::index_t(v));
        }
      }
      double best = 0.0;
      for (const auto& o : ex.all_gather({ mine[0], mine[1], mine[2] }))
      {
        const double d2 = geoshaping::bit_cast<double>(o[1]);
        if (o[0] && (grasp < 0 || d2 < best || (d2 == best && o[2] < grasp)))
          grasp = o[2], best = d2;
      }
    }
  }

  const geoshaping::TransferFunction tf =
    Transfer(this, state.StretchCurve, state.CompressionCurve, state.ShearCurve);
  const bool validTransfer = !*tf.validate();
  if (!validTransfer)
  {
    vtkErrorMacro("Invalid transfer function: " << tf.validate() << ".");
  }
  else
  {
    state.Deformer.set_transfer_function(tf);
    state.Deformer.set_queue(static_cast<geoshaping::QueueKind>(this->CandidateQueue));
    state.Deformer.set_valid_region_frame(
      static_cast<geoshaping::ValidRegionFrame>(this->ValidRegionFrame));
  }
  if (!validTransfer || grasp < 0)
  {
    state.Deformer.reset(); // no grasp: the rest shape
  }
  else
  {
    const auto start = std::chrono::steady_clock::now();
    const geoshaping::FrameResult r = state.Partition->deform(grasp,
      Eigen::Vector3d(this->Displacement[0], this->Displacement[1], this->Displacement[2]), ex);
    this->Statistics.LastDeformationMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!r.ok)
    {
      vtkErrorMacro("No deformation: " << r.message << "; output is the undeformed input.");
    }
    PartitionedRefinement refined;
    if (r.ok && this->RefinementIterations > 0) // collective; Envelope in the Axes frame
    {
      geoshaping::ProjectionOptions options;
      options.max_iterations = this->RefinementIterations;
      options.tolerance = this->RefinementTolerance;
      options.solver = geoshaping::ProjectionSolver::envelope;
      refined = RefinePartitioned(
        state.Passes, state.Deformer, state.Envelope, this->GraspPointId, options, ex);
      this->Statistics.LastRefinementMilliseconds = refined.milliseconds;
      this->Statistics.NumberOfRefinementSweeps = refined.report.iterations;
      this->Statistics.NumberOfRefinedPoints = vtkIdType(refined.refined);
    }
    // Totals over all processes (the bytes include the refinement's), and the grasp's
    // malleability from the process that owns it.
    std::int64_t moved = 0, examined = 0, bytes = 0, graspMalleability = -1;
    std::vector<geoshaping::index_t> holding;
    state.Partition->holders(grasp, holding);
    for (geoshaping::index_t v : holding)
      if (r.ok && state.Deformer.owned(v))
        graspMalleability =
          geoshaping::bit_cast<std::int64_t>(double(state.Deformer.malleability(v)));
    for (const auto& v : ex.all_gather({ std::int64_t(r.moved), std::int64_t(r.examined),
           std::int64_t(ex.bytes_sent()), graspMalleability }))
    {
      moved += v[0];
      examined += v[1];
      bytes += v[2];
      if (v[3] >= 0)
        this->Statistics.LastGraspMalleability = geoshaping::bit_cast<double>(v[3]);
    }
    this->Statistics.NumberOfBytesExchanged = vtkIdType(bytes);
    // Each superstep of the refinement's label correction is one round.
    this->Statistics.NumberOfSupersteps =
      vtkIdType(state.Partition->supersteps() + refined.supersteps);
    this->Statistics.NumberOfRounds = vtkIdType(state.Partition->rounds() + refined.supersteps);
    this->Statistics.NumberOfDisplacedPoints = vtkIdType(moved);
    this->Statistics.NumberOfExaminedCandidates = vtkIdType(examined);
    this->Statistics.LastGraspPointId = r.ok ? grasp : -1;
    state.FrameRecipe = Recipe(this, grasp);
    if (r.ok && !AllAgree(ex, n == 0 || this->OutputFits()))
      this->DropFrame(shown);
  }
  if (n > 0)
    this->WriteOutput(input, output, shown, touched);
  if (n > 0 && state.GeneratedIds)
    output->GetPointData()->SetGlobalIds(state.GeneratedIds);
  return true;
}
