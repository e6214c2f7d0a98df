#pragma once
// The client side of the edit history (docs/editing.md), free of Qt, VTK and ParaView so
// that it is unit tested (Testing/GUI/TestEditControl.cpp): the client owns the
// ChainMailDeformation's `EditHistory` list, so after each server command it copies the
// change into that list; and the point dabs that paint the surface the user sees.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace geoshaping::interactor
{

enum class EditCommand
{
  commit,
  undo,
  redo,
  reset
};

// The proxy property of a command: "CommitEdit", "UndoEdit", "RedoEdit", "ResetEdits".
const char* command_property(EditCommand command);

// What the edit controller reads of and writes to the ChainMailDeformation proxy.
// pqHapticsPipeline implements it with vtkSMProxy/vtkSMPropertyHelper; the tests with a
// model of the filter.
class EditProxy
{
public:
  virtual ~EditProxy() = default;
  virtual void invoke(const char* command) = 0;   // vtkSMProxy::InvokeCommand
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

// Runs one command and keeps the client's list in step, as docs/editing.md's Python
// functions do:
//   commit: CommitEdit, then append LastEdit only if the server's list grew by one (a
//           commit with nothing to commit leaves LastEdit at the previous edit); release.
//   undo:   UndoEdit and drop the last record (nothing when the list is empty).
//   redo:   RedoEdit, then append LastEdit only if the server's list grew by one.
//   reset:  ResetEdits and empty the list.
// Every command releases the grasp (the filter already did on commit; the client proxy
// is brought in step) and pushes the proxy. A server list that is not the client's
// length before the command (someone pressed a panel button) is reported, and the
// client's list wins at the push.
EditResult run_edit(EditCommand command, EditProxy& proxy);

// Paint on the surface the user sees: the points under a brush (ids, distances to its
// centre on the shown surface) -> MalleabilityPaint PointDabs triples (id, value,
// weight = strength * falloff(d / radius)). `falloff` is MalleabilityPaint's Falloff
// (0 Constant, 1 Linear, 2 Smooth, 3 Gaussian), as the core's falloff_weight. Points with
// weight 0 are left out.
double falloff_weight(int falloff, double r);
void append_point_dabs(const std::vector<long long>& ids, const std::vector<double>& distances,
  double radius, double value, double strength, int falloff, std::vector<double>& triples);

} // namespace geoshaping::interactor
