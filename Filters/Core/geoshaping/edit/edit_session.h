#pragma once
// The edits as a pipeline sees them (docs/editing.md): the list of records a client owns
// (vtkChainMailDeformationFilter's EditHistory property: what a state file saves), the
// commands that change it, and the history that brings a deformer to it.
//
//   records():  the edits to apply, in order (AddEdit / RemoveAllEdits set it)
//   commit:     the frame's shape becomes rest; its record is appended and applied
//               (the history's redo tail is dropped)
//   undo:       the last record leaves the list      } applied at the next
//   redo:       the history's next record rejoins it } synchronize(); undone edits
//   reset:      the list empties                     } stay redoable
//   redoable(): history size - list size, while the list is a prefix of the history
//
// A command changes only the list (and, for commit, the deformer's rest shape); grasp and
// displacement belong to the caller, who releases them after a commit (or the next frame
// applies the grasp again, to the new rest shape). Every operation costs time in
// proportion to the edits' vertices (EditHistory), never the mesh size.
//
// On a partitioned mesh (`place.exchange`, docs/mpi.md) every piece holds the same list
// and runs the same commands: undo, redo and reset only change the list (no
// communication); commit and synchronize are collective (EditHistory), and the records
// name global ids, so every piece's list is the same text and a record made on N pieces
// replays on M.
#include "geoshaping/edit/edit_history.h"

#include <functional>
#include <string>
#include <vector>

namespace geoshaping
{

class EditSession
{
public:
  const std::vector<std::string>& records() const { return records_; }
  void add(std::string record);
  void clear();

  // The deformer's last frame (`vertices` moved by `displacements` from rest) becomes its
  // rest shape. False, and nothing changes, while a change of the list is not yet
  // synchronized (the frame was computed on another rest shape).
  bool commit(ChainMailDeformer& deformer, const EditRecipe& recipe,
    const std::vector<index_t>& vertices, const std::vector<Eigen::Vector3d>& displacements,
    const EditPlace& place = {});
  bool undo();  // false when the list is empty
  bool redo();  // false when nothing is redoable
  bool reset(); // false when the list is empty
  // The record last committed or redone ("" before any): the client appends it to its list.
  const std::string& last_edit() const { return last_; }
  int redoable() const;

  // Whether the list changed since the last synchronize().
  bool pending() const { return pending_; }
  // The deformer's mesh was set again: every record is applied again at the next
  // synchronize() (the history is forgotten, the deformer is not touched).
  void forget_applied();
  // Brings the deformer to records() with the least work (EditHistory::synchronize): false
  // with `error` at the first bad record, the edits before it applied.
  bool synchronize(ChainMailDeformer& deformer, std::string& error,
    const std::function<bool(index_t)>& fits = {}, const EditPlace& place = {});
  // Vertices whose rest position changed since the last call (EditHistory::take_touched).
  std::vector<index_t> take_touched() { return history_.take_touched(); }

private:
  std::vector<std::string> records_;
  EditHistory history_;
  std::string last_;
  bool pending_ = false;
};

} // namespace geoshaping
