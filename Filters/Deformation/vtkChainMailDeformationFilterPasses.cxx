// The passes after the frame (refinement, relaxation) of vtkChainMailDeformationFilter:
// progress, abort and statistics around the core's geoshaping::FramePasses.
#include "vtkChainMailDeformationFilterInternals.h"
#include "vtkChainMailDeformationFilterParallelRefine.h"

#include <algorithm>

using namespace vtkChainMailDeformationFilterDetail;

std::function<bool()> vtkChainMailDeformationFilter::SweepMonitor(
  int total, int& sweeps, bool& aborted)
{
  // Asked after every sweep: the progress bar moves, and an abort stops the sweeps.
  return [this, total, &sweeps, &aborted]
  {
    this->UpdateProgress(double(++sweeps) / std::max(1, total));
    aborted = this->CheckAbort();
    return aborted;
  };
}

void vtkChainMailDeformationFilter::KeepAbortedPass(const char* pass, int done, int total)
{
  // Each sweep keeps a valid deformation: the result so far is kept rather than emptied
  // by the executive.
  this->SetAbortOutput(false);
  this->SetAbortExecute(0);
  vtkWarningMacro(<< pass << " stopped after " << done << " of " << total
                  << " sweeps at the user's request.");
}

void vtkChainMailDeformationFilter::Refine(std::int64_t grasp)
{
  vtkInternals& state = *this->Internals;
  geoshaping::ProjectionOptions options;
  options.max_iterations = this->RefinementIterations;
  options.tolerance = this->RefinementTolerance;
  options.solver = static_cast<geoshaping::ProjectionSolver>(this->RefinementSolver);
  if (state.Partition) // collective, Envelope with the Axes region; an abort is not agreed
  {
    const PartitionedRefinement refined = RefinePartitioned(
      state.Passes, state.Deformer, state.Envelope, grasp, options, *state.Processes);
    this->Statistics.LastRefinementMilliseconds = refined.milliseconds;
    this->Statistics.NumberOfRefinementSweeps = refined.report.iterations;
    this->Statistics.NumberOfRefinedPoints = vtkIdType(refined.refined);
    // Each superstep of its label correction is one round.
    this->Statistics.NumberOfSupersteps = vtkIdType(refined.supersteps);
    this->Statistics.NumberOfRounds = vtkIdType(refined.supersteps);
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  int sweeps = 0;
  bool aborted = false;
  options.stop = this->SweepMonitor(this->RefinementIterations, sweeps, aborted);
  const geoshaping::ProjectionReport report =
    state.Passes.refine(state.Deformer, state.Vertex(grasp), options);
  if (aborted)
  {
    this->KeepAbortedPass("Refinement", report.iterations, this->RefinementIterations);
  }
  this->Statistics.LastRefinementMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->Statistics.NumberOfRefinementSweeps = report.iterations;
  this->Statistics.NumberOfRefinedPoints = vtkIdType(state.Passes.refined_count());
}

void vtkChainMailDeformationFilter::Relax(std::int64_t grasp)
{
  vtkInternals& state = *this->Internals;
  int sweeps = 0;
  bool aborted = false;
  geoshaping::RelaxationOptions options;
  options.iterations = this->RelaxationIterations;
  options.stop = this->SweepMonitor(this->RelaxationIterations, sweeps, aborted);
  const geoshaping::RelaxationReport report =
    state.Passes.relax(state.Deformer, state.Vertex(grasp), options);
  if (aborted)
  {
    this->KeepAbortedPass("Relaxation", report.iterations, this->RelaxationIterations);
  }
  this->Statistics.NumberOfRelaxationSweeps = report.iterations;
  this->Statistics.NumberOfRelaxedPoints = vtkIdType(state.Passes.relaxed_count());
}
