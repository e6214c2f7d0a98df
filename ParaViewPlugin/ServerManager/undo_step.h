#pragma once
// One user action = one step of ParaView's undo stack (Edit > Undo, Ctrl+Z), as
// ParaView's own widgets and Blender's sculpt mode do it (docs/editing.md, "ParaView's
// undo stack"). Without a GUI (pvpython, pvbatch) there is no undo stack and these do
// nothing.
//
// ParaView records every push of a proxy's changed properties as an undo step of its
// own. An interactive tool pushes dozens a second (a drag frame: GraspPointId,
// Displacement; a paint dab: PointDabs), so:
//   - its per-frame pushes run inside an `Exclude` (never on the stack), and
//   - the action, once over, is pushed as one `Step`: elements of our own (an edit of
//     the EditHistory list, vtkSMEditHistoryUndoElement) and/or, for a proxy that is
//     `track`ed, its state from the start of the action to the end (ParaView's own
//     element, vtkSMRemoteObjectUpdateUndoElement: undo loads the state before).
//
//     geoshaping::undo::Step stroke("Paint stroke");
//     stroke.track(paintProxy);        // at the press
//     ...                              // each frame: { Exclude e; proxy->UpdateVTKObjects(); }
//     stroke.finish();                 // at the release: one step, whatever the frames
//
// A Step opened inside an outer undo set (a panel's own BEGIN_UNDO_SET) joins it.
#include "GeoShapingServerManagerModule.h"

#include <memory>
#include <string>

class vtkSMProxy;
class vtkSMUndoElement;
class vtkSMUndoStackBuilder;
class vtkUndoSet;

namespace geoshaping::undo
{

// ParaView's undo stack builder when it records now: a GUI session, not while the stack
// is undoing or redoing, not inside an Exclude (or BEGIN_UNDO_EXCLUDE). Else nullptr.
GEOSHAPINGSERVERMANAGER_EXPORT vtkSMUndoStackBuilder* recording_builder();

// While alive, pushes are not recorded on ParaView's undo stack (pqUndoStack's
// beginNonUndoableChanges at the server-manager level); nests.
class GEOSHAPINGSERVERMANAGER_EXPORT Exclude
{
public:
  Exclude();
  ~Exclude();
  Exclude(const Exclude&) = delete;
  Exclude& operator=(const Exclude&) = delete;

private:
  vtkSMUndoStackBuilder* Builder;
  bool Was = false;
};

class GEOSHAPINGSERVERMANAGER_EXPORT Step
{
public:
  explicit Step(std::string label);
  ~Step(); // unfinished: nothing is pushed
  Step(const Step&) = delete;
  Step& operator=(const Step&) = delete;

  // Remembers `proxy`'s pushed state now; finish() adds one element that goes from it to
  // the state then. Track a proxy before the action pushes anything to it.
  void track(vtkSMProxy* proxy);
  // An element of our own (e.g. vtkSMEditHistoryUndoElement); kept in order, after the
  // tracked states.
  void add(vtkSMUndoElement* element);
  // Pushes the step (or adds it to the enclosing undo set): true when something was
  // recorded, false when there is no undo stack, it does not record now, or the step is
  // empty. A Step finishes once.
  bool finish();

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;
};

// The step Edit > Undo would undo now (`redo`: the one Edit > Redo would redo), or
// nullptr: the Haptics dock's Undo and Redo are ParaView's when that step is one of its
// target's edits.
GEOSHAPINGSERVERMANAGER_EXPORT vtkUndoSet* next_step(bool redo);

} // namespace geoshaping::undo
