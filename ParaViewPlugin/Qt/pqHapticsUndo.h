#pragma once
// The Haptics dock and ParaView's undo stack (Edit > Undo, Ctrl+Z): one stack for both
// (docs/editing.md, "ParaView's undo stack"). Every edit command that changes the
// EditHistory list is a step of ParaView's stack (vtkSMChainMailDeformationProxy); the
// interactor's per-frame pushes are never steps (pqHapticsProxies::render, under
// geoshaping::undo::Exclude). The dock's Undo and Redo step ParaView's stack when its
// next step is an edit of the dock's target, so Alt+Z and Ctrl+Z do the same thing.
#include "edit_commands.h"

#include <string>
#include <vector>

class vtkSMProxy;
class vtkUndoSet;

namespace pqHapticsUndo
{

// The label of a paint stroke's step on ParaView's undo stack (Edit > Undo Paint Stroke).
extern const char* const StrokeLabel;

// The labels of the steps on ParaView's redo stack, the next first (none without a GUI).
std::vector<std::string> redoLabels();

// Whether `step` holds an edit of `deformation`'s list.
bool isEditOf(vtkUndoSet* step, vtkSMProxy* deformation);

// Undo or redo: when ParaView's next step that way is an edit of `deformation`, runs it
// through ParaView's undo stack (exactly Edit > Undo / Redo) and returns true; false, and
// nothing done, otherwise (the caller then sends the command).
bool stepThroughStack(vtkSMProxy* deformation, geoshaping::interactor::EditCommand command);

// What the dock shows of `deformation`'s edits: the client's list length and what RedoEdit
// can re-apply (information read from the server). Right after Load State, an undo from
// the Edit menu or a panel button as after the dock's own commands.
geoshaping::interactor::EditResult status(vtkSMProxy* deformation);

// The dock's "Edits" line for `r`: the edits, and what its Redo restores
// (geoshaping::interactor::redoable_steps: redoable edits and paint strokes).
std::string editsText(const geoshaping::interactor::EditResult& r);

} // namespace pqHapticsUndo
