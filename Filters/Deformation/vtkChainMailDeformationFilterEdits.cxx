// Refinement and editing (commit, undo, redo) of vtkChainMailDeformationFilter.
#include "vtkChainMailDeformationFilterInternals.h"

#include <algorithm>

using namespace vtkChainMailDeformationFilterDetail;

void vtkChainMailDeformationFilter::Refine(vtkIdType grasp)
{
  vtkInternals& in = *this->Internals;
  const geoshaping::TransferFunction& tf = in.Deformer.transfer_function();
  if (!in.Projector || !SameTransfer(tf, in.LinksTransfer))
  {
    in.Links = geoshaping::link_mesh(in.Deformer);
    in.LinksTransfer = tf;
    in.Projector = std::make_unique<geoshaping::LinkProjector>(in.Links);
  }
  const auto start = std::chrono::steady_clock::now();
  // Asked after every sweep: the progress bar moves, and an abort stops the sweeps.
  int sweeps = 0;
  bool aborted = false;
  geoshaping::ProjectionOptions options;
  options.max_iterations = this->RefinementIterations;
  options.tolerance = this->RefinementTolerance;
  // Dykstra sweeps: cheaper per iteration than ADMM and on the report's front for the
  // interactive iteration counts (docs/report.md); ADMM computes the references.
  options.solver = geoshaping::ProjectionSolver::dykstra;
  options.stop = [this, &sweeps, &aborted]
  {
    this->UpdateProgress(double(++sweeps) / std::max(1, this->RefinementIterations));
    aborted = this->CheckAbort();
    return aborted;
  };
  const geoshaping::ProjectionReport report =
    geoshaping::refine_links(*in.Projector, in.Deformer, geoshaping::index_t(grasp), options);
  if (aborted)
  {
    // Each sweep only lowers the link error: the result so far is a valid deformation,
    // kept rather than emptied by the executive.
    this->SetAbortOutput(false);
    this->SetAbortExecute(0);
    vtkWarningMacro("Refinement stopped after " << report.iterations << " of "
                                                << this->RefinementIterations
                                                << " sweeps at the user's request.");
  }
  this->LastRefinementMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->NumberOfRefinementSweeps = report.iterations;
  this->NumberOfRefinedPoints = vtkIdType(in.Projector->changed().size());
  in.Refining = true;
}

void vtkChainMailDeformationFilter::AddEdit(const char* record)
{
  this->Internals->EditRecords.emplace_back(record ? record : "");
  this->Internals->EditsDirty = true;
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllEdits()
{
  this->Internals->EditRecords.clear();
  this->Internals->EditsDirty = true;
  this->Modified();
}

int vtkChainMailDeformationFilter::GetNumberOfEdits()
{
  return static_cast<int>(this->Internals->EditRecords.size());
}

const char* vtkChainMailDeformationFilter::GetEdit(int i)
{
  const auto& records = this->Internals->EditRecords;
  return i >= 0 && std::size_t(i) < records.size() ? records[std::size_t(i)].c_str() : nullptr;
}

const char* vtkChainMailDeformationFilter::GetLastEdit()
{
  return this->Internals->LastEdit.c_str();
}

int vtkChainMailDeformationFilter::GetNumberOfRedoableEdits()
{
  const vtkInternals& in = *this->Internals;
  return in.History.size() > in.EditRecords.size()
           ? static_cast<int>(in.History.size() - in.EditRecords.size())
           : 0;
}

void vtkChainMailDeformationFilter::CommitEdit()
{
  vtkInternals& in = *this->Internals;
  if (!in.GeometryValid || in.EditsDirty || this->LastGraspPointId < 0)
  {
    vtkWarningMacro("CommitEdit: nothing to commit (no deformation in the last update).");
    return;
  }
  IdList vertices = in.Deformer.moved();
  if (in.Refining)
  {
    for (geoshaping::index_t v : in.Refined)
      if (!in.Deformer.moved_this_frame(v))
        vertices.push_back(v);
  }
  std::vector<Eigen::Vector3d> displacements;
  displacements.reserve(vertices.size());
  for (geoshaping::index_t v : vertices)
    displacements.push_back(in.FinalDisplacement(v));
  in.History.commit(in.Deformer, in.FrameRecipe, vertices, displacements);
  in.LastEdit = in.History.record(in.History.applied() - 1);
  in.EditRecords.push_back(in.LastEdit);
  in.Refining = false;
  in.Projector.reset();
  // Released: the next update shows the committed shape, not the grasp applied again.
  this->LastGraspPointId = -1;
  this->LastGraspMalleability = std::numeric_limits<double>::quiet_NaN();
  this->GraspPointId = -1;
  std::fill(this->Displacement, this->Displacement + 3, 0.0);
  this->Modified();
}

void vtkChainMailDeformationFilter::UndoEdit()
{
  vtkInternals& in = *this->Internals;
  if (in.EditRecords.empty())
    return;
  in.EditRecords.pop_back();
  in.EditsDirty = true;
  this->Modified();
}

void vtkChainMailDeformationFilter::RedoEdit()
{
  vtkInternals& in = *this->Internals;
  if (in.History.size() <= in.EditRecords.size())
    return;
  in.LastEdit = in.History.record(in.EditRecords.size());
  in.EditRecords.push_back(in.LastEdit);
  in.EditsDirty = true;
  this->Modified();
}

void vtkChainMailDeformationFilter::ResetEdits()
{
  vtkInternals& in = *this->Internals;
  if (in.EditRecords.empty())
    return;
  in.EditRecords.clear();
  in.EditsDirty = true;
  this->Modified();
}
