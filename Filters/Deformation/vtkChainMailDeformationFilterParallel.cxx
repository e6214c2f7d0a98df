// What vtkChainMailDeformationFilter's stages do only on several processes (docs/mpi.md):
// the refusals, the ghost ring, the deformer over a piece with one ghost level (the
// core's PartitionedChainMail, which propagates across processes through a
// geoshaping::Exchange over the global vtkMultiProcessController).
#include "vtkChainMailDeformationFilterInternals.h"

#include "vtkCommunicator.h"
#include "vtkGeoShapingControllerExchange.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "geoshaping/parallel/partitioned_chainmail.h"

#include <algorithm>

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

} // namespace

std::unique_ptr<geoshaping::Exchange> vtkChainMailDeformationFilterDetail::ProcessExchange()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
    return nullptr;
  return std::make_unique<ControllerExchange>(controller);
}

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

bool vtkChainMailDeformationFilter::SelectInput(vtkPointSet*& input, vtkPointSet* output)
{
  vtkInternals& state = *this->Internals;
  if (!state.Processes)
  {
    return input->GetPoints() && input->GetNumberOfPoints() > 0;
  }
  // Not distributed yet: decided from properties, so the same on every process (and
  // whether any process has a piece of an obstacle: an empty connection, the panel's
  // Pipeline Connection with nothing chosen, is no obstacle).
  const auto obstacles = [this, &state]()
  {
    bool mine = false;
    for (int i = 0; i < this->GetNumberOfInputConnections(1); ++i)
      mine = mine ||
             !vtkChainMailDeformationFilterDetail::IsEmptyObstacle(this->GetInputDataObject(1, i));
    return !state.AllAgree(!mine);
  };
  const auto markers = [this, &state]()
  {
    bool mine = false;
    for (int i = 0; i < this->GetNumberOfInputConnections(2); ++i)
    {
      vtkDataSet* data = vtkDataSet::SafeDownCast(this->GetInputDataObject(2, i));
      mine = mine || (data && data->GetNumberOfPoints() > 0);
    }
    return !state.AllAgree(!mine);
  };
  std::string refused;
  if (this->RefinementIterations > 0 &&
      (this->RefinementSolver != REFINEMENT_ENVELOPE || this->ValidRegionFrame != AXES))
    refused =
      std::string("refinement with RefinementSolver ") +
      geoshaping::solver_name(static_cast<geoshaping::ProjectionSolver>(this->RefinementSolver)) +
      (this->ValidRegionFrame == AXES ? " with the Axes region" : " with the Link region") +
      " (use RefinementSolver Envelope with ValidRegionFrame Axes)";
  else if (this->RelaxationIterations > 0)
    refused = "RelaxationIterations > 0 (relaxation)";
  else if (this->RefinementIterations > 0 && this->GetNumberOfInputConnections(1) > 0 &&
           obstacles())
    refused = "refinement with Obstacles (the passes' obstacle gate is not distributed)";
  else if (this->HonourMarkers && this->GetNumberOfInputConnections(2) > 0 && markers())
    refused = "HonourMarkers with markers (the markers' pins are found in one process)";
  else if (this->CandidateQueue != FIFO && this->CandidateQueue != FIFO_PRIORITY)
    refused = std::string("the ") +
              geoshaping::queue_name(static_cast<geoshaping::QueueKind>(this->CandidateQueue)) +
              " queue (sequential; use FIFO or FIFO Priority)";
  if (!refused.empty())
  {
    vtkErrorMacro("Not supported on data split across " << state.Processes->pieces()
                                                        << " processes yet: " << refused
                                                        << "; output is the undeformed input.");
    return false;
  }
  // The ghost ring, made here when the input lacks it; the output is then the input with
  // the ring, deformed.
  std::string ringError;
  vtkPointSet* ringed =
    state.GhostRing.Ensure(input, vtkMultiProcessController::GetGlobalController(), ringError);
  if (!ringed) // the same on every process
  {
    vtkErrorMacro(<< ringError << "; output is the undeformed input.");
    state.GeometryValid = false;
    state.Partition.reset();
    return false;
  }
  if (ringed != input)
  {
    output->ShallowCopy(ringed);
    input = ringed;
  }
  return true;
}

bool vtkChainMailDeformationFilter::SetUpPiece(
  vtkPointSet* input, const double* xyz, geoshaping::Adjacency adjacency, bool globalIds)
{
  vtkInternals& state = *this->Internals;
  geoshaping::Exchange& ex = *state.Processes;
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<std::int64_t> gid;
  std::vector<std::uint8_t> owned;
  std::string refusal;
  state.GeneratedIds = nullptr;
  if (!vtkGeoShapingAdapter::IdentifyPiece(input, xyz, globalIds, ex, gid, owned, refusal))
  {
    vtkErrorMacro(<< refusal << "; output is the undeformed input.");
    state.Partition.reset();
    return false;
  }
  if (!globalIds)
  {
    state.GeneratedIds = vtkSmartPointer<vtkIdTypeArray>::New();
    state.GeneratedIds->SetName("GlobalIds");
    state.GeneratedIds->SetNumberOfTuples(n);
    std::copy(gid.begin(), gid.end(), state.GeneratedIds->GetPointer(0));
  }
  state.Partition = std::make_unique<geoshaping::PartitionedChainMail>(state.Deformer);
  state.Envelope.reset(); // set up again on the next refinement
  state.EditExchange = vtkChainMailDeformationFilterDetail::ProcessExchange();
  const std::string error = state.Partition->set_piece(
    xyz, geoshaping::index_t(n), std::move(adjacency), gid.data(), owned.data(), ex);
  if (!error.empty())
  {
    vtkErrorMacro("Refused partition: " << error << "; output is the undeformed input.");
    state.Partition.reset();
    return false;
  }
  state.GeometryValid = true;
  return true;
}
