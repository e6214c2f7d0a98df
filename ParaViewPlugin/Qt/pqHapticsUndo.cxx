#include "pqHapticsUndo.h"

#include "EditControl.h"
#include "undo_step.h"
#include "vtkSMEditHistoryUndoElement.h"

#include <pqApplicationCore.h>
#include <pqUndoStack.h>

#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMUndoStack.h>
#include <vtkSMUndoStackBuilder.h>
#include <vtkUndoSet.h>

namespace interactor = geoshaping::interactor;

namespace pqHapticsUndo
{

const char* const StrokeLabel = "Paint Stroke";

std::vector<std::string> redoLabels()
{
  std::vector<std::string> labels;
  pqUndoStack* stack = pqApplicationCore::instance()->getUndoStack();
  vtkSMUndoStackBuilder* builder = stack ? stack->GetUndoStackBuilder() : nullptr;
  vtkSMUndoStack* steps = builder ? builder->GetUndoStack() : nullptr;
  for (unsigned int i = 0; steps && i < steps->GetNumberOfRedoSets(); ++i)
  {
    const char* label = steps->GetRedoSetLabel(i);
    labels.emplace_back(label ? label : "");
  }
  return labels;
}

std::string editsText(const interactor::EditResult& r)
{
  std::string text =
    "Edits: " + std::to_string(r.edits) + ", redoable " +
    std::to_string(interactor::redoable_steps(r.redoable, redoLabels(), StrokeLabel));
  return r.message.empty() ? text : text + " (" + r.message + ")";
}

bool isEditOf(vtkUndoSet* step, vtkSMProxy* deformation)
{
  if (!step || !deformation)
  {
    return false;
  }
  for (int i = 0; i < step->GetNumberOfElements(); ++i)
  {
    auto* edit = vtkSMEditHistoryUndoElement::SafeDownCast(step->GetElement(i));
    if (edit && edit->GetProxyGlobalId() == deformation->GetGlobalID())
    {
      return true;
    }
  }
  return false;
}

bool stepThroughStack(vtkSMProxy* deformation, interactor::EditCommand command)
{
  const bool redo = command == interactor::EditCommand::redo;
  pqUndoStack* stack = pqApplicationCore::instance()->getUndoStack();
  if (!stack || (!redo && command != interactor::EditCommand::undo) ||
      !isEditOf(geoshaping::undo::next_step(redo), deformation))
  {
    return false;
  }
  if (redo)
  {
    stack->redo();
  }
  else
  {
    stack->undo();
  }
  return true;
}

interactor::EditResult status(vtkSMProxy* deformation)
{
  interactor::EditResult result;
  if (!deformation || !deformation->GetProperty("EditHistory"))
  {
    result.message = "no ChainMailDeformation";
    return result;
  }
  deformation->UpdatePropertyInformation();
  result.edits = vtkSMPropertyHelper(deformation, "EditHistory").GetNumberOfElements();
  result.redoable = vtkSMPropertyHelper(deformation, "NumberOfRedoableEdits").GetAsInt();
  return result;
}

} // namespace pqHapticsUndo
