// Refinement and editing (commit, undo, redo) of vtkChainMailDeformationFilter.
#include "vtkChainMailDeformationFilterInternals.h"

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

void vtkChainMailDeformationFilter::Refine(vtkIdType grasp)
{
  vtkInternals& in = *this->Internals;
  in.EnsureLinks();
  const auto start = std::chrono::steady_clock::now();
  int sweeps = 0;
  bool aborted = false;
  geoshaping::ProjectionOptions options;
  options.max_iterations = this->RefinementIterations;
  options.tolerance = this->RefinementTolerance;
  // Dykstra sweeps: cheaper per iteration than ADMM and on the report's front for the
  // interactive iteration counts (docs/report.md); ADMM computes the references.
  options.solver = geoshaping::ProjectionSolver::dykstra;
  options.stop = this->SweepMonitor(this->RefinementIterations, sweeps, aborted);
  const geoshaping::ProjectionReport report =
    geoshaping::refine_links(*in.Projector, in.Deformer, geoshaping::index_t(grasp), options);
  if (aborted)
  {
    this->KeepAbortedPass("Refinement", report.iterations, this->RefinementIterations);
  }
  this->Statistics.LastRefinementMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->Statistics.NumberOfRefinementSweeps = report.iterations;
  this->Statistics.NumberOfRefinedPoints = vtkIdType(in.Projector->changed().size());
  in.Refining = true;
}

void vtkChainMailDeformationFilter::Relax(vtkIdType grasp)
{
  vtkInternals& in = *this->Internals;
  in.EnsureLinks();
  // The start: the frame's result after the refinement (if any), given sparsely.
  IdList vertices = in.Deformer.moved();
  if (in.Refining)
  {
    for (geoshaping::index_t v : in.Projector->changed())
      if (!in.Deformer.moved_this_frame(v))
        vertices.push_back(v);
  }
  geoshaping::Displacements values;
  values.reserve(vertices.size());
  for (geoshaping::index_t v : vertices)
    values.push_back(in.FinalDisplacement(v));
  const auto start = std::chrono::steady_clock::now();
  int sweeps = 0;
  bool aborted = false;
  geoshaping::RelaxationOptions options;
  options.iterations = this->RelaxationIterations;
  options.stop = this->SweepMonitor(this->RelaxationIterations, sweeps, aborted);
  const geoshaping::RelaxationReport report =
    in.Relaxer->relax(geoshaping::index_t(grasp), vertices, values, options);
  if (aborted)
  {
    this->KeepAbortedPass("Relaxation", report.iterations, this->RelaxationIterations);
  }
  this->Statistics.LastRelaxationMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->Statistics.NumberOfRelaxationSweeps = report.iterations;
  this->Statistics.NumberOfRelaxedPoints = vtkIdType(in.Relaxer->changed().size());
  in.Relaxing = true;
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
  if (!in.GeometryValid || in.EditsDirty || this->Statistics.LastGraspPointId < 0)
  {
    vtkWarningMacro("CommitEdit: nothing to commit (no deformation in the last update).");
    return;
  }
  IdList vertices = in.Deformer.moved();
  IdList beyond; // what the passes moved outside the frame's region, once each
  for (const IdList* pass : IdLists{ &in.Refined, &in.Relaxed })
    for (geoshaping::index_t v : *pass)
      if (!in.Deformer.moved_this_frame(v))
        beyond.push_back(v);
  std::sort(beyond.begin(), beyond.end());
  vertices.insert(vertices.end(), beyond.begin(), std::unique(beyond.begin(), beyond.end()));
  std::vector<Eigen::Vector3d> displacements;
  displacements.reserve(vertices.size());
  for (geoshaping::index_t v : vertices)
    displacements.push_back(in.FinalDisplacement(v));
  in.History.commit(in.Deformer, in.FrameRecipe, vertices, displacements);
  in.LastEdit = in.History.record(in.History.applied() - 1);
  in.EditRecords.push_back(in.LastEdit);
  in.Refining = false;
  in.Relaxing = false;
  in.Invalidate(vtkInternals::Stale::Links);
  // Released: the next update shows the committed shape, not the grasp applied again.
  this->Statistics.LastGraspPointId = -1;
  this->Statistics.LastGraspMalleability = std::numeric_limits<double>::quiet_NaN();
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
