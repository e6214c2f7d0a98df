// The edit commands of vtkChainMailDeformationFilter (commit, undo, redo, reset and the
// edit list), around the core's geoshaping::EditSession.
#include "vtkChainMailDeformationFilterInternals.h"

using namespace vtkChainMailDeformationFilterDetail;

void vtkChainMailDeformationFilter::AddEdit(const char* record)
{
  this->Internals->Edits.add(record ? record : "");
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllEdits()
{
  this->Internals->Edits.clear();
  this->Modified();
}

int vtkChainMailDeformationFilter::GetNumberOfEdits()
{
  return static_cast<int>(this->Internals->Edits.records().size());
}

const char* vtkChainMailDeformationFilter::GetEdit(int i)
{
  const auto& records = this->Internals->Edits.records();
  return i >= 0 && std::size_t(i) < records.size() ? records[std::size_t(i)].c_str() : nullptr;
}

const char* vtkChainMailDeformationFilter::GetLastEdit()
{
  return this->Internals->Edits.last_edit().c_str();
}

int vtkChainMailDeformationFilter::GetNumberOfRedoableEdits()
{
  return this->Internals->Edits.redoable();
}

void vtkChainMailDeformationFilter::CommitEdit()
{
  vtkInternals& state = *this->Internals;
  std::vector<geoshaping::index_t> vertices;
  geoshaping::Displacements displacements;
  state.Passes.final_shape(state.Deformer, vertices, displacements);
  if (!state.GeometryValid || this->Statistics.LastGraspPointId < 0 ||
      !state.Edits.commit(
        state.Deformer, state.FrameRecipe, vertices, displacements, state.Placement()))
  {
    vtkWarningMacro("CommitEdit: nothing to commit (no deformation in the last update).");
    return;
  }
  state.Invalidate(vtkInternals::Stale::Links); // the passes' results and link data
  // The frame is now the rest shape. GraspPointId and Displacement are the client's: it
  // releases them (ParaView's proxy does, docs/editing.md), else the next update applies
  // the grasp again, to the new rest shape.
  this->Statistics.LastGraspPointId = -1;
  this->Statistics.LastGraspMalleability = std::numeric_limits<double>::quiet_NaN();
  this->Modified();
}

void vtkChainMailDeformationFilter::UndoEdit()
{
  if (this->Internals->Edits.undo())
    this->Modified();
}

void vtkChainMailDeformationFilter::RedoEdit()
{
  if (this->Internals->Edits.redo())
    this->Modified();
}

void vtkChainMailDeformationFilter::ResetEdits()
{
  if (this->Internals->Edits.reset())
    this->Modified();
}
