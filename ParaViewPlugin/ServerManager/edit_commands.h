#pragma once
// The client side of the edit history (docs/editing.md), free of Qt, VTK and ParaView so
// that it is unit tested (Testing/GUI/TestEditControl.cpp). The client owns the
// ChainMailDeformation's `EditHistory` list (SaveState writes the client's values), so
// after the server has run an edit command the client copies the change into that list.
// vtkSMChainMailDeformationProxy does this for every command invoked on the proxy — the
// properties panel's buttons, the Haptics dock, its shortcuts, Python's InvokeCommand —
// so there is one path for every edit.
#include <string>
#include <vector>

namespace geoshaping::interactor
{

enum class EditCommand
{
  commit,
  undo,
  redo,
  reset,
  snap // SnapToMarkers: one edit the filter makes, followed as a commit is
};

// The proxy property of a command: "CommitEdit", "UndoEdit", "RedoEdit", "ResetEdits",
// "SnapToMarkers";
// is_edit_command() is its inverse (false for any other name).
const char* command_property(EditCommand command);
bool is_edit_command(const std::string& property, EditCommand& command);

// What the edit bookkeeping reads of and writes to the ChainMailDeformation proxy.
// vtkSMChainMailDeformationProxy implements it with vtkSMPropertyHelper; the tests with a
// model of the filter.
class EditProxy
{
public:
  virtual ~EditProxy() = default;
  virtual void update_information() = 0;          // vtkSMProxy::UpdatePropertyInformation
  virtual std::string last_edit() = 0;            // information property LastEdit
  virtual int number_of_edits() = 0;              // information property NumberOfEdits (server)
  virtual int number_of_redoable_edits() = 0;     // information NumberOfRedoableEdits
  virtual std::vector<std::string> history() = 0; // the client's EditHistory
  virtual void set_history(const std::vector<std::string>& records) = 0;
  virtual void release() = 0; // GraspMode Point Id, GraspPointId -1, Displacement 0
  virtual void push() = 0;    // vtkSMProxy::UpdateVTKObjects
};

struct EditResult
{
  bool changed = false;  // the list (and so the shape) changed
  std::size_t edits = 0; // records in EditHistory afterwards
  int redoable = 0;      // what RedoEdit can still re-apply
  std::string message;   // why nothing changed, empty otherwise
};

// Once the server has run `command`, brings the client's list in step:
//   commit, redo, snap: append LastEdit if the server's list is now one longer than the
//                 client's (a commit with nothing to commit leaves LastEdit at the
//                 previous edit and the server's list unchanged);
//   undo:         drop the last record (nothing when the list is empty);
//   reset:        empty the list.
// Every command releases the grasp (the filter already did on commit; the client proxy is
// brought in step) and pushes the proxy (the pushed list is the server's own, so the
// filter's synchronize does nothing but compare).
EditResult follow_edit(EditCommand command, EditProxy& proxy);

// Sets the client's list to `records`, releases and pushes: one step of ParaView's undo
// stack (Edit > Undo, Ctrl+Z) going back to the list before an edit command or forth to
// the list after it. The server's list is set the way a state file sets it; its
// synchronize undoes or re-applies what differs, and an edit undone this way stays
// redoable, so stepping back over a commit is the command UndoEdit, bit for bit.
// `changed`: the list differed; no message.
EditResult restore_edits(const std::vector<std::string>& records, EditProxy& proxy);

} // namespace geoshaping::interactor
